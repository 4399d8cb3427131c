"""Literals and generic operations take their type from their context (IEC 61131-3 ed. 2 2.4.1, ed. 3 6.4.2).

An untyped literal is ANY_INT or ANY_REAL until its context fixes it; a generic
operation (an arithmetic or logic operator, a standard function whose result is
its generic type: ADD, MAX, LIMIT, SEL, MUX, SQRT, EXPT ...) computes in the
smallest type that fits its typed operands *and* its context, and its literals
take that type. The context is what the value is used as: the assignment target,
the formal parameter, the other operand of a comparison, the declared type. The
checker types every expression bottom-up first (``BodyChecker.typed``: literals
untyped, generic operations in the ``lub`` of their typed operands), then
``settle`` walks down from where the expression is used and fixes each node's
``ty``. After it no node of a checked expression is untyped, so the lowering
reads every type it needs from the AST.

A literal that does not fit the type chosen for it is a located ST-RANGE error,
never a silent wrap (``16#FFFF`` into INT). A literal expression is folded exactly
as the scan computes it in that type (``32767 + 1`` in INT wraps, with a warning).
Without any context a literal expression takes the smallest of INT, DINT, LINT
(ULINT) that fits its values (ST-24), or LREAL. docs/st.md, "Literal typing".
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from ..iec import stdlib
from ..iec.values import f32, wrap
from . import ast
from . import types as t
from .rules import fold_arithmetic
from .types import ERROR, Type

_ARITHMETIC = frozenset({"+", "-", "*", "/", "MOD"})
_LOGIC = frozenset({"AND", "OR", "XOR"})
_FAMILY = {"+": "ANY_NUM", "-": "ANY_NUM", "*": "ANY_NUM", "/": "ANY_NUM", "MOD": "ANY_INT"}
_FAMILY.update({op: "ANY_BIT" for op in _LOGIC})


class FoldError(Exception):
    """A constant expression that has no value in its type: ``node`` says where."""

    def __init__(self, message: str, node: Any):
        super().__init__(message)
        self.node = node


# ---------------------------------------------------------------- choosing the type


def context_type(natural: Type, context: Type | None, family: str, literals: list[Type]) -> Type:
    """The type a generic operation computes in: its natural type widened to fit the context, when a type of
    ``family`` fits both; for an operation of literals only, the context itself when every literal may take it,
    else the smallest type of the family that fits them all (``literals``: their untyped types)."""
    if isinstance(natural, t.UNTYPED):
        if context is not None and t.in_family(context, family) and all(t.takes_literal(context, x) for x in literals):
            return context
        return default_type(literals, family)
    if context is None or context is ERROR or natural is ERROR:
        return natural
    wider = t.lub(natural, context)
    return wider if wider is not None and t.in_family(wider, family) else natural


def default_type(literals: list[Type], family: str = "ANY_NUM") -> Type:
    """The smallest type of ``family`` that fits every literal (ST-24: INT when they fit), LREAL with a real."""
    if any(isinstance(x, t.UntypedReal) for x in literals) or family == "ANY_REAL":
        return t.LREAL
    fallback = t.concrete(t.UntypedInt(), family)
    values = [x.value for x in literals if isinstance(x, (t.UntypedInt, t.UntypedReal))]
    for candidate in _CANDIDATES.get(family, _CANDIDATES["ANY_NUM"]):
        if all(t.literal_fits(candidate, value) for value in values):
            return candidate
    return fallback


_CANDIDATES = {
    "ANY_NUM": tuple(t.Elementary(n) for n in ("INT", "DINT", "LINT", "ULINT")),
    "ANY_BIT": tuple(t.Elementary(n) for n in ("BYTE", "WORD", "DWORD", "LWORD")),
}
_CANDIDATES["ANY_INT"] = _CANDIDATES["ANY_MAGNITUDE"] = _CANDIDATES["ANY_ELEMENTARY"] = _CANDIDATES["ANY_NUM"]
_CANDIDATES["ANY"] = _CANDIDATES["ANY_NUM"]


# ---------------------------------------------------------------- settling a checked expression


def settle(checker: Any, node: ast.Expr, context: Type | None) -> None:
    """Fix the types of ``node`` and everything below it that waited for a context (see the module docstring)."""
    handler = _SETTLE.get(type(node))
    if handler is not None:
        handler(checker, node, context)


def _literal(checker: Any, node: Any, context: Type | None) -> None:
    natural = node.ty
    if not isinstance(natural, t.UNTYPED):
        return
    if context is not None and not t.takes_literal(context, natural):
        if context is not ERROR:
            return  # the consumer reports "cannot assign ANY_INT literal to TIME" in its own words
        context = None
    target = context if context is not None else default_type([natural])
    _fix_literals(checker, node, target)


def _fix_literals(checker: Any, node: Any, target: Type) -> None:
    """A literal expression's nodes all take ``target``; a value that leaves it is reported (ST-RANGE)."""
    notes: list[tuple[Any, str]] = []
    try:
        fold(node, target, notes)
    except FoldError as error:
        checker.report("ST-RANGE", str(error), error.node)
    for where, message in notes:
        checker.report("ST-RANGE", message, where, severity="warning")
    _set_type(node, target)


