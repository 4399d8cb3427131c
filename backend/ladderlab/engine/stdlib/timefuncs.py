"""Date and time functions (spec FUN-85..FUN-87), also used for + - * / on time operands.

All values are integer milliseconds (TYP-03), so each function is one integer
expression; the result type's store rule does the rest: TIME wraps to 32 bits
(FUN-90), TIME_OF_DAY wraps modulo 24 h (FUN-86), DATE_AND_TIME saturates at
the epoch. The exception is FUN-87: a DATE or DT difference beyond the TIME
range saturates instead of wrapping (checked form: ENO FALSE).

The long forms (LTIME, LTIME_OF_DAY, LDATE, LDATE_AND_TIME: nanoseconds) take
the same functions when every time operand is long (the result is then long:
LTOD - LTOD is an LTIME); a long and a short operand together are refused (the
checker asks for a conversion).

MUL_TIME / DIV_TIME by a REAL round the result to the nearest millisecond,
ties to even like REAL_TO_* (FUN-11); DIV_TIME by an integer truncates toward
zero like integer DIV (FUN-31). Dividing by zero is a fault.
"""

from __future__ import annotations

from ...iec.elementary import LONG_TIME_TYPES, SHORT_TO_LONG
from ...iec.values import resolve, value_range
from ..errors import division_by_zero
from .build import HELPERS, Impl, finite_args
from .functions import categories, reject, round_half_even

TIME_MIN, TIME_MAX = value_range("TIME")  # type: ignore[misc]
LTIME_MIN, LTIME_MAX = value_range("LTIME")  # type: ignore[misc]  # LTIME has a range


def saturate_time(ms: int) -> int:
    return TIME_MIN if ms < TIME_MIN else TIME_MAX if ms > TIME_MAX else ms


def saturate_ltime(ns: int) -> int:
    return LTIME_MIN if ns < LTIME_MIN else LTIME_MAX if ns > LTIME_MAX else ns


def divide_time(ms: int, divisor: float) -> int:
    if not divisor:
        raise division_by_zero(ms, divisor)
    return round_half_even(ms / divisor)


HELPERS.update(ll__sat_time=saturate_time, ll__sat_ltime=saturate_ltime, ll__tdiv=divide_time)


def time_lengths(types: tuple[str, ...]) -> bool | None:
    """True when every time-like argument is a long form (ns), False when all are short (ms), None when mixed."""
    longs = {resolve(x).name in LONG_TIME_TYPES for x in types if resolve(x).elem.unit_ns}
    return None if len(longs) > 1 else True in longs


def _long(result: str, store: str | None) -> tuple[str, str | None]:
    """The result type and store override of a time function whose operands are long forms."""
    return SHORT_TO_LONG[result], store and store.replace("ll__sat_time", "ll__sat_ltime")


# name -> (argument categories, exact expression, result type, store override)
_FIXED: dict[str, tuple[tuple[str, ...], str, str, str | None]] = {
    "ADD_TIME": (("time", "time"), "a0 + a1", "TIME", None),
    "SUB_TIME": (("time", "time"), "a0 - a1", "TIME", None),
    "ADD_TOD_TIME": (("tod", "time"), "a0 + a1", "TIME_OF_DAY", None),
    "SUB_TOD_TIME": (("tod", "time"), "a0 - a1", "TIME_OF_DAY", None),
    "SUB_TOD_TOD": (("tod", "tod"), "a0 - a1", "TIME", None),
    "ADD_DT_TIME": (("dt", "time"), "a0 + a1", "DATE_AND_TIME", None),
    "SUB_DT_TIME": (("dt", "time"), "a0 - a1", "DATE_AND_TIME", None),
    "SUB_DATE_DATE": (("date", "date"), "a0 - a1", "TIME", "ll__sat_time({x})"),
    "SUB_DT_DT": (("dt", "dt"), "a0 - a1", "TIME", "ll__sat_time({x})"),
    "CONCAT_DATE_TOD": (("date", "tod"), "a0 + a1", "DATE_AND_TIME", None),
}


def fixed(name: str):
    cats, exact, result, store = _FIXED[name]

    def implement(types: tuple[str, ...], result_type: str | None) -> Impl:
        long = time_lengths(types)
        if categories(types) != cats or long is None:
            raise reject(name, types)
        return Impl(exact, *_long(result, store)) if long else Impl(exact, result, store)

    return implement


def scale(name: str, int_expr: str, real_expr: str):
    """MUL_TIME / DIV_TIME: TIME by ANY_NUM -> TIME, LTIME by ANY_NUM -> LTIME."""

    def implement(types: tuple[str, ...], result_type: str | None) -> Impl:
        cats = categories(types)
        result = resolve(types[0]).name
        if cats == ("time", "int"):
            return Impl(int_expr, result)
        if cats == ("time", "real"):
            return Impl(real_expr, result, precheck=finite_args(name))
        raise reject(name, types)

    return implement


TIME_FUNCTIONS = {name: fixed(name) for name in _FIXED}
TIME_FUNCTIONS["MUL_TIME"] = scale("MUL_TIME", "a0 * a1", "ll__round(a0 * a1)")
TIME_FUNCTIONS["DIV_TIME"] = scale("DIV_TIME", "ll__idiv(a0, a1)", "ll__tdiv(a0, a1)")


def clock(types: tuple[str, ...], result_type: str | None) -> Impl:
    """CODESYS ``TIME()``: the milliseconds since the PLC started, here the simulation's virtual clock at the start of
    the running scan (``ll_now``, a global of each generated module: the call is always inlined there), wrapping as
    TIME does."""
    return Impl("int(ll_now)", "TIME")  # whole milliseconds (a task may run every 0.5 ms)
