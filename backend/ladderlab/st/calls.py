"""Checking calls: user functions, programs, FB instances, standard functions and ADR/REF/SIZEOF.

Spec: POU-13..15 (formal / positional calls), POU-23..25 and ST-25 (FB calls,
``=>`` outputs), VAR-51 / ST-55 (VAR_IN_OUT needs a variable), FUN-02 (generic
inputs share one type), POU-32 (only programs call programs), ST-57.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

from ..iec import stdlib
from ..iec.spelling import did_you_mean
from ..iec.values import article
from . import ast
from . import types as t
from .context_typing import default_type, untyped_leaves
from .gvls import shared_use
from .libraries import library_of
from .methods import SUPER, check_method_call, method_callee, this_type
from .printer import print_expression
from .rules import assignable_or_report, root_name
from .symbols import THIS, PouInfo, Symbol
from .types import ERROR, VOID, Type

_SYSTEM = {"ADR", "REF", "SIZEOF", "__ISVALIDREF"}
_SELF = ("THIS", "SUPER")
_WRITABLE = (ast.Name, ast.Member, ast.Index, ast.Deref, ast.DirectAddr)


@dataclass
class Param:
    name: str
    type: Type
    in_out: bool = False


def check_call(checker: Any, node: ast.Call, statement: bool) -> Type:
    callee = node.callee
    method = method_callee(checker, callee)
    if method is not None:
        return check_method_call(checker, node, *method)
    if isinstance(callee, ast.Deref) and isinstance(callee.base, ast.Name) and callee.base.name.upper() in _SELF:
        return _body_call(checker, node, statement)
    if not isinstance(callee, ast.Name):
        return _instance_call(checker, node, checker.expr(callee), statement)
    upper = callee.name.upper()
    symbol = checker.lookup(callee.name)
    if symbol is not None:
        callee.ref, callee.ty = symbol, symbol.type
        return _instance_call(checker, node, symbol.type, statement)
    if checker.result.shared and shared_use(checker.result, checker.report, callee, callee.name):
        _args_untyped(checker, node)
        return ERROR
    pou = checker.result.pous.get(upper)
    if pou is not None:
        return _pou_call(checker, node, pou, statement)
    if upper in _SYSTEM:
        return _system_call(checker, node, upper)
    function = stdlib.function(upper)
    if function is not None:
        node.ref = function
        return _std_call(checker, node, function)
    if stdlib.function_block(upper) is not None:
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"{callee.name} is a function block type: declare an instance (e.g. t1 : {upper};) and call the instance",
            callee,
        )
        return ERROR
    _args_untyped(checker, node)
    library = library_of(callee.name)
    if library is not None:
        hint = (
            f": it is in the {library} library, which the project does not use: add it in the project's Library manager"
            f" (--library {library} for a .st file)"
        )
    else:
        hint = did_you_mean(callee.name, [*checker.result.pous, *stdlib.FUNCTIONS])
    checker.report("ST-UNKNOWN-POU", f"unknown function '{callee.name}'" + hint, callee)
    return ERROR


def _body_call(checker: Any, node: ast.Call, statement: bool) -> Type:
    """``SUPER^(...)`` runs the base's body on the same instance (CODESYS), in a derived function block's body or
    in its methods; ``THIS^(...)`` in a method runs the instance's own body (its class's: a derived FB's body for a
    derived instance). The arguments set the (inherited) inputs and read the outputs as in any FB call. A body that
    would run itself again (``THIS^()`` in the body, or through methods) is ST-RECURSION (POU-02, methods.py)."""
    callee: ast.Deref = node.callee
    caller = checker.pou
    word = callee.base.name.upper()
    in_method = caller is not None and caller.method is not None
    owner = caller.method.owner if in_method else caller
    if caller is None or owner.kind != "FUNCTION_BLOCK":
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"{word}^() runs a function block's body: call it in a function block's body or methods, not here",
            node,
        )
        return ERROR
    if word == THIS and not in_method:
        _args_untyped(checker, node)
        message = f"THIS^() in {owner.name}'s own body would run the body again from inside itself (POU-02)"
        checker.report("ST-RECURSION", message, node)
        return ERROR
    base = this_type(checker, callee)
    if base is None or base is ERROR:
        _args_untyped(checker, node)
        return ERROR
    callee.ty = base
    if not statement:
        _args_untyped(checker, node)
        checker.report("ST-NOT-CALLABLE", f"{word}^() runs a body: call it as a statement", node)
        return ERROR
    if word == SUPER:
        owner.runs_base_body = True
    caller.bodies_called.append((base.pou, word == THIS, node))
    inputs = [
        Param(s.name, s.type, s.var_class == "VAR_IN_OUT") for s in base.pou.parameters("VAR_INPUT", "VAR_IN_OUT")
    ]
    outputs = [Param(s.name, s.type) for s in base.pou.parameters("VAR_OUTPUT")]
    check_arguments(checker, node, "SUPER^", inputs, outputs, function=False)
    return VOID


def _args_untyped(checker: Any, node: ast.Call) -> None:
    """Still check the argument expressions (their own errors) when the callee is unknown."""
    for arg in node.args:
        checker.expr(arg.value)


def _pou_call(checker: Any, node: ast.Call, pou: PouInfo, statement: bool) -> Type:
    node.ref = pou
    if checker.pou is not None:
        checker.pou.calls.add(pou.name.upper())
    if pou.kind == "FUNCTION_BLOCK":
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"{pou.name} is a function block type: declare an instance (e.g. inst : {pou.name};) and call the instance",
            node.callee,
        )
        return ERROR
    if pou.plant:
        _args_untyped(checker, node)
        checker.report(
            "ST-PLANT",
            f"{pou.name} is a plant: it models the process and runs in the plant task before every scan; "
            "control code cannot call it (read and write the signals it shares instead)",
            node.callee,
        )
        return ERROR
    if pou.kind == "PROGRAM":
        if checker.pou is not None and checker.pou.kind != "PROGRAM":
            caller = "method" if checker.pou.method is not None else checker.pou.kind.lower().replace("_", " ")
            checker.report("ST-NOT-CALLABLE", f"a {caller} cannot call the program {pou.name}", node.callee)
        if not statement:
            checker.report("ST-NOT-CALLABLE", f"the program {pou.name} has no value: call it as a statement", node)
    inputs = [Param(s.name, s.type, s.var_class == "VAR_IN_OUT") for s in pou.parameters("VAR_INPUT", "VAR_IN_OUT")]
    outputs = [Param(s.name, s.type) for s in pou.parameters("VAR_OUTPUT")]
    check_arguments(checker, node, pou.name, inputs, outputs, function=pou.kind == "FUNCTION")
    return (pou.return_type or VOID) if pou.kind == "FUNCTION" else VOID


def _instance_call(checker: Any, node: ast.Call, ty: Type, statement: bool) -> Type:
    if ty is ERROR:
        _args_untyped(checker, node)
        return ERROR
    if not isinstance(ty, t.FbType):
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"'{print_expression(node.callee)}' is a {ty}, not a function or function block instance",
            node.callee,
        )
        return ERROR
    node.ref = root_name(node.callee).ref if root_name(node.callee) is not None else None
    if isinstance(node.ref, Symbol) and node.ref.var_class == "VAR_INPUT" and node.callee is root_name(node.callee):
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"'{node.ref.name}' is an input: a function block instance passed as an input is a copy whose "
            "outputs can be read, but it cannot be called (declare it VAR_IN_OUT to call the caller's instance)",
            node.callee,
        )
        return ERROR
    if not statement:
        _args_untyped(checker, node)
        checker.report(
            "ST-NOT-CALLABLE",
            f"the function block instance '{print_expression(node.callee)}' cannot be "
            "called inside an expression: call it as a statement and read its outputs (e.g. inst.Q)",
            node,
        )
        return ERROR
    if ty.std is not None:
        inputs, outputs = _std_fb_params(ty.std.name)
    else:
        inputs = [
            Param(s.name, s.type, s.var_class == "VAR_IN_OUT") for s in ty.pou.parameters("VAR_INPUT", "VAR_IN_OUT")
        ]
        outputs = [Param(s.name, s.type) for s in ty.pou.parameters("VAR_OUTPUT")]
    check_arguments(checker, node, ty.name, inputs, outputs, function=False)
    return VOID


@functools.cache
def _std_fb_params(name: str) -> tuple[list[Param], list[Param]]:
    """A standard FB's inputs and outputs as parameters (the catalogue is fixed; read-only lists)."""
    std = stdlib.function_block(name)
    return (
        [Param(p.name, t.elementary(p.type) or ERROR) for p in std.inputs],
        [Param(p.name, t.elementary(p.type) or ERROR) for p in std.outputs],
    )


