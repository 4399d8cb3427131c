"""The lab bench over HTTP and the websocket (issue 21): panel input events applied at the next scan and
logged with it, injected faults, the time scale, run until, the inputs as a file, the examples."""

from __future__ import annotations

import json
import struct

from fastapi.testclient import TestClient

from ladderlab.examples import EXAMPLES_DIR, example_names
from ladderlab.simulation.registry import SimulationRegistry

from .test_simulations_support import log_of, motor_sim, of_type, recv, recv_until, registry, subscribe, wait_for

__all__ = ["motor_sim", "registry"]


def _tank(client: TestClient, registry: SimulationRegistry) -> str:
    """The tank example (its reference solution), simulated, stopped."""
    assert client.post("/api/projects", json={"name": "tank", "example": "tank_filling"}).status_code == 201
    response = client.post("/api/projects/tank/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def _ws(sim: str) -> str:
    return f"/api/simulations/{sim}/ws"


def test_a_panel_event_while_stopped_waits_for_the_next_scan_and_is_logged_with_it(client, registry):
    sim = _tank(client, registry)
    with client.websocket_connect(_ws(sim)) as ws:
        recv(ws)
        assert subscribe(ws, ["Auto", "Pump"])["changed"] == {"AUTO": False, "PUMP": False}
        ws.send_json({"type": "panel", "path": "Auto", "value": True, "panel": "Tank", "widget": "mode"})
        ws.send_json({"type": "single_cycle"})
        entry, _ = recv_until(ws, log_of("panel"))
        assert (entry["message"], entry["scan"]) == ("panel Tank/mode: Auto := TRUE", 0)
        values, _ = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 1)
        assert values["changed"] == {"AUTO": True, "PUMP": True}  # the low switch is closed: the pump starts
    info = client.get(f"/api/simulations/{sim}").json()
    assert (info["scan_count"], info["pending_inputs"]) == (1, 0)
    lines = client.get(f"/api/simulations/{sim}/inputs").text.splitlines()
    assert [json.loads(line) for line in lines] == [
        {"scan": 0, "kind": "panel", "path": "Auto", "value": True, "source": "panel Tank/mode"}
    ]


def test_bad_panel_and_fault_requests_are_refused_with_the_reason(client, registry):
    sim = _tank(client, registry)
    with client.websocket_connect(_ws(sim)) as ws:
        recv(ws)
        cases = [
            ({"type": "panel", "path": "Nope", "value": True}, "bad_path", "unknown variable or program 'Nope'"),
            ({"type": "panel", "path": "Tank.Level", "value": "high"}, "bad_value", "TANK.LEVEL"),
            ({"type": "inject", "path": "LSH", "mode": "stuck"}, "bad_value", "hold a BOOL with stuck_true"),
            ({"type": "inject", "path": "LSH", "mode": "melted"}, "bad_message", "inject.mode"),
            ({"type": "inject_clear", "path": "LSH"}, "bad_path", "LSH has no injected fault"),
            ({"type": "speed", "scale": 500}, "bad_message", "speed.scale"),
            ({"type": "run_until"}, "bad_message", "give a condition or a time_ms"),
            ({"type": "run_until", "condition": "Tank.Level"}, "bad_value", "is not a BOOL"),
            ({"type": "run_until", "condition": "Tank.Level >= lots"}, "bad_value", "TANK.LEVEL"),
        ]
        for message, code, words in cases:
            ws.send_json(message)
            error, _ = recv_until(ws, of_type("error"))
            assert error["code"] == code and words in error["message"], (message, error)
    assert client.get(f"/api/simulations/{sim}").json()["pending_inputs"] == 0


