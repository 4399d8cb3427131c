"""Scan history over the websocket and REST (issue 23 item 3): go to a past scan and the subscribed values and
the history marker are those of that scan; the live scans go on meanwhile; back to live; find the scan where a
variable changed. Scans are numbered as ``values.scan`` (scans completed): Count equals that number."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

from fastapi.testclient import TestClient

from ladderlab.model import Project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import (
    FAST,
    counter,
    counter_project,
    entry,
    install,
    of_type,
    recv_until,
    registry,
    subscribe,
)

__all__ = ["counter", "registry"]  # fixtures


def _values(**fields):
    def match(message):
        if message["type"] != "values":
            return False
        history = message.get("history") or {}
        return all(history.get(key) == value for key, value in fields.items())

    return match


def test_seek_shows_a_past_scan_while_the_live_scans_go_on(client: TestClient, counter: str) -> None:
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count", "Main.Idle"])
        for _ in range(4):
            ws.send_json({"type": "single_cycle"})
        ws.send_json({"type": "write", "path": "Main.Idle", "value": 42})  # applies at the start of scan 5
        for _ in range(6):
            ws.send_json({"type": "single_cycle"})
        recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 10)

        ws.send_json({"type": "seek", "scan": 3})
        past = recv_until(ws, _values(viewing=3))[0]
        assert (past["scan"], past["history"]["first"], past["history"]["last"]) == (3, 1, 10)
        assert past["changed"]["MAIN.COUNT"] == 3 and past["changed"]["MAIN.IDLE"] == 7
        assert past["time_ms"] == 30.0  # the third scan of a 10 ms task runs at 30 ms (the first at 10 ms)

        ws.send_json({"type": "seek", "scan": 5})
        past = recv_until(ws, _values(viewing=5))[0]
        assert (past["changed"]["MAIN.COUNT"], past["changed"]["MAIN.IDLE"]) == (5, 42)

        ws.send_json({"type": "single_cycle"})  # the live simulation goes on; the view stays
        later = recv_until(ws, _values(viewing=5, last=11))[0]
        assert later["scan"] == 5 and "MAIN.COUNT" not in later["changed"]

        ws.send_json({"type": "seek", "scan": 99})
        error = recv_until(ws, of_type("error"))[0]
        assert error == {
            "type": "error",
            "code": "bad_value",
            "message": "scan 99 has not run yet (the last scan is 11)",
        }

        found = client.get(f"/api/simulations/{counter}/history/find", params={"path": "main.idle", "scan": 1})
        assert found.json() == {"scan": 5}
        back = client.get(
            f"/api/simulations/{counter}/history/find", params={"path": "Main.Idle", "scan": 11, "direction": -1}
        )
        assert back.json() == {"scan": 5}

        ws.send_json({"type": "live"})
        live = recv_until(ws, _values(viewing=None))[0]
        assert live["scan"] == 11 and live["changed"]["MAIN.COUNT"] == 11


def test_seek_over_rest_and_the_history_in_the_simulation_info(client: TestClient, counter: str) -> None:
    for _ in range(3):
        client.post(f"/api/simulations/{counter}/cycle")
    info = client.post(f"/api/simulations/{counter}/seek", json={"scan": 2}).json()
    assert {key: info["history"][key] for key in ("first", "last", "viewing")} == {"first": 1, "last": 3, "viewing": 2}
    assert 0 < info["history"]["bytes"] <= info["history"]["budget_bytes"] == 256 * 1024 * 1024
    unknown = client.get(f"/api/simulations/{counter}/history/find", params={"path": "Main.Nope", "scan": 1})
    assert unknown.status_code == 422
    assert unknown.json()["detail"]["message"] == "MAIN has no variable 'Nope'"
    info = client.post(f"/api/simulations/{counter}/live").json()
    assert info["history"]["viewing"] is None


def test_find_where_a_condition_became_true_and_the_diff_of_two_scans(client: TestClient, counter: str) -> None:
    """Issue 23 item 3: "where <condition> became TRUE" (Count >= 4 first holds after scan 4; Flag toggles every
    scan, so NOT Flag becomes TRUE every second scan) and the variables that differ between two scans."""
    for _ in range(8):
        client.post(f"/api/simulations/{counter}/cycle")
    find = f"/api/simulations/{counter}/history/find"
    assert client.get(find, params={"condition": "Main.Count >= 4", "scan": 1}).json() == {"scan": 4}
    assert client.get(find, params={"condition": "Main.Count >= 4", "scan": 4}).json() == {"scan": None}
    assert client.get(find, params={"condition": "Main.Flag", "scan": 1}).json() == {"scan": 3}
    assert client.get(find, params={"condition": "Main.Flag", "scan": 8, "direction": -1}).json() == {"scan": 7}
    refused = client.get(find, params={"condition": "Main.Count", "scan": 1})
    assert refused.status_code == 422
    assert (
        refused.json()["detail"]["message"] == "'Main.Count': MAIN.COUNT is not a BOOL; compare it, e.g. MAIN.COUNT > 0"
    )
    outside = client.get(find, params={"path": "Main.Count", "scan": 9})
    assert outside.json()["detail"]["message"] == "scan 9 is not in the history (scans 1 to 8)"

    diff = client.get(f"/api/simulations/{counter}/history/diff", params={"first": 2, "second": 5}).json()
    # Count 2 -> 5, Flag TRUE after an odd number of scans; Result, Divisor, Idle, Kept, Trig unchanged
    assert diff == {"first": 2, "second": 5, "differences": {"MAIN.COUNT": [2, 5], "MAIN.FLAG": [False, True]}}


def test_the_timeline_marks_inputs_and_runtime_errors(client: TestClient, counter: str) -> None:
    """Issue 23 item 3: marks for writes, forces and runtime errors, at the scan they belong to."""
    cycle = f"/api/simulations/{counter}/cycle"
    client.post(cycle)
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "write", "path": "Main.Idle", "value": 1})
        ws.send_json({"type": "force", "path": "Main.Trig", "value": True})
        ws.send_json({"type": "single_cycle"})  # scan 2: the write and the force
        ws.send_json({"type": "single_cycle"})
        ws.send_json({"type": "write", "path": "Main.Divisor", "value": 0})  # scan 4 divides by zero
        ws.send_json({"type": "single_cycle"})
        recv_until(ws, of_type("status", state="faulted"))
    marks = client.get(f"/api/simulations/{counter}/history/marks").json()
    assert marks == [{"scan": 2, "kinds": ["force", "write"]}, {"scan": 4, "kinds": ["error", "write"]}]
    assert client.get(f"/api/simulations/{counter}").json()["history"]["marked"] == 4


def test_the_timeline_marks_trace_triggers_and_breakpoint_hits(client: TestClient, counter: str) -> None:
    """Issue 23 item 3: a trace's trigger marks the scan it fired at (Count crosses 3 upwards at the end of scan
    3, the trace's ``triggered`` scan), a breakpoint the scan halted in (scan 6: five scans completed, halted at
    line 2 of the sixth); both over REST and, through ``marked``, the websocket."""
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        trigger = {"path": "Main.Count", "condition": "cross_up", "level": 3}
        ws.send_json({"type": "trace_start", "paths": ["Main.Count"], "samples": 2, "trigger": trigger})
        recv_until(ws, of_type("trace_data", state="waiting"))  # the trace is armed before the scans run
        for _ in range(5):
            ws.send_json({"type": "single_cycle"})
        traced = recv_until(ws, lambda m: m["type"] == "trace_data" and m["triggered"] is not None)[0]
        assert traced["triggered"]["scan"] == 3
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "line": 2})
        ws.send_json({"type": "single_cycle"})
        recv_until(ws, of_type("status", state="halted"))
        marked = recv_until(ws, _values(marked=2))[0]
        assert marked["history"]["last"] == 5
    marks = client.get(f"/api/simulations/{counter}/history/marks").json()
    assert marks == [{"scan": 3, "kinds": ["trigger"]}, {"scan": 6, "kinds": ["breakpoint"]}]


def test_continue_from_a_past_scan_starts_a_branch_and_keeps_the_old_one(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    """Issue 23 item 4: from scan 3, "continue from here" takes that scan's state (stopped); the next scans run
    without the write the first branch had at scan 5; both branches stay viewable."""
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count", "Main.Idle"])
        for _ in range(4):
            ws.send_json({"type": "single_cycle"})
        ws.send_json({"type": "write", "path": "Main.Idle", "value": 42})
        for _ in range(2):
            ws.send_json({"type": "single_cycle"})
        recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 6)
        ws.send_json({"type": "fork"})
        refused = recv_until(ws, of_type("error"))[0]
        assert refused["message"] == "go to a past scan first: continue from here starts from the scan shown"

        ws.send_json({"type": "seek", "scan": 3})
        recv_until(ws, _values(viewing=3))
        ws.send_json({"type": "fork"})
        forked, before = recv_until(ws, _values(viewing=None, branch=2))
        live = entry(registry, counter).handle
        assert forked["scan"] == 3 and "MAIN.COUNT" not in forked["changed"]  # as the client saw it at scan 3
        assert (live.read("Main.Count"), live.read("Main.Idle")) == (3, 7)
        assert (forked["history"]["first"], forked["history"]["last"]) == (3, 3)
        logs = [m["message"] for m in before if m["type"] == "log"]
        assert "continued from scan 3 of branch 1: branch 2 is live" in logs
        for _ in range(3):
            ws.send_json({"type": "single_cycle"})
        now = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 6)[0]
        assert now["history"]["last"] == 6 and now["changed"]["MAIN.COUNT"] == 6
        assert live.read("Main.Idle") == 7
        assert client.get(f"/api/simulations/{counter}").json()["state"] == "stopped"

        ws.send_json({"type": "seek", "scan": 6, "branch": 1})  # the first branch: the write applied at scan 5
        old = recv_until(ws, _values(viewing=6, viewing_branch=1))[0]
        assert old["changed"]["MAIN.IDLE"] == 42
        ws.send_json({"type": "seek", "scan": 6})  # this branch at scan 6 never had it
        new = recv_until(ws, _values(viewing=6, viewing_branch=2))[0]
        assert new["changed"]["MAIN.IDLE"] == 7 and new["scan"] == 6
        ws.send_json({"type": "seek", "scan": 2})  # before the fork: not in this branch
        error = recv_until(ws, of_type("error"))[0]
        assert error["message"] == "scan 2 is no longer in the history: it starts at scan 3"
        ws.send_json({"type": "seek", "scan": 2, "branch": 3})
        error = recv_until(ws, of_type("error"))[0]
        assert error["message"] == "there is no branch 3 (branches 1 to 2)"


def test_a_session_downloads_as_a_recording_that_ladderlab_replay_prints(
    client: TestClient, counter: str, capsys
) -> None:
    """Issue 23 item 5: the browser's "Download recording" is the file ladderlab replay takes: the project's
    folder in the workspace, its revision, the inputs with their scans; the rows are the session's scans."""
    from ladderlab.cli import main

    cycle = f"/api/simulations/{counter}/cycle"
    client.post(cycle)
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "write", "path": "Main.Idle", "value": 5})
        ws.send_json({"type": "single_cycle"})
        ws.send_json({"type": "single_cycle"})
        recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 3)
    response = client.get(f"/api/simulations/{counter}/recording")
    assert response.status_code == 200
    data = response.json()
    assert (data["format"], data["scans"], data["inputs"]) == (
        "ladderlab-recording",
        3,
        [{"scan": 1, "kind": "write", "path": "Main.Idle", "value": 5}],
    )
    path = Path(data["project"]).parent.parent / "session.json"
    path.write_bytes(response.content)
    capsys.readouterr()
    assert main(["replay", str(path), "--watch", "Main.Count", "--watch", "Main.Idle", "--format", "jsonl"]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert rows == [
        {"scan": 0, "time_ms": 10, "Main.Count": 1, "Main.Idle": 7},
        {"scan": 1, "time_ms": 20, "Main.Count": 2, "Main.Idle": 5},
        {"scan": 2, "time_ms": 30, "Main.Count": 3, "Main.Idle": 5},
    ]

    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "seek", "scan": 2})
        recv_until(ws, _values(viewing=2))
        ws.send_json({"type": "fork"})
        recv_until(ws, _values(branch=2))
    refused = client.get(f"/api/simulations/{counter}/recording")
    assert refused.status_code == 409
    assert refused.json()["detail"]["message"] == (
        "this session cannot be replayed from scan 0 by ladderlab replay: it continued from a past scan"
    )


