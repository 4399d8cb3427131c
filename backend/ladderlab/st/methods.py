"""METHODs of function blocks (IEC 61131-3 ed. 3, 6.6.5; CODESYS): declaring, checking bodies, checking calls.

A method ``M`` of the FB ``F`` is checked as a function ``F.M`` (``PouInfo`` with ``method`` set) whose hidden
first in-out ``THIS`` is the instance it is called on: the method's own variables are a function's (fresh in
every call), and a name it does not declare is a variable of ``F`` reached through ``THIS`` (ir/context.py).
A call ``inst.M(a := 1)`` passes ``inst`` as ``THIS``; ``THIS^`` inside a method is that instance, in the FB's own
body the instance running it (the engine's ``self``, ir/context.py ``this_var``).

A PROGRAM has methods and properties too (CODESYS): its instance is ``THIS``, so ``M()`` and ``THIS^.M()`` in the
program run on the instance running it, and ``Prog.M()`` elsewhere on the instance named like the program (the one
``Prog.x`` reads, ir/lower_expr.py ``program_instance``). Nothing extends a program: its methods are neither
ABSTRACT nor FINAL, and PROTECTED is PRIVATE.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from ..iec.spelling import did_you_mean
from ..model.project import Method, PouAction, Property
from . import ast
from . import types as t
from .parser import parse_declarations, parse_statements, parse_type
from .printer import print_expression
from .registers import check_registers
from .symbols import THIS, MethodInfo, PouInfo, PropertyRef, Symbol
from .types import ERROR, VOID, Type

# The VAR blocks a method may declare (its VAR and VAR_OUTPUT, like a function's variables, are fresh in every call;
# the outputs are copied to the call's ``=>`` targets when it returns: ir/method_outputs.py).
_ALLOWED = {"VAR", "VAR_TEMP", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL"}


def method_file(fb: str, method: str, part: str) -> str:
    """The diagnostics' file of a method's declarations, body or return type: ``<FB>.<method>/<part>``."""
    return f"{fb}.{method}/{part}"


def declare_methods(
    checker: Any, fb: PouInfo, methods: list[Method], properties: list[Property] = (), actions: list[PouAction] = ()
) -> list[tuple[PouInfo, Method]]:
    """Register and declare the methods of ``fb`` (``checker``: the ProjectChecker), its PROPERTYs' accessors
    as methods ``<P>.GET`` (returning the property's type) and ``<P>.SET`` (whose input is the property's name),
    and its ACTIONs (CODESYS, IL-08) as public methods without variables or result: an action runs on the
    instance's variables like a method, so ``inst.A()``, ``CAL inst.A`` and ``A()`` inside the FB are method calls;
    their bodies are parsed and checked later by ``check_method_body``, once every POU and method is declared."""
    from .checker import check_identifier  # the checker imports this module

    declared = []
    members = [(method, method.name, method.name) for method in methods]
    as_actions = [Method(name=action.name, body=action.body) for action in actions]
    members += [(method, method.name, method.name) for method in as_actions]
    for prop in properties:
        for kind, accessor in (("GET", prop.get), ("SET", prop.set)):
            if accessor is not None:
                as_method = Method(
                    name=prop.name,
                    access=prop.access,
                    return_type=prop.type if kind == "GET" else None,
                    declarations=(f"VAR_INPUT {prop.name} : {prop.type}; END_VAR " if kind == "SET" else "")
                    + accessor.declarations,
                    body=accessor.body,
                )
                members.append((as_method, prop.name, f"{prop.name}.{kind}"))
    members_word = "methods, properties or actions" if actions else "methods or properties"
    member_word = "method, property or action" if actions else "method or property"
    for method, name, label in members:
        report = checker._reporter(method_file(fb.name, label, "declarations"), f"{fb.name}.{label}")
        key = label.upper()
        action = any(method is a for a in as_actions)
        if fb.kind not in ("FUNCTION_BLOCK", "PROGRAM") or (action and fb.kind != "FUNCTION_BLOCK"):
            owners = "a function block has actions" if action else "a function block or a program has methods"
            report("ST-DECL", f"only {owners}, not a {fb.kind.lower().replace('_', ' ')}", None)
            continue
        check_identifier(name, None, report)
        if fb.kind == "PROGRAM" and (method.abstract or method.final):  # (CODESYS: a program is no class to extend)
            word = "ABSTRACT" if method.abstract else "FINAL"
            report("ST-DECL", f"a program's method cannot be {word}: nothing extends a program", None)
        upper = name.upper()
        if key in fb.methods or (key != upper and upper in fb.methods):  # (methods are declared first)
            report("ST-DUPLICATE", f"{fb.name} has two {members_word} called '{name}'", None)
            continue
        if upper in fb.symbols:
            report("ST-DUPLICATE", f"'{name}' is both a variable and a {member_word} of {fb.name}", None)
            continue
        info = PouInfo(f"{fb.name}.{label}", "FUNCTION", "st", None)
        info.method = MethodInfo(fb, name, method.access, method.final, method.abstract, key, action)
        info.symbols[THIS] = Symbol(
            THIS, "VAR_IN_OUT", t.FbType(fb.name, pou=fb), ast.NamedType(fb.name), pou=info.name
        )
        fb.methods[key] = info
        _declare(checker, info, method, report)
        declared.append((info, method))
    return declared


def _declare(checker: Any, info: PouInfo, method: Method, report) -> None:
    from .body import BodyChecker

    fb = info.method.owner
    label = info.name[len(fb.name) + 1 :]
    if method.return_type:
        file = method_file(fb.name, label, "return_type")
        parsed = parse_type(method.return_type, file=file, pou=info.name)
        checker.result.diagnostics += parsed.diagnostics
        if parsed.ast is not None:
            info.return_spec = parsed.ast
            where = checker._reporter(file, info.name)
            info.return_type = checker.resolve(parsed.ast, BodyChecker(checker.result, info, where))
            if isinstance(info.return_type, t.FbType):
                where("ST-DECL", f"a method cannot return a function block instance ({info.return_type.name})", None)
                info.return_type = ERROR
        else:
            info.return_type = ERROR
    parsed = parse_declarations(method.declarations, file=method_file(fb.name, label, "declarations"), pou=info.name)
    checker.result.diagnostics += parsed.diagnostics
    body_checker = BodyChecker(checker.result, info, report)
    for block in parsed.ast or []:
        if block.kind not in _ALLOWED:
            report("ST-DECL", f"{block.kind} is not allowed in a method", block)
            continue
        checker.declare_block(block, info.symbols, body_checker, info)
    for symbol in info.symbols.values():
        if symbol.name.upper() in fb.symbols and symbol.var_class != "VAR_EXTERNAL" and symbol.name != THIS:
            report(
                "ST-DUPLICATE",
                f"'{symbol.name}' is also a variable of {fb.name}: the method's own would hide it",
                symbol,
                severity="warning",
            )


def check_method_body(checker: Any, info: PouInfo, method: Method) -> None:
    """Parse and check a method's statements; an ABSTRACT method has none."""
    from .body import BodyChecker

    fb = info.method.owner
    file = method_file(fb.name, info.name[len(fb.name) + 1 :], "body")
    report = checker._reporter(file, info.name)
    parsed = parse_statements(method.body, file=file, pou=info.name)
    checker.result.diagnostics += parsed.diagnostics
    if parsed.ast is None:
        return
    if method.abstract:
        if parsed.ast:
            report("ST-DECL", f"the ABSTRACT method {method.name} has no body: a derived FB implements it", None)
        return
    body = BodyChecker(checker.result, info, report)
    body.statements(parsed.ast)
    check_registers(parsed.ast, report)
    info.body = parsed.ast
    fb.calls |= {name for name in info.calls if name != fb.name.upper()}


