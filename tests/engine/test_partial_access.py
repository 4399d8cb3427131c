"""Partial access to bit strings (IEC 61131-3 ed. 3, 6.5.6): ``x.%X3`` (as ``x.3``), ``x.%B1``, ``x.%W0``, ``x.%D1``,
``x.%L0``, read and written, on variables, array elements and structure fields; a part outside the variable is a
located error. Expected values are computed here from the bit pattern (parts numbered from the least significant).
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.ir.diagram_support import box, coil, contact, fbd_pou, inp, ld_pou, net, out, project, rung

D = 0x11223344
L = 0x0102030405060708


def part(value: int, width: int, index: int) -> int:
    return (value >> (width * index)) & ((1 << width) - 1)


def put(value: int, width: int, index: int, new: int) -> int:
    mask = ((1 << width) - 1) << (width * index)
    return (value & ~mask) | ((new << (width * index)) & mask)


def run(declarations: str, body: str, *paths: str) -> list:
    text = f"TYPE S : STRUCT f : DWORD; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n"
    project_, diagnostics = source_to_project(text, "parts")
    assert project_ is not None, diagnostics
    build = build_project(project_)
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    return [sim.read(f"Main.{p}") for p in paths]


VARS = f"d : DWORD := 16#{D:X}; l : LWORD := 16#{L:X}; i : INT := -2; k : DINT := -300;"


@pytest.mark.parametrize(
    "expression, result_type, expected",
    [
        ("d.%B0", "BYTE", part(D, 8, 0)),
        ("d.%B3", "BYTE", part(D, 8, 3)),
        ("l.%B7", "BYTE", part(L, 8, 7)),
        ("d.%W1", "WORD", part(D, 16, 1)),
        ("l.%W2", "WORD", part(L, 16, 2)),
        ("l.%D1", "DWORD", part(L, 32, 1)),
        ("l.%L0", "LWORD", L),
        ("d.%D0", "DWORD", D),
        ("i.%B1", "BYTE", part(-2 & 0xFFFF, 8, 1)),  # an integer's two's complement pattern
        ("k.%W0", "WORD", part(-300 & 0xFFFFFFFF, 16, 0)),
        ("d.%X2", "BOOL", bool(part(D, 1, 2))),
        ("l.%X63", "BOOL", False),
        ("d.%X4", "BOOL", bool(part(D, 1, 4))),
    ],
)
def test_reading_a_part(expression, result_type, expected):
    (value,) = run(f"{VARS}\nr : {result_type};", f"r := {expression};", "r")
    assert value == expected


@pytest.mark.parametrize(
    "statement, path, expected",
    [
        ("d.%B1 := 16#FF;", "d", put(D, 8, 1, 0xFF)),
        ("d.%B0 := 0;", "d", put(D, 8, 0, 0)),
        ("l.%W1 := 16#ABCD;", "l", put(L, 16, 1, 0xABCD)),
        ("l.%D1 := 16#DEADBEEF;", "l", put(L, 32, 1, 0xDEADBEEF)),
        ("l.%X40 := FALSE;", "l", put(L, 1, 40, 0)),
        ("d.%X31 := TRUE;", "d", put(D, 1, 31, 1)),
        ("i.%B0 := 0;", "i", -256),  # 16#FFFE -> 16#FF00
        ("k.%W1 := 0;", "k", put(-300 & 0xFFFFFFFF, 16, 1, 0)),
    ],
)
def test_writing_a_part_keeps_the_other_bits(statement, path, expected):
    (value,) = run(VARS, statement, path)
    assert value == expected


def test_parts_of_array_elements_and_structure_fields():
    arr, f = run(
        "arr : ARRAY[0..1] OF DWORD := [16#AABBCCDD, 16#01020304]; s : S := (f := 16#FFFFFFFF);",
        "arr[1].%B2 := arr[0].%B1;\ns.f.%W0 := 16#1234;\narr[0].%X0 := s.f.%X31;",
        "arr",
        "s.f",
    )
    assert arr == [0xAABBCCDD, put(0x01020304, 8, 2, 0xCC)]
    assert f == 0xFFFF1234


@pytest.mark.parametrize(
    "statement, column, message",
    [
        ("b := d.%B4;", 6, "'%B4' is outside a DWORD: it has bytes 0..3"),
        ("d := w.%D0;", 6, "a WORD has no double words: it is 16 bits wide"),
        ("x := d.%X32;", 6, "'%X32' is outside a DWORD: it has bits 0..31"),
        ("x := d.32;", 6, "'32' is outside a DWORD: it has bits 0..31"),
        ("b := r.%B0;", 6, "'%B0' cannot be selected from a REAL"),
        ("w.%B2 := 1;", 1, "'%B2' is outside a WORD: it has bytes 0..1"),
    ],
)
def test_a_part_outside_the_variable_is_a_located_error(statement, column, message):
    text = f"PROGRAM Main\nVAR d : DWORD; w : WORD; b : BYTE; x : BOOL; r : REAL; END_VAR\n{statement}\nEND_PROGRAM\n"
    project_, _ = source_to_project(text, "parts")
    found = [d.format() for d in build_project(project_).diagnostics if d.severity == "error"]
    assert found == [f"Main/body:3:{column}, POU Main: error ST-UNKNOWN-MEMBER: {message}"]


def test_a_part_is_an_operand_of_an_ld_box():
    pou = ld_pou(
        "Main",
        f"VAR d : DWORD := 16#{D:X}; b : BYTE; run : BOOL := TRUE; END_VAR",
        rung(
            "N1", contact("C1", "d.%X2"), box("B1", "MOVE", en=True, IN="d.%B2", outputs={"OUT": "b"}), coil("Q", "run")
        ),
    )
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    assert sim.read("Main.b") == part(D, 8, 2)


def test_ld_coils_write_a_bit_and_keep_the_others():
    """IEC ed. 3 6.5.6 and CODESYS' short form: a coil on ``w.3`` / ``w.%X5`` (set, negated too) writes that bit."""
    pou = ld_pou(
        "Main",
        "VAR w : WORD := 16#8001; d : DWORD := 16#F0; run : BOOL := TRUE; k : INT := 1; END_VAR",
        rung("N1", contact("C1", "run"), coil("Q1", "w.3")),
        rung("N2", contact("C2", "d.4"), coil("Q2", "w.%X5", "set")),
        rung("N3", contact("C3", "d.0"), coil("Q3", "k.1", "negated")),
        rung("N4", contact("C4", "run"), coil("Q4", "w.0", "reset")),
    )
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    w = put(put(put(0x8001, 1, 3, 1), 1, 5, 1), 1, 0, 0)
    assert [sim.read("Main.w"), sim.read("Main.k")] == [w, put(1, 1, 1, 1)]