def check_arguments(
    checker: Any, node: ast.Call, callee: str, inputs: list[Param], outputs: list[Param], *, function: bool
) -> None:
    """Formal or positional arguments against the callee's parameters (POU-13..15, ST-25, ST-55)."""
    formal = [a for a in node.args if a.name is not None]
    positional = [a for a in node.args if a.name is None]
    if formal and positional:
        _args_untyped(checker, node)
        checker.report(
            "ST-CALL-ARGS", f"do not mix formal (name := value) and positional arguments in a call to {callee}", node
        )
        return
    if positional and (len(positional) > len(inputs) or (function and len(positional) < len(inputs))):
        _args_untyped(checker, node)
        checker.report("ST-CALL-ARGS", f"{callee} takes {len(inputs)} input(s), got {len(positional)}", node)
        return
    for arg, param in zip(positional, inputs):
        _input(checker, arg, param, callee)
    by_name_in = {p.name.upper(): p for p in inputs} | {"EN": Param("EN", t.BOOL)}
    by_name_out = {p.name.upper(): p for p in outputs} | {"ENO": Param("ENO", t.BOOL)}
    seen: set[str] = set()
    for arg in formal:
        upper = arg.name.upper()
        if upper in seen:
            checker.report("ST-CALL-ARGS", f"parameter '{arg.name}' is given twice", arg)
        seen.add(upper)
        if arg.output and upper in by_name_out:
            _output(checker, arg, by_name_out[upper])
        elif not arg.output and upper in by_name_in:
            _input(checker, arg, by_name_in[upper], callee)
        else:
            checker.expr(arg.value)
            _misplaced(checker, arg, callee, by_name_in, by_name_out)
    if function and not positional:
        missing = [p.name for p in inputs if p.in_out and p.name.upper() not in seen]
        if missing:
            checker.report(
                "ST-CALL-ARGS", f"missing in-out parameter(s) {', '.join(missing)} in the call to {callee}", node
            )


