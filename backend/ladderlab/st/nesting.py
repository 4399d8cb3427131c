"""How deeply a parsed text nests, measured without recursion, against the documented limits.

Every later stage (checker, lowering, code generator) recurses per level, on a stack sized for
``limits.EXPRESSION_DEPTH`` and ``limits.STATEMENT_DEPTH`` (deep.py). Text nested deeper is
refused here, at the construct where it crosses the limit, so nothing after the parser meets it.
Expression depth counts the operators, calls, selectors and literals on the way from a statement
(or a declaration) down to a leaf: a sum of 250 terms is 250 deep. Statement depth counts IF,
CASE, FOR, WHILE and REPEAT inside each other.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import fields, is_dataclass
from typing import Any

from .. import limits
from . import ast

COMPOUND = (ast.If, ast.Case, ast.For, ast.While, ast.Repeat)
_STATEMENTS = (*COMPOUND, ast.Assign, ast.RefAssign, ast.CallStmt, ast.Exit, ast.Continue, ast.Return, ast.Empty)
_SKIPPED = frozenset({"span", "ty", "ref"})
_CHILD_FIELDS: dict[type, tuple[str, ...]] = {}


def too_deep(root: Any) -> tuple[str, ast.Span] | None:
    """(message, span of the construct that crosses a limit), or None."""
    max_expression, max_statement = limits.EXPRESSION_DEPTH.value, limits.STATEMENT_DEPTH.value
    todo: list[tuple[Any, int, int, ast.Span]] = [(root, 0, 0, ast.NO_SPAN)]
    while todo:
        node, expressions, statements, near = todo.pop()
        if isinstance(node, (list, tuple)):
            todo.extend((item, expressions, statements, near) for item in node)
            continue
        if not is_dataclass(node):
            continue
        span = getattr(node, "span", None) or near
        if isinstance(node, COMPOUND):
            statements += 1
            if statements > max_statement:
                return limits.STATEMENT_DEPTH.too_deep("this statement"), span
        elif not isinstance(node, _STATEMENTS) and span is not ast.NO_SPAN:
            expressions += 1
            if expressions > max_expression:
                return limits.EXPRESSION_DEPTH.too_deep("this expression"), span
        if isinstance(node, _STATEMENTS):
            expressions = 0
        for name in _children(type(node)):
            value = getattr(node, name)
            if value is not None and not isinstance(value, (str, int, float, bool)):
                todo.append((value, expressions, statements, span))
    return None


def nodes(root: Any) -> Iterator[Any]:
    """Every AST node under ``root`` (a node or a list of them), without recursion."""
    todo = [root]
    while todo:
        node = todo.pop()
        if isinstance(node, (list, tuple)):
            todo.extend(node)
        elif is_dataclass(node):
            yield node
            todo.extend(
                value
                for name in _children(type(node))
                if (value := getattr(node, name)) is not None and not isinstance(value, (str, int, float, bool))
            )


def _children(kind: type) -> tuple[str, ...]:
    names = _CHILD_FIELDS.get(kind)
    if names is None:
        names = _CHILD_FIELDS[kind] = tuple(f.name for f in fields(kind) if f.name not in _SKIPPED)
    return names
