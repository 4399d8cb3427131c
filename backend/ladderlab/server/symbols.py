"""The resolved declarations of one POU, for the variable table and operand autocomplete, and the
instance tree of the watch list and the Variables view (what a program, FB instance, structure or
array holds: ``GET /api/projects/{name}/variables?path=``).

They come from the ST checker, which resolves every POU's declarations before (and
independently of) its body, so the table is complete while the body has errors. The checker (and the parser
under it) is imported at the first request, not with the server (startup, issue 27).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from fastapi import APIRouter

from ..iec.spelling import did_you_mean
from ..model import Project
from ..model.api import SymbolTable, VariableChildren, VariableNode
from ..st import types as t
from ..st.monitoring import monitored_property, property_names
from ..storage import NotFoundError
from .context import WorkspaceDep
from .errors import ApiError, responses

if TYPE_CHECKING:
    from ..st.configuration import InstanceInfo
    from ..st.symbols import CheckResult, PouInfo, Symbol

router = APIRouter(prefix="/api/projects", tags=["symbols"])

#: Diagnostic ``file`` values of the texts every POU's symbols depend on.
_SHARED_TEXTS = {"types", "globals"}


def symbol_table(project: Project, pou_name: str) -> SymbolTable:
    """The POU's symbols in declaration order, the globals, and the diagnostics that concern them."""
    from ..simulation.document import symbol_info
    from ..st.checker import check_project as check_st

    pou = project.pou(pou_name)
    if pou is None:
        raise NotFoundError("POU", pou_name)
    result = check_st(project)
    key = pou.name.upper()
    info = result.pous[key]  # the checker registers every POU (the first one, like project.pou, on duplicates)
    diagnostics = [
        d
        for d in result.diagnostics
        if (d.pou is not None and d.pou.upper() == key) or d.file in _SHARED_TEXTS or (d.file or "").startswith("gvls/")
    ]
    return SymbolTable(
        pou=pou.name,
        symbols=[symbol_info(s) for s in info.symbols.values()],
        globals=[symbol_info(s, result.listed.get(key)) for key, s in result.globals.items()],
        diagnostics=diagnostics,
    )


@router.get("/{name}/pous/{pou}/symbols", response_model=SymbolTable, responses=responses(404, 422))
def get_symbols(name: str, pou: str, workspace: WorkspaceDep) -> SymbolTable:
    return symbol_table(workspace.load(name).project, pou)


# --------------------------------------------------------------------------- the instance tree (ON-10)

#: An array lists at most this many elements of its first dimension (the rest is counted in ``more``).
MAX_ELEMENTS = 1000
#: Variables a running instance holds: VAR_TEMP lives only during a call, externals are the globals.
_INSTANCE_CLASSES = ("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_STAT")


def _expandable(ty: t.Type) -> bool:
    return isinstance(ty, (t.FbType, t.StructType, t.ArrayType, t.PointerType))


def _node(name: str, path: str, type_text: str, ty: t.Type, var_class: str | None = None) -> VariableNode:
    return VariableNode(
        name=name,
        path=path,
        type=type_text,
        var_class=var_class,
        expandable=_expandable(ty),
        pointer=isinstance(ty, t.PointerType),
    )


def _variable(symbol: Symbol, path: str) -> VariableNode:
    from ..st.printer import print_type

    return _node(symbol.name, path, print_type(symbol.type_spec), symbol.type, symbol.var_class)


def _members(ty: t.Type, path: str, indices: tuple[int, ...]) -> tuple[list[VariableNode], int]:
    """The members of a variable of type ``ty`` at ``path`` (``indices``: of an array indexed partly so far)."""
    if isinstance(ty, t.FbType) and ty.pou is not None:
        symbols = [s for s in ty.pou.symbols.values() if s.var_class in _INSTANCE_CLASSES]
        return [*(_variable(s, f"{path}.{s.name}") for s in symbols), *_monitored(ty.pou, path)], 0
    if isinstance(ty, t.FbType) and ty.std is not None:
        pins = [(p, "VAR_INPUT") for p in ty.std.inputs] + [(p, "VAR_OUTPUT") for p in ty.std.outputs]
        return [
            VariableNode(name=p.name, path=f"{path}.{p.name}", type=p.type, var_class=c, expandable=False)
            for p, c in pins
        ], 0
    if isinstance(ty, t.StructType):
        return [_node(name, f"{path}.{name}", str(field), field) for name, field in ty.fields.values()], 0
    if isinstance(ty, t.PointerType):  # ON-11: what it points to, as CODESYS expands a pointer online
        name = f"{path.rsplit('.', 1)[-1]}^"
        return [_node(name, f"{path}^", str(ty.target), ty.target)], 0
    if isinstance(ty, t.ArrayType) and ty.dims and ty.dims[0] is not None:
        (low, high), rest = ty.dims[0], ty.dims[1:]
        inner = t.ArrayType(rest, ty.element) if rest else ty.element
        base = path[: path.rindex("[")] if indices else path
        last = min(high, low + MAX_ELEMENTS - 1)
        return [
            _node(f"[{i}]", f"{base}[{', '.join(map(str, (*indices, i)))}]", str(inner), inner)
            for i in range(low, last + 1)
        ], high - last
    return [], 0


def _monitored(pou: PouInfo, path: str) -> list[VariableNode]:
    """The properties of an instance of ``pou`` shown online ({attribute 'monitoring'}, st/monitoring.py), after its
    variables, as CODESYS's online view lists them: one value each (var_class PROPERTY)."""
    found = [monitored_property(pou, name) for name in property_names(pou)]
    return [
        VariableNode(
            name=prop.name, path=f"{path}.{prop.name}", type=str(prop.type), var_class="PROPERTY", expandable=False
        )
        for prop, _ in filter(None, found)
    ]