def method_callee(checker: Any, callee: ast.Expr) -> tuple[PouInfo, ast.Expr | None] | None:
    """The method a call's callee names, with the instance it is called on (None: the caller's own ``THIS``),
    or None when the callee is no method: ``inst.M``, ``THIS^.M`` or, in an FB or its method, a bare ``M``."""
    caller = checker.pou
    if isinstance(callee, ast.Name):
        own = _own_fb(caller)
        if own is not None and checker.lookup(callee.name) is None:
            found = own.find_method(callee.name)
            return (found, None) if found is not None else None
        return None
    if not isinstance(callee, ast.Member):
        return None
    base = callee.base
    if not isinstance(base, (ast.Name, ast.Member, ast.Index, ast.Deref)):
        return None
    from .body import BodyChecker

    silent = BodyChecker(checker.result, caller, lambda *args, **kwargs: None)  # typed for real once it is a method
    base_type = silent.expr(copy.deepcopy(base))
    if isinstance(base_type, t.InterfaceType):  # a call through an interface variable (st/interfaces.py)
        owner = base_type.info
    elif isinstance(base_type, t.FbType) and base_type.pou is not None:
        owner = base_type.pou
    else:
        return None
    found = owner.find_method(callee.name)
    if found is None:
        return None
    checker.expr(base)
    return found, base


