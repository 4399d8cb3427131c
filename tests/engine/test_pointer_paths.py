"""ON-11: online paths through pointers and references. ``p^`` reads, writes and forces what a POINTER TO / REF_TO
points to now, ``rs^.f`` and ``ra^[3]`` step on from there, ``r.f`` reads through a CODESYS REFERENCE TO; a NULL
pointer names no variable (a clear refusal, never a Python error). Expected values are worked out by hand from
the program text."""

from __future__ import annotations

import pytest

from ladderlab.engine.inputs import InputEvent, InputRefused
from ladderlab.engine.paths import NoTarget, UnknownPath

from .test_references import simulation

DECLARATIONS = (
    "a : ARRAY [1..3] OF INT := [10, 20, 30]; s : S; i : INT := 1; p : POINTER TO INT; rs : REF_TO S;\n"
    "ra : REF_TO ARRAY [1..3] OF INT; r : REFERENCE TO S; n : REF_TO INT; run : BOOL;"
)
BODY = "IF run THEN i := i + 1; END_IF;\np := ADR(a[i]);\nrs := REF(s);\nra := REF(a);\nr REF= s;\ns.f := s.f + 1;"


def test_paths_through_pointers_read_what_the_pointer_points_to_now():
    """ON-11: ``Main.p^`` follows p from scan to scan; member and index chains go on through the target."""
    sim = simulation(DECLARATIONS, BODY)
    sim.cycle(1)
    assert sim.read("Main.p") == "ADR(a[i])"
    assert sim.read("Main.p^") == 10  # a[1]
    assert sim.read("Main.rs^") == {"F": 1, "G": [0, 0, 0]}
    assert sim.read("Main.rs^.f") == 1
    assert sim.read("Main.ra^[3]") == 30
    assert sim.read("main.RA^") == [10, 20, 30]
    assert sim.read("Main.r.f") == 1  # REFERENCE TO: read through without '^' (CODESYS)
    assert sim.read("Main.r^.f") == 1
    assert sim.location("Main.rs^.f").path == "MAIN.RS^.F"  # canonical: the IR's upper-case names
    sim.write("Main.run", True)
    for scan, element in ((2, 20), (3, 30)):
        sim.cycle(1)
        assert sim.read("Main.p^") == element, scan
        assert sim.read("Main.rs^.f") == scan


def test_writing_and_forcing_through_a_pointer_reach_its_target():
    sim = simulation(DECLARATIONS, BODY)
    sim.cycle(1)
    sim.write("Main.p^", 99)  # p points to a[1]
    sim.write("Main.rs^.g[2]", 7)
    sim.cycle(1)
    assert sim.read("Main.a") == [99, 20, 30]
    assert sim.read("Main.s.g") == [0, 7, 0]
    sim.force("Main.r.f", 500)  # the program adds 1 each scan; the force holds it before and after
    sim.cycle(2)
    assert sim.read("Main.s.f") == 500
    assert sim.forced == {"MAIN.R.F": 500}
    sim.unforce("Main.r.f")
    sim.cycle(1)
    assert sim.read("Main.s.f") == 501


def test_a_force_through_a_pointer_holds_whatever_it_points_to_scan_by_scan():
    sim = simulation(DECLARATIONS, BODY)
    sim.cycle(1)
    sim.force("Main.p^", -1)
    sim.write("Main.run", True)
    sim.cycle(1)  # i = 2: before the scan p still points to a[1], after it to a[2]
    assert sim.read("Main.a") == [-1, -1, 30]
    sim.cycle(1)
    assert sim.read("Main.a") == [-1, -1, -1]


def test_a_null_pointer_names_no_variable():
    sim = simulation(DECLARATIONS, BODY)
    sim.cycle(1)
    assert sim.read("Main.n") == "NULL"
    with pytest.raises(NoTarget, match=r"MAIN.N is NULL: MAIN.N\^ is no variable now"):
        sim.read("Main.n^")
    with pytest.raises(ValueError, match=r"MAIN\.N is NULL"):
        sim.write("Main.n^", 3)  # refused at once: nothing waits for the next scan
    assert sim.pending == []
    with pytest.raises(InputRefused, match="not through a pointer"):
        sim.submit(InputEvent("fault", "Main.p^", mode="stuck", value=1))


def test_bad_pointer_paths_are_located_refusals():
    sim = simulation(DECLARATIONS, BODY)
    with pytest.raises(ValueError, match=r"MAIN.I is an INT, not a pointer or reference: '\^' cannot follow it"):
        sim.read("Main.i^")
    with pytest.raises(UnknownPath, match="has no field 'h'"):
        sim.read("Main.rs^.h")
    with pytest.raises(ValueError, match="a reference is set by the program"):
        sim.write("Main.p", 1)
