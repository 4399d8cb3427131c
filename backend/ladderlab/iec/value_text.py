"""IEC literal text <-> values, for *_TO_STRING, STRING_TO_* and online writes.

``format_value`` writes the literal forms of spec section 1.7/1.8 (T#1h30m,
TOD#11:38:52.35, D#2003-06-21, DT#2003-06-21-11:38:52.35) so that a value
converted to STRING converts back. ``parse`` accepts those forms (any case,
with or without the type prefix, with ``_`` separators and 2#/8#/16# bases)
and returns the plain number without range checks: callers wrap (conversions)
or reject (``values.coerce``).
"""

from __future__ import annotations

import datetime as _dt
import math
import re

from .elementary import ALIASES, LONG_TIME_TYPES
from .literals import (
    decode_date,
    decode_duration,
    decode_integer,
    decode_time_literal,
    decode_tod,
    encode_duration,
    encode_time_literal,
    literal_form,
    literal_type,
)
from .values import MS_PER_DAY, f32, resolve

_EPOCH = _dt.date(1970, 1, 1).toordinal()
_PREFIXES = {  # category -> prefixes accepted besides the type's own name
    "time": {"T"},
    "tod": {"TOD"},
    "date": {"D"},
    "dt": {"DT"},
}

_PREFIX_RE = re.compile(r"([A-Z_]+)#(.*)\Z", re.S)
_INT_RE = re.compile(r"(?:([+-]?)([0-9][0-9_]*)|(2|8|16)#([0-9A-F][0-9A-F_]*))\Z")
_REAL_RE = re.compile(r"[+-]?[0-9][0-9_]*(?:\.[0-9][0-9_]*)?(?:E[+-]?[0-9]+)?\Z")
_TIME_RE = re.compile(r"(-?)((?:[0-9][0-9_]*(?:\.[0-9]+)?(?:MS|US|NS|D|H|M|S)_?)+)\Z")
_TOD_RE = re.compile(r"([0-9]{1,2}):([0-9]{1,2})(?::([0-9]{1,2})(?:\.([0-9]+))?)?\Z")
_DATE_RE = re.compile(r"([0-9]{4})-([0-9]{1,2})-([0-9]{1,2})\Z")
_DT_RE = re.compile(r"([0-9]{4}-[0-9]{1,2}-[0-9]{1,2})-(.+)\Z")


def parse(text: str, type_name: str) -> object:
    """The raw value (bool, int, float, int ms or str) that ``text`` denotes as a ``type_name`` literal."""
    ref = resolve(type_name)
    if ref.category == "string":
        return text
    body = _strip_prefix(text.strip().upper(), ref.name, ref.category)
    result = _PARSERS[ref.category](body) if body else None
    if result is not None and ref.name in LONG_TIME_TYPES:
        result = _long(body, ref.name)
    if result is None:
        from .values import article

        form = literal_form(ref.name) if ref.category in _PREFIXES else None
        raise ValueError(f"{text!r} is not {article(ref.name)}" + (f" ({form.hint()})" if form else ""))
    return result


def _strip_prefix(text: str, name: str, category: str) -> str:
    match = _PREFIX_RE.match(text)
    if not match:  # also 16#FF: a base, not a type prefix
        return text
    prefix = ALIASES.get(match.group(1), match.group(1))
    if prefix == name or match.group(1) in _PREFIXES.get(category, ()) or literal_type(match.group(1)) == name:
        return match.group(2)
    return ""  # a prefix naming another type


def _parse_int(text: str) -> int | None:
    match = _INT_RE.match(text)
    if not match:
        return None
    sign, decimal, base, digits = match.groups()
    if decimal is not None:
        value = decode_integer(decimal)[0]
        return -value if sign == "-" else value
    try:
        return decode_integer(f"{base}#{digits}")[0]
    except ValueError:  # a digit beyond the base, e.g. 2#102
        return None


def _parse_real(text: str) -> float | None:
    return float(text.replace("_", "")) if _REAL_RE.match(text) else None


