"""The scan loop's lean path (issue 27): one cyclic task and nothing else to schedule runs ``cycle`` without the
general scheduling steps. It must behave exactly as the general path (``run_for`` takes that one), skip the
watchdog's CPU clock when the program has no loop, and sample the scan times."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import SAMPLE_EVERY

from ..support import fuzz_settings
from .test_simulation_st import simulation

COUNTER = """
PROGRAM Main
VAR n : INT; limit : INT := 1000; lamp : BOOL; t : TON; fired : BOOL; END_VAR
n := n + 1;
IF n > limit THEN n := 0; END_IF;
lamp := n MOD 3 = 0;
t(IN := lamp, PT := T#20ms);
fired := t.Q;
END_PROGRAM
"""

LOOPING = """
PROGRAM Main
VAR i, s : INT; END_VAR
s := 0;
FOR i := 1 TO 3 DO s := s + i; END_FOR;
END_PROGRAM
"""


class _Readings:
    """A clock that counts its readings and advances 1 ms per reading."""

    def __init__(self) -> None:
        self.readings = 0

    def __call__(self) -> float:
        self.readings += 1
        return self.readings / 1000.0


def test_a_program_without_loops_never_reads_the_watchdog_clock():
    clock = _Readings()
    sim = simulation(COUNTER, watchdog_clock=clock)
    assert not sim.compiled.watched
    sim.cycle(50)
    assert clock.readings == 0 and sim.read("MAIN.N") == 50


def test_a_program_with_a_loop_arms_the_watchdog_every_scan():
    clock = _Readings()
    sim = simulation(LOOPING, watchdog_clock=clock)
    assert sim.compiled.watched
    sim.cycle(5)
    assert clock.readings == 5 and sim.read("MAIN.S") == 6  # 1 + 2 + 3


def test_scan_times_are_sampled_every_sixteenth_scan_and_every_scan_is_counted():
    wall = _Readings()  # each sampled scan reads it twice: 1 ms apart
    sim = simulation(COUNTER, wall_clock=wall)
    sim.cycle(40)
    assert sim.stats.count == 40 and sim.scan_count == 40
    assert sim.stats.samples == 3 and wall.readings == 6  # scans 0, 16 and 32
    assert sim.stats.min_ms == sim.stats.max_ms == sim.stats.avg_ms == 1.0
    assert SAMPLE_EVERY == 16


_steps = st.lists(
    st.one_of(
        st.tuples(st.just("cycle"), st.integers(1, 7)),
        st.tuples(st.just("write"), st.integers(-5, 1200)),
        st.tuples(st.just("force"), st.booleans()),
        st.tuples(st.just("release"), st.none()),
        st.tuples(st.just("reset"), st.booleans()),
    ),
    max_size=12,
)


@fuzz_settings(fast=30)
@given(_steps)
def test_cycle_on_the_lean_path_equals_run_for_on_the_general_path(steps):
    """``cycle(k)`` (lean: one task) and ``run_for(k * 10 ms)`` (the general scheduling) give the same values,
    forces and scan history, whatever inputs come between the scans."""
    lean, general = simulation(COUNTER), simulation(COUNTER)
    assert lean._lone is not None
    heard: dict[str, list] = {"lean": [], "general": []}
    lean.on_scan = lambda n, t, scheduled: heard["lean"].append((n, t, scheduled))
    general.on_scan = lambda n, t, scheduled: heard["general"].append((n, t, scheduled))
    for kind, value in steps:
        if kind == "cycle":
            assert lean.cycle(value) == value
            assert general.run_for(value * 10.0) == value
        elif kind == "write":
            for sim in (lean, general):
                sim.write("MAIN.N", value)
        elif kind == "force":
            for sim in (lean, general):
                sim.force("MAIN.LAMP", value)
        elif kind == "release":
            for sim in (lean, general):
                sim.unforce("MAIN.LAMP")
        else:
            for sim in (lean, general):
                sim.reset(cold=value)
        assert lean.snapshot() == general.snapshot()
        assert lean.time_ms == general.time_ms and lean.scan_count == general.scan_count
        assert lean.forced == general.forced
    lean.cycle(1)
    general.run_for(10.0)
    assert lean.snapshot() == general.snapshot()
    assert heard["lean"] == heard["general"]
    assert lean.stats.count == general.stats.count == lean.scan_count
