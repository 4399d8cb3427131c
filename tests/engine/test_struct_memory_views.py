"""A STRUCT's memory seen through a pointer of another type (issue 25 item 1, CODESYS ``POINTER TO BYTE`` over a
structure, docs/st.md). CODESYS lays a STRUCT out naturally, the same on every x86/ARM target while no member is
8 bytes wide: members in declaration order, each at a multiple of its alignment (its size for 1-, 2- and 4-byte
numbers, 1 for BOOL and STRING[n], an array's element's, a nested STRUCT's largest member's), the size a multiple of
the largest alignment. Padding bytes hold nothing: they read 0 and writing anything else there is a located fault,
like a character after a STRING's terminator. SIZEOF (TYP-45) counts the padding. Little-endian as CODESYS on
x86/ARM. Every layout below is worked out by hand in the comments.
"""

from __future__ import annotations

import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .test_references import build

# R: a BYTE at 0, padding 1..3, b DINT at 4..7 (a multiple of 4), c WORD at 8..9, padding 10..11: 12 bytes (a
# multiple of R's alignment, 4).
R = "TYPE R : STRUCT a : BYTE; b : DINT; c : WORD; END_STRUCT; END_TYPE\n"


def simulation(types: str, declarations: str, body: str):
    result = build(f"{types}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n")
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def test_members_read_and_written_through_byte_word_and_dword_pointers_scan_by_scan():
    """Each scan: b's bytes 4..7 read as a DWORD and incremented, c (bytes 8..9) read as a WORD and its low byte
    set through a BYTE pointer at byte 8, a's byte 0 incremented through the BYTE pointer; the padding bytes 1 and
    10 read 0."""
    sim = simulation(
        R,
        "r : R := (a := 16#10, b := 16#01020304, c := 16#A0B0); pb : POINTER TO BYTE; pw : POINTER TO WORD;"
        "pd : POINTER TO DWORD; n : DINT; bits : DWORD; cword : WORD; pad1, pad10 : BYTE;",
        "n := SIZEOF(r);\npd := ADR(r);\npd := pd + 4;\nbits := pd^;\npd^ := DINT_TO_DWORD(DWORD_TO_DINT(bits) + 1);\n"
        "pw := ADR(r);\npw := pw + 8;\ncword := pw^;\npb := ADR(r);\npb := pb + 8;\n"
        "pb^ := USINT_TO_BYTE(BYTE_TO_USINT(pb^) + 1);\npb := ADR(r);\npb^ := USINT_TO_BYTE(BYTE_TO_USINT(pb^) + 1);\n"
        "pb := pb + 1;\npad1 := pb^;\npb := pb + 9;\npad10 := pb^;",
    )
    for scan in range(3):
        sim.cycle(1)
        assert sim.fault is None
        assert (sim.read("Main.n"), sim.read("Main.pad1"), sim.read("Main.pad10")) == (12, 0, 0)
        assert sim.read("Main.bits") == 0x01020304 + scan  # b before this scan's increment
        assert sim.read("Main.cword") == 0xA0B0 + scan  # c before this scan's low byte increment
        assert sim.read("Main.r") == {"A": 0x11 + scan, "B": 0x01020305 + scan, "C": 0xA0B1 + scan}