def test_an_injected_fault_is_in_every_values_message_and_in_the_log(client, registry):
    sim = _tank(client, registry)
    with client.websocket_connect(_ws(sim)) as ws:
        recv(ws)
        subscribe(ws, ["LSL", "Tank.Level"])
        ws.send_json({"type": "inject", "path": "LSL", "mode": "stuck_false"})
        ws.send_json({"type": "inject", "path": "Tank.Level", "mode": "noisy", "amplitude": 2.0})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 1)
        assert values["injected"] == {"LSL": "stuck_false", "TANK.LEVEL": "noisy"}
        # the empty tank closes the low switch, but the program reads it stuck open: it stays FALSE (unchanged)
        assert "LSL" not in values["changed"] and abs(values["changed"]["TANK.LEVEL"]) <= 2.0
        ws.send_json({"type": "inject_clear"})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 2)
        assert values["injected"] == {} and values["changed"]["LSL"] is True
    lines = [json.loads(line) for line in client.get(f"/api/simulations/{sim}/inputs").text.splitlines()]
    assert [(line["scan"], line["kind"], line.get("mode")) for line in lines] == [
        (0, "fault", "stuck_false"),
        (0, "fault", "noisy"),
        (1, "clear_fault", None),
    ]
    assert isinstance(lines[1]["seed"], int)  # chosen by the server, recorded so the noise replays


def f32(x: float) -> float:
    return struct.unpack("f", struct.pack("f", x))[0]


def tank_scans_to(level_limit: float) -> tuple[int, float]:
    """The plant's arithmetic in REAL (float32), computed here: scans until the level reaches the limit.
    Scan 0 runs the plant with the pump still off; the pump runs from scan 1: +0.05, less 1.5 % / s."""
    level, scan, pump = 0.0, 0, False
    while True:
        gained = f32(level + (f32(0.05) if pump else 0.0))
        level = min(max(f32(gained - f32(f32(1.5) * f32(0.01))), 0.0), 100.0)
        if level >= level_limit:
            return scan, level
        pump, scan = True, scan + 1


def test_run_until_a_condition_stops_after_the_scan_where_it_holds(client, registry):
    """At 100x, until the high switch (80 %): the run stops after the first scan with the level at 80 % or more."""
    sim = _tank(client, registry)
    with client.websocket_connect(_ws(sim)) as ws:
        recv(ws)
        ws.send_json({"type": "panel", "path": "Auto", "value": True})
        ws.send_json({"type": "speed", "scale": 100})
        ws.send_json({"type": "run_until", "condition": "LSH"})
        reached = lambda m: log_of("state")(m) and "run until: LSH holds after scan" in m["message"]  # noqa: E731
        _, seen = recv_until(ws, reached, timeout=60)
        messages = [m["message"] for m in seen if m["type"] == "log"]
        assert "time scale 100x real time" in messages and "run until LSH" in messages
    wait_for(lambda: client.get(f"/api/simulations/{sim}").json()["state"] == "stopped")
    info = client.get(f"/api/simulations/{sim}").json()
    scan, level = tank_scans_to(80.0)
    assert (info["speed"], info["until"], info["scan_count"]) == (100, None, scan + 1)
    assert registry.get(sim).handle.read("Tank.Level") == level


def test_run_until_a_virtual_time_runs_every_scan_due_by_then(client, registry):
    sim = _tank(client, registry)
    with client.websocket_connect(_ws(sim)) as ws:
        recv(ws)
        ws.send_json({"type": "speed", "scale": 100})
        ws.send_json({"type": "run_until", "time_ms": 500})
        recv_until(ws, of_type("status", state="stopped"), timeout=20)
    wait_for(lambda: client.get(f"/api/simulations/{sim}").json()["state"] == "stopped")
    info = client.get(f"/api/simulations/{sim}").json()
    assert (info["scan_count"], info["time_ms"]) == (50, 500)


def test_the_examples_list_the_exercises_first_and_start_from_the_students_files(client):
    examples = client.get("/api/examples").json()
    names = [e["name"] for e in examples]
    assert names[:8] == [
        "room_lights",
        "fire_alarm",
        "traffic_lights",
        "tank_filling",
        "conveyor_sorter",
        "garage_door",
        "star_delta",
        "batch_mixer",
    ]
    assert set(names) == set(example_names(EXAMPLES_DIR))
    assert all(e["exercise"] and e["plants"] and e["panels"] for e in examples[:8])
    client.post("/api/projects", json={"name": "solution", "example": "room_lights"})
    client.post("/api/projects", json={"name": "student", "example": "room_lights", "start": "exercise"})
    solution = client.get("/api/projects/solution").json()["project"]
    student = client.get("/api/projects/student").json()["project"]
    lights = {p["name"]: p for p in solution["pous"]}["Lights"]
    mine = {p["name"]: p for p in student["pous"]}["Lights"]
    assert lights["declarations"] == mine["declarations"] and "lamp := VX <> VIX;" in lights["body"]
    assert "lamp" not in mine["body"].replace("lamp on", "") and mine["body"].lstrip().startswith("(*")
    assert student["panels"] == solution["panels"] and student["exercise"].startswith("# Room lighting")
    response = client.post("/api/projects", json={"name": "x", "example": "nope"})
    assert response.status_code == 422 and "unknown example 'nope'" in response.json()["detail"]["message"]


