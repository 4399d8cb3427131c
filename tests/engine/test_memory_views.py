"""Memory seen through a pointer of another type (issue 25 item 2, CODESYS ``POINTER TO``): a POINTER TO DWORD over
a REAL reads and writes its IEEE-754 bits, a POINTER TO BYTE walks the bytes of a DWORD, an array or a STRING,
little-endian as CODESYS on x86/ARM, with CODESYS's layout (BOOL 1 byte, STRING[n] n + 1 bytes). Writes change the
target exactly; leaving the variable, or a write the variable cannot hold (a character after a STRING's terminator,
a BOOL byte of 2), is a located fault; a STRUCT's bytes: test_struct_memory_views.py. Expected values come from
IEEE-754 (REAL 1.0 = 16#3F800000, -2.5 = 16#C0200000, LREAL 1.0 = 16#3FF0000000000000) and from the byte order.
"""

from __future__ import annotations

import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .test_references import simulation


def test_a_pointer_to_dword_reads_and_writes_the_ieee_bits_of_a_real():
    sim = simulation(
        "x : REAL := 1.0; y : REAL := -2.5; px : POINTER TO DWORD; xbits, ybits : DWORD; big : LREAL := 1.0;"
        "pl : POINTER TO LWORD; bl : LWORD;",
        "px := ADR(x);\nxbits := px^;\npx := ADR(y);\nybits := px^;\npx^ := 16#40490FDB;\npl := ADR(big);\nbl := pl^;",
    )
    sim.cycle(1)
    assert (sim.read("Main.xbits"), sim.read("Main.ybits")) == (0x3F800000, 0xC0200000)
    assert sim.read("Main.y") == struct.unpack("<f", struct.pack("<I", 0x40490FDB))[0]  # float32 pi, 3.1415927
    assert sim.read("Main.bl") == 0x3FF0000000000000


def test_a_byte_pointer_walks_a_dword_little_endian_and_writes_one_byte():
    sim = simulation(
        "d : DWORD := 16#11223344; pb : POINTER TO BYTE; b0, b1, b2, b3 : BYTE;",
        "pb := ADR(d);\nb0 := pb^;\npb := pb + 1;\nb1 := pb^;\npb := pb + 1;\nb2 := pb^;\npb := pb + 1;\n"
        "b3 := pb^;\npb := ADR(d);\npb^ := 16#FF;",
    )
    sim.cycle(1)
    assert [sim.read(f"Main.b{i}") for i in range(4)] == [0x44, 0x33, 0x22, 0x11]
    assert sim.read("Main.d") == 0x112233FF
    assert sim.read("Main.pb") == "ADR(d)"


def test_a_byte_pointer_walks_an_int_array_and_a_word_view_of_a_byte_array():
    sim = simulation(
        "a : ARRAY [1..2] OF INT := [-2, 258]; pb : POINTER TO BYTE; bytes : ARRAY [0..3] OF BYTE; i : INT;"
        "raw : ARRAY [0..3] OF BYTE := [16#34, 16#12, 16#78, 16#56]; pw : POINTER TO WORD; w0, w1 : WORD;",
        "pb := ADR(a);\nFOR i := 0 TO 3 DO\n  bytes[i] := pb^;\n  pb := pb + 1;\nEND_FOR;\n"
        "pw := ADR(raw[0]);\nw0 := pw^;\npw := pw + 2;\nw1 := pw^;\npw^ := 16#BEEF;",
    )
    sim.cycle(1)
    assert sim.read("Main.bytes") == [0xFE, 0xFF, 0x02, 0x01]  # -2 = 16#FFFE, 258 = 16#0102
    assert (sim.read("Main.w0"), sim.read("Main.w1")) == (0x1234, 0x5678)
    assert sim.read("Main.raw") == [0x34, 0x12, 0xEF, 0xBE]


def test_a_string_seen_as_bytes_and_as_an_array_of_bytes():
    sim = simulation(
        "s : STRING[5] := 'AB'; pb : POINTER TO BYTE; pa : POINTER TO ARRAY [1..6] OF BYTE; c1, c3, c6 : BYTE;",
        "pa := ADR(s);\nc1 := pa^[1];\nc3 := pa^[3];\nc6 := pa^[6];\npa^[3] := 67;\n"  # 'C' after 'AB'
        "pb := ADR(s);\npb := pb + 3;\npb^ := 68;",  # 'D' where the terminator was
    )
    sim.cycle(1)
    assert (sim.read("Main.c1"), sim.read("Main.c3"), sim.read("Main.c6")) == (65, 0, 0)  # STRING[5]: 6 bytes
    assert sim.read("Main.s") == "ABCD"


