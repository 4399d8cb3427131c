"""Named global variable lists (CODESYS's GVLs, ``Project.gvls``): ``GVL_IO.bStart`` names the list's variable,
a qualified_only list's variables are used only so (docs/st.md, "Global variable lists").

The lists' variables share the one global storage of the project's other globals, so a name may be declared by
one list only (CODESYS allows it in two and then needs the qualified name; the second declaration is an error
here instead). ``GVL.x`` is checked as the global ``x``: the checker sets the ``ref`` of the member and of its
base to the variable (``list_qualified``), so every later stage reads it as that global.
"""

from __future__ import annotations

from typing import Any

from ..iec.spelling import did_you_mean
from ..model.project import Project
from . import ast
from .symbols import CheckResult, GvlInfo, Symbol
from .types import ERROR, Type


def gvl_file(name: str) -> str:
    """The diagnostics' file of a GVL's text (``gvls/<name>``; its folder file is ``gvls/<name>.st``)."""
    return f"gvls/{name}"


def gvl_texts(project: Project) -> list[tuple[str, str]]:
    """(VAR_GLOBAL text, diagnostics file) of every named list."""
    return [(gvl.text, gvl_file(gvl.name)) for gvl in project.gvls]


def register_lists(result: CheckResult, project: Project) -> dict[str, GvlInfo]:
    """Each list's (still empty) entry in ``result.gvls``; diagnostics file -> the list."""
    files = {}
    for gvl in project.gvls:
        info = result.gvls[gvl.name.upper()] = GvlInfo(gvl.name, gvl.qualified_only)
        files[gvl_file(gvl.name)] = info
    return files


def clashing_name(result: CheckResult, info: GvlInfo) -> str | None:
    """What else is called like the list (a POU, a type or a global variable), for a located error, or None."""
    key = info.name.upper()
    pou = result.pous.get(key)
    if pou is not None:
        return f"the {pou.kind.lower().replace('_', ' ')} {pou.name}"
    if key in result.types or key in result.interfaces:
        return f"the type {key}"
    symbol = result.globals.get(key)
    return f"the global variable {symbol.name}" if symbol is not None else None


def twice_hint(result: CheckResult, name: str, in_list: bool) -> str:
    """Why a second global declaration of ``name`` is refused when a list is involved (``in_list``: the second
    is in one); "" when none is."""
    first = result.listed.get(name.upper())
    if first is None and not in_list:
        return ""
    where = f"the global variable list {first.name}" if first is not None else "the global variables"
    return (
        f" (first in {where}: all global variable lists share one storage, so LadderLab needs a name to be "
        "declared once; rename one)"
    )


def list_qualified(node: Any) -> bool:
    """``GVL.x`` as the checker resolved it: a member whose ``ref`` and whose base's are the list's variable."""
    return (
        type(node) is ast.Member and type(node.base) is ast.Name and node.ref is not None and node.ref is node.base.ref
    )


def list_member(checker: Any, node: ast.Member) -> Type | None:
    """The type of ``GVL.x`` (its ``ref`` set), reported when the list has no ``x``; None when the base is not a
    list's name: a variable, instance, program or type of that name comes first (CODESYS: the local name wins)."""
    base = node.base
    result: CheckResult = checker.result
    if type(base) is not ast.Name or not result.gvls:
        return None
    gvl = result.gvls.get(base.name.upper())
    if gvl is None or checker.lookup(base.name) is not None or base.name.upper() in result.pous:
        return None
    symbol = gvl.members.get(node.name.upper())
    if symbol is None:
        names = [s.name for s in gvl.members.values()]
        message = f"the global variable list {gvl.name} has no variable '{node.name}'" + did_you_mean(node.name, names)
        checker.report("ST-UNKNOWN-VAR", message, node)
        return ERROR
    node.ref = base.ref = symbol
    base.ty = symbol.type
    return symbol.type


def check_unqualified(checker: Any, node: ast.Name, symbol: Symbol) -> None:
    """A bare use of a qualified_only list's variable is an error naming the list (CODESYS's attribute)."""
    gvl = checker.result.listed.get(node.name.upper())
    if gvl is not None and gvl.qualified_only and checker.result.globals.get(node.name.upper()) is symbol:
        checker.report(
            "ST-QUALIFIED-ONLY",
            f"'{node.name}' belongs to the global variable list {gvl.name}, which is qualified_only: "
            f"write {gvl.name}.{symbol.name}",
            node,
        )