def _walk(result: CheckResult, path: str) -> tuple[t.Type, tuple[int, ...]]:
    """The type of the variable at ``path`` (and the indices of a partly indexed array at its end)."""
    from ..engine.paths import GLOBALS_PREFIX, tokens

    parts = tokens(path)
    if not parts or parts[0][0] != "name":
        raise ApiError(422, f"{path!r} is not a variable path")
    head, rest = parts[0][1], parts[1:]
    program = _instance_pou(result, head)
    if program is not None:
        ty: t.Type = t.FbType(program.name, pou=program)
    else:
        qualified = rest[:1] == [("punct", ".")] and rest[1:2] and rest[1][0] == "name"
        gvl = result.gvls.get(head.upper())
        listed = qualified and gvl is not None and rest[1][1].upper() in gvl.members
        if qualified and gvl is not None and not listed and head.upper() != GLOBALS_PREFIX:
            raise ApiError(404, f"the global variable list {gvl.name} has no variable {rest[1][1]!r}")
        if qualified and (listed or head.upper() == GLOBALS_PREFIX):  # GVL_IO.x: the list's variable, GVL.x: a global
            head, rest = rest[1][1], rest[2:]
        symbol = gvl.members[head.upper()] if listed and gvl is not None else result.globals.get(head.upper())
        if symbol is None:
            raise ApiError(404, f"no program or global variable {head!r}{did_you_mean(head, _top_names(result))}")
        ty = symbol.type
    indices: tuple[int, ...] = ()
    while rest:
        if isinstance(ty, t.PointerType) and rest[0] in (("punct", "^"), ("punct", ".")):
            ty, indices = ty.target, ()  # p^, or r.x through a REFERENCE TO (engine/paths.py)
            if rest[0] == ("punct", "^"):
                rest = rest[1:]
        elif rest[0] == ("punct", ".") and len(rest) > 1 and rest[1][0] == "name":
            member = rest[1][1]
            children, _ = _members(ty, path, ())
            found = next((c for c in children if c.name.upper() == member.upper()), None)
            if found is None or not isinstance(ty, (t.FbType, t.StructType)):
                raise ApiError(404, f"{path}: {ty} has no member {member!r}")
            ty, indices, rest = _member_type(ty, member), (), rest[2:]
        elif rest[0] == ("punct", "[") and isinstance(ty, t.ArrayType):
            close = rest.index(("punct", "]"))
            numbers = [int(v) for kind, v in rest[1:close] if kind == "int"]
            if len(numbers) > len(ty.dims):
                raise ApiError(422, f"{path}: {ty} has {len(ty.dims)} dimension(s)")
            left = ty.dims[len(numbers) :]
            ty, indices, rest = (
                (t.ArrayType(left, ty.element) if left else ty.element),
                (*indices, *numbers),
                rest[close + 1 :],
            )
        else:
            raise ApiError(422, f"{path!r} is not a variable path")
    return ty, (indices if isinstance(ty, t.ArrayType) else ())


def _member_type(ty: t.Type, member: str) -> t.Type:
    upper = member.upper()
    if isinstance(ty, t.StructType):
        return ty.fields[upper][1]
    if isinstance(ty, t.FbType) and ty.pou is not None:
        found: t.Type = ty.pou.symbols[upper].type
        return found
    assert isinstance(ty, t.FbType) and ty.std is not None  # _walk found the member among the pins
    pin = next(p for p in (*ty.std.inputs, *ty.std.outputs) if p.name == upper)
    return t.elementary(pin.type) or t.ERROR


def _instances(result: CheckResult) -> dict[str, InstanceInfo]:
    """The program instances the project runs, by upper-case name (a configuration names them; without one,
    each PROGRAM has one instance named after it)."""
    return result.configuration.instances if result.configuration is not None else {}


def _instance_pou(result: CheckResult, name: str) -> PouInfo | None:
    """The PROGRAM of the instance ``name``; a PROGRAM's own name stands for its only instance (engine paths)."""
    instance = _instances(result).get(name.upper())
    if instance is not None:
        return instance.pou
    program = result.pou(name)
    if program is None or program.kind != "PROGRAM":
        return None
    if sum(1 for i in _instances(result).values() if i.pou is program) > 1:
        return None
    return program


def _top_names(result: CheckResult) -> list[str]:
    return [i.name for i in _instances(result).values()] + [s.name for s in result.globals.values()]


def variable_children(project: Project, path: str) -> VariableChildren:
    """What the variable at ``path`` holds, for the watch list's and the Variables view's tree; the programs
    and the globals when ``path`` is empty."""
    from ..st.checker import check_project as check_st

    result = check_st(project)
    text = path.strip()
    if not text:
        programs = [
            VariableNode(name=i.name, path=i.name, type=i.pou.name, var_class="PROGRAM", expandable=True)
            for i in _instances(result).values()
        ]
        return VariableChildren(
            path="", type=None, children=[*programs, *(_variable(s, s.name) for s in result.globals.values())]
        )
    try:
        ty, indices = _walk(result, text)
    except ValueError as error:
        raise ApiError(422, str(error)) from None
    children, more = _members(ty, text, indices)
    return VariableChildren(path=text, type=str(ty), children=children, more=more)


@router.get("/{name}/variables", response_model=VariableChildren, responses=responses(404, 422))
def get_variables(name: str, workspace: WorkspaceDep, path: str = "") -> VariableChildren:
    return variable_children(workspace.load(name).project, path)
