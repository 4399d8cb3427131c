"""Resolved types and the IEC compatibility rules the checker applies (spec §2, FUN-02, ST-20..26).

Untyped literals have their own types (``UntypedInt``/``UntypedReal``, ANY_INT and
ANY_REAL of IEC 61131-3 ed. 3, 6.4.2) until their context fixes them (st/context.py).
Lossless widening (SINT -> INT, UINT -> DINT, REAL -> LREAL ...) is accepted with a
warning; ``lub`` is the smallest type two types widen to. Anything else needs an
explicit ``*_TO_*`` conversion.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from math import isfinite
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
    #: CODESYS REFERENCE TO: the checker reads and writes through it (``r := 5`` writes the target); REF= binds it
    implicit: bool = False

    @property
    def name(self) -> str:  # type: ignore[override]
        return f"{'REFERENCE TO' if self.implicit else 'REF_TO'} {self.target}"


@dataclass(eq=False)
class StructType(Type):
    name: str
    fields: dict[str, tuple[str, Type]] = field(default_factory=dict)  # upper name -> (name as written, type)
    pack_mode: int | None = None  # CODESYS's largest member alignment (1, 2, 4, 8), None: natural (ir/byte_layout.py)


@dataclass(eq=False)
class EnumType(Type):
    name: str
    values: dict[str, tuple[str, int]] = field(default_factory=dict)  # upper name -> (name as written, value)
    base: str = "INT"  # the integer type it is stored as (IEC ed. 3, CODESYS: INT unless the declaration names one)


@dataclass(eq=False)
class FbType(Type):
    """An FB instance's type: a user FUNCTION_BLOCK / PROGRAM (``pou``) or a standard FB (``std``)."""

    name: str
    pou: Any = None
    std: Any = None


@dataclass(frozen=True)
class InterfaceType(Type):
    """A variable of an INTERFACE's type: a reference to an instance of an FB implementing it, or NULL
    (st/interfaces.py); ``info`` is the interface's PouInfo (kind INTERFACE)."""

    name: str
    info: Any = None


@dataclass(frozen=True)
class UntypedInt(Type):
    """An integer literal, or an expression of integer literals only; ``value`` when it is known exactly."""

    value: int | None = None
    name: str = "ANY_INT literal"


@dataclass(frozen=True)
class UntypedReal(Type):
    """A real literal, or an expression of literals with a real among them."""

    value: float | None = None
    name: str = "ANY_REAL literal"


UNTYPED = (UntypedInt, UntypedReal)


class _Error(Type):
    """The type of an expression that already produced an error: compatible with everything (no cascades)."""

    name = "<error>"


class _Void(Type):
    name = "no value"


class NullType(Type):
    """The type of ``NULL`` (IEC 61131-3 ed. 3): the reference to nothing, which any reference type takes."""

    name = "NULL"


ERROR = _Error()
VOID = _Void()
NULL = NullType()
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


#: CODESYS's ``ExpressionResult`` (library Analyzation), the element type of the SFC flag
#: ``SFCErrorAnalyzationTable`` (docs/sfc.md): one part of a transition condition that holds the transition.
#: Built in, so a chart declares the flag as in CODESYS; a user TYPE of the same name takes precedence.
EXPRESSION_RESULT = "EXPRESSIONRESULT"


@functools.cache  # one type: StructType compares by identity
def expression_result() -> StructType:
    string = StringType(False)
    return StructType(
        "ExpressionResult",
        {
            "NAME": ("name", string),
            "ADDRESS": ("address", string),
            "COMMENT": ("comment", string),
            "VALUE": ("value", BOOL),
            "FAILED": ("failed", BOOL),
        },
    )


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


def literal_fits(t: Type, value: int | float | None) -> bool:
    """Can the literal value be stored in ``t`` exactly as written (integers) or within its range (reals)?"""
    if value is None or not isinstance(t, Elementary):
        return True
    if t.category == "real":
        return isfinite(value) and (t.name == "LREAL" or abs(value) <= _REAL_MAX)
    if isinstance(value, float):
        return False
    lo, hi = t.info.min, t.info.max
    return lo is None or lo <= value <= hi


_REAL_MAX = 3.4028235677973366e38  # the largest finite binary32 value (a larger literal would become inf)


