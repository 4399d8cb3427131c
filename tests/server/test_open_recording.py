"""Opening a recording in the browser (issue 23 item 5, "the browser can download and open recordings"):
``POST /api/projects/{name}/recordings`` with the file runs its scans with their recorded inputs into a
history-only simulation, which can be viewed scan by scan, compared and continued from; a project at another
revision and a file that is not a recording are refused in the user's words.

The counter project (test_simulations_support.py): every scan ``Count := Count + 1``, ``Flag := NOT Flag``,
``Result := 100 / Divisor``; ``Idle`` starts at 7. Scans are numbered as ``values.scan`` numbers them (scans
completed, so after scan k Count = k); a recording numbers them from 0 (the input of line ``scan: 2`` applies
before the third scan)."""

from __future__ import annotations

import dataclasses
import json
import os
import signal

from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .test_simulations_support import (
    FAST,
    counter_project,
    install,
    log_of,
    of_type,
    recv_until,
    registry,
    subscribe,
    wait_for,
)

__all__ = ["registry"]  # fixture

WATCH = ["Main.Count", "Main.Idle", "Main.Result"]
HISTORY_ONLY = (
    "this simulation shows a recording, history only: go to one of its scans and continue from there "
    "(Continue from here) to run it or change its inputs"
)


def _recording(revision: str, scans: int = 6, inputs: list[dict[str, object]] | None = None) -> bytes:
    """A recording as the CLI and the download write it, by hand: Idle := 42 before scan 2 (0-based: the third
    scan), Divisor := 4 before scan 3 (the fourth)."""
    if inputs is None:
        inputs = [
            {"scan": 2, "kind": "write", "path": "Main.Idle", "value": 42},
            {"scan": 3, "kind": "write", "path": "Main.Divisor", "value": 4},
        ]
    data = {
        "format": "ladderlab-recording",
        "version": 1,
        "project": "/elsewhere/counter",
        "revision": revision,
        "scans": scans,
        "watch": None,
        "inputs": inputs,
    }
    return json.dumps(data).encode()


def _open(client: TestClient, content: bytes, name: str = "counter"):
    return client.post(
        f"/api/projects/{name}/recordings",
        params={"file": "run.json"},
        content=content,
        headers={"Content-Type": "application/json"},
    )


def _seen(seen: dict[str, object], found: tuple[dict, list[dict]]) -> dict:
    """The values a client holds after ``found`` (recv_until's answer): a values message sends what changed."""
    message, before = found
    for earlier in [*before, message]:
        if earlier["type"] == "values":
            seen.update(earlier["changed"])
    return message


def _viewing(scan: int):
    return lambda m: m["type"] == "values" and (m.get("history") or {}).get("viewing") == scan


