"""Properties marked {attribute 'monitoring'} online over the real websocket (issue 25): watched, traced, refused
when written, and a faulting GET as a located log entry with no value (never a wrong one). Expected values follow
from the program text by hand and CODESYS's online help ("Attribute: monitoring": 'variable' shows the value of
the last Get or Set, read only; 'call' runs the Get to show it)."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

from .test_simulations_support import log_of, of_type, recv, recv_until, registry, subscribe
from .test_trace import collect, cycles, done

__all__ = ["registry"]  # fixture used below

SOURCE = """
FUNCTION_BLOCK Tank
VAR amount : INT; END_VAR
{attribute 'monitoring' := 'variable'}
PROPERTY Level : INT
GET
Level := amount * 10;
END_GET
SET
amount := Level;
END_SET
END_PROPERTY
{attribute 'monitoring' := 'call'}
PROPERTY Share : INT
GET
Share := 100 / amount;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : Tank; n : INT; x : INT; END_VAR
n := n + 1;
IF n >= 2 THEN t.Level := n; END_IF;
IF n >= 3 THEN x := t.Level; END_IF;
END_PROGRAM
"""
FAULT_LINE = SOURCE.splitlines().index("Share := 100 / amount;") + 1


@pytest.fixture
def sim_id(client: TestClient, workspace: Workspace, registry: SimulationRegistry) -> str:
    project, diagnostics = source_to_project(SOURCE, "monitored")
    assert project is not None, diagnostics
    workspace.create(project)
    response = client.post("/api/projects/monitored/simulations")
    assert response.status_code == 201, response.text
    return str(response.json()["id"])


def values_of(ws: Any, scan: int) -> dict[str, Any]:
    message, _ = recv_until(ws, of_type("values", scan=scan))
    return dict(message["changed"])


def test_both_modes_are_watched_scan_by_scan_and_a_faulting_get_is_logged_where_it_faults(
    client: TestClient, sim_id: str
) -> None:
    """Scan 2: SET 2 (Level 2), Share 100 / 2; scan 3: SET 3 then GET 30 (Level 30), Share 100 / 3 = 33."""
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        ws.send_json({"type": "subscribe", "paths": ["Main.t.Level", "Main.t.Share"], "interval_ms": 20})
        first, before = recv_until(ws, of_type("values"))
        assert first["changed"] == {"MAIN.T.LEVEL": 0, "MAIN.T.SHARE": None}  # amount is 0: its GET faults
        assert first["types"]["MAIN.T.SHARE"] == {"name": "INT", "names": None}
        logs = [m for m in before if log_of("fault")(m)]  # logged as the frame was read, once
        assert len(logs) == 1
        log = logs[0]
        assert log["level"] == "error"
        assert log["message"].startswith(
            f"MAIN.T.SHARE: its GET faulted: division by zero: 100 / 0 at POU TANK.SHARE.GET, line {FAULT_LINE} "
            "column 1, task monitoring, scan 0"
        )
        assert (log["at"]["pou"], log["at"]["line"]) == ("TANK.SHARE.GET", FAULT_LINE)
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 1) == {}
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 2) == {"MAIN.T.LEVEL": 2, "MAIN.T.SHARE": 50}
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 3) == {"MAIN.T.LEVEL": 30, "MAIN.T.SHARE": 33}


def test_writing_a_monitored_property_is_refused_with_the_reason(client: TestClient, sim_id: str) -> None:
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        subscribe(ws, ["Main.n"])
        ws.send_json({"type": "write", "path": "Main.t.Level", "value": 1})
        error, _ = recv_until(ws, of_type("error"))
        assert error["message"] == (
            "MAIN.T.LEVEL cannot be written: a property monitored as 'variable' shows the value of its last GET or "
            "SET, and is read only (CODESYS); assign the property in the program or write the variables its SET "
            "writes"
        )
        ws.send_json({"type": "write", "path": "Main.t.Share", "value": 1})
        error, _ = recv_until(ws, of_type("error"))
        assert error["message"] == (
            "MAIN.T.SHARE cannot be written: a property monitored as 'call' is written by running its SET, and it "
            "has none"
        )


def test_both_modes_are_traced_and_a_faulting_get_leaves_a_gap(client: TestClient, sim_id: str) -> None:
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        subscribe(ws, [], interval_ms=20)
        ws.send_json({"type": "trace_start", "paths": ["Main.t.Level", "Main.t.Share"], "samples": 3})
        cycles(ws, 3)
        merged, _ = collect(ws, done)
    assert merged["scans"] == [1, 2, 3]
    assert merged["values"] == {"MAIN.T.LEVEL": [0, 2, 30], "MAIN.T.SHARE": [None, 50, 33]}


def test_the_instance_tree_lists_the_monitored_properties_after_the_variables(
    client: TestClient, workspace: Workspace
) -> None:
    """CODESYS's online view of an FB instance shows its monitored properties besides its variables."""
    project, _ = source_to_project(SOURCE.replace("END_PROPERTY\nEND_FUNCTION_BLOCK", HIDDEN), "tree")
    workspace.create(project)
    response = client.get("/api/projects/tree/variables", params={"path": "Main.t"})
    assert response.status_code == 200, response.text
    children = [(c["name"], c["path"], c["type"], c["var_class"]) for c in response.json()["children"]]
    assert children == [
        ("amount", "Main.t.amount", "INT", "VAR"),
        ("Level", "Main.t.Level", "INT", "PROPERTY"),
        ("Share", "Main.t.Share", "INT", "PROPERTY"),
    ]


