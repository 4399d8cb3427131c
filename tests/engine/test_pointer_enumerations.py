"""Enumerations reached by a pointer or reference of another type hold only their members' values (issue 25).

CODESYS stores an enumeration as its base type, INT unless the declaration names another (CODESYS online help,
"Enumeration": ``TYPE COLOR : (white := 16#FFFFFF00, ...) DWORD``), and lets ``ADR()`` of it into any POINTER.
LadderLab sees it through that base: read through a ``POINTER TO INT`` (a ``REF_TO INT``, a byte view, a STRUCT
over its bytes ...) it is its member's integer value, little-endian byte by byte as CODESYS on x86/ARM; a write
that would leave it holding a value that is none of its members' is the located fault ``subrange_violation`` naming
the value, the enumeration and what it went through, and the variable keeps its value. The other way round, a
``POINTER TO E`` over an INT faults reading a value no member has. Pointers: seed 000 TYP-42 (ADR), TYP-43 (byte
arithmetic), TYP-44 (``^``), TYP-46 (initialiser), TYP-45 (SIZEOF), TYP-47 (the run-time check covers the target).
Expected values are worked out by hand from the program text and CODESYS's layout (docs/st.md).
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.support import line_of

from .ed3_support import build, errors, program

TYPES = """TYPE Mode : (off, slow, fast); END_TYPE
TYPE Colour : (white := 16#FFFFFF00, black) DWORD; END_TYPE
TYPE Rec : STRUCT a : BYTE; m : Mode; END_STRUCT; END_TYPE
TYPE Wide : STRUCT a : BYTE; c : Colour; END_STRUCT; END_TYPE
FUNCTION SetInt : INT
VAR_IN_OUT x : INT; END_VAR
VAR_INPUT n : INT; END_VAR
x := n;
SetInt := 0;
END_FUNCTION
FUNCTION SetMode : INT
VAR_IN_OUT x : Mode; END_VAR
x := Mode.fast;
SetMode := 0;
END_FUNCTION
FUNCTION_BLOCK Owner
VAR_OUTPUT q : POINTER TO Mode; END_VAR
VAR v : Mode; END_VAR
q := ADR(v);
END_FUNCTION_BLOCK"""


# (declarations, body writing k (the scan number) into a Mode through the path, the variable, what the fault names,
# the statement faulting, its POU)
WRITES = [
    ("m : Mode; p : POINTER TO INT;", "p := ADR(m);\np^ := k;", "m", "ADR(m)", "p^ := k;", "MAIN"),
    ("m : Mode; p : REF_TO INT;", "p := REF(m);\np^ := k;", "m", "REF(m)", "p^ := k;", "MAIN"),
    ("m : Mode; p : POINTER TO BYTE;", "p := ADR(m);\np^ := INT_TO_BYTE(k);", "m", "ADR(m)", "p^ := INT_TO_BYTE(k);", "MAIN"),
    ("m : Mode; p : POINTER TO INT := ADR(m);", "p^ := k;", "m", "ADR(m)", "p^ := k;", "MAIN"),
    ("a : ARRAY[1..3] OF Mode; p : POINTER TO INT;", "p := ADR(a[2]);\np^ := k;", "a[2]", "ADR(a[2])", "p^ := k;", "MAIN"),
    ("a : ARRAY[1..3] OF Mode; p : POINTER TO INT;", "p := ADR(a[1]);\np[2] := k;", "a[3]", "ADR(a[1]) + 4", "p[2] := k;", "MAIN"),
    ("s : Rec; p : POINTER TO INT;", "p := ADR(s.m);\np^ := k;", "s.m", "ADR(s.m)", "p^ := k;", "MAIN"),
    ("s : Rec; p : POINTER TO BYTE;", "p := ADR(s) + 2;\np^ := INT_TO_BYTE(k);", "s.m", "ADR(s) + 2", "p^ := INT_TO_BYTE(k);", "MAIN"),
    ("m : Mode; p : POINTER TO INT; n : INT;", "p := ADR(m);\nn := SetInt(p^, k);", "m", "ADR(m)", "x := n;", "SETINT"),
    ("o : Owner; p : POINTER TO INT;", "o(q => p);\np^ := k;", "o.v", "ADR(v)", "p^ := k;", "MAIN"),
]  # fmt: skip


@pytest.mark.parametrize("declarations, body, path, through, statement, pou", WRITES)
def test_a_write_through_another_type_keeps_an_enumeration_to_its_members_scan_by_scan(
    declarations, body, path, through, statement, pou
):
    """k counts scans: 1 (slow) and 2 (fast) are written, 3 is no Mode and faults naming what it was written through,
    at the writing statement; the variable keeps fast (2). Each row was refused at compile time before (a STRUCT
    holding an enumeration too)."""
    text = program(f"k : INT; {declarations}", f"k := k + 1;\n{body}", TYPES)
    sim = build(text).simulation()
    for scan in (1, 2):
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        assert sim.read(f"Main.{path}") == scan
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        f"3 is none of the values of the enumeration MODE: written through {through}",
    )
    assert (sim.fault.pou, sim.fault.origin.line) == (pou, line_of(text, statement))
    assert sim.read(f"Main.{path}") == 2


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_the_high_byte_written_into_an_enumeration_faults_in_every_variant(variant):
    """m is fast (2); its high byte written 0 leaves it 2, written 1 makes 1 * 256 + 2 = 258, no Mode (TYP-43,
    little-endian)."""
    body = "k := k + 1;\np := ADR(m) + 1;\np^ := INT_TO_BYTE(k - 1);"
    text = program("k : INT; m : Mode := Mode.fast; p : POINTER TO BYTE;", body, TYPES)
    sim = build(text, variant).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.m")) == (None, 2)
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "258 is none of the values of the enumeration MODE: written through ADR(m) + 1",
    )
    assert sim.fault.origin.line == line_of(text, "p^ := INT_TO_BYTE(k - 1);") and sim.read("Main.m") == 2


def test_read_through_another_type_an_enumeration_is_its_base_integer():
    """Mode.fast is 2 as an INT; Colour.white is the DWORD 16#FFFFFF00, so its bytes are 00 FF FF FF (little-endian)
    and a WORD from its second byte is 16#FFFF; black follows white, 16#FFFFFF01. SIZEOF: INT 2, DWORD 4 (CODESYS's
    Enumeration page: the base type)."""
    declarations = (
        "m : Mode := Mode.fast; c : Colour; pi : POINTER TO INT; pb : POINTER TO BYTE; pw : POINTER TO WORD; "
        "pd : POINTER TO DWORD; i : INT; b0 : BYTE; b1 : BYTE; w : WORD; d : DWORD; sm : INT; sc : INT;"
    )
    body = """pi := ADR(m);
