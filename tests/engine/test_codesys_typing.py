"""CODESYS typing (``Project.typing = "codesys"``, issue 25): CODESYS V3's arithmetic on bit strings, shifts on
integers, implicit conversions and its wide registers, scan by scan (ST-20 stays the IEC default).

Every expected value comes from CODESYS's documentation, quoted in the test's docstring:

* "Operators" (content.helpme-codesys.com, _cds_struct_reference_operators): "The CODESYS compiler ... computes
  temporary results always with the native size ... at least with 32-bit temporary values on x86 and ARM systems";
  its examples 1-4 with wVar/dwVar (quoted below);
* "Operator: SHL" / "SHR": "Note the number of bits which CODESYS uses for this operation as defined by the data
  type of the input variable in" (16#45 SHL 2 is 16#14 in a BYTE, 16#0114 in a WORD; SHR 2 is 16#11); SHR of a
  signed type: "an arithmetic shift will be executed ..., that means it will be filled with the value of the
  topmost bit" (CODESYS V2.3 / ABB Automation Builder's CODESYS help);
* Beckhoff's TwinCAT 3 (CODESYS V3) "Type conversion operators": "Conversions from a 'smaller' type to a 'larger'
  type, such as from BYTE to INT or from WORD to DINT ... are also possible implicitly".
"""

from __future__ import annotations

import functools
import math
import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.st.types import typing_rules

from .ed3_support import program

VARIANTS = ("fast", "debug")


def _build(text: str, typing: str = "codesys", variant: str = "fast"):
    with typing_rules(typing):  # the rules the text is parsed by too (an END_IF without ';')
        project, diagnostics = source_to_project(text, "codesys")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    return build_project(project.model_copy(update={"typing": typing}), variant)


