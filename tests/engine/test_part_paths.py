"""A bit or part as a simulation path (issue 25): ``Main.v.%B1`` reads the part of v's bit pattern (an integer's
two's complement) numbered from the least significant (IEC 61131-3 ed. 3, 6.5.6), and writing it changes only that
part, an integer wrapping back to its signed value. Expected values come from the bit pattern computed here."""

from __future__ import annotations

import functools

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

#: name -> (width in bits, signed)
TYPES = {"BYTE": (8, False), "WORD": (16, False), "LWORD": (64, False), "SINT": (8, True), "INT": (16, True)}
TYPES |= {"DINT": (32, True), "UDINT": (32, False), "LINT": (64, True)}
LETTERS = {1: "X", 8: "B", 16: "W", 32: "D", 64: "L"}


@functools.cache
def simulation() -> Simulation:
    declarations = " ".join(f"v{name} : {name};" for name in TYPES)
    text = f"PROGRAM Main\nVAR {declarations} END_VAR\n;\nEND_PROGRAM\n"
    project, diagnostics = source_to_project(text, "paths")
    assert project is not None, diagnostics
    return build_project(project).simulation()


def signed(pattern: int, bits: int, is_signed: bool) -> int:
    return pattern - (1 << bits) if is_signed and pattern >> (bits - 1) else pattern


@st.composite
def cases(draw: st.DrawFn) -> tuple[str, int, int, int, int]:
    """A type, a bit pattern of it, a part (width, index) inside it and a new value for that part."""
    name = draw(st.sampled_from(sorted(TYPES)))
    bits = TYPES[name][0]
    width = draw(st.sampled_from([w for w in LETTERS if w <= bits]))
    index = draw(st.integers(0, bits // width - 1))
    return name, draw(st.integers(0, (1 << bits) - 1)), width, index, draw(st.integers(0, (1 << width) - 1))


@settings(max_examples=60, deadline=None)
@given(cases())
def test_a_part_path_reads_and_writes_the_bits_of_its_variable(case: tuple[str, int, int, int, int]) -> None:
    name, pattern, width, index, new = case
    bits, is_signed = TYPES[name]
    sim = simulation()
    sim.write(f"Main.v{name}", signed(pattern, bits, is_signed))
    sim.cycle(1)
    path = f"Main.v{name}.%{LETTERS[width]}{index}"
    part = (pattern >> (width * index)) & ((1 << width) - 1)
    assert sim.read(path) == (bool(part) if width == 1 else part)
    sim.write(path, bool(new) if width == 1 else new)
    sim.cycle(1)
    mask = ((1 << width) - 1) << (width * index)
    assert sim.read(f"Main.v{name}") == signed((pattern & ~mask) | (new << (width * index)), bits, is_signed)


@pytest.mark.parametrize(
    ("path", "message"),
    [
        ("Main.vWORD.%X16", "MAIN.VWORD.%X16 is outside MAIN.VWORD, a WORD: it has bits 0..15"),
        ("Main.vBYTE.%W0", "MAIN.VBYTE.%W0: a BYTE has no words, it is 8 bits wide"),
        ("Main.vINT.9", "MAIN.VINT.%X9"),  # the short form names the same bit
    ],
)
def test_part_paths_name_the_part_or_say_why_not(path: str, message: str) -> None:
    sim = simulation()
    try:
        found = sim.location(path).path
    except ValueError as error:
        found = str(error)
    assert found == message


def test_a_part_of_a_real_is_no_path() -> None:
    text = "PROGRAM Main\nVAR r : REAL; END_VAR\n;\nEND_PROGRAM\n"
    project, _ = source_to_project(text, "paths")
    assert project is not None
    sim = build_project(project).simulation()
    with pytest.raises(ValueError, match=r"^MAIN.R is a REAL: it has no bit or part '%X0'$"):
        sim.location("Main.r.%X0")


def test_a_part_of_a_located_variable_reads_and_writes_the_process_image() -> None:
    """An input word's bit written online reaches the program (the image's world side); a forced bit holds."""
    text = (
        "PROGRAM Main\nVAR inw AT %IW0 : WORD; outb AT %QB0 : BYTE; lamp : BOOL; END_VAR\n"
        "lamp := inw.%X3;\noutb.%X1 := lamp;\nEND_PROGRAM\n"
    )
    project, diagnostics = source_to_project(text, "paths")
    assert project is not None, diagnostics
    sim = build_project(project).simulation()
    sim.write("Main.inw.%X3", True)
    sim.cycle(1)
    assert [sim.read("Main.inw"), sim.read("Main.lamp"), sim.read("Main.outb"), sim.read("Main.outb.1")] == [
        0b1000,
        True,
        0b10,
        True,
    ]
    sim.force("Main.inw.%X0", True)
    sim.cycle(1)
    assert sim.read("Main.inw") == 0b1001
    with pytest.raises(ValueError, match=r"^MAIN.INW is a WORD in the process image: it has no members$"):
        sim.location("Main.inw.x")