def _misplaced(checker: Any, arg: ast.Arg, callee: str, inputs: dict, outputs: dict) -> None:
    upper = arg.name.upper()
    if arg.output and upper in inputs:
        checker.report("ST-CALL-ARGS", f"'{arg.name}' is an input of {callee}: write {arg.name} := value", arg)
    elif not arg.output and upper in outputs:
        checker.report("ST-CALL-ARGS", f"'{arg.name}' is an output of {callee}: write {arg.name} => variable", arg)
    else:
        names = [p.name for p in (*inputs.values(), *outputs.values())]
        checker.report("ST-CALL-ARGS", f"{callee} has no parameter '{arg.name}'" + did_you_mean(arg.name, names), arg)


def _input(checker: Any, arg: ast.Arg, param: Param, callee: str) -> None:
    if param.in_out:
        _in_out(checker, arg, param, callee)
        return
    if isinstance(param.type, t.PointerType) and param.type.implicit:
        _bind(checker, arg, param, callee)
        return
    value = checker.expr(arg.value, param.type)
    assignable_or_report(checker, param.type, value, arg.value, f"input {param.name} of {callee}")


def _bind(checker: Any, arg: ast.Arg, param: Param, callee: str) -> None:
    """A REFERENCE TO input given a variable is bound to it for the call (CODESYS), as ``REF=`` binds."""
    value = checker.expr(arg.value)
    reference: t.PointerType = param.type  # type: ignore[assignment]  # _input checked it is one
    if value is ERROR:
        return
    if not isinstance(arg.value, _WRITABLE):
        checker.report("ST-NOT-LVALUE", f"{reference} input {param.name} of {callee} needs a variable", arg.value)
    elif not t.same(reference.target, value) and not t.derived(reference.target, value):
        checker.report(
            "ST-TYPE-MISMATCH", f"input {param.name} of {callee}: a {reference} cannot refer to a {value}", arg.value
        )
    else:
        problem = unreferable(checker, arg.value)
        if problem is not None:
            checker.report("ST-REF", f"input {param.name} of {callee} cannot refer to {problem}", arg.value)


def _in_out(checker: Any, arg: ast.Arg, param: Param, callee: str) -> None:
    value = checker.expr(arg.value, param.type)
    root = root_name(arg.value)
    if not isinstance(arg.value, _WRITABLE):
        checker.report(
            "ST-NOT-LVALUE",
            f"in-out parameter {param.name} of {callee} needs a variable, not an expression or literal",
            arg.value,
        )
    elif root is not None and isinstance(root.ref, Symbol) and root.ref.constant:
        checker.report(
            "ST-CONST-WRITE",
            f"the CONSTANT '{root.ref.name}' cannot be passed as in-out parameter {param.name}",
            arg.value,
        )
    elif not t.same(param.type, value) and not _open_array(param.type, value) and not t.derived(param.type, value):
        checker.report(
            "ST-TYPE-MISMATCH",
            f"in-out parameter {param.name} of {callee} needs {article(str(param.type))}, got {value}",
            arg.value,
        )


