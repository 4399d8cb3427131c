"""Comment handling the LALR lexer cannot do: nested ``(* *)`` and declaration comments.

Nested comments (ST-04, an option; imported libraries such as OSCAT need it) are
blanked out before lexing, keeping newlines so every line/column stays right.
Trailing comments of variable declarations are attached to ``VarDecl.comment``
for the symbol table and the editor.
"""

from __future__ import annotations

import re
from typing import Any

_OUTSIDE = re.compile(r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|//[^\n]*|\{[^}]*\}|(\(\*)")
_INSIDE = re.compile(r"\(\*|\*\)")
_TRAILING = re.compile(r"[ \t]*;?[ \t]*(?:\(\*(.*?)\*\)|//(.*))")


def blank_nested_comments(text: str) -> str:
    """Replace every (possibly nested) ``(* ... *)`` by spaces; an unterminated one is left for the parser."""
    pieces: list[str] = []
    copied = position = 0
    while True:
        match = _OUTSIDE.search(text, position)
        if match is None:
            break
        position = match.end()
        if match.group(1) is None:
            continue
        end = _comment_end(text, position)
        if end is None:
            break
        pieces += [text[copied : match.start()], _blank(text[match.start() : end])]
        copied = position = end
    pieces.append(text[copied:])
    return "".join(pieces)


def _comment_end(text: str, position: int) -> int | None:
    depth = 1
    while depth:
        match = _INSIDE.search(text, position)
        if match is None:
            return None
        depth += 1 if match.group() == "(*" else -1
        position = match.end()
    return position


def _blank(comment: str) -> str:
    """Every character but the line breaks as a space (lines and columns stay where they were)."""
    return "\n".join(" " * len(line) for line in comment.split("\n"))


def attach_comments(tree: Any, text: str) -> None:
    """Set ``VarDecl.comment`` from a comment that follows the declaration on its last line."""
    if "(*" not in text and "//" not in text:  # none to attach (a 2.5 MB text's 100,000 declarations: ~0.05 s)
        return
    lines = text.split("\n")
    for decl in _var_decls(tree):
        span = decl.span
        if not span.line or span.end_line > len(lines):
            continue
        match = _TRAILING.match(lines[span.end_line - 1], span.end_column - 1)
        if match:
            decl.comment = (match.group(1) if match.group(1) is not None else match.group(2)).strip()


def _var_decls(tree: Any):
    from . import ast  # here: storage splits files with this module's blanking, without the AST (issue 27)

    if isinstance(tree, list):
        for item in tree:
            yield from _var_decls(item)
    elif isinstance(tree, ast.Source):
        for item in tree.items:
            yield from _var_decls(item)
    elif isinstance(tree, (ast.Pou, ast.Configuration, ast.Resource)):
        yield from _var_decls(getattr(tree, "var_blocks", None) or getattr(tree, "items", []))
    elif isinstance(tree, ast.VarBlock):
        yield from tree.decls
    elif isinstance(tree, ast.TypeBlock):
        for decl in tree.decls:
            if isinstance(decl.type, ast.StructType):
                yield from decl.type.members
