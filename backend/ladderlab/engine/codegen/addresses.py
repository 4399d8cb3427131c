"""A pointer as a number (CODESYS typing: ``dw := pt``, ``pt := dw``, ``pt < dw``; docs/st.md).

LadderLab's variables live in no memory, so addresses are given synthetically, once per simulation. Each outermost
variable (one that is part of no STRUCT or array: a program's, an FB instance's, a FUNCTION's, a global) gets,
the first time an address inside it is taken as a number, a base address for the simulation's life, unique, a
multiple of ``ALIGN``, never 0, with a gap after it so one past its end belongs to it alone. Any part of it (a
member, an element, a row, nested in any way) lies at that base plus the part's byte offset as ir/byte_layout.py
lays the variable out, so ``ADR(rec.m) = ADR(rec) + offset of m`` and ``ADR(a[1, 0]) = ADR(a) + a row's size``.

The engine's values do not know the variable they are part of, so ``ADR(x.m)`` and a VAR_IN_OUT argument ``x.m``
tell it (``part``, emitted by engine/codegen/expressions.py under CODESYS typing): the STRUCTs and arrays inside
``x`` are linked to ``x`` with their offsets. A part of a variable whose outermost variable has no byte layout (a
STRUCT with a TIME member), or of one the engine was never told of (inside an FB instance passed to a VAR_IN_OUT),
has no exact address: taking it as a number is the located fault ``invalid_argument``, never a made-up number.
``p = q`` and ``p < q`` compare the bytes of one variable the same way, however each pointer got there.

``dw := pt`` is the number of the byte pt points to; ``pt := dw`` finds the variable the number lies in and points
there, seeing its bytes as the pointer's type (a ``ViewRef`` over the outermost variable); a number in no variable
gives a ``Stray`` pointer that faults when it is read or written through, and 0 is NULL. Only alignment and offsets
within one variable mean anything: which base a variable gets is this simulation's choice, as a PLC's linker's is.
"""

from __future__ import annotations

import bisect
from typing import Any

from ..errors import INVALID_ARGUMENT, OUT_OF_MEMORY, PlcRuntimeError
from .runtime import ORDERS, Ref, Structure, is_composite_value, pointer_order
from .views import ArrayLayout, Stray, StructLayout, ViewRef, layout

#: Every base address is a multiple of this (CODESYS aligns no variable to more than 8 bytes).
ALIGN = 8
#: The first base address: low addresses stay free, as on a PLC, so a small number is no variable's.
FIRST = 0x1_0000
#: Addresses are 32-bit (SIZEOF of a pointer is 4: ir/byte_layout.py).
LIMIT = 1 << 32
#: Variables of calls that returned are forgotten once this many more were registered since the last clean-up.
_CLEAN_EVERY = 4096


class Outer:
    """An outermost variable ``c[k]``: its byte layout (``whole``; None with the ``reason`` it has none), the name
    its pointers are shown from (``ADR(name) + n``), the call it belongs to (``frame``, None: the simulation's) and
    its base address once one is given."""

    __slots__ = ("base", "c", "frame", "k", "name", "reason", "value", "whole", "written")

    def __init__(self, c: object, k: object, whole: Any, reason: str | None, name: str, frame: Any) -> None:
        self.c, self.k, self.whole, self.reason, self.name, self.frame = c, k, whole, reason, name, frame
        self.value = c[k]  # type: ignore[index]  # a container and its key, as a Ref's
        self.base: int | None = None
        self.written = True  # its name as the program writes it (else the IR's, upper case)

    def alive(self) -> bool:
        return self.frame is None or self.frame.alive