HIDDEN = """END_PROPERTY
PROPERTY Hidden : INT
GET
Hidden := amount;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK"""


def test_the_history_finds_a_variable_propertys_changes_and_refuses_a_called_one(
    client: TestClient, sim_id: str
) -> None:
    """Level after scans 1..3: 0, 2, 30 (SET 2; SET 3 then GET 30)."""
    for _ in range(3):
        client.post(f"/api/simulations/{sim_id}/cycle")
    find = f"/api/simulations/{sim_id}/history/find"
    assert client.get(find, params={"path": "Main.t.Level", "scan": 1}).json() == {"scan": 2}
    assert client.get(find, params={"condition": "Main.t.Level >= 30", "scan": 1}).json() == {"scan": 3}
    refused = client.get(find, params={"path": "Main.t.Share", "scan": 1})
    assert refused.status_code == 422
    assert refused.json()["detail"]["message"] == (
        "MAIN.T.SHARE is a property monitored as 'call': finding its changes would run its GET on every recorded "
        "scan; use 'variable' (its last value is recorded) or the variables its GET reads"
    )


VALVE = """
FUNCTION_BLOCK Valve
VAR pos : INT; END_VAR
{attribute 'monitoring' := 'call'}
PROPERTY Opening : INT
GET
Opening := pos;
END_GET
SET
pos := 1000 / Opening;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR v : Valve; END_VAR
END_PROGRAM
"""


def test_a_write_of_a_call_property_runs_its_set_and_a_fault_in_it_is_logged_where_it_faults(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """1000 / 4 = 250 before scan 1; writing 0 faults in the SET (logged at its line), the value stays 250."""
    project, _ = source_to_project(VALVE, "valve")
    workspace.create(project)
    sim_id = client.post("/api/projects/valve/simulations").json()["id"]
    line = VALVE.splitlines().index("pos := 1000 / Opening;") + 1
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        assert subscribe(ws, ["Main.v.Opening"])["changed"] == {"MAIN.V.OPENING": 0}
        ws.send_json({"type": "write", "path": "Main.v.Opening", "value": 4})
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 1) == {"MAIN.V.OPENING": 250}
        ws.send_json({"type": "write", "path": "Main.v.Opening", "value": 0})
        ws.send_json({"type": "single_cycle"})
        log, _ = recv_until(ws, log_of("fault"))
        assert log["message"].startswith(f"division by zero: 1000 / 0 at POU VALVE.OPENING.SET, line {line} column 1")
        assert (log["at"]["pou"], log["at"]["line"]) == ("VALVE.OPENING.SET", line)
        ws.send_json({"type": "single_cycle"})
        values_of(ws, 3)  # the tasks went on
        ws.send_json({"type": "force", "path": "Main.v.Opening", "value": 4})
        error, _ = recv_until(ws, of_type("error"))
        assert error["message"] == (
            "MAIN.V.OPENING is a property monitored as 'call': a write runs its SET once, and no variable holds its "
            "value to force"
        )
