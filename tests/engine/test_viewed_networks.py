"""Monitoring records only the networks a client views (issue 27): what a monitor frame shows is exact.

The monitor variant stores a network's probes only while ``ll_v[n]`` says a client views it
(``Simulation.view``, docs/runtime.md "Viewed networks"). The reference here is the debug variant of the same
program, which records every probe in every scan and shares no code with the monitor variant; both run the same random LD programs under
the same random writes while the views change between scans:

* engine (also with chunks small enough that each has its twin without probes, run while none of its networks
  is viewed): every element of a network viewed since before the last scan shows what the reference shows (value,
  executed or not); the elements of a network viewed only since then are ``unknown``, never a stale value;
* runner: the power flow a client holds after each frame (full frames replaced, the others applied as changes)
  equals the reference's at that frame's scan, every watched element included, also the networks a client
  scrolled to while the simulation was stopped (read from the history's replay of that scan), after a seek to
  a past scan (whose replay records only the viewed networks), other networks viewed while it is shown, and back.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.codegen import chunks
from ladderlab.engine.simulation import Simulation
from ladderlab.simulation.build import build_project
from ladderlab.simulation.runner import SimRunner
from tests.engine.test_fast_equals_debug import BOOLS, ld_programs
from tests.support import fuzz_settings

_writes = st.lists(st.tuples(st.sampled_from(BOOLS), st.booleans()), max_size=3)
_views = st.lists(st.integers(0, 7), max_size=4)  # network numbers (modulo the program's) viewed from then on


def _networks(sim: Simulation) -> dict[int, list[str]]:
    """Element ids by network number, as the monitor code numbers the networks of MAIN."""
    table = sim.compiled.generated.context.probes_of("MAIN")
    by_network: dict[int, list[str]] = {}
    for index, element in enumerate(table.elements):
        by_network.setdefault(table.network_of[index], []).append(element)
    return by_network


def _shown(sim: Simulation, ids: list[str]) -> dict[str, object]:
    """What a frame shows of each element: its value when it ran in the last scan, else None (not executed)."""
    view = sim.probes("Main", ids)
    return {e: view.values.get(e) if e in view.executed else None for e in ids if e not in view.unknown}


def _pair(project, chunk_statements: int = chunks.CHUNK_STATEMENTS) -> tuple[Simulation, Simulation]:
    """A simulation of the monitor variant and the reference: the debug variant, which records every probe."""
    with pytest.MonkeyPatch.context() as patch:  # small chunks: each has its twin without probes (codegen/pou.py)
        patch.setattr(chunks, "CHUNK_STATEMENTS", chunk_statements)
        builds = [build_project(project, variant) for variant in ("monitor", "debug")]
        assert all(build.compiled is not None for build in builds), [d.message for d in builds[0].diagnostics]
    return builds[0].simulation(), builds[1].simulation()


@pytest.mark.parametrize("chunk_statements", [3, chunks.CHUNK_STATEMENTS])
@fuzz_settings(fast=25)
@given(project=ld_programs(), steps=st.lists(st.tuples(_views, _writes), min_size=1, max_size=8))
def test_viewed_networks_show_what_recording_every_network_shows(chunk_statements, project, steps):
    viewed_sim, reference = _pair(project, chunk_statements)
    networks = _networks(viewed_sim)
    viewed: set[int] = set()
    for scan, (view, writes) in enumerate(steps):
        before = set(viewed)
        viewed = {n % len(networks) for n in view}
        viewed_sim.view({"Main": [e for n in sorted(viewed) for e in networks[n]]})
        if scan:  # between scans: the networks viewed before the last scan are known, the new ones not yet
            for n in viewed:
                ids = networks[n]
                if n in before:
                    assert _shown(viewed_sim, ids) == _shown(reference, ids), f"network {n} before scan {scan}"
                else:
                    assert viewed_sim.probes("Main", ids).unknown == set(ids)
        for name, value in writes:
            for sim in (viewed_sim, reference):
                sim.write(f"Main.{name}", value)
        assert viewed_sim.cycle(1) == reference.cycle(1) == 1
        assert viewed_sim.snapshot() == reference.snapshot(), f"scan {scan}"
        for n in viewed:
            ids = networks[n]
            assert _shown(viewed_sim, ids) == _shown(reference, ids), f"network {n}, scan {scan}"
        unviewed = [e for n in networks if n not in viewed for e in networks[n]]
        assert viewed_sim.probes("Main", unviewed).unknown == set(unviewed)


class _Frames:
    """A runner's sink keeping the power flow a client would hold."""

    def __init__(self) -> None:
        self.power: dict[str, dict[str, object]] = {}
        self.scan = 0

    def status(self, state, at, stack) -> None: ...

    def log(self, entry) -> None: ...

    def frame(self, frame) -> None:
        self.scan = frame["scan"]
        for instance, states in frame["power"].items():
            if frame["full"]:
                self.power[instance] = dict(states)
            else:
                self.power.setdefault(instance, {}).update(states)