def action_inputs(checker: Any, call: ast.Call) -> list[ast.Stmt]:
    """``Inst.Reset(In := FALSE)`` (IL-08 and its ST form, seed 003; CODESYS): an action has no parameters of its
    own, so the inputs it is called with are the instance's - returned as assignments to run first, and taken
    off ``call``. Any other call: nothing (``checker``: a body checker of the caller, not reporting)."""
    if not call.args or not isinstance(call.callee, ast.Member):
        return []
    found = method_callee(checker, copy.deepcopy(call.callee))
    if found is None or found[1] is None or not found[0].method.action:
        return []
    if any(arg.name is None or arg.output for arg in call.args):
        return []  # the call check reports it as written (an action takes no outputs or positional values)
    inputs: list[ast.Stmt] = [
        ast.Assign(ast.Member(copy.deepcopy(found[1]), arg.name, arg.span), arg.value, arg.span) for arg in call.args
    ]
    call.args = []
    return inputs


SUPER = "SUPER"


def is_super(node: ast.Expr) -> bool:
    """``SUPER^``: the instance a method was called on, seen as its base FB (calls through it are not dispatched)."""
    return isinstance(node, ast.Deref) and isinstance(node.base, ast.Name) and node.base.name.upper() == SUPER


def this_type(checker: Any, node: ast.Deref) -> Type | None:
    """``THIS^`` in a function block, a program or their methods: the instance the code runs on; ``SUPER^``: the
    same seen as the FB's base. None: neither (or a variable declared with that name)."""
    caller, base = checker.pou, node.base
    if not isinstance(base, ast.Name) or base.name.upper() not in (THIS, SUPER):
        return None
    declared = checker.lookup(base.name)
    if declared is not None and (caller is None or declared is not caller.this()):
        return None  # a variable someone called THIS (edition 2 code)
    owner = _own_fb(caller)
    if owner is None:
        checker.report(
            "ST-UNKNOWN-VAR",
            f"{base.name.upper()}^ is only known in a function block, a program and their methods",
            node,
        )
        return ERROR
    if base.name.upper() == THIS:
        base.ty = t.FbType(owner.name, pou=owner)
        return base.ty
    if owner.base is None:
        checker.report("ST-UNKNOWN-VAR", f"SUPER^: {owner.name} does not extend another function block", node)
        return ERROR
    base.ty = t.FbType(owner.base.name, pou=owner.base)
    return base.ty


