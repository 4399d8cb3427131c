"""Monitoring on against off (issue 27): the LD program of ``diagrams.py`` at several sizes.

Per size, three simulations of the same program scan in batches taking turns (CPU time of this thread, best of
the rounds): the fast variant (monitoring off: ``ladderlab run``, tests), the monitor variant with 20 networks
viewed (what a server simulation runs while a client shows an LD editor: ``Simulation.view``, docs/runtime.md
"Viewed networks") and the monitor variant recording every network (what it ran before, on every scan). A third
of the rungs conduct (timers, counters, adders running). Also the CPU time of reading the 20 viewed networks'
element states, as a monitor frame does (every ``publish_s``, 20 ms by default), and the monitor variant with 20
viewed as a server's runner scans it: only the last scan of each batch of ``B`` between two frames records the
viewed networks (``Simulation.record``; docs/runtime.md, "Scans no frame shows"). ``B`` is 2 for a 10 ms task at
real time and 20 ms frames, 20 at ten times real time.

On a checkout without ``Simulation.view`` (the base, to take turns with) the monitor variant records every
network and the "20 viewed" column is left out (without ``Simulation.record``, the batched ones):
``LADDERLAB_ROOT=/path/to/base`` runs this script on that checkout.
Run ``.venv/bin/python benchmarks/viewed.py [sizes...]`` (default 100, 1,000, 10,000 and 50,000 networks: issue 27's
"every size from 100 to 50,000"; the source limit is raised for the large ones).
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
BATCHES = (2, 10)  # scans between two frames, the last of them recorded


def per_scan_us(sim: Simulation, scans: int) -> float:
    start = time.thread_time()
    sim.cycle(scans)
    return (time.thread_time() - start) / scans * 1e6


def per_scan_batched_us(sim: Simulation, scans: int, batch: int) -> float:
    """As a server's runner scans: each batch of ``batch`` scans records the viewed networks on its last only."""
    start = time.thread_time()
    for _ in range(scans // batch):
        sim.record(False)
        sim.cycle(batch - 1)
        sim.record(True)
        sim.cycle(1)
    return (time.thread_time() - start) / (scans // batch * batch) * 1e6


def measure(networks: int) -> None:
    limit = os.environ.get("LADDERLAB_MAX_SOURCE_CHARACTERS")  # ~50 characters of declarations a network
    os.environ["LADDERLAB_MAX_SOURCE_CHARACTERS"] = str(max(int(limit or 0), 100 * networks))
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
    # (label, simulation, batch: None for one call of every scan, label of the figure it is compared with)
    runs: list[tuple[str, Simulation, int | None, str]] = [
        ("off (fast)", fast, None, "off (fast)"),
        ("every network", every, None, "off (fast)"),
    ]
    if hasattr(viewed, "view"):
        viewed.view({"MAIN": ids})
        runs.append(("20 viewed", viewed, None, "off (fast)"))
    if hasattr(viewed, "record"):  # the runner scans one call at a time: its "off" scans so too
        for batch in BATCHES:
            sim = Simulation(monitor.own_code())
            sim.view({"MAIN": ids})
            off = f"off, batches of {batch}"
            runs += [(off, fast, batch, off), (f"20 viewed, 1 scan in {batch} recorded", sim, batch, off)]
    for n in range(0, networks, 3):
        for sim in {id(sim): sim for _, sim, _, _ in runs}.values():
            sim.write(f"Main.A{n}", True)
    scans = max(1, 40_000 // networks // 20) * 20  # (whole batches)
    times: dict[str, list[float]] = {label: [] for label, *_ in runs}
    read: list[float] = []
    for _ in range(ROUNDS):
        for label, sim, batch, _ in runs:
            times[label].append(per_scan_us(sim, scans) if batch is None else per_scan_batched_us(sim, scans, batch))
        start = time.thread_time()
        (viewed if hasattr(viewed, "view") else every).probes("MAIN", ids)
        read.append((time.thread_time() - start) * 1e6)
    parts = [
        f"{label} {min(times[label]):.1f} us ({min(times[label]) / min(times[base]):.2f}x)"
        for label, _, _, base in runs
    ]
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
    parser.add_argument("sizes", nargs="*", type=int, default=[100, 1_000, 10_000, 50_000])
    for networks in parser.parse_args().sizes:
        measure(networks)


if __name__ == "__main__":
    main()
