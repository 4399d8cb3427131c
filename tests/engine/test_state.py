"""Simulation state capture and restore (engine/state.py): a state restored into a fresh simulation of the
same program continues exactly as the original does - variables, FB instances (timers, counters), edge
memories, probes, clock, forces (issue 20: opening a failed test's state online; a later scan history)."""

from __future__ import annotations

import pickle

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import load_project_path
from tests.support import EXAMPLES

MOTOR = build_project(load_project_path(EXAMPLES / "motor"), "monitor").compiled


def _inputs(sim, step: int, pattern: list[tuple[bool, bool, bool]]) -> None:
    start, stop, reset = pattern[step % len(pattern)]
    sim.write("Start", start)
    sim.write("Stop", stop)
    sim.write("ResetCount", reset)


@given(
    pattern=st.lists(st.tuples(st.booleans(), st.booleans(), st.booleans()), min_size=1, max_size=8),
    before=st.integers(0, 700),
    after=st.integers(1, 300),
)
def test_a_restored_state_continues_like_the_original(pattern, before, after):
    original = Simulation(MOTOR)
    for step in range(before):
        _inputs(original, step, pattern)
        original.cycle(1)
    original.force("Speed", 7)
    state = pickle.loads(pickle.dumps(original.state()))  # plain data: it crosses processes
    copy = Simulation(MOTOR)
    copy.cycle(3)  # whatever it did before is replaced
    copy.restore(state)
    assert copy.snapshot() == original.snapshot()
    assert (copy.time_ms, copy.scan_count, copy.forced) == (original.time_ms, original.scan_count, original.forced)
    for instance in ("MAIN", "MAIN.BLINK", "SCALING"):  # the power flow of the last scan, as the online view shows it
        assert copy.probes(instance) == original.probes(instance)
    for step in range(before, before + after):
        for sim in (original, copy):
            _inputs(sim, step, pattern)
            sim.cycle(1)
    assert copy.snapshot() == original.snapshot()
    for instance in ("MAIN", "MAIN.BLINK", "SCALING"):
        assert copy.probes(instance) == original.probes(instance)


def test_attached_instances_come_back_and_other_programs_are_refused():
    project, _ = source_to_project(
        "FUNCTION_BLOCK Acc\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT sum : INT; END_VAR\nsum := sum + x;\n"
        "END_FUNCTION_BLOCK\nPROGRAM Main\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"
    )
    compiled = build_project(project).compiled
    sim = Simulation(compiled)
    acc = sim.attach("PROBE", "Acc")
    acc.v_X = 5
    acc.execute(0)
    acc.execute(0)
    sim.cycle(2)
    other = Simulation(compiled)
    other.restore(sim.state())
    assert other.read("PROBE.SUM") == 10 and other.read("MAIN.N") == 2
    with pytest.raises(ValueError, match="captured from another program"):
        Simulation(MOTOR).restore(sim.state())


SHAPES = build_project(
    source_to_project(
        "TYPE Pair : STRUCT a : INT; b : BOOL; END_STRUCT; END_TYPE\n"
        "FUNCTION_BLOCK Hold\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT total : INT; END_VAR\n"
        "VAR buf : ARRAY [0..3] OF INT; i : INT; pair : Pair; END_VAR\n"
        "buf[i] := x; i := (i + 1) MOD 4; total := buf[0] + buf[1] + buf[2] + buf[3]; pair.a := total;\n"
        "END_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR n : INT; pairs : ARRAY [1..3] OF Pair; h : Hold; hs : ARRAY [1..2] OF Hold;\n"
        "r : REF_TO INT; target : INT; x : LREAL; text : STRING; END_VAR\n"
        "n := n + 1; pairs[n MOD 3 + 1].a := n; pairs[n MOD 3 + 1].b := NOT pairs[n MOD 3 + 1].b;\n"
        "h(x := n); hs[n MOD 2 + 1](x := h.total); x := x + 0.5; text := CONCAT(text, 'x');\n"
        "IF n MOD 7 = 3 THEN r := REF(target); ELSIF n MOD 7 = 5 THEN r := NULL; END_IF;\n"
        "IF r <> NULL THEN r^ := r^ + n; END_IF;\n"
        "END_PROGRAM\n"
    )[0]
).compiled


@given(before=st.integers(0, 40), after=st.integers(1, 20), other=st.integers(0, 40))
def test_states_of_every_shape_restore_exactly_and_alike(before, after, other):
    """Slots of every shape (scalars, strings, LREAL, arrays of structures, FB instances nested in arrays, a REF_TO
    that is NULL, then a reference, then NULL again) capture and restore exactly; the per-class plans
    (engine/state.py) learn a slot that changes from a scalar to a reference. A state holding a reference starts it
    as declared in any target (NULL), whatever the target ran before, so replays from it agree."""
    original = Simulation(SHAPES)
    original.cycle(before)
    state = pickle.loads(pickle.dumps(original.state()))
    copies = [Simulation(SHAPES), Simulation(SHAPES)]
    copies[1].cycle(other)  # a target that ran elsewhere (its reference set or not)
    for copy in copies:
        copy.restore(state)
        assert copy.snapshot() == {**original.snapshot(), "MAIN.R": "NULL"}
        copy.cycle(after)
    assert copies[0].snapshot() == copies[1].snapshot()
    if original.read("MAIN.R") == "NULL":  # nothing left out: the copies continue exactly as the original
        original.cycle(after)
        assert copies[0].snapshot() == original.snapshot()