def test_step_through_a_past_scan_line_by_line(client: TestClient, counter: str, registry: SimulationRegistry) -> None:
    """Issue 23 item 3 ("one network within a scan"): scan 3 shown, then stepped through in the debug variant
    from the state scan 2 left (Count 2, Flag FALSE after two toggles) with its recorded write Divisor := 4 applied
    at its start: before line 1 Count is 2; before line 2 Count is 3 and Flag still FALSE; before line 3 Flag is
    TRUE and Result still 100; at the end Result is 25. The live simulation (scan 5) and the history stay."""
    cycle = f"/api/simulations/{counter}/cycle"
    for _ in range(2):
        client.post(cycle)
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count", "Main.Flag", "Main.Result"])
        ws.send_json({"type": "write", "path": "Main.Divisor", "value": 4})
        for _ in range(3):
            ws.send_json({"type": "single_cycle"})
        recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 5)
        step = f"/api/simulations/{counter}/history/step"
        refused = client.post(step, json={})
        assert refused.status_code == 409
        assert refused.json()["detail"]["message"] == "go to a past scan first: a step goes through the scan shown"
        client.post(f"/api/simulations/{counter}/seek", json={"scan": 3})
        seen: dict[str, object] = {}
        points = []
        for _ in range(4):
            info = client.post(step, json={"granularity": "statement"}).json()
            stepping = info["history"]["stepping"]
            found = recv_until(
                ws, lambda m, point=stepping: m["type"] == "values" and m["history"]["stepping"] == point
            )
            for m in [*found[1], found[0]]:
                if m["type"] == "values":
                    seen.update(m["changed"])
            assert found[0]["scan"] == 3
            at = stepping["at"]
            points.append((at and (at["pou"], at["line"]), seen["MAIN.COUNT"], seen["MAIN.FLAG"], seen["MAIN.RESULT"]))
        assert points == [
            (("MAIN", 1), 2, False, 100),
            (("MAIN", 2), 3, False, 100),
            (("MAIN", 3), 3, True, 100),
            (None, 3, True, 25),
        ]
        ended = client.post(step, json={})
        assert ended.json()["detail"]["message"] == "scan 3 ran to its end: go to a scan to step through it"
        live = entry(registry, counter).handle
        assert live.read("Main.Count") == 5
        ws.send_json({"type": "fork"})  # from the end of the stepped scan: its state, as the seek had it
        recv_until(ws, lambda m: m["type"] == "values" and m["history"]["branch"] == 2)
        assert (live.read("Main.Count"), live.read("Main.Result")) == (3, 25)
        info = client.post(f"/api/simulations/{counter}/seek", json={"scan": 3}).json()
        assert info["history"]["stepping"] is None


