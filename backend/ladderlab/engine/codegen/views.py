"""Memory seen through a pointer of another type (CODESYS ``pt := ADR(x)`` with ``pt : POINTER TO BYTE``).

LadderLab keeps values as Python objects, not bytes; a view reads and writes the bytes a CODESYS PLC on x86/ARM would
hold, little-endian, computed from the value on each access: ``Layout.read`` encodes only the part of the variable the
access covers, ``Layout.write`` splices new bytes in and decodes the variable again. A write whose bytes the variable
cannot hold exactly (a BOOL byte of 2, a character after a STRING's terminator, a STRUCT's padding byte other than 0) is
a fault, so no value changes other than the bytes written; so is reading a byte other than 0 or 1 as a BOOL (CODESYS's
BOOL is 0 or 1, any other byte it shows as INVALID). The layouts come from the lowering as specs (ir/byte_layout.py):
``("int", size, signed)``, ``("real", size)``, ``("bool",)``, ``("string", n)``, ``("wstring", n)``, ``("range", low,
high, base spec)``, ``("enum", name, values, base spec)``, ``("array", count, element spec)``, ``("struct", name, size,
pack_mode, members)``. A subrange's bytes must decode into its range, an enumeration's into one of its members' values:
a write through a pointer of its base type (``POINTER TO INT`` over an ``INT (0..100)`` or a ``Color``) and a read
through a pointer to a subrange (an enumeration) over a variable of its base type fault ``subrange_violation`` outside
it, naming the pointer (``ADR(v)``).
"""

from __future__ import annotations

import functools
import struct
from typing import Any

from ...iec.literals import unheld_character, unheld_message
from ..errors import (
    INDEX_RANGE,
    INVALID_ARGUMENT,
    SUBRANGE,
    PlcRuntimeError,
    check_member,
    check_subrange,
    null_dereference,
    pointer_nowhere,
    pointer_outside_bytes,
)
from . import names
from .runtime import ElementRef, Ref, Seen, Structure, dangling, deep_copy

_INT_FORMATS = {(1, False): "<B", (1, True): "<b", (2, False): "<H", (2, True): "<h"}
_INT_FORMATS |= {(4, False): "<I", (4, True): "<i", (8, False): "<Q", (8, True): "<q"}


def _not_kept(what: str) -> PlcRuntimeError:
    return PlcRuntimeError(INDEX_RANGE, f"writing through a pointer would give {what}, which the variable cannot hold")


class Scalar:
    """An integer, bit string, BOOL or REAL: ``struct`` packs it little-endian."""

    def __init__(self, fmt: str, size: int, kind: str) -> None:
        self.codec, self.size, self.kind = struct.Struct(fmt), size, kind

    def encode(self, value: Any) -> bytes:
        return self.codec.pack(value)

    def decode(self, data: bytes) -> Any:
        value = self.codec.unpack(data)[0]
        if self.kind != "bool":
            return value
        if value not in (0, 1):  # CODESYS's BOOL is 0 or 1; it shows any other byte as INVALID
            what = f"the byte {value:02x} for a BOOL, which is neither 0 nor 1"
            raise PlcRuntimeError(INDEX_RANGE, f"reading through a pointer gives {what}")
        return value == 1

    def read(self, value: Any, offset: int, size: int) -> bytes:
        return self.codec.pack(value)[offset : offset + size]

    def write(self, value: Any, offset: int, data: bytes) -> Any:
        whole = bytearray(self.codec.pack(value))
        whole[offset : offset + len(data)] = data
        if self.kind == "bool" and whole[0] > 1:
            raise _not_kept(f"the bytes {bytes(whole).hex()} for a {self.kind}")
        new = self.decode(bytes(whole))
        if self.codec.pack(new) != whole:  # a REAL NaN payload Python cannot keep
            raise _not_kept(f"the bytes {bytes(whole).hex()} for a {self.kind}")
        return new


class Restricted:
    """A subrange of an integer type or an enumeration (stored as its base type, CODESYS): its base's bytes, decoded
    and written only as a value ``admit`` lets through (it raises for any other)."""

    def __init__(self, base: Scalar, admit: Any) -> None:
        self.base, self.admit, self.size = base, admit, base.size

    def encode(self, value: int) -> bytes:
        return self.base.encode(value)

    def decode(self, data: bytes) -> int:
        return self.admit(self.base.decode(data))

    def read(self, value: int, offset: int, size: int) -> bytes:
        return self.base.read(value, offset, size)

    def write(self, value: int, offset: int, data: bytes) -> int:
        return self.admit(self.base.write(value, offset, data))


