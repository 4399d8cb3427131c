"""Traces over the real websocket (issue 9, "Trace chart"; spec ON-01): every scan recorded and streamed
in ``trace_data`` chunks, triggers (edges and level crossings), ``trace_stop``, limits and refusals."""

from __future__ import annotations

import time
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import given
from hypothesis import strategies as st
from starlette.testclient import WebSocketTestSession

from ladderlab.model import Project, Task
from ladderlab.model.monitor import MAX_TRACE_SAMPLES, TraceTrigger
from ladderlab.simulation.build import build_project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.simulation.trace import TraceBook, plan_trace
from ladderlab.simulation.trace_inbox import TraceInbox
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import counter, counter_project, of_type, recv, recv_until, registry, subscribe

__all__ = ["counter", "registry"]  # fixtures used below

#: A TON with PT = 50 ms on a 10 ms task: Q rises 5 scans after Go.
TIMER_DECLARATIONS = """VAR
    Go : BOOL;
    Timer : TON;
    Q : BOOL;
    ET : TIME;
    Level : REAL := 1.5;
    Name : STRING;
    Numbers : ARRAY[1..3] OF INT;
END_VAR"""
TIMER_BODY = """Timer(IN := Go, PT := T#50ms);
Q := Timer.Q;
ET := Timer.ET;"""


