"""Build benchmark (issue 27 item 3): a 50,000-network LD program from the project model to runnable code.

The networks are diagrams.py's (``--| A |--|/ B |--( C )--``, every fourth with a TON, a CTU and an ADD); the
program's declarations are ~2.5 MB of text, so the source limit is raised for the run. Each run is a fresh
process (the build's heap must not meet a previous one's) and reports process CPU seconds of the lowering (the ST
check of the declarations, then the networks), of the compile step split into the code generator, CPython's
``compile()`` of the generated pieces and the collection that ends the build's collector pause
(ladderlab/collector.py), then of the first scan of a simulation that views no network (as the server's runner
starts one), and the peak resident set (``ru_maxrss``) with what the model alone takes. ``--variant monitor`` builds
what opening a simulation builds. The build runs as a simulation's worker runs it (simulation/worker.py): one
collector pause over the lowering, the compile and the simulation, ending in ``gc.freeze()``
(``collector_paused(for_life=True)``); ``--builds-again`` measures a process that builds again instead (a check
worker, the CLI; a checkout without ``for_life``), whose pauses end in collections. Targets: at most 6 s of CPU
and 600 MB peak. Prints one line per run and the median, with the load average. ``--backend DIR`` measures
another checkout's backend with this script (before/after: ``--backend /work/main/backend``).
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any, TypeVar

ROOT = pathlib.Path(__file__).resolve().parents[1]
BACKEND = str(pathlib.Path(os.environ.get("LADDERLAB_BENCH_BACKEND", ROOT / "backend")).resolve())  # --backend
sys.path[:0] = [BACKEND, str(ROOT)]

import ladderlab  # noqa: E402, F401  # from BACKEND, before benchmarks/diagrams.py puts this checkout's first
from benchmarks.common import load_average  # noqa: E402

NETWORKS = 50_000
T = TypeVar("T")


def _peak_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def measure(networks: int, variant: str, for_life: bool) -> dict[str, float]:
    """One build in this process: CPU seconds per phase and peak MB."""
    os.environ["LADDERLAB_MAX_SOURCE_CHARACTERS"] = str(100 * networks)  # ~50 characters of declarations a network
    from benchmarks.diagrams import project
    from ladderlab.collector import collector_paused
    from ladderlab.engine import compile as compiling
    from ladderlab.engine.simulation import Simulation
    from ladderlab.ir.lower_project import lower_project
    from ladderlab.st.parser import parse_expression

    spent: dict[str, float] = {"generate": 0.0, "compile()": 0.0, "collection": 0.0}

    def timed(name: str, function: Callable[..., T]) -> Callable[..., T]:
        def wrapper(*args: Any, **kwargs: Any) -> T:
            started = time.thread_time()  # the build runs in a thread of its own (ladderlab/deep.py)
            try:
                return function(*args, **kwargs)
            finally:
                spent[name] += time.thread_time() - started

        return wrapper

    compiling.generate = timed("generate", compiling.generate)
    compiling._compile_piece = timed("compile()", compiling._compile_piece)
    gc.collect = timed("collection", gc.collect)  # ladderlab/collector.py's one collection at the end of a pause
    assert pathlib.Path(compiling.__file__).is_relative_to(BACKEND), compiling.__file__
    parse_expression("0")  # the parser's tables load once per process
    model = project("ld", networks)
    model_mb = _peak_mb()
    started = time.process_time()
    with collector_paused(for_life=True) if for_life else contextlib.nullcontext():
        lowered = lower_project(model)
        lowering = time.process_time() - started
        assert lowered.program is not None, [d.format() for d in lowered.diagnostics[:5]]
        lowering_collection = spent["collection"]
        compiled = compiling.compile_program(lowered.program, variant)
        built = time.process_time()
        del lowered
        sim = Simulation(compiled)
    sim.view({})
    sim.cycle(1)
    total = time.process_time() - started
    return {
        "lowering": lowering,
        "lowering collection": lowering_collection,
        "compile": built - started - lowering,
        "generate": spent["generate"],
        "compile()": spent["compile()"],
        "first scan": total - (built - started),
        "total": total,
        "model MB": model_mb,
        "peak MB": _peak_mb(),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="fresh processes (default 3)")
    parser.add_argument("--networks", type=int, default=NETWORKS)
    parser.add_argument("--variant", default="fast", choices=("fast", "monitor"))
    parser.add_argument("--backend", help="the backend directory to measure (default this checkout's)")
    parser.add_argument(
        "--builds-again",
        action="store_true",
        help="build as a process that builds again does (a check worker, the CLI): collected, not frozen",
    )
    parser.add_argument("--one", action="store_true", help="measure one build in this process (JSON)")
    args = parser.parse_args()
    if args.one:
        print(json.dumps(measure(args.networks, args.variant, for_life=not args.builds_again)))
        return
    runs = []
    environment = {**os.environ, "LADDERLAB_BENCH_BACKEND": str(pathlib.Path(args.backend or BACKEND).resolve())}
    for _ in range(args.runs):
        done = subprocess.run(
            [sys.executable, __file__, "--one", "--networks", str(args.networks), "--variant", args.variant]
            + ["--builds-again"] * args.builds_again,
            check=True,
            capture_output=True,
            text=True,
            env=environment,
        )
        run = json.loads(done.stdout.splitlines()[-1])
        runs.append(run)
        print(_line(run))
    median = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
    print(
        f"{args.networks:,} LD networks ({args.variant}, {'builds again' if args.builds_again else 'for life'}, "
        f"{args.backend or BACKEND}), median of {len(runs)}: "
        f"{_line(median)} (targets 6 s, 600 MB); {load_average()}"
    )


def _line(run: dict[str, float]) -> str:
    return (
        f"lowering {run['lowering']:.2f} s CPU (collection {run['lowering collection']:.2f}), compile "
        f"{run['compile']:.2f} (generate {run['generate']:.2f}, compile() {run['compile()']:.2f}), first scan "
        f"{run['first scan']:.2f}, total "
        f"{run['total']:.2f} s; peak {run['peak MB']:.0f} MB (model {run['model MB']:.0f} MB)"
    )


if __name__ == "__main__":
    main()
