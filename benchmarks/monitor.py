"""Online-monitoring benchmark (issues 6 and 17): websocket clients watching simulations in their processes.

A real uvicorn server runs in this process; each simulation runs in its own worker process; the
websocket clients run in a child process. Two programs, 10 ms task:

* ``array``: 10,000 variables (an ARRAY OF DINT) all changing every scan. Runs: no client;
  10 clients x 1,000 paths at 50 ms; 100 clients x 100 paths at 50 ms (issue 6);
* ``ld``: the 10,000-network LD program of benchmarks/diagrams.py, a third of its rungs
  conducting (timers, counters and adders running). Runs: no client; one client viewing 20
  networks (their element states) and one client watching 1,000 paths; 10 clients viewing 20
  networks each in different parts of the program (issue 17, item 6: the server reads only what
  some client watches).

Reported per run: scan rate (target: the task's 100 scans/s held, within 2 %), mean scan time and
pacer overruns (from the simulation's info); latency from the moment the simulation's process read
the values after a scan to a client receiving them (target p99 <= 100 ms; both stamped with
``time.time()`` on this machine); CPU of the server process and of the simulation's process, as %
of one core; and the load average. ``--seconds`` sets the length of each run, ``--case`` picks one.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import pathlib
import re
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT), str(ROOT / "benchmarks")]

VARIABLES = 10_000
NETWORKS = 10_000
INTERVAL_MS = 50


def array_project():
    from ladderlab.model import Pou, Project, Task

    body = f"FOR i := 1 TO {VARIABLES} DO\n    V[i] := V[i] + 1;\nEND_FOR;"
    declarations = f"VAR\n    V : ARRAY[1..{VARIABLES}] OF DINT;\n    i : INT;\nEND_VAR"
    return Project(
        name="array",
        pous=[Pou(name="Main", kind="program", language="st", declarations=declarations, body=body)],
        tasks=[Task(name="T", interval="T#10ms", programs=["Main"])],
    )


def ld_project():
    from diagrams import project

    return project("ld", NETWORKS).model_copy(update={"name": "ld"})


def serve(projects) -> tuple[str, object, object]:
    """A uvicorn server with the benchmark projects; returns (address, registry, server)."""
    import uvicorn

    from ladderlab.server.app import create_app
    from ladderlab.simulation.registry import SimulationRegistry
    from ladderlab.storage import Workspace

    workspace = Workspace(pathlib.Path(tempfile.mkdtemp()) / "workspace")
    for project in projects:
        workspace.create(project)
    app = create_app(workspace)
    registry = app.state.simulations = SimulationRegistry()
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", timeout_graceful_shutdown=1))
    threading.Thread(target=server.run, kwargs={"sockets": [listener]}, daemon=True).start()
    while not server.started:
        time.sleep(0.01)
    return f"127.0.0.1:{listener.getsockname()[1]}", registry, server


def request(address: str, method: str, path: str, body: object = None) -> dict:
    import httpx

    headers = {"Content-Type": "application/json"}  # what the server takes for a state-changing request
    response = httpx.request(method, f"http://{address}{path}", json=body, timeout=120, headers=headers)
    response.raise_for_status()
    return response.json() if response.content else {}


class Stamps:
    """Listener on a simulation: when its process read the values of each published scan."""

    def __init__(self, handle) -> None:
        self.handle = handle
        self.walls: dict[int, float] = {}

    def event(self, message) -> None:
        pass

    def frame(self) -> None:
        frame = self.handle.frame
        self.walls.setdefault(frame.scan, frame.wall)

    def closed(self) -> None:
        pass


def cpu_seconds(pid: int) -> float:
    fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run(address: str, sim_id: str, handle, clients: list[dict], seconds: float) -> dict[str, float]:
    """Measure ``seconds`` of running with ``clients`` (each: paths, elements) connected (none: no client)."""
    stamps = Stamps(handle)
    handle.attach(stamps)
    child = None
    if clients:
        subscriptions = pathlib.Path(tempfile.mkdtemp()) / "clients.json"
        subscriptions.write_text(json.dumps(clients))
        child = subprocess.Popen(
            [sys.executable, __file__, "--client", address, sim_id, str(seconds + 2), str(subscriptions)],
            stdout=subprocess.PIPE,
            text=True,
        )
        assert child.stdout is not None
        assert child.stdout.readline().strip() == "subscribed"
        time.sleep(1.0)  # let the first (full) snapshots go out
    worker = handle.process.pid
    before = request(address, "GET", f"/api/simulations/{sim_id}")
    cpu, worker_cpu, wall = time.process_time(), cpu_seconds(worker), time.monotonic()
    time.sleep(seconds)
    cpu, wall = time.process_time() - cpu, time.monotonic() - wall
    worker_cpu = cpu_seconds(worker) - worker_cpu
    after = request(address, "GET", f"/api/simulations/{sim_id}")
    load = os.getloadavg()[0]
    latencies = []
    if child is not None:
        out, _ = child.communicate()
        for scan, received in json.loads(out):
            if scan in stamps.walls and before["scan_count"] < scan <= after["scan_count"]:
                latencies.append((received - stamps.walls[scan]) * 1000.0)
    handle.detach(stamps)
    scans = after["scan_count"] - before["scan_count"]
    mean_scan = (
        (after["scan_ms"]["avg"] * after["scan_count"] - before["scan_ms"]["avg"] * before["scan_count"]) / scans
        if scans
        else 0.0
    )
    result = {
        "scans_per_s": scans / wall,
        "mean_scan_ms": mean_scan,
        "overruns": after["overruns"] - before["overruns"],
        "server_cpu": 100.0 * cpu / wall,
        "worker_cpu": 100.0 * worker_cpu / wall,
        "load": load,
    }
    if latencies:
        latencies.sort()
        result |= {
            "messages": len(latencies),
            "latency_p50_ms": statistics.median(latencies),
            "latency_p99_ms": latencies[min(len(latencies) - 1, int(0.99 * len(latencies)))],
            "latency_max_ms": latencies[-1],
        }
    return result


async def clients_main(address: str, sim_id: str, seconds: float, clients: list[dict]) -> None:
    """Child process: one connection per client; prints [scan, arrival time] of every values message."""
    from websockets.asyncio.client import connect

    arrivals: list[tuple[int, float]] = []

    async def one(subscription: dict, ready: asyncio.Event, done: list[int]) -> None:
        async with connect(f"ws://{address}/api/simulations/{sim_id}/ws", max_size=None) as ws:
            await ws.send(json.dumps({"type": "subscribe", "interval_ms": INTERVAL_MS, **subscription}))
            done.append(1)
            if len(done) == len(clients):
                ready.set()
            end = time.monotonic() + seconds
            while (left := end - time.monotonic()) > 0:
                try:
                    text = await asyncio.wait_for(ws.recv(), left)
                except TimeoutError:
                    break
                if text.startswith('{"type":"values"'):
                    arrivals.append((json.loads(text)["scan"], time.time()))

    ready, done = asyncio.Event(), []
    tasks = [asyncio.create_task(one(c, ready, done)) for c in clients]
    await ready.wait()
    print("subscribed", flush=True)
    await asyncio.gather(*tasks)
    print(json.dumps(arrivals), flush=True)


def report(label: str, r: dict[str, float]) -> None:
    print(
        f"{label}: scan rate {r['scans_per_s']:.1f}/s (target 100), mean scan {r['mean_scan_ms']:.2f} ms, "
        f"overruns {r['overruns']}; CPU: server {r['server_cpu']:.0f}%, simulation {r['worker_cpu']:.0f}% of a core; "
        f"load average {r['load']:.1f}"
    )
    if "messages" in r:
        print(
            f"{label}: latency scan -> client p50 {r['latency_p50_ms']:.1f} ms, p99 {r['latency_p99_ms']:.1f} ms "
            f"(target <= 100), max {r['latency_max_ms']:.1f} ms over {r['messages']} messages"
        )


def network_elements() -> dict[int, list[str]]:
    """The probed elements of each network of the LD program (as an online view subscribes them)."""
    from ladderlab.simulation.build import build_project

    build = build_project(ld_project(), "monitor")
    by_network: dict[int, list[str]] = {}
    for element in build.compiled.generated.context.probes_of("MAIN").elements:
        by_network.setdefault(int(re.match(r"[a-z]+(\d+)", element).group(1)), []).append(element)
    return by_network


def view(elements: dict[int, list[str]], first: int, count: int = 20) -> dict:
    ids = [e for n in range(first, first + count) for e in elements[n]]
    return {"paths": [], "elements": [{"pou_instance": "Main", "ids": ids}]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--case", choices=["array", "ld"], help="one program only")
    parser.add_argument("--client", nargs=4, metavar=("ADDRESS", "SIM", "SECONDS", "FILE"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.client:
        address, sim_id, seconds, subscriptions = args.client
        asyncio.run(clients_main(address, sim_id, float(seconds), json.loads(pathlib.Path(subscriptions).read_text())))
        return
    cases = [args.case] if args.case else ["array", "ld"]
    projects = [array_project() if case == "array" else ld_project() for case in cases]
    address, registry, server = serve(projects)
    print(f"monitor: 10 ms task, clients at {INTERVAL_MS} ms, {args.seconds:g} s per run, each simulation in a process")
    for case in cases:
        start = time.monotonic()
        sim_id = request(address, "POST", f"/api/projects/{case}/simulations")["id"]
        print(f"{case}: simulation built in {time.monotonic() - start:.1f} s")
        handle = registry.get(sim_id).handle  # type: ignore[attr-defined]
        if case == "array":
            runs = [
                ("array, no clients", []),
                (
                    "array, 10 clients x 1000 paths",
                    [{"paths": [f"Main.V[{(k * 1000 + i) % VARIABLES + 1}]" for i in range(1000)]} for k in range(10)],
                ),
                (
                    "array, 100 clients x 100 paths",
                    [{"paths": [f"Main.V[{(k * 100 + i) % VARIABLES + 1}]" for i in range(100)]} for k in range(100)],
                ),
            ]
        else:
            for n in range(0, NETWORKS, 3):  # a third of the rungs conduct: their timers, counters, adders run
                handle.call("write", path=f"Main.A{n}", value=True)
            elements = network_elements()
            runs = [
                ("ld 10,000 networks, no clients", []),
                (
                    "ld 10,000 networks, 1 client viewing 20 networks + 1 client watching 1000 paths",
                    [view(elements, 5000), {"paths": [f"Main.X{4 * k}" for k in range(1000)]}],
                ),
                (
                    "ld 10,000 networks, 10 clients viewing 20 networks each",
                    [view(elements, 1000 * k + 7) for k in range(10)],
                ),
            ]
        request(address, "POST", f"/api/simulations/{sim_id}/start")
        time.sleep(1.0)
        for label, clients in runs:
            report(label, run(address, sim_id, handle, clients, args.seconds))
        request(address, "DELETE", f"/api/simulations/{sim_id}")
    registry.close()  # type: ignore[attr-defined]
    server.should_exit = True  # type: ignore[attr-defined]


if __name__ == "__main__":
    main()