def test_a_step_through_refuses_what_it_cannot_redo(client: TestClient, counter: str) -> None:
    """A scan that ended with a runtime error (Divisor 0 at scan 3) cannot be stepped through again (its view is
    the checkpoint after it); a continue from a scan halted in a step waits for the step to end."""
    cycle = f"/api/simulations/{counter}/cycle"
    step = f"/api/simulations/{counter}/history/step"
    client.post(cycle)
    client.post(cycle)
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "write", "path": "Main.Divisor", "value": 0})
        ws.send_json({"type": "single_cycle"})
        recv_until(ws, of_type("status", state="faulted"))
    client.post(f"/api/simulations/{counter}/seek", json={"scan": 3})
    refused = client.post(step, json={})
    assert refused.status_code == 409
    assert refused.json()["detail"]["message"] == "scan 3 cannot be stepped through: it ended with a runtime error"

    client.post(f"/api/simulations/{counter}/seek", json={"scan": 2})
    halted = client.post(step, json={}).json()["history"]["stepping"]
    assert halted["at"]["line"] == 1
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "fork"})
        error = recv_until(ws, of_type("error"))[0]
        assert error["message"] == "the scan shown is halted in a step through it: step to its end first"


#: Main calls Spin, which loops ``n`` times: the scan where ``n`` is large takes long, in a step through it too.
SPIN_PROJECT = {
    "name": "spin",
    "pous": [
        {
            **st_program(
                "Spin",
                "VAR_INPUT\n    n : DINT;\nEND_VAR\nVAR\n    i : DINT;\nEND_VAR",
                "Spin := 0;\nFOR i := 1 TO n DO\n    Spin := Spin + 1;\nEND_FOR",
            ),
            "kind": "function",
            "return_type": "DINT",
        },
        st_program(
            "Main",
            "VAR\n    n : DINT;\n    x : DINT;\n    Count : INT;\nEND_VAR",
            "Count := Count + 1;\nx := Spin(n);\nCount := Count + 0;",
        ),
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "programs": ["Main"]}],
}
SPINS = 400_000
SEEK_SPINS = 12_000_000  # some 86 ns each in the monitor variant here: a seek over them takes about 1 s