def _open_array(param: Type, value: Type) -> bool:
    """``ARRAY [*] OF T`` in-out parameters take any array of T."""
    return (
        isinstance(param, t.ArrayType)
        and None in param.dims
        and isinstance(value, t.ArrayType)
        and t.same(param.element, value.element)
    )


def _output(checker: Any, arg: ast.Arg, param: Param) -> None:
    target = checker.target(arg.value)
    if t.assignable(target, param.type) == "error":
        checker.report(
            "ST-TYPE-MISMATCH",
            f"output {param.name} is {param.type} and cannot be stored in {target}"
            + t.conversion_hint(target, param.type),
            arg.value,
        )


def _std_call(checker: Any, node: ast.Call, function: stdlib.StdFunction) -> Type:
    formal = [a for a in node.args if a.name is not None and a.name.upper() not in ("EN", "ENO")]
    positional = [a for a in node.args if a.name is None]
    if formal and positional:
        checker.report("ST-CALL-ARGS", f"do not mix formal and positional arguments in a call to {function.name}", node)
    minimum = len(function.inputs)
    if positional and (len(positional) < minimum or (not function.extensible and len(positional) > minimum)):
        expected = f"at least {minimum}" if function.extensible else str(minimum)
        checker.report("ST-CALL-ARGS", f"{function.name} takes {expected} input(s), got {len(positional)}", node)
    bound: list[tuple[ast.Arg, stdlib.Pin]] = []
    for position, arg in enumerate(positional):
        name = function.input_name(position)
        if name is not None:
            bound.append((arg, function.pin(name)))
        else:
            checker.expr(arg.value)
    for arg in formal:
        pin = function.pin(arg.name)
        if pin is None or arg.output:
            checker.expr(arg.value)
            names = [p.name for p in function.inputs]
            checker.report(
                "ST-CALL-ARGS", f"{function.name} has no input '{arg.name}'" + did_you_mean(arg.name, names), arg
            )
        else:
            bound.append((arg, pin))
    generic = _generic_type(checker, node, function, bound)
    if generic is ERROR:
        return ERROR
    if function.result != stdlib.T:
        return t.elementary(function.result) or ERROR
    if isinstance(generic, t.StringType) and function.group == "string":  # CONCAT(a, b) is longer than a
        return t.StringType(generic.wide)
    return generic


#: Shifts and rotations, which CODESYS typing also applies to integers (as the bits of their type).
_SHIFTS = frozenset({"SHL", "SHR", "ROL", "ROR"})


def _codesys_shift(function: stdlib.StdFunction, value: Type) -> bool:
    return function.name.upper() in _SHIFTS and t.codesys_typing() and t.in_family(value, "ANY_INT")


def _takes(family: str, fixed: Type | None, value: Type) -> bool:
    """Whether a non-generic input of type (or family) ``family`` takes ``value``: a member of the family, or
    assignable to the named type. CODESYS typing also gives an ANY_INT input a bit string (SHL's N as a BYTE)."""
    if t.in_family(value, family):
        return True
    if fixed is None:
        return family == "ANY_INT" and t.codesys_typing() and t.category(value) == "bits"
    return t.assignable(fixed, value) != "error"


