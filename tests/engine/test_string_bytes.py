"""The bytes of STRING and WSTRING as CODESYS holds them (issue 25, audit items 1 and 2).

CODESYS "Data type: WSTRING": "the data type WSTRING follows UCS-2 encoding ... a character is encoded with exactly
the fixed length 2 bytes ... U+0000 to U+D7FF and U+E000 to U+FFFF. The string is terminated with 0"; Beckhoff's
WSTRING page: "1 WORD per character and 1 WORD extra for the final 0 ... 162 bytes in the case of a standard
WSTRING(80)". CODESYS "Data type: STRING": "In the case of Latin-1 encoding, a STRING variable always requires 1 byte
per character plus an additional byte" (the UTF-8 compile option is not modelled: LadderLab's STRING is Latin-1,
U+0000..U+00FF). On x86/ARM a WORD is little-endian: "AB" is the WORDs 16#0041, 16#0042. A character a STRING or a
WSTRING cannot hold never becomes a byte: a literal holding one is ST-RANGE, WSTRING_TO_STRING of one faults, an
online write of one is refused.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.codegen.views import layout
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

from .test_references import TYPES, simulation
from .test_struct_memory_views import MEMCPY

#: UCS-2 characters: every code point but the surrogates (CODESYS's WSTRING page), NUL aside (the terminator).
UCS2 = st.characters(min_codepoint=1, max_codepoint=0xFFFF, blacklist_categories=("Cs",))


def _errors(declarations: str, body: str, types: str = TYPES) -> list[str]:
    """The errors of a program (its declarations on line 4 and body from line 6 on, with one line of ``types``)."""
    text = f"{types}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n"
    project, diagnostics = source_to_project(text, "bytes")
    found = [d for d in diagnostics if d.severity == "error"]
    if project is not None and not found:
        found = [d for d in build_project(project).diagnostics if d.severity == "error"]
    return [d.format() for d in found]


def test_a_wstring_is_a_little_endian_word_a_character_and_sizeof_counts_them():
    sim = simulation(
        'w : WSTRING[10] := "AB"; e : WSTRING[10] := "€"; dflt : WSTRING; txt : STRING[4];'
        "p : POINTER TO WORD; y, z, euro : WORD; pb : POINTER TO BYTE; b0, b1, e0, e1 : BYTE;"
        "n_w, n_dflt, n_s, n_type : DINT;",
        "p := ADR(w);\ny := p^;\np := p + 2;\nz := p^;\npb := ADR(w);\nb0 := pb^;\npb := pb + 1;\nb1 := pb^;\n"
        "p := ADR(e);\neuro := p^;\npb := ADR(e);\ne0 := pb^;\npb := pb + 1;\ne1 := pb^;\n"
        "n_w := SIZEOF(w);\nn_dflt := SIZEOF(dflt);\nn_s := SIZEOF(txt);\nn_type := SIZEOF(WSTRING);",
    )
    sim.cycle(1)
    assert sim.fault is None
    assert (sim.read("Main.y"), sim.read("Main.z")) == (0x0041, 0x0042)
    assert (sim.read("Main.b0"), sim.read("Main.b1")) == (0x41, 0x00)
    assert (sim.read("Main.euro"), sim.read("Main.e0"), sim.read("Main.e1")) == (0x20AC, 0xAC, 0x20)  # U+20AC
    # WSTRING[10]: 11 WORDs; WSTRING(80): 162 bytes (Beckhoff); STRING[4]: 5 bytes
    assert [sim.read(f"Main.n_{n}") for n in ("w", "dflt", "s", "type")] == [22, 162, 5, 162]


def test_a_word_written_into_a_wstring_is_its_character_and_one_past_the_text_extends_it():
    sim = simulation(
        'w : WSTRING[3] := "AB"; p : POINTER TO WORD;',
        "p := ADR(w);\np^ := 16#00E9;\np := p + 4;\np^ := 16#20AC;",  # 'é' over 'A', '€' over the terminator
    )
    sim.cycle(1)
    assert sim.fault is None and sim.read("Main.w") == "éB€"


@pytest.mark.parametrize(
    ("declarations", "body", "message"),
    [
        (
            'w : WSTRING[3] := "AB"; p : POINTER TO WORD;',
            "p := ADR(w);\np^ := 16#D83D;",
            "writing through a pointer would give the bytes 3dd8420000000000 for a WSTRING[3], which are no "
            "UCS-2 text, which the variable cannot hold",
        ),
        (
            'w : WSTRING[3] := "AB"; p : POINTER TO WORD;',
            "p := ADR(w);\np := p + 6;\np^ := 16#0043;",
            "writing through a pointer would give a WSTRING[3] with characters after its terminator (or none), "
            "which the variable cannot hold",
        ),
        (
            'w : WSTRING[1] := "A"; p : POINTER TO DWORD; y : DWORD;',
            "p := ADR(w);\np := p + 2;\ny := p^;",
            "the pointer ADR(w) + 2 reaches bytes 2..5 of a 4-byte variable: outside it",
        ),
    ],
)
def test_a_write_a_wstring_cannot_hold_or_a_read_past_it_is_a_located_fault(declarations, body, message):
    sim = simulation(declarations, body)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.message) == ("index_out_of_range", message)
    assert fault.origin.line == 6 + body.count("\n")  # TYPES, PROGRAM, VAR, declarations, END_VAR: the last line


def test_a_struct_holding_a_wstring_at_an_even_byte_is_laid_out_and_at_an_odd_one_refused():
    types = (
        "TYPE Even : STRUCT a : WORD; w : WSTRING[1]; END_STRUCT; END_TYPE\n"
        "TYPE Odd : STRUCT a : BYTE; w : WSTRING[1]; END_STRUCT; END_TYPE\n"
        "{attribute 'pack_mode' := '1'}\nTYPE Packed : STRUCT a : BYTE; w : WSTRING[1]; END_STRUCT; END_TYPE\n"
    )
    text = (
        f"{types}PROGRAM Main\nVAR\ne : Even; pk : Packed; pa : POINTER TO ARRAY [0..5] OF BYTE; "
        "bytes : ARRAY [0..5] OF BYTE; n_e, n_p : DINT; pp : POINTER TO ARRAY [0..4] OF BYTE; packed : "
        "ARRAY [0..4] OF BYTE;\nEND_VAR\n"
        'e.a := 16#1234; e.w := "Z"; pk.a := 7; pk.w := "Y";\npa := ADR(e);\nbytes := pa^;\npp := ADR(pk);\n'
        "packed := pp^;\nn_e := SIZEOF(e);\nn_p := SIZEOF(pk);\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "bytes")
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert sim.read("Main.bytes") == [0x34, 0x12, ord("Z"), 0, 0, 0]  # the WORD, then 'Z' and the NUL WORD
    assert sim.read("Main.packed") == [7, ord("Y"), 0, 0, 0]  # pack_mode 1: no padding before the WSTRING
    assert (sim.read("Main.n_e"), sim.read("Main.n_p")) == (6, 5)
    odd = "TYPE Odd : STRUCT a : BYTE; w : WSTRING[1]; END_STRUCT; END_TYPE\n"
    assert _errors("o : Odd; n : DINT;", "n := SIZEOF(o);", odd) == [
        "Main/body:6:6, POU Main: error IR-UNSUPPORTED: SIZEOF is refused for the STRUCT ODD, which holds a WSTRING at an "
        "odd byte or has an odd size (CODESYS documents no alignment for a WSTRING member: 1 or 2 bytes): place "
        "each WSTRING at an even byte and make each STRUCT's size even (a BYTE of padding), or give the STRUCT "
        "{attribute 'pack_mode' := '1'}"
    ]


@settings(max_examples=40, deadline=None)
@given(st.text(UCS2, max_size=6))
def test_any_ucs2_text_reads_back_as_its_utf16_words_byte_by_byte(text):
    sim = _WORDS_SIM
    sim.write("Main.w", text)
    sim.cycle(1)
    expected = [b for ch in text for b in (ord(ch) & 0xFF, ord(ch) >> 8)]
    assert sim.fault is None
    assert sim.read("Main.bytes") == expected + [0] * (14 - len(expected))  # WSTRING[6]: 7 WORDs, NULs after


_WORDS_SIM = simulation(
    "w : WSTRING[6]; pb : POINTER TO BYTE; bytes : ARRAY [0..13] OF BYTE; i : INT;",
    "pb := ADR(w);\nFOR i := 0 TO 13 DO\n  bytes[i] := pb^;\n  pb := pb + 1;\nEND_FOR;",
)


@settings(max_examples=60, deadline=None)
@given(st.text(UCS2, max_size=5), st.booleans())
def test_a_string_layout_encodes_only_what_its_type_holds(text, wide):
    """The layout a pointer sees (engine/codegen/views.py) against the code points themselves: a WSTRING's WORDs,
    a STRING's Latin-1 bytes; a character a STRING cannot hold is a fault, never an exception of Python's."""
    seen = layout(("wstring" if wide else "string", 5))
    if not wide and any(ord(ch) > 0xFF for ch in text):
        with pytest.raises(Exception) as fault:
            seen.encode(text)
        assert type(fault.value).__name__ == "PlcRuntimeError" and fault.value.code == "invalid_argument"
        return
    units = [ord(ch) for ch in text] + [0] * (6 - len(text))
    expected = b"".join(u.to_bytes(2 if wide else 1, "little") for u in units)
    assert seen.encode(text) == expected and seen.decode(expected) == text


LATIN1_ONLY = (
    "'€' (U+20AC) has no byte in CODESYS's STRING, which is Latin-1, one byte a character, U+0000..U+00FF (the code "
    "page of a CoDeSys 2.3 file, cp1251 say, is not modelled)"
)


@settings(max_examples=40, deadline=None)
@given(st.text(st.characters(min_codepoint=32, max_codepoint=0x1F64F, blacklist_characters="$'"), max_size=4))
def test_a_string_literal_is_accepted_exactly_when_a_string_holds_each_character(text):
    """A STRING holds one byte a character; a CoDeSys 2.3 file's code page (cp1251's 'Пуск', tests/cli/
    test_encoding.py) gives characters beyond Latin-1 their byte, so any character a WSTRING could hold (UCS-2) is
    accepted; one above U+FFFF (or a surrogate) no string holds: ST-RANGE where it is written."""
    found = _errors(f"s : STRING := '{text}';", "")
    outside = [ch for ch in text if ord(ch) > 0xFFFF or 0xD800 <= ord(ch) <= 0xDFFF]
    if not outside:
        assert found == []
        return
    assert found == [
        f"Main/declarations:4:15, POU Main: error ST-RANGE: U+{ord(outside[0]):04X} is no character a STRING or "
        "WSTRING holds: CODESYS's WSTRING is UCS-2 (U+0000..U+D7FF and U+E000..U+FFFF), a STRING one byte a character"
    ]


def test_a_string_literal_with_a_character_no_string_holds_is_a_located_error():
    message = (
        "is no character a STRING or WSTRING holds: CODESYS's WSTRING is UCS-2 (U+0000..U+D7FF and U+E000..U+FFFF), "
        "a STRING one byte a character"
    )
    assert _errors("s : STRING; w : WSTRING;", "s := '\U0001f600';\nw := \"$D800\";\ns := STRING#'\U0001f600';") == [
        f"Main/body:6:6, POU Main: error ST-RANGE: U+1F600 {message}",
        f"Main/body:7:6, POU Main: error ST-RANGE: U+D800 {message}",
        f"Main/body:8:13, POU Main: error ST-RANGE: U+1F600 {message}",
    ]


def test_the_byte_of_a_string_character_beyond_latin1_is_a_located_fault():
    """Audit item 2: ``s := '€'`` then a BYTE pointer over s: CODESYS's STRING is Latin-1, so no byte is known for
    '€' (the project's code page is not modelled): the read is the located fault ``invalid_argument``."""
    sim = simulation("s : STRING := 'a€'; p : POINTER TO BYTE; b : BYTE;", "p := ADR(s);\nb := p^;")
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.origin.line) == ("invalid_argument", 7)
    assert fault.message == f"the bytes of STRING[80]: {LATIN1_ONLY}"


