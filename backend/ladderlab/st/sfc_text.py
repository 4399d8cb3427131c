"""Textual SFC (IEC 61131-3 B.1.6) in .st files: read into the SFC model, and written from it.

Reading: the steps (``INITIAL_STEP``/``STEP`` with their ``action(qualifier[, time])`` associations), the
transitions (``TRANSITION [name] [(PRIORITY := n)] FROM a TO (b, c) := condition; END_TRANSITION``, in the order
written: the earlier of two transitions leaving one step comes first, as the left one of a drawn chart) and the
``ACTION``s (ST, or a chart of their own: IEC's ``ACTION name: function_block_body END_ACTION`` allows an SFC body)
make a graph that ``model.sfc_graph.graph_chart`` draws as a chart; texts keep their source. A named ``TRANSITION``
is a named transition (``:= expression;`` in ST, ``... TO b:`` and an instruction list in IL, blanked for the ST
parser by ``il_parser.blank_il_bodies``) that its chart transition reads by name.
Writing: the chart's graph as the same constructs, ST actions as typed, a transition whose condition is the name of
an ST or IL named transition as that ``TRANSITION name`` (what IEC text cannot say - entry and exit actions, time
limits, actions or named transitions in LD or FBD, a named transition no chart transition has as its condition -
is refused by name, see ``sfc_to_text``).
"""

from __future__ import annotations

import re
import textwrap

from ..model.diagnostics import Diagnostic
from ..model.sfc import (
    QUALIFIERS,
    TIMED_QUALIFIERS,
    SfcAction,
    SfcAssociation,
    SfcBody,
    SfcChart,
    SfcNamedTransition,
    SfcStep,
    SfcTransition,
    prefix_ids,
)
from ..model.sfc_graph import ImportedStep, ImportedTransition, UnstructuredChart, chart_graph, graph_chart
from . import ast
from .il_parser import IL_TRANSITION_HEAD
from .il_words import looks_like_il


def sfc_from_text(pou: ast.Pou, between, file: str | None = None) -> tuple[SfcBody, list[Diagnostic]]:
    """The SfcBody of a POU written in textual SFC; ``between((line, col), (line, col))`` slices the source."""
    assert pou.sfc is not None
    diagnostics: list[Diagnostic] = []

    def report(message: str, node: object, severity: str = "error") -> None:
        span = getattr(node, "span", ast.NO_SPAN)
        diagnostics.append(
            Diagnostic(
                code="ST-SFC",
                message=message,
                severity=severity,
                file=file,
                pou=pou.name,
                line=span.line or None,
                column=span.column or None,
            )
        )

    def text(node: ast.Expr) -> str:
        span = node.span
        return between((span.line, span.column), (span.end_line, span.end_column))

    actions: list[SfcAction] = []
    named: list[SfcNamedTransition] = []
    chart = _chart(pou.sfc, "", (actions, named), report, text, between)
    if chart is None:
        return SfcBody(actions=actions, transitions=named), diagnostics
    return SfcBody(chart=chart, actions=actions, transitions=named), diagnostics