def takes_literal(target: Type, literal: Type) -> bool:
    """May an untyped literal of this kind become a ``target`` (whatever its value)? An integer literal may become any
    integer, bit string or real type (and BOOL, when it is 0 or 1); a real literal only a real type."""
    if not isinstance(target, Elementary):
        return False
    if isinstance(literal, UntypedInt):
        return target.category in ("int", "bits", "real") or (target.category == "bool" and literal.value in (0, 1))
    return isinstance(literal, UntypedReal) and target.category == "real"


#: The project's type rules while it is checked and lowered (Project.typing): "iec", or "codesys" for CODESYS V3's
#: implicit conversions and arithmetic on bit strings (docs/st.md "CODESYS typing"). Set by ``typing_rules``.
_TYPING: ContextVar[str] = ContextVar("typing", default="iec")


@contextmanager
def typing_rules(typing: str) -> Iterator[None]:
    """Check (and lower) under the project's type rules: the rules below read them."""
    token = _TYPING.set(typing)
    try:
        yield
    finally:
        _TYPING.reset(token)


def moves_a_pointer(t: Type) -> bool:
    """Whether ``p + n`` / ``p - n`` may take ``n`` of this type: an integer (TYP-43) or a bit string wider than BOOL,
    which CODESYS adds to an address as the unsigned number it is (OSCAT: ``ADR(str) + INT_TO_DWORD(pos - 1)``)."""
    return in_family(t, "ANY_INT") or category(t) == "bits"


#: The numbers that hold a pointer's address under CODESYS typing: the unsigned ones of at least the 32 bits of the
#: target LadderLab computes as (SIZEOF of a pointer is 4, ir/byte_layout.py), as CODESYS assigns a POINTER to and
#: from a DWORD on a 32-bit target (an LWORD holds it too); a narrower or signed one would cut or sign it.
ADDRESS_NUMBERS = frozenset({"DWORD", "LWORD", "UDINT", "ULINT"})


def holds_address(number: Type, pointer: Type) -> bool:
    """CODESYS typing: whether ``number`` and ``pointer`` meet as an address and a pointer (``dw := pt``,
    ``pt := dw``, ``pt < dw``): a POINTER TO / REF_TO (no REFERENCE TO, which stands for its target) and an
    unsigned number of ``ADDRESS_NUMBERS``."""
    return (
        isinstance(pointer, PointerType)
        and not pointer.implicit
        and isinstance(number, Elementary)
        and address_number(number.name)
    )


def address_number(name: str) -> bool:
    """Whether the elementary type ``name`` holds a pointer's address as a number (CODESYS typing only)."""
    return codesys_typing() and name in ADDRESS_NUMBERS


def codesys_typing() -> bool:
    """Whether the project being checked uses CODESYS V3's type rules."""
    return _TYPING.get() == "codesys"


def real_from_integer(value: Type) -> bool:
    """Whether ``value`` is an integer or bit string that CODESYS typing gives where a REAL or LREAL is computed (SQRT,
    EXPT's base, ``**``: CODESYS takes "any numeric basic data type" there and returns a REAL or LREAL). It is
    converted to LREAL, which holds every 32-bit value exactly, as TwinCAT documents for EXPT ("return type is always
    LREAL")."""
    return codesys_typing() and isinstance(value, Elementary) and value.category in ("int", "bits")


def _widens(source: Elementary, target: Elementary) -> bool:
    return _widens_name(source.name, target.name, codesys_typing())


#: CODESYS computes a bit string as the unsigned integer of its width (BYTE as USINT ...).
UNSIGNED_OF_BITS = dict(zip(_BITS, _UNSIGNED))


@functools.cache
def _widens_name(s: str, d: str, codesys: bool = False) -> bool:
    for chain in (_SIGNED, _UNSIGNED, _BITS):
        if s in chain and d in chain:
            return chain.index(s) < chain.index(d)
    if s in _UNSIGNED and d in _SIGNED:
        return _UNSIGNED.index(s) < _SIGNED.index(d)
    if codesys:
        # CODESYS V3: a bit string is the unsigned integer of its width; every integer becomes a REAL or LREAL
        if s in _BITS:
            return UNSIGNED_OF_BITS[s] == d or _widens_name(UNSIGNED_OF_BITS[s], d, True)
        if s in _UNSIGNED and d in _BITS:
            return _UNSIGNED.index(s) <= _BITS.index(d)
        if d in ("REAL", "LREAL") and (s in _SIGNED or s in _UNSIGNED):
            return True
    return s == "REAL" and d == "LREAL"  # integer -> REAL always needs a conversion (ST-20)


