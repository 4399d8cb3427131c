"""References (IEC 61131-3 ed. 3, 6.4.4.10: ``REF_TO``, ``REF()``, ``NULL``, ``^``; CODESYS ``POINTER TO``, ``ADR``):
read and assigned through, scan by scan, in member and index chains and as VAR_IN_OUT arguments; a NULL dereference
is a located fault; references to constants are refused; a state round trip keeps the program's
values. Expected values are worked out by hand from the program text.
"""

from __future__ import annotations

import pickle

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

TYPES = "TYPE S : STRUCT f : INT; g : ARRAY [1..3] OF INT; END_STRUCT; END_TYPE\n"


def build(text: str, typing: str = "iec"):
    project, diagnostics = source_to_project(text, "refs")
    assert project is not None and [d.format() for d in diagnostics if d.severity == "error"] == []
    return build_project(project.model_copy(update={"typing": typing}))


def simulation(declarations: str, body: str, typing: str = "iec"):
    result = build(f"{TYPES}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n", typing)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def test_reading_and_assigning_through_a_reference_scan_by_scan():
    sim = simulation("x : INT := 5; y : INT; r : REF_TO INT := REF(x);", "y := r^ + 1;\nr^ := r^ * 2;")
    expected_x = 5
    for _ in range(3):
        sim.cycle(1)
        expected_y, expected_x = expected_x + 1, expected_x * 2
        assert (sim.read("Main.x"), sim.read("Main.y")) == (expected_x, expected_y)
    assert sim.read("Main.r") == "REF(x)"  # the online views show what the reference was made by


def test_references_in_member_and_index_chains_and_pointers_to_array_elements():
    sim = simulation(
        "a : ARRAY [1..3] OF INT := [10, 20, 30]; s : S; i : INT := 2; p : POINTER TO INT; rs : REF_TO S;\n"
        "ra : REF_TO ARRAY [1..3] OF INT;",
        "p := ADR(a[i]);\np^ := p^ + 1;\nrs := REF(s);\nrs^.f := 42;\nrs^.g[2] := rs^.f + 1;\n"
        "ra := REF(a);\nra^[3] := ra^[1] + 3;",
    )
    sim.cycle(1)
    assert sim.read("Main.a") == [10, 21, 13]
    assert sim.read("Main.s") == {"F": 42, "G": [0, 43, 0]}
    assert sim.read("Main.p") == "ADR(a[i])"


def test_a_reference_to_a_global_and_a_dereference_as_a_var_in_out_argument():
    text = (
        "VAR_GLOBAL g : DINT := 7; END_VAR\n"
        "FUNCTION_BLOCK Inc\nVAR_IN_OUT x : DINT; END_VAR\nx := x + 10;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR r : REF_TO DINT := REF(g); inc : Inc; END_VAR\nVAR_EXTERNAL g : DINT; END_VAR\n"
        "r^ := r^ + 1;\ninc(x := r^);\nEND_PROGRAM\n"
    )
    sim = build(text).simulation()
    sim.cycle(2)
    assert sim.read("GVL.g") == 7 + 2 * 11


def test_equality_of_references_and_null():
    sim = simulation(
        "x, z : INT; r : REF_TO INT; n : REF_TO INT; same, other, empty, set : BOOL;",
        "r := REF(x);\nsame := r = REF(x);\nother := r = REF(z);\nempty := n = NULL;\nset := r <> NULL;",
    )
    sim.cycle(1)
    assert [sim.read(f"Main.{v}") for v in ("same", "other", "empty", "set")] == [True, False, True, True]
    assert sim.read("Main.n") == "NULL"


def test_dereferencing_null_is_a_located_fault_in_the_scan_it_happens():
    sim = simulation("n : REF_TO INT; y, k : INT;", "k := k + 1;\nIF k > 2 THEN\n  y := n^;\nEND_IF;")
    sim.cycle(5)
    fault = sim.fault
    assert fault is not None and fault.code == "null_dereference" and fault.scan == 2  # the third scan, from 0
    assert fault.message == "N is NULL: it refers to no variable, so '^' has nothing to reach"
    assert (fault.pou, fault.origin.line) == ("MAIN", 8)  # TYPES line + PROGRAM, VAR, decl, END_VAR, 2 statements
    assert sim.read("Main.k") == 3


def test_references_to_a_constant_and_retain_references_are_located_errors():
    """A reference to a FUNCTION's own variable or to a program's VAR_TEMP is no longer refused (checked at run
    time: test_dangling_references.py, test_temp_references.py); one to a CONSTANT and a RETAIN reference still
    are."""
    text = (
        "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nVAR r : REF_TO INT; END_VAR\nr := REF(a);\nF := a;\n"
        "END_FUNCTION\n"
        "PROGRAM Main\nVAR CONSTANT c : INT := 1; END_VAR\nVAR_TEMP t : INT; END_VAR\nVAR r : REF_TO INT; END_VAR\n"
        "VAR RETAIN rr : REF_TO INT; END_VAR\nr := REF(t);\nr := REF(c);\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "refs")  # lines are the file's
    assert [d.format() for d in build_project(project).diagnostics] == [
        "Main/declarations:11:12, POU Main: error ST-DECL: a REF_TO INT cannot be RETAIN: a restart makes the "
        "variables it refers to anew (set it again after one)",
        "Main/body:13:10, POU Main: error ST-REF: REF cannot refer to the CONSTANT c: it could be written through "
        "the reference",
    ]


def test_a_reference_to_another_programs_output_follows_it_scan_by_scan():
    """ADR and REF of another program's variable (`Other.o`) refer to it: a program's variables live as long as
    the application (CODESYS: `ADR(PLC_PRG.x)`), unlike a FUNCTION's result, which the check refuses. Other runs
    first in the task, so Main reads the value Other just wrote: 3 + scans."""
    result = build(
        "PROGRAM Other\nVAR_OUTPUT o : INT := 3; END_VAR\no := o + 1;\nEND_PROGRAM\n"
        "PROGRAM Main\nVAR p : POINTER TO INT; r : REF_TO INT; y, z : INT; END_VAR\n"
        "p := ADR(Other.o); r := REF(Other.o); y := p^; z := r^ * 10;\nEND_PROGRAM\n"
    )
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    for scan in range(1, 4):
        sim.cycle(1)
        assert (sim.read("Main.y"), sim.read("Main.z")) == (3 + scan, (3 + scan) * 10)


def test_a_state_with_references_pickles_and_restores_into_another_simulation():
    """A captured reference is not carried (it holds the simulation's objects): restoring starts it as declared,
    on the target simulation's own variable; one the body sets is set again by the next scan."""
    text = "x : INT := 3; r : REF_TO INT := REF(x); q : REF_TO INT;"
    body = "r^ := r^ + 1;\nq := REF(x);"
    first = simulation(text, body)
    first.cycle(2)
    assert first.snapshot() == {"MAIN.X": 5, "MAIN.R": "REF(x)", "MAIN.Q": "REF(x)"}
    state = pickle.loads(pickle.dumps(first.state()))
    second = simulation(text, body)
    second.restore(state)
    assert (second.read("Main.x"), second.read("Main.r"), second.read("Main.q")) == (5, "REF(x)", "NULL")
    second.cycle(1)
    assert (second.read("Main.x"), second.read("Main.q")) == (6, "REF(x)")
    assert first.read("Main.x") == 5  # the second simulation's reference reaches its own x