def _scan(text: str, *paths: str, variant: str = "fast", scans: int = 1) -> list:
    result = _build(text, variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = result.simulation()
    sim.cycle(scans)
    assert sim.fault is None, sim.fault.text()
    return [sim.read(f"Main.{p}") for p in paths]


def _diagnostics(text: str, typing: str = "codesys", severity: str = "error") -> list[str]:
    return [f"{d.code} {d.line}: {d.message}" for d in _build(text, typing).diagnostics if d.severity == severity]


@pytest.mark.parametrize("variant", VARIANTS)
def test_the_register_is_not_cut_before_a_wider_variable_or_a_comparison(variant):
    """CODESYS "Operators", example 1: ``wVar := 65535; dwVar := wVar + 1;`` - "the result in dwVar is 65536".
    Example 2: ``bVar1 := (wVar1 + 1) = wVar2; bVar2 := (wVar2 - 1) = wVar1;`` with wVar1 = 65535, wVar2 = 0:
    "the result (bVar1, bVar2) of both comparisons is FALSE" on 32- and 64-bit hardware (not cut to 0 / 65535).
    Example 3: ``wVar3 := wVar1 + 1; bVar1 := wVar3 = wVar2;``: "truncated to the target data type WORD", TRUE.
    Example 4: ``TO_WORD(wVar1 + 1) = wVar2`` and ``TO_WORD(wVar2 - 1) = wVar1``: both TRUE (16-bit)."""
    text = program(
        "wVar : WORD := 65535; dwVar : DWORD; wVar1 : WORD := 65535; wVar2 : WORD; wVar3 : WORD;"
        "ex2 : BOOL := TRUE; ex2b : BOOL := TRUE; ex3 : BOOL; ex4a : BOOL; ex4b : BOOL;",
        """
dwVar := wVar + 1;
ex2 := (wVar1 + 1) = wVar2;
ex2b := (wVar2 - 1) = wVar1;
wVar3 := wVar1 + 1;
ex3 := wVar3 = wVar2;
ex4a := TO_WORD(wVar1 + 1) = wVar2;
ex4b := TO_WORD(wVar2 - 1) = wVar1;
""",
    )
    assert _scan(text, "dwVar", "ex2", "ex2b", "wVar3", "ex3", "ex4a", "ex4b", variant=variant) == [
        65536,
        False,
        False,
        0,
        True,
        True,
        True,
    ]


def test_signed_operations_compute_in_the_32_bit_register():
    """At least 32 bits on x86/ARM ("Operators"): INT 30000 + 30000 stored in a DINT is 60000 (not -5536 as a 16-bit
    INT would give), ``i + 1 > i`` with i = 32767 is TRUE (32768 > 32767), and ``(i + 1) / 2`` is 16384; stored in an
    INT the same sum is cut to 16 bits: 60000 - 65536 = -5536 (example 3's truncation)."""
    text = program(
        "i1 : INT := 30000; i2 : INT := 30000; i : INT := 32767; d : DINT; q : BOOL; half : DINT; cut : INT;",
        "d := i1 + i2; q := i + 1 > i; half := (i + 1) / 2; cut := i1 + i2;",
    )
    assert _scan(text, "d", "q", "half", "cut") == [60000, True, 16384, -5536]


def test_a_register_value_the_target_decides_is_refused_where_it_is():
    """Where even a value of the operation's own type gives another result in a wider register, nothing is guessed:
    SHL(i + 1, 8) keeps 16 or 32 bits (16#0101 SHL 8 is 16#0100 in an INT, 16#0001_0100 in a DINT), NOT (w + 1) on a
    WORD flips 16 or 32 bits, and ABS(i - 1) with i = -32768, stored in an INT, is -32767 from the register, 32767
    from a wrapped INT. Each is ST-CODESYS-REGISTER at its line; example 4's fix (TO_WORD) and an overloaded TO_x
    build. Where a value of the operation's own type is enough, it builds with a run-time check instead
    (tests/engine/test_codesys_register_fits.py)."""
    text = program(
        "w : WORD; d : DINT; dw : DWORD; i : INT;",
        "d := SHL(i + 1, 8);\ndw := NOT (w + 1);\ni := ABS(i - 1);\nd := SHL(TO_INT(i + 1), 8);\nd := TO_DINT(i + 1);",
    )
    found = _diagnostics(text)
    assert [line.split(":")[0] for line in found] == [
        "ST-CODESYS-REGISTER 6",
        "ST-CODESYS-REGISTER 7",
        "ST-CODESYS-REGISTER 8",
    ]
    assert "depends on the target" in found[0] and "TO_WORD" in found[0]


@pytest.mark.parametrize("variant", VARIANTS)
def test_arithmetic_on_bit_strings_as_unsigned_integers(variant):
    """BYTE 200 + 100 stored in a BYTE: 300 cut to 8 bits = 44 (example 3); DWORD 16#FFFF_FFFF + 1 in a DWORD wraps
    to 0 (32 bits, the register's width on x86/ARM); 7 / 2 on BYTEs is 3, DWORD 100 MOD 7 is 2, WORD 3 * 5 is 15."""
    text = program(
        "b1 : BYTE := 200; b2 : BYTE := 100; b : BYTE; dw : DWORD := 16#FFFF_FFFF; seven : BYTE := 7;"
        "quotient : BYTE; rest : DWORD; big : DWORD := 100; w : WORD := 3; product : WORD;",
        "b := b1 + b2; dw := dw + 1; quotient := seven / 2; rest := big MOD 7; product := w * 5;",
    )
    assert _scan(text, "b", "dw", "quotient", "rest", "product", variant=variant) == [44, 0, 3, 2, 15]


@pytest.mark.parametrize("variant", VARIANTS)
def test_shifts_on_integers_use_the_bits_of_the_input_type(variant):
    """SHL: "the number of bits ... as defined by the data type of the input": BYTE 16#45 SHL 2 = 16#14, WORD 16#45
    SHL 2 = 16#0114, SHR 2 = 16#11. On an INT, SHL(2024, 14) keeps 16 bits: 2024 = 2#111_1110_1000, shifted by 14
    only its two low bits (00) stay, so 0 (OSCAT's LEAP_YEAR relies on it). SHR of a signed -16 by 2 is an
    arithmetic shift: -4; SHR(UINT 40000, 3) = 5000; ROL(SINT -128, 1): 2#1000_0000 rotated is 2#0000_0001 = 1.
    N may be a BYTE (the help's own example declares ``n : BYTE``)."""
    text = program(
        "in_byte : BYTE := 16#45; in_word : WORD := 16#45; n : BYTE := 2; b : BYTE; w : WORD; r : WORD;"
        "year : INT := 2024; leap : INT := 1; neg : INT := -16; sar : INT; u : UINT := 40000; us : UINT;"
        "s : SINT := -128; rot : SINT;",
        "b := SHL(in_byte, n); w := SHL(in_word, n); r := SHR(in_word, n); leap := SHL(year, 14);"
        "sar := SHR(neg, 2); us := SHR(u, 3); rot := ROL(s, 1);",
    )
    assert _scan(text, "b", "w", "r", "leap", "sar", "us", "rot", variant=variant) == [
        0x14,
        0x0114,
        0x11,
        0,
        -4,
        5000,
        1,
    ]


def test_implicit_widening_and_narrowing():
    """Implicit conversion "from a smaller type to a larger type" (BYTE to INT, WORD to DINT) and an integer into a
    REAL: r := i with i = 3 is 3.0, r * b = 1.5 * 4 = 6.0, BYTE 200 into an INT is 200. A DINT 70000 stored in an INT
    is cut to 16 bits (example 3): 70000 - 65536 = 4464, with the warning ST-IMPLICIT-NARROW."""
    text = program(
        "i : INT := 3; r : REAL; x : REAL := 1.5; b : BYTE := 4; prod : REAL; big : BYTE := 200; wide : INT;"
        "d : DINT := 70000; small : INT;",
        "r := i; prod := x * b; wide := big; small := d;",
    )
    assert _scan(text, "r", "prod", "wide", "small") == [3.0, 6.0, 200, 4464]
    warnings = _diagnostics(text, severity="warning")
    assert [w for w in warnings if w.startswith("ST-IMPLICIT-NARROW")] == [
        "ST-IMPLICIT-NARROW 6: DINT is narrowed implicitly to INT (CODESYS typing): the value is cut as DINT_TO_INT "
        "does; write the conversion to say so"
    ]


def test_iec_typing_stays_the_default_and_refuses_all_of_it():
    """ST-20: without the setting, bit strings are not numbers, SHR takes ANY_BIT, an INT is not a REAL."""
    text = program(
        "b : BYTE; i : INT; r : REAL; n : BYTE;",
        "b := b + 1;\ni := SHR(i, 1);\nr := i;\nb := SHR(b, n);",
    )
    found = _diagnostics(text, typing="iec")
    assert [line.split(":")[0] for line in found] == [
        "ST-TYPE-MISMATCH 6",
        "ST-TYPE-MISMATCH 7",
        "ST-TYPE-MISMATCH 8",
        "ST-TYPE-MISMATCH 9",
    ]


@pytest.mark.parametrize("variant", VARIANTS)
def test_an_end_keyword_without_semicolon_before_a_statement_only_warns(variant):
    """CODESYS compiles OSCAT's REAL_TO_FRAC, whose END_IF and END_REPEAT have no ';' before the next statement:
    under CODESYS typing each is a warning at the keyword's end and the statements run as with the ';' (FOR sums
    1 + 2 + 3 = 6; IF sets k to 1, CASE 1 makes it 10, WHILE counts to 12, REPEAT to 14). IEC typing keeps ST-40's
    error."""
    text = program(
        "n : INT; i : INT; k : INT; done : BOOL;",
        """
FOR i := 1 TO 3 DO n := n + i; END_FOR
IF n = 6 THEN k := 1; END_IF
CASE k OF 1: k := 10; END_CASE
WHILE k < 12 DO k := k + 1; END_WHILE
REPEAT k := k + 1; UNTIL k >= 14 END_REPEAT
done := TRUE;""",
    )
    assert _scan(text, "n", "k", "done", variant=variant) == [6, 14, True]
    missing = [
        "ST-PARSE 7: expected ';' after END_FOR",
        "ST-PARSE 8: expected ';' after END_IF",
        "ST-PARSE 9: expected ';' after END_CASE",
        "ST-PARSE 10: expected ';' after END_WHILE",
        "ST-PARSE 11: expected ';' after END_REPEAT",
    ]
    assert _diagnostics(text, severity="warning") == missing
    _, refused = source_to_project(text, "iec")
    assert [f"{d.code} {d.line}: {d.message}" for d in refused if d.severity == "error"] == missing


#: Targets of at most 32 bits: their bits and whether they are signed.
_TARGETS = {"BYTE": (8, False), "SINT": (8, True), "WORD": (16, False), "INT": (16, True), "UINT": (16, False)}
_TARGETS |= {"DWORD": (32, False), "DINT": (32, True), "UDINT": (32, False)}


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_negated_bit_string_is_the_registers_negative_cut_where_it_is_stored(variant):
    """CODESYS computes ``-b`` (b a BYTE, 1) in its register of at least 32 bits, as ``0 - b``, and cuts it where it
    is stored ("Operators", example 1: not cut to the operand's width before a wider variable): -1 into an INT input
    of a function (OSCAT's ``inc(cnt, -step, mx)``: INC1(0, -1, 255) = (0 - 1 + 255 + 1) MOD 256 = 255), 16#FF
    into a BYTE, 16#FFFF into a WORD, 16#FFFF_FFFF into a DWORD, -1 into a DINT; ``-bb`` with bb = 200 is -200 in an
    INT and 16#38 = 56 cut to a SINT. ``b1 - b2`` (0 - 1) into a WORD is 16#FFFF the same way. The low 32 bits (or
    fewer) are the same in a 32- or 64-bit register read signed or unsigned, so every target agrees."""
    text = (
        "FUNCTION Inc1 : INT\nVAR_INPUT X : INT; D : INT; M : INT; END_VAR\n"
        "Inc1 := (X + D + M + 1) MOD (M + 1);\nEND_FUNCTION\n"
    ) + program(
        "b : BYTE := 1; bb : BYTE := 200; b1 : BYTE; b2 : BYTE := 1; counted : INT; cut : BYTE; w : WORD; dw : DWORD;"
        "d : DINT; i : INT; si : SINT; w2 : WORD;",
        "counted := Inc1(0, -b, 255); cut := -b; w := -b; dw := -b; d := -b; i := -bb; si := -bb; w2 := b1 - b2;",
    )
    names = ("counted", "cut", "w", "dw", "d", "i", "si", "w2")
    assert _scan(text, *names, variant=variant) == [255, 0xFF, 0xFFFF, 0xFFFF_FFFF, -1, -200, 56, 0xFFFF]


#: ``-x`` of each narrow unsigned type stored into targets of at most 32 bits (CODESYS typing).
_NEGATIONS = [(source, target) for source in ("BYTE", "WORD", "USINT", "UINT") for target in _TARGETS]


@functools.cache
def _negations():
    sources = dict.fromkeys(source for source, _ in _NEGATIONS)
    declarations = "".join(f"x_{s} : {s};" for s in sources) + "".join(f"n_{s}_{t} : {t};" for s, t in _NEGATIONS)
    body = "".join(f"n_{s}_{t} := -x_{s};\n" for s, t in _NEGATIONS)
    result = _build(program(declarations, body))
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 255), st.integers(0, 65535))
def test_a_negation_cut_to_at_most_32_bits_is_the_twos_complement_of_the_value(small, large):
    """The property behind the rule above: the register's 0 - x, cut to a target of at most 32 bits, is -x modulo
    2^bits read as the target reads its bits (the independent reference: two's complement arithmetic in Python),
    for every BYTE / USINT (0..255) and WORD / UINT (0..65535) value."""
    sim = _negations()
    values = {"BYTE": small, "USINT": small, "WORD": large, "UINT": large}
    for source, value in values.items():
        sim.write(f"Main.x_{source}", value)
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    for source, target in _NEGATIONS:
        bits, signed = _TARGETS[target]
        expected = -values[source] % 2**bits
        expected -= 2**bits if signed and expected >= 2 ** (bits - 1) else 0
        assert sim.read(f"Main.n_{source}_{target}") == expected, (source, target)


