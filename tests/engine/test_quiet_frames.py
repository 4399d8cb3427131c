"""A running simulation's frames show the power flow of the scan their values are of (issue 27 item 2).

The runner records the viewed networks only on the scans a frame may show (``SimRunner._records_next``;
docs/runtime.md, "Scans no frame shows"): scans run in batches between frames at a high time scale, commands come
between them. The runner here runs on a fake wall clock, turn by turn as its thread's loop does (``SimRunner.turn``),
while the reference, the debug variant of the same program, runs the same scans with the inputs the runner's
journal says each scan applied: every frame a client receives leaves it holding, for every watched element, what
the reference shows at that frame's scan, also after writes, view changes, stop/run, single cycles, a runtime
error in a scan that recorded nothing (recomputed from the history) and a seek to that scan.
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.runner import SimRunner
from tests.engine.test_fast_equals_debug import BOOLS, ld_programs
from tests.engine.test_viewed_networks import _networks, _pair, _shown
from tests.support import fuzz_settings


class _Clock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


class _Client:
    """A runner's sink keeping what a client holds after each frame, checked against the reference at its scan."""

    def __init__(self, reference: Simulation) -> None:
        self.reference = reference
        self.runner: SimRunner | None = None
        self.power: dict[str, object] = {}
        self.frames = 0
        self.faults: list[str] = []
        self.failures: list[AssertionError] = []

    def status(self, state, at, stack) -> None: ...

    def log(self, entry) -> None:
        if entry["kind"] == "fault":
            self.faults.append(entry["message"])

    def frame(self, frame) -> None:
        """(A failed check is kept: the runner's thread loop would log an exception raised here and go on.)"""
        try:
            self._check(frame)
        except AssertionError as error:
            self.failures.append(error)

    def _check(self, frame) -> None:
        assert self.runner is not None
        self.frames += 1
        states = frame["power"].get("MAIN", {})
        self.power = dict(states) if frame["full"] else {**self.power, **states}
        if self.runner._view is not None:
            return  # (a past scan: test_seek_... checks it)
        assert not (self.runner._running and self.runner.sim.quiet), "a running simulation's frame after a quiet scan"
        self._reference_at(frame["scan"])
        ids = list(self.runner._union["MAIN"][1]) if "MAIN" in self.runner._union else []
        shown = _shown(self.reference, ids)
        unknown = self.runner.sim.probes("Main", ids).unknown if ids else frozenset()
        assert set(self.power) <= set(ids)
        for e in ids:  # an element left out: its network is viewed since the last scan (the next one records it)
            assert shown[e] == self.power[e] if e in self.power else e in unknown, f"{e}, frame at {frame['scan']}"

    def _reference_at(self, scan: int) -> None:
        """The reference run to the end of ``scan`` (frames number completed scans), fed each scan's inputs."""
        assert self.runner is not None
        reference = self.reference
        while reference.scan_count < scan:
            for applied in self.runner.journal:
                if applied.scan == reference.scan_count:
                    reference.submit(applied.event)
            reference.cycle(1)
        assert reference.scan_count == scan


def _runner(project: Project, speed: float) -> tuple[SimRunner, _Client, _Clock, dict[int, list[str]]]:
    live, reference = _pair(project, 3)
    client, clock = _Client(reference), _Clock()
    runner = SimRunner(live, client, speed=speed, clock=clock, history_bytes=1 << 24)
    client.runner = runner
    return runner, client, clock, _networks(live)


def _turn(runner: SimRunner, client: _Client) -> None:
    """One turn of the runner's thread loop, then every check of the frames it sent."""
    runner.turn()
    assert not client.failures, client.failures[0]


def _command(runner: SimRunner, op: str, **args) -> None:
    runner.submit(op, args, lambda result, error: None)


_steps = st.lists(
    st.tuples(
        st.floats(0.0, 0.05),  # wall seconds that pass
        st.sampled_from(["none", "none", "none", "write", "watch", "stop", "run", "single"]),
        st.sampled_from(BOOLS),
        st.lists(st.integers(0, 7), max_size=3),
    ),
    min_size=1,
    max_size=25,
)


