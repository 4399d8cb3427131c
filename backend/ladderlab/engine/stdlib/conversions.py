"""Type conversions <SRC>_TO_<DST> between all elementary types (spec FUN-10, FUN-11).

* REAL/LREAL -> any integer-like type rounds to nearest, ties to even
  (FUN-11, IEC 3rd edition: REAL_TO_INT(2.5) = 2, (3.5) = 4, (-1.6) = -2);
  NaN and ±inf give 0 (checked form: ENO FALSE).
* Integer narrowing wraps in two's complement (FUN-11: INT_TO_SINT(200) = -56;
  checked form reports the overflow). Widening is the identity.
* x_TO_BOOL is x <> 0; BOOL_TO_x gives 0 or 1.
* Time-like types convert through their count: TIME_TO_DINT gives ms,
  LTIME_TO_LINT ns; TIME_TO_TOD / DT_TO_TOD take it modulo 24 h, DT_TO_DATE
  drops the time of day, DATE/DT saturate at the epoch. Between a short (ms)
  and a long (ns) form the count is scaled: TIME_TO_LTIME multiplies by
  1_000_000, LTIME_TO_TIME divides and truncates toward zero (as integer DIV),
  then the target's store rule applies (TIME wraps to 32 bits).
* x_TO_STRING writes the IEC literal text (INT_TO_STRING(-25) = '-25',
  T#1h30m, TOD#11:38:52.35, REAL 11.2 -> '11.2'); STRING_TO_x reads it back.
  Invalid text gives the type's default (FUN-11: 0) with ENO FALSE.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from functools import cache

from ...iec.elementary import ELEMENTARY, canonical_type_name, per_day
from ...iec.literals import unheld_character, unheld_message
from ...iec.stdlib import CONVERSION_SPELLINGS
from ...iec.value_text import format_value, parse
from ...iec.values import MS_PER_DAY, TypeRef, default_value, resolve, value_range
from ..errors import INVALID_ARGUMENT, NOT_A_NUMBER, OVERFLOW, PlcRuntimeError, PlcWarning
from .build import HELPERS, Impl, finite_args, specialise
from .functions import reject


def floor_day(ms: int, per_day: int = MS_PER_DAY) -> int:
    return ms - ms % per_day


HELPERS["ll__day"] = floor_day


def conversion(src: str, dst: str) -> Impl:
    """The Impl of SRC_TO_DST; ``dst`` may be STRING[n]."""
    s, d = resolve(src), resolve(dst)
    if d.category == "string":
        if s.category == "string":
            return Impl("a0", dst)
        return Impl("ll__format(a0)", dst, names={"ll__format": lambda v: format_value(v, s.name)})
    if s.category == "string":
        return _from_text(d)
    if d.category == "bool":
        return Impl("a0" if s.category == "bool" else "a0 != 0")
    if d.category == "real":
        return Impl("float(a0)" if d.name == "LREAL" and s.category != "real" else "a0", dst)
    return _to_integer_like(s, d)


def _to_integer_like(s: TypeRef, d: TypeRef) -> Impl:
    name = f"{s.name}_TO_{d.name}"
    precheck = None
    if s.category == "real":
        exact, precheck = "ll__round(a0)", finite_args(name)
    else:
        exact = "int(a0)" if s.category == "bool" else "a0"
    src_range, dst_range = value_range(s.name), value_range(d.name)
    if s.elem.unit_ns and d.elem.unit_ns and s.elem.unit_ns != d.elem.unit_ns:  # ms <-> ns
        factor = max(s.elem.unit_ns, d.elem.unit_ns) // min(s.elem.unit_ns, d.elem.unit_ns)
        if s.elem.unit_ns > d.elem.unit_ns:
            exact = f"({exact}) * {factor}"
            src_range = (src_range[0] * factor, src_range[1] * factor)  # type: ignore[index]  # time types have ranges
        else:
            exact = f"ll__idiv({exact}, {factor})"
    if d.category == "date":
        exact = f"ll__day({exact}, {per_day(d.elem)})"
    if src_range and dst_range[0] <= src_range[0] and src_range[1] <= dst_range[1]:  # type: ignore[index]
        return Impl(exact)  # widening: the value always fits
    if d.category in ("time", "date", "dt"):  # a duration or a date has no wrap: outside its range a call faults
        fit = functools.partial(_fit_time, name=name, target=d.name, low=dst_range[0], high=dst_range[1])
        return Impl(exact, d.name, precheck=precheck, guard=fit)
    return Impl(exact, d.name, precheck=precheck)


def _fit_time(value: int, name: str, target: str, low: int, high: int) -> int:
    """``value`` (a count of ms or ns) unchanged when a ``target`` holds it; a fault (``overflow``) otherwise: no
    wrapped or saturated duration or date stands in for the result (LTIME_TO_TIME(LTIME#30d), DATE_TO_TIME of any
    date after 1970-01-25). With ENO wired the checked form says so instead (ENO FALSE, IEC 61131-3 ed. 3 6.6.2.2)."""
    if low <= value <= high:
        return value
    unit = "ms" if ELEMENTARY[target].unit_ns == 1_000_000 else "ns"
    bounds = f"{format_value(low, target)}..{format_value(high, target)}"
    raise PlcRuntimeError(OVERFLOW, f"{name} gives {value} {unit}, outside {target} ({bounds})")


def _from_text(d: TypeRef) -> Impl:
    default = default_value(d.name)

    def parsed(text: str) -> object:
        try:
            return parse(text, d.name)
        except ValueError:
            return default

    def precheck(text: str) -> PlcWarning | None:
        try:
            parse(text, d.name)
        except ValueError as error:
            return PlcWarning(NOT_A_NUMBER, str(error))
        return None

    result = None if d.category == "bool" else d.name
    return Impl("ll__parse(a0)", result, names={"ll__parse": parsed}, precheck=precheck)


def conversion_function(src: str, dst: str, narrowed: bool = False):
    """The registry's implement() for SRC_TO_DST: checks the argument type, takes STRING[n] from the result;
    ``narrowed``: WSTRING_TO_STRING, whose characters must be ones a STRING holds."""

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        if resolve(types[0]).name != resolve(src).name:
            raise reject(f"{src}_TO_{dst}", types)
        target = result if result and resolve(dst).category == "string" else dst
        return _to_latin1(target) if narrowed else conversion(src, target)

    return implement


def conversion_names() -> dict[str, tuple[str, str, bool]]:
    """Every SRC_TO_DST name with long and short spellings (FUN-10: DT_TO_TOD = DATE_AND_TIME_TO_TIME_OF_DAY), and
    WSTRING's, which the value model holds as a STRING (a Python str): ``(src, dst, narrowed)``, narrowed for
    WSTRING_TO_STRING."""
    return {
        f"{a}_TO_{b}": (value_type_name(a), value_type_name(b), a.upper() == "WSTRING" and b.upper() == "STRING")
        for a in CONVERSION_SPELLINGS
        for b in CONVERSION_SPELLINGS
        if canonical_type_name(a) != canonical_type_name(b)
    }


def _to_latin1(dst: str) -> Impl:
    """WSTRING_TO_STRING: the same characters, each one a STRING holds (CODESYS's STRING is Latin-1); CODESYS
    documents no byte for any other, so one is a fault (``invalid_argument``) rather than a made-up character."""

    def latin1(text: str) -> str:
        unheld = unheld_character(text, wide=False)
        if unheld is not None:
            raise PlcRuntimeError(INVALID_ARGUMENT, f"WSTRING_TO_STRING: {unheld_message(unheld, False)}")
        return text

    return Impl("ll__latin1(a0)", dst, names={"ll__latin1": latin1})


def value_type_name(name: str) -> str:
    """The value model's type of a type name: WSTRING is held as STRING, every other name is its own."""
    return "STRING" if name.upper() == "WSTRING" else name


@cache
def converter(src: str, dst: str, checked: bool = False) -> Callable:
    """A specialised one-argument converter; ``checked`` returns (value, None | PlcWarning)."""
    built = specialise(f"{resolve(src).name}_TO_{resolve(dst).name}", conversion(src, dst), 1)
    return built.checked if checked else built.fast


def convert(value: object, src: str, dst: str) -> object:
    """Convert one value (convenience; generated code should hold on to ``converter(src, dst)``)."""
    return converter(src, dst)(value)
