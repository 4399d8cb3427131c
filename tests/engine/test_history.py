"""Scan history (issue 23, simulation/history.py): recording only the nondeterminism, checkpoints under a
memory budget, and exact recomputation of any past scan.

The reference for every seek is the live simulation itself: after each live scan the test keeps what the
online view would show (every variable, the power flow of every element); a seek to that scan must give
exactly the same, whatever the inputs, checkpoints and evictions in between."""

from __future__ import annotations

import time

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.compile import compile_program
from ladderlab.engine.inputs import InputEvent
from ladderlab.engine.simulation import Simulation
from ladderlab.model import ld
from ladderlab.model.project import Pou
from ladderlab.simulation.build import build_project
from ladderlab.simulation.history import History, HistoryUnavailable
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.load import load_project_path
from tests.interchange.st_support import as_st
from tests.interchange.test_st_equivalence import RICH, rich_elements, rich_series
from tests.interchange.test_st_fbd_equivalence import programs as fbd_programs
from tests.ir.diagram_support import lower_ok
from tests.ir.diagram_support import project as diagram_project
from tests.ir.test_diagram_equivalence import _Ids
from tests.ir.test_il_online import il_pou
from tests.support import EXAMPLES, fuzz_settings

# Timers (TON, TOF, TP) on the virtual clock, edge triggers (R_TRIG, F_TRIG), a counter and arithmetic: the
# state a replay must carry exactly. Two tasks at different intervals so some scans run one task only.
SOURCE = """
VAR_GLOBAL
    Shared : BOOL;
END_VAR

PROGRAM Main
VAR
    Go, Stop : BOOL;
    Level : INT;
    OnDelay : TON; OffDelay : TOF; Pulse : TP;
    Up : R_TRIG; Down : F_TRIG;
    Count : CTU;
    Rises, Falls : INT;
    Total : DINT;
    Scaled : REAL;
    Lamp : BOOL;
END_VAR
OnDelay(IN := Go AND NOT Stop, PT := T#30ms);
OffDelay(IN := Go, PT := T#20ms);
Pulse(IN := Stop, PT := T#15ms);
Up(CLK := Go);
Down(CLK := Go);
IF Up.Q THEN Rises := Rises + 1; END_IF;
IF Down.Q THEN Falls := Falls + 1; END_IF;
Count(CU := OnDelay.Q, R := Stop, PV := 3);
Total := Total + INT_TO_DINT(Level);
Scaled := INT_TO_REAL(Level) * 0.5 + TIME_TO_REAL(OnDelay.ET);
Lamp := Count.Q OR Pulse.Q;
Shared := Lamp;
END_PROGRAM

PROGRAM Slow
VAR
    Ticks : INT;
    Seen : BOOL;
END_VAR
Ticks := Ticks + 1;
Seen := Shared;
END_PROGRAM

CONFIGURATION Cfg
    RESOURCE Res ON PLC
        TASK Fast (INTERVAL := T#5ms, PRIORITY := 1);
        TASK Every (INTERVAL := T#15ms, PRIORITY := 2);
        PROGRAM Main WITH Fast : Main;
        PROGRAM Slow WITH Every : Slow;
    END_RESOURCE
END_CONFIGURATION
"""

PROJECT, _ = source_to_project(SOURCE)
BUILD = build_project(PROJECT, "monitor")
assert BUILD.compiled is not None, BUILD.diagnostics
COMPILED = BUILD.compiled


def _view(sim: Simulation) -> tuple[dict, dict]:
    """What the online view shows of a scan: every variable, and the power flow of every element."""
    return sim.snapshot(), {"MAIN": sim.probes("MAIN"), "SLOW": sim.probes("SLOW")}


def _live() -> tuple[Simulation, History, list]:
    sim = Simulation(COMPILED)
    return sim, History(sim, min_interval=4), []


def _record(sim: Simulation, history: History) -> None:
    sim.on_input = history.applied


