"""References into a FUNCTION's own variables (issue 25 item 1; IEC 61131-3 ed. 3 6.4.4.10, CODESYS ADR): allowed,
and checked at run time. OSCAT's string functions take ``pt := REF(str)`` of their own input and walk it while the
call runs; a reference that outlives the call (stored in a global or an FB variable) dangles, and reading or writing
through it then is the located fault ``dangling_reference`` - never the stale value. A function that takes no such
reference has no frame at all. Expected values are worked out by hand or by the Python reference in the test.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.paths import NoTarget

from .test_references import build

STRING_FUNCTIONS = """
FUNCTION UPPER_ASCII : STRING[40]
VAR_INPUT str : STRING[40]; END_VAR
VAR pt : REF_TO BYTE; pos, l : INT; END_VAR
pt := REF(UPPER_ASCII);
UPPER_ASCII := str;
l := LEN(str);
FOR pos := 1 TO l DO
  IF pt^ >= 97 AND pt^ <= 122 THEN
    pt^ := pt^ XOR 16#20;
  END_IF;
  pt := pt + 1;
END_FOR;
END_FUNCTION
FUNCTION REVERSED : STRING[40]
VAR_INPUT str : STRING[40]; END_VAR
VAR pi : REF_TO ARRAY[1..255] OF BYTE; po : REF_TO BYTE; i : INT; END_VAR
pi := REF(str);
po := REF(REVERSED);
FOR i := LEN(str) TO 1 BY -1 DO
  po^ := pi^[i];
  po := po + 1;
END_FOR;
po^ := 0;
END_FUNCTION
FUNCTION ALL_DIGITS : BOOL
VAR_INPUT str : STRING[40]; END_VAR
VAR pt : POINTER TO BYTE; pos : INT; END_VAR
pt := ADR(str);
FOR pos := 1 TO LEN(str) DO
  IF pt^ < 48 OR pt^ > 57 THEN
    ALL_DIGITS := FALSE;
    RETURN;
  END_IF;
  pt := pt + 1;
END_FOR;
ALL_DIGITS := LEN(str) > 0;
END_FUNCTION
"""


def _string_program(extra: str = "") -> str:
    return (
        STRING_FUNCTIONS + "PROGRAM Main\nVAR s : STRING[40]; up, rev : STRING[40]; digits : BOOL; END_VAR\n"
        f"up := UPPER_ASCII(s);\nrev := REVERSED(s);\ndigits := ALL_DIGITS(s);\n{extra}END_PROGRAM\n"
    )


def test_string_functions_walking_their_own_input_scan_by_scan():
    sim = build(_string_program()).simulation()
    for text, up, rev, digits in [
        ("abc", "ABC", "cba", False),
        ("Hello, World 42", "HELLO, WORLD 42", "24 dlroW ,olleH", False),
        ("0815", "0815", "5180", True),
        ("", "", "", False),
        ("z", "Z", "z", False),
    ]:
        sim.write("Main.s", text)
        sim.cycle(1)
        assert sim.fault is None
        assert [sim.read(f"Main.{v}") for v in ("up", "rev", "digits")] == [up, rev, digits], text


@settings(max_examples=25, deadline=None)
@given(st.text(alphabet=st.characters(min_codepoint=32, max_codepoint=126), max_size=40))
def test_string_functions_agree_with_python_for_any_ascii_text(text):
    sim = _SIM
    sim.write("Main.s", text)
    sim.cycle(1)
    expected_upper = "".join(c.upper() if "a" <= c <= "z" else c for c in text)
    expected_digits = text != "" and all("0" <= c <= "9" for c in text)
    assert sim.fault is None
    assert [sim.read(f"Main.{v}") for v in ("up", "rev", "digits")] == [expected_upper, text[::-1], expected_digits]


_SIM = build(_string_program()).simulation()

ESCAPING = """
VAR_GLOBAL kept : POINTER TO INT; END_VAR
FUNCTION KEEP : INT
VAR_INPUT x : INT; END_VAR
VAR_EXTERNAL kept : POINTER TO INT; END_VAR
kept := ADR(x);
KEEP := kept^ + 1;
END_FUNCTION
PROGRAM Main
VAR k, y, z : INT; END_VAR
VAR_EXTERNAL kept : POINTER TO INT; END_VAR
k := k + 1;
y := KEEP(k * 10);
IF k >= 3 THEN
  z := kept^;