def check_access(checker: Any, info: MethodInfo, node: ast.Expr, what: str, verb: str) -> None:
    """PRIVATE: only the FB's own code may use it; PROTECTED: also the FBs derived from it; a plant's (a PROGRAM
    modelling the process, issue 21): only the plant itself (located errors)."""
    caller_fb = _own_fb(checker.pou)
    if info.owner.plant and caller_fb is not info.owner:
        checker.report(
            "ST-PLANT",
            f"{what} {info.owner.name}.{info.name} belongs to the plant {info.owner.name}, which models the process: "
            f"control code cannot {verb} it (read and write the signals it shares instead)",
            node,
        )
        return
    if (info.access == "PRIVATE" and caller_fb is not info.owner) or (
        info.access == "PROTECTED" and (caller_fb is None or not caller_fb.derives_from(info.owner))
    ):
        if info.owner.kind == "PROGRAM":  # (nothing derives from a program: PROTECTED is PRIVATE)
            who = "its own program"
        elif info.access == "PRIVATE":
            who = "its own function block"
        else:
            who = "its function block and those derived from it"
        checker.report(
            "ST-NOT-ACCESSIBLE",
            f"{what} {info.owner.name}.{info.name} is {info.access}: only {who} may {verb} it",
            node,
        )


def property_of(fb: PouInfo, name: str) -> PropertyRef | None:
    """The PROPERTY ``name`` of ``fb`` (its own or inherited accessors), or None."""
    getter, setter = fb.find_method(f"{name}.GET"), fb.find_method(f"{name}.SET")
    if getter is None and setter is None:
        return None
    ty = getter.return_type if getter is not None else setter.symbols[name.upper()].type
    return PropertyRef((getter or setter).method.name, ty, getter, setter)


def check_property(checker: Any, node: ast.Name | ast.Member, fb: PouInfo) -> Type | None:
    """A PROPERTY used by name (``inst.P``, or ``P`` in its FB's code): its type (None: no property)."""
    found = property_of(fb, node.name)
    if found is None:
        return None
    node.ref = found
    check_access(checker, (found.getter or found.setter).method, node, "the property", "use")
    if checker.pou is not None:  # (reading or writing: either accessor may run; SUPER^.P is not dispatched)
        dispatched = not (isinstance(node, ast.Member) and is_super(node.base))
        checker.pou.methods_called += [(m, dispatched) for m in (found.getter, found.setter) if m is not None]
    return found.type or ERROR


def own_property(checker: Any, node: ast.Name) -> Type | None:
    """``P`` in the code of a function block (or its method) that has the PROPERTY ``P``."""
    owner = _own_fb(checker.pou)
    return check_property(checker, node, owner) if owner is not None else None


def _own_fb(caller: PouInfo | None) -> PouInfo | None:
    """The function block (or PROGRAM, CODESYS) whose instance ``THIS^`` is in ``caller``'s code: its own, or a
    method's owner."""
    if caller is not None and caller.method is not None:
        return caller.method.owner
    return caller if caller is not None and caller.kind in ("FUNCTION_BLOCK", "PROGRAM") else None


def is_self(node: ast.Expr) -> bool:
    """``THIS^`` or ``SUPER^`` (``this_type`` typed it: no variable of that name is declared)."""
    return (
        isinstance(node, ast.Deref)
        and isinstance(node.base, ast.Name)
        and node.base.name.upper() in (THIS, SUPER)
        and node.base.ref is None
    )


def check_method_call(checker: Any, node: ast.Call, method: PouInfo, instance: ast.Expr | None) -> Type:
    """``inst.M(...)``: whether the caller may call it (its access specifier), then its arguments as a function's."""
    from .calls import Param, check_arguments

    info = method.method
    node.ref = method
    caller = checker.pou
    caller_fb = _own_fb(caller)
    check_access(checker, info, node.callee, "the method", "call")
    if info.abstract and instance is not None and is_super(instance):  # otherwise a derived FB's runs
        checker.report(
            "ST-NOT-CALLABLE", f"the method {info.owner.name}.{info.name} is ABSTRACT: it has no body to run", node
        )
    if instance is not None and isinstance(node.callee, ast.Member):
        node.callee.ref = method
    if caller is not None:  # through SUPER^ exactly that method runs; otherwise any override may
        caller.methods_called.append((method, instance is None or not is_super(instance)))
    if (
        caller is not None
        and info.owner.kind != "INTERFACE"
        and (caller_fb is None or not caller_fb.derives_from(info.owner))
    ):
        caller.calls.add(info.owner.name.upper())  # (its own FB's methods are no call of another POU)
    inputs = [Param(s.name, s.type, s.var_class == "VAR_IN_OUT") for s in method.parameters("VAR_INPUT", "VAR_IN_OUT")]
    outputs = [Param(s.name, s.type) for s in method.parameters("VAR_OUTPUT")]
    name = f"{info.owner.name}.{info.name}" if instance is None else f"{print_expression(instance)}.{info.name}"
    check_arguments(checker, node, name, inputs, outputs, function=True)
    return method.return_type or VOID


