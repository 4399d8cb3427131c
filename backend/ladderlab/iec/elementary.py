"""The IEC 61131-3 elementary types: one table used by the checker, the IR and the engine.

Value model (spec TYP-03): integers and bit strings are Python ints wrapped to
their width; REAL is a float rounded to IEEE float32 on every store, LREAL a
float; TIME is signed 32-bit milliseconds; TIME_OF_DAY is milliseconds since
midnight; DATE and DATE_AND_TIME are milliseconds since 1970-01-01 00:00:00
(DATE at day resolution); STRING is a str of at most its declared length.
The IEC 3rd edition long forms LTIME, LTIME_OF_DAY, LDATE and LDATE_AND_TIME are
the same quantities in 64-bit integer nanoseconds (``unit_ns`` says which unit a
time-like type counts in).
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
    #: Nanoseconds per stored unit of a time-like type: 1_000_000 (ms) for TIME and the dates, 1 for the L forms.
    unit_ns: int = 0

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
    unit_ns = 1_000_000 if category in ("time", "date", "tod", "dt") else 0
    return ElementaryType(name, category, bits, signed, default, unit_ns)


def _long(name: str, category: Category, signed: bool = False) -> ElementaryType:
    """An IEC 3rd edition long time type (LTIME, LDATE, ...): 64-bit nanoseconds."""
    return ElementaryType(name, category, 64, signed, 0, 1)


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
        _long("LTIME", "time", signed=True),
        _long("LDATE", "date"),
        _long("LTIME_OF_DAY", "tod"),
        _long("LDATE_AND_TIME", "dt"),
        _t("STRING", "string", default=""),
    )
}

#: Short spellings accepted wherever a type name is (TOD, DT) - spec TYP-01; LTOD, LDT (IEC 3rd edition).
ALIASES: dict[str, str] = {"TOD": "TIME_OF_DAY", "DT": "DATE_AND_TIME", "LTOD": "LTIME_OF_DAY", "LDT": "LDATE_AND_TIME"}

#: The IEC 3rd edition long time types and the 2nd edition type each is the nanosecond form of.
LONG_TIME_TYPES = {"LTIME": "TIME", "LDATE": "DATE", "LTIME_OF_DAY": "TIME_OF_DAY", "LDATE_AND_TIME": "DATE_AND_TIME"}
SHORT_TO_LONG = {short: long for long, short in LONG_TIME_TYPES.items()}

#: Nanoseconds in a day: the time of day wraps at it, a date is a multiple of it.
NS_PER_DAY = 86_400_000_000_000

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
GENERIC["ANY_DATE"] = frozenset(n for n, t in ELEMENTARY.items() if t.category in ("date", "tod", "dt"))
GENERIC["ANY_DURATION"] = frozenset({"TIME", "LTIME"})
GENERIC["ANY_MAGNITUDE"] = GENERIC["ANY_NUM"] | GENERIC["ANY_DURATION"]
GENERIC["ANY_ELEMENTARY"] = frozenset(ELEMENTARY)
GENERIC["ANY"] = GENERIC["ANY_ELEMENTARY"]


def canonical_type_name(name: str) -> str:
    """Upper-case name with TOD/DT expanded; unknown names are returned upper-cased."""
    upper = name.upper()
    return ALIASES.get(upper, upper)


def elementary(name: str) -> ElementaryType | None:
    return ELEMENTARY.get(canonical_type_name(name))


def per_day(elem: ElementaryType) -> int:
    """Stored units of a time-like type in one day (86_400_000 ms, or NS_PER_DAY for the L forms)."""
    return NS_PER_DAY // elem.unit_ns
