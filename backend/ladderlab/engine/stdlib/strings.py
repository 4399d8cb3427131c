"""Character string functions (spec FUN-80..FUN-83): 1-based positions as IEC.

The result is cut to the result type's length (STRING[n]; checked form: ENO
FALSE). Out-of-range L and P are clamped to the valid range, and the checked
form reports them (FUN-83): L >= 0; P in 1..LEN+1 for MID, DELETE and REPLACE;
P in 0..LEN(IN1) for INSERT, which inserts *after* the P-th character
(FUN-81), so P = 0 means "at the front". FIND returns 0 when IN2 does not
occur, and also when IN2 is empty (there is nothing to find).
"""

from __future__ import annotations

from ..errors import INVALID_ARGUMENT, PlcWarning
from .build import HELPERS, Impl, call_text, params
from .functions import categories, reject


def find(haystack: str, needle: str) -> int:
    return haystack.find(needle) + 1 if needle else 0


HELPERS["ll__find"] = find


# name -> (number of leading STRING inputs, operation on valid inputs, limits(*inputs) -> ((pin, value, lo, hi), ..))
# where hi None = unbounded. The limits drive both the clamping and the checked form's report.
_POSITIONAL = {
    "LEFT": (1, lambda s, n: s[:n], lambda s, n: (("L", n, 0, None),)),
    "RIGHT": (1, lambda s, n: s[len(s) - n :], lambda s, n: (("L", n, 0, None),)),
    "MID": (
        1,
        lambda s, n, p: s[p - 1 : p - 1 + n],
        lambda s, n, p: (("L", n, 0, None), ("P", p, 1, len(s) + 1)),
    ),
    "INSERT": (2, lambda a, b, p: a[:p] + b + a[p:], lambda a, b, p: (("P", p, 0, len(a)),)),
    "DELETE": (
        1,
        lambda s, n, p: s[: p - 1] + s[p - 1 + n :],
        lambda s, n, p: (("L", n, 0, None), ("P", p, 1, len(s) + 1)),
    ),
    "REPLACE": (
        2,
        lambda a, b, n, p: a[: p - 1] + b + a[p - 1 + n :],
        lambda a, b, n, p: (("L", n, 0, None), ("P", p, 1, len(a) + 1)),
    ),
}


def _fit(value: int, lo: int, hi: int | None) -> int:
    if value < lo:
        return lo
    return hi if hi is not None and value > hi else value


def _check_types(name: str, types: tuple[str, ...], strings: int) -> None:
    expected = ("string",) * strings + ("int",) * (len(types) - strings)
    if categories(types) != expected:
        raise reject(name, types)


def positional(name: str):
    strings, operation, limits = _POSITIONAL[name]

    def clamped(*args):
        return operation(*args[:strings], *(_fit(v, lo, hi) for _, v, lo, hi in limits(*args)))

    def precheck(*args):
        bad = [f"{pin} = {v}" for pin, v, lo, hi in limits(*args) if _fit(v, lo, hi) != v]
        if not bad:
            return None
        return PlcWarning(INVALID_ARGUMENT, f"{call_text(name, args)}: {', '.join(bad)} is out of range")

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        _check_types(name, types, strings)
        call = f"ll__op({', '.join(params(len(types)))})"
        return Impl(call, result or "STRING", names={"ll__op": clamped}, precheck=precheck)

    return implement


def length(types: tuple[str, ...], result: str | None) -> Impl:
    _check_types("LEN", types, 1)
    return Impl("len(a0)")


def find_position(types: tuple[str, ...], result: str | None) -> Impl:
    _check_types("FIND", types, 2)
    return Impl("ll__find(a0, a1)")


def concat(types: tuple[str, ...], result: str | None) -> Impl:
    _check_types("CONCAT", types, len(types))
    return Impl(" + ".join(params(len(types))), result or "STRING")