class String:
    """STRING[n] (``wide`` False): n + 1 bytes, the characters (one Latin-1 byte each, CODESYS's STRING), a NUL
    terminator, then zeros; WSTRING[n] (``wide``): 2 * (n + 1) bytes, each character a UCS-2 WORD, little-endian
    (CODESYS's "WSTRING" page), a NUL WORD after them. A string holds only its text, so the bytes after its
    terminator read 0 and a character written there is a fault."""

    def __init__(self, length: int, wide: bool = False) -> None:
        self.length, self.wide = length, wide
        self.unit = 2 if wide else 1
        self.size = (length + 1) * self.unit
        self.codec = "utf-16-le" if wide else "latin-1"

    def encode(self, value: str) -> bytes:
        try:
            data = value.encode(self.codec)
        except UnicodeEncodeError:
            data = b""
        if len(data) != len(value) * self.unit:  # a STRING's 'П' (a CoDeSys 2.3 file's cp1251): its byte is unknown
            unheld = unheld_character(value, self.wide) or value[0]
            raise PlcRuntimeError(INVALID_ARGUMENT, f"the bytes of {self.name}: {unheld_message(unheld, self.wide)}")
        return data.ljust(self.size, b"\0")

    def decode(self, data: bytes) -> str:
        if not self.wide:
            return data.split(b"\0", 1)[0].decode("latin-1")
        end = next((i for i in range(0, len(data) - 1, 2) if not data[i] and not data[i + 1]), len(data) & ~1)
        text = data[:end]
        if any(0xD8 <= text[i] <= 0xDF for i in range(1, len(text), 2)):  # a surrogate: no UCS-2 character
            what = f"the bytes {text.hex()} for a WSTRING, which are no UCS-2 text (a WORD 16#D800..16#DFFF)"
            raise PlcRuntimeError(INDEX_RANGE, f"reading through a pointer gives {what}")
        return text.decode("utf-16-le")

    def read(self, value: str, offset: int, size: int) -> bytes:
        return self.encode(value)[offset : offset + size]

    def write(self, value: str, offset: int, data: bytes) -> str:
        whole = bytearray(self.encode(value))
        whole[offset : offset + len(data)] = data
        try:
            new = self.decode(bytes(whole))
        except PlcRuntimeError:
            raise _not_kept(f"the bytes {bytes(whole).hex()} for a {self.name}, which are no UCS-2 text") from None
        if len(new) > self.length or self.encode(new) != whole:
            raise _not_kept(f"a {self.name} with characters after its terminator (or none)")
        return new

    @property
    def name(self) -> str:
        return f"{'WSTRING' if self.wide else 'STRING'}[{self.length}]"


