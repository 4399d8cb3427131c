"""Tasks on the virtual clock (CFG-05, CFG-06), build-time task errors, and the real-time pacer."""

from __future__ import annotations

import pytest

from ladderlab.engine.compile import CompileError
from ladderlab.engine.simulation import Simulation
from ladderlab.engine.tasks import Pacer

from .irbuild import DINT, INT, add, assign, c, div, g, mul, pou, prog, slot, task, v

ORDER = g("ORDER", DINT)


def _marker(name: str, mark: int):
    """A program counting its runs and appending its mark to the global ORDER (ORDER := ORDER * 10 + mark)."""
    runs = v("RUNS", INT)
    return pou(
        name,
        [slot("RUNS", INT)],
        [assign(runs, add(runs, c(1, INT))), assign(ORDER, add(mul(ORDER, c(10, DINT)), c(mark, DINT)))],
    )


def _two_tasks(**kwargs):
    program = prog(
        _marker("FASTP", 1),
        _marker("SLOWP", 2),
        _marker("ALSO", 3),
        globals=[slot("ORDER", DINT, "VAR_GLOBAL")],
        tasks=[task("FAST", 10, 5, "FASTP", "ALSO"), task("SLOW", 25, 1, "SLOWP")],
    )
    return Simulation(program, **kwargs)


def test_two_intervals_run_on_the_virtual_clock_in_priority_order():
    """Each scan moves to the earliest due time; at 50 ms both are due: SLOW (priority 1) before FAST (5)."""
    sim = _two_tasks()
    rows = []
    for _ in range(8):
        sim.write("ORDER", 0)
        sim.cycle()
        rows.append((sim.time_ms, sim.read("ORDER"), sim.read("FASTP.RUNS"), sim.read("SLOWP.RUNS")))
    assert rows == [
        (10, 13, 1, 0),
        (20, 13, 2, 0),
        (25, 2, 2, 1),
        (30, 13, 3, 1),
        (40, 13, 4, 1),
        (50, 213, 5, 2),
        (60, 13, 6, 2),
        (70, 13, 7, 2),
    ]


def test_run_for_and_scan_at_follow_the_due_times():
    sim = _two_tasks()
    assert sim.run_for(50) == 6 and sim.time_ms == 50
    sim.write("ORDER", 0)
    sim.scan_at(52)  # an explicit scan runs every task
    assert sim.read("ORDER") == 213 and sim.next_scan_time() == 60
    sim.write("ORDER", 0)
    sim.cycle()
    assert (sim.time_ms, sim.read("ORDER")) == (60, 13)


def test_without_a_task_configuration_every_program_runs_every_10_ms():
    sim = Simulation(prog(_marker("A", 1), _marker("B", 2), globals=[slot("ORDER", DINT, "VAR_GLOBAL")]))
    sim.cycle(2)
    assert (sim.time_ms, sim.read("ORDER"), [t.name for t in sim.tasks]) == (20, 1212, ["DEFAULT"])


def test_programs_not_in_any_task_do_not_run_but_can_be_read():
    sim = Simulation(
        prog(
            _marker("A", 1),
            _marker("IDLE", 2),
            globals=[slot("ORDER", DINT, "VAR_GLOBAL")],
            tasks=[task("T", 10, 0, "A")],
        )
    )
    sim.cycle(3)
    assert (sim.read("A.RUNS"), sim.read("IDLE.RUNS")) == (3, 0)