def test_a_negated_bit_string_compared_or_widened_past_32_bits_is_checked_when_it_runs():
    """``-b < 0`` is TRUE in a signed register and FALSE in an unsigned one, and ``-b`` into an LWORD is 16#FFFF_FFFF
    or 16#FFFF_FFFF_FFFF_FFFF by the register's width ("the computational result depends on the target system
    hardware"): built, with the located fault ``overflow`` when the value is outside BYTE (b = 1), none for b = 0.
    Under IEC typing a bit string is no number (ST-20)."""
    for body in ("IF -b < 0 THEN d := 1; END_IF;", "lw := -b;"):
        text = program("b : BYTE := 1; d : DINT; lw : LWORD;", body)
        sim = _build(text).simulation()
        sim.cycle(1)
        assert sim.fault is not None and sim.fault.code == "overflow"
        assert sim.fault.message.startswith("'-b' is -1 here, outside BYTE (0..255)")
        assert (sim.fault.pou, sim.fault.origin.line, sim.read("Main.d"), sim.read("Main.lw")) == ("MAIN", 6, 0, 0)
        assert _scan(text.replace("b : BYTE := 1", "b : BYTE := 0"), "d", "lw") == [0, 0]
    assert _diagnostics(program("b : BYTE; i : INT;", "i := -b;"), typing="iec") == [
        "ST-TYPE-MISMATCH 6: unary '-' needs a number or TIME, not BYTE"
    ]


