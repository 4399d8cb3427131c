"""CODESYS ``REFERENCE TO`` (issue 25, item 1): bound with ``REF=``, read and written through without ``^``, as array
elements, structure and array targets, named types; ``__ISVALIDREF``; the engine stays memory safe - an unbound
reference read is the located NULL fault, a reference to a CONSTANT is refused (ST-REF) - and SIZEOF.
Expected values are the referent's, computed by hand from the program text."""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.simulation.build import build_project
from ladderlab.st.parser import parse_source
from ladderlab.st.printer import print_source
from ladderlab.st.project_text import source_to_project

from .ed3_support import build, errors, program, scans

TYPES = """TYPE IntRef : REFERENCE TO INT; END_TYPE
TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE"""

BODY = """
before := __ISVALIDREF(r);
r REF= x;
after := __ISVALIDREF(r);
y := r + 1;
r := r + 10;
z := r^;
r2 REF= r;
r2 := r2 + 1;
refs[1] REF= y;
doubled := refs[1] * 2;
rp REF= p;
rp.y := rp.y + 7;
ra REF= arr;
ra[2] := ra[3] * 10;
"""
DECLS = """x : INT := 42; r : REFERENCE TO INT; y : INT; z : INT; r2 : IntRef; refs : ARRAY[0..2] OF REFERENCE TO INT;
doubled : INT; before : BOOL; after : BOOL; p : Pt; rp : REFERENCE TO Pt; arr : ARRAY[1..3] OF INT := [1, 2, 3];
ra : REFERENCE TO ARRAY[1..3] OF INT;"""


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_reference_to_reads_and_writes_its_target_scan_by_scan(variant):
    text = program(DECLS, BODY, TYPES)
    seen = scans(text, 2, "x", "y", "z", "doubled", "before", "after", "p.y", "arr", variant=variant)
    x = 42
    expected = []
    for scan in range(2):
        before = scan > 0  # r stays bound from the first scan on
        y = x + 1
        x = x + 10
        z = x
        x = x + 1  # through r2, bound to what r refers to
        expected.append([x, y, z, y * 2, before, True, 7 * (scan + 1), [1, 30, 3]])
    assert seen == expected


def test_an_unbound_reference_read_is_a_located_null_fault():
    sim = build(program("r : REFERENCE TO INT; y : INT;", "y := 1;\ny := r;")).simulation()
    sim.cycle(1)
    assert sim.fault is not None and "is NULL" in sim.fault.text() and "line 7" in sim.fault.text(), sim.fault.text()
    assert sim.read("Main.y") == 1


@pytest.mark.parametrize(
    "declarations, body, message",
    [
        ("r : REFERENCE TO INT; d : DINT;", "r REF= d;", "ST-TYPE-MISMATCH: a REFERENCE TO INT cannot refer to a DINT"),
        ("r : REF_TO INT; x : INT;", "r REF= x;", "REF= binds a REFERENCE TO variable, not REF_TO INT"),
        ("r : REFERENCE TO INT; x : INT;", "r REF= x + 1;", "ST-NOT-LVALUE: REF= needs a variable on its right"),
        ("r : REFERENCE TO INT; x : INT;", "r := REF(x);", "cannot assign REF_TO INT to INT"),
        ("x : INT; b : BOOL;", "b := __ISVALIDREF(x);", "__ISVALIDREF needs a reference, not INT"),
    ],
)
def test_reference_to_misuse_is_refused(declarations, body, message):
    found = errors(program(declarations, body))
    assert any(message in e for e in found), found


