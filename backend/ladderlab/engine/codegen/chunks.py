"""How the body of a PROGRAM / FUNCTION_BLOCK is split into chunks and dispatch segments.

CPython's ``compile()`` of one function holding 10,000 LD networks needs the
syntax tree of all of it at once (about 270 MB). So a long body becomes chunk
functions of about ``CHUNK_STATEMENTS`` IR statements each (whole blocks, in
order), each compiled on its own; ``execute`` calls them in order. A short body
is one chunk, emitted inline in ``execute``.

A POU with jumps runs in segments (docs/runtime.md, "Loops and jumps"): a block
with a label starts one, and so does the first block of every chunk, so a jump
is either inside its chunk (``continue`` in the chunk's dispatch loop) or leaves
it by returning the target segment to ``execute``'s dispatch.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ...ir import nodes as ir
from .mentions import walk, walk_filled

#: IR statements (nested ones included) per chunk function.
CHUNK_STATEMENTS = 1500


@dataclass
class ChunkPlan:
    chunks: list[list[ir.Block]]
    jumps: bool  # the POU jumps: blocks run in segments
    straight: bool = False  # no jump and no RETURN: every block of a chunk runs whenever its first does
    segments: dict[str, int] = field(default_factory=dict)  # upper-case label -> segment
    duplicates: list[ir.Block] = field(default_factory=list)  # blocks repeating an earlier label
    first_segment: list[int] = field(default_factory=list)  # per chunk
    segment_chunk: list[int] = field(default_factory=list)  # per segment

    @property
    def inline(self) -> bool:
        """One chunk: its statements are the body of ``execute`` itself."""
        return len(self.chunks) == 1

    def ends(self, chunk: int) -> int:
        """The segment after the last of ``chunk``'s (-1 after the last chunk: the POU ends)."""
        return self.first_segment[chunk + 1] if chunk + 1 < len(self.chunks) else -1


def plan(blocks: list[ir.Block], chunked: bool) -> ChunkPlan:
    """Chunks of ``blocks`` (one when not ``chunked``, e.g. a FUNCTION, whose variables are locals) and segments."""
    chunks: list[list[ir.Block]] = [[]]
    size, jumps, returns = 0, False, False
    for block in blocks:
        statements = 0
        # (a network the LD lowering filled in from a template nests statements in IFs only: walked without the
        # generators, as a 50,000-network body's are)
        for s in walk_filled(block.statements, []) if block.filled is not None else walk(block.statements):
            statements += 1
            kind = type(s)
            if kind is ir.Jump:
                jumps = True
            elif kind is ir.Return:
                returns = True
        if chunked and chunks[-1] and size + statements > CHUNK_STATEMENTS:
            chunks.append([])
            size = 0
        chunks[-1].append(block)
        size += statements
    result = ChunkPlan(chunks, jumps, not (jumps or returns))
    segment = -1
    for number, chunk in enumerate(chunks):
        if not chunk:  # an empty body (a new LD/FBD POU has no network yet): one empty segment
            segment += 1
            result.segment_chunk.append(number)
            result.first_segment.append(segment)
        for i, block in enumerate(chunk):
            if i == 0 or block.label is not None:
                segment += 1
                result.segment_chunk.append(number)
                if i == 0:
                    result.first_segment.append(segment)
            if block.label is not None:
                label = block.label.upper()
                if label in result.segments:
                    result.duplicates.append(block)
                else:
                    result.segments[label] = segment
    return result