@pytest.mark.parametrize(
    ("declarations", "body", "message", "line"),
    [
        (
            "s : STRING[3] := 'AB'; pb : POINTER TO BYTE;",
            "pb := ADR(s);\npb := pb + 3;\npb^ := 67;",
            "writing through a pointer would give a STRING[3] with characters after its terminator (or none), "
            "which the variable cannot hold",
            3,
        ),
        (
            "s : STRING[3] := 'AB'; pb : POINTER TO BYTE; y : BYTE;",
            "pb := ADR(s);\npb := pb + 4;\ny := pb^;",
            "the pointer ADR(s) + 4 reaches bytes 4..4 of a 4-byte variable: outside it",
            3,
        ),
        (
            "d : DWORD; pb : POINTER TO BYTE;",
            "pb := ADR(d);\npb := pb + 5;",
            "the pointer PB moved by 5 bytes reaches byte 5 of a 4-byte variable: outside it",
            2,
        ),
        (
            "w : WORD; pd : POINTER TO DWORD; y : DWORD;",
            "pd := ADR(w);\ny := pd^;",
            "the pointer ADR(w) reaches bytes 0..3 of a 2-byte variable: outside it",
            2,
        ),
        (
            "f : BOOL; pb : POINTER TO BYTE;",
            "pb := ADR(f);\npb^ := 2;",
            "writing through a pointer would give the bytes 02 for a bool, which the variable cannot hold",
            2,
        ),
    ],
)
def test_leaving_the_variable_or_writing_what_it_cannot_hold_is_a_located_fault(declarations, body, message, line):
    sim = simulation(declarations, body)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.message) == ("index_out_of_range", message)
    assert (fault.pou, fault.origin.line) == ("MAIN", 5 + line)  # TYPES, PROGRAM, VAR, declarations, END_VAR


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 0xFFFFFFFF), st.integers(0, 3), st.integers(0, 255))
def test_any_byte_written_into_a_dword_changes_exactly_that_byte(value, index, byte):
    sim = _BYTE_SIM
    sim.write("Main.d", value)
    sim.write("Main.i", index)
    sim.write("Main.b", byte)
    sim.cycle(1)
    expected = bytearray(struct.pack("<I", value))
    old = expected[index]
    expected[index] = byte
    assert sim.fault is None
    assert (sim.read("Main.old"), sim.read("Main.d")) == (old, struct.unpack("<I", expected)[0])


_BYTE_SIM = simulation(
    "d : DWORD; i : INT; b, old : BYTE; pb : POINTER TO BYTE;", "pb := ADR(d);\npb := pb + i;\nold := pb^;\npb^ := b;"
)


def test_an_online_path_through_a_byte_pointer_reads_and_writes_the_byte_it_points_to():
    """ON-11: ``Main.pb^`` names the byte pb sees (the second of the DWORD, little-endian 16#33)."""
    sim = simulation("d : DWORD := 16#11223344; pb : POINTER TO BYTE;", "pb := ADR(d);\npb := pb + 1;")
    sim.cycle(1)
    assert (sim.read("Main.pb"), sim.read("Main.pb^")) == ("ADR(d) + 1", 0x33)
    sim.write("Main.pb^", 0xAA)
    sim.cycle(1)
    assert sim.read("Main.d") == 0x1122AA44


def test_a_whole_array_read_through_a_view_is_a_copy():
    sim = simulation(
        "s : STRING[3] := 'AB'; pa : POINTER TO ARRAY [0..3] OF BYTE; x : ARRAY [0..3] OF BYTE;",
        "pa := ADR(s);\nx := pa^;\npa^[0] := 67;\nx[1] := 9;",
    )
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.x"), sim.read("Main.s")) == (None, [65, 9, 0, 0], "CB")  # 'A' 'B' NUL NUL


def test_a_whole_array_written_through_a_view_writes_its_bytes():
    """``pa^ := x`` over a DWORD: bytes 1, 2, 3, 4 little-endian are 16#04030201 (was an internal error)."""
    sim = simulation(
        "d : DWORD; x : ARRAY [0..3] OF BYTE := [1, 2, 3, 4]; pa : POINTER TO ARRAY [0..3] OF BYTE;",
        "pa := ADR(d);\npa^ := x;",
    )
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.d")) == (None, 0x04030201)


def test_a_pointer_declared_with_another_type_s_address_sees_its_bytes():
    """``pb : POINTER TO BYTE := ADR(s)`` in the declaration sees the STRING's bytes as the same assignment in the body
    does (TYP-46): 'a' is 97 (it read the STRING itself into the BYTE before)."""
    sim = simulation("s : STRING := 'abc'; pb : POINTER TO BYTE := ADR(s); b : BYTE;", "b := pb^;")
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.b"), sim.read("Main.pb")) == (None, 97, "ADR(s)")


def test_a_byte_view_of_an_array_element_shows_and_compares_as_that_element():
    """ADR(a[2]) seen as bytes is ADR(a[2]) (not ``+ 2``, its offset in the array), equals ADR(a[2]) and moves from
    there: one byte back is the high byte of a[1] (16#0102), ``ADR(a[2]) - 1``."""
    sim = simulation(
        "a : ARRAY [1..3] OF INT := [16#0102, 16#0304, 16#0506]; pb : POINTER TO BYTE; q : POINTER TO BYTE;"
        "same : BOOL; b : BYTE;",
        "pb := ADR(a[2]);\nsame := pb = ADR(a[2]);\nq := pb - 1;\nb := q^;",
    )
    sim.cycle(1)
    assert (sim.read("Main.pb"), sim.read("Main.same")) == ("ADR(a[2])", True)
    assert (sim.read("Main.q"), sim.read("Main.b")) == ("ADR(a[2]) - 1", 0x01)


def test_a_byte_other_than_0_or_1_read_as_a_bool_is_a_located_fault():
    """A BOOL is 0 or 1; CODESYS shows any other byte as INVALID (Beckhoff's CODESYS 2.3 manual, "BOOL"), so b = 1
    reads TRUE, 0 FALSE and 2 is a fault at the read (it read TRUE before)."""
    sim = simulation("b : BYTE := 1; pb : POINTER TO BOOL; x : BOOL;", "pb := ADR(b);\nx := pb^;")
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.x")) == (None, True)
    sim.write("Main.b", 0)
    sim.cycle(1)
    assert (sim.fault, sim.read("Main.x")) == (None, False)
    sim.write("Main.b", 2)
    sim.cycle(1)
    assert (sim.fault.code, sim.fault.message) == (
        "index_out_of_range",
        "reading through a pointer gives the byte 02 for a BOOL, which is neither 0 nor 1",
    )
    assert (sim.fault.origin.line, sim.read("Main.x")) == (7, False)  # TYPES, PROGRAM, VAR, decls, END_VAR, pb :=
