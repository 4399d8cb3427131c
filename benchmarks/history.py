"""Scan history benchmark (issue 23): what recording costs a running simulation, and how long a seek takes.

The program is scan.py's 10,000-network LD-style program in the monitor variant (the online variant). It
runs ``--scans`` scans (default 100,000) with a write every 50 scans, once without a history and once with
one (the default 256 MB budget): the CPU time per scan of both is the recording overhead, with the
checkpoint interval the history chose, a checkpoint's size and capture time, and the history's memory at
the end. Then ``--seeks`` seeks to random scans of the recorded range (from a cold replay each: the
replay simulation is reset to another checkpoint first), timed. Targets: a seek within the last 100,000
scans <= 1 s. Prints one line per figure, with the load average.
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
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.simulation.history import History  # noqa: E402

NETWORKS = 10_000


def _run(sim: Simulation, scans: int) -> float:
    """CPU seconds per scan of ``scans`` scans, with a write every 50 (the nondeterminism a user brings)."""
    start = time.process_time()
    for number in range(scans):
        if number % 50 == 0:
            sim.write("MAIN.A1", number % 100 == 0)
        sim.cycle(1)
    return (time.process_time() - start) / scans


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scans", type=int, default=100_000)
    parser.add_argument("--seeks", type=int, default=20)
    args = parser.parse_args()
    compiled = compile_program(ld_program(NETWORKS), "monitor")

    plain = Simulation(compiled)
    plain.cycle(20)
    bare = _run(plain, args.scans)
    print(f"{load_average()}; {NETWORKS} networks, monitor variant, {args.scans} scans, a write every 50")
    print(f"scan without history: {bare * 1e6:.0f} us CPU per scan")

    sim = Simulation(compiled)
    history = History(sim)
    sim.on_input = history.applied
    sim.cycle(20)
    recorded = _run(sim, args.scans)
    blob = len(history.checkpoints[-1].blob)
    print(
        f"scan with history: {recorded * 1e6:.0f} us CPU per scan ({(recorded / bare - 1) * 100:+.1f} %); "
        f"checkpoint every {history.interval} scans, {blob / 1024:.0f} KB each, captured in "
        f"{history.capture_s * 1000:.1f} ms CPU"
    )
    print(
        f"history memory: {history.size / 2**20:.1f} MB ({len(history.checkpoints)} checkpoints, "
        f"{history.log_size} bytes of input log) for scans {history.first}..{history.last}"
    )

    rng = random.Random(23)
    times, cpu = [], []
    for _ in range(args.seeks):
        history.seek(history.first)  # away from the target: every seek restores and replays
        target = rng.randint(max(history.first, history.last - 100_000), history.last)
        start, start_cpu = time.perf_counter(), time.process_time()
        history.seek(target)
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    print(
        f"seek to a random scan of the last {min(100_000, history.last - history.first + 1)}: median "
        f"{statistics.median(cpu) * 1000:.0f} ms, max {max(cpu) * 1000:.0f} ms CPU; median "
        f"{statistics.median(times) * 1000:.0f} ms, max {max(times) * 1000:.0f} ms wall (target <= 1 s)"
    )
    print(load_average())


if __name__ == "__main__":
    main()
