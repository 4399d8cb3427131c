"""Fixtures and helpers shared by the simulation and monitor tests (no tests here).

Projects are small ST programs on a 10 ms task, so scan-by-scan values are easy to
state; ``recv`` waits for a websocket message with a timeout, so a missing message
fails a test instead of hanging it.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Iterator
from typing import Any

import anyio
import pytest
from fastapi.testclient import TestClient
from starlette.testclient import WebSocketTestSession

from ladderlab.model import Project, Task
from ladderlab.simulation.registry import SimulationEntry, SimulationRegistry, SimulationSettings
from ladderlab.storage import Workspace

from .helpers import st_program

#: Counts scans; Flag toggles; Result divides by Divisor (0 is a runtime fault on line 3).
COUNTER_DECLARATIONS = """VAR
    Count : INT;
    Flag : BOOL;
    Divisor : INT := 1;
    Result : INT;
    Idle : INT := 7;
    Trig : BOOL;
END_VAR
VAR RETAIN
    Kept : DINT;
END_VAR"""
COUNTER_BODY = """Count := Count + 1;
Flag := NOT Flag;
Result := 100 / Divisor;"""

#: Shorter timings for tests; stop may wait for the simulation up to 1 s (a loaded machine may hold the process back
#: longer than the 50 ms a server waits before answering 202: test_workers.py tests that).
FAST = SimulationSettings(idle_timeout_s=60.0, reap_every_s=0.05, publish_s=0.01, answer_s=1.0)


def counter_project(name: str = "counter", interval: str = "T#10ms") -> Project:
    return Project(
        name=name,
        pous=[st_program("Main", COUNTER_DECLARATIONS, COUNTER_BODY)],
        tasks=[Task(name="Fast", interval=interval, programs=["Main"])],
    )


def install(client: TestClient, settings: SimulationSettings = FAST) -> SimulationRegistry:
    registry = SimulationRegistry(settings)
    client.app.state.simulations = registry  # type: ignore[attr-defined]
    return registry


@pytest.fixture
def registry(client: TestClient) -> Iterator[SimulationRegistry]:
    registry = install(client)
    yield registry
    registry.close()


@pytest.fixture
def counter(client: TestClient, workspace: Workspace, registry: SimulationRegistry) -> str:
    """A stopped simulation of ``counter_project()``; returns its id."""
    workspace.create(counter_project())
    response = client.post("/api/projects/counter/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


@pytest.fixture
def motor_sim(client: TestClient, motor: str, registry: SimulationRegistry) -> str:
    """A stopped simulation of the motor example (LD Main, ST Blinker, FBD Scaling)."""
    response = client.post("/api/projects/motor/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def entry(registry: SimulationRegistry, sim_id: str) -> SimulationEntry:
    return registry.get(sim_id)


def recv(ws: WebSocketTestSession, timeout: float = 3.0) -> dict[str, Any]:
    """The next message from the server, or a failure after ``timeout`` seconds."""

    async def receive() -> Any:
        with anyio.fail_after(timeout):
            return await ws._send_rx.receive()

    message = ws.portal.call(receive)
    assert message["type"] == "websocket.send", message
    return json.loads(message["text"])


def recv_until(
    ws: WebSocketTestSession, predicate: Callable[[dict[str, Any]], bool], timeout: float = 3.0
) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """Read until a message satisfies ``predicate``; returns it and every message read before it."""
    end = time.monotonic() + timeout
    seen: list[dict[str, Any]] = []
    while True:
        message = recv(ws, max(0.01, end - time.monotonic()))
        if predicate(message):
            return message, seen
        seen.append(message)


def of_type(kind: str, **fields: Any) -> Callable[[dict[str, Any]], bool]:
    return lambda message: message["type"] == kind and all(message.get(k) == v for k, v in fields.items())


def log_of(kind: str) -> Callable[[dict[str, Any]], bool]:
    """An online log entry of this kind (state, write, force, release, breakpoint, watchdog, fault, system)."""
    return lambda message: message["type"] == "log" and message["kind"] == kind


def subscribe(ws: WebSocketTestSession, paths: list[str], interval_ms: int = 20, **extra: Any) -> dict[str, Any]:
    """Subscribe and return the first (full) values message."""
    ws.send_json({"type": "subscribe", "paths": paths, "interval_ms": interval_ms, **extra})
    message, _ = recv_until(ws, lambda m: m["type"] in ("values", "error"))
    assert message["type"] == "values", message
    return message


def wait_for(condition: Callable[[], bool], timeout: float = 3.0) -> None:
    end = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < end, "condition not met in time"
        time.sleep(0.005)
