"""CODESYS typing: the numbers a DATE or a DT stands for (ir/codesys_dates.py rewrites the conversions to these).

CODESYS stores DATE and DT "as DWORD", seconds since 1970-01-01 ("Conversion: DATE, DT, TOD": "The resolution for
DATE is 1 day. The resolution for DT is 1 second. Both begin at January 1, 1970"); LadderLab holds both in ms. So
``DATE_TO_DWORD(D#2002-08-18)`` is 16#3D5EE380 (1029628800 s) there, and ``DWORD_TO_DATE`` reads seconds.
"""

from __future__ import annotations

from ...iec.values import resolve
from ..errors import INVALID_ARGUMENT, PlcRuntimeError
from .build import HELPERS, Impl

_SECONDS_PER_DAY = 86_400


def whole_days(seconds: int) -> int:
    """The DATE (ms) of ``seconds`` since 1970-01-01; a fault unless they make whole days: CODESYS's DATE would keep
    the seconds over (its DWORD), which a LadderLab DATE (a day) cannot."""
    if seconds % _SECONDS_PER_DAY:
        raise PlcRuntimeError(
            INVALID_ARGUMENT,
            f"{seconds} s since 1970-01-01 is no whole day: CODESYS's DATE would keep the {seconds % _SECONDS_PER_DAY}"
            " s over, a LadderLab DATE holds a day",
        )
    return seconds * 1000


HELPERS["ll__whole_days"] = whole_days


def seconds(types: tuple[str, ...], result: str | None) -> Impl:
    """DATE or DT -> the DWORD CODESYS stores: its whole seconds since 1970-01-01."""
    return Impl("a0 // 1000", "DWORD")


def from_seconds(types: tuple[str, ...], result: str | None) -> Impl:
    """The DWORD CODESYS stores (seconds since 1970-01-01) -> the DATE or DT ``result``."""
    if result is not None and resolve(result).category == "date":
        return Impl("ll__whole_days(a0)")
    return Impl("a0 * 1000")


#: The engine's names for them (no IEC name: only the lowering calls them).
FUNCTIONS = {"CODESYS_DATE_SECONDS": seconds, "CODESYS_SECONDS_DATE": from_seconds}
