"""CODESYS's FB_init: the method an instance runs by itself when it is initialised, with its declaration's arguments.

``fb : F(n := 3);`` gives ``F.FB_init`` its own inputs (after the two the system passes, ``bInitRetains`` and
``bInCopyCode``); ``a : ARRAY [0..1] OF F[(n := 1), (n := 2)];`` gives each element its own. Neither form is a type
of its own in the grammar: ``F(n := 3)`` reads as a based enumeration and ``F(3)`` as a sized type, which name a
function block only here (``instance_spec``). The arguments are checked against the FB_init the instance runs
(``check_instance_args``) and kept on the variable's Symbol; the engine runs the calls (ir/fb_init.py).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..iec import stdlib
from ..iec.spelling import did_you_mean
from . import ast
from . import types as t
from .rules import EnumValue, assignable_or_report
from .symbols import PouInfo, Symbol

#: The inputs every FB_init has first, which the system sets (CODESYS compiler error C0119).
SYSTEM_INPUTS = ("BINITRETAINS", "BINCOPYCODE")
#: Methods CODESYS calls by itself; LadderLab runs FB_init and FB_exit (docs/st.md, "FB_init and FB_exit").
IMPLICIT_METHODS = ("FB_INIT", "FB_EXIT", "FB_REINIT")

#: One instance's arguments as written: (input name, or None when positional; value; node to locate errors at)
Written = list[tuple[str | None, ast.Expr, Any]]


def instance_spec(spec: ast.TypeSpec, block: Callable[[str], bool]) -> tuple[ast.TypeSpec, list[Written] | None]:
    """``spec`` without FB_init arguments, and the arguments of each instance it declares (None: none given);
    ``block`` says whether a name is a function block's."""
    if isinstance(spec, ast.EnumType) and spec.base and block(spec.base):
        args: Written = [
            (v.name, v.value, v) if v.value is not None else (None, ast.Name(v.name, v.span), v) for v in spec.values
        ]
        return ast.NamedType(spec.base, spec.span), [args]
    if isinstance(spec, ast.SizedType) and block(spec.name):
        return ast.NamedType(spec.name, spec.span), [[(None, spec.size, spec.size)]]
    if isinstance(spec, ast.PositionalArgsType):
        return ast.NamedType(spec.name, spec.span), [[(None, arg, arg) for arg in spec.args]]
    if isinstance(spec, ast.InstanceArgsType):  # (written for one instance, it is one list for one instance)
        return ast.NamedType(spec.name, spec.span), _lists(spec)
    if isinstance(spec, ast.ArrayType) and isinstance(spec.element, ast.InstanceArgsType):
        element = spec.element
        return ast.ArrayType(spec.ranges, ast.NamedType(element.name, element.span), spec.span), _lists(element)
    return spec, None


def _lists(spec: ast.InstanceArgsType) -> list[Written]:
    return [[(name, value, e) for name, value in e.fields] for e in spec.elements]


def project_blocks(pous: dict[str, PouInfo]) -> Callable[[str], bool]:
    """Whether a name is a function block's: the project's (checked) or a standard one."""

    def block(name: str) -> bool:
        info = pous.get(name.upper())
        return (info is not None and info.kind == "FUNCTION_BLOCK") or stdlib.function_block(name) is not None

    return block


def check_instance_args(checker: Any, symbol: Symbol, written: list[Written], at: Any) -> None:
    """The FB_init arguments of ``symbol`` (an instance or an array of instances): each an input of the FB_init its
    FB runs, given once, of its type, constant; every input without an initial value given. Sets
    ``symbol.init_args`` to each instance's ``(INPUT, value)`` pairs."""
    report = checker.report
    ty = symbol.type
    count = 1
    while isinstance(ty, t.ArrayType):
        if None in ty.dims:
            return
        for low, high in ty.dims:
            count *= high - low + 1
        ty = ty.element
    if not isinstance(ty, t.FbType):
        if ty is not t.ERROR:
            report("ST-CALL-ARGS", f"only an instance of a function block takes FB_init arguments, not {ty}", at)
        return
    method = ty.pou.find_method("FB_INIT") if ty.pou is not None else None
    if method is None:
        report("ST-CALL-ARGS", f"{ty.name} has no FB_init method: its instances take no arguments", at)
        return
    if len(written) != count:
        report(
            "ST-INIT",
            f"{len(written)} FB_init argument lists for {count} instances of {ty.pou.name}: give one per element",
            at,
        )
        return
    symbol.init_args = [_one_instance(checker, method, args, ty.pou.name, at) for args in written]


