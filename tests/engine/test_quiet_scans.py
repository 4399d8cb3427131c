"""Scans no frame shows record no network (issue 27 item 2): the scans a frame shows are exact, the others unknown.

A server's runner runs scans in batches between two frames and records the viewed networks' power flow only on
the scans a frame may show (``Simulation.record``; docs/runtime.md, "Scans no frame shows"). The reference is
the debug variant of the same program, which records every probe of every scan: after any recorded scan the
monitor variant shows what it shows, whatever ran quietly before; after a quiet scan every viewed network is
``unknown`` (never the stale value of an earlier scan), also across a view change, a switch to the debug variant
and back, a captured state restored elsewhere, and a reset.
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.engine.tasks import Schedule, Task
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project
from tests.engine.test_fast_equals_debug import BOOLS, ld_programs
from tests.engine.test_viewed_networks import _networks, _pair, _shown
from tests.support import fuzz_settings

_writes = st.lists(st.tuples(st.sampled_from(BOOLS), st.booleans()), max_size=3)
#: (scans in the batch, the last one recorded or not, networks viewed from then on, writes before the batch)
_batches = st.lists(
    st.tuples(st.integers(1, 6), st.booleans(), st.lists(st.integers(0, 7), max_size=3), _writes),
    min_size=1,
    max_size=6,
)


def _viewed_ids(networks: dict[int, list[str]], view: list[int]) -> list[str]:
    return [e for n in sorted({n % len(networks) for n in view}) for e in networks[n]]


def _assert_unknown(sim: Simulation, ids: list[str]) -> None:
    view = sim.probes("Main", ids)
    assert view.unknown == set(ids), "a quiet scan's networks are unknown, never stale"


@fuzz_settings(fast=25)
@given(project=ld_programs(), batches=_batches, chunk_small=st.booleans())
def test_a_recorded_scan_after_quiet_ones_shows_what_the_debug_variant_shows(project, batches, chunk_small):
    live, reference = _pair(project, 3 if chunk_small else 1500)
    networks = _networks(live)
    every = [e for ids in networks.values() for e in ids]
    for number, (scans, record_last, view, writes) in enumerate(batches):
        ids = _viewed_ids(networks, view)
        live.view({"Main": ids})
        for name, value in writes:
            live.write(f"Main.{name}", value)
            reference.write(f"Main.{name}", value)
        live.record(False)
        assert live.cycle(scans - 1) == reference.cycle(scans - 1) == scans - 1
        live.record(record_last)
        assert live.cycle(1) == reference.cycle(1) == 1
        live.record(True)
        assert live.snapshot() == reference.snapshot(), f"batch {number}"
        if record_last:
            assert not live.quiet
            assert _shown(live, ids) == _shown(reference, ids), f"batch {number}"
        else:
            assert live.quiet
            _assert_unknown(live, every)
    # the next recorded scan shows every viewed network exactly, whatever ran before
    live.view({"Main": every})
    live.cycle(1)
    reference.cycle(1)
    assert _shown(live, every) == _shown(reference, every)


@fuzz_settings(fast=15)
@given(project=ld_programs(), scans=st.integers(1, 4), writes=_writes)
def test_after_a_quiet_scan_views_variants_states_and_resets_show_no_stale_power_flow(project, scans, writes):
    live, reference = _pair(project, 3)
    networks = _networks(live)
    every = [e for ids in networks.values() for e in ids]
    live.view({"Main": every})
    live.cycle(1)
    reference.cycle(1)
    for name, value in writes:
        live.write(f"Main.{name}", value)
        reference.write(f"Main.{name}", value)
    live.record(False)
    live.cycle(scans)
    reference.cycle(scans)
    _assert_unknown(live, every)
    live.view({"Main": every[:1]})  # a view change after it: still unknown (the flags are the real ones again)
    _assert_unknown(live, every[:1])
    # a state captured after a quiet scan says it recorded no network, in a simulation it is restored into
    other = Simulation(live.compiled.own_code())
    other.view({"Main": every})
    other.restore(live.state())
    _assert_unknown(other, every)
    other.cycle(1)  # records: the quiet mode belongs to the simulation that set it
    assert not other.quiet
    assert other.probes("Main", every).unknown == frozenset()
    monitor = live.compiled
    live.use_variant("debug", reference.compiled)  # it records every probe, but not of the quiet scan before
    _assert_unknown(live, every)
    live.use_variant("monitor", monitor)
    _assert_unknown(live, every)
    live.reset()  # a restart runs no scan: no element ran since (nothing unknown, nothing stale)
    reference.reset()
    assert live.probes("Main", every).executed == frozenset()
    shown = reference.probes("Main", every)
    assert (shown.executed, shown.unknown) == (frozenset(), frozenset())
    live.record(True)
    live.view({"Main": every})
    live.cycle(1)
    reference.cycle(1)
    assert _shown(live, every) == _shown(reference, every)
    live.record(False)  # quiet scans in the debug variant record all the same
    live.use_variant("debug", reference.compiled)
    live.cycle(1)
    reference.cycle(1)
    assert not live.quiet
    assert _shown(live, every) == _shown(reference, every)


def test_quiet_scans_run_the_twins_without_probes_and_leave_the_flags_as_viewed():
    """A quiet scan runs the chunk functions without probes (``ll_kf``), the view flags stay as ``view`` set them,
    and a recording scan after it records again."""
    networks = [
        ld.LdNetwork(id=f"n{i}", elements=[ld.Contact(id=f"a{i}", var="B0"), ld.Coil(id=f"c{i}", var="B1")])
        for i in range(12)
    ]
    pou = Pou(
        name="Main",
        kind="program",
        language="ld",
        declarations="VAR B0 : BOOL := TRUE; B1 : BOOL; END_VAR",
        body=ld.LdBody(networks=networks),
    )
    live, _reference = _pair(Project(name="p", pous=[pou]), 3)
    assert "ll_kf" in live.compiled.source
    live.view({"Main": ["a3", "c3"]})
    obj = live._instances_by_path()["MAIN"][0]
    flags = list(obj.ll_v)
    live.record(False)
    live.cycle(2)
    assert obj.ll_v == [False] * len(flags)  # silenced while quiet
    assert live.probes("Main", ["a3", "c3"]).unknown == {"a3", "c3"}
    live.record(True)
    live.cycle(1)
    assert obj.ll_v == flags
    view = live.probes("Main", ["a3", "c3"])
    assert view.unknown == frozenset()
    assert view.values == {"a3": True, "c3": True}
    assert view.executed == {"a3", "c3"}


@fuzz_settings(fast=50)
@given(
    intervals=st.lists(st.sampled_from([None, 1.0, 2.5, 10.0, 20.0, 30.0]), min_size=1, max_size=4),
    plant=st.booleans(),
    scans=st.integers(0, 30),
)
def test_the_scan_after_the_next_one_is_due_when_the_schedule_says(intervals, plant, scans):
    """``Schedule.following_time`` (what the runner's choice looks ahead to) is ``next_time`` once ``advance`` ran,
    for cyclic tasks, SINGLE tasks (the idle scans every 10 ms) and a plant task, at any point of the schedule."""
    tasks = [
        Task(f"T{i}", interval, 0, [], i, next_due=interval or 0.0, single=None if interval else "G.S")
        for i, interval in enumerate(intervals)
    ]
    if plant:
        tasks.append(Task("PLANTS", 5.0, 0, [], len(tasks), next_due=5.0, plant=True))
    schedule = Schedule(tasks)
    for _ in range(scans):
        schedule.advance()
    following = schedule.following_time()
    schedule.advance()
    assert following == schedule.next_time()


def test_a_recorded_scan_that_faults_after_a_quiet_one_shows_its_own_power_flow():
    """The elements after a fault in the failing network did not run (tests/engine/test_fault_stops_probes.py), so
    no value an earlier scan left shows: a recorded scan that faults right after a quiet one is exact, as recording
    every scan shows (before it, they counted as run and such a scan had to count as quiet)."""
    divide = ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "Z"})
    network = ld.LdNetwork(id="n1", elements=[ld.Contact(id="s", var="START"), divide, ld.Coil(id="o", var="Q")])
    declarations = "VAR START, Q : BOOL; X : INT := 7; Y : INT; Z : INT; END_VAR"
    body = ld.LdBody(networks=[network])
    project = Project(
        name="p", pous=[Pou(name="Main", kind="program", language="ld", declarations=declarations, body=body)]
    )
    for quiet_before in (False, True):
        live, reference = _pair(project)
        live.view({"Main": ["s", "d", "o"]})
        live.cycle(1)
        live.record(not quiet_before)
        live.cycle(1)
        live.record(True)
        reference.cycle(2)
        for sim in (live, reference):
            sim.write("Main.START", True)
            sim.cycle(1)
            assert sim.fault is not None and "division by zero" in sim.fault.message
        assert not live.quiet
        assert _shown(live, ["s", "d", "o"]) == _shown(reference, ["s", "d", "o"]) == {"s": True, "d": None, "o": None}


@fuzz_settings(fast=15)
@given(project=ld_programs(), scans=st.integers(1, 3), cold=st.booleans())
def test_after_a_reset_no_element_shows_the_power_flow_of_the_scan_before_it(project, scans, cold):
    """A restart sets the initial values and runs no scan: the power flow of the last scan before it would be
    shown beside values it was not computed from (a lit coil whose variable is FALSE again), so until the next scan
    no element ran, in the monitor variant and in the debug variant alike; the next scan is shown exactly."""
    live, reference = _pair(project, 3)
    every = [e for ids in _networks(live).values() for e in ids]
    live.view({"Main": every})
    live.cycle(scans)
    reference.cycle(scans)
    for sim in (live, reference):
        sim.reset(cold=cold)
        view = sim.probes("Main", every)
        assert (view.executed, view.unknown) == (frozenset(), frozenset()), "no element ran since the restart"
    live.cycle(1)
    reference.cycle(1)
    assert _shown(live, every) == _shown(reference, every)
    assert live.probes("Main", every).executed, "the scan after the restart ran its networks"
