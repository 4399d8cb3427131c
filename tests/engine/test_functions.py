"""Numeric, arithmetic, bit, selection and comparison functions (spec FUN-20..FUN-71, APB-02..09)."""

from __future__ import annotations

import itertools
import math
import struct
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.errors import DIVISION_BY_ZERO, DOMAIN, INDEX_RANGE, OVERFLOW, PlcRuntimeError
from ladderlab.engine.stdlib import make_function

from .helpers import BIT_TYPES, INT_TYPES, int_range, is_float32, ms, reference_wrap


def call(name, types, result, *args):
    return make_function(name, types, result)(*args)


def checked(name, types, result, *args):
    return make_function(name, types, result, checked=True)(*args)


def ints(type_name):
    lo, hi = int_range(type_name)
    return st.integers(lo, hi)


def float32s():
    return st.floats(width=32, allow_nan=False, allow_infinity=False)


def reference_f32(x: float) -> float:
    return struct.unpack("f", struct.pack("f", x))[0]


# --- FUN-20: numeric functions of one variable --------------------------------------------------


@pytest.mark.parametrize(
    "name, type_name, arg, expected",
    [
        ("ABS", "INT", -5, 5),
        ("ABS", "INT", -32768, -32768),  # FUN-20: wraps
        ("ABS", "SINT", 7, 7),
        ("ABS", "REAL", -12.0, 12.0),  # APB-06
        ("SQRT", "REAL", 25.0, 5.0),  # APB-06, issue seed example
        ("SQRT", "LREAL", 16.0, 4.0),
        ("LOG", "REAL", 1000.0, 3.0),  # APB-07
        ("LOG", "LREAL", 1000.0, 3.0),
        ("LN", "REAL", 1.0, 0.0),
        ("EXP", "LREAL", 0.0, 1.0),
        ("SIN", "REAL", 0.0, 0.0),
        ("COS", "REAL", 0.0, 1.0),
        ("ACOS", "REAL", 1.0, 0.0),
    ],
)
def test_numeric_exact_vectors_FUN_20(name, type_name, arg, expected):
    result = call(name, [type_name], type_name, arg)
    assert result == expected and type(result) is type(expected)


@pytest.mark.parametrize(
    "name, arg, expected",
    [
        ("LN", 7.389, 2.0),  # APB-07: 1e-4
        ("EXP", 2.0, 7.389056),
        ("TAN", 0.7853982, 1.0),  # APB-08
        ("ASIN", 1.0, 1.570796),
        ("ATAN", 1.0, 0.7853982),
    ],
)
def test_numeric_approximate_vectors_APB_07_08(name, arg, expected):
    assert call(name, ["REAL"], "REAL", arg) == pytest.approx(expected, abs=1e-4)


@pytest.mark.parametrize("name", ["SQRT", "LN", "LOG", "EXP", "SIN", "COS", "TAN", "ATAN"])
@given(x=st.floats(min_value=0.0625, max_value=80, width=32))
def test_real_results_are_float32_and_lreal_is_double_TYP_03(name, x):
    real = call(name, ["REAL"], "REAL", x)
    lreal = call(name, ["LREAL"], "LREAL", x)
    assert is_float32(real)
    assert real == reference_f32(lreal)
    assert lreal == getattr(math, {"LN": "log", "LOG": "log10"}.get(name, name.lower()))(x)


@pytest.mark.parametrize(
    "name, arg, expected, code",
    [
        ("SQRT", -1.0, math.nan, DOMAIN),  # FUN-20: NaN, ENO FALSE
        ("LN", 0.0, -math.inf, OVERFLOW),  # FUN-20: -inf, ENO FALSE
        ("LN", -1.0, math.nan, DOMAIN),
        ("LOG", 0.0, -math.inf, OVERFLOW),
        ("ASIN", 2.0, math.nan, DOMAIN),
        ("ACOS", -1.5, math.nan, DOMAIN),
        ("EXP", 1000.0, math.inf, OVERFLOW),
        ("EXP", 100.0, math.inf, OVERFLOW),  # finite as a double, but beyond REAL
    ],
)
def test_domain_errors_give_ieee_result_and_a_warning_FUN_20(name, arg, expected, code):
    fast = call(name, ["REAL"], "REAL", arg)
    value, warning = checked(name, ["REAL"], "REAL", arg)
    for result in (fast, value):
        assert result == expected or (math.isnan(expected) and math.isnan(result))
    assert warning is not None and warning.code == code and name in warning.message


