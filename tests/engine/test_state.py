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
