"""EXTENDS between function blocks (issue 25, item 5; IEC 61131-3 ed. 3, 6.6.3; CODESYS): inherited variables and
methods, overriding, ``SUPER^.M()``, ABSTRACT and FINAL, a derived instance passed for a base in-out, and dynamic
dispatch: a call runs the method of the instance's own FB, even from the base's code. Expected values are worked out
by hand from the program text.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.workspace import Workspace

from .oo_support import errors, run

SHAPES = """
FUNCTION_BLOCK ABSTRACT Shape
VAR_INPUT scale : INT := 1; END_VAR
VAR calls : INT; END_VAR
METHOD ABSTRACT Area : INT
END_METHOD
METHOD Describe : INT
calls := calls + 1;
Describe := Area() * 10 + calls;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Square EXTENDS Shape
VAR_INPUT side : INT; END_VAR
METHOD Area : INT
Area := side * side * scale;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Cube EXTENDS Square
METHOD Area : INT
Area := SUPER^.Area() * 6;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Measure
VAR_IN_OUT s : Shape; END_VAR
VAR_OUTPUT d : INT; END_VAR
d := s.Describe();
END_FUNCTION_BLOCK
"""


def test_dynamic_dispatch_through_a_base_in_out_and_from_the_base_methods_code_scan_by_scan():
    sim = run(
        SHAPES + "PROGRAM Main\n"
        "VAR sq : Square := (side := 2); cu : Cube := (side := 3, scale := 2); m : Measure; a, b : INT; END_VAR\n"
        "m(s := sq, d => a);\nm(s := cu, d => b);\nEND_PROGRAM\n"
    )
    square_area = 2 * 2 * 1
    cube_area = (3 * 3 * 2) * 6  # SUPER^.Area() is the square's formula on the cube's own side and scale
    for scan in range(1, 4):
        sim.cycle(1)
        # Describe is Shape's; the Area it calls is the instance's own; each instance counts its own calls
        assert (sim.read("Main.a"), sim.read("Main.b")) == (square_area * 10 + scan, cube_area * 10 + scan)
        assert (sim.read("Main.sq.calls"), sim.read("Main.cu.calls")) == (scan, scan)


def test_a_derived_fb_has_the_base_variables_its_body_and_methods_use_them():
    sim = run(
        "FUNCTION_BLOCK Base\nVAR_INPUT inc : INT := 1; END_VAR\nVAR_OUTPUT total : INT; END_VAR\n"
        "METHOD PROTECTED Bump\ntotal := total + inc;\nEND_METHOD\n"
        "total := total + 1000;\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Derived EXTENDS Base\nVAR_OUTPUT twice : INT; END_VAR\n"
        "METHOD Step\nBump();\nBump();\ntwice := total * 2;\nEND_METHOD\n"
        "Step();\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR d : Derived; t : INT; END_VAR\n"
        "d(inc := 3);\nd.Step();\nt := d.total;\nEND_PROGRAM\n"
    )
    sim.cycle(1)
    # the derived body replaces the base's (CODESYS: the base body runs only through SUPER^()): no +1000
    assert (sim.read("Main.t"), sim.read("Main.d.twice")) == (4 * 3, 4 * 3 * 2)
    sim.cycle(1)
    assert sim.read("Main.t") == 8 * 3


def test_this_in_a_function_block_body_is_the_instance_running_it():
    sim = run(
        "FUNCTION_BLOCK A\nVAR_OUTPUT n : INT; END_VAR\nVAR k : INT := 5; END_VAR\n"
        "METHOD Add\nVAR_INPUT v : INT; END_VAR\nn := n + v;\nEND_METHOD\n"
        "THIS^.Add(THIS^.k);\nAdd(1);\nTHIS^.k := k + 1;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a, b : A; END_VAR\na();\nEND_PROGRAM\n"
    )
    sim.cycle(1)
    assert (sim.read("Main.a.n"), sim.read("Main.a.k"), sim.read("Main.b.n")) == (5 + 1, 6, 0)
    sim.cycle(1)
    assert (sim.read("Main.a.n"), sim.read("Main.a.k")) == (6 + 6 + 1, 7)


def test_a_method_of_a_fb_derived_from_one_without_overrides_is_called_directly():
    sim = run(
        "FUNCTION_BLOCK A\nVAR n : INT; END_VAR\nMETHOD Inc : INT\nn := n + 1;\nInc := n;\nEND_METHOD\n"
        "END_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR b : B; r : INT; END_VAR\nr := b.Inc() + b.Inc();\nEND_PROGRAM\n"
    )
    sim.cycle(2)
    assert sim.read("Main.r") == 3 + 4


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "FUNCTION_BLOCK B EXTENDS Nothing\nEND_FUNCTION_BLOCK\n",
            [("ST-UNKNOWN-TYPE", "B/declarations", "B EXTENDS 'Nothing', which is not a function block")],
        ),
        (
            "FUNCTION_BLOCK FINAL A\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "B/declarations", "A is FINAL: no function block can extend it")],
        ),
        (
            "FUNCTION_BLOCK A EXTENDS B\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n",
            [
                ("ST-RECURSION", "A/declarations", "A -> B -> A: a function block cannot extend itself"),
            ],
        ),
        (
            "FUNCTION_BLOCK A\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nVAR x : INT; END_VAR\nEND_FUNCTION_BLOCK\n",
            [("ST-DUPLICATE", "B/declarations", "'x' is already a variable of A, which B extends")],
        ),
        (
            "FUNCTION_BLOCK A\nMETHOD FINAL M\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nMETHOD M\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "B.M/declarations", "A.M is FINAL: B cannot override it")],
        ),
        (
            "FUNCTION_BLOCK A\nMETHOD M : INT\nVAR_INPUT k : INT; END_VAR\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nMETHOD M : INT\nVAR_INPUT k : REAL; END_VAR\nEND_METHOD\n"
            "END_FUNCTION_BLOCK\n",
            [("ST-DECL", "B.M/declarations", "B.M overrides A.M but its parameter k is REAL, not INT")],
        ),
        (
            "FUNCTION_BLOCK A\nMETHOD M : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nMETHOD M : BOOL\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "B.M/declarations", "B.M overrides A.M but its result type is BOOL, not INT")],
        ),
        (
            "FUNCTION_BLOCK ABSTRACT A\nMETHOD ABSTRACT M : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "B/declarations", "B must implement the ABSTRACT method A.M (or be ABSTRACT itself)")],
        ),
        (
            "FUNCTION_BLOCK ABSTRACT A\nMETHOD ABSTRACT M : INT\nM := 1;\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-DECL", "A.M/body", "the ABSTRACT method M has no body: a derived FB implements it")],
        ),
        (
            "FUNCTION_BLOCK ABSTRACT A\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : A; END_VAR\nEND_PROGRAM\n",
            [
                (
                    "ST-DECL",
                    "Main/declarations",
                    "A is ABSTRACT: declare an instance of a function block derived from it",
                )
            ],
        ),
        (
            "FUNCTION_BLOCK ABSTRACT A\nMETHOD ABSTRACT M : INT\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nMETHOD M : INT\nM := SUPER^.M();\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-NOT-CALLABLE", "B.M/body", "the method A.M is ABSTRACT: it has no body to run")],
        ),
        (
            "FUNCTION_BLOCK A\nMETHOD M : INT\nM := SUPER^.M();\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-UNKNOWN-VAR", "A.M/body", "SUPER^: A does not extend another function block")],
        ),
        (
            "FUNCTION_BLOCK A\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nVAR x : BOOL; END_VAR\nMETHOD M\nx := SUPER^();\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [("ST-NOT-CALLABLE", "B.M/body", "SUPER^() runs a body: call it as a statement")],
        ),
        (
            "FUNCTION_BLOCK A\nVAR n : INT; END_VAR\nMETHOD PRIVATE Secret\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
            "FUNCTION_BLOCK B EXTENDS A\nMETHOD M\nSecret();\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            [
                (
                    "ST-NOT-ACCESSIBLE",
                    "B.M/body",
                    "the method A.Secret is PRIVATE: only its own function block may call it",
                )
            ],
        ),
        (
            "FUNCTION x : INT\nx := THIS^.x;\nEND_FUNCTION\n",
            [("ST-UNKNOWN-VAR", "x/body", "THIS^ is only known in a function block, a program and their methods")],
        ),
    ],
)
def test_inheritance_errors_are_located(text, expected):
    assert errors(text) == expected


def test_a_derived_instance_is_accepted_for_a_base_in_out_but_a_base_one_is_not_for_a_derived():
    text = (
        "FUNCTION_BLOCK A\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B EXTENDS A\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK TakesA\nVAR_IN_OUT x : A; END_VAR\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK TakesB\nVAR_IN_OUT x : B; END_VAR\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a : A; b : B; ta : TakesA; tb : TakesB; END_VAR\n"
        "ta(x := b);\ntb(x := a);\nEND_PROGRAM\n"
    )
    assert errors(text) == [("ST-TYPE-MISMATCH", "Main/body", "in-out parameter x of TakesB needs a B, got A")]


def test_extends_abstract_and_final_survive_a_project_folder(tmp_path):
    project, _ = source_to_project(
        SHAPES + "FUNCTION_BLOCK FINAL Last EXTENDS Cube\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c : Last := (side := 1); m : Measure; d : INT; END_VAR\nm(s := c, d => d);\nEND_PROGRAM\n",
        "p",
    )
    assert [(p.name, p.extends, p.abstract, p.final) for p in project.pous[:3]] == [
        ("Shape", None, True, False),
        ("Square", "Shape", False, False),
        ("Cube", "Square", False, False),
    ]
    workspace = Workspace(tmp_path)
    workspace.create(project)
    loaded = workspace.load("p").project
    assert loaded == project
    sim = build_project(loaded).simulation()
    sim.cycle(1)
    assert sim.read("Main.d") == (1 * 1 * 1 * 6) * 10 + 1


def test_a_breakpoint_inside_a_method_halts_there_also_when_reached_through_super():
    """ON-03 inside methods (engine level): Square.Area runs for the square, and for the cube through SUPER^."""
    text = SHAPES + (
        "PROGRAM Main\nVAR sq : Square := (side := 2); cu : Cube := (side := 3); m : Measure; a, b : INT; END_VAR\n"
        "m(s := sq, d => a);\nm(s := cu, d => b);\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "oo")
    sim = Simulation(lower_project(project).program, variant="debug")
    line = text.splitlines().index("Area := side * side * scale;") + 1
    assert len(sim.set_breakpoint("SQUARE.AREA", line=line)) == 1  # one pause point: that statement
    assert sim.cycle(1) == 0
    halts = []
    while sim.halted is not None:
        halts.append((sim.halted.reason, sim.halted.origin.pou, sim.halted.origin.line))
        sim.resume()
    assert halts == [("breakpoint", "SQUARE.AREA", line)] * 2
    assert (sim.read("MAIN.A"), sim.read("MAIN.B")) == (2 * 2 * 10 + 1, (3 * 3 * 6) * 10 + 1)
