"""Boolean power-flow building blocks shared by LD and FBD: AND/OR/NOT, edge detection, coil writes.

One definition of what a contact, an edge and a coil do (GR-15..25, LD-06), so
an LD coil and an FBD output node with the same mode compile to the same IR.
"""

from __future__ import annotations

from collections.abc import Callable

from .nodes import Assign, Binary, Const, Expr, If, Origin, Stmt, Unary, Var
from .types import BOOL

TRUE = Const(True, BOOL)
FALSE = Const(False, BOOL)


def and_(left: Expr, right: Expr) -> Expr:
    """``left AND right``; the left rail (constant TRUE) drops out."""
    if _is_true(left):
        return right
    if _is_true(right):
        return left
    return Binary("AND", left, right, BOOL)


def _is_true(value: Expr) -> bool:
    """The constant TRUE? (Only a constant can be: other nodes are not compared field by field.)"""
    return value is TRUE or (type(value) is Const and value == TRUE)


def or_(values: list[Expr]) -> Expr:
    if not values:
        return FALSE
    result = values[0]
    for value in values[1:]:
        result = Binary("OR", result, value, BOOL)
    return result


def not_(value: Expr) -> Expr:
    if isinstance(value, Const):
        return Const(not value.value, BOOL)
    return Unary("NOT", value, BOOL)


def edge(rising: bool, value: Expr, memory: Var, origin: Origin) -> tuple[Expr, Stmt]:
    """A rising (falling) edge of ``value`` since the last evaluation, and the statement that remembers it.

    ``memory`` starts FALSE, as the M of R_TRIG/F_TRIG (SFB-11, SFB-12): a rising edge is seen
    in the first evaluation when ``value`` is TRUE, a falling one only after a real TRUE.
    """
    detected = and_(value, not_(memory)) if rising else and_(memory, not_(value))
    return detected, Assign(memory, value, origin)


def coil(
    mode: str, store: Callable[[Expr, Origin], Stmt], power: Expr, memory: Callable[[], Var], origin: Origin
) -> list[Stmt]:
    """The write of an LD coil or FBD output node in ``mode`` (normal, negated, set, reset, p, n); ``store``
    makes the assignment (a variable, or a bit of one).

    ``memory`` makes the hidden slot an edge coil needs (GR-24, GR-25).
    """
    if mode == "normal":
        return [store(power, origin)]
    if mode == "negated":
        return [store(not_(power), origin)]
    if mode in ("set", "reset"):  # LD-06: IF power THEN x := TRUE / FALSE
        write = store(Const(mode == "set", BOOL), origin)
        return [write] if power == TRUE else [If([(power, [write])], [], origin)]
    detected, remember = edge(mode == "p", power, memory(), origin)
    return [store(detected, origin), remember]
