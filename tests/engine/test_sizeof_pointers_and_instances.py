"""SIZEOF of a pointer and of a function block instance (issue 25 item 1).

A pointer's SIZEOF is the size of an address: 4 bytes on the 32-bit x86/ARM target LadderLab computes as (docs/st.md;
a 64-bit CODESYS target has 8). OSCAT BASIC's ARRAY_MAX/MIN/SPR/SUM rely on it, written for 32-bit targets: called
``ARRAY_MAX(ADR(a), SIZEOF(a))`` ("the function needs to be called: array_max(adr("array"),sizeof("array"))"), they
compute ``stop := (size - SIZEOF(pt)) / SIZEOF(pt)``, the last index of an array of 4-byte REALs. An FB instance's
SIZEOF (CODESYS adds the instance's hidden data) and an interface variable's are refused where they are written.
"""

from __future__ import annotations

import pytest

from .test_references import build

ARRAY_MAX = """FUNCTION ARRAY_MAX : REAL
VAR_INPUT
  pt : POINTER TO ARRAY[0..32000] OF REAL;
  size : UINT;
END_VAR
VAR
  i, stop : UINT;
END_VAR
stop := (size - SIZEOF(pt)) / SIZEOF(pt);
ARRAY_MAX := pt^[0];
FOR i := 1 TO stop DO
  IF pt^[i] > ARRAY_MAX THEN ARRAY_MAX := pt^[i]; END_IF;
END_FOR;
END_FUNCTION
"""


def test_array_max_walks_an_array_of_the_size_its_caller_gives_scan_by_scan():
    result = build(
        ARRAY_MAX + "PROGRAM Main\nVAR\n  a : ARRAY[1..5] OF REAL := [1.5, -2.0, 7.25, 3.0, 0.5];\n"
        "  m : REAL; pointer, pointers : DINT; pp : ARRAY[0..2] OF POINTER TO INT;\nEND_VAR\n"
        "m := ARRAY_MAX(ADR(a), SIZEOF(a));\npointer := SIZEOF(ADR(a));\npointers := SIZEOF(pp);\n"
        "a[2] := a[2] + 10.0;\nEND_PROGRAM\n"
    )
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    for expected in (7.25, 8.0, 18.0):  # a[2]: -2.0, 8.0, 18.0 when the call reads it
        sim.cycle(1)
        assert sim.read("Main.m") == expected
    assert (sim.read("Main.pointer"), sim.read("Main.pointers")) == (4, 12)


@pytest.mark.parametrize(
    ("declarations", "expression", "message"),
    [
        (
            "t : TON;",
            "SIZEOF(t)",
            "SIZEOF of a function block instance is refused: CODESYS counts the instance's hidden data too (its method "
            "table pointer, the alignment of its members), which LadderLab does not lay out",
        ),
        (
            "i : I;",
            "SIZEOF(i)",
            "SIZEOF of an interface variable is refused: LadderLab does not lay out what it holds",
        ),
    ],
)
def test_sizeof_of_an_instance_or_an_interface_is_a_located_error(declarations, expression, message):
    result = build(
        "INTERFACE I\nEND_INTERFACE\n"
        f"PROGRAM Main\nVAR\n  {declarations}\n  n : DINT;\nEND_VAR\nn := {expression};\nEND_PROGRAM\n"
    )
    errors = [(d.code, d.message, d.line) for d in result.diagnostics if d.severity == "error"]
    assert errors == [("IR-UNSUPPORTED", message, 8)]  # the line of `n := ...` in the text


def test_sizeof_of_an_enumeration_is_its_base_types_width():
    """TYP-45 with CODESYS's "Enumeration" page: an enumeration is stored as its base type, INT unless the declaration
    names another; so SIZEOF is 2 for a plain one, 4 for one based on UDINT, 1 for one based on BYTE, and an array of
    three plain ones is 6."""
    result = build(
        "TYPE Color : (Red, Green, Blue); END_TYPE\nTYPE Mode : UDINT (Off := 0, Run := 1); END_TYPE\n"
        "TYPE Small : BYTE (A := 0, B); END_TYPE\nPROGRAM Main\nVAR\n  c : Color; m : Mode; s : Small;\n"
        "  cs : ARRAY[1..3] OF Color; n : ARRAY[0..3] OF DINT;\nEND_VAR\n"
        "n[0] := SIZEOF(c);\nn[1] := SIZEOF(Mode);\nn[2] := SIZEOF(s);\nn[3] := SIZEOF(cs);\nEND_PROGRAM\n"
    )
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert sim.read("Main.n") == [2, 4, 1, 6]