def _parse_bool(text: str) -> bool | None:
    return {"TRUE": True, "FALSE": False, "1": True, "0": False}.get(text)


def _parse_time(text: str) -> int | None:
    if text.lstrip("-").isdigit():  # bare milliseconds (spec ST-26 compatibility)
        return int(text)
    match = _TIME_RE.match(text)
    if not match:
        return None
    total = decode_duration("T#" + match.group(2))
    return -round(total) if match.group(1) else round(total)


def _parse_tod(text: str) -> int | None:
    match = _TOD_RE.match(text)
    if not match:
        return None
    h, m, s, _ = match.groups()
    if int(h) > 23 or int(m) > 59 or int(s or 0) > 59:
        return None
    ms = decode_tod("TOD#" + text)
    return ms if ms < MS_PER_DAY else None


def _parse_date(text: str) -> int | None:
    match = _DATE_RE.match(text)
    if not match:
        return None
    try:
        ms = decode_date("D#" + text)
    except ValueError:  # 2003-02-30
        return None
    return ms if ms >= 0 else None


def _parse_dt(text: str) -> int | None:
    match = _DT_RE.match(text)
    if not match:
        return None
    day, tod = _parse_date(match.group(1)), _parse_tod(match.group(2))
    return None if day is None or tod is None else day + tod


def _long(body: str, name: str) -> int:
    """A valid LTIME/LDATE/LTIME_OF_DAY/LDATE_AND_TIME text (checked by the short type's parser) in nanoseconds."""
    if LONG_TIME_TYPES[name] == "TIME" and body.lstrip("-").isdigit():  # bare milliseconds, as for TIME
        return int(body) * 1_000_000
    return int(decode_time_literal(f"{name}#{body}")[1])


_PARSERS = {
    "bool": _parse_bool,
    "int": _parse_int,
    "bits": _parse_int,
    "real": _parse_real,
    "time": _parse_time,
    "tod": _parse_tod,
    "date": _parse_date,
    "dt": _parse_dt,
}


def format_value(value: object, type_name: str) -> str:
    """The IEC literal text of a stored value, without type prefix for numbers (INT 5 -> '5')."""
    ref = resolve(type_name)
    cat = ref.category
    if cat == "bool":
        return "TRUE" if value else "FALSE"
    if cat == "string" or not isinstance(value, int | float):
        return str(value)
    if cat == "real":
        return format_real(float(value), ref.name == "REAL")
    if ref.name in LONG_TIME_TYPES:
        return encode_time_literal(ref.name, int(value))
    ms = int(value)  # every other category is a whole number of milliseconds or an integer
    if cat == "time":
        return format_time(ms)
    if cat == "tod":
        return "TOD#" + _clock(ms)
    if cat == "date":
        return "D#" + _date(ms)
    if cat == "dt":
        return "DT#" + _date(ms) + "-" + _clock(ms % MS_PER_DAY)
    return str(value)


def format_real(x: float, single: bool) -> str:
    """Shortest text that reads back as the same REAL/LREAL, as an IEC real literal (1.0E20, 11.2)."""
    if not math.isfinite(x):
        return "NAN" if x != x else ("INF" if x > 0 else "-INF")
    text = repr(x)
    if single:
        text = next(t for t in (f"{x:.{p}g}" for p in range(6, 10)) if f32(float(t)) == x)
    mantissa, _, exponent = text.lower().partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return mantissa + (f"E{int(exponent)}" if exponent else "")


def format_time(ms: int) -> str:
    return "T#" + encode_duration(ms)


def _clock(ms: int) -> str:
    seconds, millis = divmod(ms, 1000)
    minutes, seconds = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    fraction = f".{millis:03d}".rstrip("0") if millis else ""
    return f"{hours:02d}:{minutes:02d}:{seconds:02d}{fraction}"


def _date(ms: int) -> str:
    return _dt.date.fromordinal(_EPOCH + ms // MS_PER_DAY).isoformat()
