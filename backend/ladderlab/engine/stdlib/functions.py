"""Numeric, arithmetic, bit-string, selection and comparison functions (spec FUN-20..FUN-71).

The implement functions (``(arg_types, result_type) -> Impl``, registered in
``stdlib/__init__``) each describe one specialisation. The REAL helpers never
raise on a NaN, infinite or out-of-domain argument: they return the IEEE-754
result (FUN-20: NaN or -inf), which the checked form turns into ENO = FALSE.
"""

from __future__ import annotations

import math

from ...iec.values import resolve, wrap_expr
from ..errors import division_by_zero, index_out_of_range
from .build import HELPERS, Impl, finite_args

_INF, _NAN = math.inf, math.nan


def idiv(a: int, b: int) -> int:
    """Integer quotient truncated toward zero (FUN-31: 7/2 = 3, -7/2 = -3); b = 0 is a fault."""
    if not b:
        raise division_by_zero(a, b)
    q = a // b
    return q + 1 if q < 0 and q * b != a else q


def imod(a: int, b: int) -> int:
    """IEC MOD: remainder with the sign of the dividend, and 0 when b = 0 (FUN-31)."""
    if not b:
        return 0
    r = a % b
    return r - b if r and (a < 0) != (b < 0) else r


def fdiv(a: float, b: float) -> float:
    """IEEE division: x/0 is ±inf, 0/0 is NaN (FUN-31)."""
    try:
        return a / b
    except ZeroDivisionError:
        if a != a or a == 0:
            return _NAN
        return math.copysign(_INF, a) * math.copysign(1.0, b)


def sqrt(x: float) -> float:
    return math.sqrt(x) if x >= 0 else _NAN


def _log(fn):
    def log(x: float) -> float:
        if x > 0:
            return fn(x)
        return -_INF if x == 0 else _NAN

    return log


def exp(x: float) -> float:
    try:
        return math.exp(x)
    except OverflowError:
        return _INF


def _nan_outside_domain(fn):
    """sin/cos/tan of ±inf, asin/acos beyond ±1: NaN instead of ValueError."""

    def safe(x: float) -> float:
        try:
            return fn(x)
        except ValueError:
            return _NAN

    return safe


def power(x: float, y: float) -> float:
    """EXPT with the IEEE pow special cases instead of exceptions or complex results."""
    try:
        return math.pow(x, y)
    except OverflowError:
        return -_INF if x < 0 and _odd_integer(y) else _INF
    except ValueError:  # 0 ** negative, or negative ** non-integer
        if x == 0:
            return math.copysign(_INF, x) if _odd_integer(y) else _INF
        return _NAN


def _odd_integer(y: float) -> bool:
    return float(y).is_integer() and int(y) % 2 == 1


def shl(x: int, n: int, bits: int) -> int:
    """Shift left, zero-filled; n outside 0..bits-1 shifts everything out (FUN-40)."""
    return (x << n) & ((1 << bits) - 1) if 0 <= n < bits else 0


def shr(x: int, n: int, bits: int) -> int:
    return x >> n if 0 <= n < bits else 0


def sar(x: int, n: int) -> int:
    """SHR of a signed integer (CODESYS typing): an arithmetic shift, filled with the sign bit (so -1 from n >=
    its width on for a negative x, as CODESYS documents for signed types); a negative n shifts nothing out: 0."""
    return x >> n if n >= 0 else 0


def rol(x: int, n: int, bits: int) -> int:
    """Rotate left by n mod width (so a negative n rotates right)."""
    n %= bits
    return ((x << n) | (x >> (bits - n))) & ((1 << bits) - 1)


def ror(x: int, n: int, bits: int) -> int:
    return rol(x, -n, bits)


def limit(mn, x, mx):
    """LIMIT(MN, IN, MX) = MIN(MAX(IN, MN), MX), literally (FUN-60)."""
    x = x if x >= mn else mn
    return x if x <= mx else mx


def limit_real(mn, x, mx):
    """LIMIT of REALs: a NaN among the arguments gives NaN, as MAX and MIN of REALs do (``extreme``)."""
    if mn != mn or x != x or mx != mx:
        return math.nan
    return limit(mn, x, mx)


def extreme_real(pick, *args):
    """MAX or MIN (``pick``) of three or more REALs: NaN if any is NaN, whatever its place."""
    return math.nan if any(a != a for a in args) else pick(args)


def mux_error(k: int, n: int):
    raise index_out_of_range(k, 0, n - 1, "MUX selector K")


