"""LadderLab against its limit and its peers (issue 27), printed as ratios with the load average.

* **Hand-written Python**, the lower bound: the 10,000-network LD program of ``scan.py`` written the way a
  Python programmer would write it by hand (power flow in locals, TON and CTU inlined with their state on the
  program object, the INT addition wrapped in place). It computes the same values as LadderLab's scan (checked
  after the runs); the ratio LadderLab / hand-written is the gap to what Python allows (target <= 1.5x).
* **pyrung** (``pip install '.[bench]'``): the boolean networks of the same program (``A AND NOT B -> C``) as
  pyrung rungs, run by its interpreter (``PLC``) and by its compiled kernel (``CompiledPLC``), against LadderLab
  scanning the same networks.
* **blark**, a second ST parser: see ``parse.py``, which compares it on the texts both accept.

Every figure is the CPU time per scan of a batch of scans, the contenders taking turns batch by batch in the
same process (so a load change hits them alike), best of the rounds; run with ``.venv/bin/python
benchmarks/peers.py``.
"""

from __future__ import annotations

import pathlib
import sys
import time
from collections.abc import Callable

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from benchmarks.common import load_average  # noqa: E402
from benchmarks.scan import NETWORKS, ld_program  # noqa: E402
from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402

ROUNDS = 7
PYRUNG_NETWORKS = 1_000  # pyrung's interpreter takes ~0.5 ms per rung and scan: 1,000 rungs keep a round short

#: One network of ``scan.py``'s program as a Python programmer writes it: the power flow stays in a local.
NETWORK = """    c = s.A{n} and not s.B{n}
    s.C{n} = c
"""
#: ... and every fourth network's TON (PT 100 ms), CTU (PV 5) fed by the timer's Q, ADD and compare.
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
    if cu and not s.CNT{n}_cu and s.CNT{n}_CV < 32767:
        s.CNT{n}_CV += 1
    s.CNT{n}_cu = cu
    s.CNT{n}_Q = s.CNT{n}_CV >= 5
    x = (s.X{n} + 1 + 32768 & 65535) - 32768
    s.X{n} = x
    s.Y{n} = x > 100
"""


#: Networks per state object and function of the hand-written program: CPython specialises an attribute read of a
#: ``__slots__`` object only at offsets below 64 KB, so one object holding every variable would be ~10x slower.
PART = 500


def handwritten(networks: int) -> tuple[list[object], Callable[[int], None]]:
    """The program's state objects (PART networks' variables each, at their initial values: B TRUE in every third
    network, as ``scan.py`` declares it) and its scan function ``scan(now)``."""
    states, parts = [], []
    for first in range(0, networks, PART):
        initial: dict[str, object] = {}
        body = []
        for n in range(first, min(first + PART, networks)):
            initial |= {f"A{n}": False, f"B{n}": n % 3 == 0, f"C{n}": False}
            body.append(NETWORK.format(n=n))
            if n % 4 == 0:
                initial |= {f"T{n}_run": False, f"T{n}_Q": False, f"T{n}_ET": 0, f"T{n}_start": 0}
                initial |= {f"CNT{n}_CV": 0, f"CNT{n}_cu": False, f"CNT{n}_Q": False, f"X{n}": 0, f"Y{n}": False}
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
    start = time.thread_time()
    run(scans)
    return (time.thread_time() - start) / scans * 1e6


def lower_bound() -> None:
    """LadderLab's fast variant against the hand-written program, scan batches taking turns."""
    sim = Simulation(compile_program(ld_program(NETWORKS), "fast"))
    for n in range(0, NETWORKS, 2):  # half the contacts closed, so timers, counters and coils all move
        sim.write(f"MAIN.A{n}", True)
    states, scan = handwritten(NETWORKS)

    def variable(name: str, n: int) -> object:
        return getattr(states[n // PART], name)

    for n in range(0, NETWORKS, 2):
        setattr(states[n // PART], f"A{n}", True)
    clock = {"now": 0}

    def by_hand(scans: int) -> None:
        for _ in range(scans):
            clock["now"] += 10
            scan(clock["now"])

    ours, theirs = [], []
    for _ in range(ROUNDS):
        ours.append(_per_scan_us(sim.cycle, 8))
        theirs.append(_per_scan_us(by_hand, 8))
    same = all(
        sim.read(f"MAIN.{name}") == variable(name, n)
        for n in range(0, NETWORKS, 4)
        for name in (f"C{n}", f"X{n}", f"Y{n}")
    ) and all(sim.read(f"MAIN.CNT{n}.CV") == variable(f"CNT{n}_CV", n) for n in range(0, NETWORKS, 4))
    print(
        f"{NETWORKS} LD networks, per scan (CPU, best of {ROUNDS}): LadderLab fast {min(ours):.0f} us, "
        f"hand-written Python {min(theirs):.0f} us: {min(ours) / min(theirs):.2f}x the lower bound "
        f"(target <= 1.5x); same values: {'yes' if same else 'NO'}; {load_average()}"
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
    sim = Simulation(compile_program(ld_program(PYRUNG_NETWORKS), "fast"))  # the same rungs, plus its timers
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
    pyrung_peer()


if __name__ == "__main__":
    main()
