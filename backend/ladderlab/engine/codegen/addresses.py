"""A pointer as a number (CODESYS typing: ``dw := pt``, ``pt := dw``, ``pt < dw``; docs/st.md).

LadderLab's variables live in no memory, so addresses are given synthetically, once per simulation: the first time
the address of a variable (an object: a scalar, a STRUCT, the innermost array an element belongs to) is taken as a
number, it gets a base address for the simulation's life, unique, a multiple of ``ALIGN``, never 0, with a gap after
it so one past its end belongs to it alone. ``dw := pt`` is that base plus the byte the pointer points to;
``pt := dw`` finds the variable the number lies in and points there, seeing its bytes as the pointer's type (a
``ViewRef``); a number in no variable gives a ``Stray`` pointer that faults when it is read or written through, and
0 is NULL. Only alignment and order within one variable mean anything: which base a variable gets is this
simulation's choice, as a PLC's linker's is.
"""

from __future__ import annotations

import bisect
from typing import Any

from ..errors import OUT_OF_MEMORY, PlcRuntimeError
from .runtime import Ref
from .views import Stray, ViewRef, layout, view

#: Every base address is a multiple of this (CODESYS aligns no variable to more than 8 bytes).
ALIGN = 8
#: The first base address: low addresses stay free, as on a PLC, so a small number is no variable's.
FIRST = 0x1_0000
#: Addresses are 32-bit (SIZEOF of a pointer is 4: ir/byte_layout.py).
LIMIT = 1 << 32
#: Entries of calls that returned are dropped once there are this many more than after the last clean-up.
_CLEAN_EVERY = 4096


class AddressSpace:
    """The synthetic addresses of one simulation (``ll_addr`` in its generated module's globals)."""

    def __init__(self) -> None:
        self._bases: dict[tuple[int, object], int] = {}  # (id of the container, key) -> base
        self._starts: list[int] = []  # the bases, ascending (given in order)
        self._entries: list[tuple[ViewRef, int]] = []  # for each: a view of the variable from its start, its size
        self._next = FIRST
        self._kept = 0

    def address(self, ref: Ref | None, spec: tuple[Any, ...]) -> int:
        """``dw := pt``: the number of the byte ``ref`` (a pointer to values laid out as ``spec``) points to."""
        if ref is None:
            return 0
        if isinstance(ref, Stray):
            address: int = ref.k  # type: ignore[assignment]  # an int key
            return address
        seen: Any = ref if isinstance(ref, ViewRef) else view(ref, spec, spec)
        if seen.k is not None and seen.c[seen.k].__class__ is list:  # ADR(arr): the array its elements' pointers see
            seen = ViewRef(
                seen.c[seen.k], None, seen.whole, seen.offset, seen.seen, seen.origin, seen.frame, seen.start
            )
        key = (id(seen.c), seen.k)
        base = self._bases.get(key)
        if base is None:
            base = self._give(key, seen)
        offset: int = seen.offset
        return base + offset

    def pointer(self, number: int, spec: tuple[Any, ...]) -> Ref | None:
        """``pt := dw``: a pointer to the byte ``number`` in the variable it lies in (one past its end included),
        seeing it as ``spec``; NULL for 0; a ``Stray`` pointer for a number in no variable."""
        if number == 0:
            return None
        index = bisect.bisect_right(self._starts, number) - 1
        if index >= 0:
            whole, size = self._entries[index]
            offset = number - self._starts[index]
            if offset <= size:
                return ViewRef(
                    whole.c, whole.k, whole.whole, offset, layout(spec), whole.origin, whole.frame, whole.start
                )
        return Stray(number)

    def _give(self, key: tuple[int, object], seen: ViewRef) -> int:
        """A base for a variable whose address is taken the first time, after every base given so far."""
        size = seen.whole.size
        base = self._next
        if base + size >= LIMIT:
            raise PlcRuntimeError(
                OUT_OF_MEMORY, "the 32-bit addresses are used up: too many variables had their address taken"
            )
        self._next = (base + size + ALIGN) // ALIGN * ALIGN  # a gap of at least a byte: one past its end is its own
        whole = ViewRef(seen.c, seen.k, seen.whole, 0, seen.seen, seen.origin, seen.frame, seen.start)
        self._bases[key] = base
        self._starts.append(base)
        self._entries.append((whole, size))
        if len(self._entries) > self._kept + _CLEAN_EVERY:
            self._clean()
        return base

    def _clean(self) -> None:
        """Forget the variables of calls that returned (a FUNCTION's locals, a VAR_TEMP): a number in one now lies
        in no variable, and the objects are free to go."""
        kept = [
            (start, entry)
            for start, entry in zip(self._starts, self._entries)
            if entry[0].frame is None or entry[0].frame.alive
        ]
        self._starts = [start for start, _ in kept]
        self._entries = [entry for _, entry in kept]
        self._bases = {(id(entry[0].c), entry[0].k): start for start, entry in kept}
        self._kept = len(kept)
