"""Scan-engine benchmark: what a scan of an empty one-task program costs (the scan loop alone, issue 27: at most
0.4 us), microseconds per scan of the ironplc-benchmarks programs, and build time, microseconds per scan and peak
memory of a 10,000-network LD-style program.

The program is IR built directly, the way the LD lowering emits a rung: every
contact's power flow into a hidden BOOL slot, a coil reading the last one,
probes per element (dropped by the fast variant); every fourth network also
has a TON, a CTU fed by the timer, an ADD and a compare. Targets (issue 4):
<= 5 ms per scan, <= 3 s build (IR -> runnable) and <= 300 MB peak memory on the 2-core dev machine.
Prints one line per figure; wall and CPU time, as the CPU time is what a busy machine does not inflate.

Peak memory is the ``ru_maxrss`` (peak resident set) of a fresh process per part: the ironplc programs,
then the 10,000-network program built and scanned in the fast, the monitor and the debug variant, each
part in its own ``python benchmarks/scan.py --part NAME`` child, so no part inherits another's heap.
"""

from __future__ import annotations

import argparse
import pathlib
import resource
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.ir import nodes as ir  # noqa: E402
from ladderlab.ir import types as t  # noqa: E402
from ladderlab.simulation.build import build_project  # noqa: E402
from ladderlab.st.project_text import source_to_project  # noqa: E402

BOOL, INT, TIME = t.Elementary("BOOL"), t.Elementary("INT"), t.Elementary("TIME")


def _var(name: str, ty: t.IrType, *path: ir.Member) -> ir.Var:
    return ir.Var("local", name, ty, tuple(path))


def ld_program(networks: int) -> ir.Program:
    slots: list[ir.Slot] = []
    blocks: list[ir.Block] = []
    for n in range(networks):
        net = f"N{n}"

        def at(element: str, net: str = net) -> ir.Origin:
            return ir.Origin("MAIN", network=net, element=element)

        a, b, coil, h1, h2 = (f"A{n}", f"B{n}", f"C{n}", f"E{n}_1", f"E{n}_2")
        slots += [
            ir.Slot(a, "VAR", BOOL),
            ir.Slot(b, "VAR", BOOL, n % 3 == 0),
            ir.Slot(coil, "VAR", BOOL),
            ir.Slot(h1, "VAR", BOOL, hidden=True),
            ir.Slot(h2, "VAR", BOOL, hidden=True),
        ]
        va, vb, vc, v1, v2 = (_var(x, BOOL) for x in (a, b, coil, h1, h2))
        statements: list[ir.Stmt] = [
            ir.Assign(v1, va, at("E1")),
            ir.Probe("E1", v1, at("E1")),
            ir.Assign(v2, ir.Binary("AND", v1, ir.Unary("NOT", vb, BOOL), BOOL), at("E2")),
            ir.Probe("E2", v2, at("E2")),
            ir.Assign(vc, v2, at("E3")),
            ir.Probe("E3", v2, at("E3")),
        ]
        if n % 4 == 0:
            ton, ctu, x, y = f"T{n}", f"CNT{n}", f"X{n}", f"Y{n}"
            slots += [
                ir.Slot(ton, "VAR", t.FbInstance("TON")),
                ir.Slot(ctu, "VAR", t.FbInstance("CTU")),
                ir.Slot(x, "VAR", INT),
                ir.Slot(y, "VAR", BOOL),
            ]
            vx = _var(x, INT)
            statements += [
                ir.FbCall(_var(ton, t.FbInstance("TON")), [("IN", vc), ("PT", ir.Const(100, TIME))], [], at("E4")),
                ir.FbCall(
                    _var(ctu, t.FbInstance("CTU")),
                    [("CU", _var(ton, BOOL, ir.Member("Q"))), ("PV", ir.Const(5, INT))],
                    [],
                    at("E5"),
                ),
                ir.Assign(vx, ir.Binary("ADD", vx, ir.Const(1, INT), INT), at("E6")),
                ir.Assign(_var(y, BOOL), ir.Binary("GT", vx, ir.Const(100, INT), BOOL), at("E7")),
            ]
        blocks.append(ir.Block(statements, ir.Origin("MAIN", network=net)))
    main = ir.Pou("MAIN", "program", slots, blocks, language="ld")
    return ir.Program({"MAIN": main}, [], [ir.TaskSpec("CYCLIC", 10, 0, ["MAIN"])])


