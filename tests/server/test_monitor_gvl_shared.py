"""A name two global variable lists declare, online over the websocket and HTTP (issue 25): ``GVL_A.x`` and
``GVL_B.x`` are two variables, watched, written and forced apart, and the server names each by its qualified path
(the name alone is no variable: CODESYS's "ambiguous use of name"); the Variables view opens each list's instance.
tests/engine/test_gvl_shared_names.py has the language side."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import GlobalVariableList, Project, Task
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import log_of, of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixtures used below

PROJECT = Project(
    name="shared",
    gvls=[
        GlobalVariableList(name="GVL_A", text="VAR_GLOBAL\n    x : INT := 5;\n    t : TON;\nEND_VAR"),
        GlobalVariableList(name="GVL_B", text="VAR_GLOBAL\n    x : INT;\n    t : TP;\nEND_VAR"),
    ],
    pous=[st_program("Main", "", "GVL_B.x := GVL_B.x + GVL_A.x;")],
    tasks=[Task(name="Fast", interval="T#10ms", programs=["Main"])],
)


def test_each_lists_variable_is_watched_written_and_forced_by_its_qualified_path(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(PROJECT)
    sim = client.post("/api/projects/shared/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["GVL_A.x", "gvl_b.X"])
        assert first["changed"] == {"GVL_A.X": 5, "GVL_B.X": 0}
        ws.send_json({"type": "write", "path": "GVL_A.x", "value": "7"})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=1))
        assert values["changed"] == {"GVL_A.X": 7, "GVL_B.X": 7}
        ws.send_json({"type": "force", "path": "GVL_B.x", "value": 100})
        log, _ = recv_until(ws, log_of("force"))
        assert log["message"] == "forced GVL_B.X := 100"
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=2))
        assert (values["forced"], values["changed"]) == (["GVL_B.X"], {"GVL_B.X": 100})
        ws.send_json({"type": "subscribe", "paths": ["x"]})
        error, _ = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == (
            "bad_path",
            "x is declared in several global variable lists: write GVL_A.X or GVL_B.X",
        )


def test_each_lists_instance_opens_in_the_instance_tree(client: TestClient, workspace: Workspace) -> None:
    workspace.create(PROJECT)
    children = {
        path: [
            (n["name"], n["path"])
            for n in client.get("/api/projects/shared/variables", params={"path": path}).json()["children"]
        ]
        for path in ("GVL_A.t", "GVL_B.t")
    }
    assert children["GVL_A.t"] == [("IN", "GVL_A.t.IN"), ("PT", "GVL_A.t.PT"), ("Q", "GVL_A.t.Q"), ("ET", "GVL_A.t.ET")]
    assert children["GVL_B.t"] == [("IN", "GVL_B.t.IN"), ("PT", "GVL_B.t.PT"), ("Q", "GVL_B.t.Q"), ("ET", "GVL_B.t.ET")]
    symbols = client.get("/api/projects/shared/pous/Main/symbols").json()
    assert [(s["name"], s["gvl"]) for s in symbols["globals"]] == [
        ("GVL_A.x", "GVL_A"),
        ("GVL_B.x", "GVL_B"),
        ("GVL_A.t", "GVL_A"),
        ("GVL_B.t", "GVL_B"),
    ]