def test_wstring_to_string_keeps_latin1_and_faults_on_any_other_character():
    sim = simulation(
        'w : WSTRING := "aü"; e : WSTRING := "a€"; s, t, u : STRING; pb : POINTER TO BYTE; b : BYTE;',
        "s := WSTRING_TO_STRING(w);\npb := ADR(s);\npb := pb + 1;\nb := pb^;\nt := TO_STRING(e);",
    )
    sim.cycle(1)
    assert (sim.read("Main.s"), sim.read("Main.b")) == ("aü", 0xFC)  # 'ü' is Latin-1 16#FC
    fault = sim.fault
    assert fault is not None and (fault.code, fault.origin.line) == ("invalid_argument", 10)
    assert fault.message == f"WSTRING_TO_STRING: {LATIN1_ONLY}"
    assert sim.read("Main.t") == ""


def test_an_online_write_of_a_character_no_string_holds_is_refused():
    sim = simulation("s : STRING[4]; w : WSTRING[4];", "")
    with pytest.raises(ValueError, match=r"MAIN\.S: U\+1F600 is no character a STRING or WSTRING holds"):
        sim.write("Main.s", "\U0001f600")
    with pytest.raises(ValueError, match=r"MAIN\.W: U\+1F600 is no character a STRING or WSTRING holds"):
        sim.write("Main.w", "\U0001f600")
    sim.write("Main.w", "€")
    sim.write("Main.s", "Пуск")  # a course's cp1251 text, as its literals
    sim.cycle(1)
    assert (sim.read("Main.w"), sim.read("Main.s")) == ("€", "Пуск")


