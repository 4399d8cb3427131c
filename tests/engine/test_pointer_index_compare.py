"""Pointer indexing and comparison as CODESYS defines them (issue 25 item 1; CODESYS "POINTER TO" help, "Index access
to pointers": ``piData[i] := (piData + i * SIZEOF(INT))^``, not ``(piData + i)^``; its static analysis SA0061 counts
``=`` and ``<>`` as the usual operations on pointers, and ``p <> 0`` is how CODESYS code tests for a pointer that
points nowhere). ``p[i]`` is the i-th element on from where p points, read and written, with the same located fault
as ``p + n`` when it leaves the array; ``p = q`` / ``p <> q`` compare what two pointers point to, ``p = 0`` whether
p is NULL; ``p < q`` (issue 25 item 3) orders two pointers into one variable by the byte they point to, and is a
located fault for pointers into different variables or NULL (LadderLab's variables have no addresses to order).
Expected values are worked out by hand from the program texts."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .test_references import build, simulation

ARRAY = "a : ARRAY [0..3] OF INT := [10, 20, 30, 40]; p, q : POINTER TO INT; x, y : INT; i : INT := 1;"


def test_indexing_a_pointer_reads_and_writes_elements_on_from_its_target_scan_by_scan():
    sim = simulation(ARRAY, "p := ADR(a[1]);\nx := p[i];\np[2] := x + 1;\ny := p[0] + p[-1];\ni := i + 1;")
    a = [10, 20, 30, 40]
    for scan, i in ((1, 1), (2, 2)):
        sim.cycle(1)
        x = a[1 + i]  # p points to a[1]: p[i] is a[1 + i]
        a[3] = x + 1  # p[2] is a[3]
        assert (sim.read("Main.x"), sim.read("Main.a"), sim.read("Main.y")) == (x, a, 20 + 10), scan
    sim.cycle(1)  # i = 3: p[3] would be a[4], outside the array
    fault = sim.fault
    assert fault is not None and fault.code == "index_out_of_range"
    assert fault.message.startswith("the pointer ADR(a[1]) + 6 reaches element 4 of 4")  # one past the end
    assert (fault.pou, fault.origin.line) == ("MAIN", 7)  # TYPES, PROGRAM, VAR, declarations, END_VAR, p := ...


@settings(max_examples=60, deadline=None)
@given(start=st.integers(0, 3), index=st.integers(-5, 5))
def test_p_of_i_is_the_element_i_on_or_a_fault(start, index):
    """Against the array itself: a[start + index] when that is an element, else the located fault."""
    sim = simulation(ARRAY, f"p := ADR(a[{start}]);\nx := p[{index}];")
    sim.cycle(1)
    if 0 <= start + index <= 3:
        assert sim.fault is None and sim.read("Main.x") == [10, 20, 30, 40][start + index]
    else:
        assert sim.fault is not None and sim.fault.code == "index_out_of_range"


def test_pointer_comparisons_with_each_other_null_and_zero():
    """``q = 0`` is CODESYS's test for NULL: CODESYS typing (IEC typing refuses it: test_pointer_zero.py)."""
    sim = simulation(
        ARRAY + " same, other, nowhere, somewhere, zero_first : BOOL; n : INT;",
        "IF n > 0 THEN q := ADR(a[n]); END_IF;\np := ADR(a[1]);\nsame := p = q;\nother := p <> q;\n"
        "nowhere := q = 0;\nsomewhere := q <> NULL;\nzero_first := 0 = q;\nn := n + 1;",
        typing="codesys",
    )
    for scan, (same, null) in enumerate(((False, True), (True, False), (False, False)), start=1):
        sim.cycle(1)  # q: NULL in scan 1, then ADR(a[1]), ADR(a[2])
        values = [sim.read(f"Main.{v}") for v in ("same", "other", "nowhere", "somewhere", "zero_first")]
        assert values == [same, not same, null, not null, null], scan


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ("IF p < 5 THEN x := 1; END_IF;", "'<' needs operands of the same type"),
        ("IF p = 5 THEN x := 1; END_IF;", "'=' needs operands of the same type: REF_TO INT and ANY_INT literal"),
        ("x := p[1, 2];", "a pointer takes one index: p[i] is (p + i * SIZEOF(p^))^"),
        ("WHILE p[i] > 0 DO i := i + 1; END_WHILE;", "p[i] cannot be evaluated here in the right order"),
    ],
)
def test_what_stays_refused(body, message):
    result = build(f"PROGRAM Main\nVAR\n{ARRAY}\nEND_VAR\n{body}\nEND_PROGRAM\n")
    assert any(message in d.message for d in result.diagnostics if d.severity == "error"), [
        d.format() for d in result.diagnostics
    ]


@settings(max_examples=40, deadline=None)
@given(first=st.integers(0, 3), second=st.integers(0, 3))
def test_pointers_into_one_array_are_ordered_by_element_like_their_indices(first, second):
    sim = _ORDER_SIM
    sim.write("Main.i", first)
    sim.write("Main.j", second)
    sim.cycle(1)
    assert sim.fault is None
    expected = [first < second, first <= second, first > second, first >= second]
    assert [sim.read(f"Main.{v}") for v in ("lt", "le", "gt", "ge")] == expected


_ORDER_SIM = simulation(
    ARRAY + " j : INT; lt, le, gt, ge : BOOL;",
    "p := ADR(a[0]) + i * SIZEOF(a[0]);\nq := ADR(a[j]);\nlt := p < q;\nle := p <= q;\ngt := p > q;\nge := p >= q;",
)


def test_a_byte_pointer_walking_a_string_stops_at_a_pointer_to_its_end():
    """OSCAT's loops ``WHILE pt < stop DO``: both pointers see the same STRING's bytes."""
    sim = simulation(
        "s : STRING[10] := 'abcd'; pt, stop : POINTER TO BYTE; n : INT;",
        "pt := ADR(s);\nstop := ADR(s);\nstop := stop + LEN(s);\nn := 0;\n"
        "WHILE pt < stop DO\n  pt^ := pt^ XOR 16#20;\n  pt := pt + 1;\n  n := n + 1;\nEND_WHILE;",
    )
    sim.cycle(1)
    assert (sim.read("Main.s"), sim.read("Main.n"), sim.fault) == ("ABCD", 4, None)


@pytest.mark.parametrize(
    ("body", "message", "line"),
    [
        ("p := ADR(a[0]);\nq := ADR(x);\ny := SEL(p < q, 1, 2);", "ADR(a[0]) < ADR(x)", 3),
        ("p := ADR(a[0]);\ny := SEL(p >= q, 1, 2);", "ADR(a[0]) >= NULL", 2),
    ],
)
def test_ordering_pointers_into_different_variables_or_null_is_a_located_fault(body, message, line):
    sim = simulation(ARRAY, body)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and fault.code == "invalid_argument"
    assert fault.message == f"{message}: only pointers into one variable (an array, a STRING) can be ordered"
    assert (fault.pou, fault.origin.line) == ("MAIN", 5 + line)  # TYPES, PROGRAM, VAR, declarations, END_VAR
