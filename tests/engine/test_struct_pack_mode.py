"""CODESYS's ``{attribute 'pack_mode' := 'N'}`` above a STRUCT's TYPE, and STRUCTs with 8-byte members (issue 25
item 1, docs/st.md). CODESYS's page "Attribute: pack_mode" (content.helpme-codesys.com, CODESYS Development System,
_cds_pragma_attribute_pack_mode): 0 and 1 pack without gaps; with 2, 4 or 8 every member lies at a multiple of its
size capped by N (a 4-byte one at a multiple of 2 with pack_mode 2); STRINGs at any byte; in arrays of the STRUCT
bytes follow each one so that the next is aligned, so the size is a multiple of the largest capped alignment.
Without the attribute a STRUCT has the target's default pack mode, 4 on some targets (Beckhoff's CX7000 page: "works
with the DWordAlignment (pack mode 4) if you do not use the attribute") and 8 on others: LadderLab accepts an 8-byte
member there only where both give the same bytes. SIZEOF is TYP-45, pointer arithmetic in bytes TYP-43. Every layout
is worked out by hand in the comments.
"""

from __future__ import annotations

import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from .test_references import build
from .test_struct_memory_views import MEMCPY, assert_byte_writes_read_back, simulation

PACKED = "{{attribute 'pack_mode' := '{mode}'}}\nTYPE P : STRUCT a : BYTE; b : DINT; c : BYTE; END_STRUCT; END_TYPE\n"


@pytest.mark.parametrize(
    ("mode", "expected"),
    [
        # 0 and 1: a at 0, b at 1..4, c at 5: 6 bytes, no padding
        ("0", [0xAA, 0x01, 0x02, 0x03, 0x04, 0xCC]),
        ("1", [0xAA, 0x01, 0x02, 0x03, 0x04, 0xCC]),
        # 2: b at 2..5 (a multiple of min(4, 2)), c at 6, the size 7 rounded up to a multiple of 2: 8
        ("2", [0xAA, 0, 0x01, 0x02, 0x03, 0x04, 0xCC, 0]),
        # 4 (and 8: no member is wider than 4): b at 4..7, c at 8, the size 9 rounded up to a multiple of 4: 12
        ("4", [0xAA, 0, 0, 0, 0x01, 0x02, 0x03, 0x04, 0xCC, 0, 0, 0]),
        ("8", [0xAA, 0, 0, 0, 0x01, 0x02, 0x03, 0x04, 0xCC, 0, 0, 0]),
    ],
)
def test_a_packed_struct_sizeof_bytes_and_an_oscat_style_copy_scan_by_scan(mode, expected):
    """Each scan adds 1 to src.b, reads src's bytes through a POINTER TO ARRAY OF BYTE and copies SIZEOF(src) bytes
    into dst (OSCAT's ``ADR(x), SIZEOF(x)``): b's low byte (16#01 at first) is one more each scan."""
    size = len(expected)
    low = expected.index(0x01)
    sim = simulation(
        PACKED.format(mode=mode) + MEMCPY,
        f"src : P := (a := 16#AA, b := 16#04030200, c := 16#CC); dst : P; n : DINT; ok : BOOL;"
        f"pa : POINTER TO ARRAY [0..{size - 1}] OF BYTE; bytes : ARRAY [0..{size - 1}] OF BYTE;",
        "src.b := src.b + 1;\nn := SIZEOF(src);\npa := ADR(src);\nbytes := pa^;\n"
        "ok := MEMCPY(ADR(dst), ADR(src), SIZEOF(src));",
    )
    for scan in range(1, 4):
        sim.cycle(1)
        assert sim.fault is None and sim.read("Main.n") == size
        assert sim.read("Main.bytes") == expected[:low] + [scan] + expected[low + 1 :]
        assert sim.read("Main.dst") == {"A": 0xAA, "B": 0x04030200 + scan, "C": 0xCC}


@pytest.mark.parametrize(("mode", "size"), [("0", 8), ("2", 10), ("4", 12), ("8", 12)])
def test_sizeof_of_the_documented_example(mode, size):
    """Beckhoff's "Attribute 'pack_mode'" page (str_Test: BYTE, DINT, BYTE, INT): 1 + 4 + 1 + 2 = 8 bytes with 0;
    10 with 2 (a padding byte after each BYTE); 12 with 4 (three after each BYTE); 8 changes nothing."""
    sim = simulation(
        f"{{attribute 'pack_mode' := '{mode}'}}\n"
        "TYPE str_Test : STRUCT byTest1 : BYTE; iTest : DINT; byTest2 : BYTE; nValue : INT; END_STRUCT\nEND_TYPE\n",
        "s : str_Test; n : DINT;",
        "n := SIZEOF(s);",
    )
    sim.cycle(1)
    assert sim.read("Main.n") == size