def test_fbd_output_nodes_write_a_bit_or_a_part():
    pou = fbd_pou(
        "Main",
        "VAR d : DWORD := 16#11223344; flag : BOOL := TRUE; END_VAR",
        net("n1", [inp("v1", "16#AB"), out("o1", "d.%B2")], [("v1.OUT", "o1.IN")]),
        net("n2", [inp("v2", "flag"), out("o2", "d.31")], [("v2.OUT", "o2.IN")]),
    )
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    assert sim.read("Main.d") == put(put(0x11223344, 8, 2, 0xAB), 1, 31, 1)


def test_ld_box_outputs_write_a_part_only_when_the_box_runs():
    """Issue 25: a function box's OUT into a bit or part (``w.%B1``, ``w.%X0``, an integer's ``k.%B0``) writes that part
    as ST's ``w.%B1 := MOVE(16#AB)`` does, the other bits kept; with EN FALSE the box does not run and the variable
    keeps its value (LD-08), as with a whole variable at OUT."""
    pou = ld_pou(
        "Main",
        "VAR w : WORD := 16#1235; k : INT := -1; run : BOOL := TRUE; END_VAR",
        rung("N1", contact("C1", "run"), box("B1", "MOVE", en=True, IN="16#AB", outputs={"OUT": "w.%B1"})),
        rung("N2", contact("C2", "run"), box("B2", "GT", en=True, IN1="k", IN2="0", outputs={"OUT": "w.%X0"})),
        rung("N3", contact("C3", "run"), box("B3", "MOVE", en=True, IN="16#00", outputs={"OUT": "k.%B0"})),
    )
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    w = put(put(0x1235, 8, 1, 0xAB), 1, 0, 0)  # -1 > 0 is FALSE
    k = put(0xFFFF, 8, 0, 0x00) - 0x10000  # INT's two's complement pattern 16#FF00
    assert [sim.read("Main.w"), sim.read("Main.k")] == [w, k]
    sim.write("Main.run", False)
    sim.write("Main.w", 0x1235)
    sim.write("Main.k", 5)
    sim.cycle(1)
    assert [sim.read("Main.w"), sim.read("Main.k")] == [0x1235, 5]  # no box ran: nothing written
    sim.write("Main.run", True)
    sim.cycle(1)
    assert [sim.read("Main.w"), sim.read("Main.k")] == [put(put(0x1235, 8, 1, 0xAB), 1, 0, 1), put(5, 8, 0, 0)]


def test_a_box_output_into_a_part_keeps_the_st_type_rules():
    """The part's type takes the result by ST's assignment rule (ST-23), reported at the box's OUT."""
    pou = ld_pou(
        "Main",
        "VAR w : WORD; r : REAL := 1.5; run : BOOL := TRUE; END_VAR",
        rung("N1", contact("C1", "run"), box("B1", "MOVE", en=True, IN="r", outputs={"OUT": "w.%B1"})),
        rung("N2", contact("C2", "run"), box("B2", "MOVE", en=True, IN="16#AB", outputs={"OUT": "w.%B2"})),
    )
    found = [d.format() for d in build_project(project(pou)).diagnostics if d.severity == "error"]
    assert found == [
        "POU Main, network 1, MOVE.OUT: error ST-TYPE-MISMATCH: output OUT of MOVE ('w.%B1'): expected BYTE, got REAL "
        "without a conversion such as REAL_TO_BYTE",
        "POU Main, network 2, MOVE.OUT: error ST-UNKNOWN-MEMBER: '%B2' is outside a WORD: it has bytes 0..1",
    ]
