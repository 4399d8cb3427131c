"""Pointers and references to a base function block (issue 25, item 1; CODESYS "Calling a Method", "Object-oriented
programming"; IEC 61131-3 ed. 3 6.6.6.7 for ``?=``): a POINTER TO / REF_TO / REFERENCE TO a base FB takes the
instance of an FB that EXTENDS it, and a method or property called through it is the instance's own FB's
(dynamically bound, as through a base-typed VAR_IN_OUT: test_inheritance.py). ``?=`` gives a reference to a derived
FB when the instance is of it (or of one extending it), else NULL. An unrelated FB, or a base instance for a
derived pointer, stays refused where it is written. Expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .oo_support import build, errors
from .test_inheritance import SHAPES
from .test_properties import TANK

POLYMORPHIC = SHAPES + (
    "PROGRAM Main\n"
    "VAR sq : Square := (side := 2); cu : Cube := (side := 1);\n"
    "  shapes : ARRAY [1..2] OF POINTER TO Shape; i : INT; d : ARRAY [1..2] OF INT; scales : INT;\n"
    "END_VAR\n"
    "shapes[1] := ADR(sq); shapes[2] := ADR(cu);\n"
    "FOR i := 1 TO 2 DO d[i] := shapes[i]^.Describe(); END_FOR;\n"
    "shapes[2]^.scale := shapes[2]^.scale + 1;\n"
    "scales := shapes[1]^.scale * 10 + shapes[2]^.scale;\n"
    "END_PROGRAM\n"
)


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_an_array_of_base_pointers_dispatches_to_each_instances_own_method(variant):
    project, _ = source_to_project(POLYMORPHIC, "oo")
    result = build_project(project, variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    for scan in range(1, 4):
        sim.cycle(1)
        # Describe is Shape's: Area() * 10 + calls; Area is the instance's own. The square: 2 * 2 * 1 = 4; the cube:
        # Square's formula on its side 1 and its scale (1, 2, 3: raised through the pointer after each call) times 6
        cube_area = 1 * 1 * scan * 6
        assert [sim.read("Main.d[1]"), sim.read("Main.d[2]")] == [4 * 10 + scan, cube_area * 10 + scan]
        assert (sim.read("Main.scales"), sim.read("Main.cu.scale")) == (1 * 10 + scan + 1, scan + 1)
        # online, the path through the pointer reaches the cube's own variables (ON-11) as the base declares them
        assert (sim.read("Main.shapes[2]^.scale"), sim.read("Main.shapes[2]")) == (scan + 1, "ADR(cu)")


@pytest.mark.parametrize(
    "declaration, bind, call",
    [
        ("r : REFERENCE TO Shape;", "r REF= sq;", "r.Describe()"),
        ("r : REF_TO Shape;", "r := REF(sq);", "r^.Describe()"),
        ("r : POINTER TO Shape := ADR(sq);", "", "r^.Describe()"),
    ],
)
def test_each_kind_of_base_reference_takes_a_derived_instance(declaration, bind, call):
    text = SHAPES + (
        f"PROGRAM Main\nVAR sq : Square := (side := 3); {declaration} a : INT; END_VAR\n{bind}\na := {call};\n"
        "END_PROGRAM\n"
    )
    sim = build(text).simulation()
    for scan in (1, 2):
        sim.cycle(1)
        assert sim.read("Main.a") == 3 * 3 * 10 + scan  # Square's Area, the square's own call count


def test_a_property_read_through_a_base_pointer_is_the_overriding_one():
    text = TANK + (
        "FUNCTION_BLOCK BigTank EXTENDS Tank\n"
        "PROPERTY Full : BOOL\nGET\nFull := Level >= 50;\nEND_GET\nEND_PROPERTY\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR big : BigTank; small : Tank; p : POINTER TO Tank; f, g : BOOL; l : INT; END_VAR\n"
        "p := ADR(big); p^.Fill(30); f := p^.Full; l := p^.Level;\n"
        "p := ADR(small); p^.Level := p^.Level + 30; g := p^.Full;\nEND_PROGRAM\n"
    )
    sim = build(text).simulation()
    seen = []
    for _ in range(4):
        sim.cycle(1)
        seen.append((sim.read("Main.f"), sim.read("Main.l"), sim.read("Main.g"), sim.read("Main.small.amount")))
    # BigTank is full from 50, a Tank from 100 (Level's SET clips at 100)
    assert seen == [(False, 30, False, 30), (True, 60, False, 60), (True, 90, False, 90), (True, 100, True, 100)]


ATTEMPT = SHAPES + (
    "PROGRAM Main\n"
    "VAR sq : Square := (side := 2); cu : Cube := (side := 1); seen : POINTER TO Shape;\n"
    "  asSquare : POINTER TO Square; asCube : REF_TO Cube; n : INT; hits : INT; side : INT;\n"
    "END_VAR\n"
    "n := n + 1;\n"
    "IF n MOD 2 = 1 THEN seen := ADR(sq); ELSE seen := ADR(cu); END_IF;\n"
    "asSquare ?= seen; asCube ?= seen; hits := 0;\n"
    "IF asSquare <> NULL THEN hits := hits + 1; side := asSquare^.side; END_IF;\n"
    "IF asCube <> NULL THEN hits := hits + 10; END_IF;\n"
    "END_PROGRAM\n"
)


def test_an_assignment_attempt_gives_the_derived_reference_or_null():
    sim = build(ATTEMPT).simulation()
    seen = []
    for _ in range(4):
        sim.cycle(1)
        seen.append((sim.read("Main.hits"), sim.read("Main.side"), sim.read("Main.asCube")))
    # the square is a Square, not a Cube; the cube is both (Cube EXTENDS Square)
    assert seen == [(1, 2, "NULL"), (11, 1, "ADR(cu)"), (1, 2, "NULL"), (11, 1, "ADR(cu)")]


def test_an_assignment_attempt_from_an_interface_variable_into_an_fb_pointer():
    """``p ?= i``: the instance behind the interface variable when it is of p's FB, else NULL; a POINTER TO the
    interface variable itself calls through it (dispatched by the instance, test_interfaces.py)."""
    text = (
        "INTERFACE IShape\nMETHOD Area : INT\nEND_METHOD\nEND_INTERFACE\n"
        "FUNCTION_BLOCK Sq IMPLEMENTS IShape\nVAR_INPUT side : INT; END_VAR\n"
        "METHOD Area : INT\nArea := side * side;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Circle IMPLEMENTS IShape\nMETHOD Area : INT\nArea := 3;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR s : Sq := (side := 4); c : Circle; i : IShape; p : POINTER TO Sq; pi : POINTER TO IShape;\n"
        "  n, a, b : INT;\nEND_VAR\n"
        "n := n + 1;\nIF n MOD 2 = 1 THEN i := s; ELSE i := c; END_IF;\n"
        "p ?= i;\nIF p <> NULL THEN a := p^.Area() + p^.side; ELSE a := -1; END_IF;\n"
        "pi := ADR(i); b := pi^.Area();\nEND_PROGRAM\n"
    )
    sim = build(text).simulation()
    seen = []
    for _ in range(4):
        sim.cycle(1)
        seen.append((sim.read("Main.a"), sim.read("Main.b")))
    assert seen == [(4 * 4 + 4, 16), (-1, 3)] * 2


def test_a_breakpoint_in_the_override_halts_when_called_through_a_base_pointer():
    text = SHAPES + (
        "PROGRAM Main\nVAR sq : Square := (side := 2); cu : Cube := (side := 3); p : POINTER TO Shape; a, b : INT;\n"
        "END_VAR\np := ADR(sq); a := p^.Describe();\np := ADR(cu); b := p^.Describe();\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "oo")
    sim = Simulation(lower_project(project).program, variant="debug")
    line = text.splitlines().index("Area := SUPER^.Area() * 6;") + 1
    assert len(sim.set_breakpoint("CUBE.AREA", line=line)) == 1
    sim.cycle(1)
    halts = []
    while sim.halted is not None:
        halts.append((sim.halted.reason, sim.halted.origin.pou, sim.halted.origin.line, sim.read("MAIN.A")))
        sim.resume()
    # only the cube runs Cube.Area; the square's call (a already written) came first
    assert halts == [("breakpoint", "CUBE.AREA", line, 2 * 2 * 10 + 1)]
    assert sim.read("MAIN.B") == (3 * 3 * 1 * 6) * 10 + 1


@pytest.mark.parametrize(
    "declarations, body, expected",
    [
        (
            "m : Measure; p : REF_TO Shape;",
            "p := REF(m);",
            ("ST-TYPE-MISMATCH", "cannot assign REF_TO Measure to REF_TO Shape"),
        ),
        (
            "sq : Square; p : POINTER TO Cube;",
            "p := ADR(sq);",
            ("ST-TYPE-MISMATCH", "cannot assign REF_TO Square to REF_TO Cube"),
        ),
        (
            "sq : Square; r : REFERENCE TO Cube;",
            "r REF= sq;",
            ("ST-TYPE-MISMATCH", "a REFERENCE TO Cube cannot refer to a Square"),
        ),
        (
            "sq : Square; p : POINTER TO Shape; q : POINTER TO Square;",
            "p := ADR(sq); q := p;",
            ("ST-TYPE-MISMATCH", "cannot assign REF_TO Shape to REF_TO Square"),
        ),
        (
            "p : POINTER TO Square; x : INT;",
            "p ?= x;",
            (
                "ST-TYPE-MISMATCH",
                "?= into a REF_TO Square tries a reference to a function block or an interface variable, not a INT",
            ),
        ),
    ],
)
def test_what_is_no_instance_of_the_pointers_fb_stays_refused(declarations, body, expected):
    text = SHAPES + f"PROGRAM Main\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n"
    assert errors(text) == [(expected[0], "Main/body", expected[1])]


def test_pointer_arithmetic_over_an_fb_instance_stays_refused_where_written():
    text = (
        SHAPES
        + "PROGRAM Main\nVAR sq : Square; p : POINTER TO Shape; END_VAR\np := ADR(sq);\np := p + 4;\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "oo")
    found = [d.format() for d in build_project(project).diagnostics if d.severity == "error"]
    assert found == [
        "Main/body:31:6, POU Main: error IR-UNSUPPORTED: moving or ordering pointers needs the size of what they point "
        "to: SIZEOF of a function block instance is refused: CODESYS counts the instance's hidden data too (its method "
        "table pointer, the alignment of its members), which LadderLab does not lay out"
    ]
