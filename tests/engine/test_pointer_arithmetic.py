"""Pointer arithmetic as CODESYS defines it (issue 25 item 1; CODESYS "POINTER TO" help: ``p := p + SIZEOF(x)``
moves a pointer by bytes; IEC 61131-3 ed. 3 TYP-43 lets ``+``/``-`` take a pointer and an integer): a pointer made
by ``ADR(arr[i])`` moves along the array, a whole element (``SIZEOF`` of it) per step. Memory stays safe: moving
outside the array (one past its end is allowed, as loops need it), by a part of an element, from a variable that is
no array element, or reading one past the end is a located fault naming the pointer - never a Python error or a
write into a neighbour. Expected values are worked out by hand from the program texts.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .test_references import simulation


def test_a_pointer_walks_an_array_by_sizeof_scan_by_scan():
    sim = simulation(
        "arr : ARRAY [1..4] OF INT := [10, 20, 30, 40]; p : POINTER TO INT; sum : INT; i : INT;",
        "p := ADR(arr[1]);\nsum := 0;\nFOR i := 1 TO 4 DO\n  sum := sum + p^;\n  p^ := p^ + 1;\n"
        "  p := p + SIZEOF(arr[1]);\nEND_FOR;",
    )
    for scan in range(3):
        sim.cycle(1)
        assert sim.read("Main.sum") == 100 + 4 * scan  # each scan adds 1 to every element after summing it
        assert sim.read("Main.arr") == [11 + scan, 21 + scan, 31 + scan, 41 + scan]
        assert sim.read("Main.p") == "ADR(arr[1]) + 8"  # one past the end: allowed, never dereferenced


def test_bytes_of_a_byte_array_and_elements_of_a_structure_array():
    sim = simulation(
        "b : ARRAY [0..5] OF BYTE := [1, 2, 3, 4, 5, 6]; pb : POINTER TO BYTE; third : BYTE;"
        "pts : ARRAY [0..2] OF S; ps : POINTER TO S; last : INT;",
        "pb := ADR(b[0]) + 2;\nthird := pb^;\npb := pb - 1;\npb^ := 99;\n"
        "pts[2].f := 7;\nps := ADR(pts[0]);\nps := ps + 2 * SIZEOF(pts[0]);\nlast := ps^.f;",
    )
    sim.cycle(1)
    assert (sim.read("Main.third"), sim.read("Main.b")) == (3, [1, 99, 3, 4, 5, 6])
    assert sim.read("Main.last") == 7  # S is 2 + 3 * 2 = 8 bytes: 16 bytes on is pts[2]


@pytest.mark.parametrize(
    ("declarations", "body", "message", "line"),
    [
        (
            "a : ARRAY [1..3] OF INT; p : POINTER TO INT; y : INT;",
            "p := ADR(a[1]);\np := p + 3 * SIZEOF(a[1]);\ny := p^;",
            "the pointer ADR(a[1]) + 6 reaches element 3 of 3 element(s): outside the variable it points into",
            3,
        ),
        (
            "a : ARRAY [1..3] OF INT; p : POINTER TO INT;",
            "p := ADR(a[1]);\np := p - 2;",
            "the pointer P moved by -2 bytes reaches element -1 of 3 element(s) of 2 byte(s): outside the "
            "variable it points into",
            2,
        ),
        (  # part of an element: the INT at bytes 5..6 of the 6-byte array
            "a : ARRAY [1..3] OF INT; p : POINTER TO INT; y : INT;",
            "p := ADR(a[1]);\np := p + 5;\ny := p^;",
            "the pointer ADR(a[1]) + 5 reaches bytes 5..6 of a 6-byte variable: outside it",
            3,
        ),
        (  # one past the end of a variable that is no array element: allowed, not dereferenced
            "x : DINT; p : POINTER TO DINT;",
            "p := ADR(x);\np := p + 4;\np^ := 1;",
            "the pointer ADR(x) + 4 reaches bytes 4..7 of a 4-byte variable: outside it",
            3,
        ),
        (
            "x : DINT; p : POINTER TO DINT;",
            "p := ADR(x);\np := p + 5;",
            "the pointer P moved by 5 bytes reaches byte 5 of a 4-byte variable: outside it",
            2,
        ),
        (
            "p : POINTER TO INT;",
            "p := p + 2;",
            "the pointer P is NULL: it refers to no variable, so '^' has nothing to reach",
            1,
        ),
    ],
)
def test_leaving_the_object_is_a_located_fault(declarations, body, message, line):
    sim = simulation(declarations, body)
    sim.cycle(2)
    fault = sim.fault
    code = "null_dereference" if "NULL" in message else "index_out_of_range"
    assert fault is not None and (fault.code, fault.message, fault.scan) == (code, message, 0)
    assert (fault.pou, fault.origin.line) == ("MAIN", 5 + line)  # TYPES, PROGRAM, VAR, declarations, END_VAR


@settings(max_examples=25, deadline=None)  # (each example builds a project)
@given(st.lists(st.integers(-6, 6), min_size=1, max_size=8))
def test_any_walk_stays_inside_or_faults_where_it_leaves(steps):
    """Property: a walk of whole elements over ARRAY [0..4] OF INT either ends on the element a model of it says,
    or faults at the first step leaving 0..5 (5: one past the end, allowed)."""
    sim, position = _walk(
        "a : ARRAY [0..4] OF INT := [0, 1, 2, 3, 4]; p : POINTER TO INT; seen : INT := -1;",
        [2 * step for step in steps],
        "IF p <> ADR(a[0]) + 10 THEN seen := p^; END_IF;",
        10,
    )
    if position is not None:
        assert sim.fault is None and sim.read("Main.seen") == (position // 2 if position < 10 else -1)


def _walk(declarations: str, moves: list[int], then: str, end: int):
    """A program moving ``p := ADR(a[0])`` by each of ``moves`` bytes, then running ``then``, scanned once; and the
    byte the pointer ends on, or None after checking that the run faulted where a move left 0..end (one past the
    end of the array: allowed)."""
    sim = simulation(declarations, "p := ADR(a[0]);\n" + "".join(f"p := p + {m};\n" for m in moves) + then)
    sim.cycle(1)
    position = 0
    for move in moves:
        position += move
        if not 0 <= position <= end:
            assert sim.fault is not None and sim.fault.code == "index_out_of_range"
            return sim, None
    return sim, position


def test_a_state_with_a_moved_pointer_pickles_and_restores():
    """A moved pointer is a reference like any other: left out of a captured state (docs/runtime.md), which
    pickles; the restored simulation sets it again when its body runs."""
    import pickle

    text = "a : ARRAY [0..2] OF INT := [5, 6, 7]; p : POINTER TO INT; y : INT;"
    body = "p := ADR(a[0]) + 4;\ny := p^;\na[2] := a[2] + 1;"
    first = simulation(text, body)
    first.cycle(2)
    assert (first.read("Main.p"), first.read("Main.y")) == ("ADR(a[0]) + 4", 8)
    state = pickle.loads(pickle.dumps(first.state()))
    second = simulation(text, body)
    second.restore(state)
    assert (second.read("Main.a"), second.read("Main.p")) == ([5, 6, 9], "NULL")
    second.cycle(1)
    assert (second.read("Main.y"), second.read("Main.a")) == (9, [5, 6, 10])


SEED_GLOBALS = "VAR_GLOBAL\n  arrayINT : ARRAY[0..10] OF INT;\nEND_VAR\n"


def _seed_program(name: str, declarations: str) -> str:
    return (
        f"{SEED_GLOBALS}PROGRAM {name}\n  VAR\n{declarations}\n    varINT : INT;\n  END_VAR\n"
        "  intPTR^ := 11;\n  intPTR := intPTR + sizeof( INT);\n  intPTR^ := 22;\n"
        "  intPTR := intPTR + sizeof( INT);\n  varINT := intPTR^;\nEND_PROGRAM\n"
    )


def test_seed_000_ex_3_12_ptr_to_walks_the_global_array_ex_15():
    """EX-15 (TYP-40, TYP-42..45): Mosaic ``PTR_TO``; every scan: arrayINT[0] = 11, [1] = 22, varINT = [2] = 0."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project

    text = _seed_program("ExamplePtr", "    intPTR : PTR_TO INT;").replace(
        "  intPTR^ := 11;", "  intPTR := ADR( arrayINT[0]);\n  intPTR^ := 11;"
    )
    project, diagnostics = source_to_project(text, "seed")
    assert diagnostics == []
    sim = build_project(project).simulation()
    for _ in range(3):
        sim.cycle(1)
        assert sim.read("arrayINT")[:3] == [11, 22, 0] and sim.read("ExamplePtr.varINT") == 0


