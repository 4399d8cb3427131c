"""INTERFACEs (IEC 61131-3 ed. 3, 6.6.6; CODESYS): method prototypes a function block IMPLEMENTS, variables of an
interface's type (a reference to an implementing instance, or NULL), calls through them dispatched by the instance's
FB, and the assignment attempt ``?=``.

An INTERFACE is declared among the TYPEs (the project's types text); its methods are checked like an FB's
(st/methods.py), without a body: a call ``i.M()`` runs the method of the FB of the instance ``i`` refers to.
"""

from __future__ import annotations

from typing import Any

from ..iec.spelling import did_you_mean
from . import ast
from . import types as t
from .inheritance import signature_difference
from .methods import property_of
from .symbols import THIS, MethodInfo, PouInfo, Symbol

_ALLOWED = {"VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT"}


def register_interfaces(checker: Any, decls: list[ast.InterfaceDecl]) -> None:
    """Their names first (so TYPEs, globals and POUs may declare variables of them)."""
    report = checker._reporter("types", None)
    for decl in decls:
        upper = decl.name.upper()
        if upper in checker.result.interfaces or upper in checker.type_decls or upper in checker.result.pous:
            report("ST-DUPLICATE", f"the name '{decl.name}' is already in use", decl)
            continue
        checker.result.interfaces[upper] = PouInfo(decl.name, "INTERFACE", "st", None)


def declare_interfaces(checker: Any, decls: list[ast.InterfaceDecl]) -> None:
    """The interfaces they extend and their method prototypes, once the TYPEs are resolved."""
    from .body import BodyChecker

    report = checker._reporter("types", None)
    for decl in decls:
        info = checker.result.interfaces.get(decl.name.upper())
        if info is None or info.name != decl.name:
            continue
        for name in decl.extends:
            base = checker.result.interfaces.get(name.upper())
            if base is None:
                report("ST-UNKNOWN-TYPE", f"{decl.name} EXTENDS '{name}', which is not an interface", decl)
            elif base.implements(info):
                report("ST-RECURSION", f"{decl.name} EXTENDS {name}, which extends {decl.name}", decl)
            else:
                info.interfaces.append(base)
        for method in decl.methods:
            if method.name.upper() in info.methods:
                report("ST-DUPLICATE", f"{decl.name} has two methods called '{method.name}'", method)
                continue
            prototype = _prototype(info, method.name, method.name)
            body = BodyChecker(checker.result, prototype, report)
            if method.return_type is not None:
                prototype.return_spec = method.return_type
                prototype.return_type = checker.resolve(method.return_type, body)
            for block in method.var_blocks:
                if block.kind not in _ALLOWED:
                    report("ST-DECL", f"an interface's method declares its parameters only, not {block.kind}", block)
                    continue
                checker.declare_block(block, prototype.symbols, body, prototype)
            if method.body:
                report(
                    "ST-DECL", f"{decl.name}.{method.name} is a prototype: an interface's method has no body", method
                )
            if set(method.modifiers) - {"PUBLIC"}:
                report("ST-DECL", "an interface's methods are PUBLIC: they take no other modifier", method)
        for prop in decl.properties:
            _declare_property(checker, info, prop, report)


def _prototype(info: PouInfo, name: str, key: str) -> PouInfo:
    """An interface's method (or property accessor ``<P>.GET`` / ``.SET``) as a function ``<I>.<key>`` whose
    ``THIS`` is the interface: what a call through an interface variable passes (ir/lower_project.py)."""
    prototype = PouInfo(f"{info.name}.{key}", "FUNCTION", "st", None)
    prototype.method = MethodInfo(info, name, abstract=True, key=key.upper())
    this = t.InterfaceType(info.name, info)
    prototype.symbols[THIS] = Symbol(THIS, "VAR_IN_OUT", this, ast.NamedType(info.name), pou=prototype.name)
    info.methods[key.upper()] = prototype
    return prototype


def _declare_property(checker: Any, info: PouInfo, prop: ast.PropertyDecl, report) -> None:
    """A PROPERTY prototype (CODESYS): its accessors as prototypes ``<I>.<P>.GET`` (returning the property's type)
    and ``<I>.<P>.SET`` (whose input is the property's name), as an FB's property (st/methods.py), without bodies."""
    from .body import BodyChecker

    upper = prop.name.upper()
    if upper in info.methods or f"{upper}.GET" in info.methods or f"{upper}.SET" in info.methods:
        report("ST-DUPLICATE", f"{info.name} has two methods or properties called '{prop.name}'", prop)
        return
    if set(prop.modifiers) - {"PUBLIC"}:
        report("ST-DECL", "an interface's properties are PUBLIC: they take no other modifier", prop)
    if not prop.accessors:
        report("ST-DECL", f"the property {info.name}.{prop.name} declares neither GET nor SET", prop)
    for accessor in prop.accessors:
        if f"{upper}.{accessor.kind}" in info.methods:
            report("ST-DUPLICATE", f"the property {info.name}.{prop.name} has two {accessor.kind}s", accessor)
            continue
        if accessor.var_blocks or accessor.body:
            report(
                "ST-DECL",
                f"{info.name}.{prop.name} is a prototype: an interface's property has no variables or statements "
                f"in its {accessor.kind}",
                accessor,
            )
        prototype = _prototype(info, prop.name, f"{prop.name}.{accessor.kind}")
        ty = checker.resolve(prop.type, BodyChecker(checker.result, prototype, report))
        if accessor.kind == "GET":
            prototype.return_spec, prototype.return_type = prop.type, ty
        else:
            value = Symbol(prop.name, "VAR_INPUT", ty, prop.type, pou=prototype.name)
            prototype.symbols[upper] = value


