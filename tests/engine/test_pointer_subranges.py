"""Subrange variables reached by pointer or reference stay in their range (issue 25, item 1: memory safety).

A subrange ``INT (0..100)`` written through a pointer of its base type (REF_TO INT, POINTER TO INT, REFERENCE TO
INT, a VAR_IN_OUT of INT), through a byte view (POINTER TO BYTE, moved by an offset), or as an array element or a
STRUCT member, faults ``subrange_violation`` with the words of a direct out-of-range assignment (``500 is outside the
subrange 0..100``) and what it was written through, at the writing statement's POU and line; in-range writes work.
A pointer to a subrange over a variable of its base type faults when it reads a value outside the range; a pointer
copied out of an FB or method output keeps the check; an array assigned whole into an array of a subrange (an
assignment, an input, an output) has every element checked. Pointers:
seed 000 TYP-42 (ADR), TYP-43 (byte arithmetic), TYP-44 (``^``), TYP-46 (initialiser), TYP-47 (the run-time check
covers the target object; subranges TYP-14). Expected values are computed by hand from the program text.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.model.project import Pou
from ladderlab.simulation.build import build_project
from tests.ir.diagram_support import box, ld_pou, project, rung
from tests.support import line_of

from .ed3_support import build, errors, program

TYPES = """TYPE Pct : INT (0..100); END_TYPE
TYPE Rec : STRUCT m : Pct; END_STRUCT; END_TYPE
FUNCTION SetInt : INT
VAR_IN_OUT x : INT; END_VAR
VAR_INPUT n : INT; END_VAR
x := n;
SetInt := 0;
END_FUNCTION
FUNCTION SetRef : INT
VAR_INPUT r : REFERENCE TO INT; n : INT; END_VAR
r := n;
SetRef := 0;
END_FUNCTION
FUNCTION_BLOCK Owner
VAR_OUTPUT q : POINTER TO Pct; END_VAR
VAR v : Pct; END_VAR
q := ADR(v);
END_FUNCTION_BLOCK
FUNCTION_BLOCK Lender
VAR v : Pct; END_VAR
METHOD Lend : BOOL
VAR_OUTPUT q : POINTER TO Pct; END_VAR
q := ADR(v);
Lend := TRUE;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Setter
VAR_IN_OUT io : INT; END_VAR
VAR_INPUT n : INT; END_VAR
io := n;
END_FUNCTION_BLOCK"""


# (declarations, body writing k * 40 into the subrange through the path, the variable read, what the fault names,
# the statement faulting, the POU it is in)
WRITES = [
    ("v : Pct; p : REF_TO INT;", "p := REF(v);\np^ := k * 40;", "v", "REF(v)", "p^ := k * 40;", "MAIN"),
    ("v : Pct; p : POINTER TO INT;", "p := ADR(v);\np^ := k * 40;", "v", "ADR(v)", "p^ := k * 40;", "MAIN"),
    ("v : Pct; r : REFERENCE TO INT;", "r REF= v;\nr := k * 40;", "v", "REF(v)", "r := k * 40;", "MAIN"),
    ("v : Pct; p : POINTER TO BYTE;", "p := ADR(v);\np^ := INT_TO_BYTE(k * 40);", "v", "ADR(v)", "p^ := INT_TO_BYTE(k * 40);", "MAIN"),
    ("v : Pct; p : POINTER TO INT := ADR(v);", "p^ := k * 40;", "v", "ADR(v)", "p^ := k * 40;", "MAIN"),
    ("a : ARRAY[1..3] OF Pct; p : POINTER TO INT;", "p := ADR(a[2]);\np^ := k * 40;", "a[2]", "ADR(a[2])", "p^ := k * 40;", "MAIN"),
    ("a : ARRAY[1..3] OF Pct; p : POINTER TO INT;", "p := ADR(a[1]);\np[1] := k * 40;", "a[2]", "ADR(a[1]) + 2", "p[1] := k * 40;", "MAIN"),
    ("a : ARRAY[1..3] OF Pct; p : POINTER TO Pct; q : POINTER TO INT;", "p := ADR(a[1]);\nq := p + 4;\nq^ := k * 40;", "a[3]", "ADR(a[1]) + 4", "q^ := k * 40;", "MAIN"),
    ("s : Rec; p : POINTER TO INT;", "p := ADR(s.m);\np^ := k * 40;", "s.m", "ADR(s.m)", "p^ := k * 40;", "MAIN"),
    ("v : Pct; p : POINTER TO INT; n : INT;", "p := ADR(v);\nn := SetInt(p^, k * 40);", "v", "ADR(v)", "x := n;", "SETINT"),
    ("v : Pct; n : INT;", "n := SetInt(v, k * 40);", "v", "the VAR_IN_OUT argument V", "x := n;", "SETINT"),
    ("v : Pct; f : Setter;", "f(io := v, n := k * 40);", "v", "the VAR_IN_OUT argument V", "io := n;", "SETTER"),
    ("v : Pct; n : INT;", "n := SetRef(v, k * 40);", "v", "REF(v)", "r := n;", "SETREF"),
    ("o : Owner; p : POINTER TO INT;", "o(q => p);\np^ := k * 40;", "o.v", "ADR(v)", "p^ := k * 40;", "MAIN"),
    ("l : Lender; p : POINTER TO INT; b : BOOL;", "l.Lend(q => p);\np^ := k * 40;", "l.v", "ADR(v)", "p^ := k * 40;", "MAIN"),
]  # fmt: skip


@pytest.mark.parametrize("declarations, body, path, through, statement, pou", WRITES)
def test_a_write_through_a_pointer_keeps_a_subrange_in_its_range_scan_by_scan(
    declarations, body, path, through, statement, pou
):
    """k counts scans: 40 and 80 are written, 120 is a fault naming what it was written through; the variable keeps
    80. Each row was a silent 120 before (and later 160, 200...)."""
    text = program(f"k : INT; {declarations}", f"k := k + 1;\n{body}", TYPES)
    sim = build(text).simulation()
    for scan in (1, 2):
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        assert sim.read(f"Main.{path}") == 40 * scan
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None
    assert (fault.code, fault.message) == (
        "subrange_violation",
        f"120 is outside the subrange 0..100: written through {through}",
    )
    assert (fault.pou, fault.origin.line) == (pou, line_of(text, statement))
    assert sim.read(f"Main.{path}") == 80


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_a_byte_written_into_a_subrange_faults_when_the_whole_leaves_it(variant):
    """The high byte of v (50) written 0, then 1: 1 * 256 + 50 = 306 is outside 0..100 (little-endian, TYP-43)."""
    body = "k := k + 1;\np := ADR(v) + 1;\np^ := INT_TO_BYTE(k - 1);"
    text = program("k : INT; v : Pct := 50; p : POINTER TO BYTE;", body, TYPES)
    sim = build(text, variant).simulation()
    sim.cycle(1)
    assert sim.fault is None and sim.read("Main.v") == 50
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "306 is outside the subrange 0..100: written through ADR(v) + 1",
    )
    assert sim.fault.origin.line == line_of(text, "p^ := INT_TO_BYTE(k - 1);") and sim.read("Main.v") == 50


def test_a_whole_array_written_through_a_pointer_faults_at_the_element_outside_the_range():
    """Elements are written in order: a[1] takes 1, a[2] would take 500 (outside 0..100), a[3] keeps 0."""
    declarations = "a : ARRAY[1..3] OF Pct; b : ARRAY[1..3] OF INT := [1, 500, 3]; p : POINTER TO ARRAY[1..3] OF INT;"
    text = program(declarations, "p := ADR(a);\np^ := b;", TYPES)
    sim = build(text).simulation()
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "500 is outside the subrange 0..100: written through ADR(a) + 2",
    )
    assert sim.read("Main.a") == [1, 0, 0]


def test_a_pointer_to_a_subrange_faults_reading_a_value_outside_it():
    """x is an INT holding 30, then 130: read through a POINTER TO Pct, 130 is no Pct value."""
    body = "x := x + 100;\np := ADR(x);\nw := p^;"
    text = program("x : INT := -70; p : POINTER TO Pct; w : Pct;", body, TYPES)
    sim = build(text).simulation()
    sim.cycle(1)
    assert sim.fault is None and sim.read("Main.w") == 30
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "130 is outside the subrange 0..100: read through ADR(x)",
    )
    assert sim.fault.origin.line == line_of(text, "w := p^;") and sim.read("Main.w") == 30


def test_a_pointer_to_an_array_element_shows_and_compares_as_that_element():
    """ADR(a[2]) seen through a POINTER TO INT (a view of the subrange array) is shown as written and equals ADR(a[2])."""
    body = "p := ADR(a[2]);\nsame := p = ADR(a[2]);\nother := p = ADR(a[1]);"
    text = program("a : ARRAY[1..3] OF Pct; p : POINTER TO INT; same : BOOL; other : BOOL;", body, TYPES)
    sim = build(text).simulation()
    sim.cycle(1)
    assert (sim.read("Main.p"), sim.read("Main.same"), sim.read("Main.other")) == ("ADR(a[2])", True, False)


def test_an_array_of_a_subrange_passed_to_a_var_in_out_of_its_base_is_refused():
    """The callee reaches an in-out array's elements directly: no view could check them, so the call is refused."""
    text = program(
        "a : ARRAY[1..3] OF Pct; n : INT;",
        "n := Fill(a);",
        TYPES
        + """
FUNCTION Fill : INT
VAR_IN_OUT x : ARRAY[1..3] OF INT; END_VAR
x[2] := 500;
Fill := 0;
END_FUNCTION""",
    )
    found = errors(text)
    assert found == [
        f"POU MAIN line {line_of(text, 'n := Fill(a);')} column 1: error ENGINE-COMPILE: an ARRAY [1..3] OF INT (0..100) "
        "cannot be passed to a VAR_IN_OUT ARRAY [1..3] OF INT: the subrange of its elements would go unchecked (pass "
        "an array of the parameter's element type)"
    ]


