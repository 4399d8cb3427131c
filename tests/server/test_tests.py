"""The Tests panel's endpoints: list, check, run with streamed progress, open a failed test online (issue 20).

Real HTTP round trips over the app; the project is the example (examples/motor with tests/motor.st)."""

from __future__ import annotations

import json

from fastapi.testclient import TestClient

from .test_simulations_support import recv, subscribe

FAILING = """TEST 'runs'
  Start := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(Motor);
END_TEST
TEST 'fails after 5 s'
  Start := TRUE;
  RUN_FOR(T#5s);
  ASSERT_EQ(Main.RunTimer.ET, T#4s, 'wrong on purpose');
END_TEST
"""


def _project(client: TestClient, extra: str | None = FAILING) -> dict:
    project = client.get("/api/projects/motor").json()["project"]
    if extra is not None:
        project["tests"].append({"name": "extra", "text": extra})
    return project


def _events(response) -> list[dict]:
    assert response.status_code == 200, response.text
    assert response.headers["content-type"].startswith("application/x-ndjson")
    return [json.loads(line) for line in response.text.splitlines()]


def test_list_names_every_test_of_the_working_copy(client: TestClient, motor: str) -> None:
    listing = client.post("/api/tests/list", json=_project(client)).json()
    assert [f["file"] for f in listing["files"]] == ["tests/motor.st", "tests/extra.st"]
    assert listing["files"][1]["tests"] == [{"name": "runs", "line": 1}, {"name": "fails after 5 s", "line": 6}]


def test_check_gives_located_diagnostics_of_one_test_file(client: TestClient, motor: str) -> None:
    project = _project(client, "TEST 'x'\n  ASSERT_EQ(Main.Nope, 1);\nEND_TEST\n")
    info = client.post("/api/tests/check", json={"project": project, "file": "tests/extra.st"}).json()
    assert [(d["line"], d["column"], d["message"]) for d in info["diagnostics"]] == [
        (2, 13, "Main has no input or output 'Nope'")
    ]
    missing = client.post("/api/tests/check", json={"project": project, "file": "tests/none.st"})
    assert (missing.status_code, missing.json()["detail"]["message"]) == (
        404,
        "project 'motor' has no test file 'tests/none.st'",
    )


def test_run_streams_each_file_then_each_result_then_the_summary(client: TestClient, motor: str) -> None:
    events = _events(client.post("/api/tests/run", json={"project": _project(client), "file": "tests/extra.st"}))
    assert [e["type"] for e in events] == ["file", "result", "result", "done"]
    assert events[0]["file"]["tests"] == [{"name": "runs", "line": 1}, {"name": "fails after 5 s", "line": 6}]
    results = {e["result"]["name"]: e["result"] for e in events[1:3]}  # in the order the worker processes finish
    assert results["runs"]["outcome"] == "passed"
    failed = results["fails after 5 s"]
    assert failed["failure"] == {
        "message": "ASSERT_EQ failed: Main.RunTimer.ET expected T#4s, got T#4s990ms",
        "line": 9,
        "column": 3,
        "verb": "ASSERT_EQ",
        "actual": "T#4s990ms",
        "expected": "T#4s",
        "note": "wrong on purpose",
        "kind": "assertion",
    }
    assert events[3]["summary"] | {"seconds": 0} == {
        "passed": 1,
        "failed": 1,
        "skipped": 0,
        "files_with_errors": 0,
        "seconds": 0,
    }


def test_run_one_test_or_all_with_coverage(client: TestClient, motor: str) -> None:
    project = _project(client, FAILING + "TEST 'runs [twice]'\n  ASSERT(TRUE);\nEND_TEST\n")
    body = {"project": project, "file": "tests/extra.st", "test": "runs"}
    one = _events(client.post("/api/tests/run", json=body))
    assert [e["result"]["name"] for e in one if e["type"] == "result"] == ["runs"]  # that name exactly
    assert one[-1]["summary"]["skipped"] == 2
    every = _events(client.post("/api/tests/run", json={"project": _project(client), "coverage": True}))
    assert sum(e["type"] == "result" for e in every) == 8
    coverage = every[-1]["coverage"]
    assert coverage["Main"]["never_executed"] == [] and coverage["Blinker"]["never_executed_lines"] == []


def test_open_a_failed_test_as_the_simulation_stood_at_the_failure(client: TestClient, motor: str) -> None:
    body = {"project": _project(client), "file": "tests/extra.st", "test": "fails after 5 s"}
    opened = client.post("/api/tests/open", json=body)
    assert opened.status_code == 201, opened.text
    info = opened.json()
    assert (info["state"], info["scan_count"]) == ("stopped", 500)
    with client.websocket_connect(f"/api/simulations/{info['id']}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.RunTimer.ET", "Motor", "Main.MotorRunning"])
        assert first["changed"] == {"MAIN.RUNTIMER.ET": 4990, "MOTOR": True, "MAIN.MOTORRUNNING": False}
        assert first["time_ms"] == 5000.0
    passing = client.post("/api/tests/open", json={**body, "test": "runs"})
    assert (passing.status_code, passing.json()["detail"]["message"]) == (
        409,
        "the test 'runs' passes: there is no failure to open",
    )