class ArrayLayout:
    """An array (a list) of ``count`` elements laid one after the other, no padding: only the elements an access
    covers are encoded."""

    def __init__(self, count: int, element: Any) -> None:
        self.count, self.element = count, element
        self.size = count * element.size

    def encode(self, value: list) -> bytes:
        return b"".join(self.element.encode(v) for v in value)

    def decode(self, data: bytes) -> list:
        step = self.element.size
        return [self.element.decode(data[i : i + step]) for i in range(0, len(data), step)]

    def read(self, value: list, offset: int, size: int) -> bytes:
        step = self.element.size
        first, last = offset // step, (offset + size - 1) // step
        parts = [self.element.read(value[i], 0, step) for i in range(first, last + 1)]
        start = offset - first * step
        return b"".join(parts)[start : start + size]

    def write(self, value: list, offset: int, data: bytes) -> list:
        step = self.element.size
        end = offset + len(data)
        for i in range(offset // step, (end - 1) // step + 1):
            low, high = max(offset, i * step), min(end, (i + 1) * step)
            value[i] = self.element.write(value[i], low - i * step, data[low - offset : high - offset])
        return value


class StructLayout:
    """A STRUCT (a generated ``Structure``): its members' bytes at their offsets, padding bytes between and after
    them. Padding holds nothing, so it reads 0 and a write of anything else there is a fault (as after a STRING's
    terminator). Only the members an access covers are encoded; a write changes them on the structure itself."""

    def __init__(self, name: str, size: int, members: tuple) -> None:
        self.name, self.size = name, size
        self.members = tuple((names.slot(member), offset, layout(spec)) for member, offset, spec in members)
        used = {offset + i for _, offset, member in self.members for i in range(member.size)}
        self.padding = frozenset(range(size)) - used

    def _covered(self, offset: int, end: int):
        """``(attribute, member offset, layout, first, last)`` of each member bytes ``offset..end - 1`` reach."""
        for attribute, start, member in self.members:
            low, high = max(offset, start), min(end, start + member.size)
            if low < high:
                yield attribute, start, member, low, high

    def encode(self, value: Any) -> bytes:
        """All its bytes (``pt^ := rec`` over other memory): the members', and padding 0."""
        return self.read(value, 0, self.size)

    def read(self, value: Any, offset: int, size: int) -> bytes:
        data = bytearray(size)
        for attribute, start, member, low, high in self._covered(offset, offset + size):
            data[low - offset : high - offset] = member.read(getattr(value, attribute), low - start, high - low)
        return bytes(data)

    def write(self, value: Any, offset: int, data: bytes) -> Any:
        end = offset + len(data)
        padding = sorted(i for i in self.padding if offset <= i < end and data[i - offset])
        if padding:
            raise _not_kept(
                f"the byte {data[padding[0] - offset]:02x} in padding byte {padding[0]} of the STRUCT {self.name}"
            )
        for attribute, start, member, low, high in self._covered(offset, end):
            old = getattr(value, attribute)
            new = member.write(old, low - start, data[low - offset : high - offset])
            if new is not old:
                setattr(value, attribute, new)
        return value


@functools.cache
def layout(spec: tuple) -> Any:
    """The runtime layout of a spec from the lowering (ir/byte_layout.py)."""
    kind = spec[0]
    if kind == "int":
        return Scalar(_INT_FORMATS[(spec[1], spec[2])], spec[1], "int")
    if kind == "real":
        return Scalar("<f" if spec[1] == 4 else "<d", spec[1], "real")
    if kind == "bool":
        return Scalar("<B", 1, "bool")
    if kind in ("string", "wstring"):
        return String(spec[1], kind == "wstring")
    if kind == "struct":
        return StructLayout(spec[1], spec[2], spec[4])
    if kind == "range":
        return Restricted(layout(spec[3]), functools.partial(check_subrange, low=spec[1], high=spec[2]))
    if kind == "enum":
        return Restricted(layout(spec[3]), functools.partial(check_member, values=spec[2], enumeration=spec[1]))
    return ArrayLayout(spec[1], layout(spec[2]))


class ViewRef(Ref):
    """A pointer that sees the variable ``(c, k)`` (laid out as ``whole``; ``k`` None: the array ``c`` itself) from
    byte ``offset`` on as a value of the ``seen`` layout. It may point one past the variable's end, not read or
    write there; ``frame`` is the function call whose variable it is (runtime.Frame), None for any other. ``origin``
    is the REF()/ADR() it came from, which points at byte ``start``: its text is that origin moved by the rest."""

    __slots__ = ("frame", "offset", "origin", "seen", "start", "whole")

    def __init__(
        self, c: object, k: object, whole: Any, offset: int, seen: Any, origin: str, frame: Any, start: int = 0
    ) -> None:
        moved = offset - start
        super().__init__(c, k, origin + (f" {'+' if moved > 0 else '-'} {abs(moved)}" if moved else ""))
        self.whole, self.offset, self.seen, self.origin, self.frame = whole, offset, seen, origin, frame
        self.start = start

    def _target(self, size: int) -> object:
        """The variable, once the ``size`` bytes from ``offset`` on are known to lie inside it (and its call alive)."""
        if self.frame is not None and not self.frame.alive:
            raise dangling(self.text, self.frame)
        if not 0 <= self.offset <= self.whole.size - size:
            raise pointer_outside_bytes(f"the pointer {self.text}", self.offset, size, self.whole.size)
        return self.c if self.k is None else self.c[self.k]  # type: ignore[index]  # see __init__

    def _span(self) -> int:
        """The bytes an access covers: what it sees, but a STRING seen only up to the variable's end when that comes
        first (CODESYS reads a STRING up to its terminator: ``POINTER TO STRING`` over a STRING[4], moved by 2)."""
        if isinstance(self.seen, String):
            return max(0, min(self.seen.size, self.whole.size - self.offset))
        return self.seen.size

    def _read(self, value: object, span: int) -> bytes:
        """The ``span`` bytes seen from ``offset``; a STRING's text must end inside them: else it reads on past the
        variable (a fault naming the bytes it would reach) or past the STRING[n] the pointer sees (a fault too:
        CODESYS documents no value for a ``POINTER TO STRING`` over a longer text, STRING being STRING[80])."""
        data = self.whole.read(value, self.offset, span)
        if isinstance(self.seen, String) and not _terminated(data, self.seen):
            if span < self.seen.size:
                raise pointer_outside_bytes(
                    f"the pointer {self.text}", self.offset, span + self.seen.unit, self.whole.size
                )
            raise PlcRuntimeError(INDEX_RANGE, _longer_than_seen(self, value))
        return data

    def _encoded(self, new: object, span: int) -> bytes:
        """The bytes of ``new`` written from ``offset``: a STRING's text and terminator, and zeros up to ``span``
        (after a terminator the variable holds nothing); a text reaching past the variable is a fault."""
        data = self.seen.encode(new)
        if span < self.seen.size:
            if not _terminated(data[:span], self.seen):
                needed = (len(new) + 1) * self.seen.unit  # type: ignore[arg-type]  # a str: the seen is a String
                raise pointer_outside_bytes(f"the pointer {self.text}", self.offset, needed, self.whole.size)
            data = data[:span]
        return data

    @property
    def v(self) -> object:
        if isinstance(self.seen, ArrayLayout):  # each element is checked when it is read or written
            self._target(0)
            return ArrayView(self, self.seen)
        if isinstance(self.seen, StructLayout):  # each member is, as it is read or written
            self._target(self.seen.size)
            return StructView(self, self.seen)
        span = self._span()
        value = self._target(span)
        try:
            return self.seen.decode(self._read(value, span))
        except PlcRuntimeError as error:
            raise self._through(error, "read") from None

    @v.setter
    def v(self, new: object) -> None:
        span = self._span()
        value = self._target(span)
        try:
            written = self.whole.write(value, self.offset, self._encoded(new, span))
        except PlcRuntimeError as error:
            raise self._through(error, "written") from None
        if self.k is not None and written is not value:
            self.c[self.k] = written  # type: ignore[index]  # as above

    def trial(self, key: object, new: object) -> None:
        """Fault as writing ``new`` would, on a copy: nothing is written (a user's write through the pointer, its
        pair ``(self, key)``, is refused when it is given: engine/paths.py)."""
        span = self._span()
        value = deep_copy(self._target(span))
        try:
            self.whole.write(value, self.offset, self._encoded(new, span))
        except PlcRuntimeError as error:
            raise self._through(error, "written") from None

    def _through(self, error: PlcRuntimeError, how: str) -> PlcRuntimeError:
        """A subrange fault of a value met through this pointer, saying so (the direct assignment's words first)."""
        if error.code != SUBRANGE:
            return error
        return PlcRuntimeError(SUBRANGE, f"{error.message}: {how} through {self.text}")

    @property
    def pair(self) -> tuple[object, object]:
        """``(self, "v")``: a VAR_IN_OUT or an online path reaches the bytes through ``v``; checked here, so an
        online path through a pointer outside its variable (or dangling) names no variable (engine/paths.py)."""
        self._target(0 if isinstance(self.seen, ArrayLayout) else self._span())
        return (self, "v")

    def at(self, offset: int, seen: Any) -> ViewRef:
        """The view of the ``seen`` value ``offset`` bytes further on (an element, a member of what this one sees)."""
        return ViewRef(self.c, self.k, self.whole, self.offset + offset, seen, self.origin, self.frame, self.start)

    def __getitem__(self, key: str) -> object:  # (self, "v") as a VAR_IN_OUT reference
        return self.v

    def __setitem__(self, key: str, value: object) -> None:
        self.v = value

    def place(self, size: int) -> tuple[object, int]:
        return (id(self.c) if self.k is None else (id(self.c), self.k)), self.offset

    def shifted(self, offset: int, size: int, what: str) -> ViewRef:
        """``p + offset`` bytes, whatever the size of what p sees: anywhere from the variable's start to one past
        its end."""
        position = self.offset + offset
        if not 0 <= position <= self.whole.size:
            raise pointer_outside_bytes(f"{what} moved by {offset} bytes", position, 0, self.whole.size)
        return ViewRef(self.c, self.k, self.whole, position, self.seen, self.origin, self.frame, self.start)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, ViewRef):
            return other.c is self.c and other.k == self.k and other.offset == self.offset
        if not isinstance(other, Ref) or other.c is not self.c:
            return False
        if self.k is None:  # the array c seen from one of its elements: ``other`` to that element
            return isinstance(other.k, int) and other.k * self.whole.element.size == self.offset
        return self.offset == 0 and other.k == self.k

    def __hash__(self) -> int:
        return hash((id(self.c), self.k, self.offset))