def test_an_opened_recording_is_a_history_to_view_compare_and_continue_from(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    revision = workspace.create(counter_project())
    response = _open(client, _recording(revision))
    assert response.status_code == 201, response.text
    info = response.json()
    sim = info["id"]
    assert response.headers["Location"] == f"/api/simulations/{sim}"
    assert (info["state"], info["scan_count"], info["time_ms"]) == ("stopped", 6, 60.0)
    history = info["history"]
    assert (history["first"], history["last"], history["viewing"], history["recording"]) == (1, 6, 6, True)

    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        shown = subscribe(ws, WATCH)  # the last scan of the recording is shown
        assert shown["scan"] == 6 and shown["history"]["viewing"] == 6
        seen = dict(shown["changed"])
        assert [seen[p] for p in ("MAIN.COUNT", "MAIN.IDLE", "MAIN.RESULT")] == [6, 42, 25]
        expected = {  # scan: Count, Idle (42 from the third scan on), Result (100 / 4 from the fourth on)
            1: [1, 7, 100],
            2: [2, 7, 100],
            3: [3, 42, 100],
            4: [4, 42, 25],
        }
        for scan, values in expected.items():
            ws.send_json({"type": "seek", "scan": scan})
            past = _seen(seen, recv_until(ws, _viewing(scan)))
            assert past["time_ms"] == 10.0 * scan
            assert [seen[p] for p in ("MAIN.COUNT", "MAIN.IDLE", "MAIN.RESULT")] == values, scan

        for command in ({"type": "single_cycle"}, {"type": "run"}, {"type": "write", "path": "Main.Idle", "value": 1}):
            ws.send_json(command)
            refused = recv_until(ws, of_type("error"))[0]
            assert refused["code"] == "bad_state"
            assert refused["message"] == (
                "this simulation shows a recording, history only: go to one of its scans and continue from there "
                "(Continue from here) to run it or change its inputs"
            )

        diff = client.get(f"/api/simulations/{sim}/history/diff", params={"first": 2, "second": 4}).json()
        assert diff["differences"] == {
            "MAIN.COUNT": [2, 4],
            "MAIN.DIVISOR": [1, 4],
            "MAIN.IDLE": [7, 42],
            "MAIN.RESULT": [100, 25],
        }  # Flag: FALSE after an even number of scans in both

        ws.send_json({"type": "seek", "scan": 3})
        recv_until(ws, _viewing(3))
        ws.send_json({"type": "fork"})  # continue from scan 3: no longer history only; Divisor stays 1
        forked = recv_until(ws, lambda m: m["type"] == "values" and (m.get("history") or {}).get("branch") == 2)[0]
        assert forked["history"]["recording"] is False
        ws.send_json({"type": "single_cycle"})
        after = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 4)[0]
        assert after["changed"]["MAIN.COUNT"] == 4 and "MAIN.RESULT" not in after["changed"]  # still 100
        ws.send_json({"type": "seek", "scan": 6, "branch": 1})  # the recording itself is kept
        kept = recv_until(ws, _viewing(6))[0]
        assert kept["changed"]["MAIN.COUNT"] == 6 and kept["changed"]["MAIN.RESULT"] == 25