def test_a_nested_struct_and_a_string_member_seen_as_an_array_of_bytes():
    """Inner: x BYTE at 0, padding 1, y WORD at 2..3: 4 bytes, alignment 2. Outer: f BOOL at 0, padding 1, i Inner
    at 2..5 (its padding at 3), s STRING[2] at 6..8 (alignment 1; 'A', NUL, NUL), padding 9..11, d DWORD at 12..15:
    16 bytes, alignment 4. A write through the array view changes the member whose byte it is. ``ADR(o.i) + 2``
    and ``ADR(o) + 12`` as a POINTER TO BYTE are bytes 2 of i (y's low byte) and 12 of o (d's low byte)."""
    sim = simulation(
        "TYPE Inner : STRUCT x : BYTE; y : WORD; END_STRUCT; END_TYPE\n"
        "TYPE Outer : STRUCT f : BOOL; i : Inner; s : STRING[2]; d : DWORD; END_STRUCT; END_TYPE\n",
        "o : Outer := (f := TRUE, i := (x := 16#AB, y := 16#1234), s := 'A', d := 16#DEADBEEF);"
        "pa : POINTER TO ARRAY [0..15] OF BYTE; bytes : ARRAY [0..15] OF BYTE; n, m : DINT; pb : POINTER TO BYTE;"
        "ylow, dlow : BYTE;",
        "n := SIZEOF(o);\nm := SIZEOF(o.i);\npa := ADR(o);\nbytes := pa^;\npa^[7] := 66;\npa^[4] := 16#78;\n"
        "pb := ADR(o.i) + 2;\nylow := pb^;\npb := ADR(o) + 12;\ndlow := pb^;",
    )
    sim.cycle(1)
    assert sim.fault is None and (sim.read("Main.n"), sim.read("Main.m")) == (16, 4)
    assert (sim.read("Main.ylow"), sim.read("Main.dlow"), sim.read("Main.pb")) == (0x78, 0xEF, "ADR(o) + 12")
    assert sim.read("Main.bytes") == [1, 0, 0xAB, 0, 0x34, 0x12, 65, 0, 0, 0, 0, 0, 0xEF, 0xBE, 0xAD, 0xDE]
    assert sim.read("Main.o") == {"F": True, "I": {"X": 0xAB, "Y": 0x1278}, "S": "AB", "D": 0xDEADBEEF}


def test_an_array_of_structs_sizeof_and_pointer_arithmetic_by_the_struct_size():
    """TYP-43/TYP-45: ARRAY [1..3] OF R: 3 * 12 = 36 bytes; element k starts at 12 * (k - 1). A POINTER TO R moved
    by SIZEOF(R)
    reaches the next element (its b summed); a POINTER TO DINT at byte 12 + 4 = 16 is arr[2].b; the BYTE at 24 + 8
    is arr[3].c's low byte; byte 35 is arr[3]'s last padding byte and reads 0."""
    sim = simulation(
        R,
        "arr : ARRAY [1..3] OF R; pr : POINTER TO R; pd : POINTER TO DINT; pb : POINTER TO BYTE; i : INT;"
        "sum : DINT; size, whole : DINT; last : BYTE;",
        "size := SIZEOF(arr[1]);\nwhole := SIZEOF(arr);\npd := ADR(arr);\npd := pd + 16;\npd^ := pd^ + 5;\n"
        "pb := ADR(arr[1]);\npb := pb + 32;\npb^ := USINT_TO_BYTE(BYTE_TO_USINT(pb^) + 1);\npb := pb + 3;\nlast := pb^;\n"
        "sum := 0;\npr := ADR(arr[1]);\nFOR i := 1 TO 3 DO\n  sum := sum + pr^.b;\n  pr := pr + SIZEOF(R);\nEND_FOR;",
    )
    for scan in range(1, 4):
        sim.cycle(1)
        assert sim.fault is None and (sim.read("Main.size"), sim.read("Main.whole"), sim.read("Main.last")) == (
            12,
            36,
            0,
        )
        assert sim.read("Main.sum") == 5 * scan  # arr[2].b after this scan's increment
        assert [e["C"] for e in sim.read("Main.arr")] == [0, 0, scan]
    assert sim.read("Main.pr") == "ADR(arr[1]) + 36"  # one past the end


MEMCPY = """FUNCTION MEMCPY : BOOL
VAR_INPUT dst, src : POINTER TO ARRAY [0..32000] OF BYTE; size : UINT; END_VAR
VAR k : UINT; END_VAR
FOR k := 0 TO size - 1 DO
  dst^[k] := src^[k];
END_FOR;
MEMCPY := TRUE;
END_FUNCTION
"""


