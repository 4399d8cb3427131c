"""PROPERTYs of function blocks (issue 25, item 5; CODESYS): read through GET, written through SET (whose input is
the property's name), inside the FB by their bare name, overridden in derived FBs, read-only without SET; the ST
export and PLCopen carry them. Expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .oo_support import build, errors, run

TANK = """
FUNCTION_BLOCK Tank
VAR amount : INT; writes : INT; END_VAR
PROPERTY Level : INT
GET
Level := amount;
END_GET
SET
VAR clipped : INT; END_VAR
clipped := LIMIT(0, Level, 100);
amount := clipped;
writes := writes + 1;
END_SET
END_PROPERTY
PROPERTY Full : BOOL
GET
Full := Level >= 100;
END_GET
END_PROPERTY
METHOD Fill
VAR_INPUT n : INT; END_VAR
Level := Level + n;
END_METHOD
END_FUNCTION_BLOCK
"""
MAIN = """
PROGRAM Main
VAR t : Tank; l : INT; f : BOOL; END_VAR
t.Fill(30);
t.Level := t.Level + 5;
l := t.Level;
f := t.Full;
END_PROGRAM
"""


def trace(project, scans: int) -> list[tuple]:
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    rows = []
    for _ in range(scans):
        sim.cycle(1)
        rows.append((sim.read("Main.l"), sim.read("Main.f"), sim.read("Main.t.writes")))
    return rows


def expected(scans: int) -> list[tuple]:
    """The same program worked by hand: SET clips to 0..100 and counts its calls."""
    level, writes, rows = 0, 0, []
    for _ in range(scans):
        for new in (level + 30, None):  # Fill(30) sets Level; then t.Level := t.Level + 5
            level = max(0, min(100, (new if new is not None else level + 5)))
            writes += 1
        rows.append((level, level >= 100, writes))
    return rows


def test_a_property_is_read_through_get_and_written_through_set_scan_by_scan():
    project, _ = source_to_project(TANK + MAIN, "oo")
    assert trace(project, 4) == expected(4) == [(35, False, 2), (70, False, 4), (100, True, 6), (100, True, 8)]


def test_a_derived_fb_overrides_a_property_and_the_base_code_uses_the_override():
    text = TANK + (
        "FUNCTION_BLOCK BigTank EXTENDS Tank\nVAR_OUTPUT strict : BOOL; END_VAR\n"
        "PROPERTY Full : BOOL\nGET\nFull := Level >= 50;\nstrict := SUPER^.Full;\nEND_GET\n"
        "END_PROPERTY\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Watch\nVAR_IN_OUT t : Tank; END_VAR\nVAR_OUTPUT full : BOOL; END_VAR\nfull := t.Full;\n"
        "END_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR b : BigTank; w : Watch; f : BOOL; END_VAR\nb.Fill(30);\nw(t := b, full => f);\nEND_PROGRAM\n"
    )
    sim = build(text).simulation()
    sim.cycle(1)
    assert sim.read("Main.f") is False  # 30
    sim.cycle(1)
    assert sim.read("Main.f") is True  # 60 >= 50: BigTank's Full, though Watch sees a Tank
    assert sim.read("Main.b.strict") is False  # SUPER^.Full: Tank's own (60 < 100)


@pytest.mark.parametrize(
    ("program", "expected"),
    [
        (
            "t.Full := TRUE;",
            ("ST-READONLY", "Main/body", "the property Full has no SET: it can be read, not assigned"),
        ),
        (
            "t.Levl := 1;",
            ("ST-UNKNOWN-MEMBER", "Main/body", "Tank has no input or output 'Levl' - did you mean 'Level'?"),
        ),
    ],
)
def test_property_errors_are_located(program, expected):
    text = TANK + f"PROGRAM Main\nVAR t : Tank; END_VAR\n{program}\nEND_PROGRAM\n"
    assert errors(text) == [expected]


def test_a_property_passed_by_reference_is_a_located_error():
    text = TANK + (
        "FUNCTION_BLOCK Inc\nVAR_IN_OUT x : INT; END_VAR\nx := x + 1;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR t : Tank; i : Inc; END_VAR\ni(x := t.Level);\nEND_PROGRAM\n"
    )
    line = text.splitlines().index("i(x := t.Level);") + 1
    assert [(d.code, d.file, d.line, d.message) for d in build(text).diagnostics if d.severity == "error"] == [
        (
            "IR-UNSUPPORTED",
            "Main/body",
            line,
            "the property Level is not a variable: read it or assign it with ':=' in ST (its GET and SET run then), "
            "it cannot be passed or written by reference here",
        )
    ]


def test_a_private_property_is_refused_outside_its_fb():
    text = TANK.replace("PROPERTY Full : BOOL", "PROPERTY PRIVATE Full : BOOL") + (
        "PROGRAM Main\nVAR t : Tank; f : BOOL; END_VAR\nf := t.Full;\nEND_PROGRAM\n"
    )
    assert [(d.code, d.message) for d in build(text).diagnostics if d.severity == "error"] == [
        ("ST-NOT-ACCESSIBLE", "the property Tank.Full is PRIVATE: only its own function block may use it")
    ]


def test_properties_survive_the_st_export_and_plcopen():
    project, _ = source_to_project(TANK + MAIN, "oo")
    text = export_project_st(project).text
    assert "PROPERTY PUBLIC Level : INT\nGET\nLevel := amount;\nEND_GET\nSET\n" in text
    again, diagnostics = source_to_project(text, "oo")
    assert diagnostics == [] and trace(again, 3) == expected(3)
    imported = import_plcopen(export_plcopen(project), name="oo")
    assert imported.diagnostics == [] and imported.project == project


def test_a_property_whose_get_calls_back_into_it_is_refused():
    text = (
        "FUNCTION_BLOCK F\nMETHOD M : INT\nM := P;\nEND_METHOD\n"
        "PROPERTY P : INT\nGET\nP := M();\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n"
    )
    assert errors(text) == [
        ("ST-RECURSION", "F.M/body", "recursive call F.M -> F.P.GET -> F.M: methods must not call themselves (POU-02)")
    ]


def test_get_and_set_stay_usable_as_names_and_an_accessor_must_be_get_or_set():
    sim = run(
        "FUNCTION Get : INT\nGet := 7;\nEND_FUNCTION\nPROGRAM Main\nVAR set : INT; END_VAR\nset := Get();\nEND_PROGRAM\n"
    )
    sim.cycle(1)
    assert sim.read("Main.set") == 7
    project, diagnostics = source_to_project(
        "FUNCTION_BLOCK F\nPROPERTY P : INT\nFETCH\nP := 1;\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n", "oo"
    )
    assert [(d.code, d.line, d.message) for d in diagnostics] == [
        ("ST-PARSE", 3, "a property holds GET ... END_GET and SET ... END_SET, not 'FETCH'")
    ]


def test_a_property_and_a_method_of_one_name_are_refused():
    text = "FUNCTION_BLOCK F\nMETHOD P : INT\nEND_METHOD\nPROPERTY P : INT\nGET\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n"
    assert errors(text) == [("ST-DUPLICATE", "F.P.GET/declarations", "F has two methods or properties called 'P'")]
