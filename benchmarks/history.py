"""Scan history benchmark (issue 23): what recording costs a running simulation, and how long a seek takes.

The program is scan.py's 10,000-network LD-style program in the monitor variant (the online variant). Four
simulations of it, two without a history and two with (the default 256 MB budget), run ``--scans`` scans each
(default 100,000) with a write every 50 scans, taking turns in ``--turns`` blocks (the order rotating), so a
change of the machine's load or clock weighs on all alike; each is compiled on its own, as CPython specialises
the bytecode of a code object for the types it meets and two simulations of one compiled program share its code
objects (the one measured second would pay for the other's specialisation). Compiled copies of one program
also differ in speed by themselves, whatever the history (the same role on another copy moved the figures by up
to 8 points at load 8-10, hist5), so each role is played by two copies compiled alternately, and the two plain
copies' difference is printed: the floor of what the figures resolve. The CPU time per scan of both roles is the
recording overhead; beside it, the share of the scan time the history's own code took (its hooks and
checkpoints, timed inside the recorded runs), the checkpoint interval the history chose, a checkpoint's size and
capture time, and the history's memory at the end. Then ``--seeks`` seeks to random scans of the recorded range
(from a cold replay each: the replay simulation is reset to another checkpoint first), timed, after the first
seek, which builds the replay simulation and is timed on its own. Targets: recording ~5 % of the scan time; a
seek within the last 100,000 scans <= 1 s. Prints one line per figure, with the load average.
"""

from __future__ import annotations

import argparse
import pathlib
import random
import statistics
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from benchmarks.common import load_average  # noqa: E402
from benchmarks.scan import ld_program  # noqa: E402
from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.inputs import AppliedInput  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.simulation.history import History  # noqa: E402

NETWORKS = 10_000


def _run(sim: Simulation, first: int, scans: int) -> float:
    """CPU seconds of scans ``first`` .. ``first + scans - 1``, with a write every 50 (the nondeterminism a user
    brings)."""
    start = time.process_time()
    for number in range(first, first + scans):
        if number % 50 == 0:
            sim.write("MAIN.A1", number % 100 == 0)
        sim.cycle(1)
    return time.process_time() - start


def _turns(sims: list[Simulation], scans: int, turns: int) -> list[float]:
    """CPU seconds per scan of each simulation, ``scans`` each, run in ``turns`` blocks taking turns (each block
    in another order)."""
    spent = [0.0] * len(sims)
    block = scans // turns
    for turn in range(turns):
        for k in range(len(sims)):
            which = (turn + k) % len(sims)
            spent[which] += _run(sims[which], turn * block, block)
    return [total / (block * turns) for total in spent]


class _Timed(History):
    """A history that adds up the CPU time of its own code (the engine's hooks; checkpoints run inside them)."""

    spent = 0.0

    def _scanned(self, scan: int, time_ms: float, scheduled: bool) -> None:
        start = time.process_time()
        super()._scanned(scan, time_ms, scheduled)
        self.spent += time.process_time() - start

    def applied(self, applied: AppliedInput) -> None:
        start = time.process_time()
        super().applied(applied)
        self.spent += time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scans", type=int, default=100_000)
    parser.add_argument("--seeks", type=int, default=20)
    parser.add_argument("--turns", type=int, default=20)
    args = parser.parse_args()

    sims = [Simulation(compile_program(ld_program(NETWORKS), "monitor")) for _ in range(4)]  # own code objects
    recorded = sims[1::2]  # compiled alternately: plain, recorded, plain, recorded
    histories = [_Timed(sim) for sim in recorded]
    for sim, history in zip(recorded, histories):
        sim.on_input = history.applied
    for sim in sims:
        sim.cycle(20)
    for history in histories:
        history.spent = 0.0
    print(f"{load_average()}; {NETWORKS} networks, monitor variant, {args.scans} scans, a write every 50")
    times = _turns(sims, args.scans, args.turns)
    bare, with_history = statistics.mean(times[0::2]), statistics.mean(times[1::2])
    floor = abs(times[2] / times[0] - 1) * 100
    print(
        f"scan without history: {bare * 1e6:.0f} us CPU per scan (the two plain copies: "
        f"{times[0] * 1e6:.0f} / {times[2] * 1e6:.0f} us, {floor:.1f} % apart)"
    )
    own = statistics.mean(h.spent / (t * args.scans) for h, t in zip(histories, times[1::2]))
    history = histories[0]
    blob = len(history.checkpoints[-1].blob)
    print(
        f"scan with history: {with_history * 1e6:.0f} us CPU per scan ({(with_history / bare - 1) * 100:+.1f} %; "
        f"the history's own code {own * 100:.1f} % of it); checkpoint every {history.interval} scans, "
        f"{blob / 1024:.0f} KB each, captured in {history.capture_s * 1000:.1f} ms CPU"
    )
    print(
        f"history memory: {history.size / 2**20:.1f} MB ({len(history.checkpoints)} checkpoints, "
        f"{history.log_size} bytes of input log) for scans {history.first}..{history.last}"
    )

    start, start_cpu = time.perf_counter(), time.process_time()
    history.seek(history.first)  # the first seek builds the replay simulation and compiles the code it records with
    print(
        f"first seek (builds the replay): {(time.process_time() - start_cpu) * 1000:.0f} ms CPU, "
        f"{(time.perf_counter() - start) * 1000:.0f} ms wall"
    )
    rng = random.Random(23)
    walls, cpu = [], []
    for _ in range(args.seeks):
        history.seek(history.first)  # away from the target: every seek restores and replays
        target = rng.randint(max(history.first, history.last - 100_000), history.last)
        start, start_cpu = time.perf_counter(), time.process_time()
        history.seek(target)
        walls.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    print(
        f"seek to a random scan of the last {min(100_000, history.last - history.first + 1)}: median "
        f"{statistics.median(cpu) * 1000:.0f} ms, max {max(cpu) * 1000:.0f} ms CPU; median "
        f"{statistics.median(walls) * 1000:.0f} ms, max {max(walls) * 1000:.0f} ms wall (target <= 1 s)"
    )
    print(load_average())


if __name__ == "__main__":
    main()