@pytest.mark.parametrize("name, arg", [("SQRT", 2.0), ("SIN", math.inf), ("SQRT", math.nan), ("LN", math.inf)])
def test_no_new_warning_for_valid_or_already_non_finite_input_FUN_20(name, arg):
    """A NaN or inf argument already carries its error: the function only propagates it."""
    _, warning = checked(name, ["REAL"], "REAL", arg)
    assert warning is None


# --- FUN-30, FUN-31: arithmetic ------------------------------------------------------------------


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("ADD", ["INT", "INT"], (20, 1), 21),  # APB-05 with A = 20
        ("SUB", ["INT", "INT"], (20, 4), 16),
        ("DIV", ["INT", "INT"], (20, 8), 2),
        ("MOD", ["INT", "INT"], (12, 8), 4),  # APB-05, issue seed example
        ("MOD", ["INT", "INT"], (7, 2), 1),  # ST-35f
        ("MOD", ["INT", "INT"], (-7, 2), -1),  # FUN-31: sign of the dividend
        ("MOD", ["INT", "INT"], (7, -2), 1),
        ("MOD", ["INT", "INT"], (-7, -2), -1),
        ("MOD", ["INT", "INT"], (7, 0), 0),  # FUN-31: IEC body gives 0
        ("MOD", ["INT", "INT"], (-32768, -1), 0),
        ("DIV", ["INT", "INT"], (7, 2), 3),  # FUN-31: toward zero
        ("DIV", ["INT", "INT"], (-7, 2), -3),
        ("DIV", ["INT", "INT"], (7, -2), -3),
        ("DIV", ["INT", "INT"], (-7, -2), 3),
        ("DIV", ["INT", "INT"], (-32768, -1), -32768),  # wraps
        ("DIV", ["UDINT", "UDINT"], (2**32 - 1, 2), 2**31 - 1),
        ("ADD", ["INT", "INT"], (32767, 1), -32768),  # ST-90
        ("ADD", ["SINT", "SINT", "SINT", "SINT"], (100, 20, 7, 1), -128),  # FUN-03 extensible
        ("MUL", ["INT", "INT", "INT"], (2, 3, 4), 24),
        ("MUL", ["USINT", "USINT"], (16, 16), 0),
        ("SUB", ["UINT", "UINT"], (0, 1), 65535),
        ("ADD", ["REAL", "REAL"], (0.1, 0.2), reference_f32(0.1 + 0.2)),
        ("ADD", ["LREAL", "LREAL", "LREAL"], (0.1, 0.2, 0.3), 0.1 + 0.2 + 0.3),
        ("DIV", ["REAL", "REAL"], (1.0, 3.0), reference_f32(1 / 3)),
        ("DIV", ["LREAL", "LREAL"], (7.0, 2.0), 3.5),
        ("EXPT", ["REAL", "INT"], (2.0, 3), 8.0),  # APB-06, issue seed example
        ("EXPT", ["REAL", "REAL"], (5.0, 4.0), 625.0),  # ST-35c
        ("EXPT", ["LREAL", "INT"], (-2.0, 3), -8.0),
        ("EXPT", ["LREAL", "REAL"], (4.0, 0.5), 2.0),
        ("MOVE", ["INT"], (5,), 5),
        ("MOVE", ["STRING"], ("abc",), "abc"),
    ],
)
def test_arithmetic_vectors_FUN_30_31(name, types, args, expected):
    result = call(name, types, types[0], *args)
    assert result == expected and type(result) is type(expected)


def test_real_extensible_add_rounds_every_step_to_float32():
    """ADD(a, b, c) on REAL is (a + b) + c with each sum a REAL, as on a PLC."""
    big, tiny = 16777216.0, 1.0  # 2**24: adding 1.0 is lost in float32 but not in double
    assert call("ADD", ["REAL"] * 3, "REAL", big, tiny, tiny) == big
    assert call("ADD", ["LREAL"] * 3, "LREAL", big, tiny, tiny) == big + 2


