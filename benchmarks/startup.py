"""Startup benchmark (issue 27): how long ``ladderlab serve`` takes to answer ``/api/health`` against a bare FastAPI
app served by uvicorn the same way, and how long the first simulation of the example project takes to open.

Each round starts both servers as fresh processes, one after the other (the order alternates), and times from
the start of the process to the first answer of ``/api/health``; the ratio of the two in the same round is the
figure (target: at most 1.5x). Then the served example is opened as a simulation (``POST
/api/projects/{example}/simulations``; target: under 0.3 s). Prints the medians with the load average.
"""

from __future__ import annotations

import http.client
import json
import pathlib
import socket
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from benchmarks.common import load_average  # noqa: E402

ROUNDS = 5
BARE = """
import sys, uvicorn
from fastapi import FastAPI
app = FastAPI()
@app.get("/api/health")
async def health():
    return {"status": "ok"}
uvicorn.run(app, host="127.0.0.1", port=int(sys.argv[1]), log_level="warning")
"""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _request(port: int, method: str, path: str, timeout: float = 30.0) -> tuple[int, bytes]:
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        headers = {"Content-Type": "application/json"} if method == "POST" else {}
        connection.request(method, path, body=b"{}" if method == "POST" else None, headers=headers)
        response = connection.getresponse()
        return response.status, response.read()
    finally:
        connection.close()


def _until_healthy(process: subprocess.Popen, port: int, started: float) -> float:
    while True:
        if process.poll() is not None:
            raise RuntimeError(f"the server ended with {process.returncode} before answering")
        try:
            if _request(port, "GET", "/api/health", timeout=1.0)[0] == 200:
                return time.perf_counter() - started
        except OSError:
            time.sleep(0.005)


def _stop(process: subprocess.Popen) -> None:
    process.terminate()
    try:
        process.wait(10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def bare_start() -> float:
    port = _free_port()
    started = time.perf_counter()
    process = subprocess.Popen([sys.executable, "-c", BARE, str(port)])
    try:
        return _until_healthy(process, port, started)
    finally:
        _stop(process)


def ladderlab_start() -> tuple[float, float]:
    """(seconds to the first /api/health answer, seconds the first simulation of the example took to open)."""
    port = _free_port()
    with tempfile.TemporaryDirectory() as workspace:
        started = time.perf_counter()
        process = subprocess.Popen(
            [sys.executable, "-m", "ladderlab.cli", "serve", "--port", str(port), "--workspace", workspace],
            stdout=subprocess.DEVNULL,
        )
        try:
            healthy = _until_healthy(process, port, started)
            status, body = _request(port, "GET", "/api/projects")
            names = [p["name"] for p in json.loads(body)]
            opened = time.perf_counter()
            status, body = _request(port, "POST", f"/api/projects/{names[0]}/simulations")
            if status != 201:
                raise RuntimeError(f"opening the example failed: {status} {body[:200]!r}")
            return healthy, time.perf_counter() - opened
        finally:
            _stop(process)


def main() -> None:
    ratios, bares, ours, firsts = [], [], [], []
    for round_ in range(ROUNDS):
        if round_ % 2:
            (healthy, first), bare = ladderlab_start(), bare_start()
        else:
            bare, (healthy, first) = bare_start(), ladderlab_start()
        bares.append(bare)
        ours.append(healthy)
        firsts.append(first)
        ratios.append(healthy / bare)
    print(
        f"/api/health: ladderlab serve {statistics.median(ours):.2f} s, bare FastAPI {statistics.median(bares):.2f} s: "
        f"{statistics.median(ratios):.2f}x (rounds {min(ratios):.2f}-{max(ratios):.2f}x; target <= 1.5x); "
        f"{load_average()}"
    )
    print(
        f"first simulation of the example: {statistics.median(firsts) * 1000:.0f} ms "
        f"({min(firsts) * 1000:.0f}-{max(firsts) * 1000:.0f}; target < 300 ms); {load_average()}"
    )


if __name__ == "__main__":
    main()