@pytest.mark.parametrize("variant", VARIANTS)
def test_functions_of_real_take_an_integer_as_an_lreal(variant):
    """CODESYS "Operator: EXPT": "Permitted data types for the input values: Numeric base data types (SINT, ... INT,
    ... LWORD)", the return value a REAL or LREAL, ``lrPow := EXPT(iBase, iExponent)`` with 2 and 7 is 128;
    "Operator: SQRT": "any numeric basic data type" (SQRT(16) is 4). The integer is converted to LREAL (TwinCAT:
    "return type is always LREAL"; every 32-bit value is exact in it), so ``EXPT(i, 1.5) * 0.836`` with i = 4 is
    8 * 0.836 computed in LREAL and rounded to the REAL it is stored in (OSCAT's BFT_TO_MS), with a warning; so is
    ``i ** 2``. IEC typing keeps FUN-33's ANY_REAL base."""
    text = program(
        "iBase : INT := 2; iExponent : INT := 7; lrPow : LREAL; i : INT := 4; w : WORD := 16; d : DINT := 16777217;"
        "root : LREAL; speed : REAL; square : REAL; big : LREAL;",
        "lrPow := EXPT(iBase, iExponent);\nroot := SQRT(w);\nspeed := EXPT(i, 1.5) * 0.836;\nsquare := i ** 2;"
        "\nbig := SQRT(d);",
    )
    assert _scan(text, "lrPow", "root", "speed", "square", "big", variant=variant) == [
        128.0,
        4.0,
        struct.unpack("<f", struct.pack("<f", 8 * 0.836))[0],
        16.0,
        math.sqrt(16777217),
    ]
    assert _diagnostics(text, severity="warning") == [
        "ST-IMPLICIT-CONV 6: EXPT computes in LREAL (CODESYS typing): its INT input is converted implicitly",
        "ST-IMPLICIT-CONV 7: SQRT computes in LREAL (CODESYS typing): its WORD input is converted implicitly",
        "ST-IMPLICIT-CONV 8: EXPT computes in LREAL (CODESYS typing): its INT input is converted implicitly",
        "ST-IMPLICIT-NARROW 8: LREAL is narrowed implicitly to REAL (CODESYS typing): the value is cut as LREAL_TO_REAL "
        "does; write the conversion to say so",
        "ST-IMPLICIT-CONV 9: '**' computes in LREAL (CODESYS typing): its INT base is converted implicitly",
        "ST-IMPLICIT-NARROW 9: LREAL is narrowed implicitly to REAL (CODESYS typing): the value is cut as LREAL_TO_REAL "
        "does; write the conversion to say so",
        "ST-IMPLICIT-CONV 10: SQRT computes in LREAL (CODESYS typing): its DINT input is converted implicitly",
    ]
    assert _diagnostics(text, typing="iec") == [
        "ST-TYPE-MISMATCH 6: EXPT works on ANY_REAL, not on INT",
        "ST-TYPE-MISMATCH 7: SQRT works on ANY_REAL, not on WORD",
        "ST-TYPE-MISMATCH 8: EXPT works on ANY_REAL, not on INT",
        "ST-TYPE-MISMATCH 9: the base of '**' must be REAL or LREAL, not INT; convert it (e.g. INT_TO_REAL)",
        "ST-TYPE-MISMATCH 10: SQRT works on ANY_REAL, not on DINT",
    ]


