"""OSCAT BASIC 3.33 (../shared/external/oscat/oscat.st) lowered as one project: how many POUs build and run (issue 25).

What "build" means here: the whole library is one project; a POU *builds* when, in a project holding only the POUs
that build (found by dropping every POU with an error and building again until nothing changes), it has no error
diagnostic located in it. So a POU whose own text is fine but that uses a POU that does not build does not build
either (counted under "uses a POU that does not build"). The count, the first error's code and message (with
the names taken out) of each POU that does not build, grouped, are printed; the floors assert the counts.

"Run": a program calling a handful of OSCAT functions is built with the POUs that build and scanned once; the
expected values are the ones OSCAT's own documentation (the comment at the top of each function) states, worked
out by hand, not taken from running LadderLab.

Skips cleanly when ../shared/external is absent (tests/support.external).
"""

from __future__ import annotations

import collections
import functools
import re
import struct

import pytest

from ladderlab.model.project import Pou
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.support import PASS_RATES, external

#: Floors, IEC typing (the default) and CODESYS typing (Project.typing, docs/st.md "CODESYS typing"). Raise them
#: when more of OSCAT builds; what still fails is listed by cause in docs/st.md.
FLOOR_IEC = 324
FLOOR_CODESYS = 532


@functools.cache
def _oscat(typing: str):
    """(project, names of the POUs that build, {POU name: its first error}) for the given typing."""
    project, _ = source_to_project(external("oscat", "oscat.st").read_text(encoding="utf-8"), "oscat")
    if typing != "iec":
        project = project.model_copy(update={"typing": typing})
    first_errors: dict[str, object] = {}
    kept = list(project.pous)
    for round_number in range(1, 100):
        build = build_project(project.model_copy(update={"pous": kept}))
        failing = {}
        for diagnostic in build.diagnostics:
            if diagnostic.severity == "error" and diagnostic.pou is not None:
                failing.setdefault(diagnostic.pou.upper(), diagnostic)
        if not failing:
            return project, {p.name.upper() for p in kept}, first_errors
        for name, diagnostic in failing.items():
            first_errors.setdefault(name, diagnostic if round_number == 1 else _CASCADE)
        kept = [p for p in kept if p.name.upper() not in failing]
    raise AssertionError("dropping the POUs that do not build did not settle")


#: The cause of a POU that has no error of its own but uses one that does not build.
_CASCADE = "uses a POU that does not build"


def _cause(diagnostic) -> str:
    """An error's code and message with quoted names and numbers taken out, so equal causes group together."""
    if diagnostic is _CASCADE:
        return _CASCADE
    message = re.sub(r"function [A-Z_0-9]+", "function …", re.sub(r"'[^']*'", "'…'", diagnostic.message))
    return f"{diagnostic.code}: {re.sub(r'[0-9]+', 'N', message)[:110]}"


@pytest.mark.parametrize(("typing", "floor"), [("iec", FLOOR_IEC), ("codesys", FLOOR_CODESYS)])
def test_oscat_pous_build(typing, floor):
    project, built, first_errors = _oscat(typing)
    total = len(project.pous)
    PASS_RATES[f"OSCAT BASIC POUs that build ({typing} typing)"] = (len(built), total)
    causes = collections.Counter(_cause(d) for d in first_errors.values())
    print(f"\nOSCAT BASIC, {typing} typing: {len(built)} / {total} POUs build; first error of the others, by cause:")
    for cause, count in causes.most_common():
        print(f"  {count:4} {cause}")
    assert len(built) >= floor


