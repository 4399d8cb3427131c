"""How a CODESYS PLC (x86/ARM: little-endian) lays a variable out in bytes, for pointers that see memory as another
type (``POINTER TO BYTE`` over a STRING, ``POINTER TO DWORD`` over a REAL). The engine reads and writes those bytes
from the value (engine/codegen/views.py); the specs here are what it is given.

A spec is ``("int", size, signed)`` for the integers and bit strings, ``("real", size)``, ``("bool",)`` (one byte),
``("string", n)`` (STRING[n]: n + 1 bytes, a NUL after the text), ``("array", count, element spec)`` (the elements
one after another; a multi-dimensional array is an array of arrays, the first dimension outermost) or
``("struct", name, size, alignment, ((member, offset, spec), ...))`` (a STRUCT: its members in declaration order
at CODESYS's natural alignment, padding bytes between and after them).
"""

from __future__ import annotations

from ..iec.values import article
from .types import Array, Elementary, Enum, IrType, Reference, Struct, Subrange, describe

Spec = tuple


def byte_layout(ty: IrType) -> Spec | str:
    """The spec of ``ty``, or why LadderLab cannot lay it out exactly as CODESYS does."""
    if isinstance(ty, Subrange):
        return byte_layout(ty.base)
    if isinstance(ty, Elementary):
        info = ty.info
        if info.category in ("int", "bits"):
            return ("int", info.bits // 8, info.signed) if info.bits > 1 else ("bool",)
        if info.category == "bool":
            return ("bool",)
        if info.category == "real":
            return ("real", info.bits // 8)
        if ty.name == "STRING":
            return ("string", ty.max_length)
        return f"a {describe(ty)} (its bytes in CODESYS are not the value LadderLab keeps)"
    if isinstance(ty, Array):
        spec = byte_layout(ty.element)
        if isinstance(spec, str):
            return spec
        for lo, hi in reversed(ty.dims):
            spec = ("array", hi - lo + 1, spec)
        return spec
    if isinstance(ty, Struct):
        return _struct_layout(ty)
    if isinstance(ty, Enum):
        return f"the enumeration {ty.name} (CODESYS stores it as its base type, INT unless it names another)"
    if isinstance(ty, Reference):
        return f"a {describe(ty)} (an address: 4 or 8 bytes depending on the target)"
    return f"a {describe(ty)} (it has no byte layout)"


def seen_layout(ty: IrType) -> Spec | str:
    """The spec of what a pointer of another type sees (``pt^``), or why it cannot: no STRUCT, whose members the
    generated code reaches on the STRUCT's own value, never on bytes decoded into a copy."""
    spec = element = byte_layout(ty)
    while isinstance(element, tuple) and element[0] == "array":
        element = element[2]
    if isinstance(element, tuple) and element[0] == "struct":
        return f"the STRUCT {element[1]} (a pointer of another type may see a STRUCT's bytes, not other bytes as one)"
    return spec


def _struct_layout(ty: Struct) -> Spec | str:
    """CODESYS's natural layout: each member at the next multiple of its alignment, the size a multiple of the
    largest one. It is the same on every x86/ARM target, 32- or 64-bit, unless a member is 8 bytes wide."""
    members, end, largest = [], 0, 1
    for field in ty.fields:
        spec = byte_layout(field.type)
        if isinstance(spec, str):
            return f"the STRUCT {ty.name}, whose member {field.name} is {spec}"
        align = _alignment(spec)
        if align == 8:
            return (
                f"the STRUCT {ty.name}, whose member {field.name} is {article(describe(field.type))} (CODESYS aligns "
                "8-byte members to 4 or 8 bytes depending on the target)"
            )
        end += -end % align
        members.append((field.name, end, spec))
        end += _spec_size(spec)
        largest = max(largest, align)
    return ("struct", ty.name, end + -end % largest, largest, tuple(members))


def _alignment(spec: Spec) -> int:
    """The alignment of a member (a STRUCT member lies at a multiple of it): a number's size, 1 for BOOL and
    STRING, an array's element's, a STRUCT's largest member's."""
    kind = spec[0]
    if kind in ("int", "real"):
        return spec[1]
    if kind == "array":
        return _alignment(spec[2])
    return spec[3] if kind == "struct" else 1


def _spec_size(spec: Spec) -> int:
    """How many bytes a variable laid out as ``spec`` takes."""
    kind = spec[0]
    if kind in ("int", "real"):
        return spec[1]
    if kind == "string":
        return spec[1] + 1
    if kind == "array":
        return spec[1] * _spec_size(spec[2])
    return spec[2] if kind == "struct" else 1