def test_a_pointer_to_string_over_a_shorter_string_reads_and_writes_up_to_its_terminator():
    """Audit item 3: a POINTER TO STRING (STRING[80]) over a STRING[4] sees the variable's 5 bytes, not 81: moved by
    2 it reads the text from there to the terminator, as CODESYS reads a STRING ('abcd' from byte 2 is 'cd'); a
    write stores the text and its terminator, zeros after them."""
    sim = simulation(
        "s : STRING[4] := 'abcd'; p : POINTER TO STRING; whole, tail : STRING; t : STRING[6] := 'abcdef';"
        "q : POINTER TO STRING;",
        "p := ADR(s);\nwhole := p^;\np := p + 2;\ntail := p^;\nq := ADR(t);\nq := q + 1;\nq^ := 'xy';",
    )
    sim.cycle(1)
    assert sim.fault is None
    assert [sim.read(f"Main.{n}") for n in ("whole", "tail", "t", "p", "q")] == [
        "abcd",
        "cd",
        "axy",
        "ADR(s) + 2",
        "ADR(t) + 1",
    ]


@pytest.mark.parametrize(
    ("declarations", "body", "message"),
    [
        (
            "t : STRING[6] := 'ab'; q : POINTER TO STRING;",
            "q := ADR(t);\nq := q + 2;\nq^ := 'xyzuvw';",  # 6 characters and a NUL from byte 2: bytes 2..8
            "the pointer ADR(t) + 2 reaches bytes 2..8 of a 7-byte variable: outside it",
        ),
        (
            "buf : ARRAY [0..3] OF BYTE := [65, 66, 67, 68]; p : POINTER TO STRING; y : STRING;",
            "p := ADR(buf);\ny := p^;",  # no NUL in the buffer: the text runs on past its 4 bytes
            "the pointer ADR(buf) reaches bytes 0..4 of a 4-byte variable: outside it",
        ),
    ],
)
def test_a_string_seen_past_the_end_of_its_variable_is_a_fault_naming_the_variables_size(declarations, body, message):
    sim = simulation(declarations, body)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.message) == ("index_out_of_range", message)
    assert fault.origin.line == 6 + body.count("\n")


