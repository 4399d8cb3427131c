"""ST export of an SFC POU: readable IEC ST that runs like the chart (docs/sfc.md, "ST export").

The text is the chart's scan written out, in the order ``ir/lower_sfc.py`` runs it (whose plan it reuses: the
steps, action controls, passes and transition order are the lowering's own):

* every step is an ``SFC_STEP`` variable named like it (``Fill : SFC_STEP;``, the initial one ``:= (X := TRUE)``)
  and every action an ``ACTION_CONTROL`` named like it, so ``Fill.X``, ``Fill.T`` and ``Pump.Q`` read the same in
  the actions, the conditions and other POUs; a BOOL variable associated with steps gets an ``ACTION_CONTROL`` of
  its own and takes its Q;
* the SFC flags, the steps (their time; entering and leaving for entry and exit actions; time limits), the
  action controls (``Pump(N := Fill.X OR Empty.X, R := FALSE);``), the actions in a ``FOR`` loop over the passes
  (exit, entry, final runs, active), each under the ``IF`` of its passes, the named transitions, every
  condition into a flag, the transitions that fire (priority, then drawing order; a step is taken once), then
  the steps they leave (``Fill(X := FALSE);``) and enter (``Drain.X := TRUE;``).

ST actions are written as typed; IL actions and transitions through the IL export (``il.py``: a RET ends the
action, an IL transition's value is its accumulator at the end); LD and FBD actions and transitions through the
network exporters; an action written in SFC as its chart, the same way. A RETURN in an ST action (ending the action,
not the POU) has no ST form inside the loop: such a POU is refused with a located diagnostic.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ...ir import nodes as ir
from ...ir.context import PouContext
from ...ir.diagram_checks import canonical_label
from ...ir.lower_sfc import ACTIVE_PASS, EXIT_PASS, FINAL_PASS, PIN, TABLE_FLAG, SfcLowering
from ...ir.sfc_analysis import BOOL_FIELDS, STRING_FIELDS, Part, condition_parts
from ...model import Diagnostic, Pou, Project, fbd, ld
from ...model.sfc import SfcBody, SfcChart
from ...model.sfc_graph import ChartGraph
from ...st import ast
from ...st import types as st_types
from ...st.nesting import nodes
from ...st.parser import parse_statements
from ...st.printer import print_expression, print_statements
from ...st.sfc import action_file, il_key
from ...st.symbols import CheckResult, Symbol
from .body import Network, body_lines, comment, network_title
from .elements import PouScope
from .fbd import fbd_network
from .il import IlRefused, il_as_st, il_refused
from .ld import ld_network
from .names import Names
from .network import Declarations, plan

INDENT = "    "


@dataclass
class SfcExport:
    pou: Pou | None
    diagnostics: list[Diagnostic] = field(default_factory=list)


def st_sfc_pou(project: Project, pou: Pou, checked: CheckResult, diagnostics: list[Diagnostic]) -> SfcExport:
    """The ST version of the SFC POU ``pou`` (``diagnostics``: the POU's own, errors refuse it)."""
    info = checked.pou(pou.name)
    assert info is not None and isinstance(pou.body, SfcBody)
    ctx = PouContext(checked, info, diagnostics)
    lowering = SfcLowering(pou, ctx)
    blocks = lowering.blocks()
    if any(d.severity == "error" for d in diagnostics):
        return SfcExport(None, diagnostics)
    writer = _Writer(pou, checked, lowering, ir.Pou(ctx.name, "program", ctx.slots, blocks))
    text = writer.body()
    if writer.problems:
        return SfcExport(None, diagnostics + writer.problems)
    return SfcExport(
        Pou(
            name=pou.name,
            kind=pou.kind,
            language="st",
            return_type=pou.return_type,
            declarations=writer.declarations_text(),
            body=text,
        ),
        [d for d in diagnostics if d.severity != "error"],
    )


class _Writer:
    def __init__(self, pou: Pou, checked: CheckResult, lowering: SfcLowering, lowered: ir.Pou):
        self.pou = pou
        self.info = lowering.info
        self.body_model: SfcBody = lowering.body
        self.checked = checked
        self.plan = lowering
        self.lowered = lowered
        self.declarations = Declarations(Names.for_pou(checked, pou.name))
        info = checked.pou(pou.name)
        assert info is not None
        self.scope = PouScope(checked, info, self.declarations)
        self.problems: list[Diagnostic] = []
        self.lines: list[str] = []
        self.depth = 0
        self.flags = {name: lowering.info.symbols.get(name) or checked.globals.get(name) for name in lowering.flags}
        # the export's own flags, made for the steps that have them in the lowering
        self.names: dict[tuple[str, str], str] = {}
        for key, slots in lowering.steps.items():
            name = slots.step.name
            for part, var, kind in (
                ("entered", slots.entered, "VAR"),
                ("left", slots.left, "VAR"),
                ("mem", slots.memory, "VAR"),
                ("entering", slots.entering, "VAR_TEMP"),
                ("leaving", slots.leaving, "VAR_TEMP"),
                ("taken", slots.taken, "VAR_TEMP"),
            ):
                if var is not None:
                    self.names[(key, part)] = self.declarations.declare(f"{name}_{part}", "BOOL", kind)
        for key, control in lowering.controls.items():
            if control.target is not None:
                self.names[(key, "control")] = self.declarations.declare(
                    f"{control.name}_control", "ACTION_CONTROL", "VAR"
                )
        assert lowering.graph_made is not None
        self.graph = lowering.graph_made
        #: every chart of the POU: its own (None) and each SFC action's (upper-case name)
        self.graphs: dict[str | None, ChartGraph] = {None: self.graph, **lowering.inner}
        for graph in self.graphs.values():
            for transition in graph.transitions:
                element = transition.transition
                self.names[(element.id, "c")] = self.declarations.declare(f"{element.id}_c", "BOOL", "VAR_TEMP")
                self.names[(element.id, "f")] = self.declarations.declare(f"{element.id}_fires", "BOOL", "VAR_TEMP")
        self.quit_memory = (
            self.declarations.declare("sfc_quit_mem", "BOOL", "VAR") if "SFCQUITERROR" in lowering.flags else None
        )
        self.analysis = lowering.analysis
        self.analysis_count = (
            self.declarations.declare("sfc_analysis_n", "INT", "VAR_TEMP") if self.analysis is not None else None
        )
        self.analysis_index = (
            self.declarations.declare("sfc_analysis_i", "INT", "VAR_TEMP")
            if self.analysis is not None and self.analysis.table is not None
            else None
        )
        self.passes = {owner: lowering.action_passes(owner) for owner in self.graphs}
        self.counters: dict[str | None, str] = {}
        self.closing: dict[str, str] = {}
        for owner, passes in self.passes.items():
            if any(p for _, p in passes):
                suffix = "" if owner is None else f"_{lowering.inner_name(owner)}"
                self.counters[owner] = self.declarations.declare(f"sfc_pass{suffix}", "INT", "VAR_TEMP")
            if owner is not None:
                name = lowering.inner_name(owner)
                self.closing[owner] = self.declarations.declare(f"{name}_closing", "BOOL", "VAR_TEMP")

    # ------------------------------------------------------------ text
    def line(self, text: str = "") -> None:
        self.lines.append(INDENT * self.depth + text if text else "")

    def flag(self, name: str) -> str | None:
        symbol = self.flags.get(name)
        return symbol.name if symbol is not None else None

    def step_name(self, key: str) -> str:
        return self.plan.steps[key].step.name

    def control_name(self, key: str) -> str:
        control = self.plan.controls[key]
        return self.names[(key, "control")] if control.target is not None else control.name

    def declarations_text(self) -> str:
        blocks = [self.pou.declarations] if self.pou.declarations.strip() else []
        state = [
            f"{INDENT}{s.step.name} : SFC_STEP{' := (X := TRUE)' if s.initial else ''};"
            for s in self.plan.steps.values()
        ]
        state += [f"{INDENT}{a.name} : ACTION_CONTROL;" for a in self.body_model.actions]
        state += [f"{INDENT}{t.name} : BOOL;" for t in self.body_model.transitions]
        if state:
            blocks.append(
                "\n".join(
                    [f"VAR {comment('the steps, actions and named transitions of the chart')}", *state, "END_VAR"]
                )
            )
        for var_class in ("VAR", "VAR_TEMP"):
            items = [(name, type_text) for name, type_text, kind in self.declarations.items if kind == var_class]
            if items:
                lines = [f"{var_class} {comment('generated by the ST export')}"]
                lines += [f"{INDENT}{name} : {type_text};" for name, type_text in items]
                blocks.append("\n".join([*lines, "END_VAR"]))
        return "\n".join(blocks)

    def body(self) -> str:
        self.flags_part()
        self.steps_part(None)
        self.controls_part(None)
        self.actions_part(None)
        self.named_transitions_part()
        self.transitions_part(None)
        return "\n".join(self.lines)

    # ------------------------------------------------------------ 1. flags
    def flags_part(self) -> None:
        trans, init, reset = self.flag("SFCTRANS"), self.flag("SFCINIT"), self.flag("SFCRESET")
        pause, quit_ = self.flag("SFCPAUSE"), self.flag("SFCQUITERROR")
        if not any((trans, init, reset, pause, quit_)):
            return
        self.line(comment("SFC flags"))
        if trans:
            self.line(f"{trans} := FALSE;")
        resets = [f for f in (init, reset) if f]
        if resets:
            self.line(f"IF {' OR '.join(resets)} THEN")
            self.depth += 1
            self.reset_chart()
            self.depth -= 1
            self.line("END_IF;")
        holds = [f for f in (init, pause) if f]
        if holds:
            self.line(f"IF {' OR '.join(holds)} THEN")
            self.line(f"{INDENT}RETURN;")
            self.line("END_IF;")
        if quit_ and self.quit_memory:
            self.line(f"IF {self.quit_memory} AND NOT {quit_} THEN")
            self.depth += 1
            for key in self.plan.steps:
                name = self.step_name(key)
                self.line(f"IF {name}.X THEN")
                self.line(f"{INDENT}{name}(X := FALSE);")
                self.line(f"{INDENT}{name}.X := TRUE;")
                self.line("END_IF;")
            self.depth -= 1
            self.line("END_IF;")
            self.line(f"{self.quit_memory} := {quit_};")
            self.line(f"IF {quit_} THEN")
            self.depth += 1
            self.clear_error()
            self.line("RETURN;")
            self.depth -= 1
            self.line("END_IF;")

    def reset_chart(self) -> None:
        initial = None
        for key, slots in self.plan.steps.items():
            name = slots.step.name
            self.line(f"{name}(X := FALSE);")
            for part in ("mem", "entered", "left"):
                if (key, part) in self.names:
                    self.line(f"{self.names[(key, part)]} := FALSE;")
        for slots in self.plan.steps.values():
            if slots.initial:  # of the POU's chart and of every action's chart
                self.line(f"{slots.step.name}.X := TRUE;")
                if slots.owner is None:
                    initial = slots.step.name
        for key, control in self.plan.controls.items():
            pins = ", ".join(
                [*(f"{pin} := FALSE" for pin in PIN.values() if pin in control.inputs and pin != "R"), "R := TRUE"]
            )
            self.line(f"{self.control_name(key)}({pins});")
            if control.target is not None:
                self.line(f"{control.name} := {self.control_name(key)}.Q;")
        self.clear_error()
        current = self.flag("SFCCURRENTSTEP")
        if current and initial is not None:
            self.line(f"{current} := '{initial}';")

    def clear_error(self) -> None:
        if error := self.flag("SFCERROR"):
            self.line(f"{error} := FALSE;")
        for name in ("SFCERRORSTEP", "SFCERRORPOU"):
            if flag := self.flag(name):
                self.line(f"{flag} := '';")
        self.clear_analysis()

    def clear_analysis(self) -> None:
        """SFCErrorAnalyzation and every entry of SFCErrorAnalyzationTable back to empty (ir/sfc_analysis.py)."""
        if text := self.flag("SFCERRORANALYZATION"):
            self.line(f"{text} := '';")
        table = self.flags.get(TABLE_FLAG)
        if table is None or self.analysis_index is None:
            return
        low, high, fields = _table_shape(table)
        index = self.analysis_index
        self.line(f"FOR {index} := {low} TO {high} DO")
        for upper, (name, _) in fields.items():
            if upper in STRING_FIELDS or upper in BOOL_FIELDS:
                empty = "''" if upper in STRING_FIELDS else "FALSE"
                self.line(f"{INDENT}{table.name}[{index}].{name} := {empty};")
        self.line("END_FOR;")

    def record_analysis(self, key: str) -> None:
        """The parts of the conditions leaving the step that hold them, into the table and the string."""
        if self.analysis is None or self.analysis_count is None:
            return
        graph = self.graphs.get(self.plan.steps[key].owner)
        if graph is None:
            return
        self.clear_analysis()
        count = self.analysis_count
        self.line(f"{count} := 0;")
        table, text = self.flags.get(TABLE_FLAG), self.flag("SFCERRORANALYZATION")
        for transition in graph.evaluation_order():
            if key not in transition.sources:
                continue
            condition = transition.transition.condition.strip()
            for part in condition_parts(condition, self.analysis.symbol):
                terms = [f"NOT ({condition})", *(f"({t})" if v else f"NOT ({t})" for t, v in part.terms)]
                self.line(f"IF {' AND '.join(terms)} THEN")
                self.depth += 1
                if table is not None:
                    self.table_entry(table, part, count)
                if text:
                    self.line(f"IF {count} = 0 THEN")
                    self.line(f"{INDENT}{text} := {_string(part.text)};")
                    self.line("ELSE")
                    self.line(f"{INDENT}{text} := CONCAT({text}, {_string(' | ' + part.text)});")
                    self.line("END_IF;")
                self.line(f"{count} := {count} + 1;")
                self.depth -= 1
                self.line("END_IF;")

    def table_entry(self, table: Symbol, part: Part, count: str) -> None:
        low, high, fields = _table_shape(table)
        texts = {"NAME": part.text, "ADDRESS": part.address, "COMMENT": part.comment}
        self.line(f"IF {count} <= {high - low} THEN")
        for upper, (name, _) in fields.items():
            target = f"{INDENT}{table.name}[{count} + {low}].{name}"
            if upper in texts:
                self.line(f"{target} := {_string(texts[upper])};")
            elif upper == "VALUE":
                self.line(f"{target} := {part.text};")
            elif upper == "FAILED":
                self.line(f"{target} := TRUE;")
        self.line("END_IF;")

    # ------------------------------------------------------------ 2. steps
    def steps_part(self, owner: str | None) -> None:
        self.line(comment("steps: their time, entering and leaving, time limits"))
        error, enable = self.flag("SFCERROR"), self.flag("SFCENABLELIMIT")
        where, pou = self.flag("SFCERRORSTEP"), self.flag("SFCERRORPOU")
        for key, slots in self.plan.steps.items():
            if slots.owner != owner:
                continue
            name = slots.step.name
            self.line(f"{name}();")
            if (key, "mem") in self.names:
                entered, left, mem = (self.names[(key, p)] for p in ("entered", "left", "mem"))
                entering, leaving = self.names[(key, "entering")], self.names[(key, "leaving")]
                self.line(f"{entering} := {entered} OR ({name}.X AND NOT {mem});")
                self.line(f"{leaving} := {left} OR (NOT {name}.X AND {mem});")
                self.line(f"{mem} := {name}.X;")
                self.line(f"{entered} := FALSE;")
                self.line(f"{left} := FALSE;")
            limit = (slots.step.max_time or "").strip()
            if error and limit:
                terms = [f"{name}.X", f"NOT {error}", f"{name}.T > {limit}"]
                if enable:
                    terms.insert(0, enable)
                self.line(f"IF {' AND '.join(terms)} THEN")
                self.line(f"{INDENT}{error} := TRUE;")
                if where:
                    self.line(f"{INDENT}{where} := '{name}';")
                if pou:
                    self.line(f"{INDENT}{pou} := '{self.pou.name}';")
                self.depth += 1
                self.record_analysis(key)
                self.depth -= 1
                self.line("END_IF;")

    # ------------------------------------------------------------ 3. action control
    def controls_part(self, owner: str | None) -> None:
        active = [(key, c) for key, c in self.plan.controls.items() if c.inputs and c.owner == owner]
        if not active:
            return
        self.line(comment("action control (IEC 61131-3 ACTION_CONTROL): the qualifiers of the active steps"))
        for key, control in active:
            instance = self.control_name(key)
            for step, _, text, _ in control.times:
                self.line(f"IF {self.step_name(step)}.X THEN")
                self.line(f"{INDENT}{instance}.T := {text.strip()};")
                self.line("END_IF;")
            pins = [
                f"{pin} := {' OR '.join(f'{self.step_name(s)}.X' for s in control.inputs[pin])}"
                for pin in PIN.values()
                if pin in control.inputs
            ]
            if "R" not in control.inputs:
                pins.append("R := FALSE")
            self.line(f"{instance}({', '.join(pins)});")
            if control.target is not None:
                self.line(f"{control.name} := {instance}.Q;")

    # ------------------------------------------------------------ 4. actions
    def actions_part(self, owner: str | None) -> None:
        counter = self.counters.get(owner)
        if counter is None:
            return
        numbers = sorted({n for _, passes in self.passes[owner] for n in passes})
        self.line(
            comment(
                "actions: exit actions, entry actions, final runs (A and not Q), active actions (Q); "
                "alphabetical in each pass"
            )
        )
        self.line(f"FOR {counter} := {numbers[0]} TO {numbers[-1]} DO")
        self.depth += 1
        for action, passes in self.passes[owner]:
            if not passes:
                continue
            terms = []
            for number, keys in sorted(passes.items()):
                if number == FINAL_PASS:
                    when = f"{action.name}.A AND NOT {action.name}.Q"
                elif number == ACTIVE_PASS:
                    when = f"{action.name}.Q"
                else:
                    part = "leaving" if number == EXIT_PASS else "entering"
                    when = " OR ".join(self.names[(k, part)] for k in keys)
                    when = f"({when})" if len(keys) > 1 else when
                terms.append(f"({counter} = {number} AND {when})")
            self.line(f"IF {' OR '.join(terms)} THEN")
            self.depth += 1
            self.line(comment(f"action {action.name}"))
            if isinstance(action.body, SfcChart):
                self.inner_chart(action.name.upper())
            elif action.language == "il":
                self.il_part("actions", action.name)
            else:
                self.text_or_networks(action.body, f"actions/{action.name}", action_file(self.pou.name, action.name))
            self.depth -= 1
            self.line("END_IF;")
        self.depth -= 1
        self.line("END_FOR;")

    def inner_chart(self, owner: str) -> None:
        """An action written in SFC, as ``ir/lower_sfc.py`` runs it: while the action is active (Q) one scan of its
        chart; in its final run the chart closes (its steps are left, no transition fires, the initial step is set
        again)."""
        closing = self.closing[owner]
        mine = [slots for slots in self.plan.steps.values() if slots.owner == owner]
        self.line(f"{closing} := NOT {self.plan.controls[owner].name}.Q;")
        self.line(f"IF {closing} THEN")
        for slots in mine:
            self.line(f"{INDENT}{slots.step.name}(X := FALSE);")
        self.line("END_IF;")
        self.steps_part(owner)
        self.controls_part(owner)
        self.actions_part(owner)
        self.line(f"IF NOT {closing} THEN")
        self.depth += 1
        self.transitions_part(owner)
        self.depth -= 1
        self.line("END_IF;")
        self.line(f"IF {closing} THEN")
        for slots in mine:
            if slots.initial:
                self.line(f"{INDENT}{slots.step.name}.X := TRUE;")
        self.line("END_IF;")

    def il_part(self, part: str, name: str) -> None:
        """An IL action (a RET ends it) or IL named transition (the accumulator at its end is its value) as ST, through
        the IL POU export (``il.py``); its accumulators are variables of the POU."""
        il = self.info.il_parts[il_key(part, name)]
        statements = list(il.statements)
        if part == "transitions":
            assert il.end is not None  # the lowering refused the transition otherwise
            statements.append(ast.Assign(ast.Name(name), il.end.value))
        file = f"{self.pou.name}/{part}/{name}"
        what = f"the IL {'action' if part == 'actions' else 'transition'} {name}"
        try:
            body, kept = il_as_st(statements, il.accumulators, self.declarations.names, returns=part == "actions")
        except IlRefused as refused:
            self.problems.append(il_refused(refused, self.pou.name, file, what))
            return
        if _returns(body):
            self.refuse(f"a RET inside a loop or branch of {what} ends only the action; ST has no such statement", file)
        for name_, acc in kept:
            self.declarations.add(name_, str(acc.type), "VAR")
        for text_line in print_statements(body).rstrip("\n").splitlines():
            self.line(text_line)

    def text_or_networks(self, body: object, part: str, file: str) -> None:
        if isinstance(body, str):
            parsed = parse_statements(body)
            if parsed.ast is not None and _returns(parsed.ast):
                self.refuse(
                    "a RETURN in an action ends only the action; the ST export has no such statement: "
                    "end the action's statements with IF instead",
                    file,
                )
            for text_line in body.splitlines():
                self.line(text_line.rstrip())
            return
        if isinstance(body, (ld.LdBody, fbd.FbdBody)):
            self.networks(body, part, file)

    def networks(self, body: ld.LdBody | fbd.FbdBody, part: str, file: str) -> None:
        if any(_is_return(item) for network in body.networks for item in _items(network)):
            self.refuse(
                "a RETURN in an action or transition ends only that part of the chart; the ST export has no "
                "such statement",
                file,
            )
            return
        lowered = ir.Pou(
            self.lowered.name, "program", self.lowered.slots, [b for b in self.lowered.blocks if b.origin.body == part]
        )
        networks: list[Network] = []
        for index, network in enumerate(body.networks):
            code = (
                ld_network(self.scope, network, index + 1)
                if isinstance(network, ld.LdNetwork)
                else fbd_network(self.scope, network, lowered)
            )
            title = network_title(index + 1, network.label, network.comment)
            controls = [(c.label, c.element) for c in code.controls]
            networks.append(Network(network.id, title, plan(code, self.declarations), controls))
        labels = {canonical_label(n.label): i for i, n in enumerate(body.networks) if n.label}
        for made in body_lines(networks, labels, self.declarations):
            self.line(made.text)

    def refuse(self, message: str, file: str) -> None:
        self.problems.append(Diagnostic(code="EXPORT-UNSUPPORTED", message=message, pou=self.pou.name, file=file))

    # ------------------------------------------------------------ 5. transitions
    def named_transitions_part(self) -> None:
        for transition in self.body_model.transitions:
            self.line(comment(f"transition {transition.name}"))
            if transition.language == "il":
                self.il_part("transitions", transition.name)
            elif isinstance(transition.body, str):
                self.line(f"{transition.name} := {transition.body.strip()};")
            else:
                self.line(f"{transition.name} := FALSE;")
                self.networks(
                    transition.body, f"transitions/{transition.name}", f"{self.pou.name}/transitions/{transition.name}"
                )

    def transitions_part(self, owner: str | None) -> None:
        graph = self.graphs[owner]
        self.line(comment("transitions: every condition, then those that fire (a step is taken once)"))
        for transition in graph.transitions:
            element = transition.transition
            self.line(f"{self.names[(element.id, 'c')]} := {element.condition.strip()};")
        tip, tip_mode = self.flag("SFCTIP"), self.flag("SFCTIPMODE")
        for transition in graph.evaluation_order():
            element = transition.transition
            terms = []
            takes = []
            for key in transition.sources:
                slots = self.plan.steps[key]
                terms.append(f"{slots.step.name}.X")
                if (key, "taken") in self.names:
                    terms.append(f"NOT {self.names[(key, 'taken')]}")
                    takes.append(self.names[(key, "taken")])
                if (slots.step.min_time or "").strip():
                    terms.append(f"{slots.step.name}.T >= {slots.step.min_time.strip()}")
            terms.append(self.names[(element.id, "c")])
            if tip_mode:
                terms.append(f"(NOT {tip_mode} OR {tip or 'FALSE'})")
            fires = self.names[(element.id, "f")]
            self.line(f"{fires} := {' AND '.join(terms)};")
            if takes:
                self.line(f"IF {fires} THEN")
                for taken in takes:
                    self.line(f"{INDENT}{taken} := TRUE;")
                self.line("END_IF;")
        for transition in graph.transitions:
            self.line(f"IF {self.names[(transition.transition.id, 'f')]} THEN")
            for key in transition.sources:
                self.line(f"{INDENT}{self.step_name(key)}(X := FALSE);")
                if (key, "left") in self.names:
                    self.line(f"{INDENT}{self.names[(key, 'left')]} := TRUE;")
            self.line("END_IF;")
        for transition in graph.transitions:
            self.line(f"IF {self.names[(transition.transition.id, 'f')]} THEN")
            for key in transition.targets:
                self.line(f"{INDENT}{self.step_name(key)}.X := TRUE;")
                if (key, "entered") in self.names:
                    self.line(f"{INDENT}{self.names[(key, 'entered')]} := TRUE;")
            self.line("END_IF;")
        if owner is not None:  # the flags are about the POU's chart
            return
        if (trans := self.flag("SFCTRANS")) and self.graph.transitions:
            fired = " OR ".join(self.names[(t.transition.id, "f")] for t in self.graph.transitions)
            self.line(f"{trans} := {fired};")
        if current := self.flag("SFCCURRENTSTEP"):
            self.line(f"{current} := '';")
            for slots in (s for s in self.plan.steps.values() if s.owner is None):
                self.line(f"IF {slots.step.name}.X THEN")
                self.line(f"{INDENT}{current} := '{slots.step.name}';")
                self.line("END_IF;")


def _returns(statements: list) -> bool:
    return any(isinstance(node, ast.Return) for node in nodes(statements))


def _items(network: ld.LdNetwork | fbd.FbdNetwork) -> list[object]:
    if isinstance(network, ld.LdNetwork):
        return list(ld.walk(network.elements))
    return list(network.nodes)


def _is_return(item: object) -> bool:
    return getattr(item, "type", None) == "return"


def _string(text: str) -> str:
    return print_expression(ast.StringLit(text))


def _table_shape(table: Symbol) -> tuple[int, int, dict[str, tuple[str, st_types.Type]]]:
    """The bounds and fields of an SFCErrorAnalyzationTable the lowering accepted (ir/sfc_analysis.table_problem)."""
    ty = table.type
    assert isinstance(ty, st_types.ArrayType) and ty.dims[0] is not None
    assert isinstance(ty.element, st_types.StructType)
    low, high = ty.dims[0]
    return low, high, ty.element.fields
