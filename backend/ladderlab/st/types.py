"""Resolved types and the IEC compatibility rules the checker applies (spec §2, FUN-02, ST-20..26).

Untyped literals have their own types (``UntypedInt``/``UntypedReal``) that adopt
the type of the other operand or of the assignment target (LEX-26, FUN-02).
Lossless widening (SINT -> INT, INT -> REAL, REAL -> LREAL ...) is accepted with a
warning; anything else needs an explicit ``*_TO_*`` conversion.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Any

from ..iec.elementary import ELEMENTARY, GENERIC, STRING_TYPES, ElementaryType, canonical_type_name


class Type:
    """Base of every resolved type; ``name`` is what messages show."""

    name: str = "?"

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True, eq=True)
class Elementary(Type):
    name: str

    @property
    def info(self) -> ElementaryType:
        return ELEMENTARY[self.name]

    @property
    def category(self) -> str:
        return self.info.category


@dataclass(frozen=True, eq=True)
class StringType(Type):
    wide: bool = False
    length: int | None = None

    @property
    def name(self) -> str:  # type: ignore[override]
        return "WSTRING" if self.wide else "STRING"


@dataclass(frozen=True, eq=True)
class ArrayType(Type):
    dims: tuple[tuple[int, int] | None, ...]
    element: Type

    @property
    def name(self) -> str:  # type: ignore[override]
        ranges = ", ".join("*" if d is None else f"{d[0]}..{d[1]}" for d in self.dims)
        return f"ARRAY [{ranges}] OF {self.element}"


@dataclass(frozen=True, eq=True)
class PointerType(Type):
    target: Type

    @property
    def name(self) -> str:  # type: ignore[override]
        return f"REF_TO {self.target}"


@dataclass(eq=False)
class StructType(Type):
    name: str
    fields: dict[str, tuple[str, Type]] = field(default_factory=dict)  # upper name -> (name as written, type)


@dataclass(eq=False)
class EnumType(Type):
    name: str
    values: dict[str, tuple[str, int]] = field(default_factory=dict)  # upper name -> (name as written, value)


@dataclass(eq=False)
class FbType(Type):
    """An FB instance's type: a user FUNCTION_BLOCK / PROGRAM (``pou``) or a standard FB (``std``)."""

    name: str
    pou: Any = None
    std: Any = None


@dataclass(frozen=True)
class UntypedInt(Type):
    value: int | None = None
    name: str = "ANY_INT literal"


@dataclass(frozen=True)
class UntypedReal(Type):
    name: str = "ANY_REAL literal"


class _Error(Type):
    """The type of an expression that already produced an error: compatible with everything (no cascades)."""

    name = "<error>"


class _Void(Type):
    name = "no value"


ERROR = _Error()
VOID = _Void()
BOOL = Elementary("BOOL")
INT = Elementary("INT")
TIME = Elementary("TIME")

_SIGNED = ["SINT", "INT", "DINT", "LINT"]
_UNSIGNED = ["USINT", "UINT", "UDINT", "ULINT"]
_BITS = ["BYTE", "WORD", "DWORD", "LWORD"]


@functools.cache  # types are immutable; asked for every pin of every call checked
def elementary(name: str) -> Type | None:
    canonical = canonical_type_name(name)
    if canonical in STRING_TYPES:
        return StringType(canonical == "WSTRING")
    return Elementary(canonical) if canonical in ELEMENTARY else None


def category(t: Type) -> str | None:
    if isinstance(t, Elementary):
        return t.category
    if isinstance(t, StringType):
        return "string"
    if isinstance(t, UntypedInt):
        return "int"
    if isinstance(t, UntypedReal):
        return "real"
    return None