def unknown_member_hint(fb: PouInfo, name: str) -> str:
    """A did-you-mean over an FB's pins and methods."""
    return did_you_mean(name, [s.name for s in fb.parameters()] + [m.method.name for m in fb.methods.values()])


def check_method_recursion(checker: Any, methods: list[PouInfo], blocks: list[PouInfo]) -> None:
    """POU-02 for methods: no method may call itself, directly or through others - counting every method a
    dispatched call may run (the overrides in derived FBs, the implementations of an interface's method) and the
    bodies ``THIS^()`` (the instance's class's: the FB's or a derived one's) and ``SUPER^()`` run, with the methods
    those call (a body that calls the method whose ``THIS^()`` runs it)."""

    def runs(called: PouInfo, dispatched: bool) -> list[PouInfo]:
        owner, key = called.method.owner, called.method.key
        found = [
            fb.find_method(key) for fb in blocks if dispatched and (fb.derives_from(owner) or fb.implements(owner))
        ]
        return [called, *(m for m in found if m is not None and m is not called)]

    def edges(pou: PouInfo) -> list[tuple[PouInfo, Any]]:
        """What ``pou`` (a method or an FB body) runs, each with the call to locate a cycle at (None: the method)."""
        found = [(target, None) for called, dispatched in pou.methods_called for target in runs(called, dispatched)]
        for fb, dispatched, call in pou.bodies_called:
            derived = [b for b in blocks if dispatched and b is not fb and b.derives_from(fb)]
            found += [(body, call) for body in (fb, *derived)]
        return found

    def name(pou: PouInfo) -> str:
        return pou.name if pou.method is not None else f"{pou.name} (body)"

    done: set[int] = set()

    def report(cycle: list[PouInfo], calls: list[tuple[PouInfo, Any]]) -> None:
        """At the first THIS^() / SUPER^() of the cycle (``calls``: each caller with its body call, or None), else
        at the method the cycle comes back to."""
        message = f"recursive call {' -> '.join(name(m) for m in cycle)}: methods must not call themselves (POU-02)"
        caller, call = next(((c, n) for c, n in calls if n is not None), (None, None))
        if caller is not None:
            owner = caller.method
            file = method_file(owner.owner.name, owner.name, "body") if owner else f"{caller.name}/body"
            checker._reporter(file, caller.name)("ST-RECURSION", message, call)
            return
        target = cycle[-1]
        fb = target.method.owner
        file = method_file(fb.name, target.name[len(fb.name) + 1 :], "body")
        checker._reporter(file, target.name)("ST-RECURSION", message, None)

    for method in methods:
        if id(method) not in done and _visit_methods(method, [method], [], edges, report, done):
            return


def _visit_methods(
    pou: PouInfo,
    path: list[PouInfo],
    calls: list[tuple[PouInfo, Any]],
    edges: Callable[[PouInfo], list[tuple[PouInfo, Any]]],
    report: Callable[[list[PouInfo], list[tuple[PouInfo, Any]]], None],
    done: set[int],
) -> bool:
    """Depth first from ``pou`` (``calls``: the call into each of ``path`` after the first); True once a cycle is
    reported (one report is enough). (A module function, not a closure calling itself: that closure was a
    reference cycle that kept the checker and its result alive until a collection; issue 27.)"""
    for target, call in edges(pou):
        if target in path:
            start = path.index(target)
            report([*path[start:], target], [*calls[start:], (pou, call)])
            return True
        if id(target) not in done and _visit_methods(
            target, [*path, target], [*calls, (pou, call)], edges, report, done
        ):
            return True
    done.add(id(pou))
    return False
