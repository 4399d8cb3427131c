"""The IEC value model at run time (spec TYP-03): storing, defaults, user writes.

Widths, signedness and defaults come from ``st.elementary`` (the one table of
elementary types). "Storing" a value in a type is what every assignment and
every function result goes through:

* integers and bit strings wrap in two's complement to the type's width (FUN-90);
* TIME wraps to signed 32 bits, LTIME to signed 64 bits; TIME_OF_DAY and
  LTIME_OF_DAY are taken modulo 24 h (FUN-86);
* DATE and DATE_AND_TIME saturate to [1970-01-01, 9999-12-31 23:59:59.999]
  (the value model starts at the epoch; the upper end is where the text form
  D#/DT# stops; cf. FUN-87 "saturated"); LDATE and LDATE_AND_TIME, 64-bit
  nanoseconds, to [1970-01-01, 2262-04-11 23:47:16.854775807];
* REAL rounds to IEEE float32 (TYP-03), LREAL is a Python float;
* STRING is cut to its declared length (TYP-04).

The same rules exist as Python source (``store_expr``) so the code generator
can inline them; such source may name the helpers in ``INLINE_NAMES``.
"""

from __future__ import annotations

import math
import re
import struct
import sys
from collections.abc import Callable
from functools import cache
from typing import Any, NamedTuple

from .. import limits
from .elementary import (
    DEFAULT_STRING_LENGTH,
    ELEMENTARY,
    ElementaryType,
    elementary,
    per_day,
)

MS_PER_DAY = 86_400_000
#: Last millisecond of 9999-12-31, the largest DATE_AND_TIME the DT# text form can show.
DT_MAX = 253_402_300_799_999
#: The largest LDATE_AND_TIME: the last nanosecond a signed 64-bit count from 1970 reaches (2262-04-11).
LDT_MAX = (1 << 63) - 1

_F32 = struct.Struct("<f")
_pack, _unpack = _F32.pack, _F32.unpack
FLT_MAX: float = _unpack(b"\xff\xff\x7f\x7f")[0]


def f32(x: float) -> float:
    """Round to the nearest IEEE float32 (ties to even); beyond FLT_MAX it becomes ±inf."""
    try:
        single: float = _unpack(_pack(x))[0]
        return single
    except (OverflowError, struct.error):  # struct.error: an int too large even for a double
        return math.inf if x > 0 else -math.inf


def clamp_dt(x: int) -> int:
    """Saturate a DATE / DATE_AND_TIME millisecond count to the supported calendar range."""
    return 0 if x < 0 else DT_MAX if x > DT_MAX else x


def clamp_ldt(x: int) -> int:
    """Saturate an LDATE / LDATE_AND_TIME nanosecond count to [1970-01-01, LDT_MAX]."""
    return 0 if x < 0 else LDT_MAX if x > LDT_MAX else x


#: Globals that inlined store / function source may reference (add them to the generated module).
INLINE_NAMES: dict[str, object] = {"ll__f32": f32, "ll__clamp_dt": clamp_dt, "ll__clamp_ldt": clamp_ldt}


class TypeRef(NamedTuple):
    """An elementary type plus, for STRING, its declared length."""

    elem: ElementaryType
    length: int = 0

    @property
    def name(self) -> str:
        return self.elem.name

    @property
    def category(self) -> str:
        return self.elem.category


_STRING_N = re.compile(r"STRING\s*[\[(]\s*(\d+)\s*[\])]\Z")


@cache
def resolve(type_name: str) -> TypeRef:
    """``INT``, ``tod``, ``STRING``, ``STRING[20]`` -> TypeRef; ValueError for anything else."""
    text = type_name.strip().upper()
    sized = _STRING_N.match(text)
    if sized:
        length = int(sized.group(1))
        if not 1 <= length <= limits.STRING_LENGTH.value:
            raise ValueError(f"STRING length {length} is outside 1..{limits.STRING_LENGTH.value}")
        return TypeRef(ELEMENTARY["STRING"], length)
    elem = elementary(text)
    if elem is None:
        raise ValueError(f"{type_name!r} is not an elementary type")
    return TypeRef(elem, DEFAULT_STRING_LENGTH if elem.category == "string" else 0)


def value_range(type_name: str) -> tuple[int, int] | None:
    """Inclusive integer range of an int, bit-string or time-like type; None for others."""
    ref = resolve(type_name)
    cat = ref.category
    if cat == "tod":
        return 0, per_day(ref.elem) - 1
    if cat in ("date", "dt"):
        return 0, DT_MAX if ref.elem.unit_ns > 1 else LDT_MAX
    if cat in ("int", "bits", "time", "bool"):
        lo, hi = ref.elem.min, ref.elem.max
        assert lo is not None and hi is not None  # these categories have integer ranges
        return lo, hi
    return None


def wrap_expr(expr: str, type_name: str) -> str:
    """Python source wrapping ``expr`` (an int) to the width of an int, bit-string or TIME type."""
    ref = resolve(type_name)
    if ref.category not in ("int", "bits", "time"):
        raise ValueError(f"{ref.name} does not wrap (not an integer, bit string or TIME)")
    mask = (1 << ref.elem.bits) - 1
    if ref.elem.signed:
        half = 1 << (ref.elem.bits - 1)
        return f"((({expr}) + {half}) & {mask}) - {half}"
    return f"({expr}) & {mask}"