@pytest.mark.parametrize("type_name", INT_TYPES)
@given(data=st.data())
def test_integer_add_sub_mul_are_python_then_wrap_FUN_90(type_name, data):
    args = data.draw(st.lists(ints(type_name), min_size=2, max_size=4))
    assert call("ADD", [type_name] * len(args), type_name, *args) == reference_wrap(sum(args), type_name)
    assert call("MUL", [type_name] * len(args), type_name, *args) == reference_wrap(math.prod(args), type_name)
    a, b = args[:2]
    assert call("SUB", [type_name] * 2, type_name, a, b) == reference_wrap(a - b, type_name)
    value, warning = checked("ADD", [type_name] * len(args), type_name, *args)
    lo, hi = int_range(type_name)
    assert value == reference_wrap(sum(args), type_name)
    assert (warning is None) == (lo <= sum(args) <= hi)


@pytest.mark.parametrize("type_name", INT_TYPES)
@given(data=st.data())
def test_integer_div_and_mod_truncate_toward_zero_FUN_31(type_name, data):
    a = data.draw(ints(type_name))
    b = data.draw(ints(type_name).filter(bool))
    quotient = math.trunc(Fraction(a, b))
    assert call("DIV", [type_name] * 2, type_name, a, b) == reference_wrap(quotient, type_name)
    assert call("MOD", [type_name] * 2, type_name, a, b) == a - quotient * b


@given(a=float32s(), b=float32s())
def test_real_add_mul_are_correctly_rounded_float32(a, b):
    assert call("ADD", ["REAL", "REAL"], "REAL", a, b) == reference_f32(float(Fraction(a) + Fraction(b)))
    product = call("MUL", ["REAL", "REAL"], "REAL", a, b)
    assert is_float32(product)


@pytest.mark.parametrize("type_name", ["INT", "UDINT", "LINT"])
def test_integer_division_by_zero_is_a_fault_FUN_31(type_name):
    for form in (False, True):
        with pytest.raises(PlcRuntimeError) as caught:
            make_function("DIV", [type_name] * 2, type_name, checked=form)(7, 0)
        assert caught.value.code == DIVISION_BY_ZERO
        assert caught.value.message == "division by zero: 7 / 0"


@pytest.mark.parametrize(
    "a, b, expected",
    [(1.0, 0.0, math.inf), (-1.0, 0.0, -math.inf), (1.0, -0.0, -math.inf), (0.0, 0.0, math.nan)],
)
def test_real_division_by_zero_is_ieee_with_a_warning_FUN_31(a, b, expected):
    value, warning = checked("DIV", ["REAL", "REAL"], "REAL", a, b)
    fast = call("DIV", ["LREAL", "LREAL"], "LREAL", a, b)
    for result in (value, fast):
        assert result == expected or (math.isnan(expected) and math.isnan(result))
    assert warning is not None


@pytest.mark.parametrize(
    "base, exponent, expected",
    [
        (-8.0, 1 / 3, math.nan),
        (0.0, -1, math.inf),
        (-0.0, -1, -math.inf),
        (10.0, 400, math.inf),
        (-10.0, 401, -math.inf),
    ],
)
def test_expt_special_cases_never_raise_FUN_33(base, exponent, expected):
    value, warning = checked("EXPT", ["LREAL", "LREAL"], "LREAL", base, exponent)
    assert value == expected or (math.isnan(expected) and math.isnan(value))
    assert warning is not None


@pytest.mark.parametrize("type_name", INT_TYPES)
def test_overflow_warning_only_in_checked_form_FUN_90(type_name):
    lo, hi = int_range(type_name)
    assert call("ADD", [type_name] * 2, type_name, hi, 1) == lo
    assert checked("SUB", [type_name] * 2, type_name, lo, 1)[1].code == OVERFLOW
    assert checked("ADD", [type_name] * 2, type_name, hi, 0) == (hi, None)


# --- FUN-40, FUN-41, APB-03: shifts and rotations -------------------------------------------------