class AddressSpace:
    """The synthetic addresses of one simulation (``ll_addr`` in its generated module's globals)."""

    def __init__(self) -> None:
        self._outers: dict[tuple[int, object], Outer] = {}  # (id of the container, key) -> the variable
        self._links: dict[int, tuple[object, Outer, int, Any]] = {}  # id of a STRUCT / array inside one -> (it,
        # its outermost variable, its byte offset there, its layout)
        self._starts: list[int] = []  # the bases given, ascending
        self._based: list[Outer] = []  # the variable of each
        self._next = FIRST
        self._registered = 0

    def part(
        self,
        ref: object,
        pair: tuple[object, object],
        spec: tuple[Any, ...] | str,
        name: str,
        frame: Any,
        written: bool,
    ) -> object:
        """``ADR(x.m)`` or a VAR_IN_OUT argument ``x.m`` (``ref``, returned): its outermost variable ``x`` is
        ``pair``, laid out as ``spec`` (or why it has no layout), named ``name`` (as ``written`` in an ADR(), else
        the IR's upper-case name until an ADR() names it); it is linked to its parts once (again if it is another
        value now)."""
        c, k = pair
        outer = self._outers.get((id(c), k))
        value = c[k]  # type: ignore[index]  # a container and its key, as a Ref's
        if outer is None or outer.c is not c or (outer.value is not value and is_composite_value(value)):
            outer = self._register(c, k, spec, name, frame)
            outer.written = written
        elif written and not outer.written:
            outer.name, outer.written = name, True
        return ref

    def address(self, ref: Ref | None, spec: tuple[Any, ...]) -> int:
        """``dw := pt``: the number of the byte ``ref`` (a pointer to values laid out as ``spec``) points to."""
        if ref is None:
            return 0
        if isinstance(ref, Stray):
            address: int = ref.k  # type: ignore[assignment]  # an int key
            return address
        if isinstance(ref, ViewRef):
            outer, offset = self._place(ref, ref.whole)
            return self._base(outer) + offset + ref.offset
        outer, offset = self._place(ref, layout(spec))
        return self._base(outer) + offset

    def pointer(self, number: int, spec: tuple[Any, ...]) -> Ref | None:
        """``pt := dw``: a pointer to the byte ``number`` in the variable it lies in (one past its end included),
        seeing it as ``spec``; NULL for 0; a ``Stray`` pointer for a number in no variable."""
        if number == 0:
            return None
        index = bisect.bisect_right(self._starts, number) - 1
        if index >= 0:
            outer = self._based[index]
            offset = number - self._starts[index]
            if offset <= outer.whole.size:
                origin = f"ADR({outer.name})"
                return ViewRef(outer.c, outer.k, outer.whole, offset, layout(spec), origin, outer.frame)
        return Stray(number)

    def same(self, left: Ref | None, right: Ref | None) -> bool:
        """``p = q``: one variable referred to (``Ref.__eq__``), or one byte of one outermost variable, however each
        pointer got there (``ADR(rec.m)`` and ``ADR(rec) + 2``, a pointer made from a number)."""
        if left == right:
            return True
        places = self._in_one_variable(left, right)
        return places is not None and places[0] == places[1]

    def order(self, left: Ref | None, right: Ref | None, left_size: int, right_size: int, op: str) -> bool:
        """``p < q`` (``<=``, ``>``, ``>=``): the bytes two pointers into one outermost variable point to, however
        each got there (``ADR(buf) + n`` and ``ADR(buf[i])``); else as runtime.pointer_order orders them."""
        places = self._in_one_variable(left, right)
        if places is not None:
            return ORDERS[op](*places)
        return pointer_order(left, right, left_size, right_size, op)

    def _in_one_variable(self, left: Ref | None, right: Ref | None) -> tuple[int, int] | None:
        """The bytes two pointers point to when both lie in one outermost variable an address was taken in."""
        if not self._outers or not isinstance(left, Ref) or not isinstance(right, Ref):  # NULL, no address taken
            return None
        if isinstance(left, Stray) or isinstance(right, Stray):
            return None
        here, there = self._locate(left), self._locate(right)
        if here is None or there is None or here[0] is not there[0]:
            return None
        return here[1], there[1]

    def _locate(self, ref: Ref) -> tuple[Outer, int] | None:
        """The outermost variable ``ref`` points into and the byte there, if known (no address is given)."""
        c, k = ref.c, ref.k
        moved = ref.offset if isinstance(ref, ViewRef) else 0
        link = self._links.get(id(c))
        if link is not None and link[0] is c and link[3] is not None:
            _, outer, offset, seen = link
            return outer, offset + moved + (0 if k is None else _offset_of(seen, k))
        whole = self._outers.get((id(c), 0 if k is None else k))
        return (whole, moved) if whole is not None and whole.c is c else None

    def _place(self, ref: Ref, whole: Any) -> tuple[Outer, int]:
        """The outermost variable ``ref``'s ``(c, k)`` lies in and its byte offset there; a variable no link names
        (not inside a STRUCT or an array: ``whole`` lays it out) becomes an outermost one itself."""
        c, k = ref.c, ref.k
        link = self._links.get(id(c))
        if link is not None and link[0] is c:  # c: a STRUCT or an array inside an outermost variable
            _, outer, offset, seen = link
            self._exact(outer, ref)
            return outer, offset + (0 if k is None else _offset_of(seen, k))
        whole_variable = self._outers.get((id(c), 0 if k is None else k))  # (k None: a FUNCTION's one in its box)
        if whole_variable is not None and whole_variable.c is c:
            self._exact(whole_variable, ref)
            return whole_variable, 0
        if k is not None and not isinstance(c, list | Structure):  # a variable of an instance, a global
            frame = getattr(ref, "frame", None)
            return self._register(c, k, whole, _name(ref.text), frame), 0
        raise PlcRuntimeError(
            INVALID_ARGUMENT,
            f"the pointer {ref.text} as a number: the STRUCT or array it points into was reached through an FB "
            "instance passed to a VAR_IN_OUT, a pointer or a path calling a function, so which variable it is part of "
            "is unknown here (take that variable's address where it is declared first: ADR(x))",
        )

    @staticmethod
    def _exact(outer: Outer, ref: Ref) -> None:
        """A part of ``outer`` has an exact address only when ``outer`` has a byte layout."""
        if outer.reason is not None:
            raise PlcRuntimeError(
                INVALID_ARGUMENT,
                f"the pointer {ref.text} as a number: it points into {outer.name}, which has no byte layout, so "
                f"where it lies there is unknown: {outer.reason}",
            )

    def _register(self, c: object, k: object, spec: Any, name: str, frame: Any) -> Outer:
        """``c[k]``, an outermost variable laid out as ``spec`` (a spec, a layout, or why it has none), linked to
        the STRUCTs and arrays inside it."""
        if isinstance(spec, str):
            outer = Outer(c, k, None, spec, name, frame)
            self._link_unlaid(outer.value, outer)
        else:
            outer = Outer(c, k, layout(spec) if isinstance(spec, tuple) else spec, None, name, frame)
            self._link(outer.value, outer.whole, outer, 0)
        self._outers[(id(c), k)] = outer
        self._registered += 1
        if self._registered > _CLEAN_EVERY:
            self._clean()
        return outer

    def _link(self, value: Any, seen: Any, outer: Outer, offset: int) -> None:
        """Link ``value`` (laid out as ``seen`` at ``offset`` in ``outer``) and every STRUCT and array inside it."""
        if isinstance(seen, StructLayout):
            self._links[id(value)] = (value, outer, offset, seen)
            for name, start, member in seen.members:
                if isinstance(member, StructLayout | ArrayLayout):
                    self._link(getattr(value, name), member, outer, offset + start)
        elif isinstance(seen, ArrayLayout):
            self._links[id(value)] = (value, outer, offset, seen)
            if isinstance(seen.element, StructLayout | ArrayLayout):
                for index, element in enumerate(value):
                    self._link(element, seen.element, outer, offset + index * seen.element.size)

    def _link_unlaid(self, value: Any, outer: Outer) -> None:
        """Link the STRUCTs and arrays inside ``outer``, which has no byte layout (their addresses fault)."""
        if not is_composite_value(value):
            return
        self._links[id(value)] = (value, outer, 0, None)
        parts = value if value.__class__ is list else [getattr(value, name) for name in value.ll_fields]
        for part in parts:
            self._link_unlaid(part, outer)

    def _base(self, outer: Outer) -> int:
        """The base address of ``outer``, given the first time it is asked for, after every base given so far."""
        if outer.base is not None:
            return outer.base
        base = self._next
        if base + outer.whole.size >= LIMIT:
            raise PlcRuntimeError(
                OUT_OF_MEMORY, "the 32-bit addresses are used up: too many variables had their address taken"
            )
        self._next = (base + outer.whole.size + ALIGN) // ALIGN * ALIGN  # a gap of a byte at least: one past its
        outer.base = base  # end is its own
        self._starts.append(base)
        self._based.append(outer)
        return base

    def _clean(self) -> None:
        """Forget the variables of calls that returned (a FUNCTION's, a VAR_TEMP): a number in one now lies in no
        variable, and the objects are free to go."""
        self._outers = {key: outer for key, outer in self._outers.items() if outer.alive()}
        self._links = {key: link for key, link in self._links.items() if link[1].alive()}
        kept = [(start, outer) for start, outer in zip(self._starts, self._based) if outer.alive()]
        self._starts = [start for start, _ in kept]
        self._based = [outer for _, outer in kept]
        self._registered = 0


def _offset_of(seen: Any, key: object) -> int:
    """The byte offset of the member or element ``key`` in a STRUCT or an array laid out as ``seen``."""
    if isinstance(seen, StructLayout):
        start: int = next(start for name, start, _ in seen.members if name == key)
        return start
    offset: int = key * seen.element.size  # an element's index (an int key)
    return offset


def _name(text: str) -> str:
    """The variable a reference's text ``ADR(x)`` / ``REF(x)`` names (the text itself for any other)."""
    for call in ("ADR(", "REF("):
        if text.startswith(call) and text.endswith(")"):
            return text[len(call) : -1]
    return text