#: CODESYS "Data type: STRING": "If a size is not defined, then CODESYS allocates 80 characters by default", so a
#: ``POINTER TO STRING`` sees a STRING[80] (and a POINTER TO WSTRING a WSTRING[80]: Beckhoff's "WSTRING(80)").
DEFAULT_LENGTH = 80


def _longer(pointer: str, kind: str, held: int) -> str:
    return (
        f"the pointer {pointer} sees a {kind}[80], and the text there ({held} characters) runs on past its 80 "
        f"characters: what CODESYS reads then is not documented; declare the pointer POINTER TO {kind}(n) with n at "
        "least the text's length"
    )


@pytest.mark.parametrize(
    ("declarations", "body", "message"),
    [
        (
            "s : STRING(255); p : POINTER TO STRING; n : INT := -1;",
            f"s := '{'x' * 103}';\np := ADR(s);\nn := LEN(p^);",
            _longer("ADR(s)", "STRING", 103),
        ),
        (
            "s : STRING(255); r : REF_TO STRING; n : INT := -1; t : STRING;",
            f"s := '{'x' * 90}';\nr := REF(s);\nt := r^;",
            _longer("REF(s)", "STRING", 90),
        ),
        (
            "s : STRING(255); p : POINTER TO STRING; n : INT := -1;",
            f"s := '{'x' * 85}';\np := ADR(s) + 4;\nn := LEN(p^);",  # 81 characters from byte 4 on
            _longer("ADR(s) + 4", "STRING", 81),
        ),
        (
            "w : WSTRING(255); p : POINTER TO WSTRING; n : INT := -1;",
            f'w := "{"y" * 100}";\np := ADR(w);\nn := LEN(p^);',
            _longer("ADR(w)", "WSTRING", 100),
        ),
    ],
)
def test_a_pointer_to_string_over_a_longer_text_is_a_located_fault_never_its_first_80_characters(
    declarations, body, message
):
    """Brief polish25 item 2: ``p^`` of a POINTER TO STRING is a STRING[80]; over a STRING(255) holding more, what
    CODESYS gives depends on memory past the 81 bytes the type covers, which it does not document, so the read is
    the located fault naming the pointer and the text's length, and nothing is stored (n keeps -1)."""
    sim = simulation(declarations, body)
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.message) == ("index_out_of_range", message)
    assert (fault.pou, fault.origin.line) == ("MAIN", 6 + body.count("\n"))
    assert sim.read("Main.n") == -1