@settings(max_examples=60, deadline=None)
@given(low=st.integers(-200, 200), span=st.integers(0, 300), value=st.integers(-32768, 32767))
def test_any_value_written_through_a_pointer_is_kept_in_range_or_faults(low, span, value):
    """In low..high the subrange variable takes the value; outside it the write faults with the value and the range,
    and the variable keeps its start value (0 when the range holds it, else low: TYP-05's default)."""
    high = low + span
    text = program(f"v : INT ({low}..{high}); p : POINTER TO INT; n : INT := {value};", "p := ADR(v);\np^ := n;")
    sim = build(text).simulation()
    sim.cycle(1)
    if low <= value <= high:
        assert sim.fault is None and sim.read("Main.v") == value
    else:
        assert (sim.fault.code, sim.fault.message) == (
            "subrange_violation",
            f"{value} is outside the subrange {low}..{high}: written through ADR(v)",
        )
        assert sim.read("Main.v") == (0 if low <= 0 <= high else low)


ARRAYS = """FUNCTION Middle : INT
VAR_INPUT a : ARRAY[1..3] OF Pct; END_VAR
Middle := a[2];
END_FUNCTION
FUNCTION_BLOCK Keeper
VAR_INPUT a : ARRAY[1..3] OF Pct; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK Giver
VAR_INPUT n : INT; END_VAR
VAR_OUTPUT o : ARRAY[1..3] OF INT; END_VAR
o[2] := n;
END_FUNCTION_BLOCK"""


