"""The process image (issue 16; IEC 61131-3 2.4.1.1, VAR-70..76, ST-12..15): direct addresses with or without a
declared name, one byte-addressed memory per area with overlaps (little endian), inputs read at the start of a
scan and outputs published at its end, forcing, the seeds' Mosaic forms and default types.

Expected values follow from the byte layout (``struct``, ``int.to_bytes``) and the seeds' examples.
"""

from __future__ import annotations

import struct

import pytest

from ladderlab.engine.paths import UnknownPath
from ladderlab.iec.addresses import parse_address
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def simulation(text: str, variant: str = "fast"):
    project, diagnostics = source_to_project(text, "io")
    assert project is not None, diagnostics
    build = build_project(project, variant)
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    return build.simulation()


def errors(text: str) -> list[str]:
    project, _ = source_to_project(text, "io")
    return [d.format() for d in build_project(project).diagnostics if d.severity == "error"]


@pytest.mark.parametrize(
    "text, area, offset, bit, default",
    [
        ("%IX0.1", "I", 0, 1, "BOOL"),
        ("%I1.2", "I", 1, 10, "BOOL"),  # no size: a bit (ST-13)
        ("%IX5", "I", 0, 5, "BOOL"),  # one number: bit 5 (Concept's %IX5, ST-26)
        ("%QB7", "Q", 7, None, "BYTE"),
        ("%IW2", "I", 2, None, "INT"),  # S002 Table 10.1
        ("%MD48", "M", 48, None, "REAL"),  # the seeds' default (CODESYS would say DWORD: ST-15)
        ("%ML8", "M", 8, None, "LWORD"),
        ("%X0.0", "I", 0, 0, "BOOL"),  # Mosaic input bit (VAR-71)
        ("%Y2.0", "Q", 2, 16, "BOOL"),
        ("%YW10", "Q", 10, None, "INT"),
        ("%XF10", "I", 10, None, "REAL"),
        ("%R122", "M", 122, None, "BYTE"),  # the same byte as %MB122 (VAR-72)
        ("%RW152.9", "M", 153, 152 * 8 + 9, "BOOL"),  # bit 9 of the word at 152, little endian
        ("%S6", "S", 6, None, "BYTE"),
    ],
)
def test_addresses_and_their_default_types(text, area, offset, bit, default):
    address = parse_address(text)
    assert (address.area, address.offset, address.bit, address.default_type) == (area, offset, bit, default)


OVERLAPS = """
PROGRAM Main
VAR w AT %MW0 : INT; b1 AT %MB1 : BYTE; x AT %MX1.7 : BOOL; d AT %MD4 : REAL; u AT %MD4 : UDINT; END_VAR
VAR step : INT; END_VAR
CASE step OF
  0: w := 16#0102;
  1: x := TRUE;
  2: d := 1.5;
END_CASE;
step := step + 1;
END_PROGRAM
"""


def test_one_memory_per_area_overlapping_little_endian():
    sim = simulation(OVERLAPS)
    sim.cycle(1)
    assert (sim.read("Main.w"), sim.read("Main.b1"), sim.read("%MB0"), sim.read("%MX0.1"), sim.read("%MX1.0")) == (
        0x0102,
        0x01,
        0x02,
        True,
        True,
    )
    sim.cycle(1)  # %MX1.7 is the top bit of %MB1, so of %MW0: INT 0x8102 is negative
    assert (sim.read("Main.b1"), sim.read("Main.w")) == (0x81, 0x8102 - 0x10000)
    sim.cycle(1)  # 1.5 as binary32, read back as an unsigned double word
    assert sim.read("Main.u") == struct.unpack("<I", struct.pack("<f", 1.5))[0]
    assert sim.read("%MD4") == 1.5  # the default type of D is REAL


IMAGE = """
VAR_GLOBAL start AT %IX0.0 : BOOL; END_VAR
PROGRAM Main
VAR lamp AT %QX3.0 : BOOL; seen, before, after : BOOL; level : INT; END_VAR
before := %IX0.1;
seen := start;
after := %IX0.1;
%QX3.1 := %IX0.1;
lamp := start;
level := %IW2 * 2;
%QW4 := level;
END_PROGRAM
"""


def test_unnamed_addresses_read_and_write_and_the_cli_paths_reach_them():
    sim = simulation(IMAGE)
    sim.write("%IX0.1", True)
    sim.write("start", True)
    sim.write("%IW2", 21)
    sim.cycle(1)
    assert (sim.read("%QX3.1"), sim.read("Main.lamp"), sim.read("%QX3.0"), sim.read("%QW4")) == (True, True, True, 42)
    with pytest.raises(UnknownPath, match=r"%IX9.0 is outside the process image: the program uses 4 byte\(s\) of %I"):
        sim.read("%IX9.0")


def test_inputs_are_read_at_the_start_of_a_scan_and_outputs_published_at_its_end():
    sim = simulation(IMAGE, "debug")
    sim.set_breakpoint("Main", line=6)  # after 'before := %IX0.1', before 'after := %IX0.1'
    sim.cycle(1)
    assert sim.halted is not None
    sim.write("%IX0.1", True)  # while halted a write acts at once, as on any variable (the watch list, ON-07)
    assert sim.read("%IX0.1") is True
    sim.resume()
    assert (sim.read("Main.before"), sim.read("Main.after"), sim.read("%QX3.1")) == (False, True, True)
    assert sim.published("%QX3.1") is True  # the end of the scan published the output image
    sim.clear_breakpoints()
    sim.set_breakpoint("Main", line=10)  # 'level := ...': %QX3.1 was written this scan, not yet published
    sim.write("%IX0.1", False)
    sim.cycle(1)
    assert sim.halted is not None
    assert (sim.read("%QX3.1"), sim.published("%QX3.1")) == (False, True)  # the world still sees the last scan
    sim.resume()
    assert sim.published("%QX3.1") is False
    with pytest.raises(ValueError, match=r"%IX0\.1 is not an output"):
        sim.published("%IX0.1")


