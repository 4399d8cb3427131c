"""What the ST checker knows of SFC POUs: their implicit variables and the ST texts inside them.

An SFC POU gets one implicit variable per step (an ``SFC_STEP``: ``Step.X`` active, ``Step.T`` its time,
SFC-06), per action (an ``ACTION_CONTROL``: ``Action.Q`` the action flag, ``Action.A`` running, the IEC
action control block) and per named transition (a BOOL, written by the transition's own body and read by
the chart). They are declared after the user's variables, so the bodies, the chart's expressions and other
POUs (``boolvar := sfc1.step1.X;``) see them; they are read-only for programs (the chart sets them).
ST and IL actions are checked like ST and IL bodies (an IL named transition like an IL body); where a diagnostic is
reported: ``<POU>/chart`` (with the element id of the step), ``<POU>/actions/<name>`` and
``<POU>/transitions/<name>`` (line and column in that text).
"""

from __future__ import annotations

from ..iec import stdlib
from ..model.diagnostics import Diagnostic
from ..model.names import pou_name_problem
from ..model.project import Pou
from ..model.sfc import SfcBody, steps
from . import ast
from . import types as t
from .body import BodyChecker
from .il_check import check_il_body
from .il_parser import IlParseResult, parse_il
from .parser import ParseResult, parse_statements
from .registers import check_registers
from .symbols import CheckResult, PouInfo, Symbol

#: What an implicit symbol stands for (``Symbol.implicit``).
STEP, ACTION, TRANSITION = "step", "action", "transition"


def chart_file(pou: str) -> str:
    return f"{pou}/chart"


def action_file(pou: str, action: str) -> str:
    return f"{pou}/actions/{action}"


def transition_file(pou: str, transition: str) -> str:
    return f"{pou}/transitions/{transition}"


def il_key(part: str, name: str) -> str:
    """The key of an IL action (``part`` "actions") or IL named transition ("transitions") in ``PouInfo.il_parts``:
    its ``Origin.body``."""
    return f"{part}/{name}"


def parse_actions(pou: Pou) -> dict[str, ParseResult | IlParseResult]:
    """The ST and IL actions of an SFC POU (by upper-case name) and its IL named transitions (by their
    ``il_key``), parsed; the parse diagnostics are in the results."""
    body = pou.body
    assert isinstance(body, SfcBody)
    out: dict[str, ParseResult | IlParseResult] = {}
    for action in body.actions:
        file = action_file(pou.name, action.name)
        if action.language == "st" and isinstance(action.body, str):
            out[action.name.upper()] = parse_statements(action.body, file=file, pou=pou.name)
        elif action.language == "il" and isinstance(action.body, str):
            out[action.name.upper()] = parse_il(action.body, file=file, pou=pou.name)
    for transition in body.transitions:
        if transition.language == "il" and isinstance(transition.body, str):
            file = transition_file(pou.name, transition.name)
            out[il_key("transitions", transition.name)] = parse_il(transition.body, file=file, pou=pou.name)
    return out


def declare_implicit(pou: Pou, info: PouInfo, diagnostics: list[Diagnostic]) -> None:
    """Add the steps, actions and named transitions of an SFC POU to its symbols; report bad and taken names."""
    body = pou.body
    assert isinstance(body, SfcBody)
    if info.kind == "FUNCTION":
        diagnostics.append(
            Diagnostic(
                code="SFC-KIND",
                message=f"the function {pou.name} cannot be written in SFC: a function keeps nothing from one call to "
                "the next, a chart keeps its active steps (write a function block or a program)",
                file=chart_file(pou.name),
                pou=pou.name,
            )
        )
    step_type = _std_fb("SFC_STEP")
    action_type = _std_fb("ACTION_CONTROL")
    for owner, chart in body.charts():
        for number, step in enumerate(steps(chart.elements)):
            init = ast.StructInit([("X", ast.BoolLit(True))]) if number == 0 else None
            where = chart_file(pou.name) if owner is None else action_file(pou.name, owner)
            _declare(info, diagnostics, step.name, step_type, STEP, init, f"step {step.name}", where, step.id)
    for action in body.actions:
        where = action_file(pou.name, action.name)
        _declare(info, diagnostics, action.name, action_type, ACTION, None, f"action {action.name}", where, None)
    for transition in body.transitions:
        where = transition_file(pou.name, transition.name)
        _declare(
            info, diagnostics, transition.name, t.BOOL, TRANSITION, None, f"transition {transition.name}", where, None
        )


def _std_fb(name: str) -> t.FbType:
    std = stdlib.function_block(name)
    assert std is not None
    return t.FbType(std.name, std=std)


def _declare(
    info: PouInfo,
    diagnostics: list[Diagnostic],
    name: str,
    ty: t.Type,
    implicit: str,
    init: ast.Init | None,
    what: str,
    file: str,
    element: str | None,
) -> None:
    def report(code: str, message: str) -> None:
        diagnostics.append(Diagnostic(code=code, message=message, file=file, pou=info.name, element=element))

    problem = pou_name_problem(name)
    if problem:
        report("ST-NAME", f"{what}: {name!r} is not a valid name: {problem}")
        return
    taken = info.symbols.get(name.upper())
    if taken is not None:
        other = f"the {taken.implicit} {taken.name}" if taken.implicit else f"the variable {taken.name}"
        report(
            "SFC-DUPLICATE",
            f"{what} has the name of {other}: names of steps, actions, transitions and variables must differ",
        )
        return
    type_name = ty.name
    info.symbols[name.upper()] = Symbol(
        name, "VAR", ty, ast.NamedType(type_name), init, pou=info.name, implicit=implicit
    )


def check_actions(
    checked: CheckResult, reporter, pou: Pou, info: PouInfo, parsed: dict[str, ParseResult | IlParseResult]
) -> None:
    """Check the ST and IL actions and IL named transitions of ``pou`` (``reporter(file)`` reports into ``file``);
    the checked statements of actions go to ``info.actions``, an IL part's checked form to ``info.il_parts``."""
    assert isinstance(pou.body, SfcBody)
    for action in pou.body.actions:
        result = parsed.get(action.name.upper())
        if result is not None:
            info.actions[action.name.upper()] = _check(checked, reporter, info, result, "actions", action.name)
    for transition in pou.body.transitions:
        result = parsed.get(il_key("transitions", transition.name))
        if result is not None:
            _check(checked, reporter, info, result, "transitions", transition.name)


def _check(
    checked: CheckResult, reporter, info: PouInfo, result: ParseResult | IlParseResult, part: str, name: str
) -> list[ast.Stmt] | None:
    report = reporter((action_file if part == "actions" else transition_file)(info.name, name))
    if isinstance(result, IlParseResult):
        if result.body is None:
            return None
        il = check_il_body(checked, info, result.body, report)
        info.il_parts[il_key(part, name)] = il
        return il.statements
    if result.ast is None:
        return None
    BodyChecker(checked, info, report).statements(result.ast)
    check_registers(result.ast, report)
    return result.ast
