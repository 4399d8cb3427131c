"""Diagram benchmark (issue 5): a generated 10,000-network LD program and the same logic in FBD, from the
project model through the LD/FBD lowering and the engine.

Each network: ``--| A |--|/ B |--( C )--``; every fourth also ``--| C |--[TON]--[CTU]--( Y )--`` and an
ADD box with EN counting while C is on. Figures (issue 5 targets, 2-core machine): lowering + compile
(<= 3 s), microseconds per scan with monitoring off (fast variant, <= 5 ms) and on (monitor variant:
probes, no pause points, <= 2x off), and the debug variant (probes and pause points: what the server
switches to while breakpoints are set or a step runs). Prints one line per figure, wall and CPU time, for
each of ``--runs`` fresh processes per language, then the build's best / median / worst.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import re
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
#: The engine measured: this checkout's, or another's (``LADDERLAB_ROOT=/path/to/base``) with these benchmarks
ENGINE = pathlib.Path(os.environ.get("LADDERLAB_ROOT") or ROOT) / "backend"
sys.path[:0] = [str(ENGINE), str(ROOT)]

from ladderlab.engine.compile import compile_program  # noqa: E402
from ladderlab.engine.simulation import Simulation  # noqa: E402
from ladderlab.ir.lower_project import lower_project  # noqa: E402
from ladderlab.model import fbd, ld  # noqa: E402
from ladderlab.model.project import Pou, Project, Task  # noqa: E402
from ladderlab.st.parser import parse_expression  # noqa: E402

NETWORKS = 10_000


#: Every TIMED-th network has the timer, counter and adder branches; ``peers.py``'s counter/timer-heavy variant
#: gives them to every network (``timed=1``).
TIMED = 4


def declarations(networks: int, timed: int = TIMED) -> str:
    lines = ["VAR"]
    for n in range(networks):
        lines.append(f"    A{n}, B{n}, C{n} : BOOL;")
        if n % timed == 0:
            lines.append(f"    T{n} : TON; K{n} : CTU; X{n} : INT; Y{n} : BOOL;")
    return "\n".join(lines + ["END_VAR"])


def ld_network(n: int, timed: int = TIMED) -> ld.LdNetwork:
    elements: list = [
        ld.Contact(id=f"a{n}", var=f"A{n}"),
        ld.Contact(id=f"b{n}", var=f"B{n}", mode="nc"),
        ld.Coil(id=f"c{n}", var=f"C{n}"),
    ]
    if n % timed:
        return ld.LdNetwork(id=f"n{n}", elements=elements)
    timers = [
        ld.Contact(id=f"tc{n}", var=f"C{n}"),
        ld.Box(id=f"t{n}", call="TON", instance=f"T{n}", inputs={"PT": "T#100ms"}),
        ld.Box(id=f"k{n}", call="CTU", instance=f"K{n}", inputs={"PV": "5"}),
        ld.Coil(id=f"y{n}", var=f"Y{n}"),
    ]
    add = [ld.Box(id=f"x{n}", call="ADD", en=True, inputs={"IN1": f"X{n}", "IN2": "1"}, outputs={"OUT": f"X{n}"})]
    return ld.LdNetwork(
        id=f"n{n}", elements=[*elements[:2], ld.Parallel(id=f"p{n}", branches=[[elements[2]], timers, add])]
    )


def fbd_network(n: int) -> fbd.FbdNetwork:
    def wire(a: str, b: str) -> fbd.Wire:
        (x, p), (y, q) = a.split("."), b.split(".")
        return fbd.Wire.model_validate({"from": {"node": x, "pin": p}, "to": {"node": y, "pin": q}})

    nodes: list = [
        fbd.InputNode(id=f"a{n}", expr=f"A{n}"),
        fbd.InputNode(id=f"b{n}", expr=f"B{n}"),
        fbd.Block(id=f"g{n}", call="AND", pins={"IN2": fbd.PinFlags(negated=True)}),
        fbd.OutputNode(id=f"c{n}", var=f"C{n}"),
    ]
    wires = [wire(f"a{n}.OUT", f"g{n}.IN1"), wire(f"b{n}.OUT", f"g{n}.IN2"), wire(f"g{n}.OUT", f"c{n}.IN")]
    if n % 4 == 0:
        nodes += [
            fbd.InputNode(id=f"pt{n}", expr="T#100ms"),
            fbd.Block(id=f"t{n}", call="TON", instance=f"T{n}"),
            fbd.InputNode(id=f"pv{n}", expr="5"),
            fbd.Block(id=f"k{n}", call="CTU", instance=f"K{n}"),
            fbd.OutputNode(id=f"y{n}", var=f"Y{n}"),
            fbd.InputNode(id=f"x{n}", expr=f"X{n}"),
            fbd.InputNode(id=f"one{n}", expr="1"),
            fbd.Block(id=f"add{n}", call="ADD", en=True),
            fbd.OutputNode(id=f"xo{n}", var=f"X{n}"),
        ]
        wires += [
            wire(f"g{n}.OUT", f"t{n}.IN"),
            wire(f"pt{n}.OUT", f"t{n}.PT"),
            wire(f"t{n}.Q", f"k{n}.CU"),
            wire(f"pv{n}.OUT", f"k{n}.PV"),
            wire(f"k{n}.Q", f"y{n}.IN"),
            wire(f"g{n}.OUT", f"add{n}.EN"),
            wire(f"x{n}.OUT", f"add{n}.IN1"),
            wire(f"one{n}.OUT", f"add{n}.IN2"),
            wire(f"add{n}.OUT", f"xo{n}.IN"),
        ]
    return fbd.FbdNetwork(id=f"n{n}", nodes=nodes, wires=wires)


def project(language: str, networks: int, timed: int = TIMED) -> Project:
    """``timed``: every how many networks have the timer, counter and adder (LD only; FBD every fourth)."""
    body = (
        ld.LdBody(networks=[ld_network(n, timed) for n in range(networks)])
        if language == "ld"
        else fbd.FbdBody(networks=[fbd_network(n) for n in range(networks)])
    )
    pou = Pou(
        name="Main",
        kind="program",
        language=language,
        declarations=declarations(networks, timed if language == "ld" else TIMED),
        body=body,
    )
    return Project(name="bench", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


def per_scan_us(sims: dict[str, Simulation], rounds: int) -> dict[str, tuple[float, float]]:
    """Median wall and CPU microseconds per scan of each simulation. The simulations take turns scan by
    scan, so a change in the machine's load affects all of them alike (the ratios are what count)."""
    for sim in sims.values():
        for n in range(0, NETWORKS, 3):  # a third of the rungs conduct: their timers, counters and adders run
            sim.write(f"Main.A{n}", True)
        sim.cycle(5)  # warm up the interpreter's specialisation
    wall: dict[str, list[float]] = {name: [] for name in sims}
    cpu: dict[str, list[float]] = {name: [] for name in sims}
    for _ in range(rounds):
        for name, sim in sims.items():
            before, before_cpu = time.perf_counter(), time.process_time()
            sim.cycle(1)
            wall[name].append((time.perf_counter() - before) * 1e6)
            cpu[name].append((time.process_time() - before_cpu) * 1e6)
    return {name: (statistics.median(wall[name]), statistics.median(cpu[name])) for name in sims}