def _chart(sfc: ast.Sfc, owner: str, parts, report, text, between) -> SfcChart | None:
    """The chart of ``sfc`` (``owner``: the action it is the body of, or ""); its actions and named transitions, and
    those of the charts inside them, are added to ``parts`` (the POU's two lists, one for all charts)."""
    actions, named = parts
    steps, transitions = [], []
    for number, item in enumerate(sfc.items, 1):
        if isinstance(item, ast.SfcStep):
            associations = [a for a in (_association(a, number, report, text) for a in item.associations) if a]
            step = SfcStep(id=f"s{number}", name=item.name, actions=associations)
            steps.append(ImportedStep(step, item.initial))
        elif isinstance(item, ast.SfcTransition):
            written = _condition(item, named, report, text, between)
            condition = SfcTransition(id=f"t{number}", condition=written, priority=item.priority)
            transitions.append(ImportedTransition(condition, list(item.sources), list(item.targets)))
        elif isinstance(item.body, ast.Sfc):  # an action written in SFC (docs/sfc.md)
            inner = _chart(item.body, item.name, parts, report, text, between)
            body = prefix_ids(inner, f"{item.name}_") if inner is not None else SfcChart()
            actions.append(SfcAction(name=item.name, language="sfc", body=body))
        elif not item.body and looks_like_il(written := _source_after(item, between, "END_ACTION", _ACTION_HEAD)):
            actions.append(SfcAction(name=item.name, language="il", body=written))  # blanked for the ST parser
        else:
            body = ""
            if item.body:  # to END_ACTION: a statement's span ends before its ';'
                first, end = item.body[0].span, item.span
                body = between((first.line, first.column), (end.end_line, end.end_column - len("END_ACTION"))).rstrip()
            actions.append(SfcAction(name=item.name, language="st", body=body))
    what = f"the chart of action {owner}" if owner else "the chart"
    try:
        chart, unreachable = graph_chart(steps, transitions)
    except UnstructuredChart as error:
        report(f"{what} cannot be drawn: {error}", sfc)
        return None
    for name in unreachable:
        report(f"step {name} is reached from no initial step: it was left out", sfc, "warning")
    return chart


def _condition(item: ast.SfcTransition, named: list[SfcNamedTransition], report, text, between) -> str:
    """The chart condition of a textual transition: its expression, or (a named one) its name, the named transition
    (ST: the expression, IL: the instructions) added to ``named`` the first time the name is met."""
    if item.name is None:
        if item.condition is None:
            report(
                "an IL transition condition is kept as a named transition: give it a name (TRANSITION name FROM)", item
            )
            return "FALSE"
        return text(item.condition)
    if item.condition is None:
        made = SfcNamedTransition(
            name=item.name, language="il", body=_source_after(item, between, "END_TRANSITION", IL_TRANSITION_HEAD)
        )
    else:
        made = SfcNamedTransition(name=item.name, language="st", body=text(item.condition))
    known = next((t for t in named if t.name.upper() == item.name.upper()), None)
    if known is None:
        named.append(made)
    elif (known.language, known.body) != (made.language, made.body):
        report(f"the transition {item.name} is written again with another condition: one name, one condition", item)
    return (known or made).name


_ACTION_HEAD = r"[^:]*:"


def _source_after(item: ast.SfcAction | ast.SfcTransition, between, end: str, head: str) -> str:
    """What an ``ACTION name: ... END_ACTION`` or ``TRANSITION ... TO b: ... END_TRANSITION`` holds after its
    ``head`` in the original text, dedented (the IL instructions blanked for the ST parser)."""
    span = item.span
    text = between((span.line, span.column), (span.end_line, span.end_column - len(end)))
    found = re.match(head, text, re.IGNORECASE)
    inner = text[found.end() :] if found else ""
    return textwrap.dedent(inner.strip("\n").rstrip()).strip("\n")


def _association(item: ast.SfcAssociation, number: int, report, text) -> SfcAssociation | None:
    qualifier = (item.qualifier or "N").upper()
    if qualifier not in QUALIFIERS:
        report(f"{qualifier} is not an action qualifier ({', '.join(QUALIFIERS)})", item)
        return None
    args = list(item.args)
    time = text(args.pop(0)) if qualifier in TIMED_QUALIFIERS and args else None
    if args:
        report(f"the indicator variables of {item.action} are not kept", item, "warning")
    return SfcAssociation(id=f"a{number}_{item.action}", qualifier=qualifier, action=item.action, time=time)  # type: ignore[arg-type]  # checked against QUALIFIERS