def test_a_reference_bound_to_a_function_variable_works_during_the_call_and_a_constant_is_refused():
    """REF= to a FUNCTION's own input is accepted since references into a call are checked at run time (issue 25:
    the reference dies with the call, tests/engine/test_dangling_references.py); one to a CONSTANT is ST-REF."""
    text = """FUNCTION F : INT
VAR_INPUT a : INT; END_VAR
VAR r : REFERENCE TO INT; END_VAR
r REF= a;
r := r * 3;
F := a + 1;
END_FUNCTION
PROGRAM Main
VAR y : INT; k : INT; END_VAR
k := k + 1;
y := F(k);
END_PROGRAM
"""
    sim = build(text).simulation()
    for scan in range(1, 4):
        sim.cycle(1)
        assert sim.read("Main.y") == 3 * scan + 1  # a := a * 3 through r, then F := a + 1
    found = errors(
        text.replace("VAR_INPUT a : INT; END_VAR", "VAR CONSTANT a : INT := 2; END_VAR").replace("F(k)", "F()")
    )
    assert len(found) == 1 and "ST-REF: REF= cannot refer to the CONSTANT a" in found[0], found


def test_st_export_writes_reference_to_and_ref_assign_back():
    parsed = parse_source(program(DECLS, BODY, TYPES))
    assert parsed.ok, parsed.diagnostics
    printed = print_source(parsed.ast)
    assert "r : REFERENCE TO INT;" in printed and "r REF= x;" in printed and "IntRef : REFERENCE TO INT;" in printed
    assert parse_source(printed).ast == parsed.ast


def test_reference_is_still_a_name():
    """REFERENCE is a keyword only before TO (OSCAT-style code may call a variable so)."""
    assert scans(program("reference : INT;", "reference := 3;"), 1, "reference") == [[3]]


def test_sizeof_of_types_and_variables():
    text = program(
        "a : ARRAY[1..4] OF DINT; s : STRING[10]; n1 : DINT; n2 : DINT; n3 : DINT; n4 : DINT; lt : LTIME;",
        "n1 := SIZEOF(a); n2 := SIZEOF(LINT); n3 := SIZEOF(lt); n4 := SIZEOF(INT);",
    )
    assert scans(text, 1, "n1", "n2", "n3", "n4") == [[16, 8, 8, 2]]


def test_plcopen_round_trip_keeps_reference_to():
    """TC6 XML has no REFERENCE TO: it travels as a derived type named by its ST text and reads back as one."""
    project, _ = source_to_project(program(DECLS, BODY, TYPES), "refs")
    data = export_plcopen(project)
    assert b'<derived name="REFERENCE TO INT"' in data
    imported = import_plcopen(data)
    assert [d.format() for d in imported.diagnostics if d.severity == "error"] == []
    sim = build_project(imported.project).simulation()
    sim.cycle(1)
    assert [sim.read("Main.x"), sim.read("Main.arr")] == [42 + 10 + 1, [1, 30, 3]]


def test_a_reference_to_input_is_bound_by_the_call_and_stays_bound():
    """CODESYS: ``inst(r := y)`` binds the REFERENCE TO input r to y; later calls without it keep the binding."""
    text = """FUNCTION_BLOCK Inc
VAR_INPUT r : REFERENCE TO INT; END_VAR
r := r + 1;
END_FUNCTION_BLOCK
FUNCTION Twice : INT
VAR_INPUT r : REFERENCE TO INT; END_VAR
r := r * 2;
Twice := r;
END_FUNCTION
PROGRAM Main
VAR x : INT := 5; y : INT := 1; i : Inc; i2 : Inc; t : INT; END_VAR
i.r REF= x;
i();
i2(r := y);
i2();
t := Twice(x);
END_PROGRAM
"""
    x, y = 5, 1
    expected = []
    for _ in range(2):
        x = (x + 1) * 2
        y = y + 2
        expected.append([x, y, x])
    assert scans(text, 2, "x", "y", "t") == expected


@pytest.mark.parametrize(
    "argument, message",
    [
        ("y + 1", "ST-NOT-LVALUE: REFERENCE TO INT input r of Inc needs a variable"),
        ("d", "input r of Inc: a REFERENCE TO INT cannot refer to a DINT"),
    ],
)
def test_a_reference_to_input_needs_a_variable_of_its_type(argument, message):
    text = f"""FUNCTION_BLOCK Inc
VAR_INPUT r : REFERENCE TO INT; END_VAR
r := r + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR y : INT; d : DINT; i : Inc; END_VAR
i(r := {argument});
END_PROGRAM
"""
    found = errors(text)
    assert len(found) == 1 and message in found[0], found
