"""A pointer as a number under CODESYS typing (issue 25, docs/st.md "A pointer as a number"): CODESYS's "Pointers"
page, "a pointer holds the address of the object": a POINTER is assigned to and from a DWORD on a 32-bit target
(SIZEOF of a pointer is 4 here), compared with one as an address. LadderLab gives each variable whose address is
taken a synthetic base address, aligned to 8, never 0; what is asserted is what every PLC guarantees: a number
made from a pointer leads back to the byte it pointed to, bytes of one variable are consecutive, 0 is NULL, an
aligned variable's address is a multiple of 4, and a number in no variable is a located fault when it is used.
"""

from __future__ import annotations

import functools

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.st.types import typing_rules

from .ed3_support import program

VARIANTS = ("fast", "monitor", "debug")


def _build(text: str, typing: str = "codesys", variant: str = "fast"):
    with typing_rules(typing):
        project, diagnostics = source_to_project(text, "addresses")
    assert project is not None and not [d for d in diagnostics if d.severity == "error"], diagnostics
    return build_project(project.model_copy(update={"typing": typing}), variant)


def _simulation(declarations: str, body: str, variant: str = "fast"):
    result = _build(program(declarations, body), variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def _errors(declarations: str, body: str, typing: str) -> list[str]:
    result = _build(program(declarations, body), typing)
    return [f"{d.code} {d.line}:{d.column} {d.message}" for d in result.diagnostics if d.severity == "error"]


@pytest.mark.parametrize("variant", VARIANTS)
def test_an_address_as_a_number_leads_back_to_its_byte_and_bytes_are_consecutive(variant):
    sim = _simulation(
        "buf : ARRAY[0..7] OF BYTE := [10, 11, 12, 13, 14, 15, 16, 17]; d : DWORD;"
        "a0, a3, whole, dd : DWORD; l : LWORD; pt : POINTER TO BYTE; pw : POINTER TO WORD; b : BYTE; w : WORD;"
        "step, aligned, lower, nul : BOOL; pn : POINTER TO BYTE; zero : DWORD;",
        "a0 := ADR(buf[0]);\na3 := ADR(buf[3]);\nwhole := ADR(buf);\nl := ADR(buf[1]);\n"
        "pt := a3 + 2;\nb := pt^;\npw := a0 + 6;\nw := pw^;\npw^ := 16#BEEF;\n"
        "step := a3 - a0 = 3;\ndd := ADR(d);\naligned := (dd AND 3) = 0 AND (a0 AND 3) = 0;\n"
        "lower := ADR(buf[1]) < a3 AND a3 > ADR(buf[1]) AND a3 <= a3;\npn := ADR(b);\npn := zero;\nnul := pn = 0;",
        variant,
    )
    sim.cycle(1)
    assert sim.fault is None, sim.fault.text()
    assert sim.read("Main.b") == 15 and sim.read("Main.w") == 0x1110  # buf[5]; buf[6..7] little-endian
    first = sim.read("Main.a0")
    sim.cycle(1)  # the addresses stay for the simulation's life: the second scan reads what the first wrote
    assert sim.fault is None and sim.read("Main.a0") == first and sim.read("Main.w") == 0xBEEF
    assert sim.read("Main.buf")[6:] == [0xEF, 0xBE]
    assert sim.read("Main.whole") == sim.read("Main.a0") != 0  # an array's address is its first element's
    assert sim.read("Main.l") == sim.read("Main.a0") + 1
    assert (sim.read("Main.step"), sim.read("Main.aligned"), sim.read("Main.lower")) == (True, True, True)
    assert sim.read("Main.nul") and sim.read("Main.pn") == "NULL"
    assert sim.read("Main.pt") == "ADR(buf[0]) + 5"  # the online view names the variable the number lies in


#: The round trip: a pointer into a ten-byte buffer at element 2, moved by k as a pointer (q) and as a number (dw).
_ROUND_TRIP = program(
    "buf : ARRAY[0..9] OF BYTE := [100, 101, 102, 103, 104, 105, 106, 107, 108, 109]; k : DINT;"
    "pt, q, back : POINTER TO BYTE; dw : DWORD; direct, via : BYTE;",
    "pt := ADR(buf[2]);\nq := pt + k;\ndw := q;\nback := dw;\nvia := back^;\ndirect := q^;",
)


@functools.cache
def _round_trip(variant: str):
    result = _build(_ROUND_TRIP, variant=variant)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result


@settings(max_examples=40, deadline=None)
@given(k=st.integers(-12, 12), variant=st.sampled_from(VARIANTS))
def test_a_pointer_made_from_the_number_of_pt_plus_k_reaches_the_byte_pt_plus_k_does(k, variant):
    sim = _round_trip(variant).simulation()
    sim.write("Main.k", k)
    sim.cycle(1)
    if 0 <= 2 + k < 10:  # inside the buffer: the same byte either way
        assert sim.fault is None, sim.fault.text()
        assert sim.read("Main.via") == sim.read("Main.direct") == 102 + k
        assert sim.read("Main.back") == sim.read("Main.q")
    else:  # outside (one past its end included: nothing to read there) it is a located fault, never a value
        assert sim.fault is not None and sim.fault.code == "index_out_of_range"
        assert sim.fault.pou == "MAIN" and sim.fault.origin.line in (7, 10)  # q := pt + k; via := back^;
        assert sim.read("Main.via") == sim.read("Main.direct") == 0


@pytest.mark.parametrize("variant", VARIANTS)
def test_a_number_in_no_variable_is_a_located_fault_when_read_through(variant):
    sim = _simulation(
        "x : DINT := 7; dw : DWORD; p : POINTER TO DINT; y : DINT;",
        "dw := ADR(x);\np := dw + 4;\ny := p^;",  # one past x's end: x's own, nothing to read
        variant,
    )
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.origin.line) == ("index_out_of_range", 8)
    assert sim.fault.message == "the pointer ADR(x) + 4 reaches bytes 4..7 of a 4-byte variable: outside it"
    sim = _simulation(
        "x : DINT := 7; dw : DWORD := 16#40; p : POINTER TO DINT; y : DINT;", "p := dw;\ny := p^;", variant
    )
    sim.cycle(1)
    assert sim.fault is not None and (sim.fault.code, sim.fault.origin.line) == ("index_out_of_range", 7)
    assert sim.fault.message == "the pointer 16#40 reaches the address 64, which lies in no variable"
    assert sim.read("Main.y") == 0