@fuzz_settings(fast=20)
@given(
    project=ld_programs(),
    steps=st.lists(st.tuples(_views, _writes, st.integers(0, 2)), min_size=1, max_size=8),
    seek=st.integers(0, 20),
    later=st.lists(st.integers(0, 7), min_size=1, max_size=4),
)
def test_frames_show_the_power_flow_of_every_watched_element_exactly(project, steps, seek, later):
    live, reference = _pair(project, 3)
    networks = _networks(live)
    frames = _Frames()
    runner = SimRunner(live, frames, history_bytes=1 << 24)
    shown: dict[int, dict[str, object]] = {}  # scan -> the reference's states of every element
    every = [e for ids in networks.values() for e in ids]
    for number, (view, writes, scans) in enumerate(steps):
        ids = [e for n in sorted({n % len(networks) for n in view}) for e in networks[n]]
        runner.watch("client", [], [("Main", ids)])
        runner._settle(publish=True)  # the frame a subscription answers with
        assert frames.power.get("MAIN", {}) == _shown(reference, ids) if reference.scan_count else True, number
        for name, value in writes:
            runner.write(f"Main.{name}", value)
            reference.write(f"Main.{name}", value)
        for _ in range(scans):
            runner.single_cycle()
            runner._settle(publish=True)
            reference.cycle(1)
            shown[reference.scan_count] = _shown(reference, every)
            assert frames.scan == reference.scan_count
            assert frames.power["MAIN"] == _shown(reference, ids), f"step {number}"
    if shown:  # a past scan shows every watched element as it was, and the live one again after
        scan = sorted(shown)[seek % len(shown)]
        runner.seek(scan)
        runner._settle(publish=True)
        watched = runner._union["MAIN"][1]
        assert frames.power["MAIN"] == {e: shown[scan][e] for e in watched}
        # the replay recorded only the networks viewed (their probed code compiles at first use: History.viewed)
        unviewed = [e for e in every if e not in watched]
        assert runner.shown.probes("Main", unviewed).unknown == set(unviewed)
        # other networks viewed while the past scan is shown: it is replayed again and shows them as they were
        ids = [e for n in sorted({n % len(networks) for n in later}) for e in networks[n]]
        runner.watch("client", [], [("Main", ids)])
        runner._settle(publish=True)
        assert frames.power["MAIN"] == {e: shown[scan][e] for e in ids}
        runner.live()
        runner._settle(publish=True)
        assert frames.power["MAIN"] == _shown(reference, ids)


def test_a_fault_in_a_chunk_nobody_views_is_reported_as_in_the_fast_variant():
    """A chunk whose networks nobody views runs its twin without probes: a fault there names the same network,
    box and values as the fast variant's report."""
    from ladderlab.model import ld
    from ladderlab.model.project import Pou, Project

    networks = [
        ld.LdNetwork(id=f"n{i}", elements=[ld.Contact(id=f"a{i}", var="B0"), ld.Coil(id=f"c{i}", var="B1")])
        for i in range(10)
    ]
    divide = ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "X"})
    networks.append(ld.LdNetwork(id="nd", elements=[ld.Contact(id="a", var="B0"), divide, ld.Coil(id="c", var="B1")]))
    declarations = "VAR B0 : BOOL := TRUE; B1 : BOOL; X : INT := 7; Y : INT; END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    reports = []
    for variant in ("fast", "monitor"):
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(chunks, "CHUNK_STATEMENTS", 3)
            sim = build_project(Project(name="p", pous=[pou]), variant).simulation()
        if variant == "monitor":
            assert "ll_kf" in sim.compiled.source  # the chunks have their twins
            sim.view({})
        sim.cycle(1)
        assert sim.fault is not None
        reports.append(sim.fault.diagnostic().message)
    assert reports[0] == reports[1]
    assert "division by zero: 7 / 0 at POU MAIN, network 11, DIV" in reports[1]