def _set_type(node: Any, target: Type) -> None:
    node.ty = target
    if isinstance(node, ast.Unary):
        _set_type(node.operand, target)
    elif isinstance(node, ast.Binary):
        _set_type(node.left, target)
        _set_type(node.right, target)


def _unary(checker: Any, node: ast.Unary, context: Type | None) -> None:
    natural = node.ty
    if not _numeric(natural):
        settle(checker, node.operand, natural if natural is not ERROR else None)
        return
    final = _adapt(checker, node, context, "ANY_BIT" if node.op == "NOT" else "ANY_NUM")
    if final is not None:
        settle(checker, node.operand, final)


def _binary(checker: Any, node: ast.Binary, context: Type | None) -> None:
    op = node.op
    if op not in _FAMILY and op != "**":
        return  # comparisons settle their operands when typed; their BOOL result takes no context
    if not _numeric(node.ty):
        for operand in (node.left, node.right):  # TIME * n, pointer + n, STRING + STRING: operands keep their types
            settle(checker, operand, None)
        return
    if op == "**":  # EXPT: the base takes the context (within ANY_REAL); a typed exponent keeps its own type
        final = _adapt(checker, node, context, "ANY_REAL")
        if final is not None:
            settle(checker, node.left, final)
            settle(checker, node.right, final if isinstance(node.right.ty, t.UNTYPED) else None)
        return
    final = _adapt(checker, node, context, _FAMILY[op])
    if final is not None:
        settle(checker, node.left, final)
        settle(checker, node.right, final)


def _call(checker: Any, node: ast.Call, context: Type | None) -> None:
    function = node.ref
    if function is None and isinstance(node.ty, t.UntypedInt):  # SIZEOF: an integer whose value only the lowering knows
        node.ty = context if context is not None and t.takes_literal(context, node.ty) else t.INT
        return
    if not isinstance(function, stdlib.StdFunction) or function.result != stdlib.T or not _numeric(node.ty):
        return  # user functions, FB instances and fixed-result functions settled their arguments when typed
    generic = generic_arguments(function, node)
    family = next((p.type for p in function.inputs if p.generic), "ANY")
    final = _adapt(checker, node, context, family)
    if final is not None:
        for value in generic:
            settle(checker, value, final)


def _numeric(ty: Type) -> bool:
    """Numbers and bit strings adapt to their context; so do untyped literal expressions."""
    return isinstance(ty, t.UNTYPED) or (isinstance(ty, t.Elementary) and ty.category in _ADAPTING)


_ADAPTING = frozenset({"int", "bits", "real", "bool"})


def _adapt(checker: Any, node: Any, context: Type | None, family: str) -> Type | None:
    """Fix ``node.ty`` for its context; the type its operands are to take, or None when nothing is left to do
    (a literal expression, folded and fixed whole)."""
    natural = node.ty
    if isinstance(natural, t.UNTYPED) and literal_only(node):
        _literal(checker, node, context)
        return None
    final = context_type(natural, context, family, untyped_leaves(node) if isinstance(natural, t.UNTYPED) else [])
    _widened(checker, node, natural, final)
    node.ty = final
    return final


