"""The process image: one byte-addressed memory per area, and typed views generated code reads and writes.

Areas (iec/addresses.py): ``I`` inputs, ``Q`` outputs, ``M`` memory (Mosaic ``R``), ``S`` system. The program
works on images: at the start of every scan the inputs the world set (``inputs``: ``--set %IX0.1``, writes and
forces) are copied into the input image ``I`` it reads, and at the end of every scan its output image ``Q`` is
published (``outputs``), after the forces are applied again, so a forced output is what is published. ``M`` and
``S`` are plain memory. Paths to an address or a located variable read and write the program's image, like any
variable (so a halted scan shows what the program works with); a write to an input also sets the inputs, which the
next scans read again (docs/runtime.md).

A view is a typed window on one buffer, indexed by byte offset (a bit view: by bit number): ``view[k]`` reads,
``view[k] = v`` writes, so ``(view, k)`` is a reference like any other ``(container, key)`` of the engine and a
located variable reads and writes through it in generated code: ``ll_io_I_INT[2]``. Multi-byte values are
little endian, so overlapping addresses (``%MW0`` and ``%MB1``) see the same bytes.
"""

from __future__ import annotations

import struct
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from ..iec.addresses import Address, parse_address
from ..iec.elementary import ELEMENTARY

#: How each elementary type is held in memory: (bytes, signed) of an integer, or a struct format of a float.
_INTEGERS = {name: (max(1, info.bits // 8), info.signed) for name, info in ELEMENTARY.items() if info.bits}
_FLOATS = {"REAL": struct.Struct("<f"), "LREAL": struct.Struct("<d")}


class BitView:
    """BOOL at a bit address, indexed by bit number (byte * 8 + bit)."""

    __slots__ = ("buffer",)

    def __init__(self, buffer: bytearray) -> None:
        self.buffer = buffer

    def __getitem__(self, bit: int) -> bool:
        return (self.buffer[bit >> 3] >> (bit & 7)) & 1 == 1

    def __setitem__(self, bit: int, value: bool) -> None:
        mask = 1 << (bit & 7)
        byte = self.buffer[bit >> 3]
        self.buffer[bit >> 3] = byte | mask if value else byte & ~mask & 0xFF


class ByteBoolView:
    """BOOL at a byte (or wider) address: its first byte, 0 or 1 (CODESYS)."""

    __slots__ = ("buffer",)

    def __init__(self, buffer: bytearray) -> None:
        self.buffer = buffer

    def __getitem__(self, offset: int) -> bool:
        return self.buffer[offset] != 0

    def __setitem__(self, offset: int, value: bool) -> None:
        self.buffer[offset] = 1 if value else 0


class IntView:
    """An integer, bit string, TIME, TOD, DATE or DT (its engine value: an int) in ``width`` bytes."""

    __slots__ = ("buffer", "signed", "width")

    def __init__(self, buffer: bytearray, width: int, signed: bool) -> None:
        self.buffer, self.width, self.signed = buffer, width, signed

    def __getitem__(self, offset: int) -> int:
        return int.from_bytes(self.buffer[offset : offset + self.width], "little", signed=self.signed)

    def __setitem__(self, offset: int, value: int) -> None:
        self.buffer[offset : offset + self.width] = value.to_bytes(self.width, "little", signed=self.signed)


class FloatView:
    """REAL (binary32) or LREAL (binary64)."""

    __slots__ = ("buffer", "format")

    def __init__(self, buffer: bytearray, format: struct.Struct) -> None:
        self.buffer, self.format = buffer, format

    def __getitem__(self, offset: int) -> float:
        return self.format.unpack_from(self.buffer, offset)[0]

    def __setitem__(self, offset: int, value: float) -> None:
        self.format.pack_into(self.buffer, offset, value)


class MirrorView:
    """What a path writes to an input: the inputs the world set and the input image the program reads, so a
    write acts at once (also in a halted scan) and the next scans read it again; reads come from the image."""

    __slots__ = ("image", "inputs")

    def __init__(self, image: View, inputs: View) -> None:
        self.image, self.inputs = image, inputs

    def __getitem__(self, key: int) -> object:
        return self.image[key]

    def __setitem__(self, key: int, value: Any) -> None:  # the view's type: paths coerce what they write
        self.inputs[key] = value
        self.image[key] = value


View = BitView | ByteBoolView | IntView | FloatView
AREA_ORDER = "IQMS"


@dataclass
class IoPoint:
    """One address the program uses, for the I/O view: its area, its path (the address), its type, and the
    variables declared at it (paths, none for an address used or declared without a name)."""

    area: str
    address: str
    type: str
    names: list[str] = field(default_factory=list)


def image_view_name(buffer: str, kind: str) -> str:
    """The module global generated code reads a view through: ``ll_io_I_INT``, ``ll_io_inputs_BIT``."""
    return f"ll_io_{buffer}_{kind}"  # (engine/paths.py Roots makes the views no generated code names)


def located_address(text: str | None) -> Address:
    """The address of a located variable (``Slot.address``, set on every located slot)."""
    if text is None:
        raise ValueError("not a located variable")
    return parse_address(text)


def view_kind(address: Address, type_name: str | None) -> str:
    """The view a variable of ``type_name`` at ``address`` is read through (one per kind and buffer)."""
    if type_name is None:
        raise ValueError(f"only an elementary variable can be located at {address.text}")
    if type_name == "BOOL":
        return "BIT" if address.bit is not None else "BOOL8"
    return type_name


def key_of(address: Address) -> int:
    """The index into its view: the bit number of a bit address, else the byte offset."""
    return address.bit if address.bit is not None else address.offset


class ProcessImage:
    """The areas of one simulation, sized to the addresses its program uses."""

    def __init__(self, addresses: Iterable[Address | str]) -> None:
        sizes: dict[str, int] = {}
        for written in addresses:
            address = parse_address(written) if isinstance(written, str) else written
            sizes[address.area] = max(sizes.get(address.area, 0), address.end)
        self.sizes = sizes
        self.inputs = bytearray(sizes.get("I", 0))  # what the world set
        self.buffers = {area: bytearray(size) for area, size in sizes.items()}  # the program's images
        self.outputs = bytearray(sizes.get("Q", 0))  # published at the end of every scan
        self._views: dict[tuple[str, str], View] = {}

    def view(self, buffer: str, kind: str) -> View | MirrorView:
        """The view of ``kind`` (a type name, ``BIT`` or ``BOOL8``) on a buffer: an area's image, ``inputs`` /
        ``outputs`` (the world's side of I and Q), or ``set`` (an input written: the inputs and the image)."""
        if buffer == "set":
            return MirrorView(self._view("I", kind), self._view("inputs", kind))
        return self._view(buffer, kind)

    def _view(self, buffer: str, kind: str) -> View:
        found = self._views.get((buffer, kind))
        if found is None:
            memory = (
                self.inputs if buffer == "inputs" else self.outputs if buffer == "outputs" else self.buffers[buffer]
            )
            if kind == "BIT":
                found = BitView(memory)
            elif kind == "BOOL8":
                found = ByteBoolView(memory)
            elif kind in _FLOATS:
                found = FloatView(memory, _FLOATS[kind])
            else:
                width, signed = _INTEGERS[kind]
                found = IntView(memory, width, signed)
            self._views[(buffer, kind)] = found
        return found

    def read_inputs(self) -> None:
        """The start of a scan: the program's input image takes the inputs the world set."""
        if self.inputs:
            self.buffers["I"][:] = self.inputs

    def publish(self) -> None:
        """The end of a scan: the outputs take the program's output image."""
        if self.outputs:
            self.outputs[:] = self.buffers["Q"]

    def clear(self) -> None:
        """A restart: the output and memory images and the published outputs are cleared; the inputs stay as the
        world set them, and the input image shows them."""
        for memory in self.buffers.values():
            memory[:] = bytes(len(memory))
        self.outputs[:] = bytes(len(self.outputs))
        self.read_inputs()

    def state(self) -> dict[str, bytes]:
        """Every buffer's bytes (engine/state.py): the images, the inputs and the published outputs."""
        return {"inputs": bytes(self.inputs), "outputs": bytes(self.outputs)} | {
            area: bytes(memory) for area, memory in self.buffers.items()
        }

    def restore(self, state: dict[str, bytes]) -> None:
        """Write captured buffers back in place (the views keep reading the same memories)."""
        memories = {"inputs": self.inputs, "outputs": self.outputs, **self.buffers}
        for name, data in state.items():
            memories[name][:] = data

    @staticmethod
    def path_buffer(area: str, writing: bool) -> str:
        """The buffer a path to ``area`` reads (``writing`` False) or writes: the program's image, like any
        variable (so halted scans and watch lists show the values the program works with); a write to an input
        also sets the inputs the world set (``set``), which the next scans read again."""
        return "set" if writing and area == "I" else area