class _Cost:
    """The history's CPU clock with known costs: each scan ``scan_s``, each checkpoint's capture ``capture_s``
    (the history reads the clock just before and just after a capture)."""

    def __init__(self, sim: Simulation, scan_s: float, capture_s: float) -> None:
        self.sim, self.scan_s, self.capture_s, self.readings = sim, scan_s, capture_s, 0

    def __call__(self) -> float:
        self.readings += 1
        return self.sim.scan_count * self.scan_s + (self.readings // 2) * self.capture_s


EVENTS = st.one_of(
    st.tuples(st.just("write"), st.sampled_from(["Main.Go", "Main.Stop"]), st.booleans()),
    st.tuples(st.just("write"), st.just("Main.Level"), st.integers(-100, 100)),
    st.tuples(st.just("panel"), st.sampled_from(["Main.Go", "Main.Stop"]), st.booleans()),
    st.tuples(st.just("force"), st.sampled_from(["Main.Go", "Main.Level"]), st.integers(0, 1)),
    st.tuples(st.just("release"), st.sampled_from(["Main.Go", "Main.Level"]), st.none()),
    st.tuples(st.just("fault"), st.just("Main.Level"), st.integers(0, 1000)),
    st.tuples(st.just("clear_fault"), st.none(), st.none()),
    st.tuples(st.just("reset"), st.none(), st.booleans()),
)


def _event(kind: str, path: str | None, value: object, forced: dict) -> InputEvent | None:
    if kind == "force":
        return InputEvent("force", path, bool(value) if path == "Main.Go" else value)
    if kind == "release":
        return InputEvent("release", path) if path.upper() in forced else None
    if kind == "fault":
        return InputEvent("fault", path, mode="noisy", amplitude=5.0, seed=value)
    if kind == "clear_fault":
        return InputEvent("clear_fault")
    if kind == "reset":
        return InputEvent("reset", cold=bool(value))
    return InputEvent(kind, path, value)  # type: ignore[arg-type]  # write and panel, as drawn


@fuzz_settings(fast=30)
@given(
    steps=st.lists(st.tuples(st.lists(EVENTS, max_size=3), st.integers(1, 12), st.booleans()), min_size=1, max_size=25),
    seeks=st.lists(st.integers(0, 10_000), min_size=1, max_size=12),
    budget=st.sampled_from([None, 6_000]),
    interval=st.integers(1, 8),
)
def test_every_seeked_scan_equals_the_live_scan(steps, seeks, budget, interval):
    """LAB-23 (issue 23, item 2 and 6): random writes, panel presses, forces and releases, noisy faults, warm
    and cold resets and scans at chosen times; every seek equals what the live run showed at that scan, also
    after the budget evicted checkpoints (``budget`` 6,000 bytes keeps a few)."""
    sim = Simulation(COMPILED)
    budget_bytes = {"budget_bytes": budget} if budget else {}  # 1 ms scans, 0.01 ms captures: a checkpoint
    history = History(sim, min_interval=interval, clock=_Cost(sim, 1e-3, 1e-5), **budget_bytes)  # every interval
    _record(sim, history)
    seen = []
    for events, scans, chosen_time in steps:
        for kind, path, value in events:
            event = _event(kind, path, value, {p.upper(): v for p, v in sim.forced.items()})
            if event is not None:
                sim.submit(event)
        for _ in range(scans):
            if chosen_time:
                sim.scan_at(sim.time_ms + 7)
            else:
                sim.cycle(1)
            seen.append(_view(sim))
    assert history.last == len(seen) - 1
    if budget:
        assert history.size <= budget or len(history.checkpoints) == 1
    live_before = _view(sim)
    for raw in seeks:
        scan = history.first + raw % (history.last - history.first + 1)
        assert _view(history.seek(scan)) == seen[scan], f"scan {scan}"
    assert _view(sim) == live_before  # seeking never touches the live simulation
    for scan in range(history.first, history.last + 1):  # stepping forward and back, one scan at a time
        assert history.seek(scan).snapshot() == seen[scan][0], f"scan {scan}"


def test_an_idle_scan_costs_no_log_bytes():
    """Issue 23 item 1: 2,000 scans without input add nothing to the log; each input adds its line."""
    sim = Simulation(COMPILED)
    history = History(sim)
    _record(sim, history)
    sim.cycle(2_000)
    assert history.log_size == 0
    sim.write("Main.Level", 3)
    sim.cycle(1)
    line = b'{"kind":"write","path":"Main.Level","value":3}'
    assert history.log_size == len(line) + 8
    assert history.inputs_of(2_000) == [{"kind": "write", "path": "Main.Level", "value": 3}]
    sim.cycle(500)
    assert history.log_size == len(line) + 8


def _adaptive(budget: int | None = None, seek_ms: float = 2.05) -> History:
    sim = Simulation(COMPILED)
    budget_bytes = {"budget_bytes": budget} if budget else {}
    return History(sim, min_interval=10, seek_ms=seek_ms, clock=_Cost(sim, 1e-4, 5.03e-4), **budget_bytes)


def test_checkpoints_adapt_to_the_scan_and_the_budget_drops_the_oldest():
    """Issue 23 item 1: 0.1 ms scans and 0.503 ms captures (CPU): captures within 3 % of the scan time (the default
    ``overhead``) mean a checkpoint every ceil(0.503 / 0.003) = 168 scans, unless a seek would replay more than
    ``seek_ms`` (2.05 ms: 20 scans). Over budget the oldest go first."""
    history = _adaptive()
    history.live.cycle(300)
    assert history.interval == 20
    assert [c.scan for c in history.checkpoints] == [0, 10, *range(30, 300, 20)]
    cheap = _adaptive(seek_ms=1e9)
    cheap.live.cycle(300)
    assert [c.scan for c in cheap.checkpoints] == [0, 10, 178]

    budget = 4 * len(history.checkpoints[-1].blob)
    small = _adaptive(budget)
    small.live.cycle(300)
    scans = [c.scan for c in small.checkpoints]
    assert small.size <= budget and 2 <= len(scans) <= 5
    assert scans == [0, 10, *range(30, 300, 20)][-len(scans) :]
    assert small.first == scans[0] - 1 >= 0  # the scan the oldest checkpoint was taken after
    try:
        small.seek(small.first - 1)
    except HistoryUnavailable as error:
        assert str(error) == f"scan {small.first - 1} is no longer in the history: it starts at scan {small.first}"
    else:
        raise AssertionError("a dropped scan was seeked")
    try:
        small.seek(300)
    except HistoryUnavailable as error:
        assert str(error) == "scan 300 has not run yet (the last scan is 299)"
    else:
        raise AssertionError("a future scan was seeked")


class _Costs(_Cost):
    """``_Cost`` whose captures cost each of ``captures_s`` in turn."""

    def __init__(self, sim: Simulation, scan_s: float, captures_s: list[float]) -> None:
        super().__init__(sim, scan_s, 0.0)
        self.captures_s, self.spent = captures_s, 0.0

    def __call__(self) -> float:
        self.readings += 1
        if self.readings % 2 == 0:  # the reading after a capture
            self.spent += self.captures_s[(self.readings // 2 - 1) % len(self.captures_s)]
        return self.sim.scan_count * self.scan_s + self.spent


def test_the_interval_follows_the_typical_capture_not_the_cheapest():
    """hist4 item 4: captures that cost 0.6, 0.6 and 0.2 ms in turn (0.1 ms scans): the median of the latest, 0.6
    ms, sets the interval, ceil(0.6 / (0.03 * 0.1)) = 200 scans; the cheapest (0.2 ms: 67 scans) made the captures
    cost three times the 3 % they are allowed."""
    sim = Simulation(COMPILED)
    history = History(sim, min_interval=10, seek_ms=1e9, clock=_Costs(sim, 1e-4, [6e-4, 6e-4, 2e-4]))
    sim.cycle(240)
    assert [c.scan for c in history.checkpoints] == [0, 10, 210]
    assert history.interval == 200


def test_a_write_while_halted_is_kept_as_a_checkpoint():
    """A scan changed at a breakpoint cannot be replayed in the monitor code: the checkpoint after it is its
    view, and the scans after it replay from there."""
    debug = build_project(PROJECT, "debug").compiled
    sim = Simulation(debug)
    history = History(sim, min_interval=1_000, seek_ms=1e9)
    _record(sim, history)
    sim.cycle(5)
    sim.set_breakpoint("Main", line=26)  # Total := ...: after the timers and the edges ran
    sim.cycle(1)
    assert sim.halted is not None
    sim.write("Main.Level", 40)  # at once, inside the halted scan: Total adds 40 in this very scan
    sim.write("Main.Go", True)  # R_TRIG already ran in this scan: its edge counts in the next one
    sim.clear_breakpoints()
    sim.resume()
    halted_scan = sim.scan_count - 1
    seen = {halted_scan: sim.snapshot()}
    for _ in range(6):
        sim.cycle(1)
        seen[sim.scan_count - 1] = sim.snapshot()
    assert [c.scan for c in history.checkpoints] == [0, halted_scan + 1]
    for scan, values in seen.items():
        assert history.seek(scan).snapshot() == values
    assert seen[halted_scan]["MAIN.TOTAL"] == 40
    assert (seen[halted_scan]["MAIN.RISES"], seen[halted_scan + 1]["MAIN.RISES"]) == (0, 1)


def test_find_the_scan_where_a_variable_changed():
    """Issue 23 item 3: the previous and the next scan where ``Main.Rises`` changed (a rising edge of Go)."""
    sim = Simulation(COMPILED)
    history = History(sim, min_interval=4)
    _record(sim, history)
    sim.cycle(10)
    sim.write("Main.Go", True)  # applied at scan 10: R_TRIG fires in scan 10
    sim.cycle(10)
    sim.write("Main.Go", False)
    sim.cycle(10)
    sim.write("Main.Go", True)  # scan 30
    sim.cycle(10)
    assert history.changed("Main.Rises", 0, 1) == 10
    assert history.changed("Main.Rises", 10, 1) == 30
    assert history.changed("Main.Rises", 30, 1) is None
    assert history.changed("Main.Rises", 39, -1) == 30
    assert history.changed("Main.Rises", 30, -1) == 10
    assert history.changed("Main.Rises", 10, -1) is None


# An LD FUNCTION (its power flow is probed; it has no instance to hold the probes), called every third scan
# with a value above 10 or not.
FUNCTIONS = diagram_project(
    Pou(
        name="Big",
        kind="function",
        language="ld",
        return_type="BOOL",
        declarations="VAR_INPUT x : INT; END_VAR",
        body=ld.LdBody(
            networks=[
                ld.LdNetwork(
                    id="n1",
                    elements=[ld.Compare(id="gt", op="GT", left="x", right="10"), ld.Coil(id="big", var="Big")],
                )
            ]
        ),
    ),
    Pou(
        name="Main",
        kind="program",
        language="st",
        declarations="VAR n : INT; y : BOOL; END_VAR",
        body="n := n + 1;\nIF n MOD 3 = 0 THEN\n    y := Big(n MOD 20);\nEND_IF;",
    ),
)


def test_a_restored_scan_shows_the_power_flow_of_its_functions():
    """Issue 23: a FUNCTION has no instance, its probes (ST line values, LD power flow) live beside the program's;
    a seek to a scan just after a checkpoint (which may not call the function: its values are the last ones it
    computed) and to the oldest viewable scan (restored, not replayed) shows the function as it was live,
    whatever the replay simulation showed before (here: the newest scan)."""
    compiled = build_project(FUNCTIONS, "monitor").compiled
    sizer = History(Simulation(compiled))
    sim = Simulation(compiled)
    budget = 6 * len(sizer.checkpoints[0].blob)  # a few checkpoints: the oldest are evicted
    history = History(sim, min_interval=5, seek_ms=1e9, clock=_Cost(sim, 1e-3, 1e-5), budget_bytes=budget)
    _record(sim, history)
    seen = []
    for _ in range(60):
        sim.cycle(1)
        seen.append((sim.snapshot(), sim.probes("BIG")))
    assert history.first > 0 and history.first == history.checkpoints[0].scan - 1
    checkpointed = [c.scan for c in history.checkpoints if c.scan <= history.last]
    assert any(scan % 3 != 2 for scan in checkpointed)  # scans (numbered from 0) where Scale did not run
    for scan in [history.first, *checkpointed]:
        history.seek(history.last)
        replay = history.seek(scan)
        assert (replay.snapshot(), replay.probes("BIG")) == seen[scan], f"scan {scan}"
    assert seen[history.first][1].values  # the function ran before the oldest scan: it has values to show


def _seeks_match_live(project, writes, interval: int, seeks: list[int], pou: str = "MAIN") -> None:
    """Run ``project`` 60 scans with ``writes`` (scan, variable of Main, value) under a history; every seeked
    scan shows the live variables and power flow of ``pou`` of that scan."""
    build = build_project(project, "monitor")
    assert build.compiled is not None, build.diagnostics
    sim = Simulation(build.compiled)
    history = History(sim, min_interval=interval, clock=_Cost(sim, 1e-3, 1e-5))
    _record(sim, history)
    seen = []
    for scan in range(60):
        for at, name, value in writes:
            if at == scan:
                sim.write(f"Main.{name}", value if name.startswith("c") else value > 0)
        sim.cycle(1)
        seen.append((sim.snapshot(), sim.probes(pou)))
    for scan in seeks:
        replay = history.seek(scan)
        assert (replay.snapshot(), replay.probes(pou)) == seen[scan], f"scan {scan}"


_RICH_WRITES = st.lists(
    st.tuples(st.integers(0, 59), st.sampled_from(["i0", "i1", "i2", "c0", "c1"]), st.integers(-3, 3)), max_size=25
)


@fuzz_settings(fast=15)
@given(
    pou=fbd_programs(),
    writes=_RICH_WRITES,
    interval=st.integers(1, 9),
    seeks=st.lists(st.integers(0, 59), min_size=1, max_size=8),
)
def test_random_fbd_programs_seek_to_what_ran_live(pou, writes, interval, seeks):
    """Issue 23 item 6 for generated programs: the FBD networks of the cross-language tests (BOOL, INT, compare
    and select blocks, TON/CTU, edge and negated pins, feedback, jumps) with random writes over 60 scans; every
    seeked scan shows the live variables and FBD power flow (each pin's value) of that scan."""
    _seeks_match_live(diagram_project(pou), writes, interval, seeks)


@fuzz_settings(fast=10)
@given(
    program=st.lists(rich_series(), min_size=1, max_size=4),
    writes=_RICH_WRITES,
    interval=st.integers(1, 9),
    seeks=st.lists(st.integers(0, 59), min_size=1, max_size=8),
    as_text=st.booleans(),
)
def test_random_ld_programs_and_their_st_seek_to_what_ran_live(program, writes, interval, seeks, as_text):
    """Issue 23 item 6 for generated LD and ST programs: the rich LD rungs of the ST-export equivalence tests
    (contacts of every mode, compares, coils of every mode anywhere, nested parallels, TON/CTU/ADD boxes) and,
    as ST, their export: every seeked scan shows the live variables and power flow (LD rung states, ST line
    probes) of that scan."""
    ids = _Ids()
    networks = [
        ld.LdNetwork(id=f"n{index}", elements=rich_elements(series, ids)) for index, series in enumerate(program)
    ]
    pou = Pou(name="Main", kind="program", language="ld", declarations=RICH, body=ld.LdBody(networks=networks))
    project = diagram_project(pou)
    _seeks_match_live(as_st(project) if as_text else project, writes, interval, seeks)


class _Quiet:
    """A runner's sink that drops its messages."""

    def status(self, state, at, stack) -> None: ...

    def log(self, entry) -> None: ...

    def frame(self, frame) -> None: ...


@fuzz_settings(fast=15)
@given(
    branches=st.lists(
        st.tuples(st.lists(st.tuples(st.integers(0, 20), st.integers(-50, 50)), max_size=4), st.integers(1, 20)),
        min_size=1,
        max_size=4,
    ),
    forks=st.lists(st.integers(0, 1000), min_size=3, max_size=3),
)
def test_seeks_equal_the_live_scans_of_every_branch_after_forks(branches, forks):
    """Issue 23 items 4 and 6: a run, then forks from random past scans, each branch running with other writes;
    every scan of every branch (the earlier ones kept) seeks to what that branch showed live."""
    from ladderlab.simulation.runner import SimRunner

    runner = SimRunner(Simulation(COMPILED), _Quiet(), history_bytes=1 << 24)
    seen: list[dict[int, dict]] = []
    for number, (writes, scans) in enumerate(branches):
        if number:  # fork from a past scan of the branch before
            history = runner.history
            scan = history.first + 1 + forks[number - 1] % (history.last - history.first + 1)
            runner.seek(scan)
            runner.fork()
        shown = {runner.sim.scan_count: runner.sim.snapshot()} if number else {}
        for step in range(scans):
            for at, value in writes:
                if at == step:
                    runner.sim.write("Main.Level", value)
            runner.sim.cycle(1)
            shown[runner.sim.scan_count] = runner.sim.snapshot()
        seen.append(shown)
    for number, shown in enumerate(seen, 1):
        for scan, values in shown.items():
            if scan == 0 or scan - 1 < (runner.branches + [runner.history])[number - 1].first:
                continue
            runner.seek(scan, branch=number)
            assert runner.shown.snapshot() == values, f"branch {number}, scan {scan}"


STEPPED = source_to_project(
    """
PROGRAM Main
VAR
    A, B, C : INT;
END_VAR
A := A + 1;
B := A * 10;
C := B + A;
END_PROGRAM

CONFIGURATION Cfg
    RESOURCE Res ON PLC
        TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM Main WITH Fast : Main;
    END_RESOURCE
END_CONFIGURATION
"""
)[0]


def test_step_through_a_past_scan_line_by_line_without_changing_the_history():
    """Issue 23 item 3 ("one network within a scan"): scan 2 (the third) replayed in the debug variant from the
    state scan 1 left (A = 2, B = 20, C = 22), its recorded write A := 100 applied at its start; each step halts
    before the next line, so the values are those of the lines run so far: line 6 (A := A + 1) halts with
    A = 100, line 7 after it with A = 101, line 8 with B = 1010, and the end of the scan has C = 1111, which is
    what a seek to scan 2 shows. The live simulation and the recorded scans are untouched."""
    sim = Simulation(build_project(STEPPED, "monitor").compiled)
    history = History(sim, min_interval=1)
    _record(sim, history)
    sim.cycle(2)
    sim.write("Main.A", 100)
    sim.cycle(2)
    live = sim.snapshot()
    debug = build_project(STEPPED, "debug").compiled

    stepper = history.stepper(2, debug)
    seen = []
    halt = stepper.step("statement")
    while halt is not None:
        values = stepper.snapshot()
        seen.append((halt.origin.line, values["MAIN.A"], values["MAIN.B"], values["MAIN.C"]))
        halt = stepper.step("statement")
    assert seen == [(6, 100, 20, 22), (7, 101, 20, 22), (8, 101, 1010, 22)]
    end = stepper.snapshot()
    assert (end["MAIN.A"], end["MAIN.B"], end["MAIN.C"]) == (101, 1010, 1111)
    assert end == history.seek(2).snapshot()
    assert stepper.scan_count == 3 and stepper.time_ms == 30.0

    assert sim.snapshot() == live and sim.scan_count == 4  # the live simulation did not move
    assert history.seek(3).snapshot()["MAIN.C"] == 1122  # A 102, B 1020: the scans after it stay as recorded
    first = history.stepper(0, debug)  # the first scan starts from the initial checkpoint
    assert first.step("statement").origin.line == 6 and first.snapshot()["MAIN.A"] == 0
    with pytest.raises(HistoryUnavailable, match=r"^scan 4 has not run yet \(the last scan is 3\)$"):
        history.stepper(4, debug)


def test_step_through_a_past_scan_of_il_from_load_to_load():
    """IL (tests/ir/test_il_online.py's program): scan 1 replayed with its recorded write a := 5; a step halts at
    each load, jump or call (ON-04): LD a (line 1, a = 5), LD a (line 4, after a := a + 1: 6), JMPC done (line 6,
    6 > 2), then the jump skips the CAL and lands on LD a (line 11) with b still 10 from scan 0; the scan ends
    with b = 60."""
    program = lower_ok(il_pou())
    sim = Simulation(program, variant="monitor")
    history = History(sim, min_interval=1)
    _record(sim, history)
    sim.cycle(1)
    sim.write("Main.a", 5)
    sim.cycle(1)
    stepper = history.stepper(1, compile_program(program, "debug"))
    seen = []
    halt = stepper.step("statement")
    while halt is not None:
        seen.append((halt.origin.line, stepper.read("Main.a"), stepper.read("Main.b")))
        halt = stepper.step("statement")
    assert seen == [(1, 5, 10), (4, 6, 10), (6, 6, 10), (11, 6, 10)]
    assert (stepper.read("Main.a"), stepper.read("Main.b")) == (6, 60)
    assert stepper.snapshot() == history.seek(1).snapshot()


def test_step_over_a_call_in_a_past_scan():
    """The example motor, scan 3 (0-based; Start written before it): "statement" steps into the ST block
    Blinker that LD network lamp calls and on into the FBD program Scaling; "over" stays in the POU it started in
    and its callers, and from Main's last network goes on to the next program of the task, Scaling (as CODESYS
    steps over the end of a program; engine/debug.py ``_over``). The live debugger stepping its own scan 3 halts
    at the same points. Both end where a seek to that scan ends."""
    project = load_project_path(EXAMPLES / "motor")
    sim = Simulation(build_project(project, "monitor").compiled)
    history = History(sim)
    _record(sim, history)
    sim.cycle(3)
    sim.write("Start", True)
    sim.cycle(3)
    debug = build_project(project, "debug").compiled
    walked = {}
    for granularity in ("statement", "over"):
        stepper = history.stepper(3, debug)
        walked[granularity] = _walk(stepper, [granularity])
        assert stepper.snapshot() == history.seek(3).snapshot()
        live = Simulation(debug)
        live.cycle(3)
        live.write("Start", True)
        assert _walk(live, [granularity]) == walked[granularity]
    main = [("MAIN", network) for network in ("seal_in", "run_timer", "count_starts", "lamp")]
    assert walked["statement"] == [*main, *[("BLINKER", line) for line in (1, 2, 3, 4)], ("SCALING", "speed")]
    assert walked["over"] == [*main, ("SCALING", "speed")]


def _walk(sim: Simulation, granularities: list[str]) -> list[tuple[str, object]]:
    """The halts of one scan stepped through with ``granularities`` in turn (the last one repeated to its end)."""
    points = []
    for number in range(1000):
        halt = sim.step(granularities[min(number, len(granularities) - 1)])
        if halt is None:
            return points
        points.append((halt.origin.pou.upper(), halt.origin.network or halt.origin.line))
    raise AssertionError("the scan did not end")


OVER_THE_END = """
FUNCTION_BLOCK Counter
VAR_OUTPUT
    n : INT;
END_VAR
n := n + 1;
n := n * 2;
END_FUNCTION_BLOCK

PROGRAM First
VAR
    c : Counter;
    x, y : INT;
END_VAR
x := 1;
c();
y := c.n;
END_PROGRAM

PROGRAM Second
VAR
    z : INT;
END_VAR
z := z + 1;
z := z + 2;
END_PROGRAM

PROGRAM Other
VAR
    w : INT;
END_VAR
w := 5;
END_PROGRAM

CONFIGURATION Cfg
    RESOURCE Res ON PLC
        TASK Main (INTERVAL := T#10ms, PRIORITY := 1);
        TASK Later (INTERVAL := T#10ms, PRIORITY := 2);
        PROGRAM First WITH Main : First;
        PROGRAM Second WITH Main : Second;
        PROGRAM Other WITH Later : Other;
    END_RESOURCE
END_CONFIGURATION
"""


F15, F16, F17 = ("FIRST", 15), ("FIRST", 16), ("FIRST", 17)  # OVER_THE_END's statements by (POU, line)
C6, C7, S24, S25 = ("COUNTER", 6), ("COUNTER", 7), ("SECOND", 24), ("SECOND", 25)


@pytest.mark.parametrize(
    ("granularities", "halts"),
    [
        # into Counter; over its last statement: the caller's next one (CODESYS "Step Over"); over First's last
        # statement: the next program of its task, Second; over Second's last: the scan's end (Other runs in
        # another task)
        (["statement", "statement", "statement", "over"], [F15, F16, C6, C7, F17, S24, S25]),
        (["over"], [F15, F16, F17, S24, S25]),
        # out of Counter: the caller, after the call
        (["statement", "statement", "statement", "out", "over"], [F15, F16, C6, F17, S24, S25]),
        (["statement"], [F15, F16, C6, C7, F17, S24, S25, ("OTHER", 32)]),
    ],
)
def test_step_over_the_end_of_a_pou_live_and_in_a_past_scan(granularities, halts):
    """hist4 item 3: a step over at the last statement of a called POU halts at the caller's next statement; at
    the end of a program, at the next program of the same task (not another task's). The live debugger stepping
    its scan 2 and the history's stepper going through the recorded scan 2 halt at the same points."""
    project, _ = source_to_project(OVER_THE_END)
    debug = build_project(project, "debug").compiled
    live = Simulation(debug)
    live.cycle(2)
    sim = Simulation(build_project(project, "monitor").compiled)
    history = History(sim, min_interval=1)
    _record(sim, history)
    sim.cycle(3)
    lived = _walk(live, granularities)
    assert lived == halts
    assert _walk(history.stepper(2, debug), granularities) == lived


SPIN = """
PROGRAM Main
VAR
    n, i, x : DINT;
END_VAR
x := 0;
FOR i := 1 TO n DO
    x := x + 1;
END_FOR
END_PROGRAM
"""


def test_a_replay_runs_under_the_watchdogs_of_the_live_tasks():
    """A scan that ran live under a 60 s watchdog (the task's budget; the engine's default is 0.1 s) but takes longer
    than 0.1 s of CPU is replayed under the same budget: the seek shows what ran live, not a watchdog trip."""
    project, _ = source_to_project(SPIN)
    sim = build_project(project, "monitor").simulation(watchdog_s=60.0)
    history = History(sim, min_interval=1)
    _record(sim, history)
    sim.cycle(1)
    loops = 1
    while True:  # enough loops to take 0.15 s of CPU on this machine, at least
        sim.write("Main.n", loops)
        started = time.thread_time()
        sim.cycle(1)
        if time.thread_time() - started > 0.15:
            break
        loops *= 4
    assert sim.fault is None and sim.read("Main.x") == loops
    last = sim.scan_count - 1
    replay = history.seek(last)
    assert replay.fault is None and replay.read("Main.x") == loops
    assert replay.snapshot() == sim.snapshot()


def _code_objects(sim: Simulation) -> set[int]:
    """The ids of the code objects of every function the simulation's generated module defined (methods too)."""
    found: set[int] = set()
    for value in sim._ns.values():
        functions = vars(value).values() if isinstance(value, type) else (value,)
        generated = (f.__code__ for f in functions if hasattr(f, "__code__"))  # not the runtime's helpers
        found |= {id(code) for code in generated if code.co_filename == sim.compiled.filename}
    return found


def test_the_replay_runs_code_objects_of_its_own_so_a_seek_leaves_the_live_scan_specialised():
    """CPython specialises a code object for the classes it meets, and each simulation has its own classes: a
    replay running the live simulation's code objects made the live scan of the 10,000-network benchmark ten times
    slower for a while after each seek (1.0 -> 10.3 ms per scan). The replay runs copies (CompiledProgram.own_code)
    and computes the same."""
    project, _ = source_to_project(SOURCE)
    sim = build_project(project, "monitor").simulation()
    history = History(sim, min_interval=4)
    _record(sim, history)
    for scan in range(12):
        sim.write("Main.Go", scan % 5 < 3)
        sim.cycle(1)
    replay = history.seek(sim.scan_count - 1)
    assert replay.snapshot() == sim.snapshot()
    live, own = _code_objects(sim), _code_objects(replay)
    assert live and own and not live & own


def test_a_checkpoint_follows_every_log_bytes_of_inputs():
    """Issue 23 item 1 ("or every few MB of input log"): with checkpoints due only every 1,000 scans, a history
    whose ``log_bytes`` is 300 takes one at the end of the scan whose inputs bring the log since the last one to
    300 bytes or more: each write ``{"kind":"write","path":"Main.Level","value":NN}`` is 47 bytes and 8 of
    bookkeeping, so the sixth write (330 bytes) does, and the count starts again from there."""
    sim = Simulation(COMPILED)
    history = History(sim, min_interval=1_000, seek_ms=1e9, log_bytes=300)
    _record(sim, history)
    for value in range(10, 22):  # one write before each of scans 0 to 11
        sim.write("Main.Level", value)
        sim.cycle(1)
    assert [c.scan for c in history.checkpoints] == [0, 6, 12]
    assert history.log_size == 12 * (47 + 8)
    assert history.seek(8).snapshot()["MAIN.LEVEL"] == 18
