"""Independent reference values for the engine tests (no runtime code used here)."""

from __future__ import annotations

import datetime as dt
import struct

from ladderlab.iec.elementary import ELEMENTARY

DAY = 86_400_000
INT_TYPES = [n for n, t in ELEMENTARY.items() if t.category == "int"]
BIT_TYPES = [n for n, t in ELEMENTARY.items() if t.category == "bits"]


def ms(d: int = 0, h: int = 0, m: int = 0, s: float = 0, millis: int = 0) -> int:
    """A duration in milliseconds, written like T#1d2h3m4s5ms."""
    return round((((d * 24 + h) * 60 + m) * 60 + s) * 1000) + millis


def date_ms(text: str) -> int:
    """'2003-06-21' or '2003-06-21 11:38:52.350' as ms since 1970-01-01 (no time zone)."""
    moment = dt.datetime.fromisoformat(text)
    return (moment - dt.datetime(1970, 1, 1)) // dt.timedelta(milliseconds=1)


def int_range(name: str) -> tuple[int, int]:
    t = ELEMENTARY[name]
    return t.min, t.max  # type: ignore[return-value]


def reference_wrap(value: int, name: str) -> int:
    """Two's complement wrap by modular arithmetic, written differently from the runtime's masks."""
    lo, hi = int_range(name)
    return (value - lo) % (hi - lo + 1) + lo


def is_float32(x: float) -> bool:
    return struct.unpack("f", struct.pack("f", x))[0] == x or x != x
