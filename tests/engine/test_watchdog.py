"""The per-task watchdog (ST-12, ST-33, ST-93 [REC]): endless loops stop the task with a located fault."""

from __future__ import annotations

import time

import pytest

from ladderlab.engine.simulation import Simulation
from tests.support import NESTED_LOOPS, NESTED_LOOPS_DECLARATIONS

from .irbuild import (
    BOOL,
    DINT,
    INT,
    add,
    assign,
    c,
    call,
    for_,
    function,
    gt,
    jump,
    lt,
    network,
    pou,
    prog,
    repeat,
    slot,
    task,
    v,
    while_,
)
from .test_simulation_st import simulation


class _Ticks:
    """A wall clock that advances 1 ms per reading, so watchdog tests do not depend on the machine's speed."""

    def __init__(self) -> None:
        self.now = 0.0
        self.readings = 0

    def __call__(self) -> float:
        self.readings += 1
        self.now += 0.001
        return self.now


def _busy_counter():
    n = v("N", INT)
    return pou("OTHER", [slot("N", INT)], [assign(n, add(n, c(1, INT)))])


def test_endless_while_stops_the_task_with_a_watchdog_fault_naming_pou_and_line():
    """ST-12: WHILE i > 0 DO n := n * 2; END_WHILE never ends; the other task keeps running."""
    i, n = v("I", INT), v("N", INT)
    main = pou(
        "MAIN",
        [slot("I", INT, initial=1), slot("N", INT)],
        [assign(n, c(1, INT)), while_(gt(i, c(0, INT)), [assign(n, add(n, c(0, INT)))])],
    )
    ticks = _Ticks()
    sim = Simulation(
        prog(main, _busy_counter(), tasks=[task("T1", 10, 0, "MAIN"), task("T2", 10, 1, "OTHER")]),
        watchdog_s=0.2,
        watchdog_clock=ticks,
    )
    sim.cycle(3)
    fault = sim.fault
    assert (fault.kind, fault.code, fault.task, fault.pou, fault.origin.line) == (
        "watchdog",
        "watchdog",
        "T1",
        "MAIN",
        2,
    )
    assert fault.message == "watchdog: scan exceeded 0.2 s" and fault.instance == "MAIN" and fault.values == {"I": 1}
    assert len(sim.faults) == 1 and sim.read("OTHER.N") == 3
    assert 200 <= ticks.readings < 260  # the clock is read about every WATCHDOG_EVERY iterations, not every one


def test_while_true_end_while_with_the_real_clock():
    """`WHILE TRUE DO END_WHILE;` returns within about the watchdog time and leaves the simulation usable."""
    main = pou("MAIN", [slot("X", INT)], [assign(v("X", INT), c(5, INT)), while_(c(True, BOOL), [])])
    sim = Simulation(prog(main), watchdog_s=0.2)
    start = time.perf_counter()
    sim.cycle()
    assert 0.2 <= time.perf_counter() - start < 2.0
    assert sim.fault.kind == "watchdog" and sim.fault.origin.line == 2 and sim.read("MAIN.X") == 5
    sim.cycle(2)  # the stopped task does not run again
    assert len(sim.faults) == 1 and sim.time_ms == 30


def test_endless_backward_jump_is_caught_and_names_the_network():
    x = v("X", INT)
    blocks = [network("N1", [assign(x, add(x, c(1, INT)))], label="AGAIN"), network("N2", [jump("AGAIN")])]
    sim = Simulation(prog(pou("MAIN", [slot("X", INT)], blocks)), watchdog_s=0.05, watchdog_clock=_Ticks())
    sim.cycle()
    fault = sim.fault
    assert fault.kind == "watchdog" and (fault.origin.pou, fault.origin.network) == ("MAIN", "N2")
    assert fault.values == {} and sim.read("MAIN.X") > 256


