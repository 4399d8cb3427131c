"""How a CODESYS PLC (x86/ARM: little-endian) lays a variable out in bytes, for pointers that see memory as another
type (``POINTER TO BYTE`` over a STRING, ``POINTER TO DWORD`` over a REAL). The engine reads and writes those bytes
from the value (engine/codegen/views.py); the specs here are what it is given.

A spec is ``("int", size, signed)`` for the integers and bit strings, ``("real", size)``, ``("bool",)`` (one byte),
``("string", n)`` (STRING[n]: n + 1 bytes, a NUL after the text) or ``("array", count, element spec)`` (the elements
one after another; a multi-dimensional array is an array of arrays, the first dimension outermost).
"""

from __future__ import annotations

from .types import Array, Elementary, IrType, Struct, Subrange, describe

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
        return f"the STRUCT {ty.name} (CODESYS aligns its members to their size, which LadderLab does not lay out)"
    return f"a {describe(ty)} (it has no byte layout)"