def link_implements(checker: Any, project: Any) -> None:
    """Each function block's IMPLEMENTS list."""
    for pou in project.pous:
        info = checker.result.pous.get(pou.name.upper())
        if not pou.implements or info is None or info.name != pou.name:
            continue
        report = checker._reporter(f"{pou.name}/declarations", pou.name)
        if info.kind != "FUNCTION_BLOCK":
            report("ST-DECL", f"only a function block IMPLEMENTS interfaces, not a {pou.kind}", None)
            continue
        for name in pou.implements:
            interface = checker.result.interfaces.get(name.upper())
            if interface is None:
                known = [i.name for i in checker.result.interfaces.values()]
                report(
                    "ST-UNKNOWN-TYPE",
                    f"{pou.name} IMPLEMENTS '{name}', which is not an interface" + did_you_mean(name, known),
                    None,
                )
            else:
                info.interfaces.append(interface)


def check_implementations(checker: Any, blocks: list[PouInfo]) -> None:
    """Every method of every interface a function block implements (directly or through its base) is one of its
    methods, its own or inherited, with the same parameters and result; every PROPERTY one of its properties with
    the same type and (at least) the accessors the interface declares."""
    for fb in blocks:
        report = checker._reporter(f"{fb.name}/declarations", fb.name)
        for interface in fb.all_interfaces():
            accessors = [p for p in interface.methods.values() if p.method.key != p.method.name.upper()]
            for name in dict.fromkeys(p.method.name for p in accessors):  # each property once
                _check_property(fb, interface, name, report)
            for prototype in interface.methods.values():
                name = prototype.method.name
                if prototype.method.key != name.upper():
                    continue
                found = fb.find_method(prototype.method.key)
                if found is None:
                    if not fb.abstract:
                        report("ST-DECL", f"{fb.name} implements {interface.name} but has no method {name}", None)
                    continue
                difference = signature_difference(prototype, found)
                if difference:
                    report("ST-DECL", f"{found.name} implements {prototype.name} but {difference}", None)
                elif found.method.access != "PUBLIC":
                    report("ST-DECL", f"{found.name} implements {prototype.name}, so it must be PUBLIC", None)


def _check_property(fb: PouInfo, interface: PouInfo, name: str, report) -> None:
    """The PROPERTY ``name`` of ``interface`` (checked once, whichever accessors it declares) in ``fb``."""
    wanted, found = property_of(interface, name), property_of(fb, name)
    if found is None:
        if not fb.abstract:
            report("ST-DECL", f"{fb.name} implements {interface.name} but has no property {name}", None)
        return
    what = f"the property {fb.name}.{found.name} implements {interface.name}.{wanted.name}"
    pairs = (("GET", wanted.getter, found.getter), ("SET", wanted.setter, found.setter))
    missing = [kind for kind, declared, implemented in pairs if declared is not None and implemented is None]
    if not t.same(found.type, wanted.type):
        report("ST-DECL", f"{what} but its type is {found.type}, not {wanted.type}", None)
    elif missing:
        report("ST-DECL", f"{what} but has no {' or '.join(missing)}, which the interface declares", None)
    elif (found.getter or found.setter).method.access != "PUBLIC":
        report("ST-DECL", f"{what}, so it must be PUBLIC", None)


def check_attempt(checker: Any, stmt: ast.Assign) -> None:
    """``target ?= value``: the target an interface variable, the value an instance or an interface variable; or
    (IEC ed. 3 6.6.6.7) the target a REF_TO / POINTER TO a function block, the value a reference or pointer to
    another of the tree or an interface variable: the reference when its instance is of the target's FB or one
    extending it, else NULL."""
    target = checker.target(stmt.target)
    value = checker.expr(stmt.value)
    if target is t.ERROR or value is t.ERROR:
        return
    if attempted_fb(target) is not None:
        if not (attempted_fb(value) is not None or isinstance(value, t.InterfaceType)):
            message = (
                f"?= into a {target} tries a reference to a function block or an interface variable, not a {value}"
            )
            checker.report("ST-TYPE-MISMATCH", message, stmt.value)
        return
    if not isinstance(target, t.InterfaceType):
        checker.report("ST-TYPE-MISMATCH", f"?= assigns to a variable of an interface's type, not to a {target}", stmt)
    elif not isinstance(value, (t.InterfaceType, t.FbType)) or (isinstance(value, t.FbType) and value.pou is None):
        checker.report(
            "ST-TYPE-MISMATCH", f"?= tries an FB instance or an interface variable, not a {value}", stmt.value
        )


def attempted_fb(ty: t.Type) -> Any:
    """The user FB (PouInfo) a REF_TO / POINTER TO ``ty`` refers to, which ``?=`` may try; else None."""
    if isinstance(ty, t.PointerType) and not ty.implicit and isinstance(ty.target, t.FbType):
        return ty.target.pou
    return None


def reference_comparison(left: t.Type, right: t.Type) -> bool:
    """``i = j``, ``i <> NULL`` and CODESYS's ``i <> 0`` / ``p <> 0``: whether interface variables refer to one
    instance, whether a pointer or interface variable is NULL (CODESYS's 0: no other number is an address here).
    A pointer compared with 0 is CODESYS typing's only: IEC ed. 3 compares a reference with NULL and references."""
    if not isinstance(left, (t.InterfaceType, t.PointerType)):
        left, right = right, left
    if isinstance(left, t.PointerType):
        return t.null_literal(left, right)  # a REFERENCE TO compares its target's value
    zero = isinstance(right, t.UntypedInt) and right.value == 0
    return isinstance(left, t.InterfaceType) and (isinstance(right, (t.InterfaceType, t.NullType)) or zero)