def test_the_program_writing_an_input_lasts_until_the_next_scan_reads_the_inputs():
    sim = simulation(
        "PROGRAM Main\nVAR a, b : BOOL; END_VAR\na := %IX0.0;\n%IX0.0 := TRUE;\nb := %IX0.0;\nEND_PROGRAM\n"
    )
    for _ in range(2):
        sim.cycle(1)
        assert (sim.read("Main.a"), sim.read("Main.b")) == (False, True)
    sim.write("%IX0.0", True)
    sim.cycle(1)
    assert (sim.read("Main.a"), sim.read("Main.b")) == (True, True)


def test_forced_inputs_reach_the_program_and_forced_outputs_are_published():
    sim = simulation(IMAGE)
    sim.force("%IX0.1", True)
    sim.force("%QX3.1", False)  # the program writes TRUE into it every scan
    sim.cycle(2)
    assert (sim.read("Main.after"), sim.read("%QX3.1")) == (True, False)
    sim.unforce_all()
    sim.cycle(1)
    assert sim.read("%QX3.1") is True  # the program's output again; the input keeps the value it was forced to


EX_3_21 = """
VAR_GLOBAL
  SymbolicVar AT %MB120 : USINT;
               AT %MB121 : USINT;
               AT %R122 : USINT := 242;
  counterOut AT %Y0.0 : BOOL;
END_VAR

PROGRAM ExampleDirectVar
  VAR_EXTERNAL
    AT %S6 : USINT;
    AT %X0.0, AT %X0.1 : BOOL;
  END_VAR
  VAR
    counter : CTU;
  END_VAR

  SymbolicVar := %MB121 + %R122;
  counter(CU := %X0.0, R := %X0.1, PV := 100, Q => counterOut);
END_PROGRAM
"""


def test_seed_example_3_21_addresses_in_declarations():
    """Seed 000 EX-24 (Ex 3.21): 0 + 242 = 242; %MB121 forced to 10: 252, to 20: 262 wraps to 6 (USINT)."""
    sim = simulation(EX_3_21)
    sim.cycle(1)
    assert (sim.read("SymbolicVar"), sim.read("%MB122")) == (242, 242)  # %R122 is %MB122 (VAR-72)
    sim.force("%MB121", 10)
    sim.cycle(1)
    assert sim.read("SymbolicVar") == 252
    sim.force("%MB121", 20)
    sim.cycle(1)
    assert sim.read("SymbolicVar") == 6
    for scan in range(200):  # 100 rising edges on %X0.0 (Mosaic input bit 0.0)
        sim.write("%X0.0", scan % 2 == 0)
        sim.cycle(1)
    assert sim.read("counterOut") is True and sim.read("%Y0.0") is True
    sim.write("%X0.1", True)
    sim.cycle(1)
    assert sim.read("counterOut") is False


def test_a_restart_clears_the_images_and_keeps_the_inputs_the_world_set():
    sim = simulation(EX_3_21)
    sim.write("%X0.1", True)
    sim.force("%MB121", 3)
    sim.cycle(1)
    assert sim.read("SymbolicVar") == 245
    sim.unforce_all()
    sim.reset(cold=True)
    assert (sim.read("SymbolicVar"), sim.read("%R122"), sim.read("%MB121"), sim.read("%X0.1")) == (0, 242, 0, True)


@pytest.mark.parametrize(
    "declaration, message",
    [
        ("x AT %IW0 : DINT;", "error ST-ADDRESS: %IW0 has 16 bits: a DINT has 32"),
        ("x AT %IX0.8 : BOOL;", "error ST-ADDRESS: %IX0.8: a byte has bits 0..7, not 8"),
        ("x AT %IX0.1 : INT;", "error ST-ADDRESS: %IX0.1 is a bit: only a BOOL can be located there"),
        ("x AT %MB0 : STRING;", "error ST-ADDRESS: a STRING cannot be located at %MB0: only elementary types other"),
    ],
)
def test_a_bad_address_or_type_is_located(declaration, message):
    found = errors(f"PROGRAM Main\nVAR {declaration} END_VAR\nEND_PROGRAM\n")
    assert len(found) == 1 and found[0].startswith("Main/declarations:2:") and message in found[0], found


def test_a_function_cannot_locate_a_variable():
    found = errors("FUNCTION F : INT\nVAR x AT %MW0 : INT; END_VAR\nF := x;\nEND_FUNCTION\n")
    assert found == [
        "F/declarations:2:5, POU F: error ST-DECL: a function has no memory of its own: it cannot locate a "
        "variable AT an address"
    ]


def test_retain_on_a_located_variable_is_a_warning_and_a_warm_restart_clears_it():
    text = "PROGRAM Main\nVAR RETAIN\n  k AT %MW0 : INT;\nEND_VAR\nk := k + 1;\nEND_PROGRAM\n"
    project, _ = source_to_project(text, "io")
    build = build_project(project)
    assert [d.format() for d in build.diagnostics] == [
        "Main/declarations:3:3, POU Main: warning ST-ADDRESS: RETAIN has no effect on a variable at %MW0: the "
        "process image is cleared on a restart"
    ]
    sim = build.simulation()
    sim.cycle(3)
    sim.reset(cold=False)
    assert sim.read("Main.k") == 0