def in_family(t: Type, family: str) -> bool:
    """Is ``t`` a member of the generic family (ANY_NUM ...) or equal to the named type?"""
    if t is ERROR or family == "ANY":
        return True
    if isinstance(t, UntypedInt):
        return family in ("ANY_INT", "ANY_NUM", "ANY_MAGNITUDE", "ANY_ELEMENTARY", "ANY_REAL", "ANY_BIT")
    if isinstance(t, UntypedReal):
        return family in ("ANY_REAL", "ANY_NUM", "ANY_MAGNITUDE", "ANY_ELEMENTARY")
    if isinstance(t, StringType):
        return family in ("ANY_STRING", "ANY_ELEMENTARY", "STRING" if not t.wide else "WSTRING")
    if isinstance(t, Elementary):
        members = GENERIC.get(family)
        return t.name in members if members is not None else t.name == canonical_type_name(family)
    return False


def literal_fits(t: Type, value: int | None) -> bool:
    if value is None or not isinstance(t, Elementary):
        return True
    lo, hi = t.info.min, t.info.max
    return lo is None or lo <= value <= hi


def _widens(source: Elementary, target: Elementary) -> bool:
    s, d = source.name, target.name
    for chain in (_SIGNED, _UNSIGNED, _BITS):
        if s in chain and d in chain:
            return chain.index(s) < chain.index(d)
    if s in _UNSIGNED and d in _SIGNED:
        return _UNSIGNED.index(s) < _SIGNED.index(d)
    return s == "REAL" and d == "LREAL"  # integer -> REAL always needs a conversion (ST-20)


def same(a: Type, b: Type) -> bool:
    if a is b or a is ERROR or b is ERROR:
        return True
    if isinstance(a, StringType) and isinstance(b, StringType):
        return a.wide == b.wide
    if isinstance(a, PointerType) and isinstance(b, PointerType):
        return same(a.target, b.target) or (isinstance(a.target, Elementary) and a.target.name == "BYTE")
    return a == b if not isinstance(a, (StructType, EnumType, FbType)) else a is b


def assignable(target: Type, source: Type) -> str | None:
    """None when ``source`` may be stored in ``target``; "widen" for a lossless implicit conversion; else "error"."""
    if same(target, source):
        return None
    if isinstance(source, UntypedInt):
        if isinstance(target, Elementary) and target.category in ("int", "bits", "real", "bool"):
            if target.category == "bool" and source.value not in (0, 1, None):
                return "error"
            return None if literal_fits(target, source.value) else "error"
        return "error"
    if isinstance(source, UntypedReal):
        return None if isinstance(target, Elementary) and target.category == "real" else "error"
    if isinstance(target, Elementary) and isinstance(source, Elementary) and _widens(source, target):
        return "widen"
    if isinstance(target, PointerType) and isinstance(source, PointerType):
        return "widen"
    return "error"


def common(a: Type, b: Type) -> tuple[Type, str | None]:
    """The type two operands are combined in: (type, None | "widen" | "error")."""
    if a is ERROR or b is ERROR:
        return (b if a is ERROR else a), None
    if isinstance(a, (UntypedInt, UntypedReal)) and isinstance(b, (UntypedInt, UntypedReal)):
        return (a if isinstance(a, UntypedInt) and isinstance(b, UntypedInt) else UntypedReal()), None
    if isinstance(a, (UntypedInt, UntypedReal)):
        return b, assignable(b, a)
    if isinstance(b, (UntypedInt, UntypedReal)):
        return a, assignable(a, b)
    if same(a, b):
        return a, None
    if assignable(a, b) == "widen":
        return a, "widen"
    if assignable(b, a) == "widen":
        return b, "widen"
    return a, "error"


def concrete(t: Type) -> Type:
    """An untyped literal standing alone takes the IEC default: INT for integers (ST-24), LREAL for reals."""
    if isinstance(t, UntypedInt):
        return Elementary("DINT") if not literal_fits(INT, t.value) else INT
    if isinstance(t, UntypedReal):
        return Elementary("LREAL")
    return t


def conversion_hint(target: Type, source: Type) -> str:
    """``' without a conversion such as REAL_TO_INT'`` when both are elementary."""
    if isinstance(target, (Elementary, StringType)) and isinstance(source, (Elementary, StringType)):
        return f" without a conversion such as {source.name}_TO_{target.name}"
    return ""
