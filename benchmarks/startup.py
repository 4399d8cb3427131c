"""Startup benchmark (issue 27): how long ``ladderlab serve`` takes to answer ``/api/health`` against a bare FastAPI
app served by uvicorn the same way, and how long the first simulation of the example project takes to open.

Each round starts both servers as fresh processes, one after the other (the order alternates), and times from
the start of the process to the first answer of ``/api/health``; the ratio of the two in the same round is the
figure (target: at most 1.5x). Then the served example is opened as a simulation (``POST
/api/projects/{example}/simulations``; target: under 0.3 s), right after the answer and ``WARM_S`` later.
Prints the medians with the load average.
"""

from __future__ import annotations

import compileall
import http.client
import json
import os
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
#: A user's first click comes seconds after the page loaded: the worker machinery (the fork server, which
#: imports the compiler) starts beside the answering server and is ready by then.
WARM_S = 2.0
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


def _until_healthy(process: subprocess.Popen, port: int, started: float) -> tuple[float, float]:
    """(wall seconds, CPU seconds of the server's process) until its first answer of /api/health."""
    while True:
        if process.poll() is not None:
            raise RuntimeError(f"the server ended with {process.returncode} before answering")
        try:
            if _request(port, "GET", "/api/health", timeout=1.0)[0] == 200:
                return time.perf_counter() - started, _cpu_s(process.pid)
        except OSError:
            time.sleep(0.005)


def _cpu_s(pid: int) -> float:
    """User + system CPU seconds of process ``pid`` so far (all its threads; Linux ``/proc``): on the shared machine
    wall times mostly measure the other helpers' load, CPU times measure the work."""
    fields = pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _stop(process: subprocess.Popen) -> None:
    process.terminate()
    try:
        process.wait(10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


def bare_start() -> tuple[float, float]:
    port = _free_port()
    started = time.perf_counter()
    process = subprocess.Popen([sys.executable, "-c", BARE, str(port)])
    try:
        return _until_healthy(process, port, started)
    finally:
        _stop(process)


def _open(port: int, project: str) -> float:
    """Seconds ``project`` takes to open as a simulation."""
    opened = time.perf_counter()
    status, body = _request(port, "POST", f"/api/projects/{project}/simulations")
    if status != 201:
        raise RuntimeError(f"opening the example failed: {status} {body[:200]!r}")
    return time.perf_counter() - opened


def ladderlab_start() -> tuple[tuple[float, float], float, float]:
    """((wall, CPU) seconds to the first /api/health answer, seconds the first simulation of the example took to open
    right after it, seconds the next one took ``WARM_S`` later: the server has started its workers by then)."""
    port = _free_port()
    with tempfile.TemporaryDirectory() as workspace:
        started = time.perf_counter()
        process = subprocess.Popen(
            [sys.executable, "-m", "ladderlab.cli", "serve", "--port", str(port), "--workspace", workspace],
            stdout=subprocess.DEVNULL,
        )
        try:
            healthy = _until_healthy(process, port, started)
            _, body = _request(port, "GET", "/api/projects")
            names = [p["name"] for p in json.loads(body)]
            first = _open(port, names[0])
            time.sleep(WARM_S)
            return healthy, first, _open(port, names[0])
        finally:
            _stop(process)


def main() -> None:
    _compile_sources()
    ratios, cpu_ratios, bares, ours, bare_cpus, our_cpus, firsts, warms = [], [], [], [], [], [], [], []
    for round_ in range(ROUNDS):
        if round_ % 2:
            ((healthy, cpu), first, warm), (bare, bare_cpu) = ladderlab_start(), bare_start()
        else:
            (bare, bare_cpu), ((healthy, cpu), first, warm) = bare_start(), ladderlab_start()
        bares.append(bare)
        ours.append(healthy)
        bare_cpus.append(bare_cpu)
        our_cpus.append(cpu)
        firsts.append(first)
        warms.append(warm)
        ratios.append(healthy / bare)
        cpu_ratios.append(cpu / bare_cpu)
    print(
        f"/api/health: ladderlab serve {statistics.median(ours):.2f} s, bare FastAPI {statistics.median(bares):.2f} s: "
        f"{statistics.median(ratios):.2f}x (rounds {min(ratios):.2f}-{max(ratios):.2f}x; target <= 1.5x); "
        f"process CPU {statistics.median(our_cpus):.2f} s / {statistics.median(bare_cpus):.2f} s: "
        f"{statistics.median(cpu_ratios):.2f}x (rounds {min(cpu_ratios):.2f}-{max(cpu_ratios):.2f}x); {load_average()}"
    )
    print(
        f"first simulation of the example, {WARM_S:g} s after /api/health: {statistics.median(warms) * 1000:.0f} ms "
        f"({min(warms) * 1000:.0f}-{max(warms) * 1000:.0f}; target < 300 ms); right after /api/health (waits for "
        f"the workers): {statistics.median(firsts) * 1000:.0f} ms ({min(firsts) * 1000:.0f}-{max(firsts) * 1000:.0f}); "
        f"{load_average()}"
    )


def _compile_sources() -> None:
    """Byte-compile LadderLab as an installed package is (pip compiles on install; the bare app's FastAPI is): a
    checkout run with PYTHONDONTWRITEBYTECODE would otherwise compile every module at every start."""
    compileall.compile_dir(ROOT / "backend" / "ladderlab", quiet=1)


if __name__ == "__main__":
    main()