def test_a_project_may_define_multime_and_divtime_under_codesys_typing():
    """MULTIME and DIVTIME are seed 000's names for MUL_TIME and DIV_TIME (KW-01 reserves them); CODESYS has neither,
    and OSCAT BASIC defines its own MULTIME ("multiplies a time by a real number"). Under CODESYS typing a project's
    own function of that name is no redefinition and is what its calls run: OSCAT's body gives MULTIME(T#2s, 1.5) =
    T#3s, and a DIVTIME of the project's that returns its input untouched gives T#6s for DIVTIME(T#6s, 4), where the
    standard one gives T#1s500ms (FUN-86). IEC typing keeps them reserved (ST-DUPLICATE)."""
    functions = (
        "FUNCTION MULTIME : TIME\nVAR_INPUT t : TIME; M : REAL; END_VAR\n"
        "MULTIME := DWORD_TO_TIME(REAL_TO_DWORD(DWORD_TO_REAL(TIME_TO_DWORD(t)) * M));\nEND_FUNCTION\n"
        "FUNCTION DIVTIME : TIME\nVAR_INPUT t : TIME; n : INT; END_VAR\nDIVTIME := t;\nEND_FUNCTION\n"
    )
    text = functions + program(
        "product : TIME; quotient : TIME;", "product := MULTIME(T#2s, 1.5);\nquotient := DIVTIME(T#6s, 4);"
    )
    assert _scan(text, "product", "quotient") == [3000, 6000]
    assert _diagnostics(text, typing="iec") == [
        "ST-DUPLICATE None: 'MULTIME' is a standard function or function block name and cannot be redefined",
        "ST-DUPLICATE None: 'DIVTIME' is a standard function or function block name and cannot be redefined",
    ]
    assert _scan(program("quotient : TIME;", "quotient := DIVTIME(T#6s, 4);"), "quotient") == [1500]