def main() -> None:
    """Each language in fresh processes (the second does not run amid the first one's heap), ``--runs`` times:
    the shared machine has slow spells, so the build figure is summarised as best / median / worst."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--language", choices=["ld", "fbd"], help="measure one language in this process")
    parser.add_argument("--runs", type=int, default=3, help="fresh processes per language (default 3)")
    arguments = parser.parse_args()
    if arguments.language is not None:
        measure(arguments.language)
        return
    for language in ("ld", "fbd"):
        builds = []
        for _ in range(arguments.runs):
            run = subprocess.run(
                [sys.executable, __file__, "--language", language], check=True, capture_output=True, text=True
            )
            print(run.stdout, end="")
            builds += [float(found) for found in re.findall(r"lowering \+ compile ([0-9.]+) s CPU", run.stdout)]
        builds.sort()
        print(
            f"{language.upper()} lowering + compile over {len(builds)} fresh processes: best {builds[0]:.2f} s, "
            f"median {statistics.median(builds):.2f} s, worst {builds[-1]:.2f} s CPU (target <= 3 s)"
        )


def measure(language: str) -> None:
    cpu = time.process_time()
    parse_expression("0")  # the LALR parser is built once per process (the server's first build pays it)
    print(f"ST parser built once: {time.process_time() - cpu:.2f} s CPU")
    model = project(language, NETWORKS)
    start, cpu = time.perf_counter(), time.process_time()
    result = lower_project(model)  # as build_project: the ST check of the declarations, then the networks
    _lowered, lowered_cpu = time.perf_counter() - start, time.process_time() - cpu
    assert result.program is not None, [d.format() for d in result.diagnostics[:5]]
    compiled = compile_program(result.program, "fast")
    build, build_cpu = time.perf_counter() - start, time.process_time() - cpu
    # CPU time: the machine is shared, wall time includes waiting for a core
    print(
        f"{language.upper()} {NETWORKS} networks: lowering {lowered_cpu:.2f} s CPU, compile "
        f"{build_cpu - lowered_cpu:.2f} s CPU, lowering + compile {build_cpu:.2f} s CPU / {build:.2f} s wall "
        "(target <= 3 s)"
    )
    name = language.upper()
    times = per_scan_us({"fast": Simulation(compiled), "monitor": Simulation(result.program, variant="monitor")}, 15)
    (off, off_cpu), (on, on_cpu) = times["fast"], times["monitor"]
    debug, debug_cpu = per_scan_us({"debug": Simulation(result.program, variant="debug")}, 10)["debug"]
    print(f"{name} scan, monitoring off (fast variant): {off:.0f} us wall, {off_cpu:.0f} us CPU (target <= 5000 us)")
    print(
        f"{name} scan, monitoring on (monitor variant): {on:.0f} us wall, {on_cpu:.0f} us CPU = "
        f"{on_cpu / off_cpu:.2f}x off in CPU time, {on / off:.2f}x in wall time (target <= 2x)"
    )
    print(
        f"{name} scan, debug variant (probes and pause points): {debug:.0f} us wall, {debug_cpu:.0f} us CPU = "
        f"{debug_cpu / off_cpu:.2f}x off"
    )


if __name__ == "__main__":
    main()
