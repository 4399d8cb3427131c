"""CODESYS's ``{attribute 'pack_mode' := 'N'}``, the one pragma that changes what a program computes here (and
``{attribute 'call_after_init'}``, which would, refused: ``unsupported_pragmas``).

The lexer skips every pragma (``%ignore PRAGMA``); this pass finds the pack_mode ones in the text and gives each
to the TYPE declaration it stands above (``TypeDecl.pack_mode``), as CODESYS places it: "Insert location: above
the declaration of the data structure" (https://content.helpme-codesys.com/en/CODESYS%20Development%20System/
_cds_pragma_attribute_pack_mode.html). Written before ``TYPE`` or before the name inside a TYPE block, it belongs
to the declaration that follows (comments and other pragmas may stand between). One that stands above anything
else (a function block, a variable, a STRUCT's member) has no effect - LadderLab lays out no FB instance's memory,
and CODESYS packs a STRUCT as a whole - and is the warning ST-PRAGMA where it stands, so it is not taken for one that
packs (``_misplaced``).
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Iterator
from typing import Any

from ..model.diagnostics import Diagnostic
from . import ast

#: Why ``{attribute 'call_after_init'}`` is refused (IR-UNSUPPORTED), wherever it is found (the PLCopen import too)
CALL_AFTER_INIT_REFUSED = (
    "LadderLab does not call a method marked {attribute 'call_after_init'} after the instance is initialised, as "
    "CODESYS does: call the method from the program (on its first scan) and remove the attribute"
)
_CALL_AFTER_INIT = re.compile(r"\{\s*attribute\s+'call_after_init'\s*\}", re.IGNORECASE)
_PACK_MODE = re.compile(r"\{\s*attribute\s+'pack_mode'\s*:=\s*'([^']*)'\s*\}", re.IGNORECASE)
# What the lexer skips too: strings are jumped over, a pragma is captured (group 1)
_LEXED = re.compile(r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|\(\*[\s\S]*?\*\)|/\*[\s\S]*?\*/|//[^\n]*|(\{[^}]*\})")
_BETWEEN = re.compile(r"(?:\s+|\(\*[\s\S]*?\*\)|/\*[\s\S]*?\*/|//[^\n]*|\{[^}]*\})*")
_TYPE = re.compile(r"TYPE\b", re.IGNORECASE)


def pack_mode_pragma(value: str) -> str:
    """The pragma as LadderLab writes it."""
    return f"{{attribute 'pack_mode' := '{value}'}}"


def block_text(block: ast.TypeBlock, text: str, head: str) -> str:
    """A TYPE block's text as written (``text``, from its TYPE to its END_TYPE; ``head``, the part before its first
    declaration) with the pack_mode pragma that stood above its TYPE, outside the block's span."""
    first = block.decls[0] if block.decls else None
    if first is None or first.pack_mode is None or _PACK_MODE.search(head):
        return text
    return f"{pack_mode_pragma(first.pack_mode)}\n{text}"


def attach_pack_modes(tree: Any, text: str, file: str | None = None) -> list[Diagnostic]:
    """Set ``pack_mode`` (the value as written) of each TYPE declaration of ``tree`` that a pack_mode pragma
    stands above in ``text`` (the text the parser read, its spans' lines and columns); the warnings of the pragmas
    that stand above nothing they pack (``_misplaced``)."""
    if "pack_mode" not in text or not isinstance(tree, ast.Source):
        return []
    starts = _line_starts(text)
    decls = {
        starts[d.span.line - 1] + d.span.column - 1: d
        for item in tree.items
        if isinstance(item, ast.TypeBlock)
        for d in item.decls
        if d.span.line
    }
    unplaced = []
    for pragma in _pack_modes(text):
        decl = decls.get(_next_declaration(text, pragma.end()))
        if decl is not None:
            decl.pack_mode = pragma.group(1)
        else:
            unplaced.append(_misplaced(pragma, starts, file, None))
    return unplaced


def misplaced_pack_modes(text: str, file: str | None = None, pou: str | None = None) -> list[Diagnostic]:
    """The warnings of the pack_mode pragmas of ``text``, a POU's declarations or body or a VAR_GLOBAL block, where
    none packs anything (no TYPE is declared there)."""
    if "pack_mode" not in text:
        return []
    starts = _line_starts(text)
    return [_misplaced(pragma, starts, file, pou) for pragma in _pack_modes(text)]


def _misplaced(pragma: re.Match[str], starts: list[int], file: str | None, pou: str | None) -> Diagnostic:
    """ST-PRAGMA at ``pragma``: it stands above no STRUCT's TYPE declaration, so it packs nothing."""
    return _at(
        pragma,
        starts,
        Diagnostic(
            severity="warning",
            code="ST-PRAGMA",
            message=(
                "the attribute 'pack_mode' has no effect here: it packs a STRUCT when it stands above the STRUCT's "
                "TYPE declaration (a function block, a variable or a member keeps its layout); move it there or "
                "remove it"
            ),
            file=file,
            pou=pou,
        ),
    )


def unsupported_pragmas(text: str, file: str | None = None, pou: str | None = None) -> list[Diagnostic]:
    """The error IR-UNSUPPORTED at each ``{attribute 'call_after_init'}`` of ``text``: CODESYS calls a method marked
    so after an instance's initialisation ("Attribute: call_after_init"), which LadderLab does not do yet, so a program
    relying on it would run with other values than CODESYS's (docs/st.md, "FB_init and FB_exit")."""
    if "call_after_init" not in text.lower():
        return []
    starts = _line_starts(text)
    refused = Diagnostic(severity="error", code="IR-UNSUPPORTED", message=CALL_AFTER_INIT_REFUSED, file=file, pou=pou)
    return [_at(pragma, starts, refused) for pragma in _pragmas(text, _CALL_AFTER_INIT)]


def _at(pragma: re.Match[str], starts: list[int], diagnostic: Diagnostic) -> Diagnostic:
    """``diagnostic`` located at ``pragma``'s text (``starts``: the offsets where its text's lines start)."""
    line, column = _position(starts, pragma.start())
    end_line, end_column = _position(starts, pragma.end())
    place = {"line": line, "column": column, "end_line": end_line, "end_column": end_column}
    return diagnostic.model_copy(update=place)


def _pack_modes(text: str) -> Iterator[re.Match[str]]:
    """The pack_mode pragmas of ``text`` (matches: the value written is group 1), outside strings and comments."""
    return _pragmas(text, _PACK_MODE)


def _pragmas(text: str, pattern: re.Pattern[str]) -> Iterator[re.Match[str]]:
    """The pragmas of ``text`` that ``pattern`` matches whole, outside strings and comments."""
    for lexed in _LEXED.finditer(text):
        if lexed.group(1) is not None:
            pragma = pattern.fullmatch(text, lexed.start(1), lexed.end(1))
            if pragma is not None:
                yield pragma


def _line_starts(text: str) -> list[int]:
    return [0] + [m.end() for m in re.finditer("\n", text)]


def _position(starts: list[int], offset: int) -> tuple[int, int]:
    """1-based line and column of ``offset``."""
    line = bisect.bisect_right(starts, offset)
    return line, offset - starts[line - 1] + 1


def _next_declaration(text: str, position: int) -> int:
    """Where the next name stands after ``position``, past comments, pragmas and one ``TYPE``."""
    position = _skip(text, position)
    keyword = _TYPE.match(text, position)
    return position if keyword is None else _skip(text, keyword.end())


def _skip(text: str, position: int) -> int:
    between = _BETWEEN.match(text, position)
    return between.end() if between is not None else position
