"""The IEC 61131-3 elementary types: one table used by the checker, the IR and the engine.

Value model (spec TYP-03): integers and bit strings are Python ints wrapped to
their width; REAL is a float rounded to IEEE float32 on every store, LREAL a
float; TIME is signed 32-bit milliseconds; TIME_OF_DAY is milliseconds since
midnight; DATE and DATE_AND_TIME are milliseconds since 1970-01-01 00:00:00
(DATE at day resolution); STRING is a str of at most its declared length.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Category = Literal["bool", "int", "bits", "real", "time", "date", "tod", "dt", "string"]


@dataclass(frozen=True)
class ElementaryType:
    name: str
    category: Category
    bits: int = 0
    signed: bool = False
    default: object = 0

    @property
    def min(self) -> int | None:
        if self.category in ("int", "bits", "time", "bool"):
            return -(1 << (self.bits - 1)) if self.signed else 0
        return None

    @property
    def max(self) -> int | None:
        if self.category in ("int", "bits", "time", "bool"):
            return (1 << (self.bits - 1)) - 1 if self.signed else (1 << self.bits) - 1
        return None


def _t(name: str, category: Category, bits: int = 0, signed: bool = False, default: object = 0) -> ElementaryType:
    return ElementaryType(name, category, bits, signed, default)


ELEMENTARY: dict[str, ElementaryType] = {
    t.name: t
    for t in (
        _t("BOOL", "bool", 1, default=False),
        _t("SINT", "int", 8, True),
        _t("INT", "int", 16, True),
        _t("DINT", "int", 32, True),
        _t("LINT", "int", 64, True),
        _t("USINT", "int", 8),
        _t("UINT", "int", 16),
        _t("UDINT", "int", 32),
        _t("ULINT", "int", 64),
        _t("BYTE", "bits", 8),
        _t("WORD", "bits", 16),
        _t("DWORD", "bits", 32),
        _t("LWORD", "bits", 64),
        _t("REAL", "real", 32, True, 0.0),
        _t("LREAL", "real", 64, True, 0.0),
        _t("TIME", "time", 32, True),
        _t("DATE", "date", 64),
        _t("TIME_OF_DAY", "tod", 32),
        _t("DATE_AND_TIME", "dt", 64),
        _t("STRING", "string", default=""),
    )
}

#: Short spellings accepted wherever a type name is (TOD, DT) - spec TYP-01.
ALIASES: dict[str, str] = {"TOD": "TIME_OF_DAY", "DT": "DATE_AND_TIME"}

#: The character string types: STRING (one byte a character) and WSTRING (two); both take a length, ``[n]``.
STRING_TYPES: tuple[str, ...] = ("STRING", "WSTRING")

#: Default length of STRING when declared without [n] (IEC default; spec TYP-04 allows up to 255, the
#: default of ``limits.STRING_LENGTH``).
DEFAULT_STRING_LENGTH = 80

#: Generic type families used only in standard function signatures (spec TYP-06/07).
GENERIC: dict[str, frozenset[str]] = {}
GENERIC["ANY_INT"] = frozenset(n for n, t in ELEMENTARY.items() if t.category == "int")
GENERIC["ANY_REAL"] = frozenset({"REAL", "LREAL"})
GENERIC["ANY_NUM"] = GENERIC["ANY_INT"] | GENERIC["ANY_REAL"]
GENERIC["ANY_BIT"] = frozenset({"BOOL", "BYTE", "WORD", "DWORD", "LWORD"})
GENERIC["ANY_DATE"] = frozenset({"DATE", "TIME_OF_DAY", "DATE_AND_TIME"})
GENERIC["ANY_MAGNITUDE"] = GENERIC["ANY_NUM"] | {"TIME"}
GENERIC["ANY_ELEMENTARY"] = frozenset(ELEMENTARY)
GENERIC["ANY"] = GENERIC["ANY_ELEMENTARY"]


def canonical_type_name(name: str) -> str:
    """Upper-case name with TOD/DT expanded; unknown names are returned upper-cased."""
    upper = name.upper()
    return ALIASES.get(upper, upper)


def elementary(name: str) -> ElementaryType | None:
    return ELEMENTARY.get(canonical_type_name(name))