@pytest.mark.parametrize(
    "name, type_name, x, n, expected",
    [
        ("SHL", "BYTE", 0x0F, 2, 0x3C),  # FUN-41
        ("SHR", "BYTE", 0xF0, 4, 0x0F),
        ("ROL", "BYTE", 0x81, 1, 0x03),
        ("ROR", "BYTE", 0x81, 1, 0xC0),
        ("SHL", "WORD", 0x8001, 1, 0x0002),
        ("ROL", "WORD", 0x8001, 1, 0x0003),
        ("ROL", "BYTE", 0x96, 3, 0xB4),  # APB-03
        ("ROR", "BYTE", 0x96, 1, 0x4B),
        ("SHR", "BYTE", 0x96, 4, 0x09),
        ("SHL", "BYTE", 0x96, 1, 0x2C),
        ("ROL", "DWORD", 0x80000000, 1, 1),
        ("ROR", "LWORD", 1, 1, 2**63),
        ("SHL", "BYTE", 0xFF, 8, 0),  # FUN-40: N >= width gives 0
        ("SHR", "WORD", 0xFFFF, 99, 0),
        ("SHL", "BYTE", 0xFF, -1, 0),  # a negative count shifts everything out too
        ("ROL", "BYTE", 0x81, 9, 0x03),  # rotation by N mod width
        ("ROR", "WORD", 0x1234, 16, 0x1234),
        ("ROL", "BYTE", 0x81, -1, 0xC0),  # negative: the other way
    ],
)
def test_shift_and_rotate_at_the_operand_width_FUN_40(name, type_name, x, n, expected):
    assert call(name, [type_name, "INT"], type_name, x, n) == expected


@pytest.mark.parametrize("type_name", BIT_TYPES)
@given(data=st.data())
def test_rotation_matches_a_bit_string_rotation(type_name, data):
    x = data.draw(ints(type_name))
    n = data.draw(st.integers(0, 200))
    width = int_range(type_name)[1].bit_length()
    bits = format(x, f"0{width}b")
    k = n % width
    assert call("ROL", [type_name, "INT"], type_name, x, n) == int(bits[k:] + bits[:k], 2)
    assert call("ROR", [type_name, "INT"], type_name, call("ROL", [type_name, "INT"], type_name, x, n), n) == x
    assert call("SHL", [type_name, "INT"], type_name, x, n) == (int(bits[n:] + "0" * n, 2) if n < width else 0)


@pytest.mark.parametrize("types", [["BOOL", "INT"], ["REAL", "INT"], ["BYTE", "REAL"], ["INT", "LREAL"]])
def test_shift_rejects_non_bit_strings_FUN_40(types):
    """BOOL and REAL are never shifted; an integer is, under CODESYS typing only (the checker decides: ST-20)."""
    with pytest.raises(TypeError):
        make_function("SHL", types, types[0])


@pytest.mark.parametrize("type_name", ["SINT", "INT", "DINT", "LINT", "USINT", "UINT"])
@given(data=st.data())
def test_integer_shifts_work_on_the_bits_of_their_type_CODESYS(type_name, data):
    """CODESYS typing: SHL/ROL/ROR on an integer work on the two's complement bits of its type, read back in it;
    SHR of a signed one is arithmetic (filled with the sign bit: floor division by 2^n), of an unsigned one logical."""
    x = data.draw(ints(type_name))
    n = data.draw(st.integers(0, 80))
    low, high = int_range(type_name)
    width = (high - low).bit_length()
    bits = format(x % (1 << width), f"0{width}b")

    def signed(pattern: str) -> int:
        value = int(pattern, 2)
        return value - (1 << width) if low < 0 and value >> (width - 1) else value

    k = n % width
    assert call("ROL", [type_name, "INT"], type_name, x, n) == signed(bits[k:] + bits[:k])
    assert call("SHL", [type_name, "INT"], type_name, x, n) == (signed(bits[n:] + "0" * n) if n < width else 0)
    assert call("SHR", [type_name, "INT"], type_name, x, n) == (x // (1 << n) if low < 0 or n < width else 0)


# --- FUN-50, APB-02, ST-35: Boolean and bitwise -------------------------------------------------


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("AND", ["BYTE", "BYTE"], (0xF0, 0x3C), 0x30),  # FUN-50
        ("OR", ["BYTE", "BYTE"], (0xF0, 0x3C), 0xFC),
        ("XOR", ["BYTE", "BYTE"], (0xF0, 0x3C), 0xCC),
        ("NOT", ["BYTE"], (0xF0,), 0x0F),
        ("XOR", ["BOOL"] * 3, (True, True, True), True),
        ("AND", ["WORD", "WORD"], (0x00FF, 0x0F0F), 0x000F),  # APB-02
        ("OR", ["WORD", "WORD"], (0x00FF, 0x0F0F), 0x0FFF),
        ("XOR", ["WORD", "WORD"], (0x00FF, 0x0F0F), 0x0FF0),
        ("NOT", ["WORD"], (0x00FF,), 0xFF00),
        ("NOT", ["WORD"], (0b0000001100110011,), 0b1111110011001100),  # ST-35e
        ("NOT", ["LWORD"], (0,), 2**64 - 1),
        ("AND", ["BOOL"] * 3, (True, True, False), False),  # ST-35m
        ("OR", ["BOOL"] * 3, (False, False, True), True),  # ST-35n
        ("NOT", ["BOOL"], (True,), False),
    ],
)
def test_bitwise_vectors_FUN_50(name, types, args, expected):
    result = call(name, types, types[0], *args)
    assert result == expected and type(result) is type(expected)