@fuzz_settings(fast=20)
@given(project=ld_programs(), speed=st.sampled_from([1.0, 10.0, 100.0]), steps=_steps)
def test_every_frame_of_a_running_simulation_shows_the_power_flow_of_its_scan(project, speed, steps):
    runner, client, clock, networks = _runner(project, speed)
    every = [e for ids in networks.values() for e in ids]
    _command(runner, "watch", key="client", paths=[], elements=[("Main", every)])
    _command(runner, "run")
    for seconds, op, name, view in steps:
        clock.now += seconds
        if op == "write":
            _command(runner, "write", path=f"Main.{name}", value=seconds > 0.02)
        elif op == "watch":
            ids = [e for n in sorted({n % len(networks) for n in view}) for e in networks[n]]
            _command(runner, "watch", key="client", paths=[], elements=[("Main", ids)])
        elif op in ("stop", "run"):
            _command(runner, op)
        elif op == "single" and not runner._running:
            _command(runner, "single_cycle")
        _turn(runner, client)
        while runner._commands and not runner._holding():  # (serve's loop does not wait then)
            _turn(runner, client)
        if runner._commands:  # held for the next scan (at most publish_s away): they run once it ran
            assert runner._running and runner.sim.quiet
            assert runner._pacer is not None and runner._delay is not None and runner._delay <= runner.publish_s
    clock.now += 1.0
    _command(runner, "stop")
    for _ in range(3):
        _turn(runner, client)
    assert not runner._commands
    assert not runner.sim.quiet  # stopped after a recorded scan: a frame (and any later one) shows it


def test_at_100x_only_the_scans_before_a_frame_record():
    """A 10 ms task at 100x: ten scans between two 20 ms frames, the last of them recorded (the others quiet)."""
    project = _divider(True)
    runner, client, clock, _networks_ = _runner(project, 100.0)
    _command(runner, "watch", key="client", paths=[], elements=[("Main", ["a", "c"])])
    _command(runner, "run")
    _turn(runner, client)
    decisions: list[bool] = []
    decide = runner._records_next
    runner._records_next = lambda: decisions.append(decide()) or decisions[-1]  # type: ignore[method-assign]
    frames = client.frames
    for _ in range(200):  # 0.2 s of wall time at 1 ms a turn: 2,000 scans
        clock.now += 0.001
        _turn(runner, client)
    assert len(decisions) == 2000
    assert 9 <= client.frames - frames <= 11
    assert sum(decisions) <= 2 * (client.frames - frames)


def _divider(zero_at_start: bool) -> Project:
    """Main divides X by Y in network 2 when START is set: a runtime error at the scan that sees it."""
    divide = ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "Z"})
    networks = [
        ld.LdNetwork(id="n1", elements=[ld.Contact(id="a", var="B0"), ld.Coil(id="c", var="B1")]),
        ld.LdNetwork(id="n2", elements=[ld.Contact(id="s", var="START"), divide, ld.Coil(id="o", var="B2")]),
    ]
    declarations = f"VAR B0 : BOOL := TRUE; B1, B2, START : BOOL; X : INT := 7; Y : INT := {0 if zero_at_start else 1}; Z : INT; END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    return Project(name="p", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


def test_a_runtime_error_in_a_quiet_scan_shows_that_scans_power_flow_recomputed_from_the_history():
    runner, client, clock, _networks_ = _runner(_divider(True), 100.0)
    ids = ["a", "c", "s", "d", "o"]
    _command(runner, "watch", key="client", paths=["Main.Z"], elements=[("Main", ids)])
    _command(runner, "run")
    _turn(runner, client)
    for _ in range(5):
        clock.now += 0.013
        _turn(runner, client)
    assert runner._running
    # START set as the world would set it: applied at the start of the next scan, which faults; quiet scans before
    # it (a write is a command: it waits for a recorded scan, so the fault needs a scan that is not the next one)
    live = runner.sim
    frames = client.frames
    live.write("Main.START", True)  # (not a command: the world's input between two quiet scans of a batch)
    clock.now += 0.002  # two scans at 100x, the first (quiet, no frame due) faults
    _turn(runner, client)
    assert client.faults and "division by zero" in client.faults[0]
    assert not runner._running
    fault_scan = live.fault.scan
    assert runner.history is not None and fault_scan in runner.history._quiet_errors  # it recorded no network
    assert client.frames > frames  # the frame after the fault: checked against the reference by the client
    assert set(client.power) == set(ids)  # every element known: the scan recomputed
    # a seek to the faulted scan later shows the same (the checkpoint after it holds the silenced flags)
    _command(runner, "seek", scan=fault_scan + 1)
    _turn(runner, client)
    assert client.power == {e: v for e, v in _shown(client.reference, ids).items()}