def test_endless_repeat_inside_a_function_names_the_function():
    k = v("K", INT)
    spin = function("SPIN", INT, [slot("K", INT)], [repeat([assign(k, add(k, c(1, INT)))], c(False, BOOL))])
    main = pou("MAIN", [slot("R", INT)], [assign(v("R", INT), call("SPIN", type=INT, user=True))])
    sim = Simulation(prog(main, spin), watchdog_s=0.05, watchdog_clock=_Ticks())
    sim.cycle()
    assert (sim.fault.pou, sim.fault.origin.line, sim.fault.instance) == ("SPIN", 1, None)


def test_watchdog_limit_per_task_and_long_finite_loops_pass():
    """A loop of 100,000 iterations is fine under a 1 s limit (default) but not under 1 ms."""
    i = v("I", INT)
    loop = [assign(i, c(0, INT)), while_(lt(i, c(30000, INT)), [assign(i, add(i, c(1, INT)))])]
    program = prog(
        pou("A", [slot("I", INT)], loop),
        pou("B", [slot("I", INT)], loop),
        tasks=[task("SLOWOK", 10, 0, "A"), task("STRICT", 10, 1, "B")],
    )
    sim = Simulation(program, watchdog_s={"strict": 0.0005, "SLOWOK": 30.0}, watchdog_clock=_Ticks())
    sim.cycle()
    assert [f.task for f in sim.faults] == ["STRICT"] and sim.read("A.I") == 30000


# ------------------------------------------------------------------ one budget per scan (issue 18, item 4)


NESTED = f"PROGRAM Main\n{NESTED_LOOPS_DECLARATIONS}\n{NESTED_LOOPS}\nEND_PROGRAM\n"
INNERMOST_LOOP_LINE = NESTED.splitlines().index("                FOR d := 1 TO 255 DO") + 1


def test_nested_loops_of_fewer_iterations_than_the_check_interval_count_on_one_budget():
    """Four nested FOR 1 TO 255 (4e9 iterations): each loop runs fewer than WATCHDOG_EVERY times per entry,
    so a count that restarted at each loop entry never read the clock. Now every back-edge of the scan
    counts: the clock is read every 256 of them and the task faults at the innermost loop."""
    ticks = _Ticks()
    sim = simulation(NESTED, watchdog_s=0.05, watchdog_clock=ticks)
    sim.cycle()  # Go is FALSE: no loop runs, no fault
    assert sim.fault is None
    sim.write("Main.Go", True)
    sim.cycle()
    assert (sim.fault.kind, sim.fault.pou, sim.fault.origin.line) == ("watchdog", "MAIN", INNERMOST_LOOP_LINE)
    # 50 readings of 1 ms: the deadline passed after about 50 x 256 innermost iterations
    assert 49 * 255 <= sim.read("Main.n") <= 51 * 256
    assert ticks.readings < 60


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_loops_in_called_function_blocks_draw_on_the_callers_budget(variant: str):
    """The same four loops split over four FB levels, each level a FOR 1 TO 255 calling the next: the
    callee's loops take the countdown where the caller's loop left it, so the scan still faults."""
    text = """
FUNCTION_BLOCK L4
VAR_IN_OUT n : DINT; END_VAR
VAR i : INT; END_VAR
FOR i := 1 TO 255 DO n := n + 1; END_FOR;
END_FUNCTION_BLOCK
FUNCTION_BLOCK L3
VAR_IN_OUT n : DINT; END_VAR
VAR i : INT; inner : L4; END_VAR
FOR i := 1 TO 255 DO inner(n := n); END_FOR;
END_FUNCTION_BLOCK
FUNCTION_BLOCK L2
VAR_IN_OUT n : DINT; END_VAR
VAR i : INT; inner : L3; END_VAR
FOR i := 1 TO 255 DO inner(n := n); END_FOR;
END_FUNCTION_BLOCK
PROGRAM Main
VAR i : INT; n : DINT; inner : L2; END_VAR
FOR i := 1 TO 255 DO inner(n := n); END_FOR;
END_PROGRAM
"""
    sim = simulation(text, variant=variant, watchdog_s=0.05, watchdog_clock=_Ticks())
    sim.cycle()
    assert (sim.fault.kind, sim.fault.pou) == ("watchdog", "L4")
    assert sim.read("Main.n") < 70 * 256