def test_an_oscat_style_byte_copy_between_structures_scan_by_scan():
    """OSCAT's buffer functions take ``ADR(x), SIZEOF(x)``: copying SIZEOF(R) = 12 bytes from one R to another
    copies every member (the padding bytes read 0 and write 0); each scan first adds 16#01010101 to src.b."""
    sim = simulation(
        R + MEMCPY,
        "src : R := (a := 200, b := -2, c := 16#8001); dst : R; ok : BOOL;",
        "src.b := src.b + 16#01010101;\nok := MEMCPY(ADR(dst), ADR(src), SIZEOF(src));",
    )
    for scan in range(1, 4):
        sim.cycle(1)
        assert sim.fault is None
        assert sim.read("Main.dst") == {"A": 200, "B": -2 + 0x01010101 * scan, "C": 0x8001}


def test_a_write_into_padding_is_a_located_fault_in_the_scan_it_happens():
    """Writing 0 into R's padding byte 2 changes nothing; writing 7 there (on the third scan) is the fault: R's
    padding cannot hold it. The DWORD at 0..3 covers a and padding 1..3, so a nonzero upper byte faults too."""
    sim = simulation(
        R,
        "r : R; pb : POINTER TO BYTE; n : INT;",
        "n := n + 1;\npb := ADR(r);\npb := pb + 2;\npb^ := 0;\nIF n = 3 THEN\n  pb^ := 7;\nEND_IF;",
    )
    sim.cycle(2)
    assert sim.fault is None
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.scan, fault.pou, fault.origin.line) == (
        "index_out_of_range",
        2,  # the third scan, from 0
        "MAIN",
        5 + 6,  # TYPE, PROGRAM, VAR, declarations, END_VAR, then the body's sixth line
    )
    assert fault.message == (
        "writing through a pointer would give the byte 07 in padding byte 2 of the STRUCT R, which the variable "
        "cannot hold"
    )
    dword = simulation(R, "r : R; pd : POINTER TO DWORD;", "pd := ADR(r);\npd^ := 16#00000100;")
    dword.cycle(1)
    assert dword.fault is not None and dword.fault.message == (
        "writing through a pointer would give the byte 01 in padding byte 1 of the STRUCT R, which the variable "
        "cannot hold"
    )


# L without a pack_mode: a BYTE at 0, then x LREAL at 4 on a target whose default pack mode is 4, at 8 where it is 8.
L_MOVES = (
    "the STRUCT L, whose member X lies at byte 4 or 8 depending on the target (without a pack_mode CODESYS aligns "
    "8-byte members to 4 or 8 bytes by target): give L the target's pack_mode ({attribute 'pack_mode' := '4'} or '8' "
    "above its TYPE), or order its members so that each 8-byte one lies at a multiple of 8 and so does the size"
)


@pytest.mark.parametrize(
    ("types", "declarations", "body", "message"),
    [
        (
            "TYPE L : STRUCT a : BYTE; x : LREAL; END_STRUCT; END_TYPE\n",
            "s : L; pb : POINTER TO BYTE;",
            "pb := ADR(s);",
            "a REF_TO BYTE cannot see a L as bytes: " + L_MOVES,
        ),
        (
            "TYPE L : STRUCT a : BYTE; x : LREAL; END_STRUCT; END_TYPE\n",
            "s : L; n : DINT;",
            "n := SIZEOF(s);",
            "SIZEOF is refused for " + L_MOVES,
        ),
        (
            "TYPE L : STRUCT a : BYTE; x : LREAL; END_STRUCT; END_TYPE\n",
            "s : ARRAY [1..2] OF L; p : POINTER TO L;",
            "p := ADR(s[1]);\np := p + 16;",
            "moving or ordering pointers needs the size of what they point to: SIZEOF is refused for " + L_MOVES,
        ),
        (
            "TYPE T : STRUCT a : BYTE; t : TIME; END_STRUCT; END_TYPE\nTYPE O : STRUCT i : T; END_STRUCT; END_TYPE\n",
            "s : O; pb : POINTER TO BYTE;",
            "pb := ADR(s);",
            "a REF_TO BYTE cannot see an O as bytes: the STRUCT O, whose member I is the STRUCT T, whose member T is a "
            "TIME (its bytes in CODESYS are not the value LadderLab keeps)",
        ),
    ],
)
def test_what_stays_refused_is_a_located_error(types, declarations, body, message):
    """A STRUCT whose layout CODESYS chooses by target (an 8-byte member at 4 or 8, no pack_mode), or with a member
    that has no byte layout (a TIME), is neither seen as bytes, nor sized, nor walked by pointer arithmetic."""
    result = build(f"{types}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n")
    errors = [(d.code, d.message, d.pou) for d in result.diagnostics if d.severity == "error"]
    assert errors == [("IR-UNSUPPORTED", message, "Main")]


