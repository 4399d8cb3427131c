"""CODESYS's ``{attribute 'call_after_init'}``: which methods an instance runs by itself once it is initialised.

From CODESYS's online help ("Attribute: call_after_init") and Beckhoff's page for the same compiler: the attribute
stands on the first line of the declarations of both the function block and the method ("for performance reasons
you must add the attribute to both"); the method is called after the instance's FB_init and after its declaration's
initial values (``fbDoIt.FB_Init(); fbDoIt.in1 := 99; fbDoIt.FB_AfterInit();``); it has no VAR_INPUT ("input
variables are unknown at the time of the call": a compile error); its name is not FB_init, FB_reinit or FB_exit; a
function block that extends one using the attribute must have the attribute too, and an override of the method
(same name) is the one that runs (it calls ``SUPER^.MyInit()`` for the base's).

Here the attribute is the head of the declarations text (the model keeps no header line, docs/st.md); one anywhere
else is ST-PRAGMA where it stands (st/pragmas.py, and ``_misplaced`` for the texts of a program, a function, a
property or the globals). ``check_call_after_init`` marks the function blocks and methods (``PouInfo.after_init``)
and reports each misuse at its attribute; ir/fb_init.py runs the calls.
"""

from __future__ import annotations

from typing import Any

from ..model.diagnostics import Diagnostic
from ..model.project import Project
from .configuration import configuration_globals
from .fb_init import IMPLICIT_METHODS
from .gvls import gvl_texts
from .methods import method_file
from .pragmas import head_call_after_init, misplaced_diagnostic
from .symbols import THIS, CheckResult, MethodInfo, PouInfo

#: (line, column, end line, end column) of an attribute in its text
Place = tuple[int, int, int, int]


def check_call_after_init(result: CheckResult, project: Project) -> None:
    """Mark the function blocks and methods with the attribute and report its misuses (once every method is
    declared and every EXTENDS linked)."""
    places: dict[int, tuple[Place, str, str]] = {}  # id(PouInfo) -> where its attribute is (file, POU)
    for pou in project.pous:
        info = result.pous.get(pou.name.upper())
        if info is None or info.name != pou.name:
            continue
        _mark(result, info, pou.declarations, f"{pou.name}/declarations", pou.name, places)
        for method in pou.methods:
            own = info.methods.get(method.name.upper())
            label = f"{pou.name}.{method.name}"
            file = method_file(pou.name, method.name, "declarations")
            if own is not None and own.method is not None and own.name.upper() == label.upper():
                _mark(result, own, method.declarations, file, label, places)
            else:
                _misplaced(result, method.declarations, file, label)
        for prop in pou.properties:
            for kind, accessor in (("GET", prop.get), ("SET", prop.set)):
                if accessor is not None:
                    label = f"{prop.name}.{kind}"
                    file = method_file(pou.name, label, "declarations")
                    _misplaced(result, accessor.declarations, file, f"{pou.name}.{label}", "on a property")
    for text, file in [(project.globals, "globals"), *gvl_texts(project), *configuration_globals(project)]:
        _misplaced(result, text, file, None, "on global variables")
    for info in result.pous.values():
        if info.kind == "FUNCTION_BLOCK":
            _check_block(result, info, places)


def _mark(
    result: CheckResult, info: PouInfo, text: str, file: str, label: str, places: dict[int, tuple[Place, str, str]]
) -> None:
    place = head_call_after_init(text)
    if place is None:
        return
    method = info.method
    if method is not None and method.owner.kind == "FUNCTION_BLOCK" and not method.action:
        problem = _method_problem(info, method)
    elif method is None and info.kind == "FUNCTION_BLOCK":
        problem = None
    else:
        problem = "on a program's method" if method is not None else f"on a {info.kind.lower().replace('_', ' ')}"
    if problem is not None:
        _report(result, place, misplaced_diagnostic(file, label, problem))
        return
    info.after_init = True
    places[id(info)] = (place, file, label)


def _method_problem(info: PouInfo, method: MethodInfo) -> str | None:
    """Why the method ``info`` may not be called after the initialisation (CODESYS's rules), or None."""
    if method.name.upper() in IMPLICIT_METHODS:
        return f"on {method.name}, which the system calls by itself (name the method otherwise)"
    inputs = [s.name for s in info.symbols.values() if s.var_class in ("VAR_INPUT", "VAR_IN_OUT") and s.name != THIS]
    if inputs:
        return (
            f"on a method with inputs ({', '.join(inputs)}): nothing passes them when the system calls it (CODESYS: "
            "a compile error)"
        )
    marked = [m.method.name for m in method.owner.methods.values() if m.after_init and m.method is not None]
    if marked:
        return f"twice in {method.owner.name} ({marked[0]} has it: the order of the calls would be unknown)"
    return None


def _check_block(result: CheckResult, info: PouInfo, places: dict[int, tuple[Place, str, str]]) -> None:
    """The attribute on the function block ``info`` and its methods agrees: both carry it, and a function block
    extending one that does carries it too; one on the function block alone calls nothing (a warning)."""
    for method in info.methods.values():
        if method.after_init and not info.after_init:
            place, file, label = places[id(method)]
            method.after_init = False
            _report(result, place, misplaced_diagnostic(file, label, f"unless {info.name} has it too"))
    base = next((fb for fb in info.lineage()[1:] if fb.after_init), None)
    if base is not None and not info.after_init:
        message = (
            f"{info.name} extends {base.name}, which has {{attribute 'call_after_init'}}: {info.name} needs it too, "
            "on the first line of its declarations (CODESYS)"
        )
        file = f"{info.name}/declarations"
        result.diagnostics.append(Diagnostic(code="ST-PRAGMA", message=message, file=file, pou=info.name))
    if info.after_init and not any(m.after_init for fb in info.lineage() for m in fb.methods.values()):
        place, file, label = places[id(info)]
        warning = misplaced_diagnostic(file, label, f"on {info.name} alone: none of its methods has it")
        _report(result, place, warning.model_copy(update={"severity": "warning"}))


def _misplaced(result: CheckResult, text: str, file: str, pou: str | None, why: str = "") -> None:
    """ST-PRAGMA at the attribute heading a text whose owner is no function block nor its method."""
    place = head_call_after_init(text)
    if place is not None:
        _report(result, place, misplaced_diagnostic(file, pou, why))


def _report(result: CheckResult, place: Place, diagnostic: Any) -> None:
    line, column, end_line, end_column = place
    result.diagnostics.append(
        diagnostic.model_copy(update={"line": line, "column": column, "end_line": end_line, "end_column": end_column})
    )