#: OSCAT function calls and the results its documentation states (the comment opening each function):
RUNS = {
    # FACT: "calculates the factorial of x; if the input is negative or higher then 12 the output will be -1"
    "FACT(5)": 120,
    "FACT(13)": -1,
    # FIB: "calculates the fibonacci sequence" (F0 = 0, F1 = 1); "X < 0 OR X > 46: -1"
    "FIB(10)": 55,
    "FIB(1)": 1,
    # EVEN: "the output is true if the input is even"
    "EVEN(4)": True,
    "EVEN(-3)": False,
    # INC1: "inc1(X,3) will generate 0,1,2,0,1,....."
    "INC1(1, 3)": 2,
    "INC1(2, 3)": 0,
    # BIT_COUNT: "bit_count(3) returns 2 because two bits (bits 0 and 1) are true"
    "BIT_COUNT(3)": 2,
    "BIT_COUNT(16#FFFF_FFFF)": 32,
    # REVERSE: "reverses the bits of a byte so that after execution bit 7 is at bit 0 location and so forth"
    "REVERSE(2#0000_0001)": 0b1000_0000,
    "REVERSE(2#1100_1010)": 0b0101_0011,
    # GCD: "the greatest common divisor of two numbers A and B"
    "GCD(12, 18)": 6,
    "GCD(-48, 36)": 12,
    # LEAP_YEAR: "true if the tested year is a leap year", "works for any year from 1970 up to 2100"
    "LEAP_YEAR(2024)": True,
    "LEAP_YEAR(2023)": False,
    # BCDC_TO_INT: "converts a two digit bcd number into an integer"
    "BCDC_TO_INT(16#42)": 42,
    # ARRAY_MAX / _MIN / _SUM / _SPR: "the function needs to be called: array_max(adr("array"),sizeof("array"))";
    # ARRAY_SPR: "for example: spread of [12,0,4,1,7] is 12 - 0 = 12" (ARR below); pointer arithmetic and SIZEOF of
    # a pointer (4 bytes on a 32-bit target)
    "ARRAY_MAX(ADR(arr), SIZEOF(arr))": 12.0,
    "ARRAY_MIN(ADR(arr), SIZEOF(arr))": 0.0,
    "ARRAY_SUM(ADR(arr), SIZEOF(arr))": 24.0,
    "ARRAY_SPR(ADR(arr), SIZEOF(arr))": 12.0,
    # ARRAY_AVG: "this function will calculate the average of a given array": 24 / 5 = 4.8, as a REAL (binary32)
    "ARRAY_AVG(ADR(arr), SIZEOF(arr))": struct.unpack("<f", struct.pack("<f", 4.8))[0],
    # BAND_B: "while X < B the result will be 0 and while X > 255-B the output will be 255 otherwise the result = X"
    "BAND_B(10, 20)": 0,
    "BAND_B(250, 20)": 255,
    "BAND_B(100, 20)": 100,
    # CODE: "extracts the code of a character at position POS of a string STR" ('B' is 66)
    "CODE('ABC', 2)": 66,
    # FIX: "truncates a string at length L or if the string is shorter then L it will be filled ... till its length"
    "FIX('abcdef', 4, 42, 0)": "abcd",
    "FIX('abc', 5, 42, 0)": "abc**",
    # DIR_TO_DEG: "converts compass directions to degrees" (L = 1: English)
    "DIR_TO_DEG('E', 1)": 90,
    "DIR_TO_DEG('SW', 1)": 225,
    # REAL_TO_FRAC: "this function calculates the closest fraction for a real number" with a denominator of at most
    # N (its input "maximale Groesse des Nenners"); the closest fractions: 3/4, -3/4, 1/3 (0.333333, N = 10) and
    # 355/113 (pi, N = 1000: no fraction with a denominator below 1000 is closer)
    "REAL_TO_FRAC(0.75, 100)": {"NUMERATOR": 3, "DENOMINATOR": 4},
    "REAL_TO_FRAC(-0.75, 100)": {"NUMERATOR": -3, "DENOMINATOR": 4},
    "REAL_TO_FRAC(0.333333, 10)": {"NUMERATOR": 1, "DENOMINATOR": 3},
    "REAL_TO_FRAC(3.14159265, 1000)": {"NUMERATOR": 355, "DENOMINATOR": 113},
    # BFT_TO_MS: "converts wind speed from beaufort to m/s", v = 0.836 * B^(3/2) (the WMO's Beaufort formula; EXPT of
    # the INT B, CODESYS typing): 4 Bft is 0.836 * 8 = 6.688 m/s, 9 Bft 0.836 * 27 = 22.572 m/s, as REALs (binary32)
    "BFT_TO_MS(4)": struct.unpack("<f", struct.pack("<f", 6.688))[0],
    "BFT_TO_MS(9)": struct.unpack("<f", struct.pack("<f", 22.572))[0],
    # MULTIME: "multiplies a time by a real number and returns a time" (OSCAT's own, CODESYS typing: docs/st.md)
    "MULTIME(T#2s, 1.5)": 3000,
    # The date functions, compared with the date they give (CODESYS's DATE_TO_DWORD counts seconds):
    # SET_DATE "creates a date output from year, month and day of month"
    "SET_DATE(2024, 2, 29) = D#2024-02-29": True,
    # DATE_ADD "adds days, weeks, month or years to a date": 2023-12-25 + 7 days + 1 week
    "DATE_ADD(D#2023-12-25, 7, 1, 0, 0) = D#2024-01-08": True,
    # MONTH_BEGIN "returns the date for the first day of the current month in the current year"
    "MONTH_BEGIN(D#2024-03-17) = D#2024-03-01": True,
    # EASTER "calculates the day of easter sunday for a given year" (2024: March 31)
    "EASTER(2024) = D#2024-03-31": True,
}
#: The array the ARRAY_* calls read.
ARR = "arr : ARRAY[1..5] OF REAL := [12.0, 0.0, 4.0, 1.0, 7.0];"