_MEMBERS = {"BYTE": "B", "SINT": "b", "WORD": "H", "INT": "h", "DWORD": "I", "DINT": "i"}


def _reference_format(types: list[str]) -> str:
    """The ``struct`` format of a STRUCT of these members with CODESYS's natural alignment, padding written out
    as ``x``: each member at a multiple of its size, the whole a multiple of the largest member's size."""
    fmt, offset = "<", 0
    for name in types:
        size = struct.calcsize("<" + _MEMBERS[name])
        fmt += "x" * (-offset % size) + _MEMBERS[name]
        offset += -offset % size + size
    largest = max(struct.calcsize("<" + _MEMBERS[name]) for name in types)
    return fmt + "x" * (-offset % largest)


def _padding(fmt: str) -> set[int]:
    """The offsets of the ``x`` (padding) bytes of a ``struct`` format."""
    found, offset = set(), 0
    for code in fmt[1:]:
        if code == "x":
            found.add(offset)
        offset += struct.calcsize("<" + code)
    return found


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.sampled_from(sorted(_MEMBERS)), min_size=1, max_size=5),
    st.lists(st.tuples(st.integers(0, 23), st.integers(0, 255)), min_size=1, max_size=6),
)
def test_random_byte_writes_read_back_as_the_reference_layout_says(types, writes):
    """Bytes written one by one through a POINTER TO BYTE into a STRUCT of random 1-, 2- and 4-byte members: the
    members, SIZEOF (TYP-45) and every byte read back are what Python's ``struct`` gives for the same bytes with
    the padding written out (``_reference_format``); a nonzero byte into padding is the fault instead."""
    assert_byte_writes_read_back(types, _reference_format(types), writes)


def assert_byte_writes_read_back(types: list[str], fmt: str, writes: list[tuple[int, int]], pragma: str = "") -> None:
    """Writes each (offset, byte) through a POINTER TO BYTE into a STRUCT X of ``types`` (declared after
    ``pragma``), then reads SIZEOF and every byte back: they and the members must be what Python's ``struct``
    gives for ``fmt`` (the reference layout, padding written out as ``x``); a nonzero byte into padding faults."""
    size = struct.calcsize(fmt)
    writes = [(offset % size, byte) for offset, byte in writes]
    members = "".join(f"m{i} : {name}; " for i, name in enumerate(types))
    body = "".join(f"pb := ADR(r);\npb := pb + {offset};\npb^ := {byte};\n" for offset, byte in writes)
    sim = simulation(
        f"{pragma}TYPE X : STRUCT {members}END_STRUCT; END_TYPE\n",
        f"r : X; pb : POINTER TO BYTE; n : DINT; out : ARRAY [0..{size - 1}] OF BYTE; i : INT;",
        f"n := SIZEOF(r);\n{body}pb := ADR(r);\nFOR i := 0 TO {size - 1} DO\n  out[i] := pb^;\n  pb := pb + 1;\nEND_FOR;",
    )
    padding = _padding(fmt)
    sim.cycle(1)
    if any(offset in padding and byte for offset, byte in writes):
        assert sim.fault is not None and sim.fault.code == "index_out_of_range"
        return
    memory = bytearray(size)
    for offset, byte in writes:
        memory[offset] = byte
    assert sim.fault is None and sim.read("Main.n") == size
    assert sim.read("Main.out") == list(memory)
    assert sim.read("Main.r") == {f"M{i}": v for i, v in enumerate(struct.unpack(fmt, memory))}
