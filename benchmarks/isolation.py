"""Isolation benchmark (issue 18, item 2): simulations in worker processes on the 2-core machine.

A real ``ladderlab serve`` runs in a child process with a workspace holding the example project and
the benchmark programs; this process is its client (REST with httpx, websocket with websockets).

* create latency: ``POST /api/projects/motor/simulations`` (the example project): the first right after
  the server answered ``/api/health``, the first a few seconds later, then 20 more (target: the first
  simulation opens in under 0.3 s);
* 16 simulations of a light program on a 13 ms task: each one's scan rate (target 76.9/s each) and
  ``/api/health`` latency meanwhile;
* 16 simulations of a heavy program (about 13 ms of CPU per scan, 14 ms task: 71 scans/s alone): the
  rate of one alone, then of each of the 16 together against what two cores allow, and how many
  watchdog faults they got (target 0: the watchdog counts the scan's own CPU time);
* watchdog response: four nested FOR 1 TO 255 loops (4e9 iterations per scan): from the websocket's
  ``single_cycle`` to the client receiving the watchdog fault (budget 100 ms);
* answers while a scan runs long (a task with a 60 s budget and an endless loop): reading the
  simulation, ``/api/health``, stop and delete (target 100 ms).

Every section prints the load average (other jobs share the machine).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import pathlib
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

import httpx  # noqa: E402

from ladderlab.model import Pou, Project, Task  # noqa: E402
from ladderlab.simulation.build import build_project  # noqa: E402
from ladderlab.storage import Workspace  # noqa: E402
from tests.support import NESTED_LOOPS, NESTED_LOOPS_DECLARATIONS  # noqa: E402

HEAVY_SCAN_MS = 13.0


def program(name: str, declarations: str, body: str, interval: str = "T#10ms", watchdog_ms: int | None = None):
    pou = Pou(name="Main", kind="program", language="st", declarations=declarations, body=body)
    task = Task(name="T", interval=interval, programs=["Main"], watchdog_ms=watchdog_ms)
    return Project(name=name, pous=[pou], tasks=[task])


def heavy(iterations: int) -> Project:
    body = f"FOR i := 1 TO {iterations} DO\n    x := x + i MOD 7;\nEND_FOR;"
    return program("heavy", "VAR\n    i : DINT;\n    x : DINT;\nEND_VAR", body, interval="T#14ms")


def calibrate() -> int:
    """Loop iterations for a scan of about HEAVY_SCAN_MS of CPU (the server's monitor variant)."""
    sim = build_project(heavy(20_000), "monitor").simulation()
    sim.cycle(3)
    start = time.thread_time()
    sim.cycle(10)
    per_iteration_ms = (time.thread_time() - start) * 1000.0 / 10 / 20_000
    return int(HEAVY_SCAN_MS / per_iteration_ms)


def projects(iterations: int) -> list[Project]:
    return [
        program("light", "VAR\n    n : DINT;\nEND_VAR", "n := n + 1;", interval="T#13ms"),
        heavy(iterations),
        program("loops", NESTED_LOOPS_DECLARATIONS, NESTED_LOOPS),
        program("busy", "VAR\n    n : DINT;\nEND_VAR", "WHILE TRUE DO n := n + 1; END_WHILE;", watchdog_ms=60_000),
    ]


class Server:
    """``ladderlab serve`` in a child process on a free port."""

    def __init__(self, workspace: pathlib.Path) -> None:
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.url = f"http://127.0.0.1:{self.port}"
        command = [sys.executable, "-m", "ladderlab.cli", "serve", "--port", str(self.port), "--workspace"]
        self.process = subprocess.Popen([*command, str(workspace)], stderr=subprocess.DEVNULL)
        # every state-changing request as JSON, as the server requires (docs/security.md)
        self.http = httpx.Client(base_url=self.url, timeout=120, headers={"Content-Type": "application/json"})
        while True:
            try:
                if self.http.get("/api/health").status_code == 200:
                    break
            except httpx.TransportError:
                time.sleep(0.02)

    def create(self, project: str) -> tuple[str, float]:
        start = time.perf_counter()
        response = self.http.post(f"/api/projects/{project}/simulations")
        assert response.status_code == 201, response.text
        return response.json()["id"], time.perf_counter() - start

    def timed(self, method: str, path: str) -> tuple[int, float]:
        start = time.perf_counter()
        response = self.http.request(method, path)
        return response.status_code, (time.perf_counter() - start) * 1000.0

    def close(self) -> None:
        self.process.terminate()
        self.process.wait(10)


def load() -> str:
    return f"load average {os.getloadavg()[0]:.1f}"


def descendants(pid: int) -> list[int]:
    """Every process below ``pid`` (the fork server and the simulations' and builds' processes)."""
    children: dict[int, list[int]] = {}
    for stat in pathlib.Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        children.setdefault(int(fields[1]), []).append(int(stat.parent.name))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def cpu_seconds(pids: list[int]) -> float:
    total = 0.0
    for pid in pids:
        try:
            fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    return total


def spread(values: list[float], unit: str = "ms") -> str:
    values = sorted(values)
    p99 = values[min(len(values) - 1, int(0.99 * len(values)))]
    return f"p50 {statistics.median(values):.1f} {unit}, p99 {p99:.1f} {unit}, max {values[-1]:.1f} {unit}"


def create_latency(workspace: pathlib.Path) -> None:
    server = Server(workspace)
    try:
        _, first = server.create("motor")
        time.sleep(3.0)
        _, settled = server.create("motor")
        times = []
        for _ in range(20):
            sim_id, seconds = server.create("motor")
            times.append(seconds * 1000.0)
            server.http.delete(f"/api/simulations/{sim_id}")
        print(
            f"create the example project's simulation: first after start {first * 1000:.0f} ms, first after 3 s "
            f"{settled * 1000:.0f} ms, then {spread(times)} (target < 300 ms); {load()}"
        )
    finally:
        server.close()


def rates(server: Server, ids: list[str], seconds: float) -> tuple[list[float], list[float], list[int], float]:
    """Each simulation's scans per second over ``seconds``, /api/health latencies meanwhile, faults, and the
    CPU the server's worker processes got (in cores)."""
    workers = descendants(server.process.pid)
    before = [server.http.get(f"/api/simulations/{i}").json()["scan_count"] for i in ids]
    start, health, cpu = time.monotonic(), [], cpu_seconds(workers)
    while time.monotonic() - start < seconds:
        health.append(server.timed("GET", "/api/health")[1])
        time.sleep(0.1)
    elapsed = time.monotonic() - start
    cores = (cpu_seconds(workers) - cpu) / elapsed
    infos = [server.http.get(f"/api/simulations/{i}").json() for i in ids]
    per_sim = [(info["scan_count"] - b) / elapsed for info, b in zip(infos, before)]
    faults = [1 if info["fault"] is not None else 0 for info in infos]
    return per_sim, health, faults, cores


def sixteen(workspace: pathlib.Path, seconds: float) -> None:
    server = Server(workspace)
    try:
        for project, label, target in (("light", "light program, 13 ms task", 1000 / 13), ("heavy", "heavy", 0)):
            ids = [server.create(project)[0] for _ in range(16)]
            if project == "heavy":
                server.http.post(f"/api/simulations/{ids[0]}/start")
                time.sleep(1.0)
                alone, _, _, _ = rates(server, ids[:1], seconds)
                server.http.post(f"/api/simulations/{ids[0]}/stop")
                scan_ms = server.http.get(f"/api/simulations/{ids[0]}").json()["scan_ms"]["avg"]
                print(
                    f"heavy program (about {HEAVY_SCAN_MS:g} ms CPU per scan, mean wall {scan_ms:.1f} ms; 14 ms task): "
                    f"alone {alone[0]:.1f} scans/s; {load()}"
                )
                label, target = "heavy program, 16 together", 2000 / HEAVY_SCAN_MS / 16
            for sim_id in ids:
                server.http.post(f"/api/simulations/{sim_id}/start")
            time.sleep(1.0)
            per_sim, health, faults, cores = rates(server, ids, seconds)
            print(
                f"16 simulations, {label}: scans/s each min {min(per_sim):.1f}, "
                f"median {statistics.median(per_sim):.1f}, max {max(per_sim):.1f}, total {sum(per_sim):.0f}/s "
                f"(target {target:.1f} each: "
                f"{'the task rate' if project == 'light' else 'what 2 cores allow'}); faults {sum(faults)}; "
                f"the simulations' processes got {cores:.2f} cores; "
                f"/api/health {spread(health)}; {load()}"
            )
            for sim_id in ids:
                server.http.delete(f"/api/simulations/{sim_id}")
    finally:
        server.close()


async def watchdog_response(server: Server, rounds: int) -> list[float]:
    from websockets.asyncio.client import connect

    sim_id, _ = server.create("loops")
    times = []
    async with connect(f"ws://127.0.0.1:{server.port}/api/simulations/{sim_id}/ws", max_size=None) as ws:
        for _ in range(rounds):
            await ws.send(json.dumps({"type": "write", "path": "Main.Go", "value": True}))
            start = time.perf_counter()
            await ws.send(json.dumps({"type": "single_cycle"}))
            while True:
                message = json.loads(await ws.recv())
                if message["type"] == "log" and message["kind"] == "watchdog":
                    times.append((time.perf_counter() - start) * 1000.0)
                    break
            server.http.post(f"/api/simulations/{sim_id}/reset")
    server.http.delete(f"/api/simulations/{sim_id}")
    return times


def long_scans(workspace: pathlib.Path, rounds: int) -> None:
    server = Server(workspace)
    try:
        times = asyncio.run(watchdog_response(server, rounds))
        print(f"watchdog (100 ms budget), nested loops: single_cycle -> fault at the client {spread(times)}; {load()}")
        answers: dict[str, list[float]] = {"read": [], "health": [], "stop": [], "delete": []}
        for _ in range(rounds):
            sim_id, _ = server.create("busy")
            server.http.post(f"/api/simulations/{sim_id}/start")
            time.sleep(0.3)  # the first scan (60 s budget) is under way
            for _ in range(5):
                answers["read"].append(server.timed("GET", f"/api/simulations/{sim_id}")[1])
                answers["health"].append(server.timed("GET", "/api/health")[1])
            answers["stop"].append(server.timed("POST", f"/api/simulations/{sim_id}/stop")[1])
            answers["delete"].append(server.timed("DELETE", f"/api/simulations/{sim_id}")[1])
        shown = "; ".join(f"{what} {spread(values)}" for what, values in answers.items())
        print(f"answers while a scan runs long (target 100 ms): {shown}; {load()}")
    finally:
        server.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0, help="length of each rate measurement")
    parser.add_argument("--rounds", type=int, default=5, help="repetitions of the watchdog and long-scan figures")
    args = parser.parse_args()
    iterations = calibrate()
    print(f"isolation: heavy program of {iterations} loop iterations (about {HEAVY_SCAN_MS:g} ms CPU per scan)")
    root = pathlib.Path(tempfile.mkdtemp())
    try:
        workspace = Workspace(root / "workspace")
        for project in projects(iterations):
            workspace.create(project)
        shutil.copytree(ROOT / "examples" / "motor", root / "workspace" / "motor")
        create_latency(root / "workspace")
        sixteen(root / "workspace", args.seconds)
        long_scans(root / "workspace", args.rounds)
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
