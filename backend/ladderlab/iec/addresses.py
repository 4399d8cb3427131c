"""Directly represented variables: ``%IX0.1``, ``%QW4``, ``%MD8``, and the seeds' Mosaic forms (IEC 61131-3 2.4.1.1,
VAR-70..76, ST-12..15).

``%`` + area + size + position. Areas: ``I`` inputs, ``Q`` outputs, ``M`` memory (IEC); Mosaic's ``X`` inputs,
``Y`` outputs, ``R`` registers (the same bytes as ``M``: ``%R10`` is ``%MB10``, VAR-72) and ``S`` system
registers. Sizes: ``X`` bit (IEC's default), ``B`` byte (8), ``W`` word (16), ``D`` double word (32), ``L`` long
word (64), Mosaic ``F`` a REAL in 32 bits. Every position is a **byte offset** (CoDeSys 2.3, TwinCAT 2 and Mosaic
address bytes: ``%MW1`` is bytes 1 and 2, overlapping ``%MW0``; CODESYS V3 would read ``%MW1`` as bytes 2-3); a bit
is ``byte.bit`` (``%IX1.2``: byte 1, bit 2) or, with one number, a bit number counted from bit 0 of byte 0
(``%IX5``, Concept's form in ST-26); ``%RW152.9`` is bit 9 of the word at byte 152. Multi-byte values are little
endian (VAR-72), so ``%MW0`` overlaps ``%MB0``, ``%MB1`` and ``%MX0.0`` .. ``%MX1.7``.

An address used without a declaration has its size's default type (S002 Table 10.1, ST-13): X -> BOOL,
B -> BYTE, W -> INT, D -> REAL, L -> LWORD (Mosaic: R and S without a size -> BYTE, F -> REAL). A declaration
``x AT %IW2 : UINT`` may give any elementary type of the address's width (BOOL on a byte or wider address
uses its first byte, CODESYS' rule); STRINGs, arrays and structures at addresses are not supported.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .elementary import ELEMENTARY, canonical_type_name
from .values import article

#: Area letter as written -> the memory it names.
AREAS = {"I": "I", "Q": "Q", "M": "M", "X": "I", "Y": "Q", "R": "M", "S": "S"}
_MOSAIC_AREAS = {"X", "Y", "R", "S"}
_WIDTH = {"X": 0, "B": 1, "W": 2, "D": 4, "L": 8, "F": 4}
DEFAULT_TYPES = {"X": "BOOL", "B": "BYTE", "W": "INT", "D": "REAL", "L": "LWORD", "F": "REAL"}
_FORM = re.compile(r"%([IQMXYRS])([XBWDLF]?)(\d+(?:\.\d+)*)\Z", re.IGNORECASE)


@dataclass(frozen=True)
class Address:
    """A parsed direct address: ``area`` I, Q, M or S; ``bit`` the absolute bit number for a bit address, else
    None; ``offset`` the first byte; ``width`` its bytes (a bit address: 1, the byte it lies in)."""

    text: str  # canonical: upper case, as written otherwise (%RW152.9 stays, not %MX153.1)
    area: str
    size: str  # X B W D L F
    offset: int
    bit: int | None = None

    @property
    def width(self) -> int:
        return 1 if self.bit is not None else _WIDTH[self.size]

    @property
    def default_type(self) -> str:
        return "BOOL" if self.bit is not None else DEFAULT_TYPES[self.size]

    @property
    def end(self) -> int:
        """The byte after the last this address covers."""
        return self.offset + self.width


def parse_address(text: str) -> Address:
    """``%IX0.1`` -> Address; ValueError saying what is wrong (``%IX0.8``: bit 8 of a byte)."""
    match = _FORM.match(text.strip())
    if match is None:
        raise ValueError(f"'{text}' is not a direct address such as %IX0.1, %QW4 or %MD8")
    area_letter, size, numbers = match.group(1).upper(), match.group(2).upper(), match.group(3)
    parts = [int(n) for n in numbers.split(".")]
    canonical = f"%{area_letter}{size}{numbers}"
    area = AREAS[area_letter]
    if not size:
        size = "B" if area_letter in ("R", "S") else "X"  # Mosaic registers address bytes; I/Q/M/X/Y bits
    if len(parts) > 2:
        raise ValueError(f"{canonical}: hierarchical addresses beyond byte.bit depend on the hardware configuration")
    if size == "X":
        if len(parts) == 1:
            return Address(canonical, area, size, parts[0] // 8, parts[0])  # %IX5: bit 5 (Concept)
        byte, bit = parts
        if bit > 7:
            raise ValueError(f"{canonical}: a byte has bits 0..7, not {bit}")
        return Address(canonical, area, size, byte, byte * 8 + bit)
    offset = parts[0]
    if len(parts) == 2:  # a bit of a larger address: %RW152.9 (Mosaic), little endian
        bit = parts[1]
        if bit >= _WIDTH[size] * 8:
            raise ValueError(f"{canonical}: a {_WIDTH[size] * 8}-bit address has bits 0..{_WIDTH[size] * 8 - 1}")
        return Address(canonical, area, size, offset + bit // 8, offset * 8 + bit)
    return Address(canonical, area, size, offset)


def incomplete(text: str) -> bool:
    """``%I*``, ``%Q*``, ``%M*``: a location a configuration assigns later (VAR_CONFIG, or the tool: TwinCAT)."""
    return text.strip().endswith("*")


def type_problem(address: Address, type_name: str) -> str | None:
    """Why a variable of ``type_name`` cannot be located at ``address`` (None when it can)."""
    name = canonical_type_name(type_name)
    info = ELEMENTARY.get(name)
    if info is None or info.category == "string":
        return f"{article(type_name)} cannot be located at {address.text}: only elementary types other than STRING can"
    if address.bit is not None:
        return None if name == "BOOL" else f"{address.text} is a bit: only a BOOL can be located there"
    if name == "BOOL":
        return None  # its first byte, 0 or 1
    width = max(1, info.bits // 8)
    if width != address.width:
        return f"{address.text} has {address.width * 8} bits: {article(name)} has {info.bits}"
    return None


def same_location(text: str | None, address: Address) -> bool:
    """Does the address written ``text`` name exactly ``address`` (``%I0.1`` and ``%IX0.1`` do)? None: no address."""
    if text is None:
        return False
    try:
        other = parse_address(text)
    except ValueError:
        return False
    return (other.area, other.offset, other.bit, other.width) == (
        address.area,
        address.offset,
        address.bit,
        address.width,
    )


#: Partial access (IEC 61131-3 ed. 3, 6.5.6): ``w.%X3`` a bit, ``.%B1`` a byte, ``.%W0`` a word, ``.%D1`` a double
#: word, ``.%L0`` a long word of an ANY_BIT variable, numbered from the least significant; the type of each part.
PARTS = {"X": (1, "BOOL"), "B": (8, "BYTE"), "W": (16, "WORD"), "D": (32, "DWORD"), "L": (64, "LWORD")}
#: How messages name the parts of each width.
PART_NAMES = {1: "bits", 8: "bytes", 16: "words", 32: "double words", 64: "long words"}
_PART = re.compile(r"%([XBWDL])(\d+)\Z", re.IGNORECASE)


def partial_access(member: str) -> tuple[int, int] | None:
    """``3`` or ``%X3`` -> (1, 3): bit 3; ``%B1`` -> (8, 1): bits 8..15; None for a name (a field or pin)."""
    if member.isdigit():
        return 1, int(member)
    match = _PART.match(member)
    if match is None:
        return None
    return PARTS[match.group(1).upper()][0], int(match.group(2))


def part_type(width: int) -> str:
    """The type of a part ``width`` bits wide: BOOL, BYTE, WORD, DWORD or LWORD."""
    return next(name for bits, name in PARTS.values() if bits == width)
