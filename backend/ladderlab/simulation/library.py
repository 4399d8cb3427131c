"""The catalogue of callable blocks: every standard function and function block, plus the project's own (a
program's PUBLIC methods among them, as functions named ``Prog.M``).

Standard entries come from the ST checker's catalogue (``iec/stdlib.py``), user entries from
the checker's resolved POU interfaces, so the box picker (``GET /api/library``) and the printed
documents offer and draw exactly what the checker accepts.
"""

from __future__ import annotations

from functools import cache
from typing import Literal

from ..iec import stdlib
from ..model import Project
from ..model.api import LibraryEntry, Pin
from ..st.checker import check_project as check_st
from ..st.libraries import with_libraries
from ..st.printer import print_type
from ..st.symbols import PouInfo, Symbol

_USER_KINDS: dict[str, Literal["function", "function_block"]] = {
    "FUNCTION": "function",
    "FUNCTION_BLOCK": "function_block",
}


def _std_pin(pin: stdlib.Pin) -> Pin:
    return Pin(name=pin.name, type=pin.type)


def _user_pin(symbol: Symbol) -> Pin:
    return Pin(name=symbol.name, type=print_type(symbol.type_spec))


def _result_type(fn: stdlib.StdFunction) -> str:
    """The declared result, with the generic ``T`` shown as the family of the inputs that share it (FUN-02)."""
    if fn.result != stdlib.T:
        return fn.result
    return next(pin.type for pin in fn.inputs if pin.generic)


@cache
def standard_entries() -> tuple[LibraryEntry, ...]:
    """Standard function blocks, then standard functions, in catalogue order (built once per process)."""
    blocks = [
        LibraryEntry(
            name=fb.name,
            kind="function_block",
            source="standard",
            inputs=[_std_pin(p) for p in fb.inputs],
            outputs=[_std_pin(p) for p in fb.outputs],
            in_outs=[],
            extensible=False,
            return_type=None,
            comment=fb.description,
        )
        for fb in stdlib.FUNCTION_BLOCKS.values()
    ]
    functions = [
        LibraryEntry(
            name=fn.name,
            kind="function",
            source="standard",
            inputs=[_std_pin(p) for p in fn.inputs],
            outputs=[],
            in_outs=[],
            extensible=fn.extensible,
            return_type=_result_type(fn),
            comment=fn.description,
        )
        for fn in stdlib.FUNCTIONS.values()
    ]
    return (*blocks, *functions)


def user_entries(project: Project) -> list[LibraryEntry]:
    """The project's functions, function blocks and programs' methods in project order, with their declared
    parameters, then those of the vendor libraries it uses (st/libraries.py)."""
    own = {p.name.upper() for p in project.pous}
    project = with_libraries(project)
    result = check_st(project)
    by_name = {p.name.upper(): p for p in reversed(project.pous)}  # the first of duplicates, as the checker
    entries = []
    for info in result.pous.values():
        kind = _USER_KINDS.get(info.kind)
        if kind is None:
            if info.kind == "PROGRAM" and not info.plant:  # no box, but other POUs call its methods ``Prog.M``
                entries += [_method_entry(f"{info.name}.{name}", m) for name, m in _public_methods([info])]
            continue
        entries.append(
            LibraryEntry(
                name=info.name,
                kind=kind,
                source="user" if info.name.upper() in own else "library",
                inputs=[_user_pin(s) for s in info.parameters("VAR_INPUT")],
                outputs=[_user_pin(s) for s in info.parameters("VAR_OUTPUT")],
                in_outs=[_user_pin(s) for s in info.parameters("VAR_IN_OUT")],
                extensible=False,
                return_type=by_name[info.name.upper()].return_type,
                comment=None,
                methods=_methods(info) if info.kind == "FUNCTION_BLOCK" else [],
            )
        )
    return entries


def _methods(fb: PouInfo) -> list[LibraryEntry]:
    """``fb``'s PUBLIC methods, its own then inherited ones not overridden, as an FBD block ``inst.M`` calls them."""
    return [_method_entry(name, method) for name, method in _public_methods(fb.lineage())]


def _public_methods(lineage: list[PouInfo]) -> list[tuple[str, PouInfo]]:
    """The PUBLIC methods of a POU and its ancestors (``lineage``, the POU first), each once: the first one found
    (an override before what it overrides), by its name as written; a PROPERTY's accessors left out."""
    found: dict[str, tuple[str, PouInfo]] = {}  # upper-case name -> (name as written, the method)
    for owner in lineage:
        for key, method in owner.methods.items():
            if key not in found and "." not in key and method.method is not None and method.method.access == "PUBLIC":
                found[key] = method.method.name, method
    return list(found.values())


def _method_entry(name: str, method: PouInfo) -> LibraryEntry:
    """A method as a box calls it: its inputs, VAR_OUTPUTs and the result as OUT."""
    return LibraryEntry(
        name=name,
        kind="function",
        source="user",
        inputs=[_user_pin(s) for s in method.parameters("VAR_INPUT")],
        outputs=[_user_pin(s) for s in method.parameters("VAR_OUTPUT")],
        in_outs=[_user_pin(s) for s in method.parameters("VAR_IN_OUT")],
        extensible=False,
        return_type=print_type(method.return_spec) if method.return_spec is not None else None,
        comment=None,
    )
