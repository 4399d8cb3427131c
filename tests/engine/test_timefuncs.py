"""Date and time functions (spec FUN-85..FUN-87) and + - * / on time operands (ST-21, ST-22)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.errors import DIVISION_BY_ZERO, INVALID_ARGUMENT, OVERFLOW, PlcRuntimeError
from ladderlab.engine.stdlib import make_function

from .helpers import DAY, date_ms, int_range, ms, reference_wrap

TIME_MIN, TIME_MAX = int_range("TIME")


def call(name, types, *args):
    return make_function(name, types, None)(*args)


def checked(name, types, *args):
    return make_function(name, types, None, checked=True)(*args)


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("ADD_TIME", ["TIME", "TIME"], (ms(h=1), ms(m=30)), ms(h=1, m=30)),  # FUN-86
        ("ADD_TOD_TIME", ["TOD", "TIME"], (ms(h=23), ms(h=2)), ms(h=1)),  # wraps modulo 24 h
        ("ADD_DT_TIME", ["DT", "TIME"], (date_ms("2003-06-21 23:00"), ms(h=2)), date_ms("2003-06-22 01:00")),
        ("SUB_TIME", ["TIME", "TIME"], (ms(s=1), 1500), -500),
        ("SUB_DATE_DATE", ["DATE", "DATE"], (date_ms("2003-06-21"), date_ms("2003-06-20")), ms(d=1)),
        ("SUB_TOD_TOD", ["TOD", "TOD"], (ms(h=12), ms(h=10, m=30)), ms(h=1, m=30)),
        ("SUB_TOD_TOD", ["TOD", "TOD"], (ms(h=10), ms(h=12)), -ms(h=2)),
        ("SUB_TOD_TIME", ["TOD", "TIME"], (ms(h=1), ms(h=2)), ms(h=23)),
        ("SUB_DT_TIME", ["DT", "TIME"], (date_ms("2003-06-22 01:00"), ms(h=2)), date_ms("2003-06-21 23:00")),
        (
            "SUB_DT_DT",
            ["DT", "DT"],
            (date_ms("2003-06-21 11:38:52.350"), date_ms("2003-06-21")),
            ms(h=11, m=38, s=52, millis=350),
        ),
        ("MUL_TIME", ["TIME", "INT"], (ms(s=2), 3), ms(s=6)),
        ("MULTIME", ["TIME", "REAL"], (ms(s=2), 1.5), ms(s=3)),  # the seed's spelling
        ("DIV_TIME", ["TIME", "INT"], (ms(s=6), 4), 1500),
        ("DIVTIME", ["TIME", "DINT"], (-7, 2), -3),  # toward zero like integer DIV
        ("DIV_TIME", ["TIME", "LREAL"], (ms(s=1), 3.0), 333),
        ("MUL_TIME", ["TIME", "REAL"], (1, 2.5), 2),  # ties to even like REAL_TO_*
        (
            "CONCAT_DATE_TOD",
            ["DATE", "TOD"],
            (date_ms("2003-06-21"), ms(h=11, m=38, s=52, millis=350)),
            date_ms("2003-06-21 11:38:52.350"),
        ),
    ],
)
def test_time_function_vectors_FUN_86(name, types, args, expected):
    assert call(name, types, *args) == expected
    assert checked(name, types, *args) == (expected, None)


@pytest.mark.parametrize(
    "op, types, args, expected",
    [
        ("ADD", ["TIME", "TIME"], (ms(h=1), ms(m=30)), ms(h=1, m=30)),  # FUN-85 [REC]: + on times
        ("ADD", ["TIME", "TIME", "TIME"], (1, 2, 3), 6),
        ("ADD", ["TOD", "TIME"], (ms(h=23), ms(h=2)), ms(h=1)),
        ("ADD", ["DT", "TIME"], (0, ms(d=1)), ms(d=1)),
        ("SUB", ["TIME", "TIME"], (1000, 1500), -500),
        ("SUB", ["DATE", "DATE"], (ms(d=2), ms(d=1)), ms(d=1)),
        ("SUB", ["TOD", "TOD"], (ms(h=2), ms(h=1)), ms(h=1)),
        ("SUB", ["DT", "DT"], (ms(d=1), 0), ms(d=1)),
        ("SUB", ["DT", "TIME"], (ms(d=1), ms(h=1)), ms(h=23)),
        ("MUL", ["TIME", "INT"], (ms(s=2), 3), ms(s=6)),  # ST-21: t1 := t2 * i4
        ("DIV", ["TIME", "INT"], (ms(s=6), 4), 1500),  # ST-21: t1 := t2 / i4
        ("MUL", ["TIME", "REAL"], (ms(s=2), 1.5), ms(s=3)),
    ],
)
def test_operators_on_time_operands_FUN_85(op, types, args, expected):
    assert call(op, types, *args) == expected


@pytest.mark.parametrize(
    "name, types, args, expected",
    [
        ("SUB_DATE_DATE", ["DATE", "DATE"], (ms(d=30), 0), TIME_MAX),  # FUN-87: saturated, ENO FALSE
        ("SUB_DATE_DATE", ["DATE", "DATE"], (0, ms(d=30)), TIME_MIN),
        ("SUB_DT_DT", ["DT", "DT"], (date_ms("2003-06-21"), 0), TIME_MAX),
        ("ADD_TIME", ["TIME", "TIME"], (TIME_MAX, 1), TIME_MIN),  # TIME wraps (FUN-90)
        ("MUL_TIME", ["TIME", "INT"], (ms(d=20), 2), reference_wrap(ms(d=40), "TIME")),
        ("SUB_DT_TIME", ["DT", "TIME"], (ms(h=1), ms(h=2)), 0),  # no DT before the epoch
    ],
)
def test_time_overflow_is_reported_FUN_87(name, types, args, expected):
    assert call(name, types, *args) == expected
    value, warning = checked(name, types, *args)
    assert value == expected and warning.code == OVERFLOW


@pytest.mark.parametrize(
    "name, types, args", [("DIV_TIME", ["TIME", "INT"], (1000, 0)), ("DIV_TIME", ["TIME", "REAL"], (1000, 0.0))]
)
def test_dividing_a_time_by_zero_is_a_fault(name, types, args):
    with pytest.raises(PlcRuntimeError) as caught:
        call(name, types, *args)
    assert caught.value.code == DIVISION_BY_ZERO


@pytest.mark.parametrize("factor", [math.nan, math.inf])
def test_scaling_a_time_by_a_non_number_gives_zero_and_a_warning(factor):
    assert call("MUL_TIME", ["TIME", "LREAL"], 1000, factor) == 0
    value, warning = checked("MUL_TIME", ["TIME", "LREAL"], 1000, factor)
    assert value == 0 and warning.code == INVALID_ARGUMENT


@given(tod=st.integers(0, DAY - 1), delta=st.integers(TIME_MIN, TIME_MAX))
def test_tod_arithmetic_stays_within_a_day(tod, delta):
    added = call("ADD_TOD_TIME", ["TOD", "TIME"], tod, delta)
    assert 0 <= added < DAY and (added - tod - delta) % DAY == 0
    assert call("SUB_TOD_TIME", ["TOD", "TIME"], added, delta) == tod


@given(day=st.integers(0, 2_900_000), tod=st.integers(0, DAY - 1))
def test_concat_and_split_of_date_and_time_round_trip(day, tod):
    moment = call("CONCAT_DATE_TOD", ["DATE", "TOD"], day * DAY, tod)
    assert make_function("DT_TO_DATE", ["DT"])(moment) == day * DAY
    assert make_function("DT_TO_TOD", ["DT"])(moment) == tod


@pytest.mark.parametrize(
    "name, types", [("ADD_TIME", ["TIME", "INT"]), ("ADD_TOD_TIME", ["TIME", "TOD"]), ("MUL_TIME", ["TIME", "TIME"])]
)
def test_time_functions_check_argument_types(name, types):
    with pytest.raises(TypeError):
        make_function(name, types)
