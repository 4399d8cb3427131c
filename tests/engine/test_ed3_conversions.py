"""IEC 61131-3 ed. 3 Table 22 conversions beyond <SRC>_TO_<DST> (issue 25, item 3): BCD in both directions with a
located fault on an invalid BCD, the typed and overloaded TRUNC forms, the overloaded TO_<type>, and WSTRING in conversions and
string functions. BCD reference values are written here from the decimal digits (``int(str(n), 16)``)."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.stdlib import make_function
from ladderlab.iec.elementary import ELEMENTARY

from .ed3_support import build, errors, program, scans


def bcd(n: int) -> int:
    """n in BCD: its decimal digits read as hexadecimal digits (1234 -> 16#1234)."""
    return int(str(n), 16)


def call(name, types, *args):
    return make_function(name, types, None)(*args)


@given(st.integers(min_value=0, max_value=9999))
def test_word_bcd_round_trip(n):
    assert call("UINT_TO_BCD_WORD", ["UINT"], n) == bcd(n)
    assert call("WORD_BCD_TO_UINT", ["WORD"], bcd(n)) == n
    assert call("BCD_TO_DINT", ["WORD"], bcd(n)) == n


@given(st.integers(min_value=0, max_value=10**16 - 1))
def test_lword_bcd_round_trip(n):
    assert call("ULINT_TO_BCD_LWORD", ["ULINT"], n) == bcd(n)
    assert call("LWORD_BCD_TO_ULINT", ["LWORD"], bcd(n)) == n


def test_bcd_conversions_scan_by_scan():
    text = program(
        "w : WORD := 16#1234; b : BYTE := 16#42; n : USINT := 7; u : UINT; i : INT; d : DINT; bw : WORD; bb : BYTE;",
        "u := WORD_BCD_TO_UINT(w); i := BCD_TO_INT(w); d := BYTE_BCD_TO_DINT(b);"
        "bb := USINT_TO_BCD(n); bw := INT_TO_BCD_WORD(i); n := n + 11;",
    )
    seen = scans(text, 3, "u", "i", "d", "bb", "bw")
    for scan, values in enumerate(seen):
        assert values == [1234, 1234, 42, bcd(7 + 11 * scan), bcd(1234)]


@pytest.mark.parametrize(
    "declarations, body, message",
    [
        (
            "w : WORD := 16#12A4; u : UINT;",
            "u := WORD_BCD_TO_UINT(w);",
            "WORD_BCD_TO_UINT(16#12A4): the digit 16#A is not BCD",
        ),
        ("w : WORD := 16#0999; s : SINT;", "s := BCD_TO_SINT(w);", "BCD_TO_SINT(16#999) = 999 does not fit its result"),
        ("i : INT := -5; w : WORD;", "w := INT_TO_BCD_WORD(i);", "INT_TO_BCD_WORD(-5): BCD in 4 digits holds 0..9999"),
        ("i : INT := 123; b : BYTE;", "b := INT_TO_BCD_BYTE(i);", "INT_TO_BCD_BYTE(123): BCD in 2 digits holds 0..99"),
    ],
)
def test_invalid_bcd_is_a_located_runtime_fault(declarations, body, message):
    sim = build(program(declarations, body)).simulation()
    sim.cycle(1)
    assert sim.fault is not None
    assert message in sim.fault.text() and "line 6" in sim.fault.text(), sim.fault.text()


def test_typed_trunc_and_overloaded_to_type():
    text = program(
        "r : REAL := -2.7; x : LREAL := 1.0E10; s : SINT; l : LINT; d : DINT; lr : LREAL; t : TIME; ws : WSTRING;",
        "s := REAL_TRUNC_SINT(r); l := LREAL_TRUNC_LINT(x); d := TO_DINT(r); lr := TO_LREAL(s);"
        "t := TO_TIME(d); ws := TO_WSTRING(d);",
    )
    # toward zero (TRUNC), nearest for <SRC>_TO_<DST> (FUN-11: -2.7 -> -3); TIME from ms
    assert scans(text, 1, "s", "l", "d", "lr", "t", "ws") == [[-2, 10**10, -3, -2.0, -3, "-3"]]


@pytest.mark.parametrize("integer", ["SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT"])
@given(data=st.data())
def test_overloaded_trunc_int_truncates_toward_zero(integer, data):
    """TRUNC_<int> (ed. 3 Table 22, the overloaded truncation): either real in, the named integer out; the
    fraction dropped toward zero (CODESYS "TRUNC_INT": 1.9 -> 1, -1.4 -> -1). Values inside the result's range."""
    low, high = ELEMENTARY[integer].min or 0, ELEMENTARY[integer].max or 0
    value = data.draw(st.floats(min_value=max(low, -(2**52)), max_value=min(high, 2**52)))
    real = data.draw(st.sampled_from(["REAL", "LREAL"])) if abs(value) < 2**24 else "LREAL"
    assert call(f"TRUNC_{integer}", [real], value) == int(value)


def test_overloaded_trunc_scan_by_scan():
    text = program(
        "r : REAL := -2.7; x : LREAL := 1.0E10; s : SINT; l : LINT; i : INT; j : INT; u : UDINT;",
        "i := TRUNC_INT(1.9); j := TRUNC_INT(-1.4); s := TRUNC_SINT(r); l := TRUNC_LINT(x); u := TRUNC_UDINT(x / 4.0);"
        "r := r - 1.0;",
    )
    # CODESYS "Operator: TRUNC_INT": TRUNC_INT(1.9) = 1, TRUNC_INT(-1.4) = -1; r is -2.7, -3.7, -4.7 (binary32
    # -3.7 and -4.7 stay strictly between -4 and -3, -5 and -4)
    assert scans(text, 3, "i", "j", "s", "l", "u") == [[1, -1, -2 - n, 10**10, 2_500_000_000] for n in range(3)]


@pytest.mark.parametrize(
    "body, message",
    [
        ("u := TRUNC_USINT(i);", "input IN of TRUNC_USINT must be ANY_REAL, not INT"),
        ("u := TRUNC_UNIT(2.5);", "unknown function 'TRUNC_UNIT' - did you mean 'TRUNC_UINT'?"),
        ("u := TRUNC_INT(2.5);", "cannot assign INT to USINT without a conversion such as INT_TO_USINT"),
    ],
)
def test_overloaded_trunc_diagnostics(body, message):
    found = errors(program("i : INT; u : USINT;", body))
    assert len(found) == 1 and message in found[0] and "Main/body:6:" in found[0], found


def test_wstring_in_conversions_and_string_functions():
    text = program(
        'ws : WSTRING := "abc"; w2 : WSTRING; n : INT; s : STRING; k : INT; w3 : WSTRING;',
        'n := LEN(ws); w2 := CONCAT(ws, "de"); k := FIND(w2, "cd"); s := WSTRING_TO_STRING(w2);'
        'w3 := INT_TO_WSTRING(WSTRING_TO_INT("42") + 1); w2 := MID(STRING_TO_WSTRING(s), 2, 2);',
    )
    assert scans(text, 1, "n", "k", "s", "w3", "w2") == [[3, 3, "abcde", "43", "bc"]]


@pytest.mark.parametrize(
    "body, message",
    [
        ("u := WORD_BCD_TO_UNT(w);", "unknown function 'WORD_BCD_TO_UNT' - did you mean 'WORD_BCD_TO_UINT'?"),
        ("u := WORD_BCD_TO_SINT(w);", "unknown function 'WORD_BCD_TO_SINT' - did you mean 'WORD_BCD_TO_INT'?"),
        ("u := TO_UNT(w);", "unknown function 'TO_UNT' - did you mean 'TO_UINT'?"),
        ("u := BYTE_BCD_TO_UINT(w);", "input IN of BYTE_BCD_TO_UINT must be BYTE, not WORD"),
    ],
)
def test_diagnostics_name_only_functions_that_exist(body, message):
    """WORD_BCD_TO_SINT does not exist (9999 does not fit a SINT): the suggestion is one that does."""
    found = errors(program("w : WORD; u : UINT;", body))
    assert len(found) == 1 and message in found[0], found