@settings(max_examples=25, deadline=None)
@given(length=st.integers(0, 255))
def test_len_through_a_pointer_to_string_is_the_texts_length_up_to_80_and_a_fault_beyond(length):
    """Against the declared lengths: a POINTER TO STRING reads a text of at most 80 characters whole (LEN its length,
    a copy the same text), a longer one faults; a POINTER TO STRING(255) reads any text of the STRING(255)."""
    sim = simulation(
        "s : STRING(255); p : POINTER TO STRING; q : POINTER TO STRING(255); n, m : INT := -1; t : STRING;",
        f"s := '{'ab' * (length // 2)}{'c' * (length % 2)}';\nq := ADR(s);\nm := LEN(q^);\np := ADR(s);\n"
        "t := p^;\nn := LEN(p^);",
    )
    sim.cycle(1)
    assert sim.read("Main.m") == length
    if length <= DEFAULT_LENGTH:
        assert sim.fault is None and (sim.read("Main.n"), len(sim.read("Main.t"))) == (length, length)
    else:
        assert sim.fault is not None and sim.fault.message == _longer("ADR(s)", "STRING", length)
        assert (sim.fault.origin.line, sim.read("Main.n"), sim.read("Main.t")) == (10, -1, "")


def test_an_oscat_style_memcpy_copies_a_wstring_word_by_word():
    """``MEMCPY(ADR(dst), ADR(src), SIZEOF(src))`` (OSCAT's byte copy) over a WSTRING[3] copies its 8 bytes: 'A'
    16#0041, '€' 16#20AC, then the terminator; into another WSTRING[3] they are the same text."""
    text = (
        f"{MEMCPY}PROGRAM Main\nVAR\n"
        'w : WSTRING[3] := "A€"; w2 : WSTRING[3]; raw : ARRAY [0..7] OF BYTE; ok1, ok2 : BOOL;\nEND_VAR\n'
        "ok1 := MEMCPY(ADR(w2), ADR(w), SIZEOF(w));\nok2 := MEMCPY(ADR(raw), ADR(w), SIZEOF(w));\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "bytes")
    result = build_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(1)
    assert sim.fault is None
    assert sim.read("Main.w2") == "A€"
    assert sim.read("Main.raw") == [0x41, 0x00, 0xAC, 0x20, 0x00, 0x00, 0x00, 0x00]
