"""Function result types of every form (issue 16): STRING[n], STRING(n), WSTRING[n], arrays, structures and
enumerations by name, subranges; from a .st file, through a project folder and through PLCopen XML.

``FUNCTION F : STRING[20]`` used to lose its result type ("needs a return type").
"""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.workspace import Workspace

SOURCE = """
TYPE TPct : INT (0..100) := 50; TArr : ARRAY [1..3] OF INT; TRec : STRUCT a : INT; s : STRING[5]; END_STRUCT;
TCol : (red, green); END_TYPE
FUNCTION F20 : STRING[20]
F20 := 'abcdefghijklmnopqrstuvwxyz';
END_FUNCTION
FUNCTION F3 : STRING(3)
F3 := 'abcdef';
END_FUNCTION
FUNCTION FArr : TArr
FArr[2] := 7;
END_FUNCTION
FUNCTION FRec : TRec
FRec.a := 3; FRec.s := 'xyzxyzxyz';
END_FUNCTION
FUNCTION FPct : TPct
END_FUNCTION
FUNCTION FSub : INT (0..10)
VAR_INPUT x : INT; END_VAR
FSub := x;
END_FUNCTION
FUNCTION FCol : TCol
FCol := green;
END_FUNCTION
FUNCTION FW : WSTRING[4]
FW := "abcdefg";
END_FUNCTION
PROGRAM Main
VAR s, s3 : STRING; a : TArr; r : TRec; p, q : INT; c : TCol; w : WSTRING; x : INT := 4; END_VAR
s := F20(); s3 := F3(); a := FArr(); r := FRec(); p := FPct(); c := FCol(); w := FW(); q := FSub(x);
END_PROGRAM
"""

EXPECTED = {
    "Main.s": "abcdefghijklmnopqrst",  # cut to STRING[20]
    "Main.s3": "abc",
    "Main.a": [0, 7, 0],
    "Main.r": {"A": 3, "S": "xyzxy"},
    "Main.p": 50,  # the TYPE's own initial value (TYP-11)
    "Main.c": 1,
    "Main.w": "abcd",
    "Main.q": 4,
}


def values(project) -> dict:
    build = build_project(project)
    assert [d.format() for d in build.diagnostics if "ST-NO-RESULT" not in d.code] == []
    sim = build.simulation()
    sim.cycle(1)
    assert sim.fault is None
    return {path: sim.read(path) for path in EXPECTED}


def test_every_form_of_result_type_runs_from_a_st_file():
    project, diagnostics = source_to_project(SOURCE, "p")
    assert diagnostics == []
    assert {p.name: p.return_type for p in project.pous if p.kind == "function"} == {
        "F20": "STRING[20]",
        "F3": "STRING(3)",
        "FArr": "TArr",
        "FRec": "TRec",
        "FPct": "TPct",
        "FSub": "INT (0..10)",
        "FCol": "TCol",
        "FW": "WSTRING[4]",
    }
    assert values(project) == EXPECTED


def test_result_types_survive_a_project_folder_and_plcopen(tmp_path):
    project, _ = source_to_project(SOURCE, "p")
    workspace = Workspace(tmp_path)
    workspace.create(project)
    loaded = workspace.load("p").project
    assert [p.return_type for p in loaded.pous] == [p.return_type for p in project.pous]
    assert values(loaded) == EXPECTED
    imported = import_plcopen(export_plcopen(project), name="p").project
    assert values(imported) == EXPECTED


def test_a_subrange_result_is_checked_when_stored():
    project, _ = source_to_project(SOURCE.replace("x : INT := 4", "x : INT := 11"), "p")
    sim = build_project(project).simulation()
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.code == "subrange_violation" and sim.fault.origin.pou == "FSUB"


@pytest.mark.parametrize(
    "return_type, expected",
    [
        ("NOPE", "F/return_type:1:1, POU F: error ST-UNKNOWN-TYPE: unknown type 'NOPE'"),
        ("STRING[", "F/return_type:1:8, POU F: error ST-PARSE: expected an expression, found end of text"),
        ("TON", "F/return_type, POU F: error ST-DECL: a function cannot return a function block instance (TON)"),
    ],
)
def test_a_bad_result_type_is_located_in_the_return_type_text(return_type, expected):
    project, _ = source_to_project("FUNCTION F : INT\nF := 1;\nEND_FUNCTION\n", "p")
    project.pous[0].return_type = return_type
    found = [d.format() for d in build_project(project).diagnostics if d.severity == "error"]
    assert found[0].startswith(expected), found
