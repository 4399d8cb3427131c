"""A conversion into TIME, DATE or DT whose result its type cannot hold is a located ``overflow`` fault, never a
wrapped or saturated value (issue 25, audit item 4).

IEC 61131-3 ed. 3 Table 26 converts between the long and short forms (LTIME_TO_TIME, LDT_TO_DT ...) and from DT to
DATE and TOD; CODESYS ("Conversion: TIME, LTIME", "Conversion: DATE, DT, TOD, LDATE, LDT, LTOD") also converts a
TIME to a DATE, DT or TOD and the date types to TIME, so each of those stays accepted. TIME is a signed 32-bit count
of ms (T#-24d20h31m23s648ms..T#24d20h31m23s647ms), DATE and DT start at 1970-01-01 (CODESYS's pages). LadderLab's
DATE_TO_TIME gives the time since 1970-01-01 (docs/st.md: conversions go through the count, here ms), so
DATE_TO_TIME(D#1970-01-02) is T#1d and any date from 1970-01-26 on (25 days: 2,160,000,000 ms) is more than TIME
holds. TIME_TO_TOD keeps the time of day (FUN-11, modulo 24 h).
"""

from __future__ import annotations

import pytest

from .ed3_support import build, program, scans

DAY_MS = 86_400_000
TIME_RANGE = "TIME (T#-24d20h31m23s648ms..T#24d20h31m23s647ms)"


def test_conversions_whose_result_fits_keep_their_value():
    text = program(
        "d : DATE := D#1970-01-02; t : TIME; lt : LTIME := LTIME#24d; short : TIME; late : TOD; day : DATE;back : DT;",
        "t := DATE_TO_TIME(d);\nshort := LTIME_TO_TIME(lt);\nlate := TIME_TO_TOD(T#25h);\n"
        "day := TIME_TO_DATE(T#1d2h);\nback := TIME_TO_DT(T#2d);",
    )
    assert scans(text, 1, "t", "short", "late", "day", "back") == [[DAY_MS, 24 * DAY_MS, 3_600_000, DAY_MS, 2 * DAY_MS]]


@pytest.mark.parametrize(
    ("declarations", "body", "message"),
    [
        (
            "d : DATE := D#2020-01-01; t : TIME;",
            "t := DATE_TO_TIME(d);",
            f"DATE_TO_TIME gives {18262 * DAY_MS} ms, outside {TIME_RANGE}",  # 2020-01-01 is day 18262
        ),
        (
            "lt : LTIME := LTIME#30d; t : TIME;",
            "t := LTIME_TO_TIME(lt);",
            f"LTIME_TO_TIME gives {30 * DAY_MS} ms, outside {TIME_RANGE}",
        ),
        (
            "t : TIME := T#-1ms; d : DATE;",
            "d := TIME_TO_DATE(t);",
            f"TIME_TO_DATE gives {-DAY_MS} ms, outside DATE (D#1970-01-01..D#9999-12-31)",  # the day before 1970
        ),
    ],
)
def test_a_result_outside_the_target_type_is_a_located_overflow_fault_in_each_variant(declarations, body, message):
    for variant in ("fast", "debug"):
        sim = build(program(declarations, body), variant).simulation()
        sim.cycle(1)
        fault = sim.fault
        assert fault is not None and (fault.code, fault.message) == ("overflow", message)
        assert (fault.pou, fault.origin.line, fault.origin.column) == ("MAIN", 6, 1)
