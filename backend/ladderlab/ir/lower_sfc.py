"""SFC POUs -> IR blocks: the chart's evolution, IEC action control and the actions, as plain statements.

Every scan of an SFC POU runs (docs/sfc.md, SFC-04):

1. the flags the user declared (SFCInit, SFCReset: back to the initial step; SFCPause, SFCQuitError: nothing
   runs; SFCTrans is cleared);
2. every step in drawing order: its ``SFC_STEP`` is called (``Step.T``), whether it was entered or left since
   the previous scan (for entry and exit actions), a probe while it is active (its breakpoint), its time limit;
3. every action's ``ACTION_CONTROL`` (IEC 61131-3 figure 15), its inputs the OR of the active steps'
   associations per qualifier; a BOOL variable associated with steps gets the Q of a hidden one;
4. the actions, in passes: exit actions of the steps left, entry actions of the steps entered, the final runs
   (A but not Q, also P1/P0 pulses), the active actions (Q); alphabetical within each pass. Each action's
   body is in the code once, behind a jump; the passes are a loop of jumps, so LD and FBD actions stay networks;
5. the named transitions' bodies, then every transition's condition (also of transitions whose steps are
   not active: the online view shows them), then the transitions that fire, in priority then drawing order,
   each step taken by the first: its steps are left (``Step(X := FALSE)``) and the next ones set; newly active
   steps act from the next scan; SFCTrans, SFCCurrentStep.

Chart statements have origins with the element id (step, transition, association); the statements of actions and
named transitions have ``Origin.body`` (``actions/<name>``, ``transitions/<name>``), their probes and labels a
``<body>/`` prefix (each LD/FBD body has ids and labels of its own).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable

from ..model import fbd, ld
from ..model.project import Pou as ModelPou
from ..model.sfc import TIMED_QUALIFIERS, SfcAction, SfcBody, SfcChart, SfcNamedTransition, SfcStep, walk
from ..model.sfc_graph import ChartGraph, chart_graph
from ..st import ast
from ..st import types as st_types
from ..st.il_check import ACCUMULATOR_PREFIX
from ..st.parser import parse_expression
from ..st.printer import print_expression
from ..st.sfc import action_file, chart_file, il_key, transition_file
from ..st.symbols import PouInfo
from .context import PouContext
from .diagram_operands import At, Operands
from .lower_expr import lower_to
from .lower_fbd import lower_fbd_body
from .lower_il import lower_il
from .lower_ld import lower_ld_body
from .lower_st import lower_statements
from .nodes import (
    Assign,
    Binary,
    Block,
    Case,
    Const,
    Expr,
    FbCall,
    For,
    If,
    Jump,
    Member,
    Origin,
    Probe,
    Repeat,
    Return,
    Stmt,
    Unary,
    Var,
    While,
)
from .sfc_analysis import Analysis, table_problem
from .types import BOOL, Elementary, FbInstance, IrType

TIME = Elementary("TIME")
INT = Elementary("INT")
TRUE, FALSE = Const(True, BOOL), Const(False, BOOL)

#: The SFC flags a POU may declare (SFC-07), by upper-case name: BOOL or STRING.
BOOL_FLAGS = (
    "SFCINIT",
    "SFCRESET",
    "SFCPAUSE",
    "SFCERROR",
    "SFCENABLELIMIT",
    "SFCTRANS",
    "SFCQUITERROR",
    "SFCTIP",
    "SFCTIPMODE",
)
STRING_FLAGS = ("SFCERRORSTEP", "SFCERRORPOU", "SFCCURRENTSTEP", "SFCERRORANALYZATION")
#: ARRAY [0..n] OF ExpressionResult: the parts of the conditions that held a timed-out step (ir/sfc_analysis.py).
TABLE_FLAG = "SFCERRORANALYZATIONTABLE"

#: The inputs of ACTION_CONTROL by qualifier (S is S0 there).
PIN = {
    "N": "N",
    "R": "R",
    "S": "S0",
    "L": "L",
    "D": "D",
    "P": "P",
    "P1": "P1",
    "P0": "P0",
    "SD": "SD",
    "DS": "DS",
    "SL": "SL",
}

END_LABEL = "__SFC_END"
PASS_LABEL = "__SFC_PASS"
#: The action passes of a scan, in order (see the module docstring).
EXIT_PASS, ENTRY_PASS, FINAL_PASS, ACTIVE_PASS = 0, 1, 2, 3


#: The suffix of the probe of a transition's condition (``t3.COND``), computed every scan.
CONDITION_PROBE = ".COND"


def condition_probe(element: str) -> str:
    return f"{element}{CONDITION_PROBE}"


def lower_sfc_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """The chart, actions and transitions of an SFC POU as IR blocks; problems are reported on ``ctx``."""
    return SfcLowering(pou, ctx).blocks()


def _and(*terms: Expr) -> Expr:
    out: Expr | None = None
    for term in terms:
        out = term if out is None else Binary("AND", out, term, BOOL)
    return out if out is not None else TRUE


def _or(terms: Iterable[Expr]) -> Expr:
    out: Expr | None = None
    for term in terms:
        out = term if out is None else Binary("OR", out, term, BOOL)
    return out if out is not None else FALSE


def _not(term: Expr) -> Expr:
    return Unary("NOT", term, BOOL)


def _member(var: Var, name: str, ty: IrType) -> Var:
    return Var(var.scope, var.name, ty, (*var.path, Member(name)))


@dataclasses.dataclass
class StepSlots:
    """What the lowering keeps of one step: its variable and, for a step with entry or exit actions, the flags."""

    step: SfcStep
    var: Var
    initial: bool
    owner: str | None = None  # the SFC action whose chart it is in (upper case), None: the POU's chart
    entered: Var | None = None  # set by the transition that activates it, read in the next scan
    left: Var | None = None
    memory: Var | None = None  # X in the previous scan (an activation by a write online)
    entering: Var | None = None  # this scan: entered (VAR_TEMP)
    leaving: Var | None = None
    taken: Var | None = None  # a transition leaving it fired in this scan (VAR_TEMP)

    @property
    def x(self) -> Var:
        return _member(self.var, "X", BOOL)

    @property
    def t(self) -> Var:
        return _member(self.var, "T", TIME)


class Control:
    """One action control block (an action's, or the hidden one of a BOOL variable) and its associations."""

    def __init__(self, name: str, var: Var, target: Var | None = None):
        self.name = name
        self.var = var
        self.target = target  # the BOOL variable that takes Q
        self.inputs: dict[str, list[str]] = {}  # ACTION_CONTROL pin -> the steps (upper-case names) feeding it
        self.times: list[tuple[str, Expr, str, str]] = []  # (step, time, its text, association id)
        self.owner: str | None = None  # the chart whose steps feed it: None (the POU's) or an SFC action's

    def member(self, pin: str) -> Var:
        return _member(self.var, pin, BOOL)


class SfcLowering:
    def __init__(self, pou: ModelPou, ctx: PouContext):
        self.pou = pou
        assert isinstance(pou.body, SfcBody) and ctx.info is not None
        self.body = pou.body
        self.ctx = ctx
        self.info = ctx.info
        self.name = ctx.name
        self.chart = chart_file(pou.name)
        self.ops = Operands(ctx, "SFC")
        self.steps: dict[str, StepSlots] = {}
        self.controls: dict[str, Control] = {}
        self.flags: dict[str, Var] = {}
        self.analysis: Analysis | None = None
        self.jumps_to_end = False
        self.refused = False
        self.graph_made: ChartGraph | None = None
        #: the charts of the actions written in SFC, by upper-case action name (run as their action's body)
        self.inner: dict[str, ChartGraph] = {}
        self.inner_conditions: dict[str, list[Stmt]] = {}
        #: the chart each action is used in (associated, entry or exit): None (the POU's) or an SFC action's name
        self.used_in: dict[str, str | None] = {}
        self.condition_vars: dict[int, Var] = {}  # id of a graph transition -> its condition's flag
        self.passes_made: dict[str | None, list[tuple[SfcAction, dict[int, list[str]]]]] = {}

    # ------------------------------------------------------------ helpers
    def origin(self, element: str | None = None) -> Origin:
        return Origin(self.name, element=element)

    def report(
        self, code: str, message: str, element: str | None = None, file: str | None = None, severity: str = "error"
    ) -> None:
        self.ctx.report(code, message, element=element, file=file or self.chart, severity=severity)

    def implicit(self, name: str) -> Var:
        return self.ctx.var_for(self.info.symbols[name.upper()])

    def errors(self) -> bool:
        return any(d.severity == "error" and d.pou == self.info.name for d in self.ctx.diagnostics)

    # ------------------------------------------------------------ the whole body
    def blocks(self) -> list[Block]:
        before = len(self.ctx.diagnostics)
        graph = self.graph()
        if graph is None:
            return []
        self.ctx.default_file = self.chart
        try:
            self.declare_steps(graph)
            for owner, inner in self.inner.items():
                self.declare_steps(inner, owner)
            if self.refused:
                return []
            self.find_flags()
            self.make_controls()
            self.associate(graph)
            for owner, inner in self.inner.items():
                self.ctx.default_file = self.inner_file(owner)
                self.associate(inner, owner)
            self.ctx.default_file = self.chart
            self.check_nesting()
            transitions = self.conditions(graph)
            for owner, inner in self.inner.items():
                self.ctx.default_file = self.inner_file(owner)
                self.inner_conditions[owner] = self.conditions(inner)
        finally:
            self.ctx.default_file = None
        actions = self.action_blocks(None)
        named = self.named_transition_blocks()
        if self.ops.errors_since(before) or any(d.severity == "error" for d in self.ctx.diagnostics[before:]):
            return []
        out = [
            Block(self.prologue(graph), self.origin()),
            Block(self.step_phase(None), self.origin()),
            Block(self.control_phase(None), self.origin()),
            *actions,
            *named,
            Block(transitions + self.evolution(graph), self.origin()),
        ]
        if self.jumps_to_end:
            out.append(Block([], self.origin(), END_LABEL))
        return out

    def graph(self) -> ChartGraph | None:
        graph = self.graph_made = chart_graph(self.body.chart)
        for problem in graph.problems:
            self.report(problem.code, problem.message, problem.element or None, severity=problem.severity)
        failed = any(p.severity == "error" for p in graph.problems)
        seen = {e.id for e in walk(self.body.chart.elements)}
        for action in self.body.actions:
            if not isinstance(action.body, SfcChart):
                continue
            inner = chart_graph(action.body)
            file = action_file(self.pou.name, action.name)
            for problem in inner.problems:
                self.report(problem.code, problem.message, problem.element or None, file, problem.severity)
            failed = failed or any(p.severity == "error" for p in inner.problems)
            for element in walk(action.body.elements):
                if element.id in seen:
                    message = f"the id {element.id!r} is used in another chart of the POU"
                    self.report("SFC-DUPLICATE", message, element.id, file)
                    failed = True
                seen.add(element.id)
            self.inner[action.name.upper()] = inner
        return None if failed else graph

    def inner_name(self, owner: str) -> str:
        """An SFC action's name as written (``owner`` is upper case)."""
        action = self.body.action(owner)
        return action.name if action else owner

    def inner_file(self, owner: str) -> str:
        return action_file(self.pou.name, self.inner_name(owner))

    def check_nesting(self) -> None:
        """An action is used in one chart only (its body is in the code once); an SFC action is not used as an entry
        or exit action (it runs while its Q is TRUE) and not inside its own chart, however deep."""
        for owner in self.inner:
            seen = {owner}
            parent = self.used_in.get(owner, "")
            while parent:
                if parent in seen:
                    self.report(
                        "SFC-ACTION",
                        f"the action {self.inner_name(owner)} is written in SFC and is used inside its own chart",
                        file=self.inner_file(owner),
                    )
                    break
                seen.add(parent)
                parent = self.used_in.get(parent, "")

    # ------------------------------------------------------------ steps, flags, associations
    def declare_steps(self, graph: ChartGraph, owner: str | None = None) -> None:
        for key, node in graph.steps.items():
            symbol = self.info.symbols.get(key)
            if symbol is None or symbol.implicit != "step":
                self.refused = True  # its name was refused (reported by the checker): the chart cannot be built
                continue
            slots = StepSlots(node.step, self.ctx.var_for(symbol), node.initial, owner)
            if node.step.entry or node.step.exit:
                hint = f"SFC_{key}"
                slots.entered = self.ctx.hidden(f"{hint}_IN", BOOL)
                slots.left = self.ctx.hidden(f"{hint}_OUT", BOOL)
                slots.memory = self.ctx.hidden(f"{hint}_M", BOOL)
                slots.entering = self.ctx.hidden(f"{hint}_ENTERING", BOOL, var_class="VAR_TEMP")
                slots.leaving = self.ctx.hidden(f"{hint}_LEAVING", BOOL, var_class="VAR_TEMP")
            self.steps[key] = slots
            for which in ("entry", "exit"):
                name = getattr(node.step, which)
                action = self.body.action(name) if name else None
                if name and action is None:
                    self.report(
                        "SFC-ACTION",
                        f"the {which} action of step {node.step.name} is {name!r}, which is no action of this POU",
                        node.step.id,
                        None if owner is None else self.inner_file(owner),
                    )
                elif action is not None:
                    if isinstance(action.body, SfcChart):
                        self.report(
                            "SFC-ACTION",
                            f"the {which} action of step {node.step.name} is {action.name}, which is written in SFC: "
                            "a chart runs while its action is active, so associate it (N) instead",
                            node.step.id,
                            None if owner is None else self.inner_file(owner),
                        )
                    self.use(action.name, owner, node.step.id)
        fan_out: dict[str, int] = {}
        for transition in graph.transitions:
            for source in transition.sources:
                fan_out[source] = fan_out.get(source, 0) + 1
        for key, count in fan_out.items():
            if count > 1 and key in self.steps:
                self.steps[key].taken = self.ctx.hidden(f"SFC_{key}_TAKEN", BOOL, var_class="VAR_TEMP")

    def find_flags(self) -> None:
        for name in (*BOOL_FLAGS, *STRING_FLAGS):
            symbol = self.info.symbols.get(name) or self.ctx.checked.globals.get(name)
            if symbol is None or symbol.implicit is not None:
                continue
            wanted = "BOOL" if name in BOOL_FLAGS else "STRING"
            ok = (
                st_types.same(symbol.type, st_types.BOOL)
                if wanted == "BOOL"
                else isinstance(symbol.type, st_types.StringType)
            )
            if not ok:
                self.report(
                    "SFC-FLAG",
                    f"the SFC flag {symbol.name} must be a {wanted}, not {symbol.type}",
                    file=f"{self.pou.name}/declarations" if symbol.pou else "globals",
                )
                continue
            self.flags[name] = self.ctx.var_for(symbol)
        symbol = self.info.symbols.get(TABLE_FLAG) or self.ctx.checked.globals.get(TABLE_FLAG)
        if symbol is not None and symbol.implicit is None:
            problem = table_problem(symbol)
            if problem is not None:
                self.report("SFC-FLAG", problem, file=f"{self.pou.name}/declarations" if symbol.pou else "globals")
            else:
                self.flags[TABLE_FLAG] = self.ctx.var_for(symbol)
        table, text = self.flag(TABLE_FLAG), self.flag("SFCERRORANALYZATION")
        if table is not None or text is not None:
            self.analysis = Analysis(self.ctx, self.info, self.ops, table, text)

    def use(self, action: str, owner: str | None, element: str) -> None:
        """Records the chart an action is used in; a second chart is a located error."""
        key = action.upper()
        if key in self.used_in and self.used_in[key] != owner:
            where = lambda o: "the POU's chart" if o is None else f"the chart of action {self.inner_name(o)}"  # noqa: E731
            self.report(
                "SFC-ACTION",
                f"the action {action} is used in {where(self.used_in[key])} and in {where(owner)}: an action belongs "
                "to one chart",
                element,
                None if owner is None else self.inner_file(owner),
            )
            return
        self.used_in[key] = owner

    def make_controls(self) -> None:
        for action in sorted(self.body.actions, key=lambda a: a.name.upper()):
            symbol = self.info.symbols.get(action.name.upper())
            if symbol is not None and symbol.implicit == "action":
                self.controls[action.name.upper()] = Control(action.name, self.ctx.var_for(symbol))

    def associate(self, graph: ChartGraph, owner: str | None = None) -> None:
        for node in graph.steps.values():
            slots = self.steps.get(node.step.name.upper())
            if slots is None:
                continue
            for association in node.step.actions:
                control = self.control_for(association.action, association.id)
                if control is None:
                    continue
                self.use(control.name, owner, association.id)
                control.owner = owner
                pin = PIN[association.qualifier]
                control.inputs.setdefault(pin, []).append(node.step.name.upper())
                timed = association.qualifier in TIMED_QUALIFIERS
                if timed and not (association.time or "").strip():
                    self.report(
                        "SFC-TIME", f"the qualifier {association.qualifier} needs a time (e.g. T#5s)", association.id
                    )
                elif not timed and (association.time or "").strip():
                    self.report("SFC-TIME", f"the qualifier {association.qualifier} takes no time", association.id)
                elif timed:
                    value, _ = self.ops.read(
                        association.time or "", At(None, association.id), "the time", st_types.Elementary("TIME")
                    )
                    if value is not None:
                        control.times.append((node.step.name.upper(), value, association.time or "", association.id))
            for which in ("min_time", "max_time"):
                text = getattr(node.step, which)
                if text is not None and text.strip():
                    self.ops.read(
                        text, At(None, node.step.id), f"the {which.replace('_', ' ')}", st_types.Elementary("TIME")
                    )
        if owner is None and any(s.step.max_time for s in self.steps.values()) and "SFCERROR" not in self.flags:
            self.report(
                "SFC-FLAG",
                "a step has a maximum time, but the POU declares no SFCError: the limit is not checked "
                "(declare SFCError : BOOL, SFCErrorStep : STRING ...)",
                next(s.step.id for s in self.steps.values() if s.step.max_time),
                severity="warning",
            )

    def control_for(self, target: str, element: str) -> Control | None:
        """The control block of an association's action, or of the BOOL variable it names (made once per text)."""
        key = target.strip().upper()
        if key in self.controls:
            return self.controls[key]
        if self.body.action(target) is not None:
            return None  # an action whose name was refused (reported by the checker)
        text = " ".join(target.split())
        key = f"VAR {text.upper()}"
        if key in self.controls:
            return self.controls[key]
        node = self.ops.parse(text, At(None, element), "the association")
        if node is None:
            return None
        checker = self.ops.checker(At(None, element))
        ty = checker.target(node)
        if ty is st_types.ERROR:
            return None
        if not st_types.same(ty, st_types.BOOL):
            self.report(
                "SFC-ACTION", f"{text!r} is no action of this POU, and as a variable it is {ty}, not BOOL", element
            )
            return None
        var = self.ops.access(node, At(None, element))
        if var is None:
            return None
        hidden = self.ctx.hidden(f"SFC_{text}", FbInstance("ACTION_CONTROL"))
        control = self.controls[key] = Control(text, hidden, var)
        return control

    # ------------------------------------------------------------ 1. the flags
    def flag(self, name: str) -> Var | None:
        return self.flags.get(name)

    def prologue(self, graph: ChartGraph) -> list[Stmt]:
        out: list[Stmt] = []
        origin = self.origin()
        if (trans := self.flag("SFCTRANS")) is not None:
            out.append(Assign(trans, FALSE, origin))
        resets = [f for f in (self.flag("SFCINIT"), self.flag("SFCRESET")) if f is not None]
        if resets:
            out.append(If([(_or(resets), self.reset_chart(graph))], [], origin))
        holds = [f for f in (self.flag("SFCINIT"), self.flag("SFCPAUSE")) if f is not None]
        if holds:
            out.append(self.to_end(_or(holds)))
        quit_ = self.flag("SFCQUITERROR")
        if quit_ is not None:
            memory = self.ctx.hidden("SFC_QUIT_M", BOOL)
            restart: list[Stmt] = []
            for slots in self.steps.values():
                restart.append(
                    If([(slots.x, [self.call_step(slots, False), Assign(slots.x, TRUE, origin)])], [], origin)
                )
            out.append(If([(_and(memory, _not(quit_)), restart)], [], origin))
            out.append(Assign(memory, quit_, origin))
            out.append(If([(quit_, self.clear_error())], [], origin))
            out.append(self.to_end(quit_))
        return out

    def to_end(self, cond: Expr) -> Jump:
        self.jumps_to_end = True
        return Jump(END_LABEL, cond, self.origin())

    def clear_error(self) -> list[Stmt]:
        origin = self.origin()
        out: list[Stmt] = []
        if (error := self.flag("SFCERROR")) is not None:
            out.append(Assign(error, FALSE, origin))
        for name in ("SFCERRORSTEP", "SFCERRORPOU"):
            if (flag := self.flag(name)) is not None:
                out.append(Assign(flag, Const("", flag.type), origin))
        if self.analysis is not None:
            out += self.analysis.clear(origin)
        return out

    def reset_chart(self, graph: ChartGraph) -> list[Stmt]:
        """SFCInit / SFCReset: every step left without its exit action, the initial step active and entered anew,
        every action control reset (R, every other input FALSE: stored actions end, no final run follows)."""
        origin = self.origin()
        out: list[Stmt] = []
        for slots in self.steps.values():
            out.append(self.call_step(slots, False))
            for flag in (slots.memory, slots.entered, slots.left):
                if flag is not None:
                    out.append(Assign(flag, FALSE, origin))
        for slots in self.steps.values():
            if slots.initial:  # of the POU's chart and of every action's chart
                out.append(Assign(slots.x, TRUE, origin))
        initial = next((s for s in self.steps.values() if s.initial and s.owner is None), None)
        for control in self.controls.values():
            inputs = [(pin, FALSE) for pin in PIN.values() if pin in control.inputs and pin != "R"] + [("R", TRUE)]
            out.append(FbCall(control.var, inputs, [], origin))
            if control.target is not None:
                out.append(Assign(control.target, control.member("Q"), origin))
        out += self.clear_error()
        if (current := self.flag("SFCCURRENTSTEP")) is not None and initial is not None:
            out.append(Assign(current, Const(initial.step.name, current.type), origin))
        return out

    def call_step(self, slots: StepSlots, x: bool | None = None) -> FbCall:
        inputs = [] if x is None else [("X", TRUE if x else FALSE)]
        return FbCall(slots.var, inputs, [], self.origin(slots.step.id))

    # ------------------------------------------------------------ 2. the steps
    def step_phase(self, owner: str | None) -> list[Stmt]:
        out: list[Stmt] = []
        for slots in self.steps.values():
            if slots.owner != owner:
                continue
            origin = self.origin(slots.step.id)
            out.append(self.call_step(slots))
            if slots.memory is not None:
                assert slots.entering and slots.leaving and slots.entered and slots.left
                out += [
                    Assign(slots.entering, _or([slots.entered, _and(slots.x, _not(slots.memory))]), origin),
                    Assign(slots.leaving, _or([slots.left, _and(_not(slots.x), slots.memory)]), origin),
                    Assign(slots.memory, slots.x, origin),
                    Assign(slots.entered, FALSE, origin),
                    Assign(slots.left, FALSE, origin),
                ]
            out.append(If([(slots.x, [Probe(slots.step.id, TRUE, origin)])], [], origin))
            limit = self.time_limit(slots)
            if limit is not None:
                out.append(limit)
        return out

    def time_limit(self, slots: StepSlots) -> Stmt | None:
        """SFC-07: a step active longer than its maximum time sets SFCError (the first error only, until reset)."""
        error = self.flag("SFCERROR")
        text = slots.step.max_time
        if error is None or not (text or "").strip():
            return None
        limit, _ = self.ops.read(text or "", At(None, slots.step.id), "the maximum time", st_types.Elementary("TIME"))
        if limit is None:
            return None
        origin = self.origin(slots.step.id)
        terms = [slots.x, _not(error), Binary("GT", slots.t, limit, BOOL)]
        if (enable := self.flag("SFCENABLELIMIT")) is not None:
            terms.insert(0, enable)
        record: list[Stmt] = [Assign(error, TRUE, origin)]
        if (where := self.flag("SFCERRORSTEP")) is not None:
            record.append(Assign(where, Const(slots.step.name, where.type), origin))
        if (pou := self.flag("SFCERRORPOU")) is not None:
            record.append(Assign(pou, Const(self.pou.name, pou.type), origin))
        graph = self.graph_made if slots.owner is None else self.inner.get(slots.owner)
        if self.analysis is not None and graph is not None:
            key = slots.step.name.upper()
            leaving = [t.transition for t in graph.evaluation_order() if key in t.sources]
            record += self.analysis.record([(t.condition, t.id) for t in leaving], origin)
        return If([(_and(*terms), record)], [], origin)

    # ------------------------------------------------------------ 3. action control
    def control_phase(self, owner: str | None) -> list[Stmt]:
        out: list[Stmt] = []
        origin = self.origin()
        for control in self.controls.values():
            if not control.inputs or control.owner != owner:
                continue
            for step, time, _, element in control.times:
                assign = Assign(_member(control.var, "T", TIME), time, self.origin(element))
                out.append(If([(self.steps[step].x, [assign])], [], origin))
            inputs = [
                (pin, _or(self.steps[key].x for key in control.inputs[pin]))
                for pin in PIN.values()
                if pin in control.inputs
            ]
            if "R" not in control.inputs:
                inputs.append(("R", FALSE))  # after SFCInit/SFCReset set it
            out.append(FbCall(control.var, inputs, [], origin))
            if control.target is not None:
                out.append(Assign(control.target, control.member("Q"), origin))
        return out

    # ------------------------------------------------------------ 4. the actions
    def action_passes(self, owner: str | None = None) -> list[tuple[SfcAction, dict[int, list[str]]]]:
        """Every action of one chart (``owner``: None for the POU's, else the SFC action's; alphabetical) with the
        passes it runs in: EXIT_PASS and ENTRY_PASS with the steps (upper case) whose leaving or entering runs it,
        FINAL_PASS and ACTIVE_PASS (no steps) when steps associate it. (The ST export writes the same passes: made
        once per chart, so an unused action is reported once.)"""
        if owner in self.passes_made:
            return self.passes_made[owner]
        out = self.passes_made[owner] = []
        for action in sorted(self.body.actions, key=lambda a: a.name.upper()):
            key = action.name.upper()
            if self.used_in.get(key) != owner:
                continue
            passes: dict[int, list[str]] = {}
            for name, slots in self.steps.items():
                if slots.leaving is not None and (slots.step.exit or "").upper() == key:
                    passes.setdefault(EXIT_PASS, []).append(name)
                if slots.entering is not None and (slots.step.entry or "").upper() == key:
                    passes.setdefault(ENTRY_PASS, []).append(name)
            control = self.controls.get(key)
            if control is not None and control.inputs:
                passes[FINAL_PASS] = passes[ACTIVE_PASS] = []
            if not passes:
                self.report(
                    "SFC-UNUSED",
                    f"the action {action.name} is not associated with any step: it never runs",
                    file=action_file(self.pou.name, action.name),
                    severity="warning",
                )
            out.append((action, passes))
        return out

    def action_blocks(self, owner: str | None) -> list[Block]:
        """Each action's body once, behind a jump that skips it unless this pass runs it; the passes loop (one loop
        per chart: the POU's, and inside an SFC action's body its own)."""
        suffix = "" if owner is None else f"_{owner}"
        counter = self.ctx.hidden(f"SFC_PASS{suffix}", INT, var_class="VAR_TEMP")
        loop = f"{PASS_LABEL}{suffix}"
        runs: list[tuple[SfcAction, Expr]] = []
        passes: set[int] = set()
        for action, wanted in self.action_passes(owner):
            passes |= set(wanted)
            control = self.controls.get(action.name.upper())
            terms: list[Expr] = []
            for number, keys in sorted(wanted.items()):
                if number == FINAL_PASS and control is not None:
                    when = _and(control.member("A"), _not(control.member("Q")))
                elif number == ACTIVE_PASS and control is not None:
                    when = control.member("Q")
                else:
                    flags = [getattr(self.steps[k], "leaving" if number == EXIT_PASS else "entering") for k in keys]
                    when = _or(flag for flag in flags if flag is not None)
                terms.append(_and(Binary("EQ", counter, Const(number, INT), BOOL), when))
            runs.append((action, _or(terms)))
        if not passes:
            for action, _ in runs:
                self.action_body(action, "")  # checked all the same
            return []
        first, last = min(passes), max(passes)
        origin = self.origin()
        blocks = [Block([Assign(counter, Const(first, INT), origin)], origin), Block([], origin, loop)]
        for action, run in runs:
            skip = f"__SFC_SKIP_{action.name.upper()}"
            body = self.action_body(action, skip)
            if run == FALSE or not body:
                continue
            blocks.append(Block([Jump(skip, _not(run), origin)], origin))
            blocks += body
            blocks.append(Block([], origin, skip))
        more = Binary("LE", counter, Const(last, INT), BOOL)
        blocks.append(
            Block(
                [Assign(counter, Binary("ADD", counter, Const(1, INT), INT), origin), Jump(loop, more, origin)],
                origin,
            )
        )
        return blocks

    def action_body(self, action: SfcAction, skip: str) -> list[Block]:
        body = f"actions/{action.name}"
        self.ctx.default_file = action_file(self.pou.name, action.name)
        try:
            if action.language == "st":
                statements = self.info.actions.get(action.name.upper())
                if statements is None:
                    return []
                return [
                    Block(
                        _rebody(lower_statements(statements, self.ctx), body, skip, self.ctx),
                        Origin(self.name, body=body),
                    )
                ]
            if action.language == "il":
                il = self.info.il_parts.get(il_key("actions", action.name))
                if il is None:
                    return []
                return self.rebodied(lower_il(il.statements, il.accumulators, il.values, self.ctx), body, skip)
            if isinstance(action.body, (ld.LdBody, fbd.FbdBody)):
                return self.diagram(action.body, action.language, body, skip)
            if isinstance(action.body, SfcChart):
                return self.inner_chart(action)
            return []
        finally:
            self.ctx.default_file = None

    def inner_chart(self, action: SfcAction) -> list[Block]:
        """The body of an action written in SFC: its chart's scan while the action is active (Q); in its final run
        (Q FALSE) the chart closes: its steps are left (their exit actions and the final runs of their actions
        run), no transition fires, and its initial step is set again for the next activation (docs/sfc.md)."""
        owner = action.name.upper()
        graph = self.inner.get(owner)
        control = self.controls.get(owner)
        if graph is None or control is None:
            return []
        origin = Origin(self.name, body=f"actions/{action.name}")
        closing = self.ctx.hidden(f"SFC_{owner}_CLOSING", BOOL, var_class="VAR_TEMP")
        mine = [slots for slots in self.steps.values() if slots.owner == owner]
        start: list[Stmt] = [Assign(closing, _not(control.member("Q")), origin)]
        start.append(If([(closing, [self.call_step(slots, False) for slots in mine])], [], origin))
        blocks = [Block(start + self.step_phase(owner) + self.control_phase(owner), origin)]
        blocks += self.action_blocks(owner)
        closed = f"__SFC_CLOSED_{owner}"
        blocks.append(Block([Jump(closed, closing, origin)], origin))
        blocks.append(Block(self.inner_conditions.get(owner, []) + self.evolution(graph, owner), origin))
        reopen = [Assign(slots.x, TRUE, origin) for slots in mine if slots.initial]
        blocks.append(Block([If([(closing, reopen)], [], origin)], origin, closed))
        return blocks

    def diagram(self, networks: ld.LdBody | fbd.FbdBody, language: str, body: str, skip: str) -> list[Block]:
        stand_in = self.pou.model_copy(update={"language": language, "body": networks})
        lowered = (lower_ld_body if language == "ld" else lower_fbd_body)(stand_in, self.ctx)
        return self.rebodied(lowered, body, skip)

    def rebodied(self, lowered: list[Block], body: str, skip: str) -> list[Block]:
        """The blocks of an LD, FBD or IL action or transition as part of the SFC POU (see ``_rebody``); labels get
        the ``<body>/`` prefix too."""
        out = []
        for block in lowered:
            block.statements = _rebody(block.statements, body, skip, self.ctx)
            out.append(
                Block(
                    block.statements,
                    dataclasses.replace(block.origin, body=body),
                    f"{body}/{block.label}" if block.label else None,
                )
            )
        return out

    # ------------------------------------------------------------ 5. transitions
    def named_transition_blocks(self) -> list[Block]:
        out: list[Block] = []
        for transition in self.body.transitions:
            symbol = self.info.symbols.get(transition.name.upper())
            if symbol is None or symbol.implicit != "transition":
                continue
            body = f"transitions/{transition.name}"
            self.ctx.default_file = transition_file(self.pou.name, transition.name)
            try:
                out += self.named_transition(transition, self.ctx.var_for(symbol), body)
            finally:
                self.ctx.default_file = None
        return out

    def named_transition(self, transition: SfcNamedTransition, result: Var, body: str) -> list[Block]:
        origin = Origin(self.name, body=body)
        if transition.language == "il":
            return self.il_transition(transition, result, body)
        if isinstance(transition.body, str):
            value = self.condition(transition.body, None, "the transition")
            return [Block([Assign(result, value, origin)], origin)] if value is not None else []
        diagram = transition.body
        self.check_transition_diagram(transition, diagram)
        skip = f"__SFC_END_{transition.name.upper()}"
        blocks = [Block([Assign(result, FALSE, origin)], origin)]
        blocks += self.diagram(diagram, transition.language, body, skip)
        blocks.append(Block([], origin, skip))
        return blocks

    def il_transition(self, transition: SfcNamedTransition, result: Var, body: str) -> list[Block]:
        """A transition written in IL (as in CODESYS): its value is the accumulator after the last instruction, a
        BOOL. SFC-03: it assigns nothing (no ST, STN, S, R), calls no FB instance or program (CAL, FB input
        operators) and does not end early (RET: the accumulator then is no value of the end)."""
        il = self.info.il_parts.get(il_key("transitions", transition.name))
        if il is None:
            return []
        origin = Origin(self.name, body=body)
        problems = 0
        for statement in il.statements:
            problem = _il_transition_problem(statement, transition.name)
            if problem is not None:
                self.ctx.report("SFC-CONDITION", problem, line=statement.span.line, column=statement.span.column)
                problems += 1
        end = il.end
        if end is None or not st_types.same(end.type, st_types.BOOL):
            held = f"holds {end.type}" if end is not None else "holds no one value"
            self.ctx.report(
                "SFC-CONDITION",
                f"the transition {transition.name} is the accumulator after its last line, a BOOL: there it {held}",
                line=end.line if end is not None else None,
            )
            return []
        if problems:
            return []
        blocks = self.rebodied(lower_il(il.statements, il.accumulators, il.values, self.ctx), body, "")
        value = lower_to(end.value, self.ctx, BOOL)
        blocks.append(Block([Assign(result, value, origin)], origin))
        return blocks

    def check_transition_diagram(self, transition: SfcNamedTransition, diagram: ld.LdBody | fbd.FbdBody) -> None:
        """SFC-03: a transition written in LD or FBD gives its value to a coil or output named like it, and
        neither assigns anything else nor calls an FB instance."""
        name = transition.name.upper()
        writes = 0
        for network in diagram.networks:
            items = ld.walk(network.elements) if isinstance(network, ld.LdNetwork) else network.nodes
            for item in items:
                target = getattr(item, "var", None)
                if item.type in ("coil", "output") and target is not None:
                    if target.strip().upper() == name:
                        writes += 1
                    else:
                        self.ctx.report(
                            "SFC-CONDITION",
                            f"a transition cannot assign {target.strip()}: it only gives its "
                            f"own value ({transition.name})",
                            network=network.id,
                            element=item.id,
                        )
                instance = getattr(item, "instance", None) if item.type in ("box", "block") else None
                if instance:
                    self.ctx.report(
                        "SFC-CONDITION",
                        f"a transition cannot call the function block instance {instance}: call it in an action",
                        network=network.id,
                        element=item.id,
                    )
        if not writes:
            self.ctx.report(
                "SFC-CONDITION",
                f"nothing sets the transition {transition.name}: add a coil or output named {transition.name}",
                severity="warning",
            )

    def condition(self, text: str, element: str | None, what: str) -> Expr | None:
        """An ST condition (SFC-03): a BOOL expression without assignment, output or in-out argument."""
        at = At(None, element)
        if ":=" in text and parse_expression(text).ast is None:
            self.ops.report(at, "SFC-CONDITION", f"{what} is a condition, not a statement: it cannot assign (:=)")
            return None
        value, _ = self.ops.read(text, at, what, st_types.BOOL)
        if value is None:
            return None
        parsed = parse_expression(text).ast
        if parsed is not None:
            self.ops.checker(at).expr(parsed)
            for call in _calls(parsed):
                if any(arg.output for arg in call.args):
                    self.ops.report(at, "SFC-CONDITION", f"{what} cannot assign through an output (=>) of a call")
                    return None
                ref = call.ref
                if isinstance(ref, PouInfo) and ref.parameters("VAR_IN_OUT"):
                    self.ops.report(
                        at, "SFC-CONDITION", f"{what} cannot call {ref.name}: its VAR_IN_OUT may change a variable"
                    )
                    return None
        return value

    def conditions(self, graph: ChartGraph) -> list[Stmt]:
        """Every chart transition's condition into a hidden flag, with a probe: its value for the online view."""
        out: list[Stmt] = []
        for transition in graph.transitions:
            element = transition.transition
            value = self.condition(element.condition, element.id, "the condition")
            flag = self.ctx.hidden(f"SFC_{element.id}_C", BOOL, var_class="VAR_TEMP")
            self.condition_vars[id(transition)] = flag
            origin = self.origin(element.id)
            if value is not None:
                out.append(Assign(flag, value, origin))
                out.append(Probe(condition_probe(element.id), flag, self.origin()))
        return out

    def evolution(self, graph: ChartGraph, owner: str | None = None) -> list[Stmt]:
        out: list[Stmt] = []
        fired: dict[int, Var] = {}
        tip = self.flag("SFCTIP")
        tip_mode = self.flag("SFCTIPMODE")
        for transition in graph.evaluation_order():
            element = transition.transition
            origin = self.origin(element.id)
            sources = [self.steps[s] for s in transition.sources if s in self.steps]
            terms: list[Expr] = []
            for slots in sources:
                terms.append(slots.x)
                if slots.taken is not None:
                    terms.append(_not(slots.taken))
                if slots.step.min_time and slots.step.min_time.strip():
                    least, _ = self.ops.read(
                        slots.step.min_time, At(None, slots.step.id), "the minimum time", st_types.Elementary("TIME")
                    )
                    if least is not None:
                        terms.append(Binary("GE", slots.t, least, BOOL))
            terms.append(self.condition_vars[id(transition)])
            if tip_mode is not None:
                terms.append(_or([_not(tip_mode), tip if tip is not None else FALSE]))
            flag = fired[id(transition)] = self.ctx.hidden(f"SFC_{element.id}_F", BOOL, var_class="VAR_TEMP")
            out.append(Assign(flag, _and(*terms), origin))
            then: list[Stmt] = [Assign(s.taken, TRUE, origin) for s in sources if s.taken is not None]
            then.append(Probe(element.id, TRUE, origin, kind="transition"))
            out.append(If([(flag, then)], [], origin))
        for transition in graph.transitions:  # leave, then enter: a step both left and entered stays active
            origin = self.origin(transition.transition.id)
            leave: list[Stmt] = []
            for key in transition.sources:
                slots = self.steps[key]
                leave.append(self.call_step(slots, False))
                if slots.left is not None:
                    leave.append(Assign(slots.left, TRUE, origin))
            out.append(If([(fired[id(transition)], leave)], [], origin))
        for transition in graph.transitions:
            origin = self.origin(transition.transition.id)
            enter: list[Stmt] = []
            for key in transition.targets:
                slots = self.steps[key]
                enter.append(Assign(slots.x, TRUE, origin))
                if slots.entered is not None:
                    enter.append(Assign(slots.entered, TRUE, origin))
            out.append(If([(fired[id(transition)], enter)], [], origin))
        origin = self.origin()
        if owner is not None:  # the flags are about the POU's chart
            return out
        if (trans := self.flag("SFCTRANS")) is not None and fired:
            out.append(Assign(trans, _or(fired.values()), origin))
        if (current := self.flag("SFCCURRENTSTEP")) is not None:
            out.append(Assign(current, Const("", current.type), origin))
            for slots in (s for s in self.steps.values() if s.owner is None):  # drawing order: right-most last
                out.append(If([(slots.x, [Assign(current, Const(slots.step.name, current.type), origin)])], [], origin))
        return out


#: IL operators that assign (SFC-03 forbids them in a transition); CAL and FB input operators become FB calls.
_IL_ASSIGNS = frozenset({"ST", "STN", "S", "R"})


def _il_transition_problem(statement: ast.Stmt, name: str) -> str | None:
    """Why a checked IL statement (st/il_check.py) has no place in a transition, or None."""
    if isinstance(statement, ast.Return) or (
        isinstance(statement, ast.If) and any(isinstance(s, ast.Return) for _, b in statement.branches for s in b)
    ):
        return f"the transition {name} is the accumulator after its last line: RET has no place in it"
    if isinstance(statement, ast.If):
        inner = [s for _, b in statement.branches for s in b]
        return next((p for p in (_il_transition_problem(s, name) for s in inner) if p), None)
    if isinstance(statement, ast.CallStmt):
        callee = getattr(statement.call, "callee", statement.call)
        return f"a transition cannot call {print_expression(callee)}: call it in an action"
    if isinstance(statement, ast.Assign) and not _accumulator(statement.target):
        return f"a transition cannot assign {print_expression(statement.target)}: it only gives its value ({name})"
    return None


def _accumulator(target: ast.Expr) -> bool:
    return isinstance(target, ast.Name) and target.name.upper().startswith(ACCUMULATOR_PREFIX)


def _calls(node: object) -> Iterable[ast.Call]:
    """Every call in an expression AST."""
    todo = [node]
    while todo:
        item = todo.pop()
        if isinstance(item, ast.Call):
            yield item
            todo += [arg.value for arg in item.args]
            todo.append(item.callee)
        elif isinstance(item, (ast.Unary,)):
            todo.append(item.operand)
        elif isinstance(item, ast.Binary):
            todo += [item.left, item.right]
        elif isinstance(item, (ast.Member, ast.Index)):
            todo.append(item.base)
            if isinstance(item, ast.Index):
                todo += list(item.indices)


def _rebody(statements: list[Stmt], body: str, skip: str, ctx: PouContext, loops: int = 0) -> list[Stmt]:
    """The statements of an action or named transition as part of the SFC POU: origins get ``body``, probes and
    labels a ``<body>/`` prefix, a RETURN ends the action (a jump to ``skip``; not from inside a loop)."""
    out: list[Stmt] = []
    for statement in statements:
        origin = dataclasses.replace(statement.origin, body=body)
        if isinstance(statement, Return):
            if loops:
                ctx.report(
                    "IR-UNSUPPORTED",
                    "RETURN inside a loop of an action is not supported: end the loop with EXIT and return after it",
                    line=origin.line,
                    column=origin.column,
                )
                continue
            out.append(Jump(skip, None, origin))
            continue
        statement.origin = origin
        if isinstance(statement, Probe):
            statement.element = f"{body}/{statement.element}"
        elif isinstance(statement, Jump):
            statement.label = f"{body}/{statement.label}"
        elif isinstance(statement, If):
            statement.branches = [(c, _rebody(b, body, skip, ctx, loops)) for c, b in statement.branches]
            statement.orelse = _rebody(statement.orelse, body, skip, ctx, loops)
        elif isinstance(statement, Case):
            statement.branches = [(labels, _rebody(b, body, skip, ctx, loops)) for labels, b in statement.branches]
            statement.orelse = _rebody(statement.orelse, body, skip, ctx, loops)
        elif isinstance(statement, (For, While, Repeat)):
            statement.body = _rebody(statement.body, body, skip, ctx, loops + 1)
        out.append(statement)
    return out