def sfc_to_text(name: str, body: SfcBody, indent: str = "    ") -> tuple[str, list[Diagnostic]]:
    """The textual SFC of a chart (steps, transitions, actions: ST, or a chart of their own inside ``ACTION``), and
    why it cannot be written if it cannot."""
    problems: list[Diagnostic] = []

    def refuse(message: str, file: str | None = None) -> None:
        problems.append(Diagnostic(code="EXPORT-UNSUPPORTED", pou=name, file=file, message=message))

    _refuse_named_transitions(name, body, refuse)
    named = {t.name.upper(): t for t in body.transitions if t.language in ("st", "il")}
    lines = _chart_lines(body.chart, indent, 1, refuse, named)
    for action in body.actions:
        if isinstance(action.body, SfcChart):
            lines.append(f"{indent}ACTION {action.name}:")
            lines += _chart_lines(action.body, indent, 2, refuse, named)
            lines.append(f"{indent}END_ACTION")
            continue
        if not isinstance(action.body, str):
            refuse(
                f"the action {action.name} is written in {action.language.upper()}: textual SFC has ST, IL and SFC "
                "actions"
            )
            continue
        lines.append(f"{indent}ACTION {action.name}:")
        lines += [f"{indent * 2}{line}".rstrip() for line in action.body.splitlines()]
        lines.append(f"{indent}END_ACTION")
    return "\n".join(lines), problems


def _refuse_named_transitions(pou: str, body: SfcBody, refuse) -> None:
    """Named transitions textual SFC cannot write: in LD or FBD, or the whole condition of no chart transition (a
    named transition is written as ``TRANSITION name ...`` at each transition whose condition is its name)."""
    from .sfc import transition_file  # st/sfc.py imports the checks, which import the .st reader (this module)

    used = {
        t.transition.condition.strip().upper() for _, chart in body.charts() for t in chart_graph(chart).transitions
    }
    for transition in body.transitions:
        file = transition_file(pou, transition.name)
        if transition.language not in ("st", "il"):
            refuse(
                f"the named transition {transition.name} is written in {transition.language.upper()}: textual SFC "
                "has transition conditions in ST and IL",
                file,
            )
        elif transition.name.upper() not in used:
            refuse(
                f"the named transition {transition.name} is the whole condition of no transition of the chart: "
                "textual SFC writes it only as a TRANSITION of its own name",
                file,
            )


def _chart_lines(chart: SfcChart, indent: str, level: int, refuse, named: dict[str, SfcNamedTransition]) -> list[str]:
    """The steps and transitions of one chart (the POU's, or an action's inside its ``ACTION``) at ``level``; a
    transition whose condition is the name of a named transition in ST or IL (``named``, by upper-case name) is
    written as that transition: ``TRANSITION name ... := expression;`` or ``TRANSITION name ... TO b:`` and the IL."""
    graph = chart_graph(chart)
    pad = indent * level
    lines: list[str] = []
    for key, node in graph.steps.items():
        step = node.step
        if step.entry or step.exit or step.min_time or step.max_time:
            refuse(f"step {step.name} has entry or exit actions or time limits, which textual SFC cannot say")
        lines.append(f"{pad}{'INITIAL_STEP' if node.initial else 'STEP'} {step.name}:")
        for association in step.actions:
            args = [association.qualifier] + ([association.time.strip()] if association.time else [])
            lines.append(f"{pad}{indent}{association.action}({', '.join(args)});")
        lines.append(f"{pad}END_STEP")
        for transition in (t for t in graph.evaluation_order() if t.sources and t.sources[0] == key):
            element = transition.transition
            priority = f" (PRIORITY := {element.priority})" if element.priority is not None else ""
            steps = [
                _list(graph.steps[s].step.name for s in names) for names in (transition.sources, transition.targets)
            ]
            written = named.get(element.condition.strip().upper())
            head = f"{pad}TRANSITION{f' {written.name}' if written else ''}{priority} FROM {steps[0]} TO {steps[1]}"
            if written is not None and written.language == "il":
                assert isinstance(written.body, str)  # IL is text
                lines.append(f"{head}:")
                lines += [f"{pad}{indent}{line}".rstrip() for line in written.body.splitlines()]
            else:
                condition = written.body if written is not None else element.condition
                assert isinstance(condition, str)  # ST is text
                lines += [head, f"{pad}{indent}:= {condition.strip()};"]
            lines.append(f"{pad}END_TRANSITION")
    return lines


def _list(names) -> str:
    names = list(names)
    return names[0] if len(names) == 1 else "(" + ", ".join(names) + ")"