def untyped_leaves(node: Any) -> list[Type]:
    """The types of the literals an untyped operation is made of (through operators and generic standard calls)."""
    if isinstance(node, (ast.IntLit, ast.RealLit)):
        return [node.ty]
    if isinstance(node, ast.Unary):
        return untyped_leaves(node.operand)
    if isinstance(node, ast.Binary):
        return untyped_leaves(node.left) + untyped_leaves(node.right)
    if isinstance(node, ast.Call) and isinstance(node.ref, stdlib.StdFunction):
        return [leaf for value in generic_arguments(node.ref, node) for leaf in untyped_leaves(value)]
    return [node.ty] if isinstance(node.ty, t.UNTYPED) else []


def generic_arguments(function: stdlib.StdFunction, node: ast.Call) -> list[ast.Expr]:
    """The argument expressions of a standard call that feed its generic inputs (they share one type, FUN-02)."""
    found = []
    for position, arg in enumerate(a for a in node.args if a.name is None):
        name = function.input_name(position)
        pin = function.pin(name) if name is not None else None
        if pin is not None and pin.generic:
            found.append(arg.value)
    for arg in node.args:
        if arg.name is not None and not arg.output:
            pin = function.pin(arg.name)
            if pin is not None and pin.generic:
                found.append(arg.value)
    return found


def _widened(checker: Any, node: Any, natural: Type, final: Type) -> None:
    if not isinstance(natural, t.UNTYPED) and final is not natural and final != natural:
        checker.report(
            "ST-IMPLICIT-CONV",
            f"computed in {final}, the type its result is used as: its {natural} operands are converted implicitly",
            node,
            severity="warning",
        )


_SETTLE: dict[type, Callable[[Any, Any, Type | None], None]] = {
    ast.IntLit: _literal,
    ast.RealLit: _literal,
    ast.Unary: _unary,
    ast.Binary: _binary,
    ast.Call: _call,
}


# ---------------------------------------------------------------- constant expressions


def fold(node: Any, target: Type, notes: list[tuple[Any, str]] | None = None) -> object:
    """The value of a literal expression computed in ``target`` exactly as the engine computes it at run time
    (integers wrap to the width, REAL rounds to binary32 at every step, FUN-90, TYP-03).

    A literal that does not fit ``target`` or a division by zero raises FoldError; a step whose result wraps or
    overflows adds ``(node, message)`` to ``notes`` (the checker warns: the value is what the scan would compute)."""
    if isinstance(node, ast.IntLit):
        return _literal_value(node.value, target, node)
    if isinstance(node, ast.RealLit):
        return _literal_value(node.value, target, node)
    if isinstance(node, ast.Unary):
        if node.op == "-" and isinstance(node.operand, (ast.IntLit, ast.RealLit)):  # a signed literal: -32768
            return _literal_value(-node.operand.value, target, node)
        _in_family(node, "NOT" if node.op == "NOT" else "-", target)
        value: Any = fold(node.operand, target, notes)
        if node.op == "-":
            return _result(-value, target, node, notes)
        return _not(value, target)
    if isinstance(node, ast.Binary):
        _in_family(node, node.op, target)
        left, right = fold(node.left, target, notes), fold(node.right, target, notes)
        return _result(_apply(node, left, right, target), target, node, notes)
    raise FoldError("not a constant expression", node)


_OPERATION_FAMILY = {**_FAMILY, "NOT": "ANY_BIT"}
_WORDING = {"ANY_NUM": "numbers (ANY_NUM)", "ANY_INT": "integers (ANY_INT)", "ANY_BIT": "BOOL or bit strings (ANY_BIT)"}