def round_half_even(x: float) -> int:
    """REAL -> integer rounding (FUN-11: ties to even); NaN and ±inf give 0."""
    try:
        return round(x)
    except (ValueError, OverflowError):
        return 0


def trunc(x: float) -> int:
    """Toward zero (FUN-11, TRUNC); NaN and ±inf give 0."""
    try:
        return int(x)
    except (ValueError, OverflowError):
        return 0


MATH_FUNCTIONS = {
    "SQRT": sqrt,
    "LN": _log(math.log),
    "LOG": _log(math.log10),
    "EXP": exp,
    "SIN": _nan_outside_domain(math.sin),
    "COS": _nan_outside_domain(math.cos),
    "TAN": _nan_outside_domain(math.tan),
    "ASIN": _nan_outside_domain(math.asin),
    "ACOS": _nan_outside_domain(math.acos),
    "ATAN": math.atan,
}

HELPERS.update(
    {f"ll__{name.lower()}": fn for name, fn in MATH_FUNCTIONS.items()},
    ll__idiv=idiv,
    ll__imod=imod,
    ll__fdiv=fdiv,
    ll__pow=power,
    ll__shl=shl,
    ll__shr=shr,
    ll__sar=sar,
    ll__rol=rol,
    ll__ror=ror,
    ll__limit=limit,
    ll__limit_real=limit_real,
    ll__extreme_real=extreme_real,
    ll__mux_error=mux_error,
    ll__round=round_half_even,
    ll__trunc=trunc,
    ll__atan2=math.atan2,
)