def _longer_than_seen(ref: ViewRef, value: object) -> str:
    """Why a STRING[n] read through a pointer stops: the text there is longer than n (a STRING(255) seen by a
    ``POINTER TO STRING``); how long, when the variable is a STRING itself."""
    seen, whole = ref.seen, ref.whole
    held = ""
    if isinstance(whole, String) and isinstance(value, str):
        held = f" ({len(value) - ref.offset // whole.unit} characters)"
    return (
        f"the pointer {ref.text} sees a {seen.name}, and the text there{held} runs on past its {seen.length} "
        "characters: what CODESYS reads then is not documented; declare the pointer "
        f"POINTER TO {'WSTRING' if seen.wide else 'STRING'}(n) with n at least the text's length"
    )


def _terminated(data: bytes, seen: Any) -> bool:
    """``data`` holds a STRING's terminator (a NUL byte; a WSTRING's a NUL WORD at an even byte)."""
    if not seen.wide:
        return b"\0" in data
    return any(not data[i] and not data[i + 1] for i in range(0, len(data) - 1, 2))


class ArrayView(Seen):
    """``pt^`` of a pointer to an array seen over other memory: ``pt^[i]`` reads and writes element i's bytes alone
    (OSCAT's ``REF_TO ARRAY[1..255] OF BYTE`` over a shorter STRING reads only the characters it indexes)."""

    __slots__ = ("ref", "seen")

    def __init__(self, ref: ViewRef, seen: ArrayLayout) -> None:
        self.ref, self.seen = ref, seen

    def _element(self, index: int) -> ViewRef:
        return self.ref.at(index * self.seen.element.size, self.seen.element)

    def __getitem__(self, index: int) -> object:
        return self._element(index).v

    def __setitem__(self, index: int, value: object) -> None:
        self._element(index).v = value

    def __len__(self) -> int:
        return self.seen.count

    def ll_copy(self) -> list:
        """Its elements' values (a nested array seen: lists of them), for an array input passed ``pt^`` by value."""
        return [deep_copy(value) for value in self]

    def trial(self, index: int, new: object) -> None:
        """``ViewRef.trial`` of element ``index`` (an online path ``pt^[i]``)."""
        self._element(index).trial("v", new)

    def ll_assign(self, source: list) -> None:
        """``pt^ := arr``: each element's bytes written in turn (runtime.assign_into)."""
        for index, value in enumerate(source):
            self[index] = value

    def __iter__(self):
        return (self[i] for i in range(self.seen.count))


