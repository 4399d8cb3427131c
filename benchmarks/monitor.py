"""Online-monitoring benchmark (issue 6): websocket clients watching a simulation that changes every scan.

One simulation with 10,000 variables (an ARRAY OF DINT) all changing every scan on a
10 ms task, served by a real uvicorn server in this process. Websocket clients run in a
child process (so this process's CPU time is the server's): 10 clients subscribed to 1,000
paths each at 50 ms, then 100 clients at 100 paths each. Reported per run:

* scan-time impact: scan rate (target: the task's 100 scans/s held), mean scan time
  and pacer overruns, against the same simulation with no client;
* end-to-end latency from the end of a scan to a client receiving its values (target
  p99 <= 100 ms). Scans are stamped in the server's after-scan hook, arrivals in the
  client process, both with ``time.time()`` on the same machine;
* server CPU (this process: scan thread, event loop, worker threads) as % of one core.

Prints one line per figure. ``--seconds`` sets the length of each run.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import pathlib
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

VARIABLES = 10_000
INTERVAL_MS = 50


def serve() -> tuple[str, object, object]:
    """A uvicorn server with the benchmark project; returns (address, registry, server)."""
    import uvicorn

    from ladderlab.model import Pou, Project, Task
    from ladderlab.server.app import create_app
    from ladderlab.simulation.registry import SimulationRegistry
    from ladderlab.storage import Workspace

    workspace = Workspace(pathlib.Path(tempfile.mkdtemp()) / "workspace")
    body = f"FOR i := 1 TO {VARIABLES} DO\n    V[i] := V[i] + 1;\nEND_FOR;"
    declarations = f"VAR\n    V : ARRAY[1..{VARIABLES}] OF DINT;\n    i : INT;\nEND_VAR"
    workspace.create(
        Project(
            name="bench",
            pous=[Pou(name="Main", kind="program", language="st", declarations=declarations, body=body)],
            tasks=[Task(name="T", interval="T#10ms", programs=["Main"])],
        )
    )
    app = create_app(workspace)
    registry = app.state.simulations = SimulationRegistry()
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", timeout_graceful_shutdown=1))
    threading.Thread(target=server.run, kwargs={"sockets": [listener]}, daemon=True).start()
    while not server.started:
        time.sleep(0.01)
    return f"127.0.0.1:{listener.getsockname()[1]}", registry, server


def request(address: str, method: str, path: str) -> dict:
    import httpx

    headers = {"Content-Type": "application/json"}  # what the server takes for a state-changing request
    response = httpx.request(method, f"http://{address}{path}", timeout=30, headers=headers)
    response.raise_for_status()
    return response.json() if response.content else {}


def run(address: str, sim_id: str, runner, clients: int, paths: int, seconds: float) -> dict[str, float]:
    """Measure ``seconds`` of running with ``clients`` websocket clients (0: none)."""
    stamps: dict[int, float] = {}
    runner.after_scan.append(lambda sim: stamps.__setitem__(sim.scan_count, time.time()))
    child = None
    if clients:
        child = subprocess.Popen(
            [sys.executable, __file__, "--client", address, sim_id, str(clients), str(paths), str(seconds + 2)],
            stdout=subprocess.PIPE,
            text=True,
        )
        assert child.stdout is not None
        assert child.stdout.readline().strip() == "subscribed"
        time.sleep(1.0)  # let the first (full) snapshots go out
    before = request(address, "GET", f"/api/simulations/{sim_id}")
    cpu, wall = time.process_time(), time.monotonic()
    time.sleep(seconds)
    cpu, wall = time.process_time() - cpu, time.monotonic() - wall
    after = request(address, "GET", f"/api/simulations/{sim_id}")
    latencies = []
    if child is not None:
        out, _ = child.communicate()
        for scan, received in json.loads(out):
            if scan in stamps and before["scan_count"] < scan <= after["scan_count"]:
                latencies.append((received - stamps[scan]) * 1000.0)
    runner.after_scan.clear()
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
        "cpu_percent": 100.0 * cpu / wall,
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


async def clients_main(address: str, sim_id: str, clients: int, paths: int, seconds: float) -> None:
    """Child process: ``clients`` connections; prints [scan, arrival time] of every values message."""
    from websockets.asyncio.client import connect

    arrivals: list[tuple[int, float]] = []

    async def one(k: int, ready: asyncio.Event, done: list[int]) -> None:
        offset = (k * paths) % VARIABLES
        async with connect(f"ws://{address}/api/simulations/{sim_id}/ws", max_size=None) as ws:
            subscription = [f"Main.V[{offset + i % VARIABLES + 1}]" for i in range(paths)]
            await ws.send(json.dumps({"type": "subscribe", "paths": subscription, "interval_ms": INTERVAL_MS}))
            done.append(k)
            if len(done) == clients:
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
    tasks = [asyncio.create_task(one(k, ready, done)) for k in range(clients)]
    await ready.wait()
    print("subscribed", flush=True)
    await asyncio.gather(*tasks)
    print(json.dumps(arrivals), flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument(
        "--client", nargs=5, metavar=("ADDRESS", "SIM", "CLIENTS", "PATHS", "SECONDS"), help=argparse.SUPPRESS
    )
    args = parser.parse_args()
    if args.client:
        address, sim_id, clients, paths, seconds = args.client
        asyncio.run(clients_main(address, sim_id, int(clients), int(paths), float(seconds)))
        return
    address, registry, server = serve()
    sim_id = request(address, "POST", "/api/projects/bench/simulations")["id"]
    runner = registry.get(sim_id).runner  # type: ignore[attr-defined]
    request(address, "POST", f"/api/simulations/{sim_id}/start")
    time.sleep(0.5)
    print(
        f"monitor: {VARIABLES} variables changing every scan, 10 ms task, clients at {INTERVAL_MS} ms, "
        f"{args.seconds:g} s per run"
    )
    for label, clients, paths in (
        ("no clients", 0, 0),
        ("10 clients x 1000 paths", 10, 1000),
        ("100 clients x 100 paths", 100, 100),
    ):
        r = run(address, sim_id, runner, clients, paths, args.seconds)
        print(
            f"{label}: scan rate {r['scans_per_s']:.1f}/s (target 100), mean scan {r['mean_scan_ms']:.2f} ms, "
            f"overruns {r['overruns']}"
        )
        print(f"{label}: server CPU {r['cpu_percent']:.0f}% of one core")
        if "messages" in r:
            print(
                f"{label}: latency scan -> client p50 {r['latency_p50_ms']:.1f} ms, p99 {r['latency_p99_ms']:.1f} ms "
                f"(target <= 100), max {r['latency_max_ms']:.1f} ms over {r['messages']} messages"
            )
    registry.close()  # type: ignore[attr-defined]
    server.should_exit = True  # type: ignore[attr-defined]


if __name__ == "__main__":
    main()