def test_a_step_that_does_not_end_in_time_is_refused_and_touches_nothing(
    client: TestClient, workspace: Workspace
) -> None:
    """hist4 item 2: ``POST .../history/step`` waits ``history_timeout_s`` (the server's setting, 1 s here) for the
    step; a step over the call of a function that loops 400,000 times in the debug variant takes longer, so it is
    refused (409, in words) while it goes on; once it ends the scan shown is halted after the call (line 3, x as the
    loop left it). The live simulation (3 scans, n back to 0) and the recorded scans stay as they were."""
    settings = dataclasses.replace(FAST, history_timeout_s=1.0, watchdog_s=60.0)
    registry = install(client, settings)
    try:
        workspace.create(Project.model_validate(SPIN_PROJECT))
        sim = client.post("/api/projects/spin/simulations").json()["id"]
        step = f"/api/simulations/{sim}/history/step"
        with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
            subscribe(ws, ["Main.x", "Main.Count", "Main.n"])
            ws.send_json({"type": "single_cycle"})
            ws.send_json({"type": "write", "path": "Main.n", "value": SPINS})
            ws.send_json({"type": "single_cycle"})
            ws.send_json({"type": "write", "path": "Main.n", "value": 0})
            ws.send_json({"type": "single_cycle"})
            recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 3, timeout=30)
            client.post(f"/api/simulations/{sim}/seek", json={"scan": 2})
            lines = [client.post(step, json={"granularity": "statement"}).json() for _ in range(2)]
            assert [info["history"]["stepping"]["at"]["line"] for info in lines] == [1, 2]

            refused = client.post(step, json={"granularity": "over"})
            assert refused.status_code == 409
            assert refused.json()["detail"]["message"] == (
                "the step did not end within 1 s (the server's history_timeout_s): the scan shown shows where it "
                "stands once it ends"
            )
            ended, before = recv_until(
                ws,
                lambda m: m["type"] == "values" and ((m["history"]["stepping"] or {}).get("at") or {}).get("line") == 3,
                timeout=60,
            )
            seen = _changed([*before, ended])
            assert (ended["scan"], seen["MAIN.X"], seen["MAIN.COUNT"], seen["MAIN.N"]) == (2, SPINS, 2, SPINS)

        live = registry.get(sim).handle
        assert [live.read(path) for path in ("Main.Count", "Main.n", "Main.x")] == [3, 0, 0]
        info = client.get(f"/api/simulations/{sim}").json()
        assert (info["scan_count"], info["history"]["first"], info["history"]["last"]) == (3, 1, 3)
        with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
            seen = dict(subscribe(ws, ["Main.x", "Main.Count"])["changed"])
            for scan, x in ((1, 0), (2, SPINS), (3, 0)):
                ws.send_json({"type": "seek", "scan": scan})
                shown, before = recv_until(ws, _values(viewing=scan), timeout=30)
                seen.update(_changed([*before, shown]))
                assert (seen["MAIN.COUNT"], seen["MAIN.X"]) == (scan, x)
    finally:
        registry.close()