def ironplc_programs() -> None:
    """Microseconds per scan of each ironplc-benchmarks program (../shared/external; skipped when absent)."""
    folder = ROOT.parent / "shared" / "external" / "ironplc-benchmarks" / "programs"
    if not folder.is_dir():
        print(f"ironplc-benchmarks: {folder} not present, skipped")
        return
    for path in sorted(folder.glob("*.st")):
        project, _ = source_to_project(path.read_text(encoding="utf-8"), path.stem)
        build = build_project(project) if project is not None else None
        if build is None or build.compiled is None:
            print(f"scan ironplc-benchmarks/{path.name}: does not build (see tests/external/test_ironplc.py)")
            continue
        sim = build.simulation()
        sim.cycle(100)
        before = time.perf_counter()
        sim.cycle(1000)
        print(f"scan ironplc-benchmarks/{path.name}: {(time.perf_counter() - before) / 1000 * 1e6:.1f} us per scan")


EMPTY = "PROGRAM Main\nVAR x : INT; END_VAR\nEND_PROGRAM\n"  # one task (the default), nothing to run
EMPTY_SCANS, EMPTY_ROUNDS = 20_000, 7


def empty_program() -> None:
    """Thread CPU per scan of a one-task program with an empty body: what the scan loop itself costs (issue 27
    item 1: at most 0.4 us; statistics, forces and the watchdog cost nothing while unused). Best of the rounds."""
    project, _ = source_to_project(EMPTY, "empty")
    build = build_project(project) if project is not None else None
    assert build is not None and build.compiled is not None
    sim = build.simulation()
    sim.cycle(1000)  # warm up the interpreter's specialisation
    best = min(_thread_cpu(lambda: sim.cycle(EMPTY_SCANS)) for _ in range(EMPTY_ROUNDS))
    print(
        f"scan an empty one-task program: {best / EMPTY_SCANS * 1e6:.2f} us per scan thread CPU, best of "
        f"{EMPTY_ROUNDS} x {EMPTY_SCANS:,} scans (target <= 0.4 us)"
    )


def _thread_cpu(run) -> float:
    before = time.thread_time()
    run()
    return time.thread_time() - before


NETWORKS = 10_000


def peak_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def variant_part(variant: str) -> None:
    """Build the 10,000-network program in one variant and time its scans (in a fresh process)."""
    program = ld_program(NETWORKS)
    start, cpu = time.perf_counter(), time.process_time()
    sim = Simulation(compile_program(program, variant))
    build, build_cpu = time.perf_counter() - start, time.process_time() - cpu
    target = " (target <= 3 s)" if variant == "fast" else ""
    print(
        f"build {NETWORKS} LD networks (IR -> runnable, {variant} variant): {build:.2f} s wall, "
        f"{build_cpu:.2f} s CPU{target}"
    )
    sim.cycle(20)  # warm up the interpreter's specialisation
    samples, cpu_samples = [], []
    for _ in range(15):
        before, cpu = time.perf_counter(), time.process_time()
        sim.cycle(4)
        samples.append((time.perf_counter() - before) / 4 * 1e6)
        cpu_samples.append((time.process_time() - cpu) / 4 * 1e6)
    target = " (target <= 5000 us)" if variant == "fast" else ""
    print(
        f"scan {NETWORKS} LD networks, {variant} variant: {statistics.median(samples):.0f} us per scan wall, "
        f"{statistics.median(cpu_samples):.0f} us CPU{target}"
    )


PARTS = {
    "empty": empty_program,
    "ironplc": ironplc_programs,
    "fast": lambda: variant_part("fast"),
    "monitor": lambda: variant_part("monitor"),
    "debug": lambda: variant_part("debug"),
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--part", choices=PARTS, help="run one part in this process (the children)")
    part = parser.parse_args().part
    if part is not None:
        PARTS[part]()
        print(f"PEAK {peak_mb():.0f}")
        return
    peaks = {}
    for name in PARTS:
        out = subprocess.run(
            [sys.executable, __file__, "--part", name], check=True, capture_output=True, text=True
        ).stdout.splitlines()
        print("\n".join(line for line in out if not line.startswith("PEAK ")), flush=True)
        peaks[name] = float(next(line for line in out if line.startswith("PEAK ")).split()[1])
    shown = ", ".join(f"{name} {mb:.0f} MB" for name, mb in peaks.items())
    print(
        f"peak memory (ru_maxrss of a fresh process per part): {shown}; largest {max(peaks.values()):.0f} MB "
        "(target <= 300 MB)"
    )


if __name__ == "__main__":
    main()
