"""Type conversions <SRC>_TO_<DST> and TRUNC (spec FUN-10, FUN-11, APB-06)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.errors import INVALID_ARGUMENT, NOT_A_NUMBER, OVERFLOW, TRUNCATED, PlcRuntimeError
from ladderlab.engine.stdlib import STANDARD_FUNCTIONS, convert, converter, make_function
from ladderlab.iec.elementary import ALIASES, ELEMENTARY
from ladderlab.iec.values import default_value, resolve

from .helpers import BIT_TYPES, DAY, INT_TYPES, date_ms, int_range, ms, reference_wrap

MOMENT = date_ms("2003-06-21 11:38:52.350")


@pytest.mark.parametrize(
    "name, arg, expected",
    [
        ("REAL_TO_INT", 2.5, 2),  # FUN-11: ties to even (IEC 3rd edition)
        ("REAL_TO_INT", 3.5, 4),
        ("REAL_TO_INT", -1.6, -2),
        ("REAL_TO_INT", -2.5, -2),
        ("LREAL_TO_DINT", 0.5, 0),
        ("LREAL_TO_DINT", 1.4999, 1),
        ("TRUNC", 2.7, 2),  # FUN-11: toward zero
        ("TRUNC", -2.7, -2),
        ("TRUNC", 4.32, 4),  # APB-06, issue seed example
        ("TRUNC", -4.32, -4),
        ("INT_TO_SINT", 200, -56),  # FUN-11: narrowing wraps
        ("DINT_TO_UINT", -1, 65535),
        ("USINT_TO_UDINT", 200, 200),  # seed example
        ("INT_TO_REAL", 5, 5.0),  # seed example
        ("DINT_TO_REAL", 16777217, 16777216.0),  # rounds to float32
        ("DINT_TO_LREAL", 16777217, 16777217.0),
        ("LREAL_TO_REAL", 0.1, 0.10000000149011612),
        ("REAL_TO_LREAL", 0.10000000149011612, 0.10000000149011612),
        ("BOOL_TO_INT", True, 1),  # FUN-11
        ("BOOL_TO_REAL", True, 1.0),
        ("INT_TO_BOOL", 5, True),  # x <> 0
        ("INT_TO_BOOL", 0, False),
        ("REAL_TO_BOOL", 0.5, True),
        ("BYTE_TO_WORD", 0xFF, 0xFF),
        ("WORD_TO_BYTE", 0x1234, 0x34),
        ("WORD_TO_INT", 0xFFFF, -1),
        ("INT_TO_WORD", -1, 0xFFFF),
        ("TIME_TO_DINT", ms(s=1), 1000),  # FUN-11: milliseconds
        ("DINT_TO_TIME", -5, -5),
        ("REAL_TO_TIME", 1.5, 2),
        ("TIME_TO_REAL", 1500, 1500.0),
        ("TIME_TO_TOD", ms(h=25), ms(h=1)),  # FUN-11 [REC]: modulo 24 h
        ("TIME_TO_TOD", -1, DAY - 1),
        ("TOD_TO_TIME", ms(h=23), ms(h=23)),
        ("DT_TO_TOD", MOMENT, ms(h=11, m=38, s=52, millis=350)),  # FUN-86
        ("DT_TO_DATE", MOMENT, date_ms("2003-06-21")),
        ("DATE_AND_TIME_TO_TIME_OF_DAY", MOMENT, ms(h=11, m=38, s=52, millis=350)),  # FUN-10 long names
        ("DATE_AND_TIME_TO_DATE", MOMENT, date_ms("2003-06-21")),
        ("DATE_TO_DT", date_ms("2003-06-21"), date_ms("2003-06-21")),
        ("UDINT_TO_DT", 5 * DAY + 7, 5 * DAY + 7),
        ("DT_TO_UDINT", MOMENT, MOMENT % 2**32),
        ("INT_TO_STRING", -25, "-25"),  # FUN-11: no padding
        ("BOOL_TO_STRING", True, "TRUE"),
        ("BYTE_TO_STRING", 255, "255"),
        ("REAL_TO_STRING", 0.10000000149011612, "0.1"),  # shortest text that reads back as the same REAL
        ("REAL_TO_STRING", 11.199999809265137, "11.2"),
        ("REAL_TO_STRING", 3.0, "3.0"),
        ("LREAL_TO_STRING", 1e20, "1.0E20"),
        ("LREAL_TO_STRING", -1.5e-7, "-1.5E-7"),
        ("TIME_TO_STRING", ms(h=1, m=30), "T#1h30m"),
        ("TIME_TO_STRING", -500, "T#-500ms"),
        ("TIME_TO_STRING", 0, "T#0s"),
        ("TOD_TO_STRING", ms(h=11, m=38, s=52, millis=350), "TOD#11:38:52.35"),
        ("TOD_TO_STRING", 0, "TOD#00:00:00"),
        ("DATE_TO_STRING", date_ms("2003-06-21"), "D#2003-06-21"),
        ("DT_TO_STRING", MOMENT, "DT#2003-06-21-11:38:52.35"),
        ("STRING_TO_INT", "-25", -25),
        ("STRING_TO_INT", "16#7F", 127),
        ("STRING_TO_BOOL", "TRUE", True),
        ("STRING_TO_REAL", "1.5", 1.5),
        ("STRING_TO_LREAL", "5", 5.0),
        ("STRING_TO_TIME", "T#1h30m", ms(h=1, m=30)),
        ("STRING_TO_TOD", "TOD#11:38:52.35", ms(h=11, m=38, s=52, millis=350)),
        ("STRING_TO_DT", "DT#2003-06-21-11:38:52.35", MOMENT),
    ],
)
def test_conversion_vectors_FUN_11(name, arg, expected):
    src = "REAL" if name == "TRUNC" else name.split("_TO_")[0]
    result = make_function(name, [src], "DINT" if name == "TRUNC" else None)(arg)
    assert result == expected and type(result) is type(expected)


@pytest.mark.parametrize(
    "name, arg, expected, code",
    [
        ("INT_TO_SINT", 200, -56, OVERFLOW),  # FUN-11: run-time warning flag
        ("REAL_TO_INT", 40000.0, -25536, OVERFLOW),
        ("REAL_TO_INT", math.nan, 0, INVALID_ARGUMENT),
        ("LREAL_TO_DINT", math.inf, 0, INVALID_ARGUMENT),
        ("LREAL_TO_REAL", 1e300, math.inf, OVERFLOW),
        ("STRING_TO_INT", "abc", 0, NOT_A_NUMBER),  # FUN-11: 0 with ENO FALSE
        ("STRING_TO_INT", "40000", -25536, OVERFLOW),
        ("STRING_TO_TIME", "soon", 0, NOT_A_NUMBER),
        ("STRING_TO_BOOL", "maybe", False, NOT_A_NUMBER),
    ],
)
def test_lossy_conversions_warn_in_the_checked_form(name, arg, expected, code):
    src = name.split("_TO_")[0]
    assert make_function(name, [src])(arg) == expected
    value, warning = make_function(name, [src], checked=True)(arg)
    assert value == expected and warning.code == code


@pytest.mark.parametrize(
    "name, arg, message",
    [
        ("TIME_TO_DATE", -1, "TIME_TO_DATE gives -86400000 ms, outside DATE (D#1970-01-01..D#9999-12-31)"),
        (
            "DT_TO_TIME",
            MOMENT,
            f"DATE_AND_TIME_TO_TIME gives {MOMENT} ms, outside TIME (T#-24d20h31m23s648ms..T#24d20h31m23s647ms)",
        ),
        (
            "LTIME_TO_TIME",
            30 * DAY * 1_000_000,
            f"LTIME_TO_TIME gives {30 * DAY} ms, outside TIME (T#-24d20h31m23s648ms..T#24d20h31m23s647ms)",
        ),
    ],
)
def test_a_duration_or_date_outside_its_type_faults_and_is_eno_false_in_the_checked_form(name, arg, message):
    """No wrapped or saturated TIME, DATE or DT stands in for a conversion's result (issue 25): the plain call faults
    ``overflow``; with ENO wired the checked form gives ENO FALSE (IEC 61131-3 ed. 3 6.6.2.2) with the old value."""
    src = name.split("_TO_")[0]
    with pytest.raises(PlcRuntimeError) as fault:
        make_function(name, [src])(arg)
    assert (fault.value.code, fault.value.message) == (OVERFLOW, message)
    assert make_function(name, [src], checked=True)(arg)[1].code == OVERFLOW


@pytest.mark.parametrize("name, arg", [("TRUNC", math.nan), ("TRUNC", -math.inf)])
def test_trunc_of_non_finite_is_zero_with_a_warning(name, arg):
    assert make_function(name, ["LREAL"], "DINT", checked=True)(arg)[0] == 0
    assert make_function(name, ["LREAL"], "DINT", checked=True)(arg)[1].code == INVALID_ARGUMENT


def test_to_string_is_cut_to_the_result_length():
    assert make_function("INT_TO_STRING", ["INT"], "STRING[2]")(-25) == "-2"
    value, warning = make_function("INT_TO_STRING", ["INT"], "STRING[2]", checked=True)(-25)
    assert value == "-2" and warning.code == TRUNCATED


@pytest.mark.parametrize("src", INT_TYPES + BIT_TYPES)
@given(data=st.data())
def test_integer_conversions_wrap_and_warn_exactly_when_out_of_range(src, data):
    value = data.draw(st.integers(*int_range(src)))
    for dst in INT_TYPES + BIT_TYPES:
        result, warning = converter(src, dst, checked=True)(value)
        lo, hi = int_range(dst)
        assert result == reference_wrap(value, dst)
        assert (warning is None) == (lo <= value <= hi)


@pytest.mark.parametrize("src", INT_TYPES + BIT_TYPES)
@given(data=st.data())
def test_widening_round_trips_are_lossless(src, data):
    value = data.draw(st.integers(*int_range(src)))
    lo, hi = int_range(src)
    for wide in INT_TYPES + BIT_TYPES + ["LREAL"]:
        if wide == "LREAL":
            if max(abs(lo), abs(hi)) > 2**53:
                continue
        elif not (int_range(wide)[0] <= lo and hi <= int_range(wide)[1]):
            continue
        assert convert(convert(value, src, wide), wide, src) == value


@given(st.floats(width=32, allow_nan=False, allow_infinity=False))
def test_real_lreal_and_string_round_trips(x):
    assert convert(convert(x, "REAL", "LREAL"), "LREAL", "REAL") == x
    text = convert(x, "REAL", "STRING")
    assert convert(text, "STRING", "REAL") == x
    assert len(text) <= 16


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_lreal_string_round_trip(x):
    assert convert(convert(x, "LREAL", "STRING"), "STRING", "LREAL") == x


@pytest.mark.parametrize("type_name", INT_TYPES + BIT_TYPES + ["TIME", "TOD", "DATE", "DT", "BOOL"])
@given(data=st.data())
def test_to_string_and_back_is_the_identity(type_name, data):
    if type_name == "BOOL":
        value = data.draw(st.booleans())
    elif type_name == "TOD":
        value = data.draw(st.integers(0, DAY - 1))
    elif type_name in ("DATE", "DT"):
        value = data.draw(st.integers(0, date_ms("9999-12-31 23:59:59.999")))
        value -= value % DAY if type_name == "DATE" else 0
    else:
        value = data.draw(st.integers(*int_range("DINT" if type_name == "TIME" else type_name)))
    assert convert(convert(value, type_name, "STRING[255]"), "STRING", type_name) == value


def test_every_pair_of_spellings_is_registered_FUN_10():
    spellings = [*ELEMENTARY, *ALIASES]
    pairs = [(a, b) for a in spellings for b in spellings if resolve(a).name != resolve(b).name]
    assert len(pairs) > 400
    for a, b in pairs:
        assert f"{a}_TO_{b}" in STANDARD_FUNCTIONS


@pytest.mark.parametrize("src", [*ELEMENTARY])
def test_defaults_convert_to_defaults(src):
    """Every non-STRING conversion maps the zero of one type to the zero of the other."""
    for dst in ELEMENTARY:
        if dst not in (src, "STRING"):
            result = make_function(f"{src}_TO_{dst}", [src])(default_value(src))
            assert result == default_value(dst) and type(result) is type(default_value(dst))


def test_conversion_checks_its_argument_type():
    with pytest.raises(TypeError):
        make_function("INT_TO_REAL", ["DINT"])
    assert make_function("TOD_TO_TIME", ["TIME_OF_DAY"])(5) == 5
