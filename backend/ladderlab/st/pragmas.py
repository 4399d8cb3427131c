"""CODESYS's ``{attribute 'pack_mode' := 'N'}`` and ``{attribute 'call_after_init'}``, the pragmas that change what a
program computes here (the second: where it stands, ``misplaced_call_after_init``; what it does, st/call_after_init.py),
and ``{attribute 'monitoring' := '...'}``, which shows a property online (where it stands here, st/monitoring.py).

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
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any

from ..model.diagnostics import Diagnostic
from . import ast

CALL_AFTER_INIT = "{attribute 'call_after_init'}"
_CALL_AFTER_INIT = re.compile(r"\{\s*attribute\s+'call_after_init'\s*\}", re.IGNORECASE)
_HEADER = re.compile(r"(?:FUNCTION_BLOCK|METHOD)\b", re.IGNORECASE)
_PACK_MODE = re.compile(r"\{\s*attribute\s+'pack_mode'\s*:=\s*'([^']*)'\s*\}", re.IGNORECASE)
_MONITORING = re.compile(r"\{\s*attribute\s+'monitoring'\s*:=\s*'([^']*)'\s*\}", re.IGNORECASE)
_PROPERTY = re.compile(r"PROPERTY\b", re.IGNORECASE)
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


def misplaced_call_after_init(
    text: str, file: str | None, pou: str | None, place: str = "", interfaces: Sequence[tuple[int, int]] = ()
) -> list[Diagnostic]:
    """The error ST-PRAGMA at each ``{attribute 'call_after_init'}`` of ``text`` that stands where it has no effect.
    CODESYS: "Insert location: first line above the declaration part of the method and of the function block". So it
    is in place at the head of a declarations text (``place`` "declarations": which POU's or method's, the checker
    sees, st/call_after_init.py) and above a FUNCTION_BLOCK or METHOD header of a whole file (``place`` "source"),
    but not above a METHOD prototype of an INTERFACE (``interfaces``: their first and last lines), which no
    instance runs."""
    if "call_after_init" not in text.lower():
        return []
    where = _Misplaced(_CALL_AFTER_INIT, _HEADER, misplaced_diagnostic, "on a method of an INTERFACE")
    return where.find(text, file, pou, place, interfaces)


def misplaced_monitoring(
    text: str, file: str | None, pou: str | None, place: str = "", interfaces: Sequence[tuple[int, int]] = ()
) -> list[Diagnostic]:
    """The warning ST-PRAGMA at each ``{attribute 'monitoring' := ...}`` of ``text`` that shows no property online:
    in place only at the head of a declarations text (``place`` "declarations": a property accessor's, the checker
    sees, st/monitoring.py) and above a PROPERTY header of a whole file (``place`` "source") but for a PROPERTY
    prototype of an INTERFACE (``interfaces``: their first and last lines), which has no value."""
    if "monitoring" not in text.lower():
        return []
    where = _Misplaced(_MONITORING, _PROPERTY, monitoring_misplaced, "on a property of an INTERFACE")
    return where.find(text, file, pou, place, interfaces)


@dataclass(frozen=True)
class _Misplaced:
    """Where an attribute that belongs at the head of a declarations text or above a ``header`` of a whole file
    stands elsewhere: ``diagnostic(file, pou, why)`` at each such ``pragma``, ``interface`` the why of one above an
    INTERFACE's prototype."""

    pragma: re.Pattern[str]
    header: re.Pattern[str]
    diagnostic: Callable[[str | None, str | None, str], Diagnostic]
    interface: str

    def find(
        self, text: str, file: str | None, pou: str | None, place: str, interfaces: Sequence[tuple[int, int]]
    ) -> list[Diagnostic]:
        starts = _line_starts(text)
        found = []
        for pragma in _pragmas(text, self.pragma):
            if place == "declarations" and _skip(text, 0) >= pragma.end():
                continue
            why = ""
            if place == "source" and self.header.match(text, _skip(text, pragma.end())):
                line = _position(starts, pragma.start())[0]
                if not any(first <= line <= last for first, last in interfaces):
                    continue
                why = self.interface
            found.append(_at(pragma, starts, self.diagnostic(file, pou, why)))
        return found


def monitoring_misplaced(file: str | None, pou: str | None, why: str = "") -> Diagnostic:
    """ST-PRAGMA (a warning): a monitoring attribute that shows nothing (``why``: where it stands, else "here")."""
    return Diagnostic(
        severity="warning",
        code="ST-PRAGMA",
        message=(
            f"the attribute 'monitoring' has no effect {why or 'here'}: it shows a property's value online when it "
            "heads the declarations of the property's GET (or SET), written above PROPERTY in IEC text; move it "
            "there or remove it"
        ),
        file=file,
        pou=pou,
    )