def categories(types: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(resolve(t).category for t in types)


def reject(name: str, types: tuple[str, ...]) -> TypeError:
    return TypeError(f"{name} is not defined for ({', '.join(types)})")


def _numeric(name: str, types: tuple[str, ...], allowed: frozenset[str]) -> None:
    if not set(categories(types)) <= allowed:
        raise reject(name, types)


_NUM = frozenset({"int", "real"})
_INT = frozenset({"int"})
_REAL = frozenset({"real"})


def chain(op: str, types: tuple[str, ...], result: str) -> Impl:
    """IN1 op IN2 op .. INn; for REAL every intermediate is rounded to float32 as a PLC would."""
    expr = "a0"
    last = len(types) - 1
    for i in range(1, len(types)):
        expr = f"{expr} {op} a{i}"
        if i < last and resolve(result).name == "REAL":
            expr = f"ll__f32({expr})"
    return Impl(expr, result)


#: CODESYS typing computes on bit strings as on the unsigned integers of their width (the checker decides when).
_NUM_OR_BITS = _NUM | {"bits"}
_INT_OR_BITS = _INT | {"bits"}


def arithmetic(name: str, op: str):
    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        _numeric(name, types, _NUM_OR_BITS)
        return chain(op, types, result or types[0])

    return implement


def divide(types: tuple[str, ...], result: str | None) -> Impl:
    _numeric("DIV", types, _NUM_OR_BITS)
    result = result or types[0]
    helper = "ll__fdiv" if resolve(result).category == "real" else "ll__idiv"
    return Impl(f"{helper}(a0, a1)", result)


def modulo(types: tuple[str, ...], result: str | None) -> Impl:
    _numeric("MOD", types, _INT_OR_BITS)  # FUN-32: ANY_INT only (bit strings: CODESYS typing)
    return Impl("ll__imod(a0, a1)", result or types[0])


def expt(types: tuple[str, ...], result: str | None) -> Impl:
    if categories(types[:1]) != ("real",):  # FUN-33: the base is ANY_REAL
        raise reject("EXPT", types)
    _numeric("EXPT", types, _NUM)
    return Impl("ll__pow(a0, a1)", result or types[0])


def absolute(types: tuple[str, ...], result: str | None) -> Impl:
    _numeric("ABS", types, _NUM)
    return Impl("abs(a0)", result or types[0])  # ABS(INT#-32768) wraps to -32768 (FUN-20)


def real_function(name: str):
    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        _numeric(name, types, _REAL)
        return Impl(f"ll__{name.lower()}(a0)", result or types[0])

    return implement


def atan2(types: tuple[str, ...], result: str | None) -> Impl:
    """ATAN2(Y, X): the angle of the point (X, Y) in -pi..pi, by the signs of both (IEEE atan2, never a fault)."""
    _numeric("ATAN2", types, _REAL)
    return Impl("ll__atan2(a0, a1)", result or types[0])


def move(types: tuple[str, ...], result: str | None) -> Impl:
    return Impl("a0")


def _bit_widths(name: str, types: tuple[str, ...]) -> int:
    """Width of the ANY_BIT operands (FUN-40/50); BOOL counts as 1."""
    refs = [resolve(t) for t in types]
    if any(r.category not in ("bits", "bool") for r in refs):
        raise reject(name, types)
    return refs[0].elem.bits


def shift(name: str):
    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        if categories(types[:1]) == ("int",):  # CODESYS typing: an integer shifted as the bits of its type
            return _integer_shift(name, types)
        bits = _bit_widths(name, types[:1])
        if bits == 1 or categories(types[1:])[0] not in _INT_OR_BITS:  # FUN-40: BOOL rejected, N is ANY_INT
            raise reject(name, types)
        return Impl(f"ll__{name.lower()}(a0, a1, {bits})")

    return implement


def _integer_shift(name: str, types: tuple[str, ...]) -> Impl:
    """SHL/SHR/ROL/ROR of an integer (CODESYS typing): on the bits of the input's type ("the number of bits CODESYS
    uses is defined by the data type of the input"); an unsigned integer as its bit string, a signed one as its
    two's complement bits read back as signed, SHR of a signed one arithmetic (``sar``)."""
    if categories(types[1:])[0] not in _INT_OR_BITS:
        raise reject(name, types)
    elem = resolve(types[0]).elem
    if not elem.signed:
        return Impl(f"ll__{name.lower()}(a0, a1, {elem.bits})")
    if name == "SHR":
        return Impl("ll__sar(a0, a1)")
    return Impl(wrap_expr(f"ll__{name.lower()}(a0 & {(1 << elem.bits) - 1}, a1, {elem.bits})", types[0]))


def bitwise(name: str, op: str):
    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        _bit_widths(name, types)
        return Impl(f" {op} ".join(f"a{i}" for i in range(len(types))))

    return implement


def negate(types: tuple[str, ...], result: str | None) -> Impl:
    bits = _bit_widths("NOT", types)
    return Impl("not a0" if bits == 1 else f"a0 ^ {(1 << bits) - 1}")


def select(types: tuple[str, ...], result: str | None) -> Impl:
    if categories(types[:1]) != ("bool",):
        raise reject("SEL", types)
    return Impl("a2 if a0 else a1")  # SEL(G, IN0, IN1)


def extreme(name: str, op: str):
    """MAX and MIN (FUN-60). Of REALs, a NaN argument gives NaN whatever its place (IEEE 754-2019 maximum and
    minimum): a bare comparison would give NaN or the other number depending on the order of the arguments."""

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        args = ", ".join(f"a{i}" for i in range(len(types)))
        real = "real" in categories(types)
        if len(types) == 2:
            return Impl(f"a0 if a0 {op} a1 or a0 != a0 else a1" if real else f"a0 if a0 {op} a1 else a1")
        return Impl(f"ll__extreme_real({name.lower()}, {args})" if real else f"{name.lower()}({args})")

    return implement


def limiter(types: tuple[str, ...], result: str | None) -> Impl:
    real = "real" in categories(types)
    return Impl(f"ll__limit{'_real' if real else ''}(a0, a1, a2)")  # LIMIT(MN, IN, MX)


def multiplexer(types: tuple[str, ...], result: str | None) -> Impl:
    """MUX(K, IN0..INn-1) = IN_K; K outside 0..n-1 is a fault (FUN-61, APB-09)."""
    if categories(types[:1]) != ("int",):
        raise reject("MUX", types)
    n = len(types) - 1
    expr = f"ll__mux_error(a0, {n})"
    for k in reversed(range(n)):
        expr = f"a{k + 1} if a0 == {k} else {expr}"
    return Impl(expr)


def comparison(op: str):
    """GT(a, b, c) = a > b AND b > c (FUN-70): Python's chained comparison is exactly that."""

    def implement(types: tuple[str, ...], result: str | None) -> Impl:
        return Impl(f" {op} ".join(f"a{i}" for i in range(len(types))))

    return implement


def truncate(types: tuple[str, ...], result: str | None) -> Impl:
    """TRUNC (FUN-11): toward zero, into the requested integer type; NaN and ±inf are invalid."""
    _numeric("TRUNC", types, _REAL)
    return Impl("ll__trunc(a0)", result or "DINT", precheck=finite_args("TRUNC"))  # APB-06 [REC]: DINT
