"""Online paths into named global variable lists over the websocket: ``GVL_IO.bStart`` subscribed, written,
forced and released as CODESYS's watch list names a GVL's variable (tests/engine/test_global_variable_lists.py
has the language side). The server names a list's variable as it names every global, by its own name (``BSTART``):
a name is declared by one list only, so the name alone is the variable."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import GlobalVariableList, Project, Task
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import log_of, of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixtures used below

PROJECT = Project(
    name="lists",
    gvls=[
        GlobalVariableList(
            name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\n    nCount : INT;\nEND_VAR"
        ),
        GlobalVariableList(name="GVL", text="VAR_GLOBAL\n    counter : INT;\nEND_VAR"),
    ],
    pous=[
        st_program(
            "Main", "", "GVL.counter := GVL.counter + 1;\nIF GVL_IO.bStart THEN GVL_IO.nCount := counter; END_IF;"
        )
    ],
    tasks=[Task(name="Fast", interval="T#10ms", programs=["Main"])],
)


def test_list_paths_are_watched_written_and_forced(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(PROJECT)
    sim = client.post("/api/projects/lists/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["GVL_IO.bStart", "GVL_IO.nCount", "GVL.counter", "counter"])
        assert first["changed"] == {"BSTART": False, "NCOUNT": 0, "COUNTER": 0}
        ws.send_json({"type": "write", "path": "gvl_io.bstart", "value": "TRUE"})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=1))
        assert values["changed"] == {"BSTART": True, "NCOUNT": 1, "COUNTER": 1}
        ws.send_json({"type": "force", "path": "GVL_IO.nCount", "value": 40})
        log, _ = recv_until(ws, log_of("force"))
        assert log["message"] == "forced NCOUNT := 40"
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=2))
        assert (values["forced"], values["changed"]["NCOUNT"]) == (["NCOUNT"], 40)
        ws.send_json({"type": "unforce", "path": "GVL_IO.nCount"})
        recv_until(ws, log_of("release"))
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=3))
        assert values["changed"]["NCOUNT"] == 3  # the program's own write again: counter is 3
        ws.send_json({"type": "subscribe", "paths": ["GVL_IO.counter"]})
        error, _ = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == (
            "bad_path",
            "the global variable list GVL_IO has no variable 'counter'",
        )
