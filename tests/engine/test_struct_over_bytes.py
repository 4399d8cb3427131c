"""Other memory seen as a STRUCT (issue 25, item 1: CODESYS's protocol-buffer pattern, ``pr : POINTER TO R :=
ADR(buffer)``): a member read or written through the pointer is its bytes where the STRUCT's layout puts them
(little-endian, CODESYS's natural alignment: docs/st.md), a whole STRUCT written through it writes every byte, its
padding 0, and a STRUCT read through it, or passed by value, is a copy. Leaving the buffer, or a byte a member cannot
hold, is a located fault. Pointers: seed 000 TYP-42 (ADR), TYP-43 (byte arithmetic), TYP-44 (``^``), TYP-45 (SIZEOF),
TYP-47 (the run-time check covers the target object). Expected values are computed by hand from the bytes.
"""

from __future__ import annotations

import pytest

from .ed3_support import build

# R: a BYTE at 0, padding 1..3, b DINT at 4..7, c WORD at 8..9, padding 10..11: 12 bytes.
# H: id WORD at 0..1, data ARRAY [0..1] OF BYTE at 2..3, flag BOOL at 4, padding 5: 6 bytes (a multiple of 2).
TYPES = """TYPE R : STRUCT a : BYTE; b : DINT; c : WORD; END_STRUCT; END_TYPE
TYPE H : STRUCT id : WORD; data : ARRAY [0..1] OF BYTE; flag : BOOL; END_STRUCT; END_TYPE
FUNCTION Bump : DINT
VAR_IN_OUT x : DINT; END_VAR
x := x + 1;
Bump := x;
END_FUNCTION
FUNCTION Cleared : BYTE
VAR_INPUT r : R; END_VAR
r.a := 0;
Cleared := r.a;
END_FUNCTION
"""

# Two records of R back to back: the first a = 16#11, b = 16#11223344, c = 16#AABB; the second a = 16#22, b = 1, c = 2.
BUFFER = (
    "raw : ARRAY [0..23] OF BYTE := [16#11, 0, 0, 0, 16#44, 16#33, 16#22, 16#11, 16#BB, 16#AA, 0, 0, "
    "16#22, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0];"
)


def simulation(declarations: str, body: str, variant: str = "fast"):
    result = build(f"{TYPES}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n", variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


@pytest.mark.parametrize("variant", ("fast", "monitor", "debug"))
def test_records_in_a_byte_buffer_read_and_written_member_by_member(variant):
    """The first record's members, then c written (bytes 8..9 become DD CC), the record copied out, the pointer moved
    by SIZEOF(R) to the second record, and the copy written there whole: bytes 12..23 are the first record's, its
    padding 0."""
    sim = simulation(
        f"{BUFFER} pr : POINTER TO R; a, a2 : BYTE; b : DINT; c : WORD; rec : R;",
        "pr := ADR(raw);\na := pr^.a;\nb := pr^.b;\nc := pr^.c;\npr^.c := 16#CCDD;\nrec := pr^;\n"
        "pr := pr + SIZEOF(rec);\na2 := pr^.a;\npr^ := rec;",
        variant,
    )
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert [sim.read(f"Main.{v}") for v in ("a", "b", "c", "a2")] == [0x11, 0x11223344, 0xAABB, 0x22]
    assert sim.read("Main.rec") == {"A": 0x11, "B": 0x11223344, "C": 0xCCDD}
    first = [0x11, 0, 0, 0, 0x44, 0x33, 0x22, 0x11, 0xDD, 0xCC, 0, 0]
    assert sim.read("Main.raw") == first + first
    assert sim.read("Main.pr") == "ADR(raw) + 12"


def test_nested_members_in_outs_and_copies_reach_the_bytes():
    """H over the buffer: data[1] is byte 3, flag byte 4 (the low byte of R's b: 16#44 becomes 1), id bytes 0..1;
    Bump(pr^.b) adds 1 to the DINT at 4..7 (16#11223301) through a VAR_IN_OUT; Cleared(pr^) clears its own copy of
    the record, never the buffer."""
    sim = simulation(
        f"{BUFFER} ph : POINTER TO H; pr : POINTER TO R; d1 : BYTE; n : DINT; zero : BYTE; w : WORD;",
        "ph := ADR(raw);\nd1 := ph^.data[1];\nph^.flag := TRUE;\nph^.id := 16#00FF;\nw := ph^.id;\n"
        "pr := ADR(raw);\nn := Bump(pr^.b);\nzero := Cleared(pr^);",
    )
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert (sim.read("Main.d1"), sim.read("Main.w"), sim.read("Main.zero")) == (0, 0xFF, 0)
    assert sim.read("Main.n") == 0x11223302
    assert sim.read("Main.raw")[:12] == [0xFF, 0, 0, 0, 0x02, 0x33, 0x22, 0x11, 0xBB, 0xAA, 0, 0]


def test_a_record_past_the_buffer_or_a_byte_a_member_cannot_hold_is_a_located_fault():
    """A 12-byte R over an 8-byte buffer reaches past it; a BOOL member over the byte 2 is no BOOL."""
    sim = simulation("raw : ARRAY [0..7] OF BYTE; pr : POINTER TO R; a : BYTE;", "pr := ADR(raw);\na := pr^.a;")
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message, sim.fault.origin.line) == (
        "index_out_of_range",
        "the pointer ADR(raw) reaches bytes 0..11 of a 8-byte variable: outside it",
        18,  # TYPES (12 lines), PROGRAM, VAR, declarations, END_VAR, pr :=, a :=
    )
    sim = simulation(
        "raw : ARRAY [0..5] OF BYTE := [0, 0, 0, 0, 2, 0]; ph : POINTER TO H; f : BOOL;",
        "ph := ADR(raw);\nf := ph^.flag;",
    )
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "index_out_of_range",
        "reading through a pointer gives the byte 02 for a BOOL, which is neither 0 nor 1",
    )


def test_an_online_path_through_the_pointer_reads_and_writes_a_member():
    """``Main.pr^.c`` (ON-11) is the WORD at bytes 8..9; writing 16#0102 sets byte 8 to 2 and byte 9 to 1."""
    sim = simulation(f"{BUFFER} pr : POINTER TO R;", "pr := ADR(raw);")
    sim.cycle(1)
    assert sim.read("Main.pr^.c") == 0xAABB
    sim.write("Main.pr^.c", 0x0102)
    sim.cycle(1)
    assert sim.read("Main.raw")[8:10] == [2, 1]


def test_an_online_write_a_member_seen_over_other_memory_cannot_hold_is_refused():
    """``Main.pq^.n`` is the INT n of Q seen over an INT (0..100): 50 is written, 500 refused when given."""
    result = build(
        "TYPE Q : STRUCT n : INT; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR\n"
        "v : INT (0..100); pq : POINTER TO Q;\nEND_VAR\npq := ADR(v);\nEND_PROGRAM\n"
    )
    sim = result.simulation()
    sim.cycle(1)
    with pytest.raises(ValueError) as refused:
        sim.write("Main.pq^.n", 500)
    assert str(refused.value) == "MAIN.PQ^.N: 500 is outside the subrange 0..100: written through ADR(v)"
    sim.write("Main.pq^.n", 50)
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.v")) == (None, 50)