@given(st.lists(st.booleans(), min_size=2, max_size=9))
def test_extensible_xor_is_parity_ST_35p(values):
    assert call("XOR", ["BOOL"] * len(values), "BOOL", *values) is (sum(values) % 2 == 1)


@pytest.mark.parametrize("name", ["AND", "OR", "XOR"])
def test_bitwise_rejects_numbers(name):
    with pytest.raises(TypeError):
        make_function(name, ["REAL", "REAL"], "REAL")


# --- FUN-60..62, APB-09: selection --------------------------------------------------------------


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("SEL", ["BOOL", "INT", "INT"], (False, 1, 2), 1),  # FUN-62
        ("SEL", ["BOOL", "INT", "INT"], (True, 1, 2), 2),
        ("SEL", ["BOOL", "STRING", "STRING"], (True, "a", "b"), "b"),
        ("MAX", ["INT"] * 3, (3, 7, 5), 7),
        ("MIN", ["INT"] * 3, (3, 7, 5), 3),
        ("MAX", ["TIME", "TIME"], (ms(s=1), ms(s=2)), ms(s=2)),
        ("MAX", ["INT", "INT"], (-4, 1), 1),  # APB-09
        ("MIN", ["INT", "INT"], (7, 2), 2),
        ("MAX", ["STRING", "STRING"], ("abc", "abd"), "abd"),
        ("LIMIT", ["INT"] * 3, (0, 150, 100), 100),  # FUN-62
        ("LIMIT", ["INT"] * 3, (0, -5, 100), 0),
        ("LIMIT", ["INT"] * 3, (0, 50, 100), 50),
        ("LIMIT", ["INT"] * 3, (-8, -20, 5), -8),  # APB-09
        ("LIMIT", ["INT"] * 3, (-8, 9, 5), 5),
        ("LIMIT", ["INT"] * 3, (-8, 3, 5), 3),
        ("LIMIT", ["INT"] * 3, (10, 5, 0), 0),  # MN > MX: MIN(MAX(IN, MN), MX) = MX, literally
        ("LIMIT", ["REAL"] * 3, (0.0, 1.5, 1.0), 1.0),
        ("MUX", ["INT"] * 4, (1, 10, 20, 30), 20),  # FUN-62
        ("MUX", ["INT", "INT", "INT", "DINT"], (0, 0, 10, 77), 0),  # APB-09 with B = 77
        ("MUX", ["INT", "INT", "INT", "DINT"], (1, 0, 10, 77), 10),
        ("MUX", ["INT", "INT", "INT", "DINT"], (2, 0, 10, 77), 77),
        ("MUX", ["USINT", "STRING", "STRING"], (1, "a", "b"), "b"),
    ],
)
def test_selection_vectors_FUN_60_62(name, types, args, expected):
    assert call(name, types, types[-1], *args) == expected


NAN = math.nan


@pytest.mark.parametrize(
    "name, types, args",
    [
        ("MAX", ["REAL"] * 2, (0.0, NAN)),
        ("MAX", ["REAL"] * 2, (NAN, 0.0)),
        ("MIN", ["LREAL"] * 2, (NAN, -1.0)),
        ("MIN", ["LREAL"] * 2, (-1.0, NAN)),
        ("MAX", ["REAL"] * 3, (1.0, NAN, 2.0)),
        ("MIN", ["REAL"] * 3, (1.0, 2.0, NAN)),
        ("LIMIT", ["REAL"] * 3, (0.0, NAN, 1.0)),
        ("LIMIT", ["REAL"] * 3, (NAN, 0.5, 1.0)),
        ("LIMIT", ["LREAL"] * 3, (0.0, 0.5, NAN)),
    ],
)
def test_a_nan_argument_of_max_min_and_limit_gives_nan_whatever_its_place_FUN_60(name, types, args):
    """IEC leaves NaN to IEEE 754, whose 2019 maximum/minimum propagate it; a bare comparison would answer NaN or
    the other number depending on the order of the arguments."""
    assert math.isnan(call(name, types, types[-1], *args))


