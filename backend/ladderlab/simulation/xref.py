"""The cross-reference list (issue 28): for every variable and direct address, where it is declared, read and written.

Built from what the build already knows, never re-derived: the declarations from the ST checker's symbols
(POU and line of each declaration, VAR_EXTERNAL naming a global), the accesses from the IR every POU lowers to
(docs/ir.md) - ST and diagrams alike, so a contact, a box pin, an FBD input node or an ST expression is a read
exactly when the engine reads it, and a coil, an output or ``Q => y`` a write. Each IR statement carries its
origin: an ST line, or an LD/FBD network and element (shown with the element's operand text and the network's
number). The lowering's own temporaries (hidden slots) are not variables of the user and are left out. A POU that
does not lower (errors) still lists its declarations and whatever the lowering reached.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterator
from typing import Any

from ..ir import nodes as ir
from ..ir.lower_project import lower_pou
from ..model import Diagnostic, Pou, Project
from ..model import fbd as fbd_model
from ..model import ld as ld_model
from ..model.xref import AccessKind, XrefAccess, XrefEntry, XrefList
from ..st.checker import check_project
from ..st.printer import print_type
from ..st.symbols import THIS, CheckResult, GvlInfo, PouInfo, Symbol

Key = tuple[str | None, str]
_ROOT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")  # (upper-case POU or None for a global, upper-case name)


def cross_reference(project: Project) -> XrefList:
    """Every variable of ``project`` with its declaration and accesses, globals first, then POU by POU."""
    checked = check_project(project)
    entries: dict[Key, XrefEntry] = {}
    for key, symbol in checked.globals.items():
        entries[(None, symbol.name.upper())] = _entry(symbol, None, checked.listed.get(key))
    for pou in project.pous:
        info = checked.pou(pou.name)
        if info is None or info.name != pou.name:
            continue
        for symbol in info.symbols.values():
            if symbol.var_class == "VAR_EXTERNAL" and (None, symbol.name.upper()) in entries:
                entries[(None, symbol.name.upper())].accesses.append(_declared(symbol, pou.name))
            else:
                entries[(pou.name.upper(), symbol.name.upper())] = _entry(symbol, pou.name)
        for method in info.methods.values():  # a METHOD's (or PROPERTY accessor's) own variables: ``F.M``
            for symbol in method.symbols.values():
                if symbol is not method.this() and symbol.var_class != "VAR_EXTERNAL":
                    entries[(method.name.upper(), symbol.name.upper())] = _entry(symbol, method.name)
    for pou in project.pous:
        info = checked.pou(pou.name)
        if info is None or info.name != pou.name:
            continue
        _accesses(project, checked, pou, entries)
        for method in info.methods.values():
            _method_accesses(checked, method, entries)
    for entry in entries.values():
        entry.accesses = _unique(entry.accesses)
    return XrefList(entries=list(entries.values()))


def _entry(symbol: Symbol, pou: str | None, gvl: GvlInfo | None = None) -> XrefEntry:
    declared = _declared(symbol, pou)
    declared.gvl = gvl.name if gvl is not None else None
    return XrefEntry(
        name=symbol.name,
        pou=pou,
        var_class=symbol.var_class,
        type=print_type(symbol.type_spec),
        address=symbol.address,
        comment=symbol.comment,
        accesses=[declared],
    )


def _declared(symbol: Symbol, pou: str | None) -> XrefAccess:
    line = symbol.span.line or None
    return XrefAccess(kind="declared", pou=pou, line=line, column=symbol.span.column or None, path=symbol.name)


def _accesses(project: Project, checked: CheckResult, pou: Pou, entries: dict[Key, XrefEntry]) -> None:
    info = checked.pou(pou.name)
    if info is None:  # not checked: cross_reference passes only the POUs the checker resolved
        return
    diagnostics: list[Diagnostic] = []
    lowered = lower_pou(pou, info, checked, diagnostics)
    places = _places(pou)
    inputs = _fbd_inputs(pou)
    names = {name: entry.name for (owner, name), entry in entries.items() if owner in (None, pou.name.upper())}
    for block in lowered.blocks:
        for kind, var, origin in _statement_accesses(block.statements):
            key: Key = (None, var.name) if var.scope == "global" else (pou.name.upper(), var.name)
            entry = entries.get(key)
            if entry is None:  # a hidden temporary of the lowering, or the function's result
                continue
            element = origin.element
            if kind == "read" and (origin.network, var.name) in inputs:  # FBD: read where the input node stands
                element = inputs[(origin.network, var.name)]
            number, operand = places.get((origin.network, element), (None, None))
            if origin.network is not None and number is None:
                number = places.get((origin.network, None), (None, None))[0]
            entry.accesses.append(
                XrefAccess(
                    kind=kind,
                    pou=pou.name,
                    network=origin.network,
                    network_number=number,
                    element=element,
                    operand=operand,
                    line=origin.line,
                    column=origin.column,
                    path=_path(var, names, checked, info),
                )
            )


def _method_accesses(checked: CheckResult, method: PouInfo, entries: dict[Key, XrefEntry]) -> None:
    """What a METHOD reads, writes and calls (lines of its body): its own variables under ``F.M``, the instance's
    (``THIS`` member paths in the IR, docs/ir.md) under its function block, the globals under theirs."""
    assert method.method is not None  # (a function block's ``methods`` holds methods only)
    fb = method.method.owner
    lowered = lower_pou(None, method, checked, [])
    own = {name: entry.name for (owner, name), entry in entries.items() if owner in (None, method.name.upper())}
    instance = {name: entry.name for (owner, name), entry in entries.items() if owner == fb.name.upper()}
    for block in lowered.blocks:
        for kind, var, origin in _statement_accesses(block.statements):
            if var.scope == "local" and var.name == THIS and var.path and isinstance(var.path[0], ir.Member):
                name, rest = var.path[0].name, var.path[1:]
                key: Key = (fb.name.upper(), name)
                path = _path(ir.Var("local", name, var.type, rest), instance, checked, fb)
            else:
                key = (None, var.name) if var.scope == "global" else (method.name.upper(), var.name)
                path = _path(var, own, checked, method)
            entry = entries.get(key)
            if entry is not None:  # (else a hidden temporary, the result, or THIS itself)
                access = XrefAccess(kind=kind, pou=method.name, line=origin.line, column=origin.column, path=path)
                entry.accesses.append(access)


def _places(pou: Pou) -> dict[tuple[str | None, str | None], tuple[int, str | None]]:
    """(network id, element id or None) -> (network number, the element's operand text) of a diagram POU."""
    found: dict[tuple[str | None, str | None], tuple[int, str | None]] = {}
    body = pou.body
    if isinstance(body, ld_model.LdBody):
        for number, network in enumerate(body.networks, 1):
            found[(network.id, None)] = (number, None)
            for element in ld_model.walk(network.elements):
                found[(network.id, element.id)] = (number, _ld_operand(element))
    elif isinstance(body, fbd_model.FbdBody):
        for number, fbd_network in enumerate(body.networks, 1):
            found[(fbd_network.id, None)] = (number, None)
            for node in fbd_network.nodes:
                text = getattr(node, "expr", None) or getattr(node, "var", None)
                if isinstance(node, fbd_model.Block):
                    text = node.instance or node.call
                found[(fbd_network.id, node.id)] = (number, text)
    return found


def _fbd_inputs(pou: Pou) -> dict[tuple[str | None, str], str]:
    """(network id, upper-case variable) -> the FBD input node that names it (the lowering reads an input node's
    variable where its consumer runs; the list shows the node the user drew)."""
    found: dict[tuple[str | None, str], str] = {}
    if isinstance(pou.body, fbd_model.FbdBody):
        for network in pou.body.networks:
            for node in network.nodes:
                if isinstance(node, fbd_model.InputNode) and (root := _ROOT.match(node.expr.strip())):
                    found.setdefault((network.id, root.group().upper()), node.id)
    return found


def _ld_operand(element: object) -> str | None:
    if isinstance(element, (ld_model.Contact, ld_model.Coil)):
        return element.var
    if isinstance(element, ld_model.Compare):
        return f"{element.left} {element.op} {element.right}"
    if isinstance(element, ld_model.Box):
        return element.instance or element.call
    return None


def _path(var: ir.Var, names: dict[str, str], checked: CheckResult, info: PouInfo) -> str:
    """The access as the user spells it: ``Blink.Out`` (an FB's pins as declared), ``arr[]`` for an element."""
    text = names.get(var.name, var.name)
    fb = _fb_of(var, checked, info)
    for selector in var.path:
        if isinstance(selector, ir.Member):
            pou = checked.pou(fb) if fb else None
            symbol = pou.symbols.get(selector.name.upper()) if pou is not None else None
            text += f".{symbol.name if symbol is not None else selector.name}"
            fb = None
        else:
            text += "[]"
    return text


def _fb_of(var: ir.Var, checked: CheckResult, info: PouInfo) -> str | None:
    """The user FB type the variable ``var`` starts from (its root's declared type), if it is one."""
    symbol = checked.globals.get(var.name) if var.scope == "global" else info.symbols.get(var.name)
    type_name = print_type(symbol.type_spec) if symbol is not None else ""
    return type_name if type_name.upper() in checked.pous else None


# ------------------------------------------------------------------ walking the IR


def _statement_accesses(statements: list[Any]) -> Iterator[tuple[AccessKind, ir.Var, ir.Origin]]:
    for statement in statements:
        origin = getattr(statement, "origin", None)
        if isinstance(statement, ir.Probe) or origin is None:
            continue
        if isinstance(statement, ir.Assign):
            yield from _reads(statement.value, origin)
            yield from _written(statement.target, origin)
        elif isinstance(statement, ir.FbCall):
            yield from _reads(statement.en, origin)
            for _, value in statement.inputs:
                yield from _reads(value, origin)
            yield from _written(statement.instance, origin, "call")
            for _, target in statement.outputs:
                yield from _written(target, origin)
            yield from _written(statement.eno, origin)
        elif isinstance(statement, ir.FnCall):
            yield from _reads(statement.en, origin)
            yield from _reads(statement.call, origin)
            yield from _written(statement.target, origin)
            yield from _written(statement.eno, origin)
        elif isinstance(statement, ir.For):
            yield from _written(statement.var, origin)
            for part in (statement.start, statement.end, statement.step):
                yield from _reads(part, origin)
            yield from _statement_accesses(statement.body)
        elif isinstance(statement, ir.If):
            for condition, body in statement.branches:
                yield from _reads(condition, origin)
                yield from _statement_accesses(body)
            yield from _statement_accesses(statement.orelse)
        elif isinstance(statement, ir.Case):
            yield from _reads(statement.selector, origin)
            for _, body in statement.branches:
                yield from _statement_accesses(body)
            yield from _statement_accesses(statement.orelse)
        elif isinstance(statement, ir.While):
            yield from _reads(statement.cond, origin)
            yield from _statement_accesses(statement.body)
        elif isinstance(statement, ir.Repeat):
            yield from _statement_accesses(statement.body)
            yield from _reads(statement.until, origin)
        elif isinstance(statement, ir.Jump):
            yield from _reads(statement.cond, origin)
        elif isinstance(statement, ir.Block):
            yield from _statement_accesses(statement.statements)


def _written(
    var: ir.Var | None, origin: ir.Origin, kind: AccessKind = "write"
) -> Iterator[tuple[AccessKind, ir.Var, ir.Origin]]:
    if var is None:
        return
    yield kind, var, origin
    for selector in var.path:  # a[i] := ... reads i
        if isinstance(selector, ir.Index):
            for index in selector.indices:
                yield from _reads(index, origin)


def _reads(expr: Any, origin: ir.Origin) -> Iterator[tuple[AccessKind, ir.Var, ir.Origin]]:
    """Every variable ``expr`` reads (VAR_IN_OUT arguments of a call are written too)."""
    if expr is None:
        return
    if isinstance(expr, ir.Var):
        yield "read", expr, origin
        for selector in expr.path:
            if isinstance(selector, ir.Index):
                for index in selector.indices:
                    yield from _reads(index, origin)
        return
    if isinstance(expr, ir.Call):
        for argument in expr.args:
            yield from _reads(argument, origin)
        method = expr.user and "." in expr.function  # ``F.M`` (no POU name has a dot): its first in-out is THIS
        for number, in_out in enumerate(expr.in_outs):
            yield from _written(in_out, origin, "call" if method and number == 0 else "write")
        return
    if dataclasses.is_dataclass(expr):
        for field in dataclasses.fields(expr):
            value = getattr(expr, field.name)
            if isinstance(value, tuple):
                for item in value:
                    yield from _reads(item, origin)
            elif dataclasses.is_dataclass(value) and not isinstance(value, ir.Origin):
                yield from _reads(value, origin)


def _unique(accesses: list[XrefAccess]) -> list[XrefAccess]:
    seen, kept = set(), []
    for access in accesses:
        key = access.model_dump_json()
        if key not in seen:
            seen.add(key)
            kept.append(access)
    return kept