def _generic_type(checker: Any, node: ast.Call, function: stdlib.StdFunction, bound) -> Type:
    """Type every argument; the generic inputs share one type T within the pin's family (FUN-02).

    T is the ``lub`` of the typed generic arguments (untyped when all are literals). When the result is T the
    call adapts to its context, which fixes T later (st/context_typing.py); otherwise T is fixed here."""
    shared: Type | None = None
    generic_values = []
    for arg, pin in bound:
        if not pin.generic:
            fixed = t.elementary(pin.type)
            value = checker.expr(arg.value, fixed)
            if value is ERROR:
                return ERROR
            if not _takes(pin.type, fixed, value):
                message = f"input {pin.name} of {function.name} must be {pin.type}, not {value}"
                checker.report("ST-TYPE-MISMATCH", message, arg.value)
            continue
        value = checker.typed(arg.value)
        if value is ERROR:
            return ERROR
        generic_values.append(arg.value)
        if shared is None:
            shared = value
            continue
        combined, verdict = t.common(shared, value)
        if verdict == "error":
            checker.report(
                "ST-TYPE-MISMATCH",
                f"{function.name} needs inputs of one type: got {shared} and {value}; "
                "convert one of them with a *_TO_* function",
                arg.value,
            )
            return ERROR
        if verdict == "widen":
            checker.report(
                "ST-IMPLICIT-CONV",
                f"{function.name} mixes {shared} and {value}: the narrower one is converted implicitly",
                arg.value,
                severity="warning",
            )
        shared = t.untyped_pair(shared, value) if isinstance(combined, t.UNTYPED) else combined
    generic_pins = [p for p in function.inputs if p.generic]
    if shared is None:
        return ERROR if generic_pins and function.result == stdlib.T else t.VOID
    family = generic_pins[0].type
    if family == "ANY_REAL" and t.real_from_integer(shared):
        checker.report(
            "ST-IMPLICIT-CONV",
            f"{function.name} computes in LREAL (CODESYS typing): its {shared} input is converted implicitly",
            node,
            severity="warning",
        )
        shared = t.LREAL
    if not t.in_family(shared, family) and not _codesys_shift(function, shared):
        checker.report("ST-TYPE-MISMATCH", f"{function.name} works on {family}, not on {shared}", node)
        return ERROR
    if function.result != stdlib.T:  # a comparison: T takes no context from the BOOL result
        fixed = shared
        if isinstance(shared, t.UNTYPED):
            fixed = default_type([leaf for value in generic_values for leaf in untyped_leaves(value)], family)
        for value in generic_values:
            checker.settle(value, fixed)
    return shared


def _system_call(checker: Any, node: ast.Call, name: str) -> Type:
    """ADR / REF (pointer to a variable, TYP-42), SIZEOF (size in bytes, TYP-45) and CODESYS __ISVALIDREF."""
    if len(node.args) != 1 or node.args[0].name is not None:
        _args_untyped(checker, node)
        checker.report("ST-CALL-ARGS", f"{name} takes exactly one argument", node)
        return ERROR
    value = node.args[0].value
    if name == "__ISVALIDREF":  # CODESYS: whether a REFERENCE TO (or any reference) refers to a variable
        ty = checker.reference(value)
        if ty is not ERROR and not isinstance(ty, t.PointerType):
            checker.report("ST-TYPE-MISMATCH", f"__ISVALIDREF needs a reference, not {ty}", value)
        return t.BOOL
    if name == "SIZEOF":
        if isinstance(value, ast.Name) and (t.elementary(value.name) or value.name.upper() in checker.result.types):
            return t.UntypedInt()
        checker.expr(value)
        return t.UntypedInt()
    ty = checker.expr(value)
    if not isinstance(value, _WRITABLE):
        checker.report("ST-NOT-LVALUE", f"{name} needs a variable", value)
        return t.PointerType(ty)
    problem = unreferable(checker, value)
    if problem is not None:
        checker.report("ST-REF", f"{name} cannot refer to {problem}", value)
    return t.PointerType(ty)


def unreferable(checker: Any, value: ast.Expr) -> str | None:
    """Why a reference to ``value`` is certainly wrong (None: it may be referred to). A FUNCTION's own variables
    (its result, inputs, in-outs, locals and VAR_TEMP) and a program's or FB's VAR_TEMP may be: the engine marks
    such a reference dead when the call returns and a dereference after that is the runtime fault
    ``dangling_reference`` (CODESYS accepts them: OSCAT's string functions walk their own input with
    ``pt := ADR(str)``, FBs a temporary buffer). Refused: another function's result and a CONSTANT, which could
    then be written."""
    root = value
    while isinstance(root, (ast.Member, ast.Index)):
        root = root.base
    own_function = checker.pou is not None and checker.pou.kind == "FUNCTION"
    if isinstance(root, ast.Name) and isinstance(root.ref, PouInfo) and root.ref.kind == "FUNCTION":
        if own_function and root.ref.name.upper() == checker.pou.name.upper():
            return None  # the function's own result variable
        return f"the result of the function {root.ref.name}: it lives only while the call runs"
    if not isinstance(root, ast.Name) or not isinstance(root.ref, Symbol):
        return None  # through a reference (r^.x): the variable r refers to
    symbol: Symbol = root.ref
    if symbol.constant:
        return f"the CONSTANT {symbol.name}: it could be written through the reference"
    return None