def _one_instance(checker: Any, method: PouInfo, args: Written, fb: str, at: Any) -> list[tuple[str, ast.Expr]]:
    report = checker.report
    inputs = user_inputs(method)
    given: dict[str, ast.Expr] = {}
    seen: set[str] = set()  # (an input given with a wrong value is not missing too)
    for position, (name, value, node) in enumerate(args):
        if name is None:
            if position >= len(inputs):
                report("ST-CALL-ARGS", f"the FB_init of {fb} takes {len(inputs)} inputs, not {len(args)}", node)
                continue
            param = inputs[position]
        else:
            param = next((p for p in inputs if p.name.upper() == name.upper()), None)
            if param is None:
                if name.upper() in SYSTEM_INPUTS:
                    report("ST-CALL-ARGS", f"{name} is the system's to set when the instance is initialised", node)
                else:
                    names = [p.name for p in inputs]
                    report(
                        "ST-CALL-ARGS",
                        f"the FB_init of {fb} has no input '{name}'" + did_you_mean(name, names),
                        node,
                    )
                continue
        if param.name.upper() in seen:
            report("ST-CALL-ARGS", f"the FB_init input {param.name} is given twice", node)
            continue
        seen.add(param.name.upper())
        found = checker.expr(value, param.type)
        what = f"FB_init input {param.name}"
        if found is t.ERROR or not assignable_or_report(checker, param.type, found, value, what):
            continue
        if not _constant(value):
            report(
                "ST-CONST-EXPR",
                f"the FB_init input {param.name} needs a constant here: LadderLab passes it when the instance is made",
                value,
            )
            continue
        given[param.name.upper()] = value
    _report_missing(checker, method, fb, seen, at)
    return list(given.items())


def _report_missing(checker: Any, method: PouInfo, fb: str, given: set[str], at: Any, array: bool = False) -> None:
    missing = [p.name for p in user_inputs(method) if p.name.upper() not in given and p.init is None]
    if missing:
        example = ", ".join(f"{name} := ..." for name in missing)
        form = f"ARRAY [...] OF {fb}[({example}), ...]" if array else f"{fb}({example})"
        checker.report("ST-CALL-ARGS", f"the FB_init of {fb} needs {', '.join(missing)}: declare it as {form}", at)


def check_no_args(checker: Any, symbol: Symbol, in_test: bool = False) -> None:
    """An instance declared without FB_init arguments: its FB_init needs none (each input has an initial value).
    ``in_test``: a test file's variable (docs/testing.md), whose instances are made without theirs (a warning)."""
    if symbol.var_class in ("VAR_IN_OUT", "VAR_EXTERNAL"):
        return
    if in_test:
        holder = _fb_init_inside(symbol.type, set())
        if holder is not None:
            checker.report(
                "ST-DECL",
                f"{holder}'s FB_init does not run for a test's variables: the instances keep their declared values",
                symbol,
                severity="warning",
            )
        return
    ty, array = symbol.type, False
    while isinstance(ty, t.ArrayType):
        ty, array = ty.element, True
    method = ty.pou.find_method("FB_INIT") if isinstance(ty, t.FbType) and ty.pou is not None else None
    if method is not None:
        _report_missing(checker, method, ty.pou.name, set(), symbol, array)


def _fb_init_inside(ty: Any, seen: set[int]) -> str | None:
    """The FB with an FB_init that a variable of ``ty`` holds an instance of (itself, inside, in an array or a
    STRUCT), or None."""
    while isinstance(ty, t.ArrayType):
        ty = ty.element
    if id(ty) in seen:
        return None
    seen.add(id(ty))
    if isinstance(ty, t.StructType):
        return next((f for _, field in ty.fields.values() if (f := _fb_init_inside(field, seen))), None)
    if not isinstance(ty, t.FbType) or ty.pou is None:
        return None
    if ty.pou.find_method("FB_INIT") is not None:
        return ty.pou.name
    made = (s.type for s in ty.pou.symbols.values() if s.var_class not in ("VAR_IN_OUT", "VAR_EXTERNAL", "VAR_TEMP"))
    return next((f for member in made if (f := _fb_init_inside(member, seen))), None)


