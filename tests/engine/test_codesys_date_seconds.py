"""CODESYS typing: a DATE or a DT converted to or from a number counts seconds since 1970-01-01 (issue 25; OSCAT's
SET_DATE, DATE_ADD, MONTH_BEGIN, YEAR_OF_DATE ... compute with DATE_TO_DWORD and DWORD_TO_DATE).

CODESYS "Conversion: DATE, DT, TOD": "The data types DATE and DT use the same memory format internally and are
stored as DWORD. The resolution for DATE is 1 day. The resolution for DT is 1 second. Both begin at January 1,
1970." Its examples (also Beckhoff's "DATE_TO conversions" / "DT_TO conversions"): DATE_TO_INT(D#1970-01-15) is
29952, DATE_TO_DWORD(D#2002-08-18) is 16#3D5EE380, DT_TO_DWORD(DT#1998-02-13-14:20) is 16#34E45690,
DT_TO_BYTE(DT#1970-01-15-05:05:05) is 129, DATE_TO_BOOL(D#1970-01-01) FALSE. A number into a DATE or DT reads the
same seconds back.
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .ed3_support import program

TEXT = program(
    "i : INT; dw : DWORD; dt_dw : DWORD; b : BYTE; zero : BOOL := TRUE; r : REAL; day : BOOL; stamp : BOOL;"
    "seconds : UDINT := 1029628800; day_of : BOOL;",
    """i := DATE_TO_INT(D#1970-01-15);
dw := DATE_TO_DWORD(D#2002-08-18);
dt_dw := DT_TO_DWORD(DT#1998-02-13-14:20:00);
b := DT_TO_BYTE(DT#1970-01-15-05:05:05);
zero := DATE_TO_BOOL(D#1970-01-01);
r := DATE_TO_REAL(D#1970-01-02);
day := DWORD_TO_DATE(16#3D5EE380) = D#2002-08-18;
stamp := DWORD_TO_DT(16#34E45690) = DT#1998-02-13-14:20:00;
day_of := UDINT_TO_DATE(seconds) = D#2002-08-18;""",
)


def _build(text: str, typing: str, variant: str = "fast"):
    project, diagnostics = source_to_project(text, "codesys")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    return build_project(project.model_copy(update={"typing": typing}), variant)


@pytest.mark.parametrize("variant", ["fast", "debug"])
def test_dates_as_numbers_are_codesys_seconds(variant):
    """CODESYS's documented examples, and DATE_TO_REAL(D#1970-01-02) = 86400.0 s; the DWORDs read back as the dates
    they stand for (UDINT 1029628800 s is D#2002-08-18)."""
    sim = _build(TEXT, "codesys", variant).simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    names = ("i", "dw", "dt_dw", "b", "zero", "r", "day", "stamp", "day_of")
    assert [sim.read(f"Main.{name}") for name in names] == [
        29952,
        0x3D5EE380,
        0x34E45690,
        129,
        False,
        86400.0,
        True,
        True,
        True,
    ]


def test_a_number_that_is_no_whole_day_stops_the_task():
    """DWORD_TO_DATE(86401): CODESYS's DATE would keep the second over (its DWORD), a LadderLab DATE is a day: the
    located fault ``invalid_argument``, never the day silently."""
    sim = _build(program("d : DATE; s : DWORD := 86401;", "d := DWORD_TO_DATE(s);"), "codesys").simulation()
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "invalid_argument"
    assert (sim.fault.origin.line, sim.fault.message.split(":")[0]) == (6, "86401 s since 1970-01-01 is no whole day")


def test_a_real_into_a_date_is_refused_where_it_is():
    """How CODESYS rounds a REAL to its seconds is not documented: REAL_TO_DATE is IR-UNSUPPORTED at its line."""
    found = [d for d in _build(program("d : DATE; r : REAL;", "d := REAL_TO_DATE(r);"), "codesys").diagnostics]
    assert [(d.code, d.line) for d in found if d.severity == "error"] == [("IR-UNSUPPORTED", 6)]


def test_iec_typing_keeps_its_own_count():
    """Without CODESYS typing a DATE converts through LadderLab's count (docs/runtime.md: ms), as before."""
    text = program("dw : DWORD;", "dw := DATE_TO_DWORD(D#1970-01-02);")
    sim = _build(text, "iec").simulation()
    sim.cycle(1)
    assert sim.read("Main.dw") == 86_400_000
