"""LadderLab against its limit and its peers (issue 27), printed as ratios with the load average.

* **Hand-written Python**, the lower bound: the 10,000-network LD program of ``diagrams.py`` written the way a
  Python programmer would write it by hand (power flow in locals, TON and CTU inlined with their state on the
  program object, the INT addition wrapped in place). It computes the same values as LadderLab's scan (checked
  after the runs); the ratio LadderLab / hand-written is the gap to what Python allows (target <= 1.5x). Twice:
  the program of ``diagrams.py`` (a timer, a counter and an adder every fourth network) and its counter/timer-heavy
  variant (all three in every network), each against a hand-written program computing the same values.
* **pyrung** (``pip install '.[bench]'``): the boolean networks of the same program (``A AND NOT B -> C``) as
  pyrung rungs, run by its interpreter (``PLC``) and by its compiled kernel (``CompiledPLC``), against LadderLab
  scanning the same networks.
* **blark**, a second ST parser: see ``parse.py``, which compares it on the texts both accept.

Every figure is the CPU time per scan of a batch of scans, the contenders taking turns batch by batch in the
same process (so a load change hits them alike), each batch after one untimed warm-up scan of its own contender
(every contender alike: the batch before it was another's), best of the rounds; run with ``.venv/bin/python
benchmarks/peers.py`` (``LADDERLAB_ROOT=/path/to/base`` measures that checkout's engine with these benchmarks).
"""

from __future__ import annotations

import pathlib
import sys
import time
from collections.abc import Callable

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT)]

from benchmarks.common import load_average  # noqa: E402
from benchmarks.diagrams import ENGINE, NETWORKS, project  # noqa: E402  # (puts the engine measured on the path)
from benchmarks.diagrams import TIMED as TIMED_EVERY  # noqa: E402
from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.ir.lower_project import lower_project  # noqa: E402

ROUNDS = 7
PYRUNG_NETWORKS = 1_000  # pyrung's interpreter takes ~0.5 ms per rung and scan: 1,000 rungs keep a round short

#: One network of ``diagrams.py``'s LD program as a Python programmer writes it: the power flow stays in a local.
NETWORK = """    c = s.A{n} and not s.B{n}
    s.C{n} = c
"""
#: ... and every fourth network's parallel branches: TON (PT 100 ms) on C, CTU (PV 5) on the timer's Q driving Y,
#: and the ADD box with EN counting X up while C is on (INT: wraps at 32767).
TIMED = """    if not c:
        s.T{n}_run = s.T{n}_Q = False
        s.T{n}_ET = 0
    else:
        if not s.T{n}_run:
            s.T{n}_run, s.T{n}_start = True, now
        elapsed = now - s.T{n}_start
        if elapsed >= 100:
            s.T{n}_Q, s.T{n}_ET = True, 100
        else:
            s.T{n}_Q, s.T{n}_ET = False, elapsed
    cu = s.T{n}_Q
    if cu and not s.K{n}_cu and s.K{n}_CV < 32767:
        s.K{n}_CV += 1
    s.K{n}_cu = cu
    q = s.K{n}_CV >= 5
    s.K{n}_Q = q
    s.Y{n} = q
    if c:
        s.X{n} = (s.X{n} + 1 + 32768 & 65535) - 32768
"""
#: Networks per state object and function of the hand-written program: CPython specialises an attribute read of a
#: ``__slots__`` object only at offsets below 64 KB, so one object holding every variable would be ~10x slower.
PART = 500


def handwritten(networks: int, timed: int = TIMED_EVERY) -> tuple[list[object], Callable[[int], None]]:
    """The program's state objects (PART networks' variables each, at their initial values) and its scan
    function ``scan(now)``; every ``timed``-th network has the timer, counter and adder."""
    states, parts = [], []
    for first in range(0, networks, PART):
        initial: dict[str, object] = {}
        body = []
        for n in range(first, min(first + PART, networks)):
            initial |= {f"A{n}": False, f"B{n}": False, f"C{n}": False}
            body.append(NETWORK.format(n=n))
            if n % timed == 0:
                initial |= {f"T{n}_run": False, f"T{n}_Q": False, f"T{n}_ET": 0, f"T{n}_start": 0}
                initial |= {f"K{n}_CV": 0, f"K{n}_cu": False, f"K{n}_Q": False, f"X{n}": 0, f"Y{n}": False}
                body.append(TIMED.format(n=n))
        namespace: dict[str, object] = {}
        exec(f"class State:\n    __slots__ = {tuple(initial)!r}\n", namespace)
        exec("def scan(s, now):\n" + "".join(body), namespace)
        state = namespace["State"]()  # type: ignore[operator]
        for name, value in initial.items():
            setattr(state, name, value)
        states.append(state)
        parts.append((state, namespace["scan"]))

    def scan(now: int) -> None:
        for state, part in parts:
            part(state, now)

    return states, scan