def test_a_bit_string_indexes_an_array_and_selects_a_case_branch():
    """CODESYS takes a BYTE as an array index and a CASE selector, as its unsigned value: a[b] with b = 3 is the
    element 30, CASE b OF 3: 'three' branch."""
    text = program(
        "a : ARRAY [0..5] OF INT := [0, 10, 20, 30, 40, 50]; b : BYTE := 3; x : INT; branch : INT;",
        "x := a[b]; CASE b OF 1: branch := 1; 3: branch := 3; ELSE branch := -1; END_CASE;",
    )
    assert _scan(text, "x", "branch") == [30, 3]


def test_min_and_max_of_a_register_value_choose_among_the_uncut_values():
    """``MAX(links, i - 1)`` in CODESYS compares the register's values: with i = -32768 (INT), i - 1 is -32769 in
    the 32-bit register, so MAX(-32768, -32769) = -32768; a 16-bit INT would have wrapped i - 1 to 32767 and chosen
    it. Stored into an INT the result is -32768 either way only when chosen from the uncut values."""
    text = program("links : INT := -32768; i : INT := -32768; rechts : INT;", "rechts := MAX(links, i - 1);")
    assert _scan(text, "rechts") == [-32768]


def test_an_action_computes_in_the_register_too():
    """The register rule holds in a function block's ACTION as in its body (example 1): d := i1 + i2 with INT 30000
    and 30000 is 60000 in a DINT; ``dw := NOT (w + 1)`` on a WORD is refused there too (ST-CODESYS-REGISTER)."""
    fb = """
FUNCTION_BLOCK Adder
VAR i1 : INT := 30000; i2 : INT := 30000; END_VAR
VAR_OUTPUT d : DINT; END_VAR
ACTION Add:
    d := i1 + i2;
END_ACTION
END_FUNCTION_BLOCK
"""
    text = fb + program("adder : Adder; d : DINT;", "adder.Add(); d := adder.d;")
    assert _scan(text, "d") == [60000]
    refused = fb.replace("d := i1 + i2;", "d := i1 + i2;\n    dw := NOT (w + 1);").replace(
        "VAR_OUTPUT d : DINT; END_VAR", "VAR_OUTPUT d : DINT; END_VAR\nVAR w : WORD; dw : DWORD; END_VAR"
    )
    assert [line.split(":")[0] for line in _diagnostics(refused + program("adder : Adder;", "adder.Add();"))] == [
        "ST-CODESYS-REGISTER 8"
    ]