@pytest.mark.parametrize(
    "declarations, statement, path, first",
    [
        ("a : ARRAY[1..3] OF Pct;", "a := b;", "a", [1, 60, 3]),
        ("m : INT;", "m := Middle(b);", "m", 60),
        ("f : Keeper;", "f(a := b);", "f.a[2]", 60),
        ("g : Giver; a : ARRAY[1..3] OF Pct;", "g(n := b[2], o => a);", "a", [0, 60, 0]),
    ],
)
def test_an_array_assigned_whole_into_an_array_of_a_subrange_has_every_element_checked(
    declarations, statement, path, first
):
    """b[2] is 60, then 120: the array (a copy, an input, an output) takes 60, and 120 is the fault of a direct
    assignment, at the statement; nothing of the array is written (it was [1, 120, 3] silently before)."""
    body = f"b[2] := b[2] + 60;\n{statement}"
    text = program(f"b : ARRAY[1..3] OF INT := [1, 0, 3]; {declarations}", body, f"{TYPES}\n{ARRAYS}")
    sim = build(text).simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert sim.read(f"Main.{path}") == first
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == ("subrange_violation", "120 is outside the subrange 0..100")
    assert sim.fault.origin.line == line_of(text, statement) and sim.read(f"Main.{path}") == first


