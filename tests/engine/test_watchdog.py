"""The per-task watchdog (ST-12, ST-33, ST-93 [REC]): endless loops stop the task with a located fault."""

from __future__ import annotations

import time

from ladderlab.engine.simulation import Simulation

from .irbuild import (
    BOOL,
    INT,
    add,
    assign,
    c,
    call,
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
        wall_clock=ticks,
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
    sim = Simulation(prog(pou("MAIN", [slot("X", INT)], blocks)), watchdog_s=0.05, wall_clock=_Ticks())
    sim.cycle()
    fault = sim.fault
    assert fault.kind == "watchdog" and (fault.origin.pou, fault.origin.network) == ("MAIN", "N2")
    assert fault.values == {} and sim.read("MAIN.X") > 256


def test_endless_repeat_inside_a_function_names_the_function():
    k = v("K", INT)
    spin = function("SPIN", INT, [slot("K", INT)], [repeat([assign(k, add(k, c(1, INT)))], c(False, BOOL))])
    main = pou("MAIN", [slot("R", INT)], [assign(v("R", INT), call("SPIN", type=INT, user=True))])
    sim = Simulation(prog(main, spin), watchdog_s=0.05, wall_clock=_Ticks())
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
    sim = Simulation(program, watchdog_s={"strict": 0.0005, "SLOWOK": 30.0}, wall_clock=_Ticks())
    sim.cycle()
    assert [f.task for f in sim.faults] == ["STRICT"] and sim.read("A.I") == 30000
