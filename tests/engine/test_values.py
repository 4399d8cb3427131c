"""The value model (spec TYP-03, TYP-04, TYP-05, FUN-90) and user writes (coerce)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.iec.elementary import DEFAULT_STRING_LENGTH
from ladderlab.iec.values import (
    DT_MAX,
    FLT_MAX,
    INLINE_NAMES,
    article,
    coerce,
    default_value,
    f32,
    resolve,
    store_expr,
    store_fn,
    value_range,
    wrap,
    wrap_expr,
    wrap_fn,
)

from .helpers import BIT_TYPES, DAY, INT_TYPES, date_ms, int_range, is_float32, ms, reference_wrap

WRAPPING = INT_TYPES + BIT_TYPES + ["TIME"]


@pytest.mark.parametrize(
    "type_name, value, expected",
    [
        ("SINT", 127 + 1, -128),
        ("SINT", -128 - 1, 127),
        ("INT", 32767 + 1, -32768),  # the example; spec ST-90
        ("INT", -32768 - 1, 32767),
        ("DINT", 2**31, -(2**31)),
        ("LINT", 2**63, -(2**63)),
        ("USINT", 256, 0),
        ("USINT", -1, 255),
        ("UINT", 65536, 0),
        ("UDINT", -1, 2**32 - 1),
        ("ULINT", 2**64 + 5, 5),
        ("BYTE", 0x1FF, 0xFF),
        ("WORD", -1, 0xFFFF),
        ("DWORD", 2**32, 0),
        ("LWORD", -1, 2**64 - 1),
        ("TIME", 2**31, -(2**31)),  # TYP-03: TIME is signed 32-bit ms
        ("INT", 1234, 1234),
    ],
)
def test_wrap_at_every_width_FUN_90(type_name, value, expected):
    assert wrap(value, type_name) == expected
    assert eval(wrap_expr("x", type_name), {"x": value}) == expected


@pytest.mark.parametrize("type_name", WRAPPING)
@given(value=st.integers(min_value=-(2**70), max_value=2**70))
def test_wrap_is_in_range_and_congruent_FUN_90(type_name, value):
    lo, hi = int_range(type_name)
    result = wrap_fn(type_name)(value)
    assert lo <= result <= hi
    assert (result - value) % (hi - lo + 1) == 0
    assert result == reference_wrap(value, type_name)


@pytest.mark.parametrize("type_name", ["BOOL", "REAL", "STRING", "TIME_OF_DAY", "DATE"])
def test_wrap_refuses_types_that_do_not_wrap(type_name):
    with pytest.raises(ValueError, match="does not wrap"):
        wrap_fn(type_name)


@pytest.mark.parametrize(
    "x, expected",
    [
        (0.1, 0.10000000149011612),
        (11.2, 11.199999809265137),  # TYP-03 / ST-43: intervals[5] = 11.2 holds after both are rounded
        (16777217.0, 16777216.0),  # 2**24 + 1 is not a float32: ties to even
        (16777219.0, 16777220.0),
        (3.5e38, math.inf),  # beyond FLT_MAX: IEEE overflow
        (-3.5e38, -math.inf),
        (FLT_MAX, FLT_MAX),
        pytest.param(10**400, math.inf, id="int-too-large-for-a-double"),
        (-0.0, -0.0),
    ],
)
def test_f32_rounds_like_ieee_single_TYP_03(x, expected):
    assert f32(x) == expected
    assert math.copysign(1, f32(x)) == math.copysign(1, expected)


def test_f32_keeps_nan():
    assert math.isnan(f32(math.nan))


@given(st.floats(allow_nan=False))
def test_f32_result_is_float32_and_idempotent_TYP_03(x):
    y = f32(x)
    assert is_float32(y)
    assert f32(y) == y
    if math.isfinite(y) and abs(y) >= 2**-126:  # normal range: nearest means within half an ulp
        assert abs(y - x) <= abs(x) * 2**-24


@pytest.mark.parametrize(
    "type_name, value, expected",
    [
        ("INT", 40000, -25536),
        ("REAL", 0.1, 0.10000000149011612),
        ("LREAL", 0.1, 0.1),
        ("TIME_OF_DAY", DAY + 5, 5),  # FUN-86: modulo 24 h
        ("TOD", -1, DAY - 1),
        ("DATE_AND_TIME", -5, 0),  # saturates at the epoch
        ("DT", DT_MAX + 1, DT_MAX),
        ("STRING", "x" * 100, "x" * DEFAULT_STRING_LENGTH),  # TYP-04
        ("STRING[3]", "abcdef", "abc"),
        ("BOOL", True, True),
    ],
)
def test_store_rules_TYP_03(type_name, value, expected):
    assert store_fn(type_name)(value) == expected
    assert eval(store_expr("x", type_name), dict(INLINE_NAMES, x=value)) == expected


@pytest.mark.parametrize(
    "type_name, expected",
    [
        ("BOOL", False),
        ("SINT", 0),
        ("INT", 0),
        ("DINT", 0),
        ("USINT", 0),
        ("UINT", 0),
        ("UDINT", 0),
        ("BYTE", 0),
        ("WORD", 0),
        ("DWORD", 0),
        ("REAL", 0.0),
        ("LREAL", 0.0),
        ("TIME", 0),  # T#0s
        ("DATE", 0),  # D#1970-01-01
        ("TIME_OF_DAY", 0),  # TOD#00:00:00
        ("DATE_AND_TIME", 0),  # DT#1970-01-01-00:00:00
        ("STRING", ""),
    ],
)
def test_default_values_TYP_05(type_name, expected):
    value = default_value(type_name)
    assert value == expected and type(value) is type(expected)


@pytest.mark.parametrize(
    "type_name, expected",
    [
        ("tod", ("TIME_OF_DAY", 0)),
        ("DT", ("DATE_AND_TIME", 0)),
        ("string[20]", ("STRING", 20)),
        ("STRING", ("STRING", 80)),
    ],
)
def test_resolve_aliases_and_string_lengths_TYP_01(type_name, expected):
    ref = resolve(type_name)
    assert (ref.name, ref.length) == expected


@pytest.mark.parametrize("type_name", ["FOO", "STRING[0]", "STRING[256]", "ANY_INT"])
def test_resolve_rejects_non_elementary(type_name):
    with pytest.raises(ValueError):
        resolve(type_name)


def test_value_ranges():
    assert value_range("INT") == (-32768, 32767)
    assert value_range("TOD") == (0, DAY - 1)
    assert value_range("REAL") is None


@pytest.mark.parametrize(
    "value, type_name, expected",
    [
        (True, "BOOL", True),
        ("false", "BOOL", False),
        (1, "BOOL", True),
        ("TRUE", "BOOL", True),
        (32767, "INT", 32767),
        ("-32768", "INT", -32768),
        ("16#FF", "BYTE", 255),
        ("2#1001_0110", "BYTE", 0x96),
        ("8#17", "USINT", 15),
        ("INT#-5", "INT", -5),
        ("1_000", "DINT", 1000),
        (5.0, "INT", 5),
        ("2.5", "REAL", 2.5),
        ("1.0E3", "LREAL", 1000.0),
        (11.2, "REAL", 11.199999809265137),
        (7, "LREAL", 7.0),
        ("T#1h30m", "TIME", ms(h=1, m=30)),
        ("t#-500ms", "TIME", -500),
        ("TIME#1.5s", "TIME", 1500),
        ("T#1d_2h", "TIME", ms(d=1, h=2)),
        ("500", "TIME", 500),  # ST-26: a bare number is milliseconds
        (1500, "TIME", 1500),
        ("TOD#11:38:52.35", "TOD", ms(h=11, m=38, s=52, millis=350)),
        ("23:59:59.999", "TIME_OF_DAY", DAY - 1),
        ("D#2003-06-21", "DATE", date_ms("2003-06-21")),
        ("DATE#1970-01-01", "DATE", 0),
        ("DT#2003-06-21-11:38:52.35", "DT", date_ms("2003-06-21 11:38:52.350")),
        ("abc", "STRING[3]", "abc"),
    ],
)
def test_coerce_accepts_user_values(value, type_name, expected):
    result = coerce(value, type_name)
    assert result == expected and type(result) is type(expected)


@pytest.mark.parametrize(
    "value, type_name, message",
    [
        (40000, "INT", r"^40000 is out of range for INT \(-32768\.\.32767\)$"),
        ("abc", "INT", r"^'abc' is not an INT$"),
        ("-1", "UINT", r"^-1 is out of range for UINT \(0\.\.65535\)$"),
        (2.5, "INT", r"^2\.5 is not an INT$"),
        (True, "INT", r"is not an INT"),
        ("16#1FF", "BYTE", r"511 is out of range for BYTE"),
        ("2#102", "BYTE", r"is not a BYTE"),
        ("REAL#5", "INT", r"is not an INT"),  # a prefix naming another type
        (2, "BOOL", r"is not a BOOL"),
        ("yes", "BOOL", r"is not a BOOL"),
        (1e39, "REAL", r"out of range for REAL"),
        pytest.param(10**400, "LREAL", r"out of range for LREAL", id="huge-LREAL"),
        (math.nan, "REAL", r"is not a REAL"),
        ("1.5.2", "REAL", r"is not a REAL"),
        ("T#25d", "TIME", r"^T#25d is out of range for TIME \(T#-24d20h31m23s648ms\.\.T#24d20h31m23s647ms\)$"),
        ("T#1x", "TIME", r"is not a TIME"),
        ("24:00:00", "TOD", r"is not a TIME_OF_DAY"),
        (DAY, "TOD", r"out of range for TIME_OF_DAY"),
        ("D#1969-12-31", "DATE", r"is not a DATE"),  # before the epoch (LEX-53)
        ("D#2003-02-30", "DATE", r"is not a DATE"),
        (5, "DATE", r"not at a day boundary"),
        ("x" * 81, "STRING", r"longer than STRING\[80\] \(81 > 80 characters\)"),
        (5, "STRING", r"is not a STRING"),
        ("", "INT", r"is not an INT"),
    ],
)
def test_coerce_rejects_with_a_clear_message(value, type_name, message):
    with pytest.raises(ValueError, match=message):
        coerce(value, type_name)


@pytest.mark.parametrize("type_name", WRAPPING)
@given(data=st.data())
def test_coerce_accepts_exactly_the_range(type_name, data):
    lo, hi = int_range(type_name)
    inside = data.draw(st.integers(lo, hi))
    assert coerce(inside, type_name) == inside
    assert coerce(str(inside), type_name) == inside
    outside = data.draw(st.one_of(st.integers(max_value=lo - 1), st.integers(min_value=hi + 1)))
    with pytest.raises(ValueError, match="out of range"):
        coerce(outside, type_name)


def test_type_names_take_the_article_they_are_read_aloud_with():
    """Messages say 'an LREAL' (el-real) and 'an SINT' (ess-int), 'a STRING' and 'a UINT' (you-int)."""
    assert [article(t) for t in ("INT", "REAL", "LREAL", "LWORD", "LTIME", "SINT", "STRING", "UINT", "ULINT")] == [
        "an INT",
        "a REAL",
        "an LREAL",
        "an LWORD",
        "an LTIME",
        "an SINT",
        "a STRING",
        "a UINT",
        "a ULINT",
    ]
