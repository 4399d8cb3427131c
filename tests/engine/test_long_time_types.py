"""LTIME, LDATE, LTIME_OF_DAY and LDATE_AND_TIME (IEC 61131-3 ed. 3, 6.4.2 Table 10: 64-bit, nanosecond
resolution; literals of Tables 8 and 9 with the LT#, LTIME#, LD#, LDATE#, LTOD#, LDT# prefixes) - issue 25, item 4.

Expected values are nanosecond counts computed here from the calendar (``datetime``) and unit arithmetic, not read
from the engine.
"""

from __future__ import annotations

import datetime as dt

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.iec.literals import decode_time_literal, encode_time_literal
from ladderlab.iec.value_text import format_value, parse
from ladderlab.iec.values import coerce
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.simulation.build import build_project
from ladderlab.st.parser import parse_expression
from ladderlab.st.printer import print_expression
from ladderlab.st.project_text import source_to_project

from .ed3_support import errors, program, scans

NS = 1
US, MS, S = 1000 * NS, 1_000_000 * NS, 1_000_000_000 * NS
M, H = 60 * S, 3600 * S
DAY = 24 * H


def ns_since_epoch(text: str) -> int:
    """'2024-01-01' or '2024-01-01 12:30:00' as nanoseconds since 1970-01-01 (no time zone)."""
    return (dt.datetime.fromisoformat(text) - dt.datetime(1970, 1, 1)) // dt.timedelta(microseconds=1) * US


@pytest.mark.parametrize(
    "literal, kind, value",
    [
        ("LTIME#100ms", "LTIME", 100 * MS),
        ("LT#1.5us", "LTIME", 1500),
        ("ltime#-1d2h3m4s5ms6us7ns", "LTIME", -(DAY + 2 * H + 3 * M + 4 * S + 5 * MS + 6 * US + 7)),
        ("LTIME#106751d23h47m16s854ms775us807ns", "LTIME", (1 << 63) - 1),  # the largest LTIME, exactly
        ("LDATE#2024-01-01", "LDATE", ns_since_epoch("2024-01-01")),
        ("LD#2024-02-29", "LDATE", ns_since_epoch("2024-02-29")),
        ("LTOD#12:30:00", "LTIME_OF_DAY", 12 * H + 30 * M),
        ("LTIME_OF_DAY#23:59:59.999999999", "LTIME_OF_DAY", DAY - 1),
        ("LDT#2024-01-01-12:30:00", "LDATE_AND_TIME", ns_since_epoch("2024-01-01 12:30:00")),
        ("LDATE_AND_TIME#2024-01-01-00:00:00.000000001", "LDATE_AND_TIME", ns_since_epoch("2024-01-01") + 1),
    ],
)
def test_long_literals_decode_to_exact_nanoseconds_and_print_back(literal, kind, value):
    assert decode_time_literal(literal) == (kind, value)
    parsed = parse_expression(literal)
    assert parsed.ok and (parsed.ast.kind, parsed.ast.value) == (kind, value)
    assert decode_time_literal(print_expression(parsed.ast)) == (kind, value)


@given(st.integers(min_value=-(1 << 63), max_value=(1 << 63) - 1))
def test_any_ltime_prints_as_a_literal_that_reads_back_exactly(ns):
    assert decode_time_literal(encode_time_literal("LTIME", ns)) == ("LTIME", ns)
    assert parse(format_value(ns, "LTIME"), "LTIME") == ns


@given(st.integers(min_value=0, max_value=(1 << 63) - 1))
def test_any_ldt_prints_as_a_literal_that_reads_back_exactly(ns):
    assert decode_time_literal(encode_time_literal("LDATE_AND_TIME", ns)) == ("LDATE_AND_TIME", ns)


def test_online_text_and_writes_of_the_long_types():
    assert format_value(1500, "LTIME") == "LTIME#1us500ns"
    assert format_value(12 * H + 250, "LTOD") == "LTOD#12:00:00.00000025"
    assert format_value(ns_since_epoch("2024-01-01 12:30:00"), "LDT") == "LDT#2024-01-01-12:30:00"
    assert format_value(ns_since_epoch("2024-06-15"), "LDATE") == "LDATE#2024-06-15"
    assert coerce("LT#2s", "LTIME") == 2 * S
    assert coerce("T#2s", "LTIME") == 2 * S  # the short prefix is the same duration
    assert coerce("LTOD#00:00:00.5", "LTOD") == 500 * MS
    with pytest.raises(ValueError, match="not at a day boundary"):
        coerce(ns_since_epoch("2024-01-01") + 1, "LDATE")
    with pytest.raises(ValueError, match="not a TIME"):
        coerce("LT#1s", "TIME")


