"""Issue 22 item 5: a malformed literal is reported with what a valid one looks like (``T#2s``, ``TIME#1h30m``), not
with the parser's view of it ("expected end of text, found 's'"); LEX-21 (based integers), LEX-40..52 (durations,
dates and times of day)."""

from __future__ import annotations

import pytest

from ladderlab.iec.value_text import parse
from ladderlab.st.parser import parse_expression, parse_statements
from tests.ir.diagram_support import box, errors, ld_pou, rung

TIME_HINT = (
    "a duration is T# then numbers with the units d, h, m, s, ms (largest first, no spaces), "
    "e.g. T#2s, T#500ms, TIME#1h30m, T#-1.5s"
)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("T#2 s", f"'T#2 s' is not a valid TIME literal: {TIME_HINT}"),
        ("T#5x", f"'T#5x' is not a valid TIME literal: {TIME_HINT}"),
        ("TIME#1hh", f"'TIME#1hh' is not a valid TIME literal: {TIME_HINT}"),
        ("T#", f"'T#' is not a valid TIME literal: {TIME_HINT}"),
        ("T#1.5.5s", f"'T#1.5.5s' is not a valid TIME literal: {TIME_HINT}"),
        (
            "16#FG",
            "'16#FG' is not a valid hexadecimal literal: a hexadecimal number is 16# then the digits 0-9 and A-F, "
            "e.g. 16#FF, 16#1A2B",
        ),
        (
            "2#102",
            "'2#102' is not a valid binary literal: a binary number is 2# then the digits 0 and 1, "
            "e.g. 2#1010, 2#1111_0000",
        ),
        ("8#9", "'8#9' is not a valid octal literal: an octal number is 8# then the digits 0 to 7, e.g. 8#17"),
        (
            "TOD#8h",
            "'TOD#8h' is not a valid TIME_OF_DAY literal: a time of day is TOD# then hours:minutes:seconds, "
            "e.g. TOD#08:30:00, TOD#23:59:59.5",
        ),
    ],
)
def test_a_malformed_literal_says_what_a_valid_one_looks_like(text, message):
    result = parse_expression(text, pou="P")
    assert [d.message for d in result.diagnostics] == [message]


@pytest.mark.parametrize("text", ["x + T#5s y", "T#5s + 3 4", "DT#2024-01-01-12:00 x"])
def test_a_valid_literal_before_an_unrelated_error_is_not_blamed(text):
    """The word after a whole literal is not part of it: the message is about what is really missing."""
    (diagnostic,) = parse_expression(text, pou="P").diagnostics
    assert diagnostic.message.startswith("expected end of text, found")


def test_the_literal_is_located_where_it_is_in_a_body():
    (diagnostic,) = parse_statements("x := 1;\ny := T#2 s;", pou="P").diagnostics
    assert (diagnostic.line, diagnostic.message) == (2, f"'T#2 s' is not a valid TIME literal: {TIME_HINT}")


def test_a_literal_on_a_box_pin_names_the_network_the_box_and_the_pin():
    main = ld_pou("Main", "VAR t : TON; END_VAR", rung("r1", box("b1", "TON", instance="t", PT="T#2 s"), label="Start"))
    assert errors(main) == [
        f"POU Main, network 1 \"Start\", TON t.PT: error ST-PARSE: 'T#2 s' is not a valid TIME literal: {TIME_HINT}"
    ]


def test_a_value_typed_online_that_is_no_time_gets_the_same_hint():
    with pytest.raises(ValueError) as refused:
        parse("5 s", "TIME")
    assert str(refused.value) == f"'5 s' is not a TIME ({TIME_HINT})"