def check_struct_members(checker: Any) -> None:
    """A STRUCT's member that is an instance (or an array of them) gets no FB_init arguments: its FB_init must need
    none."""
    report = checker._reporter("types", None)
    for typedef in checker.result.types.values():
        spec, ty = typedef.decl.type, typedef.type
        if isinstance(spec, ast.StructType) and isinstance(ty, t.StructType):
            for member in spec.members:
                for name in member.names:
                    found = ty.fields.get((name.name or "").upper())
                    if found is not None:
                        _member_needs_none(report, found[1], name)


def _member_needs_none(report: Any, ty: Any, at: Any) -> None:
    while isinstance(ty, t.ArrayType):
        ty = ty.element
    method = ty.pou.find_method("FB_INIT") if isinstance(ty, t.FbType) and ty.pou is not None else None
    missing = [p.name for p in user_inputs(method) if p.init is None] if method is not None else []
    if missing:
        report(
            "ST-CALL-ARGS",
            f"the FB_init of {ty.pou.name} needs {', '.join(missing)}, which a STRUCT's member cannot be given: "
            "give the inputs initial values, or declare the instance as a variable",
            at,
        )


_LITERALS = (ast.IntLit, ast.RealLit, ast.BoolLit, ast.StringLit, ast.TimeLit, ast.TypedLit)


def _constant(node: ast.Expr) -> bool:
    """A checked expression of literals, CONSTANT variables and enumeration values only."""
    if isinstance(node, _LITERALS):
        return True
    if isinstance(node, (ast.Name, ast.Member)) and isinstance(node.ref, EnumValue):
        return True
    if isinstance(node, ast.Name):
        return isinstance(node.ref, Symbol) and node.ref.constant
    if isinstance(node, ast.Unary):
        return _constant(node.operand)
    if isinstance(node, ast.Binary):
        return _constant(node.left) and _constant(node.right)
    return False


def user_inputs(method: PouInfo) -> list[Symbol]:
    """An FB_init's inputs that the declaration gives: all but the system's two."""
    return [p for p in method.parameters("VAR_INPUT") if p.name.upper() not in SYSTEM_INPUTS]


def check_fb_init_methods(checker: Any, fbs: list[PouInfo]) -> None:
    """Each FB_init starts with the inputs bInitRetains and bInCopyCode (BOOL) and has no other kind of parameter;
    one of a derived FB takes its base's inputs first, in their order (CODESYS C0119; Beckhoff's "FB_init with
    derived function blocks"); an FB_exit takes bInCopyCode (BOOL)."""
    for fb in fbs:
        for key, needs in (("FB_INIT", ["bInitRetains", "bInCopyCode"]), ("FB_EXIT", ["bInCopyCode"])):
            method = fb.methods.get(key)
            if method is None:
                continue
            report = checker._reporter(f"{method.name}/declarations", method.name)
            params = method.parameters()
            head = [(p.name.upper(), p.type) for p in params[: len(needs)]]
            if head != [(name.upper(), t.BOOL) for name in needs]:
                inputs = " and ".join(needs)
                report("ST-DECL", f"an {method.method.name} method needs the inputs {inputs} of type BOOL first", None)
                continue
            if any(p.var_class != "VAR_INPUT" for p in params):
                report("ST-DECL", f"{method.name} takes inputs only: nothing calls it to pass in-outs or outputs", None)
                continue
            whole = [p.name for p in params if isinstance(p.type, (t.ArrayType, t.StructType, t.FbType))]
            if whole:
                report(
                    "ST-DECL",
                    f"{method.name}'s input {whole[0]} is an array, structure or instance, which LadderLab cannot pass "
                    "when it calls the method by itself: pass a reference (REFERENCE TO, POINTER TO) or the values",
                    None,
                )
                continue
            inherited = fb.base.find_method(key) if fb.base is not None else None
            if inherited is None:
                continue
            theirs = [(p.name.upper(), p.type) for p in inherited.parameters()]
            mine = [(p.name.upper(), p.type) for p in params[: len(theirs)]]
            if len(mine) != len(theirs) or any(a[0] != b[0] or not t.same(a[1], b[1]) for a, b in zip(mine, theirs)):
                listed = ", ".join(p.name for p in inherited.parameters())
                report(
                    "ST-DECL",
                    f"{method.name} must take the inputs of {inherited.name} first, in their order ({listed})",
                    None,
                )