i := pi^;
pb := ADR(c);
b0 := pb^;
pb := pb + 1;
b1 := pb^;
pw := ADR(c) + 1;
w := pw^;
c := Colour.black;
pd := ADR(c);
d := pd^;
sm := SIZEOF(m);
sc := SIZEOF(c);"""
    sim = build(program(declarations, body, TYPES)).simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    seen = [sim.read(f"Main.{name}") for name in ("i", "b0", "b1", "w", "d", "sm", "sc")]
    assert seen == [2, 0x00, 0xFF, 0xFFFF, 0xFFFFFF01, 2, 4]


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_a_pointer_to_an_enumeration_faults_reading_an_integer_that_is_no_member(variant):
    """x is an INT: 2 read through a POINTER TO Mode is fast; 3 is no Mode, a fault at the reading statement; n
    keeps fast."""
    body = "x := x + 1;\np := ADR(x);\nn := p^;"
    text = program("x : INT := 1; p : POINTER TO Mode; n : Mode;", body, TYPES)
    sim = build(text, variant).simulation()
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.n")) == (None, 2)
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "3 is none of the values of the enumeration MODE: read through ADR(x)",
    )
    assert sim.fault.origin.line == line_of(text, "n := p^;") and sim.read("Main.n") == 2


def test_a_struct_holding_an_enumeration_has_codesys_s_layout_and_size():
    """Rec (a BYTE, a Mode): m at byte 2 (an INT aligns to 2), 4 bytes; Wide (a BYTE, a DWORD Colour): c at 4, 8
    bytes. Over a byte buffer (CODESYS's protocol-buffer pattern) pr^.m reads bytes 2..3: 01 00 is slow (1), and
    writing fast puts 02 there; bytes 07 00 are no Mode, a fault reading them."""
    declarations = (
        "buf : ARRAY[0..3] OF USINT; pr : POINTER TO Rec; m : Mode; sr : INT; sw : INT; r : Rec; w : Wide; "
        "pb : POINTER TO BYTE; b : BYTE;"
    )
    body = """sr := SIZEOF(r);
sw := SIZEOF(w);
w.c := Colour.black;
pb := ADR(w) + 4;
b := pb^;
buf[2] := buf[2] + 1;
pr := ADR(buf);
m := pr^.m;
pr^.m := Mode.fast;
buf[2] := buf[2] + 4;"""
    text = program(declarations, body, TYPES)
    sim = build(text).simulation()
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert [sim.read(f"Main.{name}") for name in ("sr", "sw", "b", "m")] == [4, 8, 0x01, 1]
    assert sim.read("Main.buf") == [0, 0, 6, 0]  # fast (2) written into byte 2, then 4 added
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "subrange_violation",
        "7 is none of the values of the enumeration MODE: read through ADR(buf) + 2",
    )
    assert sim.fault.origin.line == line_of(text, "m := pr^.m;")


def test_a_pointer_reference_or_in_out_of_the_enumeration_itself_works():
    """POINTER TO Mode, REF_TO Mode and a VAR_IN_OUT of Mode reach the variable itself: fast is written through
    each. A VAR_IN_OUT INT given a Mode stays a type error (IEC: an in-out argument has the parameter's type)."""
    body = """p := ADR(m1);
p^ := Mode.slow;
r := REF(m2);
r^ := Mode.fast;
n := SetMode(m3);"""
    declarations = "m1 : Mode; m2 : Mode; m3 : Mode; p : POINTER TO Mode; r : REF_TO Mode; n : INT;"
    sim = build(program(declarations, body, TYPES)).simulation()
    sim.cycle(1)
    assert sim.fault is None
    assert [sim.read(f"Main.{name}") for name in ("m1", "m2", "m3")] == [1, 2, 2]
    text = program("m : Mode; n : INT;", "n := SetInt(m, 1);", TYPES)
    assert errors(text) == [
        f"Main/body:{line_of(text, 'n := SetInt(m, 1);')}:13, POU Main: error ST-TYPE-MISMATCH: in-out parameter x of "
        "SetInt needs an INT, got Mode"
    ]


def test_a_user_write_or_read_through_a_pointer_of_another_type_is_refused_when_no_member_has_it():
    """Online (ON-11): ``Main.p^`` := 2 is written into m at the next scan; 5 is refused when given, in the fault's
    words, and nothing is written. ``Main.q^``, a POINTER TO Mode over the INT x = 5, is no Mode (reading it is
    refused); x takes a Mode value written through it."""
    declarations = "m : Mode; x : INT := 5; p : POINTER TO INT; q : POINTER TO Mode;"
    sim = build(program(declarations, "p := ADR(m);\nq := ADR(x);", TYPES)).simulation()
    sim.cycle(1)
    sim.write("Main.p^", 2)
    with pytest.raises(ValueError) as refused:
        sim.write("Main.p^", 5)
    assert str(refused.value) == "MAIN.P^: 5 is none of the values of the enumeration MODE: written through ADR(m)"
    with pytest.raises(ValueError) as unread:
        sim.read("Main.q^")
    assert str(unread.value) == "MAIN.Q^: 5 is none of the values of the enumeration MODE: read through ADR(x)"
    sim.write("Main.q^", 1)
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.m"), sim.read("Main.x")) == (None, 2, 1)


@settings(max_examples=40, deadline=None)
@given(
    values=st.lists(st.integers(-32768, 32767), min_size=1, max_size=5, unique=True),
    start=st.integers(0, 4),
    written=st.one_of(
        st.tuples(st.just("INT"), st.just(0), st.integers(-32768, 32767)),
        st.tuples(st.just("BYTE"), st.integers(0, 1), st.integers(0, 255)),
    ),
)
def test_any_integer_or_byte_written_into_an_enumeration_is_a_member_or_a_fault(values, start, written):
    """E's members have the given INT values and e starts as one of them. An INT written through a POINTER TO INT, or
    one byte (the low or the high one) through a POINTER TO BYTE, is taken when the INT it makes (little-endian, two's
    complement) is a member's value; otherwise it faults naming that INT, and e keeps its start value."""
    members = ", ".join(f"e{i} := {v}" for i, v in enumerate(values))
    first = values[start % len(values)]
    kind, offset, value = written
    if kind == "INT":
        whole = value
    else:
        data = bytearray(first.to_bytes(2, "little", signed=True))
        data[offset] = value
        whole = int.from_bytes(data, "little", signed=True)
    body = f"p := ADR(e) + {offset};\np^ := {value};"
    declarations = f"e : E := E#e{start % len(values)}; p : POINTER TO {kind};"
    sim = build(program(declarations, body, f"TYPE E : ({members}); END_TYPE")).simulation()
    sim.cycle(1)
    if whole in values:
        assert (sim.fault, sim.read("Main.e")) == (None, whole)
    else:
        through = f"ADR(e) + {offset}" if offset else "ADR(e)"
        assert (sim.fault.code, sim.fault.message) == (
            "subrange_violation",
            f"{whole} is none of the values of the enumeration E: written through {through}",
        )
        assert sim.read("Main.e") == first
