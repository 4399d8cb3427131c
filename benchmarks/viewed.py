"""Monitoring on against off (issue 27): the LD program of ``diagrams.py`` at several sizes.

Per size, three simulations of the same program scan in batches taking turns (CPU time of this thread, best of
the rounds): the fast variant (monitoring off: ``ladderlab run``, tests), the monitor variant with 20 networks
viewed (what a server simulation runs while a client shows an LD editor: ``Simulation.view``, docs/runtime.md
"Viewed networks") and the monitor variant recording every network (what it ran before, on every scan). A third
of the rungs conduct (timers, counters, adders running). Also the CPU time of reading the 20 viewed networks'
element states, as a monitor frame does (every ``publish_s``, 20 ms by default).

On a checkout without ``Simulation.view`` (the base, to take turns with) the monitor variant records every
network and the "20 viewed" column is left out: ``LADDERLAB_ROOT=/path/to/base`` runs this script on that checkout.
Run ``.venv/bin/python benchmarks/viewed.py [sizes...]``.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import sys
import time

ROOT = pathlib.Path(os.environ.get("LADDERLAB_ROOT") or pathlib.Path(__file__).resolve().parents[1])  # the base's
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from benchmarks.common import load_average  # noqa: E402
from benchmarks.diagrams import project  # noqa: E402
from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.ir.lower_project import lower_project  # noqa: E402

VIEWED = 20  # networks an LD editor shows
ROUNDS = 7


def per_scan_us(sim: Simulation, scans: int) -> float:
    start = time.thread_time()
    sim.cycle(scans)
    return (time.thread_time() - start) / scans * 1e6


def measure(networks: int) -> None:
    lowered = lower_project(project("ld", networks))
    assert lowered.program is not None
    fast = Simulation(compile_program(lowered.program, "fast"))
    monitor = compile_program(lowered.program, "monitor")
    # Each simulation runs code objects of its own, as a server's one simulation of a program does: two running the
    # same ones in turns undo each other's specialisation (CompiledProgram.own_code), which cost the "20 viewed"
    # batches ~0.5 us a scan at 100 networks (more than recording the probes) until 2026-11-29.
    every, viewed = Simulation(monitor), Simulation(monitor.own_code() if hasattr(monitor, "own_code") else monitor)
    first = networks // 2  # the middle of the program
    ids = [e for e in monitor.generated.context.probes_of("MAIN").elements if first <= _network(e) < first + VIEWED]
    sims = {"off (fast)": fast, "every network": every}
    if hasattr(viewed, "view"):
        viewed.view({"MAIN": ids})
        sims["20 viewed"] = viewed
    for n in range(0, networks, 3):
        for sim in sims.values():
            sim.write(f"Main.A{n}", True)
    scans = max(4, 40_000 // networks)
    times: dict[str, list[float]] = {label: [] for label in sims}
    read: list[float] = []
    for _ in range(ROUNDS):
        for label, sim in sims.items():
            times[label].append(per_scan_us(sim, scans))
        start = time.thread_time()
        (viewed if "20 viewed" in sims else every).probes("MAIN", ids)
        read.append((time.thread_time() - start) * 1e6)
    off = min(times["off (fast)"])
    parts = [f"{label} {min(ts):.1f} us ({min(ts) / off:.2f}x)" for label, ts in times.items()]
    print(
        f"{networks} networks, per scan (CPU, best of {ROUNDS} x {scans} scans): {', '.join(parts)}; "
        f"reading the 20 viewed networks {min(read):.0f} us; {load_average()}",
        flush=True,
    )


def _network(element: str) -> int:
    digits = "".join(c for c in element if c.isdigit())
    return int(digits) if digits else -1


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sizes", nargs="*", type=int, default=[100, 1_000, 10_000])
    for networks in parser.parse_args().sizes:
        measure(networks)


if __name__ == "__main__":
    main()
