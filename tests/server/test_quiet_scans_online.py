"""Over the websocket, every frame's power flow is of the scan its values are of (issue 27 item 2).

A running simulation records the viewed networks only on the scans a frame may show (docs/runtime.md, "Scans no
frame shows"): at 100x real time ten 10 ms scans run between two 20 ms frames. The program toggles B in every scan
through a normally closed contact on B (``--|/ B |--( B )--``), so that contact conducts in a scan exactly when B
is TRUE at its end: a frame whose power flow came from another scan than its values shows the contact and B apart
in about every other frame. A client folds the frames as the browser does (values and power merge) and checks each
one, while running, after a write, after stop and single cycles, and after a runtime error in a running scan.
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


def _toggler() -> Project:
    divide = ld.Box(id="d", call="DIV", en=True, inputs={"IN1": "X", "IN2": "Y"}, outputs={"OUT": "Z"})
    networks = [
        ld.LdNetwork(id="n1", elements=[ld.Contact(id="t", var="B", mode="nc"), ld.Coil(id="b", var="B")]),
        ld.LdNetwork(id="n2", elements=[ld.Contact(id="s", var="START"), divide, ld.Coil(id="o", var="Q")]),
    ]
    declarations = "VAR B, START, Q : BOOL; X : INT := 7; Y : INT; Z : INT; END_VAR"
    pou = Pou(name="Main", kind="program", language="ld", declarations=declarations, body=ld.LdBody(networks=networks))
    return Project(name="toggler", pous=[pou], tasks=[Task(name="main", interval="T#10ms", programs=["Main"])])


class _Held:
    """What the browser holds after each frame (monitor.ts: values and power merge)."""

    def __init__(self, first: dict[str, Any]) -> None:
        self.values: dict[str, Any] = dict(first["changed"])
        self.power: dict[str, Any] = dict(first["power"])
        self.frames = 0

    def fold(self, message: dict[str, Any]) -> None:
        if message["type"] != "values":
            return
        self.values.update(message["changed"])
        self.power.update(message["power"])
        self.frames += 1
        if self.values.get("MAIN.B") is not None and "Main/t" in self.power and self.power["Main/t"] is not None:
            assert self.power["Main/t"] == self.values["MAIN.B"], (message["scan"], self.values, self.power)


def _start(client: TestClient, workspace: Workspace) -> str:
    workspace.create(_toggler())
    response = client.post("/api/projects/toggler/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def _read(ws, held: _Held, predicate, timeout: float = 5.0) -> dict[str, Any]:
    message, seen = recv_until(ws, predicate, timeout=timeout)
    for m in [*seen, message]:
        held.fold(m)
    return message


def test_frames_of_a_simulation_running_at_100x_show_the_power_flow_of_their_scan(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim = _start(client, workspace)
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        recv(ws)
        held = _Held(subscribe(ws, ["Main.B", "Main.X"], elements=[{"pou_instance": "Main", "ids": ["t", "b", "s"]}]))
        ws.send_json({"type": "speed", "scale": 100})
        ws.send_json({"type": "run"})
        _read(ws, held, of_type("status", state="running"))
        scans = []
        for _ in range(30):  # frames while running: ~10 scans apart, the last of them recorded
            scans.append(_read(ws, held, of_type("values"))["scan"])
        assert scans[-1] - scans[0] >= 60, scans  # (many scans between frames: most recorded nothing)
        ws.send_json({"type": "write", "path": "Main.X", "value": 9})  # a command while running: the next frame
        _read(ws, held, lambda m: m["type"] == "values" and m["changed"].get("MAIN.X") == 9)
        ws.send_json({"type": "stop"})
        _read(ws, held, of_type("status", state="stopped"))
        stopped = _read(ws, held, of_type("values"))
        for _ in range(3):  # single cycles of the stopped simulation: each frame shows its scan
            ws.send_json({"type": "single_cycle"})
            _read(ws, held, of_type("values", scan=stopped["scan"] + 1))
            stopped = {"scan": stopped["scan"] + 1}
        assert held.power["Main/t"] is not None and held.frames >= 35


def test_a_runtime_error_in_a_scan_no_frame_was_due_after_shows_that_scans_power_flow(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """START set while running at 100x: the next scan divides by Y = 0. Whether that scan recorded its networks or
    not (recomputed from the scan history then), the frame after the fault shows its power flow: START's contact
    conducting, B's contact as B."""
    sim = _start(client, workspace)
    with client.websocket_connect(f"/api/simulations/{sim}/ws") as ws:
        recv(ws)
        held = _Held(subscribe(ws, ["Main.B"], elements=[{"pou_instance": "Main", "ids": ["t", "s", "d"]}]))
        ws.send_json({"type": "speed", "scale": 100})
        ws.send_json({"type": "run"})
        for _ in range(5):
            _read(ws, held, of_type("values"))
        assert held.power["Main/s"] is False
        ws.send_json({"type": "write", "path": "Main.START", "value": True})
        fault = _read(ws, held, log_of("fault"))
        assert "division by zero: 7 / 0" in fault["message"]
        _read(ws, held, of_type("status", state="faulted"))
        frame = _read(ws, held, of_type("values"))
        assert frame["scan"] == fault["scan"] + 1  # (frames count completed scans)
        assert held.power["Main/s"] is True  # the faulted scan's own power flow
        assert held.power["Main/t"] == held.values["MAIN.B"]