def test_an_array_seen_over_other_memory_is_copied_when_passed_by_value():
    """``Low(pa^)`` over a DWORD: the function's input is a copy, so its write leaves d as it was (it wrote d's low
    byte before); it returns what it wrote, 16#FF."""
    declarations = "d : DWORD := 16#11223344; pa : POINTER TO ARRAY[0..3] OF BYTE; n : INT;"
    function = """FUNCTION Low : INT
VAR_INPUT a : ARRAY[0..3] OF BYTE; END_VAR
a[0] := 16#FF;
Low := BYTE_TO_INT(a[0]);
END_FUNCTION"""
    sim = build(program(declarations, "pa := ADR(d);\nn := Low(pa^);", function)).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.n"), sim.read("Main.d")) == (None, 0xFF, 0x11223344)


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_an_ld_box_s_in_out_keeps_a_subrange_in_range_in_every_variant(variant):
    """An LD box of an FB whose VAR_IN_OUT is an INT, given a Pct: 50 is written, 500 faults in the FB's body. The
    monitor variant runs the network under ``if ll_view[u]:`` (its viewed-network list), which once hid the pointer
    view function of the same name: an internal error."""
    setter = Pou(
        name="Setter",
        kind="function_block",
        language="st",
        declarations="VAR_IN_OUT io : INT; END_VAR\nVAR_INPUT n : INT; END_VAR",
        body="io := n;",
    )
    main = ld_pou(
        "Main",
        "VAR f : Setter; v : Pct; k : INT; END_VAR",
        rung("r1", box("b1", "Setter", instance="f", en=True, io="v", n="k")),
    )
    sim = build_project(project(main, setter, types="TYPE Pct : INT (0..100); END_TYPE"), variant).simulation()
    sim.write("Main.k", 50)
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.v")) == (None, 50)
    sim.write("Main.k", 500)
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message, sim.fault.pou) == (
        "subrange_violation",
        "500 is outside the subrange 0..100: written through the VAR_IN_OUT argument V",
        "SETTER",
    )
    assert sim.read("Main.v") == 50


def test_a_user_write_through_a_pointer_is_refused_when_the_subrange_cannot_hold_it():
    """Online (ON-11 paths through pointers): ``Main.p^`` := 50 is written into v at the next scan; 500 is refused when
    given, with the fault's words, and nothing is written; ``Main.q^``, a POINTER TO Pct over the INT x = 500, is no
    value of its type (reading it is refused), yet x takes a Pct value written through it."""
    text = program(
        "v : Pct; x : INT := 500; p : POINTER TO INT; q : POINTER TO Pct;", "p := ADR(v);\nq := ADR(x);", TYPES
    )
    sim = build(text).simulation()
    sim.cycle(1)
    sim.write("Main.p^", 50)
    with pytest.raises(ValueError) as refused:
        sim.write("Main.p^", 500)
    assert str(refused.value) == "MAIN.P^: 500 is outside the subrange 0..100: written through ADR(v)"
    with pytest.raises(ValueError) as unread:
        sim.read("Main.q^")
    assert str(unread.value) == "MAIN.Q^: 500 is outside the subrange 0..100: read through ADR(x)"
    sim.write("Main.q^", 7)
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.v"), sim.read("Main.x")) == (None, 50, 7)