END_IF;
END_PROGRAM
"""


def test_a_reference_escaping_its_call_is_stored_but_reading_it_later_is_a_located_fault():
    sim = build(ESCAPING).simulation()
    sim.cycle(2)  # the reference is kept in a global, never read after the call: no fault
    assert sim.fault is None and (sim.read("Main.y"), sim.read("GVL.kept")) == (21, "ADR(x)")
    with pytest.raises(NoTarget, match="KEPT\\^: dangling reference: ADR\\(x\\) refers to"):
        sim.read("GVL.kept^")  # online (ON-11): the path names no variable now
    sim.cycle(3)
    fault = sim.fault
    assert fault is not None and (fault.code, fault.scan) == ("dangling_reference", 2)  # the third scan, from 0
    assert (
        fault.message == "dangling reference: ADR(x) refers to a variable of a call of FUNCTION KEEP that has returned"
    )
    assert (fault.pou, fault.origin.line) == ("MAIN", 15)  # z := kept^;
    assert fault.values["KEPT"] == "ADR(x)"  # the pointer the statement reads through
    assert (sim.read("Main.y"), sim.read("Main.z")) == (31, 0)  # the call of that scan ran, the read did not


def test_writing_through_a_dangling_reference_kept_in_a_function_block_is_the_fault_too():
    text = """
FUNCTION_BLOCK Holder
VAR_INPUT p : REF_TO ARRAY[1..3] OF INT; END_VAR
VAR_OUTPUT first : INT; END_VAR
p^[1] := 99;
first := p^[1];
END_FUNCTION_BLOCK
FUNCTION MAKE : REF_TO ARRAY[1..3] OF INT
VAR a : ARRAY[1..3] OF INT := [1, 2, 3]; END_VAR
MAKE := REF(a);
END_FUNCTION
PROGRAM Main
VAR h : Holder; END_VAR
h(p := MAKE());
END_PROGRAM
"""
    sim = build(text).simulation()
    sim.cycle(1)
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference" and (fault.pou, fault.origin.line) == ("HOLDER", 5)
    assert fault.message.endswith("REF(a) refers to a variable of a call of FUNCTION MAKE that has returned")


def test_a_pointer_moved_along_a_function_local_array_dies_with_the_call():
    text = """
VAR_GLOBAL g : POINTER TO INT; END_VAR
FUNCTION SUM3 : INT
VAR a : ARRAY[0..2] OF INT := [4, 5, 6]; p : POINTER TO INT; i : INT; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
p := ADR(a[0]);
FOR i := 0 TO 2 DO
  SUM3 := SUM3 + p^;
  p := p + SIZEOF(a[0]);
END_FOR;
g := ADR(a[0]) + SIZEOF(a[0]);
END_FUNCTION
PROGRAM Main
VAR s, late : INT; END_VAR
VAR_EXTERNAL g : POINTER TO INT; END_VAR
s := SUM3();
late := g^;
END_PROGRAM
"""
    sim = build(text).simulation()
    sim.cycle(1)
    assert sim.read("Main.s") == 15
    fault = sim.fault
    assert fault is not None and fault.code == "dangling_reference" and fault.origin.line == 17
    assert fault.message == (
        "dangling reference: ADR(a[0]) + 2 refers to a variable of a call of FUNCTION SUM3 that has returned"
    )


def test_each_call_has_its_own_frame_and_functions_without_references_have_none():
    """Two calls in one statement: the first call's frame is dead when the second's is alive. The generated code
    of a function that takes no reference to its own variables has no frame (zero cost)."""
    text = STRING_FUNCTIONS + (
        "FUNCTION PLAIN : INT\nVAR_INPUT x : INT; END_VAR\nPLAIN := x * 2;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR a : STRING[40]; n : INT; END_VAR\n"
        "a := CONCAT(UPPER_ASCII('ab'), REVERSED('xy'));\nn := PLAIN(4);\nEND_PROGRAM\n"
    )
    result = build(text)
    sim = result.simulation()
    sim.cycle(1)
    assert (sim.read("Main.a"), sim.read("Main.n"), sim.fault) == ("AByx", 8, None)
    source = result.compiled.source
    plain = source[source.index("def f_PLAIN") :].split("\n\n")[0]
    upper = source[source.index("def f_UPPER_ASCII") :].split("\n\n")[0]
    assert "ll_Frame" not in plain and "ll_fr" not in plain
    assert "ll_fr = ll_Frame('UPPER_ASCII')" in upper and "return ll_fr.end(" in upper
