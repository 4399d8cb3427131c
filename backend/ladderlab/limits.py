"""The documented limits of what LadderLab accepts, their defaults and the settings that raise them.

Every limit keeps one project, request or file from taking the server's memory, stack or time;
exceeding one is a located diagnostic that names the limit and its setting (never a
MemoryError, a RecursionError or a 500). A setting is an environment variable read when the
limit is checked, so ``ladderlab serve``, the CLI and worker processes see the same value.
docs/security.md lists them all.
"""

from __future__ import annotations

import os
from dataclasses import dataclass


@dataclass(frozen=True)
class Limit:
    """One limit: what it bounds (``what``, with ``unit``), its default and its environment setting."""

    what: str
    unit: str
    default: int
    setting: str
    ceiling: int | None = None  # what the setting cannot raise it beyond (a bound of a library below us)

    @property
    def value(self) -> int:
        raw = os.environ.get(self.setting, "").strip().replace("_", "")
        value = int(raw) if raw.isdigit() and int(raw) > 0 else self.default
        return min(value, self.ceiling) if self.ceiling is not None else value

    def message(self, found: str) -> str:
        """``found`` (what the input has, e.g. "ARRAY[0..9999999] OF INT has 10,000,000 elements"), then the
        limit and the setting that raises it."""
        return (
            f"{found}, more than the limit of {self.value:,} {self.unit} for {self.what} "
            f"(the setting {self.setting} raises it)"
        )

    def too_deep(self, subject: str) -> str:
        """For nesting limits: ``subject`` (e.g. "this expression") nests deeper than allowed."""
        return (
            f"{subject} nests deeper than the limit of {self.value:,} {self.unit} for {self.what} "
            f"(the setting {self.setting} raises it)"
        )


ARRAY_ELEMENTS = Limit("one array", "elements", 1_000_000, "LADDERLAB_MAX_ARRAY_ELEMENTS")
STRING_LENGTH = Limit("one STRING", "characters", 255, "LADDERLAB_MAX_STRING_LENGTH")
DATA_ELEMENTS = Limit("the data of one program", "values", 4_000_000, "LADDERLAB_MAX_DATA_VALUES")
# a build takes ~800 MB and ~30 s per MB of ST text (docs/security.md)
SOURCE_BYTES = Limit("the ST text of one project", "characters", 1024 * 1024, "LADDERLAB_MAX_SOURCE_CHARACTERS")
EXPRESSION_DEPTH = Limit("the nesting of one expression", "levels", 1_000, "LADDERLAB_MAX_EXPRESSION_DEPTH")
STATEMENT_DEPTH = Limit("the nesting of statements", "levels", 200, "LADDERLAB_MAX_STATEMENT_DEPTH")
# pydantic's serializer stops at ~255 levels of JSON, three per LD branch level: 80 stays below it
DIAGRAM_DEPTH = Limit("the nesting of LD branches", "levels", 50, "LADDERLAB_MAX_DIAGRAM_DEPTH", ceiling=80)
JSON_DEPTH = Limit("the nesting of one JSON document", "levels", 400, "LADDERLAB_MAX_JSON_DEPTH")
XML_DEPTH = Limit("the nesting of one XML document", "levels", 200, "LADDERLAB_MAX_XML_DEPTH")

ALL = (
    ARRAY_ELEMENTS,
    STRING_LENGTH,
    DATA_ELEMENTS,
    SOURCE_BYTES,
    EXPRESSION_DEPTH,
    STATEMENT_DEPTH,
    DIAGRAM_DEPTH,
    JSON_DEPTH,
    XML_DEPTH,
)
