"""CASE statement rules (ST-28, ST-66): integer or enum selector, constant labels, overlap warnings."""

from __future__ import annotations

from typing import Any

from . import ast
from . import types as t
from .printer import print_expression
from .rules import EnumValue, constant_value
from .types import ERROR


def check_case(checker: Any, stmt: ast.Case) -> None:
    selector = checker.expr(stmt.selector)
    if selector is not ERROR and not (t.counts(selector) or isinstance(selector, t.EnumType)):
        checker.report(
            "ST-TYPE-MISMATCH", f"the CASE selector must be an integer or an enumeration, not {selector}", stmt.selector
        )
        selector = ERROR
    covered: list[tuple[int | float, int | float, ast.Expr | ast.CaseRange]] = []
    for branch in stmt.branches:
        for label in branch.labels:
            bounds = _label_bounds(checker, label, selector)
            if bounds is None:
                continue
            for low, high, other in covered:
                if bounds[0] <= high and low <= bounds[1]:
                    checker.report(
                        "ST-CASE-OVERLAP",
                        f"CASE label {_text(label)} overlaps {_text(other)}: only the first matching branch runs",
                        label,
                        severity="warning",
                    )
                    break
            covered.append((*bounds, label))
        checker.statements(branch.body)
    checker.statements(stmt.else_body or [])


def _label_bounds(checker: Any, label: ast.Expr | ast.CaseRange, selector) -> tuple | None:
    parts = [label.low, label.high] if isinstance(label, ast.CaseRange) else [label]
    values = []
    for part in parts:
        ty = checker.expr(part, selector)
        if ty is ERROR:
            return None
        if selector is not ERROR and t.assignable(selector, ty) == "error":
            checker.report("ST-TYPE-MISMATCH", f"CASE label {_text(part)} is {ty}, the selector is {selector}", part)
            return None
        value = part.ref.value if isinstance(getattr(part, "ref", None), EnumValue) else constant_value(checker, part)
        if value is None:
            checker.report("ST-CONST-EXPR", f"CASE label {_text(part)} must be a constant", part)
            return None
        values.append(value)
    return values[0], values[-1]


def _text(label: ast.Expr | ast.CaseRange) -> str:
    if isinstance(label, ast.CaseRange):
        return f"{print_expression(label.low)}..{print_expression(label.high)}"
    return print_expression(label)