def test_long_arithmetic_and_comparisons_scan_by_scan():
    text = program(
        "a : LTIME := LT#1s; step : LTIME := LTIME#1us500ns; n : LINT;"
        "lt_tod : LTOD := LTOD#23:00:00; moment : LDT := LDT#2024-01-01-12:00:00; day : LDATE;"
        "later : BOOL; span : LTIME; back : LTOD; stamp : LDT;",
        "a := a + step * 2; n := LTIME_TO_LINT(a); later := a > LT#1s2us;"
        "lt_tod := lt_tod + LTIME#30m; back := LDT_TO_LTOD(moment); day := LDT_TO_LDATE(moment);"
        "span := moment - LDT#2024-01-01-00:00:00; stamp := CONCAT_LDATE_LTOD(day, back);",
        "",
    )
    seen = scans(text, 3, "a", "n", "later", "lt_tod", "span", "day", "back", "stamp")
    noon = ns_since_epoch("2024-01-01 12:00:00")
    for scan, values in enumerate(seen, start=1):
        a = S + scan * 3 * US
        tod = (23 * H + scan * 30 * M) % DAY  # wraps at midnight (FUN-86)
        assert values == [a, a, a > S + 2 * US, tod, 12 * H, ns_since_epoch("2024-01-01"), 12 * H, noon]


def test_conversions_between_ms_and_ns_forms():
    text = program(
        "t : TIME := T#1s500ms; lt : LTIME; short : TIME; neg : TIME; d : DATE := D#2024-01-01; ld : LDATE;"
        "dt1 : DT; r : LREAL;",
        "lt := TIME_TO_LTIME(t) + LTIME#999999ns; short := LTIME_TO_TIME(lt); neg := LTIME_TO_TIME(-lt);"
        "ld := DATE_TO_LDATE(d); dt1 := LDATE_TO_DT(ld); r := LTIME_TO_LREAL(lt);",
    )
    lt = 1500 * MS + 999_999
    assert scans(text, 1, "lt", "short", "neg", "ld", "dt1", "r") == [
        [lt, 1500, -1500, ns_since_epoch("2024-01-01"), ns_since_epoch("2024-01-01") // MS, float(lt)]
    ]


def test_ltime_wraps_at_64_bits():
    text = program("a : LTIME := LTIME#106751d23h47m16s854ms775us807ns; b : LTIME;", "b := a + LTIME#1ns;")
    assert scans(text, 1, "b") == [[-(1 << 63)]]


def test_struct_fields_and_arrays_of_long_types():
    types = "TYPE Stamp : STRUCT t : LTIME; moment : LDT; END_STRUCT; END_TYPE"
    text = program(
        "s : Stamp; log : ARRAY[1..2] OF LTOD; r : LTIME;", "s.t := LTIME#5s; r := s.t; log[2] := LTOD#1:2:3;", types
    )
    assert scans(text, 1, "r", "log[2]") == [[5 * S, H + 2 * M + 3 * S]]


@pytest.mark.parametrize(
    "body, message",
    [
        (
            "a := a + t;",
            "'+' needs operands of the same type: LTIME and TIME; convert one of them (e.g. TIME_TO_LTIME)",
        ),
        (
            "lt_tod := lt_tod + t;",
            "needs operands of the same type: LTIME_OF_DAY and TIME; convert one of them (e.g. TIME_TO_LTIME)",
        ),
        ("t := a;", "cannot assign LTIME to TIME without a conversion such as LTIME_TO_TIME"),
        ("a := T#1s;", "cannot assign TIME to LTIME without a conversion such as TIME_TO_LTIME"),
    ],
)
def test_a_long_and_a_short_time_do_not_mix_without_a_conversion(body, message):
    found = errors(program("a : LTIME; t : TIME; lt_tod : LTOD;", body))
    assert len(found) == 1 and message in found[0] and "ST-TYPE-MISMATCH" in found[0], found


def test_long_type_names_are_reserved_as_the_other_elementary_types():
    found = errors(program("LDT : INT;", "LDT := 1;"))
    assert any("ST-NAME" in e and "'LDT'" in e for e in found), found


def test_plcopen_round_trip_of_the_long_types():
    """TC6 XML 2.01 has no LTIME element: the long types travel as derived types and their literals as ST text."""
    text = program(
        "a : LTIME := LT#1us500ns; moment : LDT := LDT#2024-01-01-12:00:00; n : LINT;", "n := LTIME_TO_LINT(a);"
    )
    project, _ = source_to_project(text, "long")
    imported = import_plcopen(export_plcopen(project))
    assert [d.format() for d in imported.diagnostics if d.severity == "error"] == []
    sim = build_project(imported.project).simulation()
    sim.cycle(1)
    assert [sim.read("Main.n"), sim.read("Main.moment")] == [1500, ns_since_epoch("2024-01-01 12:00:00")]