@pytest.mark.parametrize("k", [-1, 3, 100])
def test_mux_selector_out_of_range_is_a_fault_FUN_61(k):
    for form in (False, True):
        with pytest.raises(PlcRuntimeError) as caught:
            make_function("MUX", ["INT"] * 4, "INT", checked=form)(k, 10, 20, 30)
        assert caught.value.code == INDEX_RANGE
        assert f"MUX selector K {k} is outside 0..2" == caught.value.message


@given(st.lists(st.integers(-1000, 1000), min_size=2, max_size=6))
def test_extensible_max_min_match_python(values):
    n = len(values)
    assert call("MAX", ["DINT"] * n, "DINT", *values) == max(values)
    assert call("MIN", ["DINT"] * n, "DINT", *values) == min(values)


# --- FUN-70, FUN-71, APB-04: comparison -----------------------------------------------------------


@pytest.mark.parametrize(
    "name, args, expected",
    [
        ("GT", (5, 3, 1), True),  # FUN-71
        ("GT", (5, 3, 3), False),
        ("GE", (5, 3, 3), True),
        ("EQ", (2, 2, 2), True),
        ("EQ", (2, 2, 3), False),
        ("LT", (1, 2, 3), True),
        ("LT", (1, 3, 2), False),
        ("LE", (1, 1, 2), True),
        ("NE", (1, 2), True),
        ("NE", (2, 2), False),
        ("GT", (11, 10), True),  # ST-35g
        ("GT", (10, 10), False),
    ],
)
def test_comparison_vectors_FUN_71(name, args, expected):
    assert call(name, ["INT"] * len(args), "BOOL", *args) is expected


@pytest.mark.parametrize(
    "type_name, small, big",
    [
        ("INT", 3, 5),
        ("REAL", 3.0, 5.0),
        ("TIME", 3000, 5000),
        ("STRING", "abc", "abd"),
        ("TOD", ms(h=10, m=30), ms(h=10, m=45)),
    ],
)
def test_comparisons_on_every_kind_APB_04(type_name, small, big):
    results = {name: call(name, [type_name] * 2, "BOOL", small, big) for name in ("LT", "LE", "GE", "GT", "NE", "EQ")}
    assert results == {"LT": True, "LE": True, "GE": False, "GT": False, "NE": True, "EQ": False}
    results = {name: call(name, [type_name] * 2, "BOOL", big, big) for name in ("LT", "LE", "GE", "GT", "NE", "EQ")}
    assert results == {"LT": False, "LE": True, "GE": True, "GT": False, "NE": False, "EQ": True}


@given(st.lists(st.integers(-5, 5), min_size=2, max_size=6))
def test_extensible_comparison_is_pairwise_and_FUN_70(values):
    pairs = list(itertools.pairwise(values))
    n = len(values)
    assert call("GT", ["INT"] * n, "BOOL", *values) == all(a > b for a, b in pairs)
    assert call("LE", ["INT"] * n, "BOOL", *values) == all(a <= b for a, b in pairs)
    assert call("EQ", ["INT"] * n, "BOOL", *values) == all(a == b for a, b in pairs)


# --- type checks of the specialiser ------------------------------------------------------------------


@pytest.mark.parametrize(
    "name, types",
    [
        ("MOD", ["REAL", "REAL"]),  # FUN-32, APB-05: not for REAL
        ("EXPT", ["INT", "INT"]),  # FUN-33: the base is ANY_REAL
        ("SQRT", ["INT"]),
        ("ADD", ["BOOL", "BOOL"]),
        ("SEL", ["INT", "INT", "INT"]),
        ("MUX", ["REAL", "INT", "INT"]),
    ],
)
def test_unsupported_type_combinations_are_rejected(name, types):
    with pytest.raises(TypeError, match=name):
        make_function(name, types, types[-1])
