"""Named global variable lists (CODESYS's GVLs, ``Project.gvls``): ``GVL_IO.bStart`` names the list's variable,
a qualified_only list's variables are used only so (docs/st.md, "Global variable lists").

A name declared in several lists is several variables, each used as ``LIST.x`` only (a bare ``x`` is ambiguous, as
CODESYS's C0136): each is the global ``LIST.x`` then (``share``), so storage, online paths and the engine tell them
apart. ``GVL.x`` is checked as the list's variable: the checker sets the ``ref`` of the member and of its base to
the variable (``list_qualified``), so every later stage reads it as that global.
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
    is in one; lists may share a name, the project's and the configuration's global variables, which have no list
    name to tell them apart by, may not); "" when none is."""
    upper = name.upper()
    first = result.listed.get(upper)
    lists = result.shared.get(upper)
    if first is None and lists is None and not in_list:
        return ""
    if lists is not None:
        where = "the global variable lists " + " and ".join(gvl.name for gvl in lists)
    else:
        where = f"the global variable list {first.name}" if first is not None else "the global variables"
    return f" (first in {where}; the global variables have no list name to tell the two apart by: rename one)"


def share(result: CheckResult, gvl: GvlInfo, key: str, symbol: Symbol) -> bool:
    """Add the list ``gvl``'s new variable ``symbol`` (``key``: its upper-case name) to the globals; False when a
    global variable outside the lists has its name (a duplicate). A name in several lists is each list's
    ``LIST.x`` (``result.shared``)."""
    lists = result.shared.get(key)
    if lists is None and key not in result.globals:
        result.globals[key], result.listed[key] = symbol, gvl
        return True
    if lists is None:
        first = result.listed.pop(key, None)
        if first is None:
            return False
        lists = result.shared[key] = [first]
        _qualify(result, first, result.globals.pop(key))
    lists.append(gvl)
    _qualify(result, gvl, symbol)
    return True


def _qualify(result: CheckResult, gvl: GvlInfo, symbol: Symbol) -> None:
    """``symbol``, a variable of ``gvl`` whose name another list declares too, as the global ``LIST.x``."""
    symbol.name = f"{gvl.name}.{symbol.name}"
    key = symbol.name.upper()
    result.globals[key], result.listed[key] = symbol, gvl


def shared_use(result: CheckResult, report: Any, node: Any, name: str) -> bool:
    """Report a bare use of a name that several lists declare (CODESYS C0136, "ambiguous use of name"): which lists,
    and what to write; False when ``name`` is in one list at most."""
    lists = result.shared.get(name.upper())
    if lists is None:
        return False
    names = [gvl.name for gvl in lists]
    report(
        "ST-AMBIGUOUS",
        f"'{name}' is declared in the global variable lists {', '.join(names[:-1])} and {names[-1]}: write "
        + " or ".join(f"{gvl}.{name}" for gvl in names),
        node,
    )
    return True


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
