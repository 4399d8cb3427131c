"""IR types: what the engine needs to lay out, initialise, wrap and check a value.

The checker's resolved types are lowered to these; the IR knows nothing of ST
syntax, so LD and FBD lowering produce the same types.
"""

from __future__ import annotations

import functools
import threading
from dataclasses import dataclass

from ..iec.elementary import DEFAULT_STRING_LENGTH, ELEMENTARY, ElementaryType


@dataclass(frozen=True)
class Elementary:
    """An elementary type by canonical name (``INT``, ``TIME_OF_DAY``...); ``length`` for STRING[n]; ``wide`` for a
    WSTRING, which the value model holds as a STRING (a Python str) but CODESYS lays out in 2 bytes a character."""

    name: str
    length: int | None = None
    wide: bool = False

    @property
    def info(self) -> ElementaryType:
        return ELEMENTARY[self.name]

    @property
    def max_length(self) -> int:
        return self.length if self.length is not None else DEFAULT_STRING_LENGTH


@dataclass(frozen=True)
class Subrange:
    """An integer type restricted to ``low..high``; a store outside it is a runtime error."""

    base: Elementary
    low: int
    high: int


@dataclass(frozen=True)
class Enum:
    """Enumeration values are ints; ``values`` maps each name, spelled as declared (online views and test reports
    show it so; lookups ignore case), to its int, in declaration order; ``base`` is the integer type CODESYS stores
    it as (its SIZEOF)."""

    name: str
    values: tuple[tuple[str, int], ...]
    base: str = "INT"

    def literal(self, value: object) -> str:
        """``TCOLOR#Red``: the value as its IEC literal, the name spelled as declared (``TCOLOR#7`` for a number
        no name has, which an online write of a plain number can leave)."""
        name = next((n for n, number in self.values if number == value), None)
        return f"{self.name}#{name if name is not None else value}"


@dataclass(frozen=True)
class Array:
    element: IrType
    dims: tuple[tuple[int, int], ...]


@dataclass(frozen=True)
class StructField:
    name: str
    type: IrType
    initial: object | None = None


@dataclass(frozen=True, eq=False, repr=False)
class Struct:
    """A STRUCT. One that points to itself (a linked list's ``next : POINTER TO Node``) holds itself among its
    fields' Reference targets, so equality, hashing and repr stop at the cycle (``_comparing``)."""

    name: str
    fields: tuple[StructField, ...]
    pack_mode: int | None = None  # CODESYS's {attribute 'pack_mode'}: 1, 2, 4 or 8; None: the target's default

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if not isinstance(other, Struct) or (self.name, self.pack_mode) != (other.name, other.pack_mode):
            return False
        pair, comparing = (id(self), id(other)), _comparing()
        if pair in comparing:  # met again inside its own fields: equal unless another field differs
            return True
        comparing.add(pair)
        try:
            return self.fields == other.fields
        finally:
            comparing.discard(pair)

    def __hash__(self) -> int:
        return hash((self.name, self.pack_mode))  # not the fields: a self-pointing one gets them after it exists

    def __repr__(self) -> str:
        return f"Struct({self.name!r}, {[f.name for f in self.fields]})"


_COMPARISONS = threading.local()


def _comparing() -> set[tuple[int, int]]:
    """The pairs of Structs (ids) this thread is comparing, so a STRUCT that points to itself compares without
    looping (the server builds projects in several threads)."""
    pairs: set[tuple[int, int]] | None = getattr(_COMPARISONS, "pairs", None)
    if pairs is None:
        pairs = _COMPARISONS.pairs = set()
    return pairs


@dataclass(frozen=True)
class FbInstance:
    """An instance of a function block: a user FB POU or a standard FB (``TON``, ``CTU_DINT``...)."""

    fb: str


@functools.lru_cache(maxsize=4096)
def fb_instance(fb: str) -> FbInstance:
    """``FbInstance(fb)``, one object per FB name (immutable): a 50,000-network diagram declares thousands of
    instances of each FB, and each object is one more for the build's memory and collections (issue 27)."""
    return FbInstance(fb)


@dataclass(frozen=True)
class Reference:
    """``REF_TO target`` (or CODESYS ``POINTER TO``): a reference to a variable of ``target``, or NULL.

    The engine holds it as an ``engine.codegen.runtime.Ref`` (the variable's container and key) or None; a
    dereference of NULL is a runtime error (docs/runtime.md)."""

    target: IrType


IrType = Elementary | Subrange | Enum | Array | Struct | FbInstance | Reference


def describe(ty: IrType) -> str:
    """IEC-like text of a type for messages and comments."""
    if isinstance(ty, Elementary):
        if ty.name == "STRING":
            name = "WSTRING" if ty.wide else "STRING"
            return f"{name}[{ty.length}]" if ty.length is not None else name
        return ty.name
    if isinstance(ty, Subrange):
        return f"{ty.base.name} ({ty.low}..{ty.high})"
    if isinstance(ty, Enum | Struct):
        return ty.name
    if isinstance(ty, Array):
        dims = ", ".join(f"{lo}..{hi}" for lo, hi in ty.dims)
        return f"ARRAY [{dims}] OF {describe(ty.element)}"
    if isinstance(ty, Reference):
        return f"REF_TO {describe(ty.target)}"
    return ty.fb


BOOL = Elementary("BOOL")
