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
    kinds = _KINDS
    while todo:
        node, expressions, statements, near = todo.pop()
        known = kinds.get(node.__class__)
        if known is None:
            known = _kind(node.__class__)
        kind, children = known
        if kind is _SEQUENCE:
            todo.extend((item, expressions, statements, near) for item in node)
            continue
        if kind is _LEAF:
            continue
        span = getattr(node, "span", None) or near
        if kind is _COMPOUND:
            statements += 1
            if statements > max_statement:
                return limits.STATEMENT_DEPTH.too_deep("this statement"), span
            expressions = 0
        elif kind is _STATEMENT:
            expressions = 0
        elif span is not ast.NO_SPAN:
            expressions += 1
            if expressions > max_expression:
                return limits.EXPRESSION_DEPTH.too_deep("this expression"), span
        for name in children:
            value = getattr(node, name)
            if value is not None and not isinstance(value, (str, int, float, bool)):
                todo.append((value, expressions, statements, span))
    return None


_SEQUENCE, _LEAF, _COMPOUND, _STATEMENT, _OTHER = "sequence", "leaf", "compound", "statement", "other"
#: type -> (what too_deep does with its nodes, the fields it walks into): decided once per type
_KINDS: dict[type, tuple[str, tuple[str, ...]]] = {}


def _kind(kind: type) -> tuple[str, tuple[str, ...]]:
    if issubclass(kind, (list, tuple)):
        found = (_SEQUENCE, ())
    elif not is_dataclass(kind):
        found = (_LEAF, ())
    elif issubclass(kind, COMPOUND):
        found = (_COMPOUND, _children(kind))
    elif issubclass(kind, _STATEMENTS):
        found = (_STATEMENT, _children(kind))
    else:
        found = (_OTHER, _children(kind))
    _KINDS[kind] = found
    return found


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
