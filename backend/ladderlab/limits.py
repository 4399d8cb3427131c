"""The documented limits of what LadderLab accepts, their defaults and the settings that raise them.

Every limit keeps one project, request or file from taking the server's memory, stack or time;
exceeding one is a located diagnostic that names the limit and its setting (never a
MemoryError, a RecursionError or a 500). A setting is an environment variable read when the
limit is checked, so ``ladderlab serve``, the CLI and worker processes see the same value.
docs/security.md lists them all.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Limit:
    """One limit: what it bounds (``what``, with ``unit``), its default and its environment setting."""

    what: str
    unit: str
    default: int
    setting: str

    @property
    def value(self) -> int:
        raw = os.environ.get(self.setting, "").strip().replace("_", "")
        return int(raw) if raw.isdigit() and int(raw) > 0 else self.default

    def message(self, found: str) -> str:
        """``found`` (what the input has) followed by the limit and how to raise it."""
        return (
            f"{found}, more than the limit of {self.value:,} {self.unit} for {self.what} "
            f"(the setting {self.setting} raises it)"
        )


ARRAY_ELEMENTS = Limit("one array", "elements", 1_000_000, "LADDERLAB_MAX_ARRAY_ELEMENTS")
STRING_LENGTH = Limit("one STRING", "characters", 255, "LADDERLAB_MAX_STRING_LENGTH")
DATA_ELEMENTS = Limit("the data of one program", "elements", 4_000_000, "LADDERLAB_MAX_DATA_ELEMENTS")
SOURCE_BYTES = Limit("the source text of one project", "bytes", 4 * 1024 * 1024, "LADDERLAB_MAX_SOURCE_BYTES")
EXPRESSION_DEPTH = Limit("the nesting of one expression", "levels", 1_000, "LADDERLAB_MAX_EXPRESSION_DEPTH")
STATEMENT_DEPTH = Limit("the nesting of statements", "levels", 200, "LADDERLAB_MAX_STATEMENT_DEPTH")
DIAGRAM_DEPTH = Limit("the nesting of LD branches", "levels", 50, "LADDERLAB_MAX_DIAGRAM_DEPTH")
JSON_DEPTH = Limit("the nesting of one JSON document", "levels", 400, "LADDERLAB_MAX_JSON_DEPTH")

ALL = (
    ARRAY_ELEMENTS,
    STRING_LENGTH,
    DATA_ELEMENTS,
    SOURCE_BYTES,
    EXPRESSION_DEPTH,
    STATEMENT_DEPTH,
    DIAGRAM_DEPTH,
    JSON_DEPTH,
)

_JSON_TOKEN = re.compile(rb'"(?:[^"\\]|\\.)*"|[\[\]{}]', re.DOTALL)


def json_too_deep(data: bytes | str, limit: int | None = None) -> tuple[int, int] | None:
    """Where a JSON text first nests deeper than ``limit`` (default: JSON_DEPTH): (line, column), 1-based.

    None when it does not. Strings are skipped, so brackets inside them do not count; the text need
    not be valid JSON (its parser reports syntax errors). Runs before ``json.loads``, whose recursion
    would otherwise end in a RecursionError."""
    raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
    limit = JSON_DEPTH.value if limit is None else limit
    if raw.count(b"[") + raw.count(b"{") <= limit:  # the common case: not even that many brackets
        return None
    depth = 0
    for match in _JSON_TOKEN.finditer(raw):
        token = match.group()
        if token in (b"[", b"{"):
            depth += 1
            if depth > limit:
                offset = match.start()
                line = raw.count(b"\n", 0, offset) + 1
                column = len(raw[raw.rfind(b"\n", 0, offset) + 1 : offset].decode("utf-8", "replace")) + 1
                return line, column
        elif token in (b"]", b"}"):
            depth -= 1
    return None
