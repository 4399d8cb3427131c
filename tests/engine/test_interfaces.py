"""INTERFACEs (issue 25, item 5; IEC 61131-3 ed. 3, 6.6.6; CODESYS): IMPLEMENTS with located errors for missing or
mismatched methods, variables of an interface's type assigned from instances, calls through them dispatched by the
instance's FB, the assignment attempt ``?=`` (NULL when the instance does not implement the target), comparisons with
NULL and 0. Expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.workspace import Workspace

from .oo_support import errors, run

SHAPES = """
INTERFACE IShape
METHOD Area : INT
END_METHOD
END_INTERFACE
INTERFACE INamed
METHOD Id : INT
VAR_INPUT offset : INT; END_VAR
END_METHOD
END_INTERFACE
INTERFACE ISolid EXTENDS IShape
METHOD Volume : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Square IMPLEMENTS IShape
VAR_INPUT side : INT; END_VAR
METHOD Area : INT
Area := side * side;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Rect IMPLEMENTS IShape, INamed
VAR_INPUT w, h : INT; END_VAR
METHOD Area : INT
Area := w * h;
END_METHOD
METHOD Id : INT
VAR_INPUT offset : INT; END_VAR
Id := 100 + offset;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Box EXTENDS Rect IMPLEMENTS ISolid
VAR_INPUT d : INT; END_VAR
METHOD Volume : INT
Volume := Area() * d;
END_METHOD
END_FUNCTION_BLOCK
"""


def test_calls_through_interface_variables_run_the_instances_methods_scan_by_scan():
    sim = run(
        SHAPES + "PROGRAM Main\n"
        "VAR sq : Square := (side := 3); re : Rect := (w := 2, h := 5); bx : Box := (w := 1, h := 2, d := 4);\n"
        "shapes : ARRAY [1..3] OF IShape; i : INT; total : INT; solid : ISolid; vol : INT; END_VAR\n"
        "shapes[1] := sq; shapes[2] := re; shapes[3] := bx;\n"
        "total := 0;\nFOR i := 1 TO 3 DO\n  total := total + shapes[i].Area();\nEND_FOR;\n"
        "solid := bx;\nvol := solid.Volume() + solid.Area();\n"
        "sq.side := sq.side + 1;\nEND_PROGRAM\n"
    )
    side = 3
    for _ in range(3):
        sim.cycle(1)
        # the array holds references: the square's area follows its side as the program changes it
        assert sim.read("Main.total") == side * side + 2 * 5 + 1 * 2
        assert sim.read("Main.vol") == (1 * 2) * 4 + 1 * 2  # ISolid extends IShape: Area is callable through it
        side += 1
    assert sim.read("Main.shapes") == ["sq", "re", "bx"]  # the online views show what each refers to


def test_the_assignment_attempt_gives_the_reference_or_null():
    sim = run(
        SHAPES + "PROGRAM Main\n"
        "VAR sq : Square; re : Rect; bx : Box := (w := 3, h := 3); s : IShape; n : INamed; so : ISolid;\n"
        "id1, id2 : INT := -1; got1, got2, got3, got4 : BOOL; END_VAR\n"
        "s := re;\nn ?= s;\ngot1 := n <> 0;\nIF n <> NULL THEN id1 := n.Id(offset := 5); END_IF;\n"
        "s := sq;\nn ?= s;\ngot2 := n <> 0;\nIF n <> NULL THEN id2 := n.Id(offset := 6); END_IF;\n"
        "so ?= bx;\ngot3 := so = NULL;\nso ?= re;\ngot4 := so = NULL;\nEND_PROGRAM\n"
    )
    sim.cycle(1)
    assert (sim.read("Main.got1"), sim.read("Main.id1")) == (True, 105)  # a Rect implements INamed
    assert (sim.read("Main.got2"), sim.read("Main.id2")) == (False, -1)  # a Square does not: NULL
    assert (sim.read("Main.got3"), sim.read("Main.got4")) == (False, True)  # a Box is an ISolid, a Rect is not


def test_an_interface_as_a_function_block_input_and_a_null_call_is_a_located_runtime_error():
    text = SHAPES + (
        "FUNCTION_BLOCK Doubler\nVAR_INPUT s : IShape; END_VAR\nVAR_OUTPUT a : INT; END_VAR\n"
        "a := 2 * s.Area();\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR sq : Square := (side := 4); d : Doubler; a : INT; nothing : IShape; END_VAR\n"
        "d(s := sq, a => a);\nEND_PROGRAM\n"
    )
    sim = run(text)
    sim.cycle(1)
    assert sim.read("Main.a") == 2 * 16
    broken = run(text.replace("d(s := sq, a => a);", "d(s := nothing, a => a);"))
    broken.cycle(1)
    fault = broken.fault
    assert fault is not None and fault.code == "null_dereference" and fault.scan == 0
    assert fault.message == "S is NULL: it refers to no variable, so '^' has nothing to reach"
    line = text.splitlines().index("a := 2 * s.Area();") + 1
    assert (fault.pou, fault.origin.line) == ("DOUBLER", line)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "FUNCTION_BLOCK F IMPLEMENTS IShape\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "F/declarations", "F implements IShape but has no method Area")],
        ),
        (
            "FUNCTION_BLOCK F IMPLEMENTS INamed\nMETHOD Id : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [
                (
                    "ST-DECL",
                    "F/declarations",
                    "F.Id implements INamed.Id but its parameters differ (it takes VAR_INPUT offset)",
                )
            ],
        ),
        (
            "FUNCTION_BLOCK F IMPLEMENTS IShape\nMETHOD PRIVATE Area : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "F/declarations", "F.Area implements IShape.Area, so it must be PUBLIC")],
        ),
        (
            "FUNCTION_BLOCK F IMPLEMENTS IShap\nEND_FUNCTION_BLOCK\n",
            [
                (
                    "ST-UNKNOWN-TYPE",
                    "F/declarations",
                    "F IMPLEMENTS 'IShap', which is not an interface - did you mean 'IShape'?",
                )
            ],
        ),
        (
            "PROGRAM Main\nVAR s : IShape; r : Rect; n : INamed; END_VAR\nn := s;\nEND_PROGRAM\n",
            [("ST-TYPE-MISMATCH", "Main/body", "cannot assign IShape to INamed")],
        ),
        (
            "FUNCTION_BLOCK Plain\nEND_FUNCTION_BLOCK\n"
            "PROGRAM Main\nVAR s : IShape; p : Plain; END_VAR\ns := p;\nEND_PROGRAM\n",
            [("ST-TYPE-MISMATCH", "Main/body", "cannot assign Plain to IShape")],
        ),
        (
            "PROGRAM Main\nVAR s : IShape; x : INT; END_VAR\nx := s.Volume();\nEND_PROGRAM\n",
            [("ST-UNKNOWN-MEMBER", "Main/body", "IShape has no method 'Volume'")],
        ),
        (
            "PROGRAM Main\nVAR s : ISolid; x : INT; END_VAR\nx := s.Aera();\nEND_PROGRAM\n",
            [("ST-UNKNOWN-MEMBER", "Main/body", "ISolid has no method 'Aera' - did you mean 'Area'?")],
        ),
        (
            "PROGRAM Main\nVAR s : IShape; x : INT; END_VAR\nx := s.Area;\nEND_PROGRAM\n",
            [("ST-NOT-CALLABLE", "Main/body", "'Area' is a method of IShape: call it (add the ( ))")],
        ),
        (
            "PROGRAM Main\nVAR s : IShape; x : INT; END_VAR\nx ?= s;\nEND_PROGRAM\n",
            [("ST-TYPE-MISMATCH", "Main/body", "?= assigns to a variable of an interface's type, not to a INT")],
        ),
    ],
)
def test_interface_errors_are_located(text, expected):
    assert errors(SHAPES + text) == expected


def test_an_interface_method_has_no_body():
    text = "INTERFACE I\nMETHOD M : INT\nM := 1;\nEND_METHOD\nEND_INTERFACE\n"
    assert errors(text) == [("ST-DECL", "types", "I.M is a prototype: an interface's method has no body")]


def test_interfaces_and_implements_survive_a_project_folder(tmp_path):
    project, _ = source_to_project(
        SHAPES + "PROGRAM Main\nVAR bx : Box := (w := 2, h := 3, d := 5); s : ISolid; v : INT; END_VAR\n"
        "s := bx;\nv := s.Volume();\nEND_PROGRAM\n",
        "p",
    )
    assert "INTERFACE ISolid EXTENDS IShape" in project.types
    assert [(p.name, p.implements) for p in project.pous[:3]] == [
        ("Square", ["IShape"]),
        ("Rect", ["IShape", "INamed"]),
        ("Box", ["ISolid"]),
    ]
    workspace = Workspace(tmp_path)
    workspace.create(project)
    loaded = workspace.load("p").project
    assert loaded == project
    sim = build_project(loaded).simulation()
    sim.cycle(1)
    assert sim.read("Main.v") == 2 * 3 * 5
