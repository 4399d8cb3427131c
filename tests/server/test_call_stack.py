"""The halted status message carries the call stack (issue 25 item 6; ON-03): through the app's websocket from the
simulation's own process, each call with where it stands and a FUNCTION's or METHOD's own variables with their
display types; a write while halted shows at once in a VAR_IN_OUT that refers to the written variable."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

from .test_simulations_support import of_type, recv_until, registry

__all__ = ["registry"]  # the fixture used below

TEXT = """
FUNCTION Inc : INT
VAR_IN_OUT c : INT; END_VAR
VAR t : TIME := T#1s500ms; END_VAR
c := c + 1;
Inc := c;
END_FUNCTION
FUNCTION_BLOCK Motor
METHOD Start : INT
VAR_INPUT n : INT; END_VAR
VAR r : REAL := 1.5; END_VAR
Start := Inc(n) * 10;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR m : Motor; x : INT := 4; y : INT; END_VAR
y := m.Start(n := 2);
Inc(x);
END_PROGRAM
"""


def line(text: str) -> int:
    return TEXT.splitlines().index(text) + 1


def at(pou: str, instance: str | None, text: str) -> dict:
    return {"pou": pou, "instance": instance, "network": None, "element": None, "line": line(text), "body": None}


def where(frame: dict) -> dict:
    return {k: v for k, v in frame["at"].items() if k != "column"}


def variable(name: str, kind: str, type_: str, value: object) -> dict:
    return {"name": name, "kind": kind, "type": {"name": type_, "names": None}, "value": value, "reason": None}


def test_the_halted_status_carries_the_call_stack_and_a_write_updates_it(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    project, diagnostics = source_to_project(TEXT, "stack")
    assert project is not None and diagnostics == []
    workspace.create(project)
    sim_id = client.post("/api/projects/stack/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        ws.send_json({"type": "breakpoint_set", "pou": "Inc", "line": line("Inc := c;")})
        ws.send_json({"type": "single_cycle"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        stack = status["stack"]
        assert [(f["kind"], where(f)) for f in stack] == [
            ("program", at("MAIN", "MAIN", "y := m.Start(n := 2);")),
            ("method", at("MOTOR.START", "MAIN.M", "Start := Inc(n) * 10;")),
            ("function", at("INC", None, "Inc := c;")),
        ]
        assert stack[0]["variables"] == []
        # Start(n := 2) passed n to Inc's in-out: c := c + 1 made it 3; the results are not assigned yet
        assert stack[1]["variables"] == [
            variable("N", "input", "INT", 3),
            variable("R", "var", "REAL", 1.5),
            variable("START", "result", "INT", 0),
        ]
        assert stack[2]["variables"] == [
            variable("C", "in_out", "INT", 3),
            variable("T", "var", "TIME", 1500),  # ms, shown as T#1s500ms from the type
            variable("INC", "result", "INT", 0),
        ]
        ws.send_json({"type": "continue"})  # the same breakpoint, now in Main's Inc(x): another stack
        status, seen = recv_until(ws, of_type("status", state="halted"))
        assert [m["message"] for m in seen if m["type"] == "log" and m["kind"] == "breakpoint"] == [
            f"halted at the breakpoint at INC, line {line('Inc := c;')}"
        ]  # a new halt at the same line: logged, and its stack sent
        assert [where(f) for f in status["stack"]] == [at("MAIN", "MAIN", "Inc(x);"), at("INC", None, "Inc := c;")]
        assert status["stack"][1]["variables"][0] == variable("C", "in_out", "INT", 5)  # x = 4, plus 1
        ws.send_json({"type": "write", "path": "Main.x", "value": 100})  # c refers to x: shown at once
        status, seen = recv_until(ws, of_type("status", state="halted"))
        assert status["stack"][1]["variables"][0] == variable("C", "in_out", "INT", 100)
        assert [m["kind"] for m in seen if m["type"] == "log"] == ["write"]  # the same halt: not logged again
        ws.send_json({"type": "breakpoint_clear"})
        ws.send_json({"type": "continue"})
        status, _ = recv_until(ws, of_type("status", state="stopped"))
        assert status["stack"] == []


def test_a_step_through_a_past_scan_carries_the_call_stack_of_the_point_reached(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """Issue 23 item 3 with issue 25 item 6: stepping line by line through scan 2 (replayed from the state scan 1
    left: x = 5) halts in Inc twice, each time with the call stack the live debugger shows. In the method's call, n
    (2) went to Inc's in-out and became 3; in Main's own call, c refers to x and became 6."""
    project, diagnostics = source_to_project(TEXT, "stack")
    assert project is not None and diagnostics == []
    workspace.create(project)
    sim_id = client.post("/api/projects/stack/simulations").json()["id"]
    for _ in range(3):
        client.post(f"/api/simulations/{sim_id}/cycle")
    client.post(f"/api/simulations/{sim_id}/seek", json={"scan": 2})
    stacks_in_inc = []
    for _ in range(20):  # a bounded walk: the scan has fewer points than this
        stepping = client.post(f"/api/simulations/{sim_id}/history/step", json={"granularity": "statement"}).json()[
            "history"
        ]["stepping"]
        if stepping["at"] is None:
            assert stepping["stack"] == []
            break
        innermost = stepping["stack"][-1]["at"]
        assert (innermost["pou"], innermost["line"]) == (stepping["at"]["pou"], stepping["at"]["line"])
        if (stepping["at"]["pou"], stepping["at"]["line"]) == ("INC", line("Inc := c;")):
            stacks_in_inc.append(stepping["stack"])
    assert [[where(f) for f in stack] for stack in stacks_in_inc] == [
        [
            at("MAIN", "MAIN", "y := m.Start(n := 2);"),
            at("MOTOR.START", "MAIN.M", "Start := Inc(n) * 10;"),
            at("INC", None, "Inc := c;"),
        ],
        [at("MAIN", "MAIN", "Inc(x);"), at("INC", None, "Inc := c;")],
    ]
    method, inc = stacks_in_inc[0][1], stacks_in_inc[0][2]
    assert method["variables"] == [
        variable("N", "input", "INT", 3),
        variable("R", "var", "REAL", 1.5),
        variable("START", "result", "INT", 0),
    ]
    assert inc["variables"][0] == variable("C", "in_out", "INT", 3)
    assert stacks_in_inc[1][1]["variables"][0] == variable("C", "in_out", "INT", 6)
