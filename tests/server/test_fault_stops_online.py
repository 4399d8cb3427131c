"""Over the websocket, the frame after a runtime error shows the elements after the fault as not run.

A fault in the middle of an LD rung stops the scan there (docs/runtime.md, "Probes"): the frame after it shows the
elements before the fault with that scan's power flow and values, the faulting box and the coil after it as not
run (None), never the power flow an earlier scan left next to the fault message.
"""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient

from ladderlab.model import ld
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .test_simulations_support import log_of, of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixture used below

IDS = ["s", "a", "a.OUT", "d", "d.OUT", "o"]


def _divider() -> Project:
    add = ld.Box(id="a", call="ADD", en=True, inputs={"IN1": "X", "IN2": "1"}, outputs={"OUT": "W"})
    divide = ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "W", "IN2": "Y"}, outputs={"OUT": "Z"})
    network = ld.LdNetwork(id="n1", elements=[ld.Contact(id="s", var="START"), add, divide, ld.Coil(id="o", var="Q")])
    declarations = "VAR START : BOOL := TRUE; Q : BOOL; X : INT := 7; Y : INT := 2; W, Z : INT; END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=[network]))
    return Project(name="divider", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


def test_the_frame_after_a_fault_shows_the_elements_after_it_not_run(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(_divider())
    response = client.post("/api/projects/divider/simulations")
    assert response.status_code == 201, response.text
    sim = response.json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        recv(ws)
        power: dict[str, Any] = dict(
            subscribe(ws, ["Main.Z"], elements=[{"pou_instance": "Main", "ids": IDS}])["power"]
        )

        def until(predicate) -> dict[str, Any]:
            message, seen = recv_until(ws, predicate)
            for m in [*seen, message]:
                if m["type"] == "values":
                    power.update(m["power"])
            return message

        ws.send_json({"type": "single_cycle"})
        until(of_type("values", scan=1))
        assert {e: power[f"Main/{e}"] for e in IDS} == {
            "s": True,
            "a": True,
            "a.OUT": 8,
            "d": True,
            "d.OUT": 4,
            "o": True,
        }
        ws.send_json({"type": "write", "path": "Main.Y", "value": 0})
        ws.send_json({"type": "write", "path": "Main.X", "value": 9})
        ws.send_json({"type": "single_cycle"})
        fault = until(log_of("fault"))
        assert "division by zero: 10 / 0" in fault["message"]
        until(of_type("values", scan=2))
        assert {e: power[f"Main/{e}"] for e in IDS} == {
            "s": True,
            "a": True,
            "a.OUT": 10,
            "d": None,
            "d.OUT": None,
            "o": None,
        }