@pytest.fixture
def timer(client: TestClient, workspace: Workspace, registry: SimulationRegistry) -> str:
    workspace.create(
        Project(
            name="timer",
            pous=[st_program("Main", TIMER_DECLARATIONS, TIMER_BODY)],
            tasks=[Task(name="Fast", interval="T#10ms", programs=["Main"])],
        )
    )
    response = client.post("/api/projects/timer/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def ws_url(sim_id: str) -> str:
    return f"/api/simulations/{sim_id}/ws"


def connect(ws: WebSocketTestSession) -> None:
    """Skip the opening status; a 20 ms subscription makes chunks come every 20 ms."""
    recv(ws)
    subscribe(ws, [], interval_ms=20)


def cycles(ws: WebSocketTestSession, n: int) -> None:
    for _ in range(n):
        ws.send_json({"type": "single_cycle"})


def collect(ws: WebSocketTestSession, until: Any, timeout: float = 3.0) -> tuple[dict[str, Any], list[dict]]:
    """Merge ``trace_data`` chunks until ``until(merged)``; returns the merge and the chunks."""
    merged: dict[str, Any] = {"scans": [], "time_ms": [], "values": {}, "triggered": None, "state": None}
    chunks: list[dict] = []
    end = time.monotonic() + timeout
    while not until(merged):
        chunk, _ = recv_until(ws, of_type("trace_data"), max(0.01, end - time.monotonic()))
        chunks.append(chunk)
        merged["scans"] += chunk["scans"]
        merged["time_ms"] += chunk["time_ms"]
        for path, column in chunk["values"].items():
            merged["values"].setdefault(path, []).extend(column)
        merged["triggered"] = merged["triggered"] or chunk["triggered"]
        merged["state"] = chunk["state"]
    return merged, chunks


def done(merged: dict) -> bool:
    return merged["state"] == "done"


def test_samples_stream_while_recording_and_trace_stop_ends_it(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        connect(ws)
        ws.send_json({"type": "trace_start", "id": 7, "paths": ["main.count", "Main.Flag", "MAIN.COUNT"]})
        first, _ = recv_until(ws, of_type("trace_data"))
        assert first == {
            "type": "trace_data",
            "id": 7,
            "state": "recording",
            "scans": [],
            "time_ms": [],
            "values": {"MAIN.COUNT": [], "MAIN.FLAG": []},
            "triggered": None,
            "lost": 0,
            "types": {"MAIN.COUNT": {"name": "INT", "names": None}, "MAIN.FLAG": {"name": "BOOL", "names": None}},
        }
        cycles(ws, 3)
        merged, _ = collect(ws, lambda m: len(m["scans"]) >= 3)  # before the trace ends: it is live
        assert merged["values"] == {"MAIN.COUNT": [1, 2, 3], "MAIN.FLAG": [True, False, True]}
        assert (merged["scans"], merged["time_ms"], merged["state"]) == ([1, 2, 3], [10.0, 20.0, 30.0], "recording")
        cycles(ws, 2)
        ws.send_json({"type": "trace_stop"})
        rest, chunks = collect(ws, done)
        assert rest["values"] == {"MAIN.COUNT": [4, 5], "MAIN.FLAG": [False, True]} and rest["scans"] == [4, 5]
        assert all(c["id"] == 7 for c in chunks)
        cycles(ws, 1)
        ws.send_json({"type": "trace_stop"})  # nothing recorded after the end, and nothing left to stop
        error, seen = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == ("bad_state", "no trace is running: start one with trace_start")
        assert not [m for m in seen if m["type"] == "trace_data"]


def test_a_ton_q_rises_at_exactly_pt_in_the_trace_of_a_rising_edge_trigger(client: TestClient, timer: str) -> None:
    with client.websocket_connect(ws_url(timer)) as ws:
        connect(ws)
        ws.send_json(
            {
                "type": "trace_start",
                "paths": ["Main.Q", "Main.ET", "Main.Go"],
                "samples": 8,
                "trigger": {"path": "Main.Go", "condition": "rising"},
            }
        )
        waiting, _ = recv_until(ws, of_type("trace_data"))
        assert waiting["state"] == "waiting" and waiting["scans"] == []
        cycles(ws, 2)  # Go FALSE: nothing recorded
        ws.send_json({"type": "write", "path": "Main.Go", "value": True})
        cycles(ws, 10)
        merged, _ = collect(ws, done)
    assert merged["triggered"] == {"scan": 3, "time_ms": 30.0}
    assert merged["scans"] == [3, 4, 5, 6, 7, 8, 9, 10]
    assert merged["values"] == {
        "MAIN.Q": [False, False, False, False, False, True, True, True],
        "MAIN.ET": [0, 10, 20, 30, 40, 50, 50, 50],
        "MAIN.GO": [True] * 8,
    }
    edge = merged["values"]["MAIN.Q"].index(True)
    assert merged["time_ms"][edge] - merged["triggered"]["time_ms"] == 50.0  # PT


def test_falling_and_level_crossing_triggers_start_at_the_scan_that_crosses(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        connect(ws)
        ws.send_json(
            {
                "type": "trace_start",
                "paths": ["Main.Count"],
                "samples": 2,
                "trigger": {"path": "Main.Count", "condition": "cross_up", "level": 4.5},
            }
        )
        cycles(ws, 7)
        merged, _ = collect(ws, done)
        assert (merged["triggered"], merged["scans"], merged["values"]) == (
            {"scan": 5, "time_ms": 50.0},
            [5, 6],
            {"MAIN.COUNT": [5, 6]},
        )

        # Count is 7: exactly at the level counts as crossed (from above).
        ws.send_json(
            {
                "type": "trace_start",
                "id": 2,
                "paths": ["Main.Count"],
                "samples": 1,
                "trigger": {"path": "Main.Count", "condition": "cross_down", "level": 3},
            }
        )
        cycles(ws, 1)
        ws.send_json({"type": "write", "path": "Main.Count", "value": 2})  # 8 -> 3 in the next scan
        cycles(ws, 2)
        merged, _ = collect(ws, done)
        assert (merged["triggered"], merged["values"]) == ({"scan": 9, "time_ms": 90.0}, {"MAIN.COUNT": [3]})

        # Scan 10 left Flag FALSE (it toggles every scan): it rises at scan 11 and falls at scan 12.
        ws.send_json(
            {
                "type": "trace_start",
                "id": 3,
                "paths": ["Main.Flag", "Main.Count"],
                "samples": 3,
                "trigger": {"path": "Main.Flag", "condition": "falling"},
            }
        )
        cycles(ws, 4)
        merged, chunks = collect(ws, done)
        assert merged["triggered"] == {"scan": 12, "time_ms": 120.0}
        assert merged["values"] == {"MAIN.FLAG": [False, True, False], "MAIN.COUNT": [6, 7, 8]}
        assert {c["id"] for c in chunks} == {3}


def test_a_trace_goes_on_through_a_reset_which_keeps_scan_numbers_and_time(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        connect(ws)
        ws.send_json({"type": "trace_start", "paths": ["Main.Count"], "samples": 4})
        cycles(ws, 2)
        collect(ws, lambda m: len(m["scans"]) == 2)
        assert client.post(f"/api/simulations/{counter}/reset?cold=true").status_code == 200
        cycles(ws, 2)
        merged, _ = collect(ws, done)
    assert (merged["scans"], merged["time_ms"], merged["values"]) == ([3, 4], [30.0, 40.0], {"MAIN.COUNT": [1, 2]})


def test_running_records_every_scan_without_gaps(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        connect(ws)
        ws.send_json({"type": "trace_start", "paths": ["Main.Count"]})
        ws.send_json({"type": "run"})
        live, chunks = collect(ws, lambda m: len(m["scans"]) >= 30)
        ws.send_json({"type": "trace_stop"})
        rest, _ = collect(ws, done)
    assert len([c for c in chunks if c["scans"]]) >= 2  # streamed in several chunks, not at the end
    scans = live["scans"] + rest["scans"]
    assert scans == list(range(1, len(scans) + 1))  # every scan, in order (Count counts scans)
    assert live["values"]["MAIN.COUNT"] + rest["values"]["MAIN.COUNT"] == scans
    assert live["time_ms"] + rest["time_ms"] == [10.0 * s for s in scans]


@pytest.mark.parametrize(
    ("message", "code", "text"),
    [
        (
            {"type": "trace_start", "paths": ["Main.Q"] * 21},
            "bad_message",
            "trace_start.paths: List should have at most 20 items after validation, not 21",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Q"], "samples": 10_001},
            "bad_message",
            "trace_start.samples: Input should be less than or equal to 10000",
        ),
        (
            {"type": "trace_start", "paths": []},
            "bad_message",
            "trace_start.paths: List should have at least 1 item after validation, not 0",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Q"], "trigger": {"path": "Main.ET", "condition": "cross_up"}},
            "bad_message",
            "trace_start.trigger: Value error, a cross_up trigger needs a level",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Q"], "trigger": {"path": "Main.Go", "level": 1}},
            "bad_message",
            "trace_start.trigger: Value error, a rising trigger has no level (it watches a BOOL)",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Name"]},
            "bad_path",
            "MAIN.NAME is not a BOOL or numeric variable: a trace records BOOL and numeric variables (trace the "
            "elements of arrays and structures)",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Numbers"]},
            "bad_path",
            "MAIN.NUMBERS is not a BOOL or numeric variable: a trace records BOOL and numeric variables (trace the "
            "elements of arrays and structures)",
        ),
        ({"type": "trace_start", "paths": ["Main.Qq"]}, "bad_path", "MAIN has no variable 'Qq' - did you mean 'Q'?"),
        (
            {
                "type": "trace_start",
                "paths": ["Main.Q"],
                "trigger": {"path": "Main.Go", "condition": "cross_down", "level": 1},
            },
            "bad_path",
            "the trigger MAIN.GO is not numeric: cross_down compares a number with a level (use rising or "
            "falling for a BOOL)",
        ),
        ({"type": "trace_stop"}, "bad_state", "no trace is running: start one with trace_start"),
    ],
)
def test_bad_trace_requests_are_refused_with_a_clear_error(
    client: TestClient, timer: str, message: dict, code: str, text: str
) -> None:
    with client.websocket_connect(ws_url(timer)) as ws:
        connect(ws)
        ws.send_json(message)
        error, seen = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == (code, text)
        assert not [m for m in seen if m["type"] == "trace_data"]


def test_twenty_paths_are_accepted_including_array_elements_and_times(client: TestClient, timer: str) -> None:
    paths = ["Main.Numbers[1]", "Main.Numbers[3]", "Main.Level", "Main.ET"] + ["Main.Numbers[2]"] * 16
    with client.websocket_connect(ws_url(timer)) as ws:
        connect(ws)
        ws.send_json({"type": "trace_start", "paths": paths, "samples": 1})
        cycles(ws, 1)
        merged, _ = collect(ws, done)
    assert merged["values"] == {
        "MAIN.NUMBERS[1]": [0],
        "MAIN.NUMBERS[3]": [0],
        "MAIN.LEVEL": [1.5],
        "MAIN.ET": [0],
        "MAIN.NUMBERS[2]": [0],
    }


def test_samples_a_client_does_not_take_are_capped_and_counted_as_lost() -> None:
    """In the simulation's process: samples not handed over yet are capped at MAX_TRACE_SAMPLES, the newest kept."""
    sim = build_project(counter_project()).simulation()
    book = TraceBook()
    book.start("client", 1, plan_trace(sim.location, ["Main.Count"], None), None, sim)
    for _ in range(MAX_TRACE_SAMPLES + 5):
        sim.cycle(1)
        book.sample(sim)
    chunk = book.take_all()["client"]
    assert chunk["lost"] == 5
    assert chunk["scans"][0] == 6 and chunk["scans"][-1] == MAX_TRACE_SAMPLES + 5
    assert len(chunk["scans"]) == MAX_TRACE_SAMPLES
    assert chunk["values"]["MAIN.COUNT"][:2] == [6, 7]
    assert book.take_all() == {}  # nothing new: no chunk
    trigger = TraceTrigger(path="Main.Flag", condition="rising")
    book.start("client", 2, plan_trace(sim.location, ["Main.Count"], trigger), 3, sim)  # replaces the first
    assert book.take_all()["client"]["state"] == "waiting"


def test_the_server_merges_chunks_a_client_has_not_taken_and_caps_them() -> None:
    """On the server: chunks from several frames become one; beyond MAX_TRACE_SAMPLES the oldest are counted as
    lost; a chunk of a new trace (another id) replaces what is left of the old one."""
    inbox = TraceInbox()

    def chunk(trace_id: int, first: int, count: int, **fields) -> dict:
        scans = list(range(first, first + count))
        return {
            "id": trace_id,
            "state": "recording",
            "scans": scans,
            "time_ms": [10.0 * n for n in scans],
            "values": {"X": [n * 2 for n in scans]},
            "triggered": None,
            "lost": 0,
            **fields,
        }

    inbox.add("client", chunk(1, 1, 3))  # not started on this server side: ignored
    assert inbox.take("client") is None
    inbox.open("client")
    inbox.add("client", chunk(1, 1, 6_000, triggered={"scan": 1, "time_ms": 10.0}))
    inbox.add("client", chunk(1, 6_001, 4_004, lost=2))
    inbox.add("client", chunk(1, 10_005, 3, state="done"))
    data = inbox.take("client")
    assert (data.id, data.state, data.lost, len(data.scans)) == (1, "done", 2 + 7, MAX_TRACE_SAMPLES)
    assert (data.scans[0], data.scans[-1], data.values["X"][0]) == (8, 10_007, 16)  # 10,007 sent, 7 dropped
    assert data.triggered.scan == 1 and data.time_ms[-1] == 100_070.0
    assert inbox.take("client") is None and not inbox.active("client")  # done: forgotten
    inbox.open("client")
    inbox.add("client", chunk(2, 1, 2))
    inbox.add("client", chunk(3, 5, 1))
    assert (inbox.take("client").id, inbox.active("client")) == (3, True)


@pytest.fixture(scope="module")
def idle_sim():
    """The counter program: Idle (INT := 7) and Trig (BOOL) are never written by it."""
    return build_project(counter_project()).simulation()


@given(
    condition=st.sampled_from(["rising", "falling", "cross_up", "cross_down"]),
    values=st.lists(st.integers(-3, 9), max_size=12),
    level=st.integers(-2, 8),
)
def test_recording_starts_at_the_first_scan_whose_value_passes_the_condition(
    idle_sim, condition: str, values: list[int], level: int
) -> None:
    sim = idle_sim
    sim.reset(cold=True)  # values as declared; scan numbers go on
    base = sim.scan_count
    crossing = condition.startswith("cross")
    path = "Main.Idle" if crossing else "Main.Trig"
    written = values if crossing else [v % 2 == 1 for v in values]  # odd: TRUE
    trigger = TraceTrigger(path=path, condition=condition, level=level if crossing else None)
    book = TraceBook()
    book.start("client", 1, plan_trace(sim.location, [path], trigger), None, sim)
    for value in written:
        sim.write(path, value)
        sim.cycle(1)
        book.sample(sim)
    # The definition, scan by scan: the previous value is the one before the scan (7 or FALSE at first).
    previous = [7 if crossing else False] + written[:-1]
    passes = {
        "rising": lambda a, b: b and not a,
        "falling": lambda a, b: a and not b,
        "cross_up": lambda a, b: a < level <= b,
        "cross_down": lambda a, b: a > level >= b,
    }[condition]
    first = next((i for i, (a, b) in enumerate(zip(previous, written)) if passes(a, b)), None)
    chunk = book.take_all()["client"]
    if first is None:
        assert (chunk["state"], chunk["scans"], chunk["triggered"]) == ("waiting", [], None)
    else:
        assert chunk["state"] == "recording"
        assert chunk["triggered"] is not None and chunk["triggered"]["scan"] == base + first + 1
        assert chunk["scans"] == list(range(base + first + 1, base + len(written) + 1))
        assert chunk["values"][sim.location(path).path] == written[first:]