def _per_scan_us(run: Callable[[int], None], scans: int) -> float:
    """CPU time per scan of a batch of ``scans``, after one scan untimed: the contenders take turns, so each batch
    would otherwise start on caches the others' batches filled (a larger program paying more for it)."""
    run(1)
    start = time.thread_time()
    run(scans)
    return (time.thread_time() - start) / scans * 1e6


def _ld_simulation(networks: int, variant: str = "fast", timed: int = TIMED_EVERY) -> Simulation:
    lowered = lower_project(project("ld", networks, timed))
    assert lowered.program is not None
    return Simulation(compile_program(lowered.program, variant))


def lower_bound(timed: int = TIMED_EVERY) -> None:
    """LadderLab (fast and monitor variant) against the hand-written program, batches of scans taking turns;
    ``timed``: every how many networks have a timer, a counter and an adder."""
    fast, monitor = _ld_simulation(NETWORKS, timed=timed), _ld_simulation(NETWORKS, "monitor", timed)
    states, scan = handwritten(NETWORKS, timed)
    for n in range(0, NETWORKS, 3):  # a third of the rungs conduct, as in diagrams.py
        for sim in (fast, monitor):
            sim.write(f"Main.A{n}", True)
        setattr(states[n // PART], f"A{n}", True)
    clock = {"now": 0}

    def by_hand(scans: int) -> None:
        for _ in range(scans):
            clock["now"] += 10
            scan(clock["now"])

    ours, watched, theirs = [], [], []
    for _ in range(ROUNDS):
        ours.append(_per_scan_us(fast.cycle, 8))
        watched.append(_per_scan_us(monitor.cycle, 8))
        theirs.append(_per_scan_us(by_hand, 8))

    def variable(name: str, n: int) -> object:
        return getattr(states[n // PART], name)

    same = all(
        fast.read(f"Main.{name}") == variable(name, n) == monitor.read(f"Main.{name}")
        for n in range(NETWORKS)
        for name in ([f"C{n}", f"X{n}", f"Y{n}"] if n % timed == 0 else [f"C{n}"])
    ) and all(fast.read(f"Main.K{n}.CV") == variable(f"K{n}_CV", n) for n in range(0, NETWORKS, timed))
    off, on, bound = min(ours), min(watched), min(theirs)
    program = "diagrams.py" if timed == TIMED_EVERY else "a TON, CTU and ADD in every network"
    print(
        f"{NETWORKS} LD networks ({program}), per scan (CPU, best of {ROUNDS}): LadderLab {off:.0f} us, "
        f"hand-written Python {bound:.0f} us: {off / bound:.2f}x the lower bound (target <= 1.5x); the monitor "
        f"variant recording every network {on:.0f} us = {on / off:.2f}x off (no target: a server records only the "
        f"viewed networks, benchmarks/viewed.py measures that against 1.3x); same values: {'yes' if same else 'NO'}; "
        f"engine {ENGINE.parent}; {load_average()}"
    )


def pyrung_peer() -> None:
    try:
        import pyrung
        from pyrung.core import CompiledPLC
    except ImportError:
        print("pyrung: not installed (pip install '.[bench]' to compare)")
        return
    a = [pyrung.Bool(f"A{n}") for n in range(PYRUNG_NETWORKS)]
    b = [pyrung.Bool(f"B{n}") for n in range(PYRUNG_NETWORKS)]
    c = [pyrung.Bool(f"C{n}") for n in range(PYRUNG_NETWORKS)]
    with pyrung.Program(strict=False) as logic:  # rungs made in a loop
        for n in range(PYRUNG_NETWORKS):
            with pyrung.rung(a[n], ~b[n]):
                pyrung.out(c[n])
    interpreted, compiled = pyrung.PLC(logic), CompiledPLC(logic)
    sim = _ld_simulation(PYRUNG_NETWORKS)  # the same rungs, plus the timers, counters and adders
    ours, theirs, kernel = [], [], []
    for _ in range(3):
        ours.append(_per_scan_us(sim.cycle, 20))
        theirs.append(_per_scan_us(lambda k: [interpreted.step() for _ in range(k)], 2))
        kernel.append(_per_scan_us(lambda k: [compiled.step() for _ in range(k)], 20))
    print(
        f"{PYRUNG_NETWORKS} LD networks, per scan (CPU, best of 3): LadderLab {min(ours):.0f} us (with the TON, CTU "
        f"and ADD of every fourth network), pyrung interpreter {min(theirs):.0f} us ({min(theirs) / min(ours):.0f}x "
        f"LadderLab), pyrung compiled {min(kernel):.0f} us ({min(kernel) / min(ours):.1f}x); {load_average()}"
    )


def main() -> None:
    lower_bound()
    lower_bound(timed=1)  # the counter/timer-heavy variant
    pyrung_peer()


if __name__ == "__main__":
    main()