def test_the_budget_is_per_scan_and_finite_loops_finish():
    """A scan of 1,000 short loops (255,000 back-edges) under a generous budget ends normally, every scan."""
    text = """
PROGRAM Main
VAR a, b : INT; n : DINT; END_VAR
FOR a := 1 TO 1000 DO
    FOR b := 1 TO 255 DO n := n + 1; END_FOR;
END_FOR;
END_PROGRAM
"""
    ticks = _Ticks()
    sim = simulation(text, watchdog_s=10.0, watchdog_clock=ticks)
    sim.cycle(3)
    assert sim.fault is None and sim.read("Main.n") == 3 * 255_000
    assert 3 * 990 <= ticks.readings <= 3 * 1010  # one reading per 256 back-edges (and one per task arm)


def test_a_backward_jump_loop_around_a_for_loop_counts_both():
    """A label loop (the jump dispatch of an LD/FBD body) whose network holds a short FOR: both count on one
    budget, so the endless jump faults although the FOR never reaches 256 iterations."""
    i, n = v("I", INT), v("N", DINT)
    blocks = [
        network("N1", [for_(i, c(1, INT), c(10, INT), [assign(n, add(n, c(1, DINT)))])], label="AGAIN"),
        network("N2", [jump("AGAIN")]),
    ]
    sim = Simulation(
        prog(pou("MAIN", [slot("I", INT), slot("N", DINT)], blocks)), watchdog_s=0.05, watchdog_clock=_Ticks()
    )
    sim.cycle()
    assert sim.fault.kind == "watchdog" and 45 * 256 < sim.read("MAIN.N") < 51 * 256


def test_the_default_budget_is_100_ms_of_the_scans_own_time():
    """CODESYS's default watchdog time; counted on the scan thread's CPU clock (not the wall clock)."""
    from ladderlab.engine.tasks import DEFAULT_WATCHDOG_S

    assert DEFAULT_WATCHDOG_S == 0.1
    sim = simulation(NESTED)
    sim.write("Main.Go", True)
    start = time.thread_time()
    sim.cycle()
    assert sim.fault.kind == "watchdog" and sim.fault.message == "watchdog: scan exceeded 0.1 s"
    assert 0.1 <= time.thread_time() - start < 1.0


def test_a_task_of_the_project_sets_its_own_budget():
    """Task.watchdog_ms (CODESYS: the task's watchdog time) overrides the default for that task only."""
    from ladderlab.model import Project, Task
    from ladderlab.simulation.build import build_project

    loop = "n := 0;\nWHILE n < 30000 DO n := n + 1; END_WHILE;"
    pous = [
        {"name": name, "kind": "program", "language": "st", "declarations": "VAR n : INT; END_VAR", "body": loop}
        for name in ("Tight", "Loose")
    ]
    tasks = [
        Task(name="Strict", programs=["Tight"], watchdog_ms=2),
        Task(name="Relaxed", programs=["Loose"]),  # the default given below: 30 s
    ]
    build = build_project(Project(name="w", pous=pous, tasks=tasks))
    sim = build.simulation(watchdog_s=30.0, watchdog_clock=_Ticks())  # 1 ms per clock reading
    sim.cycle()
    assert [f.task for f in sim.faults] == ["STRICT"] and sim.read("Loose.n") == 30000
    assert sim.faults[0].message == "watchdog: scan exceeded 0.002 s"


def test_a_memory_error_in_a_scan_is_an_out_of_memory_fault_at_its_statement():
    """A simulation's process runs under an address-space limit (simulation/worker.py): running out is a located
    runtime fault like any other, not an internal error."""
    from ladderlab.engine.codegen.faults import make_fault

    compiled = Simulation(prog(pou("MAIN", [slot("X", INT)], [assign(v("X", INT), c(1, INT))]))).compiled
    fault = make_fault(
        MemoryError(), compiled.generated, compiled.filename, {}, task="T", time_ms=10, scan=0, instance_path=str
    )
    assert (fault.kind, fault.code, fault.message) == (
        "runtime_error",
        "out_of_memory",
        "out of memory: the scan needs more memory than allowed",
    )
