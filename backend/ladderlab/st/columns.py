"""Declarations aligned in columns, as a careful engineer aligns them (issue 28).

``align_declarations`` rewrites only the lines that hold exactly one declaration
(``names [AT address] : type [:= initial];`` and an optional trailing comment),
keeping every token as typed: in each VAR block the names are padded to one
column, the colons line up, and the trailing comments start in one column four
spaces after the block's longest declaration. Everything else (block headers, comments on their own
lines, declarations over several lines) stays exactly as it is, and text that
does not parse is returned unchanged. The declarations table of the browser
prints the same layout (frontend/src/declarations/model.ts ``printDeclarations``;
both are tested against tests/fixtures/declaration_columns.json).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .parser import parse_declarations

INDENT = "    "
COMMENT_GAP = "    "
_TAIL = re.compile(r"^\s*;\s*(\(\*(?:(?!\*\)).)*\*\)|//.*)?\s*$")


@dataclass
class _Row:
    line: int  # 0-based
    head: str  # names and address, e.g. "Start AT %IX0.0"
    rest: str  # type and initial value, e.g. "TIME := T#1s"
    comment: str  # "(* ... *)" or "// ..." or ""


def align_declarations(text: str) -> str:
    """``text`` (VAR ... END_VAR blocks) with its one-line declarations aligned in columns."""
    parsed = parse_declarations(text)
    if not parsed.ok:
        return text
    lines = text.split("\n")
    for block in parsed.ast:
        rows = [row for decl in block.decls if (row := _row(lines, decl.span)) is not None]
        if not rows:
            continue
        width = max(len(row.head) for row in rows)
        codes = {row.line: f"{row.head.ljust(width)} : {row.rest};" for row in rows}
        code_width = max(len(code) for code in codes.values())
        for row in rows:
            code = codes[row.line]
            lines[row.line] = INDENT + (f"{code.ljust(code_width)}{COMMENT_GAP}{row.comment}" if row.comment else code)
    return "\n".join(lines)


def _row(lines: list[str], span) -> _Row | None:
    """The declaration at ``span`` when its line holds it alone (leading blanks, trailing ``;`` and comment)."""
    if not span.line or span.line != span.end_line or span.line > len(lines):
        return None
    line = lines[span.line - 1]
    before, code, after = (
        line[: span.column - 1],
        line[span.column - 1 : span.end_column - 1],
        line[span.end_column - 1 :],
    )
    semicolon = after.find(";")
    if semicolon > 0 and not re.search(r"\(\*|//|'|\"", after[:semicolon]):  # a span that stops short of a ']'
        code, after = code + after[:semicolon], after[semicolon:]
    tail = _TAIL.match(after)
    if before.strip() or tail is None:
        return None
    colon = _type_colon(code)
    if colon is None:
        return None
    head = re.sub(r"\s*,\s*", ", ", re.sub(r"\s+", " ", code[:colon].strip()))
    return _Row(span.line - 1, head, code[colon + 1 :].strip(), (tail.group(1) or "").strip())


def _type_colon(code: str) -> int | None:
    """Where the ``:`` before the type is (names and addresses hold none; ``:=`` is not it)."""
    for index, char in enumerate(code):
        if char == ":" and not code.startswith(":=", index):
            return index
    return None