def test_seed_000_ex_3_13_a_pointer_initialised_once_faults_when_it_leaves_the_array_ex_16():
    """EX-16 (TYP-46, TYP-47): the initialiser runs once, so the pointer moves two elements per scan; in scan 6 the
    write of 22 would reach element 11 of ARRAY[0..10]: the located fault, nothing written outside."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project

    text = _seed_program("ExamplePtrErr", "    intPTR : PTR_TO INT := ADR( arrayINT[0]);")
    project, diagnostics = source_to_project(text, "seed")
    assert diagnostics == []
    sim = build_project(project).simulation()
    expected = [0] * 11
    for scan in range(5):
        sim.cycle(1)
        expected[2 * scan], expected[2 * scan + 1] = 11, 22
        assert sim.fault is None and sim.read("arrayINT") == expected
        assert sim.read("ExamplePtrErr.varINT") == 0  # element 2 * scan + 2, not written yet
    sim.cycle(1)
    expected[10] = 11
    fault = sim.fault
    assert fault is not None and fault.code == "index_out_of_range" and fault.scan == 5
    assert fault.message == (
        "the pointer ADR(arrayINT[0]) + 22 reaches element 11 of 11 element(s): outside the variable it points into"
    )
    assert (fault.pou, fault.origin.line) == ("EXAMPLEPTRERR", text.splitlines().index("  intPTR^ := 22;") + 1)
    assert sim.read("arrayINT") == expected


def test_a_pointer_moved_by_a_dword_walks_the_bytes_of_a_string():
    """OSCAT's CODE: ``PT := ADR(STR) + INT_TO_DWORD(pos - 1); CODE := pt^`` (CODESYS adds a DWORD to an address).
    The pointer to the STRING moves byte by byte through its text (STRING: one byte a character, then a NUL), and a
    POINTER TO BYTE made of it reads and writes that character: 'ABC' has 'B' (66) at byte 1."""
    sim = simulation(
        "str : STRING := 'ABC'; pos : INT := 2; pt : POINTER TO BYTE; w : WORD := 2; c : BYTE; nul : BYTE;",
        "pt := ADR(str) + INT_TO_DWORD(pos - 1);\nc := pt^;\npt^ := 98;\npt := ADR(str) + w + 1;\nnul := pt^;",
    )
    sim.cycle(1)
    assert (sim.read("Main.c"), sim.read("Main.str"), sim.read("Main.nul")) == (66, "AbC", 0)
    assert sim.read("Main.pt") == "ADR(str) + 3"


def test_part_of_an_element_sees_the_bytes_of_two_neighbours_little_endian():
    """CODESYS on x86/ARM: ARRAY [0..1] OF INT [16#1234, 16#5678] is the bytes 34 12 78 56; an INT pointer one byte
    on reads 12 78 (16#7812 = 30738) and writing 16#ABCD there stores CD AB: a[0] = 16#CD34 (-13004 as an INT),
    a[1] = 16#56AB (22187)."""
    sim = simulation(
        "a : ARRAY [0..1] OF INT := [16#1234, 16#5678]; p : POINTER TO INT; y : INT;",
        "p := ADR(a[0]) + 1;\ny := p^;\np^ := WORD_TO_INT(16#ABCD);",
    )
    sim.cycle(1)
    assert (sim.read("Main.y"), sim.read("Main.a")) == (30738, [-13004, 22187])


@settings(max_examples=20, deadline=None)  # (each example builds a project)
@given(st.lists(st.integers(-3, 3), min_size=1, max_size=6))
def test_any_byte_walk_of_an_int_pointer_reads_two_little_endian_bytes_or_faults(steps):
    """Property: a POINTER TO INT walked byte by byte over ARRAY [0..2] OF INT [1, 2, 3] (CODESYS: any byte offset;
    the bytes are 01 00 02 00 03 00) reads bytes k and k + 1 little-endian (b[k] + 256 * b[k + 1]) while both lie
    inside the 6 bytes; a move outside 0..6 (6: one past the end) faults there, a read from byte 5 or 6 at the read."""
    sim, position = _walk(
        "a : ARRAY [0..2] OF INT := [1, 2, 3]; p : POINTER TO INT; w : INT := -1;", steps, "w := p^;", 6
    )
    data = [1, 0, 2, 0, 3, 0]
    if position is None:
        return
    if position > 4:
        assert sim.fault is not None and sim.fault.code == "index_out_of_range"
        assert sim.read("Main.w") == -1
    else:
        assert sim.fault is None and sim.read("Main.w") == data[position] + 256 * data[position + 1]