def store_expr(expr: str, type_name: str) -> str:
    """Python source storing ``expr`` into ``type_name`` by the rules in the module docstring."""
    ref = resolve(type_name)
    cat = ref.category
    if cat in ("int", "bits", "time"):
        return wrap_expr(expr, type_name)
    if cat == "tod":
        return f"({expr}) % {per_day(ref.elem)}"
    if cat in ("date", "dt"):
        return f"ll__clamp_dt({expr})" if ref.elem.unit_ns > 1 else f"ll__clamp_ldt({expr})"
    if cat == "string":
        return f"({expr})[:{ref.length}]"
    if ref.name == "REAL":
        return f"ll__f32({expr})"
    return expr  # BOOL and LREAL values are already what Python computes


@cache
def store_fn(type_name: str) -> Callable[[Any], Any]:
    """A one-argument callable applying ``store_expr`` (e.g. for assignments)."""
    if resolve(type_name).name == "REAL":
        return f32
    store: Callable[[Any], Any] = eval(f"lambda x: {store_expr('x', type_name)}", dict(INLINE_NAMES))
    return store


@cache
def wrap_fn(type_name: str) -> Callable[[int], int]:
    """Fast wrapper to the width of an int, bit-string or TIME type (e.g. ``wrap_fn("INT")(32768) == -32768``)."""
    wrap: Callable[[int], int] = eval(f"lambda x: {wrap_expr('x', type_name)}")
    return wrap


def wrap(value: int, type_name: str) -> int:
    return wrap_fn(type_name)(value)


def default_value(type_name: str) -> object:
    """Initial value of a variable declared without one (spec TYP-05, Table 3.8)."""
    return resolve(type_name).elem.default


def article(type_name: str) -> str:
    """'an INT', 'a REAL', 'an LREAL', 'an SINT': for error messages, as the name is read aloud (the long types'
    L and SINT's S are spelt out: "an el-real"; STRING and STRUCT are words)."""
    spelt = type_name[:1] in "AEIO" or type_name == "SINT" or (type_name[:1] == "L" and type_name[1:2].isupper())
    return ("an " if spelt else "a ") + type_name


def coerce(value: object, type_name: str) -> object:
    """Validate a value a user typed (online write/force) and return it in the value model.

    Accepts Python values (``40000``, ``2.5``, ``True``) and IEC literal text
    (``'16#FF'``, ``'T#1h30m'``, ``'TOD#12:00:00'``). Never wraps or truncates:
    a value that does not fit raises ValueError with a message for the user.
    """
    ref = resolve(type_name)
    name = ref.name if ref.category != "string" else f"STRING[{ref.length}]"
    if ref.category == "string":
        if not isinstance(value, str):
            raise ValueError(f"{value!r} is not a STRING")
        if len(value) > ref.length:
            raise ValueError(f"{value!r} is longer than {name} ({len(value)} > {ref.length} characters)")
        return value
    raw = _raw(value, ref)
    if ref.category == "bool":
        if raw in (0, 1):
            return bool(raw)
        raise ValueError(f"{value!r} is not a BOOL (TRUE, FALSE, 1 or 0)")
    if ref.category == "real":
        return _check_real(value, raw, ref.name)
    return _check_int(value, raw, ref)


def _raw(value: object, ref: TypeRef) -> int | float:
    """The number a user value denotes (text is parsed as an IEC literal of the type)."""
    if isinstance(value, str):
        from .value_text import parse  # value_text imports this module; import on use

        return parse(value, ref.name)  # type: ignore[return-value]  # a number: strings are not coerced here
    if isinstance(value, bool):
        if ref.category == "bool":
            return int(value)
    elif isinstance(value, int):
        return value
    elif isinstance(value, float) and math.isfinite(value) and (ref.category == "real" or value.is_integer()):
        return value if ref.category == "real" else int(value)
    raise ValueError(f"{value!r} is not {article(ref.name)}")


def _check_real(value: object, raw: int | float, name: str) -> float:
    largest = FLT_MAX if name == "REAL" else sys.float_info.max
    if abs(raw) > largest:  # f32() would round a little beyond FLT_MAX down to it; a user write must not
        from .value_text import format_real

        single = name == "REAL"
        raise ValueError(
            f"{value!r} is out of range for {name} ({format_real(-largest, single)}..{format_real(largest, single)})"
        )
    return f32(raw) if name == "REAL" else float(raw)


def _check_int(value: object, raw: int | float, ref: TypeRef) -> int:
    if isinstance(raw, float):  # parsed REAL literal text for an integer type
        if not raw.is_integer():
            raise ValueError(f"{value!r} is not {article(ref.name)}")
        raw = int(raw)
    lo, hi = value_range(ref.name)  # type: ignore[misc]  # _check_int is called for ranged types only
    if not lo <= raw <= hi:
        from .value_text import format_value

        shown = raw if ref.category in ("int", "bits") else format_value(raw, ref.name)
        raise ValueError(
            f"{shown} is out of range for {ref.name} ({format_value(lo, ref.name)}..{format_value(hi, ref.name)})"
        )
    if ref.category == "date" and raw % per_day(ref.elem):
        raise ValueError(f"{value!r} is not at a day boundary, as a DATE must be")
    return raw
