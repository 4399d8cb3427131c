"""A line-oriented writer for generated Python that remembers where each line came from.

Every emitted line is tagged with the origin index that was current when it
was written (the statement being generated), so a traceback line number in
the generated module maps back to an ST line or an LD/FBD network/element.

The module is compiled in pieces (``breaks``: the lines where a new piece
starts, always between top-level statements), so CPython never holds the
syntax tree of a whole 10,000-network program at once (engine/compile.py).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from contextlib import contextmanager
from typing import NamedTuple


class LazyPiece(NamedTuple):
    """A piece defining one function that is compiled when first needed (engine/compile.py): a monitor chunk with
    probes, which runs only while one of its ``runs`` of networks (the POU's ``ll_v`` flags) is viewed."""

    function: str
    pou: str  # upper case
    runs: range


class Source:
    def __init__(self) -> None:
        self.lines: list[str] = []
        self.line_origins: list[int | None] = []  # index 0 is line 1
        self.depth = 0
        self.origin: int | None = None
        self.breaks: list[int] = []  # 0-based line indices where a separately compiled piece starts
        self.lazy: dict[int, LazyPiece] = {}  # a break -> its piece when compiled at first use

    def piece(self) -> None:
        """Start a new compile piece here (between top-level statements)."""
        if self.lines and (not self.breaks or self.breaks[-1] != len(self.lines)):
            self.breaks.append(len(self.lines))

    def line(self, text: str = "") -> None:
        self.lines.append("    " * self.depth + text if text else "")
        self.line_origins.append(self.origin)

    @contextmanager
    def indent(self) -> Iterator[None]:
        self.depth += 1
        try:
            yield
        finally:
            self.depth -= 1

    @contextmanager
    def at(self, origin: int | None) -> Iterator[None]:
        """Tag the lines written inside with ``origin`` (nested statements override it)."""
        saved, self.origin = self.origin, origin
        try:
            yield
        finally:
            self.origin = saved

    def text(self) -> str:
        """The lines, each ended by a newline; joined once (``join(...) + "\\n"`` would copy a large module's
        text a second time at the build's peak: ~90 MB for the monitor variant of 50,000 networks)."""
        return "\n".join(itertools.chain(self.lines, ("",)))

    def origin_of_line(self, lineno: int) -> int | None:
        if 1 <= lineno <= len(self.line_origins):
            return self.line_origins[lineno - 1]
        return None

    def extend(self, other: Source) -> None:
        """Append the lines of ``other`` (written at its own depth) with their origins and piece breaks."""
        self.breaks.extend(len(self.lines) + b for b in other.breaks)
        self.lazy.update({len(self.lines) + b: name for b, name in other.lazy.items()})
        self.lines.extend(other.lines)
        self.line_origins.extend(other.line_origins)