def counts(t: Type) -> bool:
    """Whether ``t`` may index an array or select a CASE branch: an integer (ANY_INT), or under CODESYS typing also
    a bit string (its value as the unsigned integer of its width)."""
    return in_family(t, "ANY_INT") or (codesys_typing() and category(t) == "bits")


def narrows(target: Type, source: Type) -> bool:
    """CODESYS typing: an integer or bit string stored in a narrower (or differently signed) one, or an LREAL in a
    REAL: accepted with a warning, the value cut to the target's bits (LREAL: rounded to binary32) as CODESYS does."""
    if not (codesys_typing() and isinstance(target, Elementary) and isinstance(source, Elementary)):
        return False
    integers = ("int", "bits")
    if target.category in integers and source.category in integers:
        return True
    return target.name == "REAL" and source.name == "LREAL"


# Candidates for the smallest common type, smallest first (of one width only one can fit both).
_WIDENING_ORDER = ("SINT", "USINT", "INT", "UINT", "DINT", "UDINT", "LINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD")
_WIDENING_ORDER += ("REAL", "LREAL")


@functools.cache
def _lub_name(a: str, b: str, codesys: bool = False) -> str | None:
    if a == b:
        return a
    if codesys and a in _BITS and b in _BITS:  # two bit strings stay a bit string
        return _lub_name(a, b)
    for name in _WIDENING_ORDER:
        if (name == a or _widens_name(a, name, codesys)) and (name == b or _widens_name(b, name, codesys)):
            return name
    return None


def lub(a: Type, b: Type) -> Type | None:
    """The smallest type both ``a`` and ``b`` widen to without loss (INT, UINT -> DINT); None when there is none.

    ``a`` itself when the two are the same type (STRINGs of any length, one structure ...)."""
    if same(a, b):
        return b if a is ERROR else a
    if isinstance(a, Elementary) and isinstance(b, Elementary):
        name = _lub_name(a.name, b.name, codesys_typing())
        return None if name is None else (a if name == a.name else b if name == b.name else Elementary(name))
    return None


def same(a: Type, b: Type) -> bool:
    if a is b or a is ERROR or b is ERROR:
        return True
    if isinstance(a, StringType) and isinstance(b, StringType):
        return a.wide == b.wide
    if isinstance(a, PointerType | NullType) and isinstance(b, PointerType | NullType):
        if isinstance(a, NullType) or isinstance(b, NullType):
            return True
        return same(a.target, b.target) or (isinstance(a.target, Elementary) and a.target.name == "BYTE")
    if isinstance(a, FbType) and isinstance(b, FbType):  # one user FB POU, or one standard FB (each use resolves anew)
        return a.pou is b.pou if a.pou is not None else b.pou is None and a.std is b.std
    return a == b if not isinstance(a, (StructType, EnumType, FbType)) else a is b


def assignable(target: Type, source: Type) -> str | None:
    """None when ``source`` may be stored in ``target``; "widen" for a lossless implicit conversion; "narrow" for a
    lossy one CODESYS typing accepts (``narrows``); else "error"."""
    if same(target, source):
        return None
    if isinstance(target, InterfaceType):  # an instance (or interface) that implements it, or NULL
        return None if isinstance(source, NullType) or implements(source, target) else "error"
    if isinstance(source, UNTYPED):
        if null_literal(target, source):
            return None
        return None if takes_literal(target, source) and literal_fits(target, source.value) else "error"
    if isinstance(target, Elementary) and isinstance(source, Elementary) and _widens(source, target):
        return "widen"
    if holds_address(target, source) or holds_address(source, target):
        return None  # an address as a number and back (docs/st.md, "A pointer as a number")
    if isinstance(target, PointerType) and isinstance(source, PointerType):
        if isinstance(target.target, FbType) and isinstance(source.target, FbType):  # no bytes to see: up the tree
            return None if derived(target.target, source.target) else "error"
        return "widen"
    return "narrow" if narrows(target, source) else "error"