def _in_family(node: Any, op: str, target: Type) -> None:
    """The operation is defined on ``target`` (a literal expression can be given a type its operators lack:
    ``0.0 = NOT 2`` would compute NOT in LREAL). A literal expression for a bit string (``w := 16#FF00 + 16#FF``)
    computes as an unsigned integer of its width."""
    family = _OPERATION_FAMILY.get(op, "ANY_NUM")
    bits = isinstance(target, t.Elementary) and target.category == "bits" and family != "ANY_BIT"
    if not t.in_family(target, family) and not bits:
        raise FoldError(f"'{op}' needs {_WORDING[family]}, not {target}", node)


def _literal_value(value: Any, target: Type, node: Any) -> object:
    """A literal stored in ``target``: it must fit (``16#FFFF`` is no INT)."""
    if not isinstance(target, t.Elementary):
        return value
    category = target.category
    if category == "real":
        stored = f32(float(value)) if target.name == "REAL" else float(value)
        if not math.isfinite(stored):
            raise FoldError(f"{_shown(value)} is out of range for {target}", node)
        return stored
    if isinstance(value, float):
        raise FoldError(f"{_shown(value)} is not an integer: it cannot be {target}", node)
    if category == "bool":
        if value not in (0, 1):
            raise FoldError(f"{value} is not a BOOL (0 or 1)", node)
        return bool(value)
    low, high = target.info.min, target.info.max
    if low is not None and not low <= value <= high:
        raise FoldError(f"{value} is out of range for {target} ({low}..{high})", node)
    return value


def _result(value: Any, target: Type, node: Any, notes: list[tuple[Any, str]] | None) -> object:
    """An operation's result stored in ``target`` as the scan stores it: wrapped, or rounded to REAL."""
    if not isinstance(target, t.Elementary) or isinstance(value, bool):
        return value
    if target.category == "real":
        stored = f32(float(value)) if target.name == "REAL" else float(value)
        if not math.isfinite(stored) and notes is not None:
            notes.append((node, f"this constant expression overflows {target}: it is {stored}"))
        return stored
    stored = wrap(value, target.name)
    if stored != value and notes is not None:
        notes.append((node, f"this constant expression is {value}, out of range for {target}: it wraps to {stored}"))
    return stored


def _shown(value: Any) -> str:
    return repr(value) if isinstance(value, float) else str(value)


def _apply(node: ast.Binary, left: Any, right: Any, target: Type) -> Any:
    op = node.op
    if op in ("+", "-", "*", "/", "MOD"):
        value = fold_arithmetic(op, left, right)  # x MOD 0 = 0, the IEC body (docs/runtime.md)
        if value is None:
            raise FoldError("division by zero in a constant expression", node)
        return value
    if isinstance(left, bool) or isinstance(right, bool):
        return {"AND": left and right, "OR": left or right, "XOR": left != right, "AND_THEN": left and right}.get(
            op, left or right
        )  # OR_ELSE
    return {"AND": left & right, "OR": left | right, "XOR": left ^ right}[op]


def _not(value: Any, target: Type) -> Any:
    if isinstance(value, bool):
        return not value
    assert isinstance(target, t.Elementary)  # NOT of a number: a bit string (_in_family)
    bits = target.info.bits
    return value ^ ((1 << bits) - 1)


def literal_only(node: Any) -> bool:
    """Is ``node`` a literal expression (numeric literals, unary minus/NOT and operators on them)?"""
    if isinstance(node, (ast.IntLit, ast.RealLit)):
        return True
    if isinstance(node, ast.Unary):
        return literal_only(node.operand)
    if isinstance(node, ast.Binary) and node.op in _FAMILY:  # not '**': EXPT's special cases are the runtime's
        return literal_only(node.left) and literal_only(node.right)
    return False


def untyped_result(op: str, left: Type, right: Type) -> Type:
    """The untyped type of an operation on two literal expressions, with its exact value where it has one (the
    default type of ``100000 * 2`` standing alone depends on it)."""
    combined = t.untyped_pair(left, right)
    values = (getattr(left, "value", None), getattr(right, "value", None))
    if not isinstance(combined, t.UntypedInt) or None in values:
        return combined
    try:
        return t.UntypedInt(_apply(ast.Binary(op, ast.IntLit(0), ast.IntLit(0)), *values, None))
    except (FoldError, KeyError):
        return combined
