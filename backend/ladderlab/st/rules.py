"""Rules shared by the statement, call and CASE checks: assignment compatibility, constant folding."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from . import ast
from . import types as t
from .types import ERROR, Type


@dataclass
class EnumValue:
    """What a bare enum value name resolves to."""

    type: t.EnumType
    name: str
    value: int


def root_name(node: ast.Expr) -> ast.Name | None:
    while isinstance(node, (ast.Member, ast.Index, ast.Deref)):
        node = node.base
    return node if isinstance(node, ast.Name) else None


def assignable_or_report(checker: Any, target: Type, value: Type, node, what: str) -> bool:
    """Check ``value`` can be stored in ``target`` (ST-23/25); report and return False when not."""
    verdict = t.assignable(target, value)
    if verdict is None:
        return True
    if verdict == "widen":
        checker.report("ST-IMPLICIT-CONV", f"{value} is converted implicitly to {target}", node, severity="warning")
        return True
    if verdict == "narrow":
        checker.report(
            "ST-IMPLICIT-NARROW",
            f"{value} is narrowed implicitly to {target} (CODESYS typing): the value is cut as {value}_TO_{target} "
            "does; write the conversion to say so",
            node,
            severity="warning",
        )
        return True
    if isinstance(value, t.UntypedInt) and isinstance(target, t.Elementary) and target.category in ("int", "bits"):
        checker.report(
            "ST-RANGE", f"{value.value} is out of range for {target} ({target.info.min}..{target.info.max})", node
        )
        return False
    hint, shown = t.conversion_hint(target, value), str(value)
    if t.zero_for_null(target, value):
        hint, shown = f": {t.NULL_NOT_ZERO}", "0"
    if what == "assign":
        message = f"cannot assign {shown} to {target}{hint}"
    elif what == "init":
        message = f"cannot initialise {target} with {shown}{hint}"
    else:
        message = f"{what}: expected {target}, got {shown}{hint}"
    checker.report("ST-TYPE-MISMATCH", message, node)
    return False


def constant_value(checker: Any, node: ast.Expr | None, depth: int = 0) -> int | float | None:
    """Value of a constant expression (literals, CONSTANT variables, enum values), else None."""
    if node is None or depth > 20:
        return None
    if isinstance(node, (ast.IntLit, ast.RealLit)):
        return node.value
    if isinstance(node, ast.TypedLit):
        if isinstance(node.value, ast.Name):  # TColor#blue: the checker typed it as the enumeration
            enum, upper = getattr(node, "ty", None), node.value.name.upper()
            return enum.values[upper][1] if isinstance(enum, t.EnumType) and upper in enum.values else None
        return constant_value(checker, node.value, depth + 1)
    if isinstance(node, ast.Unary) and node.op == "-":
        value = constant_value(checker, node.operand, depth + 1)
        return -value if value is not None else None
    if isinstance(node, ast.Name):
        symbol = checker.lookup(node.name)
        if symbol is not None:
            return constant_value(checker, symbol.init, depth + 1) if symbol.constant else None
        values = checker.enum_values(node.name)
        return values[0].value if len(values) == 1 else None
    if isinstance(node, ast.Binary) and node.op in ("+", "-", "*", "/", "MOD"):
        left = constant_value(checker, node.left, depth + 1)
        right = constant_value(checker, node.right, depth + 1)
        if left is None or right is None:
            return None
        return fold_arithmetic(node.op, left, right)
    return None


def fold_arithmetic(op: str, left: Any, right: Any) -> Any:
    """``+ - * / MOD`` on constants, exactly as the scan computes them before storing: integer division
    truncates toward zero, ``x MOD 0`` is 0 (the IEC body); None for a division by zero."""
    if op == "+":
        return left + right
    if op == "-":
        return left - right
    if op == "*":
        return left * right
    if right == 0:
        return 0 if op == "MOD" and isinstance(right, int) and isinstance(left, int) else None
    if op == "/" and (isinstance(left, float) or isinstance(right, float)):
        return left / right
    quotient = abs(left) // abs(right)
    quotient = quotient if (left < 0) == (right < 0) else -quotient
    return quotient if op == "/" else left - right * quotient


def check_init(checker: Any, ty: Type, init: ast.Init) -> None:
    """An initial value against its variable's type (TYP-25, TYP-33)."""
    if isinstance(init, ast.ArrayInit):
        if not isinstance(ty, t.ArrayType):
            if ty is not ERROR:
                checker.report("ST-TYPE-MISMATCH", f"an array initialiser [...] needs an array, not {ty}", init)
            return
        count = 0
        for item in init.items:
            value = item.value if isinstance(item, ast.RepeatInit) else item
            count += item.count if isinstance(item, ast.RepeatInit) else 1
            if value is not None:
                check_init(checker, ty.element, value)
        size = 1
        for dim in ty.dims:
            size *= (dim[1] - dim[0] + 1) if dim is not None else 1
        if None not in ty.dims and count > size:
            checker.report("ST-INIT", f"{count} initial values for an array of {size} elements", init)
        return
    if isinstance(init, ast.StructInit):
        if not isinstance(ty, (t.StructType, t.FbType)):
            if ty is not ERROR:
                checker.report("ST-TYPE-MISMATCH", f"a structure initialiser (...) needs a structure, not {ty}", init)
            return
        for name, value in init.fields:
            field_type = _field_type(ty, name)
            if field_type is None:
                checker.report("ST-UNKNOWN-MEMBER", f"{ty.name} has no field '{name}'", init)
            else:
                check_init(checker, field_type, value)
        return
    value = checker.expr(init, ty)
    if value is not ERROR:
        assignable_or_report(checker, ty, value, init, "init")


def _field_type(ty: Type, name: str) -> Type | None:
    if isinstance(ty, t.StructType):
        found = ty.fields.get(name.upper())
        return found[1] if found else None
    if ty.pou is not None:
        symbol = ty.pou.symbols.get(name.upper())
        return symbol.type if symbol else None
    pin = next((p for p in (*ty.std.inputs, *ty.std.outputs) if p.name == name.upper()), None)
    return t.elementary(pin.type) if pin else None
