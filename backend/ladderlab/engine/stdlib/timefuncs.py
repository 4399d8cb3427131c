"""Date and time functions (spec FUN-85..FUN-87), also used for + - * / on time operands.

All values are integer milliseconds (TYP-03), so each function is one integer
expression; the result type's store rule does the rest: TIME wraps to 32 bits
(FUN-90), TIME_OF_DAY wraps modulo 24 h (FUN-86), DATE_AND_TIME saturates at
the epoch. The exception is FUN-87: a DATE or DT difference beyond the TIME
range saturates instead of wrapping (checked form: ENO FALSE).

MUL_TIME / DIV_TIME by a REAL round the result to the nearest millisecond,
ties to even like REAL_TO_* (FUN-11); DIV_TIME by an integer truncates toward
zero like integer DIV (FUN-31). Dividing by zero is a fault.
"""

from __future__ import annotations

from ...iec.values import value_range
from ..errors import division_by_zero
from .build import HELPERS, Impl, finite_args
from .functions import categories, reject, round_half_even

TIME_MIN, TIME_MAX = value_range("TIME")  # type: ignore[misc]


def saturate_time(ms: int) -> int:
    return TIME_MIN if ms < TIME_MIN else TIME_MAX if ms > TIME_MAX else ms


def divide_time(ms: int, divisor: float) -> int:
    if not divisor:
        raise division_by_zero(ms, divisor)
    return round_half_even(ms / divisor)


HELPERS.update(ll__sat_time=saturate_time, ll__tdiv=divide_time)

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
        if categories(types) != cats:
            raise reject(name, types)
        return Impl(exact, result, store)

    return implement


def scale(name: str, int_expr: str, real_expr: str):
    """MUL_TIME / DIV_TIME: TIME by ANY_NUM -> TIME."""

    def implement(types: tuple[str, ...], result_type: str | None) -> Impl:
        cats = categories(types)
        if cats == ("time", "int"):
            return Impl(int_expr, "TIME")
        if cats == ("time", "real"):
            return Impl(real_expr, "TIME", precheck=finite_args(name))
        raise reject(name, types)

    return implement


TIME_FUNCTIONS = {name: fixed(name) for name in _FIXED}
TIME_FUNCTIONS["MUL_TIME"] = scale("MUL_TIME", "a0 * a1", "ll__round(a0 * a1)")
TIME_FUNCTIONS["DIV_TIME"] = scale("DIV_TIME", "ll__idiv(a0, a1)", "ll__tdiv(a0, a1)")