@pytest.mark.parametrize(("mode", "counter", "reached"), [("1", 1, 4), ("2", 2, 5)])
def test_members_lie_where_the_codesys_example_says(mode, counter, reached):
    """CODESYS's example 1 (myStruct: Enable BOOL, Counter INT, MaxSize BOOL, MaxSizeReached BOOL) at 16#0100:
    Counter at 16#0101 and MaxSizeReached at 16#0104 with pack_mode 1; at 16#0102 and 16#0105 with 2. The pragma
    stands inside the TYPE block here, above the name. A byte written at those offsets lands in those members."""
    sim = simulation(
        f"TYPE\n{{attribute 'pack_mode' := '{mode}'}}\n"
        "myStruct : STRUCT Enable : BOOL; Counter : INT; MaxSize : BOOL; MaxSizeReached : BOOL; END_STRUCT;\nEND_TYPE\n",
        "s : myStruct; pb : POINTER TO BYTE;",
        f"pb := ADR(s) + {counter};\npb^ := 16#34;\npb := ADR(s) + {reached};\npb^ := 1;",
    )
    sim.cycle(1)
    assert sim.fault is None
    assert sim.read("Main.s") == {"ENABLE": False, "COUNTER": 0x34, "MAXSIZE": False, "MAXSIZEREACHED": True}


def test_8_byte_members_at_multiples_of_8_need_no_pack_mode_scan_by_scan():
    """a DINT at 0..3, b DINT at 4..7, x LREAL at 8..15, n LINT at 16..23: every 8-byte member at a multiple of 8
    and the size 24 a multiple of 8, so both default pack modes (4 and 8) give these bytes. x doubles each scan
    (LREAL 2.0 = 16#4000000000000000, 4.0 = 16#4010..., 8.0 = 16#4020...), read as an LWORD at byte 8; n counts down
    from 16#1_0000_0000, read as two DWORDs at 16 (low) and 20 (high)."""
    sim = simulation(
        "TYPE W : STRUCT a, b : DINT; x : LREAL; n : LINT; END_STRUCT; END_TYPE\n",
        "w : W := (x := 1.0, n := 16#100000000); size : DINT; pl : POINTER TO LWORD; pd : POINTER TO DWORD;"
        "xbits : LWORD; low, high : DWORD;",
        "w.x := w.x * 2.0;\nw.n := w.n - 1;\nsize := SIZEOF(w);\npl := ADR(w) + 8;\nxbits := pl^;\n"
        "pd := ADR(w) + 16;\nlow := pd^;\npd := pd + 4;\nhigh := pd^;",
    )
    for scan, bits in enumerate((0x4000000000000000, 0x4010000000000000, 0x4020000000000000), start=1):
        sim.cycle(1)
        assert sim.fault is None and sim.read("Main.size") == 24
        assert (sim.read("Main.xbits"), sim.read("Main.low"), sim.read("Main.high")) == (bits, 2**32 - scan, 0)


@pytest.mark.parametrize(("mode", "offset", "size"), [("1", 1, 9), ("2", 2, 10), ("4", 4, 12), ("8", 8, 16)])
def test_an_lreal_after_a_byte_with_a_pack_mode_scan_by_scan(mode, offset, size):
    """{BYTE; LREAL} is refused without a pack_mode (x at 4 or 8 by target); with one x lies at the next multiple of
    min(8, N) after the BYTE and the size is a multiple of it: 9, 10, 12, 16. A write of 16#3FF0000000000000 (1.0)
    as an LWORD at that offset sets x; then x is halved each scan and copied bytewise into dst."""
    sim = simulation(
        f"{{attribute 'pack_mode' := '{mode}'}}\nTYPE L : STRUCT a : BYTE; x : LREAL; END_STRUCT; END_TYPE\n" + MEMCPY,
        "s : L := (a := 7); dst : L; n : DINT; pl : POINTER TO LWORD; ok, once : BOOL;",
        f"IF NOT once THEN\n  pl := ADR(s) + {offset};\n  pl^ := 16#3FF0000000000000;\n  once := TRUE;\nEND_IF;\n"
        "s.x := s.x / 2.0;\nn := SIZEOF(s);\nok := MEMCPY(ADR(dst), ADR(s), SIZEOF(s));",
    )
    for scan in range(1, 4):
        sim.cycle(1)
        assert sim.fault is None and sim.read("Main.n") == size
        assert sim.read("Main.dst") == {"A": 7, "X": 0.5**scan}


