"""Untrusted JSON text, checked before ``json.loads``: nesting depth and lone surrogates.

``json.loads`` recurses once per nesting level, so a document nested deeper than the interpreter
allows ends in a RecursionError; and it turns a lone ``\\udcff`` escape into a string that no
UTF-8 encoder accepts, so the failure comes much later (saving, hashing, answering). Both are
found here first, with their line and column, for request bodies, websocket messages and files.
"""

from __future__ import annotations

import re

from . import limits

_TOKEN = re.compile(rb'"(?:[^"\\]|\\.)*"|[\[\]{}]', re.DOTALL)
_ESCAPE = re.compile(rb"\\(?:u([0-9a-fA-F]{4})|.)", re.DOTALL)
_SURROGATE_HINT = re.compile(rb"\\u[dD][89a-fA-F]")


def json_problem(data: bytes | str) -> tuple[str, int, int] | None:
    """Why ``data`` may not be parsed (message, line, column: 1-based), or None.

    The text need not be valid JSON otherwise: syntax errors are the parser's to report."""
    raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
    deep = _too_deep(raw, limits.JSON_DEPTH.value)
    if deep is not None:
        return (limits.JSON_DEPTH.too_deep("the JSON"), *_position(raw, deep))
    lone = _lone_surrogate(raw)
    if lone is not None:
        return (
            f"the escape {raw[lone : lone + 6].decode('ascii')} is half of a UTF-16 surrogate pair, not a character; "
            "JSON text must be valid Unicode",
            *_position(raw, lone),
        )
    return None


def _too_deep(raw: bytes, limit: int) -> int | None:
    """Offset of the first bracket past ``limit`` levels (strings skipped), or None."""
    if raw.count(b"[") + raw.count(b"{") <= limit:  # the common case: not even that many brackets
        return None
    depth = 0
    for match in _TOKEN.finditer(raw):
        token = match.group()
        if token in (b"[", b"{"):
            depth += 1
            if depth > limit:
                return match.start()
        elif token in (b"]", b"}"):
            depth -= 1
    return None


def _lone_surrogate(raw: bytes) -> int | None:
    """Offset of a ``\\uD800``-``\\uDFFF`` escape that is not part of a high-low pair, or None."""
    if _SURROGATE_HINT.search(raw) is None:
        return None
    pending: int | None = None  # offset of a high surrogate waiting for its low half
    previous_end = -1
    for match in _ESCAPE.finditer(raw):
        code = int(match.group(1), 16) if match.group(1) else None
        adjacent = match.start() == previous_end
        if pending is not None and not (adjacent and code is not None and 0xDC00 <= code <= 0xDFFF):
            return pending
        if pending is not None:
            pending = None
        elif code is not None and 0xD800 <= code <= 0xDBFF:
            pending = match.start()
        elif code is not None and 0xDC00 <= code <= 0xDFFF:
            return match.start()
        previous_end = match.end()
    return pending


def _position(raw: bytes, offset: int) -> tuple[int, int]:
    line = raw.count(b"\n", 0, offset) + 1
    column = len(raw[raw.rfind(b"\n", 0, offset) + 1 : offset].decode("utf-8", "replace")) + 1
    return line, column