def _changed(messages: list[dict]) -> dict[str, object]:
    """The values the ``values`` messages among ``messages`` changed, the later ones winning."""
    seen: dict[str, object] = {}
    for message in messages:
        if message["type"] == "values":
            seen.update(message["changed"])
    return seen


def test_a_seek_that_does_not_end_in_time_is_refused_and_touches_nothing(
    client: TestClient, workspace: Workspace
) -> None:
    """hist5 item 1: ``POST .../seek`` waits ``history_timeout_s`` (0.1 s here) like a step, find or diff: the seek
    to scan 2, whose replay runs the call of a function that loops 12 million times again, takes longer, so it is
    refused (409, in words) while the simulation's process goes on with it; once it ends, scan 2 is shown (x as the
    loop left it). The live simulation (3 scans, n back to 0) and the recorded scans stay; the next seek works. A seek
    over the websocket is refused alike (an error message in the same words)."""
    settings = dataclasses.replace(FAST, history_timeout_s=0.1, watchdog_s=60.0)
    registry = install(client, settings)
    try:
        workspace.create(Project.model_validate(SPIN_PROJECT))
        sim = client.post("/api/projects/spin/simulations").json()["id"]
        with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
            subscribe(ws, ["Main.x", "Main.Count", "Main.n"])
            ws.send_json({"type": "single_cycle"})
            ws.send_json({"type": "write", "path": "Main.n", "value": SEEK_SPINS})
            ws.send_json({"type": "single_cycle"})
            ws.send_json({"type": "write", "path": "Main.n", "value": 0})
            ws.send_json({"type": "single_cycle"})
            recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 3, timeout=30)

            refused = client.post(f"/api/simulations/{sim}/seek", json={"scan": 2})
            assert refused.status_code == 409
            assert refused.json()["detail"]["message"] == (
                "the seek to scan 2 did not end within 0.1 s (the server's history_timeout_s): scan 2 is shown once "
                "it ends"
            )
            shown, before = recv_until(ws, _values(viewing=2), timeout=60)
            seen = _changed([*before, shown])
            assert (shown["scan"], seen["MAIN.X"], seen["MAIN.COUNT"], seen["MAIN.N"]) == (2, SEEK_SPINS, 2, SEEK_SPINS)

        live = registry.get(sim).handle
        assert [live.read(path) for path in ("Main.Count", "Main.n", "Main.x")] == [3, 0, 0]
        info = client.get(f"/api/simulations/{sim}").json()
        assert (info["scan_count"], info["history"]["first"], info["history"]["last"]) == (3, 1, 3)
        assert info["state"] == "stopped"
        answered = client.post(f"/api/simulations/{sim}/seek", json={"scan": 1})
        assert answered.status_code == 200
        assert {key: answered.json()["history"][key] for key in ("first", "last", "viewing")} == {
            "first": 1,
            "last": 3,
            "viewing": 1,
        }
        with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
            seen = dict(subscribe(ws, ["Main.x", "Main.Count", "Main.n"])["changed"])
            assert (seen["MAIN.COUNT"], seen["MAIN.X"], seen["MAIN.N"]) == (1, 0, 0)
            ws.send_json({"type": "seek", "scan": 2})  # the websocket's seek waits as long, in the same words
            error = recv_until(ws, of_type("error"), timeout=30)[0]
            assert error == {
                "type": "error",
                "code": "bad_state",
                "message": "the seek to scan 2 did not end within 0.1 s (the server's history_timeout_s): scan 2 is "
                "shown once it ends",
            }
            recv_until(ws, _values(viewing=2), timeout=60)
    finally:
        registry.close()