def null_literal(target: Type, source: Type) -> bool:
    """``p := 0`` under CODESYS typing: the literal 0 stored in a POINTER TO / REF_TO is NULL (CODESYS's null
    address, as ``p <> 0`` tests it); IEC 61131-3 ed. 3 stores only NULL in a reference (6.4.4.10.2)."""
    return zero_for_null(target, source) and codesys_typing()


#: Why IEC typing refuses the literal 0 where a POINTER TO / REF_TO is stored or compared (ed. 3 6.4.4.10.2).
NULL_NOT_ZERO = "under IEC typing a reference to no variable is NULL (CODESYS typing also takes 0)"


def zero_for_null(target: Type, source: Type) -> bool:
    """The literal 0 written for a POINTER TO / REF_TO (not a REFERENCE TO, whose 0 is its target's value)."""
    zero = isinstance(source, UntypedInt) and source.value == 0
    return zero and isinstance(target, PointerType) and not target.implicit


def common(a: Type, b: Type) -> tuple[Type, str | None]:
    """The type two operands are combined in before any context: (type, None | "widen" | "error").

    A typed operand decides over an untyped one (whether the literal fits is decided when the context has fixed the
    type, st/context.py); two typed ones combine in their ``lub``; two untyped ones stay untyped."""
    if a is ERROR or b is ERROR:
        return (b if a is ERROR else a), None
    if isinstance(a, UNTYPED) and isinstance(b, UNTYPED):
        return untyped_pair(a, b), None
    if isinstance(a, UNTYPED):
        return b, None if takes_literal(b, a) else "error"
    if isinstance(b, UNTYPED):
        return a, None if takes_literal(a, b) else "error"
    if same(a, b):
        return a, None
    combined = lub(a, b)
    return (a, "error") if combined is None else (combined, "widen")


def untyped_pair(a: Type, b: Type) -> Type:
    """Two untyped operands combined (without a value: the operation's value is worked out by the caller)."""
    return UntypedInt() if isinstance(a, UntypedInt) and isinstance(b, UntypedInt) else UntypedReal()


_DEFAULT_INTEGERS = (INT, Elementary("DINT"), Elementary("LINT"), Elementary("ULINT"))
_DEFAULT_BITS = tuple(Elementary(name) for name in _BITS)
LREAL = Elementary("LREAL")


def concrete(t: Type, family: str | None = None) -> Type:
    """The type an untyped literal (expression) takes without any context: INT for integers (ST-24; DINT, LINT or
    ULINT when the value needs it), LREAL for reals; within ``family`` (ANY_REAL: LREAL, ANY_BIT: the smallest bit
    string) when a generic function asks."""
    if isinstance(t, UntypedInt):
        if family == "ANY_REAL":
            return LREAL
        candidates = _DEFAULT_BITS if family == "ANY_BIT" else _DEFAULT_INTEGERS
        return next((c for c in candidates if literal_fits(c, t.value)), candidates[-1])
    if isinstance(t, UntypedReal):
        return LREAL
    return t


def conversion_hint(target: Type, source: Type) -> str:
    """``' without a conversion such as REAL_TO_INT'`` when both are elementary."""
    if isinstance(target, (Elementary, StringType)) and isinstance(source, (Elementary, StringType)):
        return f" without a conversion such as {source.name}_TO_{target.name}"
    return ""


def derived(base: Type, value: Type) -> bool:
    """An instance of ``value`` stands for one of ``base``: a user function block that EXTENDS ``base``'s
    (st/inheritance.py), reached through a base-typed in-out, pointer or reference, which dispatches its methods
    and properties to the instance's own FB."""
    return (
        isinstance(base, FbType)
        and isinstance(value, FbType)
        and base.pou is not None
        and value.pou is not None
        and value.pou.derives_from(base.pou)
    )


def implements(source: Type, interface: InterfaceType) -> bool:
    """Whether an instance of ``source`` (an FB, or any implementer of an interface) implements ``interface``."""
    if isinstance(source, FbType) and source.pou is not None:
        return source.pou.implements(interface.info)
    if isinstance(source, InterfaceType):
        return source.info.implements(interface.info)
    return False