def test_exports_leave_the_plants_out_unless_asked(client):
    client.post("/api/projects", json={"name": "tank", "example": "tank_filling"})
    plain = client.get("/api/projects/tank/export/st").json()["text"]
    assert "PROGRAM Tank" not in plain and "PROGRAM Filling" in plain.replace("PROGRAM Filling WITH", "")
    both = client.get("/api/projects/tank/export/st", params={"with_plants": True}).json()["text"]
    assert "PROGRAM Tank" in both and "TASK PLANTS(INTERVAL := T#10ms, PRIORITY := 0);" in both
    assert "PROGRAM Tank WITH PLANTS : Tank;" in both
    xml = client.get("/api/projects/tank/export/plcopen").text
    assert 'name="Tank"' not in xml and 'name="Filling"' in xml
    assert 'name="Tank"' in client.get("/api/projects/tank/export/plcopen", params={"with_plants": True}).text


def test_a_panel_bound_to_direct_addresses_drives_the_motor(client, registry, motor_sim):
    """Widgets may be bound to direct addresses (issue 21 item 1): the motor example declares Start AT %IX0.0
    and Motor AT %QX0.0; a press at %IX0.0 seals the motor in, reported under the addresses subscribed."""
    with client.websocket_connect(_ws(motor_sim)) as ws:
        recv(ws)
        assert subscribe(ws, ["%IX0.0", "%QX0.0"])["changed"] == {"%IX0.0": False, "%QX0.0": False}
        ws.send_json({"type": "panel", "path": "%IX0.0", "value": True, "panel": "Desk", "widget": "start"})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, lambda m: m["type"] == "values" and m["scan"] == 1)
        assert values["changed"] == {"%IX0.0": True, "%QX0.0": True}
        ws.send_json({"type": "panel", "path": "%IX7.7", "value": True})
        error, _ = recv_until(ws, of_type("error"))
        assert error["code"] == "bad_path"
        assert error["message"].endswith(
            "%IX7.7 is outside the process image: the program uses 1 byte(s) of %I (%IB0..%IB0)"
        )


def test_a_widget_bound_to_a_variable_the_program_lacks_stops_the_build_at_the_widget(client, registry):
    """As CODESYS does for its visualisations: the panel could not show the variable, so the build says which
    panel, widget and field, and the simulation does not start."""
    client.post("/api/projects", json={"name": "tank", "example": "tank_filling"})
    stored = client.get("/api/projects/tank").json()
    project = stored["project"]
    tank = project["panels"][0]
    tank["widgets"][2]["bind"] = "Tank.Levl"
    tank["widgets"][3]["visible"] = "%IX7.7"
    saved = client.put("/api/projects/tank", json=project, headers={"If-Match": f'"{stored["revision"]}"'})
    assert saved.status_code == 200, saved.text
    response = client.post("/api/projects/tank/simulations")
    assert response.status_code == 422
    found = [(d["file"], d["json_path"], d["element"], d["message"]) for d in response.json()["detail"]["diagnostics"]]
    assert found == [
        (
            "hmi/Tank.json",
            "widgets[2].bind",
            "tank",
            "panel Tank, widget tank (bind): TANK has no variable 'Levl' - did you mean 'LEVEL'?",
        ),
        (
            "hmi/Tank.json",
            "widgets[3].visible",
            "lsh",
            "panel Tank, widget lsh (visible): %IX7.7 is outside the process image: the program uses 0 byte(s) of %I",
        ),
    ]