class StructView(Seen):
    """``pt^`` of a pointer to a STRUCT seen over other memory (CODESYS's ``POINTER TO Header := ADR(buffer)``):
    ``pt^.m`` reads and writes member m's bytes alone, where the STRUCT's layout puts them (``StructLayout``); the
    generated code reaches members by their attribute names, as on a ``Structure``."""

    __slots__ = ("ref", "seen")

    def __init__(self, ref: ViewRef, seen: StructLayout) -> None:
        self.ref, self.seen = ref, seen

    def _member(self, attribute: str) -> ViewRef:
        for name, offset, member in self.seen.members:
            if name == attribute:
                return self.ref.at(offset, member)
        raise AttributeError(attribute)

    def __getattr__(self, attribute: str) -> object:
        return self._member(attribute).v

    def __setattr__(self, attribute: str, value: object) -> None:
        if attribute in StructView.__slots__:
            object.__setattr__(self, attribute, value)
        else:
            self._member(attribute).v = value

    def __getitem__(self, attribute: str) -> object:  # (view, member) as a VAR_IN_OUT reference or an online path
        return self._member(attribute).v

    def __setitem__(self, attribute: str, value: object) -> None:
        self._member(attribute).v = value

    def trial(self, attribute: str, new: object) -> None:
        """``ViewRef.trial`` of a member (an online path ``pt^.m``)."""
        self._member(attribute).trial("v", new)

    def ll_assign(self, source: object) -> None:
        """``pt^ := rec``: every byte of the STRUCT written at once, its members' and 0 for padding (assign_into)."""
        self.ref.v = source

    def ll_copy(self) -> Structure:
        """Its members' values in a structure of their own, for a STRUCT input passed ``pt^`` by value."""
        copy = _copy_class(self.seen)()
        for name, _, _ in self.seen.members:
            setattr(copy, name, deep_copy(self._member(name).v))
        return copy