_RESULT_TYPES = {"FACT": "DINT", "FIB": "DINT", "EVEN": "BOOL", "INC1": "INT", "BIT_COUNT": "INT"}
_RESULT_TYPES |= {"REVERSE": "BYTE", "GCD": "INT", "LEAP_YEAR": "BOOL", "BCDC_TO_INT": "INT"}
_RESULT_TYPES |= dict.fromkeys(("ARRAY_MAX", "ARRAY_MIN", "ARRAY_SUM", "ARRAY_SPR", "ARRAY_AVG"), "REAL")
_RESULT_TYPES |= {
    "BAND_B": "BYTE",
    "CODE": "BYTE",
    "FIX": "STRING[250]",
    "DIR_TO_DEG": "INT",
    "REAL_TO_FRAC": "FRACTION",
}
_RESULT_TYPES |= {"BFT_TO_MS": "REAL", "MULTIME": "TIME"}
_RESULT_TYPES |= dict.fromkeys(("SET_DATE", "DATE_ADD", "MONTH_BEGIN", "EASTER"), "BOOL")  # compared with a date


@pytest.mark.parametrize("typing", ["iec", "codesys"])
def test_oscat_functions_run_with_their_documented_results(typing):
    project, built, _ = _oscat(typing)
    runnable = {call: expected for call, expected in RUNS.items() if call.split("(")[0] in built}
    declarations = "\n".join(
        [ARR, "plc_ms : DWORD;"]
        + [f"r{number} : {_RESULT_TYPES[call.split('(')[0]]};" for number, call in enumerate(runnable)]
    )
    body = "\n".join(f"r{number} := {call};" for number, call in enumerate(runnable))
    clock = "T_PLC_MS" in built  # "T_PLC_MS reads the internal PLC timer": the simulation's clock, in ms
    body += "\nplc_ms := T_PLC_MS();" if clock else ""
    program = Pou(
        name="RunOscat", kind="program", language="st", declarations=f"VAR\n{declarations}\nEND_VAR", body=body
    )
    pous = [p for p in project.pous if p.name.upper() in built] + [program]
    build = build_project(project.model_copy(update={"pous": pous, "tasks": []}))
    assert build.compiled is not None, [d.format() for d in build.diagnostics if d.severity == "error"][:3]
    simulation = build.simulation()
    simulation.cycle(1)
    results = {call: simulation.read(f"RunOscat.r{number}") for number, call in enumerate(runnable)}
    PASS_RATES[f"OSCAT BASIC documented calls that run ({typing} typing)"] = (len(runnable), len(RUNS))
    print(
        f"\nOSCAT calls run ({typing}): {len(runnable)} / {len(RUNS)}; not built: {sorted(set(RUNS) - set(runnable))}"
    )
    assert results == runnable
    assert len(runnable) >= (13 if typing == "iec" else 41)
    assert simulation.read("RunOscat.plc_ms") == (simulation.time_ms if clock else 0)
    assert clock or typing == "iec"