def test_an_address_is_a_number_under_codesys_typing_only_and_in_32_bits_or_more():
    declarations = "x : DINT; pt : POINTER TO DINT; dw : DWORD; w : WORD; di : DINT; ok : BOOL;"
    assert _errors(declarations, "dw := ADR(x);\npt := dw;\nok := pt < dw;", "codesys") == []
    assert _errors(declarations, "pt := ADR(x);\ndw := pt;\nok := pt < dw;", "iec") == [
        "ST-TYPE-MISMATCH 7:7 cannot assign REF_TO DINT to DWORD",
        "ST-TYPE-MISMATCH 8:7 '<' needs operands of the same type: REF_TO DINT and DWORD; convert one of them "
        "(e.g. a *_TO_* conversion)",
    ]
    assert _errors(declarations, "pt := ADR(x);\nw := pt;\ndi := pt;", "codesys") == [
        "ST-TYPE-MISMATCH 7:6 cannot assign REF_TO DINT to WORD",
        "ST-TYPE-MISMATCH 8:7 cannot assign REF_TO DINT to DINT",
    ]


def test_a_pointer_to_what_has_no_bytes_is_no_number():
    assert _errors("t : TIME; pt : POINTER TO TIME; dw : DWORD;", "pt := ADR(t);\ndw := pt;", "codesys") == [
        "IR-UNSUPPORTED 7:1 a pointer as a number needs the bytes of what it points to: a TIME (its bytes in CODESYS "
        "are not the value LadderLab keeps)"
    ]