def test_a_recording_of_ladderlab_run_opens_and_replays_its_rows(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry, capsys
) -> None:
    """The file ``ladderlab run --record`` writes opens as it is: the rows the run printed are the scans shown."""
    from ladderlab.cli import main

    workspace.create(counter_project())
    path = workspace.folder("counter").parent / "run.rec"
    run = ["run", str(workspace.folder("counter")), "--cycles", "4", "--set", "Main.Idle=9@2", "--format", "jsonl"]
    assert main([*run, "--watch", "Main.Count", "--watch", "Main.Idle", "--record", str(path)]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [(row["Main.Count"], row["Main.Idle"]) for row in rows] == [(1, 7), (2, 7), (3, 9), (4, 9)]

    response = _open(client, path.read_bytes())
    assert response.status_code == 201, response.text
    sim = response.json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        seen = dict(subscribe(ws, ["Main.Count", "Main.Idle"])["changed"])
        for row in rows:
            ws.send_json({"type": "seek", "scan": row["scan"] + 1})  # CLI rows count from 0
            past = _seen(seen, recv_until(ws, _viewing(row["scan"] + 1)))
            assert past["time_ms"] == row["time_ms"]
            assert (seen["MAIN.COUNT"], seen["MAIN.IDLE"]) == (row["Main.Count"], row["Main.Idle"])
    marks = client.get(f"/api/simulations/{sim}/history/marks").json()
    assert marks == [{"scan": 3, "kinds": ["write"]}]  # the --set applied before the third scan


def test_a_recording_of_another_revision_or_no_recording_is_refused_in_words(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    revision = workspace.create(counter_project())
    other = _open(client, _recording("0123456789abcdef"))
    assert other.status_code == 409
    assert other.json()["detail"]["message"] == (
        "run.json was recorded with revision 0123456789abcdef of /elsewhere/counter; project 'counter' is now at "
        f"revision {revision}: open it in the project as it was when it was recorded"
    )
    not_json = _open(client, b"PK\x03\x04 a zip file")
    assert not_json.status_code == 422
    assert not_json.json()["detail"]["message"].startswith("run.json: not a recording (not JSON text: ")
    other_json = _open(client, b'{"format": "plcopen"}')
    assert other_json.status_code == 422
    assert other_json.json()["detail"]["message"] == (
        "run.json: not a recording of ladderlab run --record or of a simulation's download"
    )
    bad_line = _open(client, _recording(revision, inputs=[{"scan": -1, "kind": "write", "path": "Main.Idle"}]))
    assert bad_line.status_code == 422
    assert bad_line.json()["detail"]["message"] == (
        "run.json inputs:1: scan must be the number of the scan it applies before (0 for the first)"
    )
    unknown = _open(
        client, _recording(revision, inputs=[{"scan": 1, "kind": "write", "path": "Main.Gone", "value": 1}])
    )
    assert unknown.status_code == 422
    assert unknown.json()["detail"]["message"] == (
        "the recording's inputs do not fit this project: MAIN has no variable 'Gone'"
    )
    assert client.get("/api/simulations").json() == []  # nothing is left running of a refused recording
    assert _open(client, _recording(revision), name="nope").status_code == 404


def test_a_recording_too_long_to_run_in_time_is_refused_and_left_behind(
    client: TestClient, workspace: Workspace
) -> None:
    """A recording of more scans than the server runs within its build_timeout_s: refused in words, and the
    simulation it started is gone (it would otherwise go on scanning)."""
    registry = install(client, dataclasses.replace(FAST, build_timeout_s=4.0))
    try:
        revision = workspace.create(counter_project())
        response = _open(client, _recording(revision, scans=10**9))
        assert response.status_code == 422
        assert response.json()["detail"]["message"] == (
            "run.json: its 1000000000 scans did not run within 4 s (the server's build_timeout_s)"
        )
        assert client.get("/api/simulations").json() == []
    finally:
        registry.close()


def _values(ws, seen: dict[str, object], scan: int, branch: int | None = None) -> list[object]:
    """Seek ``scan`` (of ``branch``) and return Count, Idle, Result and Kept as that scan left them."""
    ws.send_json({"type": "seek", "scan": scan, **({"branch": branch} if branch is not None else {})})
    _seen(seen, recv_until(ws, _viewing(scan)))
    return [seen[p] for p in ("MAIN.COUNT", "MAIN.IDLE", "MAIN.RESULT", "MAIN.KEPT")]


def _history(client: TestClient, sim: str) -> tuple[object, ...]:
    history = client.get(f"/api/simulations/{sim}").json()["history"]
    return history["first"], history["last"], history["viewing"], history["branch"], history["recording"]


def test_reset_of_an_opened_recording_is_refused_while_history_only_then_acts_on_the_live_branch(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """Issue 23 (hist4 item 1): a recording shown history only is not reset (as it is not run: the recording ends
    where it ended); after "Continue from here" a warm or a cold reset acts on the live branch as any reset does,
    is recorded in its history like any input, and the recording stays viewable as branch 1."""
    revision = workspace.create(counter_project())
    sim = _open(client, _recording(revision)).json()["id"]
    for body in (None, {"cold": False}, {"cold": True}):
        refused = client.post(f"/api/simulations/{sim}/reset", json=body)
        assert refused.status_code == 409
        assert refused.json()["detail"]["message"] == HISTORY_ONLY
    assert _history(client, sim) == (1, 6, 6, 1, True)  # nothing changed

    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        seen = dict(subscribe(ws, [*WATCH, "Main.Kept"])["changed"])
        assert _values(ws, seen, 4) == [4, 42, 25, 0]
        ws.send_json({"type": "fork"})  # the live branch 2 starts from scan 4
        recv_until(ws, lambda m: m["type"] == "values" and (m.get("history") or {}).get("branch") == 2)
        ws.send_json({"type": "write", "path": "Main.Kept", "value": 5})  # RETAIN: a warm reset keeps it
        ws.send_json({"type": "single_cycle"})
        _seen(seen, recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 5))
        assert [seen[p] for p in ("MAIN.COUNT", "MAIN.IDLE", "MAIN.RESULT", "MAIN.KEPT")] == [5, 42, 25, 5]

        warm = client.post(f"/api/simulations/{sim}/reset", json={"cold": False})
        assert warm.status_code == 200, warm.text
        assert client.post(f"/api/simulations/{sim}/cycle").json()["scan_count"] == 6
        cold = client.post(f"/api/simulations/{sim}/reset", json={"cold": True})
        assert cold.status_code == 200, cold.text
        info = client.post(f"/api/simulations/{sim}/cycle").json()
        assert (info["state"], info["scan_count"], info["fault"]) == ("stopped", 7, None)
        assert info["history"]["recording"] is False and info["history"]["branch"] == 2
        # the live branch's history offers the scan continued from and every scan since, before and after the resets
        assert (info["history"]["first"], info["history"]["last"]) == (4, 7)
        # each scan as IEC 61131-3 restarts leave it: a warm restart re-initialises all but RETAIN, a cold one all
        assert _values(ws, seen, 5) == [5, 42, 25, 5]
        assert _values(ws, seen, 6) == [1, 7, 100, 5]  # warm: Count, Idle, Divisor start again; Kept stays
        assert _values(ws, seen, 7) == [1, 7, 100, 0]  # cold: Kept too
        assert _values(ws, seen, 6, branch=1) == [6, 42, 25, 0]  # the recording is kept as it was
        assert _values(ws, seen, 1, branch=1) == [1, 7, 100, 0]


def test_a_crashed_simulation_opened_from_a_recording_opens_it_again_on_reset(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """Issue 23 (hist4 item 1): the process of a simulation opened from a recording crashes (history only, then
    after a fork): while it is gone no history is offered (it was in the process); the reset that starts a new
    process opens the recording again, history only, its scans as they were recorded. What ran after "Continue
    from here" was only in the process that crashed; the log says so."""
    revision = workspace.create(counter_project())
    sim = _open(client, _recording(revision)).json()["id"]
    handle = registry.get(sim).handle
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        seen = dict(subscribe(ws, [*WATCH, "Main.Kept"])["changed"])
        for fork_first in (False, True):
            if fork_first:
                assert _values(ws, seen, 2) == [2, 7, 100, 0]
                ws.send_json({"type": "fork"})
                recv_until(ws, lambda m: m["type"] == "values" and (m.get("history") or {}).get("branch") == 2)
                ws.send_json({"type": "single_cycle"})
                recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 3)
            process = handle.process
            os.kill(process.pid, signal.SIGKILL)
            log, _ = recv_until(ws, log_of("fault"))
            assert log["message"].startswith("the simulation's process ended unexpectedly (exit code -9")
            recv_until(ws, lambda m: m["type"] == "values" and m["history"] is None)  # nothing to view
            wait_for(lambda p=process: p.exitcode is not None)
            info = client.get(f"/api/simulations/{sim}").json()
            assert (info["state"], info["history"]) == ("faulted", None)

            reset = client.post(f"/api/simulations/{sim}/reset")
            assert reset.status_code == 200, reset.text
            info = reset.json()
            assert (info["state"], info["scan_count"], info["fault"]) == ("stopped", 6, None)
            assert _history(client, sim) == (1, 6, 6, 1, True)
            note, before = recv_until(ws, log_of("system"))
            _seen(seen, (note, before))
            assert note["message"] == (
                "started again in a new process: the recording of 6 scans is open again, history only (what ran "
                "after Continue from here is lost); forces and breakpoints are cleared"
            )
            _seen(seen, recv_until(ws, _viewing(6)))
            for scan, values in {3: [3, 42, 100, 0], 4: [4, 42, 25, 0], 6: [6, 42, 25, 0]}.items():
                assert _values(ws, seen, scan) == values
            ws.send_json({"type": "single_cycle"})
            assert recv_until(ws, of_type("error"))[0]["message"] == HISTORY_ONLY
