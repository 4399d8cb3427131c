"""The process image online (issue 16): a simulation lists the addresses its program uses, and the
websocket reads, writes and forces them by address like any variable."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import Project, Task
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]

DECLARATIONS = """VAR
    Start AT %IX0.1 : BOOL;
    Level AT %IW2 : INT;
    Lamp AT %QX3.0 : BOOL;
END_VAR"""
BODY = """Lamp := Start;
%QW4 := Level + 1;
%MX1.7 := %IX0.2;"""


def io_sim(client: TestClient, workspace: Workspace) -> str:
    project = Project(
        name="io",
        pous=[st_program("Main", DECLARATIONS, BODY)],
        tasks=[Task(name="Fast", interval="T#10ms", programs=["Main"])],
    )
    workspace.create(project)
    response = client.post("/api/projects/io/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def test_the_simulation_lists_every_address_in_order_with_its_declared_names(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim_id = io_sim(client, workspace)
    io = client.get(f"/api/simulations/{sim_id}").json()["io"]
    assert [(p["area"], p["address"], p["type"], p["names"]) for p in io] == [
        ("I", "%IX0.1", "BOOL", ["MAIN.START"]),
        ("I", "%IX0.2", "BOOL", []),
        ("I", "%IW2", "INT", ["MAIN.LEVEL"]),
        ("Q", "%QX3.0", "BOOL", ["MAIN.LAMP"]),
        ("Q", "%QW4", "INT", []),
        ("M", "%MX1.7", "BOOL", []),
    ]


def test_addresses_are_read_written_and_forced_over_the_websocket(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim_id = io_sim(client, workspace)
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["%IX0.1", "%QX3.0", "%QW4", "%QB4", "%MX1.7"])
        assert first["changed"] == {"%IX0.1": False, "%QX3.0": False, "%QW4": 0, "%QB4": 0, "%MX1.7": False}
        ws.send_json({"type": "write", "path": "%IX0.1", "value": True})
        ws.send_json({"type": "write", "path": "%IW2", "value": 299})
        ws.send_json({"type": "force", "path": "%IX0.2", "value": "TRUE"})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=1))
        assert values["changed"] == {"%IX0.1": True, "%QX3.0": True, "%QW4": 300, "%QB4": 44, "%MX1.7": True}
        assert values["forced"] == ["%IX0.2"]


def test_overlapping_addresses_are_rows_of_their_own(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    project = Project(
        name="overlap",
        pous=[st_program("Main", "VAR b AT %MB0 : BYTE; END_VAR", "%MW0 := 16#0102; %MD0 := %MD0;")],
        tasks=[Task(name="Fast", interval="T#10ms", programs=["Main"])],
    )
    workspace.create(project)
    sim_id = client.post("/api/projects/overlap/simulations").json()["id"]
    io = client.get(f"/api/simulations/{sim_id}").json()["io"]
    assert [(p["address"], p["type"], p["names"]) for p in io] == [
        ("%MB0", "BYTE", ["MAIN.B"]),
        ("%MW0", "INT", []),  # the default types of S002 Table 10.1
        ("%MD0", "REAL", []),
    ]