def test_the_history_budget_is_the_servers_history_mb(client: TestClient, workspace: Workspace) -> None:
    """Issue 23 item 1 ("default 256 MB, configurable"): ``history_mb`` 3 gives each simulation a history of 3 MiB
    (the default, 256 MiB, is in test_seek_over_rest_and_the_history_in_the_simulation_info); 0 keeps none, and a
    seek says so."""
    workspace.create(counter_project())
    for history_mb, budget in ((3, 3 * 1024 * 1024), (0, None)):
        registry = install(client, dataclasses.replace(FAST, history_mb=history_mb))
        try:
            sim = client.post("/api/projects/counter/simulations").json()["id"]
            info = client.post(f"/api/simulations/{sim}/cycle").json()
            assert (info["history"] or {}).get("budget_bytes") == budget
            if budget is None:
                refused = client.post(f"/api/simulations/{sim}/seek", json={"scan": 1})
                assert refused.status_code == 409
                assert refused.json()["detail"]["message"] == (
                    "this simulation keeps no scan history (the server's history_mb is 0)"
                )
        finally:
            registry.close()


def test_step_back_through_a_past_scan(client: TestClient, counter: str) -> None:
    """Issue 23 item 3 (stepping back and forth one network or line within a scan): scan 3 of the counter stepped
    to before line 3, then back: before line 2 Count is 3 (line 1 ran) and Flag FALSE, before line 1 Count is 2;
    a step back from there is refused in words; a step forward goes to line 2 again. Reference values: Count counts
    the scans, Flag toggles every scan (FALSE after the two scans before scan 3)."""
    cycle = f"/api/simulations/{counter}/cycle"
    for _ in range(4):
        client.post(cycle)
    step = f"/api/simulations/{counter}/history/step"
    with client.websocket_connect(f"/api/simulations/{counter}/ws") as ws:
        seen = dict(subscribe(ws, ["Main.Count", "Main.Flag"])["changed"])
        refused = client.post(f"/api/simulations/{counter}/history/step", json={"granularity": "back"})
        assert refused.json()["detail"]["message"] == "go to a past scan first: a step goes through the scan shown"
        client.post(f"/api/simulations/{counter}/seek", json={"scan": 3})
        refused = client.post(step, json={"granularity": "back"})
        assert refused.status_code == 409
        assert refused.json()["detail"]["message"] == (
            "step into the scan shown first: a step back goes to the point before the one reached"
        )
        points = []
        for granularity in ("statement", "statement", "statement", "back", "back", "statement"):
            info = client.post(step, json={"granularity": granularity}).json()
            stepping = info["history"]["stepping"]
            found = recv_until(
                ws, lambda m, point=stepping: m["type"] == "values" and m["history"]["stepping"] == point
            )
            for m in [*found[1], found[0]]:
                if m["type"] == "values":
                    seen.update(m["changed"])
            points.append((stepping["at"]["line"], seen["MAIN.COUNT"], seen["MAIN.FLAG"]))
            if granularity == "back" and stepping["at"]["line"] == 1:
                refused = client.post(step, json={"granularity": "back"})
                assert refused.status_code == 409
                assert refused.json()["detail"]["message"] == (
                    "scan 3 is halted before its first network or line: go one scan back to see the one before"
                )
        assert points == [(1, 2, False), (2, 3, False), (3, 3, True), (2, 3, False), (1, 2, False), (2, 3, False)]
        assert client.get(f"/api/simulations/{counter}").json()["scan_count"] == 4