@functools.cache
def _copy_class(seen: StructLayout) -> type[Structure]:
    """A structure class holding the members of ``seen`` (a by-value copy of a STRUCT seen over other memory reaches
    them by the generated class's attribute names, the only part of it that code uses)."""
    fields = tuple(name for name, _, _ in seen.members)
    return type(f"Seen_{seen.name}", (Structure,), {"__slots__": fields, "ll_fields": fields})


class Stray(Ref):
    """A pointer made from a number that lies in no variable (engine/codegen/addresses.py): it may be moved and
    compared, not read or written through (the located fault ``pointer_nowhere``, never a Python error)."""

    __slots__ = ()

    def __init__(self, address: int) -> None:
        super().__init__(None, address, f"16#{address:X}")

    def _fault(self) -> PlcRuntimeError:
        return pointer_nowhere(f"the pointer {self.text}", self.k)  # type: ignore[arg-type]  # an int key

    @property
    def v(self) -> object:
        raise self._fault()

    @v.setter
    def v(self, value: object) -> None:
        raise self._fault()

    @property
    def pair(self) -> tuple[object, object]:
        raise self._fault()

    def place(self, size: int) -> tuple[object, int]:
        return None, self.k  # type: ignore[return-value]  # orders with no variable's pointer (runtime.pointer_order)

    def shifted(self, offset: int, size: int, what: str) -> Stray:
        return Stray(self.k + offset)  # type: ignore[operator]  # an int key

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Stray) and other.k == self.k

    def __hash__(self) -> int:
        return hash(self.k)


def view(ref: Ref | None, whole: tuple, seen: tuple) -> ViewRef | Stray | None:
    """``ref`` (a pointer to a value laid out as ``whole``) seen as a pointer to ``seen``. A pointer to an array
    element sees the whole (innermost) array from that element on, so it may walk to its neighbours."""
    if ref is None or isinstance(ref, Stray):
        return ref
    seen_layout = layout(seen)
    if isinstance(ref, ViewRef):
        return ViewRef(ref.c, ref.k, ref.whole, ref.offset, seen_layout, ref.origin, ref.frame, ref.start)
    element = layout(whole)
    frame = getattr(ref, "frame", None)
    if isinstance(ref.c, list) and isinstance(ref.k, int):
        array = ArrayLayout(len(ref.c), element)
        offset = ref.k * element.size if 0 <= ref.k <= len(ref.c) else -1
        if isinstance(ref, ElementRef):  # moved by arithmetic: its origin points ``moved`` bytes before it
            return ViewRef(ref.c, None, array, offset, seen_layout, ref.origin, frame, offset - ref.moved)
        return ViewRef(ref.c, None, array, offset, seen_layout, ref.text, frame, offset)
    return ViewRef(ref.c, ref.k, element, 0, seen_layout, ref.text, frame)


def pointer_add(ref: Ref | None, offset: int, size: int, what: str, spec: tuple | None) -> Ref:
    """``p + offset`` (bytes, CODESYS) for a pointer to ``size``-byte values laid out as ``spec`` (None: no byte
    layout). Whole elements along the array p points into stay an element reference (``Ref.shifted``); any other
    move (part of an element, away from a variable that is no array element: ``ADR(str) + 3``) sees the variable's
    bytes from there as p's type, a ``ViewRef`` that faults outside the variable. A NULL ``p`` is a fault."""
    if ref is None:
        raise null_dereference(what)
    in_array = isinstance(ref.c, list) and isinstance(ref.k, int)
    if spec is None or isinstance(ref, ViewRef | Stray) or offset == 0 or (in_array and offset % size == 0):
        return ref.shifted(offset, size, what)
    return view(ref, spec, spec).shifted(offset, size, what)  # type: ignore[union-attr]  # ref is no NULL