INNER = "TYPE Inner : STRUCT x : LREAL; y, z : DINT; END_STRUCT; END_TYPE\n"


@pytest.mark.parametrize(
    ("types", "name", "what"),
    [
        # Inner: x LREAL at 0, y at 8, z at 12: 16 bytes either way, but aligned to 4 or 8; so i, after a BYTE,
        # lies at 4 or 8
        (
            INNER + "TYPE Outer : STRUCT a : BYTE; i : Inner; END_STRUCT; END_TYPE\n",
            "OUTER",
            "whose member I lies at byte 4 or 8",
        ),
        # x at 0, a at 8: 9 bytes rounded up to a multiple of 4 or of 8
        ("TYPE Outer : STRUCT x : LREAL; a : BYTE; END_STRUCT; END_TYPE\n", "OUTER", "12 or 16 bytes"),
        # the same in an array of them: the element is what to fix
        (
            "TYPE E : STRUCT x : LREAL; a : BYTE; END_STRUCT; END_TYPE\nTYPE Outer : ARRAY [1..2] OF E; END_TYPE\n",
            "E",
            "12 or 16 bytes",
        ),
        # pack_mode 8 packs Outer, not Inner: Inner keeps the target's alignment, so i lies at 4 or 8 because of it
        (
            INNER + "{attribute 'pack_mode' := '8'}\nTYPE Outer : STRUCT a : BYTE; i : Inner; END_STRUCT; END_TYPE\n",
            "INNER",
            "aligned to 4 or 8 bytes",
        ),
    ],
)
def test_a_layout_that_depends_on_the_target_is_refused_saying_how_to_fix_it(types, name, what):
    """Where the default pack modes 4 and 8 give different bytes, SIZEOF names the STRUCT to give a pack_mode and
    what moves."""
    result = build(f"{types}PROGRAM Main\nVAR\ns : Outer; n : DINT;\nEND_VAR\nn := SIZEOF(s);\nEND_PROGRAM\n")
    errors = [(d.code, d.message, d.pou) for d in result.diagnostics if d.severity == "error"]
    assert errors == [
        (
            "IR-UNSUPPORTED",
            f"SIZEOF is refused for the STRUCT {name}, {what} depending on the target (without a pack_mode CODESYS "
            f"aligns 8-byte members to 4 or 8 bytes by target): give {name} the target's pack_mode ({{attribute "
            "'pack_mode' := '4'} or '8' above its TYPE), or order its members so that each 8-byte one lies at a "
            "multiple of 8 and so does the size",
            "Main",
        )
    ]


_MEMBERS = {"BYTE": "B", "INT": "h", "DWORD": "I", "DINT": "i", "LINT": "q", "ULINT": "Q", "LWORD": "Q"}


def _packed_format(types: list[str], pack: int) -> str:
    """The ``struct`` format of a STRUCT of these members with ``{attribute 'pack_mode' := 'pack'}``, padding
    written out as ``x``, from CODESYS's table: each member at a multiple of min(its size, pack), the whole a
    multiple of the largest of those."""
    fmt, offset, largest = "<", 0, 1
    for name in types:
        align = min(struct.calcsize("<" + _MEMBERS[name]), pack)
        fmt += "x" * (-offset % align) + _MEMBERS[name]
        offset += -offset % align + struct.calcsize("<" + _MEMBERS[name])
        largest = max(largest, align)
    return fmt + "x" * (-offset % largest)


@settings(max_examples=25, deadline=None)
@given(
    st.lists(st.sampled_from(sorted(_MEMBERS)), min_size=1, max_size=5),
    st.sampled_from([1, 2, 4, 8]),
    st.lists(st.tuples(st.integers(0, 47), st.integers(0, 255)), min_size=1, max_size=6),
)
def test_random_byte_writes_into_a_packed_struct_read_back_as_the_reference_layout_says(types, pack, writes):
    """Bytes written one by one through a POINTER TO BYTE into a packed STRUCT of random 1- to 8-byte members: the
    members, SIZEOF (TYP-45) and every byte read back are what Python's ``struct`` gives for the same bytes with
    the padding written out; a nonzero byte into padding is the fault instead."""
    pragma = f"{{attribute 'pack_mode' := '{pack}'}}\n"
    assert_byte_writes_read_back(types, _packed_format(types, pack), writes, pragma)