def head_call_after_init(text: str) -> tuple[int, int, int, int] | None:
    """Where ``{attribute 'call_after_init'}`` stands at the head of a declarations text (before its first block:
    the attribute of the POU or method the text declares), as (line, column, end line, end column); None if not."""
    if "call_after_init" not in text.lower():
        return None
    head = _skip(text, 0)
    starts = _line_starts(text)
    for pragma in _pragmas(text[:head], _CALL_AFTER_INIT):
        return (*_position(starts, pragma.start()), *_position(starts, pragma.end()))
    return None


def without_call_after_init(text: str) -> tuple[str, str]:
    """A declarations text split for IEC text, where the attribute stands above the header (CODESYS): the attribute
    heading it (``CALL_AFTER_INIT`` or "") and the text without it."""
    place = head_call_after_init(text)
    return ("", text) if place is None else (CALL_AFTER_INIT, _cut(text, place))


def attributed_headers(text: str) -> set[tuple[int, int]]:
    """The (line, column) of each FUNCTION_BLOCK or METHOD header of a whole file that the call_after_init attribute
    stands above (comments and other pragmas may stand between)."""
    if "call_after_init" not in text.lower():
        return set()
    starts = _line_starts(text)
    found = set()
    for pragma in _pragmas(text, _CALL_AFTER_INIT):
        header = _skip(text, pragma.end())
        if _HEADER.match(text, header):
            found.add(_position(starts, header))
    return found


def with_call_after_init(text: str) -> str:
    """A declarations text headed by the attribute (read from above a header in IEC text), its lines kept: the
    attribute takes the first of the blank lines that pad it (st/project_text.py), or a line of its own."""
    return headed_by(CALL_AFTER_INIT, text)


def monitoring_pragma(mode: str) -> str:
    """CODESYS's ``{attribute 'monitoring' := 'mode'}`` as LadderLab writes it (st/monitoring.py)."""
    return f"{{attribute 'monitoring' := '{mode}'}}"


def head_monitoring(text: str) -> tuple[str, tuple[int, int, int, int]] | None:
    """The mode (as written) of ``{attribute 'monitoring' := '...'}`` at the head of a property accessor's
    declarations text (the property's attribute, st/monitoring.py) and where it stands; None if none heads it."""
    if "monitoring" not in text.lower():
        return None
    starts = _line_starts(text)
    for pragma in _pragmas(text[: _skip(text, 0)], _MONITORING):
        return pragma.group(1), (*_position(starts, pragma.start()), *_position(starts, pragma.end()))
    return None


def without_monitoring(text: str) -> tuple[str, str]:
    """An accessor's declarations text split for IEC text, where the attribute stands above ``PROPERTY``
    (CODESYS): the attribute heading it (or "") and the text without it."""
    found = head_monitoring(text)
    if found is None:
        return "", text
    return monitoring_pragma(found[0]), _cut(text, found[1])


def monitored_properties(text: str) -> dict[tuple[int, int], str]:
    """The (line, column) of each PROPERTY header of a whole file that a monitoring attribute stands above
    (comments and other pragmas may stand between), with the attribute's mode."""
    if "monitoring" not in text.lower():
        return {}
    starts = _line_starts(text)
    found = {}
    for pragma in _pragmas(text, _MONITORING):
        header = _skip(text, pragma.end())
        if _PROPERTY.match(text, header):
            found[_position(starts, header)] = pragma.group(1)
    return found


def headed_by(pragma: str, text: str) -> str:
    """A declarations text headed by ``pragma`` (read from above a header in IEC text), its lines kept: the pragma
    takes the first of the blank lines that pad it (st/project_text.py), or a line of its own."""
    if text.startswith("\n"):
        return pragma + text
    return f"{pragma}\n{text}" if text else pragma


def _cut(text: str, place: tuple[int, int, int, int]) -> str:
    """``text`` without the pragma at ``place`` (and the line break after it when it stood alone at the head)."""
    starts = _line_starts(text)
    start, end = starts[place[0] - 1] + place[1] - 1, starts[place[2] - 1] + place[3] - 1
    before, after = text[:start], text[end:]
    return before + after if before.strip() else after.lstrip("\n")


def misplaced_diagnostic(file: str | None, pou: str | None, why: str = "") -> Diagnostic:
    """ST-PRAGMA: a call_after_init attribute that would have no effect (``why``: what is wrong, else where it
    stands)."""
    return Diagnostic(
        severity="error",
        code="ST-PRAGMA",
        message=(
            f"the attribute 'call_after_init' has no effect {why or 'here'}: CODESYS calls a method after an "
            "instance's initialisation when the attribute stands on the first line of the declarations of both the "
            "function block and the method; move it there or remove it"
        ),
        file=file,
        pou=pou,
    )


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