def test_oscat_count_br_counts_down_by_its_step_under_codesys_typing():
    """COUNT_BR: "a byte counter with independent up and dn inputs. the counter counts from 0 to mx and continues at
    0 after it has reached mx; a step input sets the counters stepping width". It counts down with INC(cnt, -step,
    mx), INC: "increments the input X by the value D ... if the output exceeds M it will continue to count from 0
    again" (rev 1.1: "allow for negative increment"), so modulo mx + 1 = 11: from 0 down by 3 on each rising edge of
    DN gives 8, 5, 2, 10, and up by 3 then 2. The BYTE step is negated in CODESYS's register and passed to INC's INT
    input as -3 (docs/st.md "CODESYS typing")."""
    project, built, _ = _oscat("codesys")
    assert "COUNT_BR" in built
    program = Pou(
        name="RunCount",
        kind="program",
        language="st",
        declarations="VAR\ncb : COUNT_BR; up : BOOL; dn : BOOL; cnt : BYTE;\nEND_VAR",
        body="cb(UP := up, DN := dn, STEP := 3, MX := 10);\ncnt := cb.CNT;",
    )
    pous = [p for p in project.pous if p.name.upper() in built] + [program]
    simulation = build_project(project.model_copy(update={"pous": pous, "tasks": []})).simulation()
    seen = []
    for up, dn in [(False, True), (False, False)] * 4 + [(True, False)]:
        simulation.write("RunCount.up", up)
        simulation.write("RunCount.dn", dn)
        simulation.cycle(1)
        assert simulation.fault is None, simulation.fault.text()
        seen.append(simulation.read("RunCount.cnt"))
    assert seen == [8, 8, 5, 5, 2, 2, 10, 10, 2]


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_oscat_buffer_functions_and_replace_uml_under_codesys_typing(variant):
    """_BUFFER_INIT "will initialize a given array of byte with init", _BUFFER_CLEAR "with 0", called as their
    documentation says (``_buffer_init(adr("array"),sizeof("array"),init)``), here on part of an array so that
    exactly the bytes given change: they align their 32-bit accesses with the pointer's address as a number
    (docs/st.md, "A pointer as a number"). REPLACE_UML "replaces all occurences of Ä,Ö,Ü and ä,ö,ü,ß with Ae, ae,
    Oe, oe, Ue, ue and ss" (Latin-1, as TO_UML's codes 196 ... 252: $C4 is Ä)."""
    project, built, _ = _oscat("codesys")
    assert {"_BUFFER_INIT", "_BUFFER_CLEAR", "REPLACE_UML"} <= built
    program = Pou(
        name="RunBuffers",
        kind="program",
        language="st",
        declarations="VAR\nbuf : ARRAY[0..15] OF BYTE := [16(16#AA)]; done : BOOL; whole : ARRAY[0..5] OF BYTE;"
        "\ntext, plain : STRING;\nEND_VAR",
        body="done := _BUFFER_INIT(ADR(buf[1]), 13, 16#5C);\ndone := done AND _BUFFER_CLEAR(ADR(buf[3]), 6);\n"
        "done := done AND _BUFFER_INIT(ADR(whole), SIZEOF(whole), 7);\n"
        "text := REPLACE_UML('$C4rger $FCber Stra$DFe, m$F6glich');\nplain := REPLACE_UML('plain');",
    )
    pous = [p for p in project.pous if p.name.upper() in built] + [program]
    build = build_project(project.model_copy(update={"pous": pous, "tasks": []}), variant)
    simulation = build.simulation()
    simulation.cycle(1)
    assert simulation.fault is None, simulation.fault.text()
    assert simulation.read("RunBuffers.buf") == [0xAA, 0x5C, 0x5C] + [0] * 6 + [0x5C] * 5 + [0xAA, 0xAA]
    assert simulation.read("RunBuffers.whole") == [7] * 6
    assert simulation.read("RunBuffers.done") is True
    assert simulation.read("RunBuffers.text") == "Aerger ueber Strasse, moeglich"
    assert simulation.read("RunBuffers.plain") == "plain"