@pytest.mark.parametrize(
    ("tasks", "message"),
    [
        (
            [task("T1", 10, 0, "A"), task("T2", 20, 0, "A")],
            "program A is listed in tasks T1 and T2: an instance runs in one task only",
        ),
        ([task("T1", 10, 0, "A", "A")], "program A is listed twice in this task: an instance runs in one task only"),
        ([task("T1", 10, 0, "NOPE")], "task T1: unknown program NOPE"),
        ([task("T1", 10, 0, "FB")], "task T1: FB is a function block, not a program"),
        ([task("T1", 0, 0, "A")], "task T1: the interval must be a positive time, not 0 ms"),
        ([task("T1", 10, 0, "A"), task("t1", 10, 0)], "task t1 is declared twice"),
    ],
)
def test_task_configuration_errors_at_build_time(tasks, message):
    program = prog(
        _marker("A", 1),
        pou("FB", [], [], kind="function_block"),
        globals=[slot("ORDER", DINT, "VAR_GLOBAL")],
        tasks=tasks,
    )
    with pytest.raises(CompileError) as raised:
        Simulation(program)
    assert [d.message for d in raised.value.diagnostics] == [message]
    assert raised.value.diagnostics[0].code == "ENGINE-TASKS"


def test_a_fault_stops_its_task_only_until_reset():
    zero = v("ZERO", INT)
    bad = pou("BAD", [slot("ZERO", INT), slot("X", INT)], [assign(v("X", INT), div(c(1, INT), zero))])
    program = prog(
        _marker("GOOD", 1),
        bad,
        globals=[slot("ORDER", DINT, "VAR_GLOBAL")],
        tasks=[task("T1", 10, 0, "BAD"), task("T2", 10, 1, "GOOD")],
    )
    sim = Simulation(program)
    sim.cycle(3)
    assert sim.read("GOOD.RUNS") == 3 and len(sim.faults) == 1 and sim.fault.task == "T1"
    assert [t.stopped for t in sim.tasks] == [True, False]
    sim.reset()
    sim.write("BAD.ZERO", 1)
    sim.cycle()
    assert sim.fault is None and sim.read("BAD.X") == 1


class _FakeClock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_pacer_runs_the_scans_that_are_due_on_the_wall_clock():
    sim, clock = _two_tasks(), _FakeClock()
    pacer = Pacer(sim, clock=clock)
    assert pacer.poll() == pytest.approx(0.010) and sim.scan_count == 0
    clock.now += 0.026
    assert pacer.poll() == pytest.approx(0.004) and sim.time_ms == 25 and sim.scan_count == 3
    clock.now += 0.004
    pacer.poll()
    assert sim.time_ms == 30


def test_pacer_speed_and_overrun_skip_ahead():
    sim, clock = _two_tasks(), _FakeClock()
    pacer = Pacer(sim, clock=clock, speed=2.0, max_lag_ms=100)
    clock.now += 0.010  # 20 ms of virtual time at double speed
    pacer.poll()
    assert sim.time_ms == 20
    clock.now += 10.0  # the driver stalled for 10 s: skip ahead instead of running 2000 scans
    delay = pacer.poll()
    assert pacer.overruns == 1 and sim.scan_count == 3 and sim.time_ms == 25
    assert delay == pytest.approx(0.0025)  # 5 ms of virtual time to the next scan, at double speed


def test_pacer_run_sleeps_between_scans():
    sim, clock = _two_tasks(), _FakeClock()
    slept = []

    def sleep(seconds: float) -> None:
        slept.append(round(seconds, 6))
        clock.now += seconds

    Pacer(sim, clock=clock).run(0.05, sleep=sleep)
    assert sim.time_ms == 50 and slept == [0.01, 0.01, 0.005, 0.005, 0.01, 0.01]


def test_an_interrupted_pacer_returns_after_a_scan_and_keeps_its_schedule():
    """A simulation process runs commands between scans: poll() yields after the scan that saw one waiting,
    and the next poll runs the scans still due (no re-anchoring: virtual time stays in step)."""
    sim, clock = _two_tasks(), _FakeClock()
    waiting = [True]
    pacer = Pacer(sim, clock=clock, interrupted=lambda: waiting[0])
    clock.now += 0.026  # 10, 20, 25 are due
    assert pacer.poll() == 0.0 and sim.scan_count == 1 and sim.time_ms == 10
    waiting[0] = False
    assert pacer.poll() == pytest.approx(0.004) and sim.time_ms == 25 and sim.scan_count == 3
