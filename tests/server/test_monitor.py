"""The online websocket (issue 6, "Websocket"): subscribe, diffs, write, force, breakpoints, step,
single cycle, several clients, runtime errors, origin check, deletion."""

from __future__ import annotations

import asyncio
import itertools
import json
import time

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

from ladderlab.model import Project
from ladderlab.server.app import create_app
from ladderlab.server.security import Security
from ladderlab.simulation.registry import SimulationRegistry, SimulationSettings
from ladderlab.storage import Workspace
from tests.support import api_client

from .helpers import st_program
from .test_simulations_support import (
    counter,
    counter_project,
    entry,
    install,
    log_of,
    motor_sim,
    of_type,
    recv,
    recv_until,
    registry,
    subscribe,
    wait_for,
)

__all__ = ["counter", "motor_sim", "registry"]  # fixtures used below


def ws_url(sim_id: str) -> str:
    return f"/api/simulations/{sim_id}/ws"


def test_connecting_reports_the_state_then_a_full_snapshot_of_the_subscription(
    client: TestClient, counter: str
) -> None:
    client.post(f"/api/simulations/{counter}/cycle")
    with client.websocket_connect(ws_url(counter)) as ws:
        assert recv(ws) == {"type": "status", "state": "stopped", "at": None, "stack": []}
        first = subscribe(ws, ["Main.Count", "main.flag", "MAIN.Idle"])
        history = first.pop("history")  # the scan history (test_history.py): scan 1 is kept, none viewed
        assert (history["first"], history["last"], history["viewing"]) == (1, 1, None)
        assert first == {
            "type": "values",
            "scan": 1,
            "time_ms": 10.0,
            "forced": [],
            "injected": {},
            "power": {},
            "changed": {"MAIN.COUNT": 1, "MAIN.FLAG": True, "MAIN.IDLE": 7},
            "types": {"MAIN.COUNT": INT, "MAIN.FLAG": {"name": "BOOL", "names": None}, "MAIN.IDLE": INT},
        }
        assert entry(counter_registry(client), counter).clients == 1


INT = {"name": "INT", "names": None}


def test_the_snapshot_names_each_type_so_times_dates_and_enumerations_show_as_iec_text(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """TIME/DATE values travel as ms and enumerations as ints; the first message says how to show them."""
    types = "TYPE\n    Mode : (IDLE, RUN := 5, FAULT);\n    Pct : INT (0..100);\nEND_TYPE"
    program = st_program(
        "Main",
        "VAR\n    t : TIME := T#1m2s;\n    d : DATE := D#2024-05-01;\n    m : Mode := RUN;\n"
        "    p : Pct := 50;\n    a : ARRAY[1..2] OF INT;\n    tm : TON;\nEND_VAR",
        "",
    )
    workspace.create(Project(name="typed", types=types, pous=[program]))
    sim_id = client.post("/api/projects/typed/simulations").json()["id"]
    with client.websocket_connect(ws_url(sim_id)) as ws:
        recv(ws)
        first = subscribe(ws, ["Main.t", "Main.d", "Main.m", "Main.p", "Main.a", "Main.tm"])
        assert first["changed"] == {
            "MAIN.T": 62000,
            "MAIN.D": 1714521600000,
            "MAIN.M": 5,
            "MAIN.P": 50,
            "MAIN.A": [0, 0],
            "MAIN.TM": {"IN": False, "PT": 0, "Q": False, "ET": 0},
        }
        assert first["types"] == {
            "MAIN.T": {"name": "TIME", "names": None},
            "MAIN.D": {"name": "DATE", "names": None},
            "MAIN.M": {"name": "MODE", "names": {"0": "IDLE", "5": "RUN", "6": "FAULT"}},
            "MAIN.P": INT,
            "MAIN.A": {"name": "ARRAY", "names": None},
            "MAIN.TM": {"name": "TON", "names": None},
        }
        ws.send_json({"type": "single_cycle"})
        later, _ = recv_until(ws, of_type("values", scan=1))
        assert later["types"] == {}  # only the snapshot after a subscribe carries them


def counter_registry(client: TestClient) -> SimulationRegistry:
    return client.app.state.simulations  # type: ignore[attr-defined]


def test_values_carry_only_what_changed_since_the_last_message_to_this_client(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Count", "Main.Flag", "Main.Idle"])
        ws.send_json({"type": "single_cycle"})
        one, _ = recv_until(ws, of_type("values", scan=1))
        assert one["changed"] == {"MAIN.COUNT": 1, "MAIN.FLAG": True}  # Idle did not change: not sent
        ws.send_json({"type": "single_cycle"})
        two, _ = recv_until(ws, of_type("values", scan=2))
        assert two["changed"] == {"MAIN.COUNT": 2, "MAIN.FLAG": False}
        ws.send_json({"type": "write", "path": "Main.Flag", "value": True})  # NOT TRUE: FALSE again
        ws.send_json({"type": "single_cycle"})
        three, _ = recv_until(ws, of_type("values", scan=3))
        assert three["changed"] == {"MAIN.COUNT": 3}  # Flag ended FALSE as before: not sent
        ws.send_json({"type": "subscribe", "paths": ["Main.Idle"], "interval_ms": 20})
        again, _ = recv_until(ws, of_type("values"))
        assert again["changed"] == {"MAIN.IDLE": 7}  # a new subscription starts with a full snapshot


def test_running_sends_at_the_interval_with_increasing_scans(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Count"], interval_ms=50)
        ws.send_json({"type": "run"})
        recv_until(ws, of_type("status", state="running"))
        start = time.monotonic()
        messages = [recv_until(ws, of_type("values"))[0] for _ in range(6)]
        elapsed = time.monotonic() - start
        scans = [m["scan"] for m in messages]
        assert scans == sorted(set(scans))
        assert all(m["changed"]["MAIN.COUNT"] == m["scan"] for m in messages)  # Count counts scans
        assert 0.2 <= elapsed <= 1.0, elapsed  # 6 messages at 50 ms: never faster, a little slower when busy
        assert all(3 <= b - a <= 15 for a, b in itertools.pairwise(scans)), scans  # ~5 scans of 10 ms apart


def test_write_is_applied_once_before_the_next_scan(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Count", "Main.Idle"])
        ws.send_json({"type": "write", "path": "Main.Count", "value": 100})
        ws.send_json({"type": "write", "path": "Main.Idle", "value": "16#FF"})
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=1))
        assert message["changed"] == {"MAIN.COUNT": 101, "MAIN.IDLE": 255}


@pytest.mark.parametrize(
    ("message", "code", "text"),
    [
        ({"type": "write", "path": "Main.Count", "value": "abc"}, "bad_value", "MAIN.COUNT: 'abc' is not an INT"),
        (
            {"type": "write", "path": "Main.Count", "value": 40000},
            "bad_value",
            "MAIN.COUNT: 40000 is out of range for INT (-32768..32767)",
        ),
        (
            {"type": "force", "path": "Main.Flag", "value": 2},
            "bad_value",
            "MAIN.FLAG: 2 is not a BOOL (TRUE, FALSE, 1 or 0)",
        ),
        (
            {"type": "write", "path": "Main.Cuont", "value": 1},
            "bad_path",
            "MAIN has no variable 'Cuont' - did you mean 'COUNT'?",
        ),
        ({"type": "unforce", "path": "Main.Count"}, "bad_path", "MAIN.COUNT is not forced"),
        ({"type": "subscribe", "paths": ["Nope"]}, "bad_path", "unknown variable or program 'Nope'"),
        ({"type": "continue"}, "bad_state", "the simulation is not halted"),
        (
            {"type": "breakpoint_set", "pou": "Main", "line": 9},
            "bad_path",
            "Main has no statement at line 9 (possible: 1, 2, 3)",
        ),
        (
            {"type": "trace_start", "paths": ["Main.Count"], "samples": 3, "trigger": {"path": "Main.Count"}},
            "bad_path",
            "the trigger MAIN.COUNT is not a BOOL: a rising edge needs a BOOL (use cross_up or cross_down with a level "
            "for numbers)",
        ),
    ],
)
def test_bad_requests_get_an_error_naming_the_problem_and_change_nothing(
    client: TestClient, counter: str, registry: SimulationRegistry, message: dict, code: str, text: str
) -> None:
    sim = entry(registry, counter).handle
    before = sim.inspect()["snapshot"]
    with client.websocket_connect(ws_url(counter)) as ws:
        recv(ws)
        ws.send_json(message)
        error, _ = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == (code, text)
        ws.send_json({"type": "single_cycle"})  # the connection still works
        wait_for(lambda: sim.info["scan_count"] == 1)
    assert sim.inspect()["snapshot"] == {**before, "MAIN.COUNT": 1, "MAIN.FLAG": True, "MAIN.RESULT": 100}


def test_force_holds_a_value_the_program_writes_until_released(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Flag"])
        ws.send_json({"type": "force", "path": "main.flag", "value": "TRUE"})
        log, _ = recv_until(ws, log_of("force"))
        assert (log["level"], log["message"]) == ("info", "forced MAIN.FLAG := TRUE")
        for scan in (1, 2, 3):
            ws.send_json({"type": "single_cycle"})
            values, _ = recv_until(ws, of_type("values", scan=scan))
            assert values["forced"] == ["MAIN.FLAG"]
        assert entry(counter_registry(client), counter).handle.read("Main.Flag") is True
        ws.send_json({"type": "unforce", "path": "Main.Flag"})
        log, _ = recv_until(ws, log_of("release"))
        assert log["message"] == "released the force on MAIN.FLAG"
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=4))
        assert (values["forced"], values["changed"]) == ([], {"MAIN.FLAG": False})
        ws.send_json({"type": "force", "path": "Main.Count", "value": 5})
        ws.send_json({"type": "force", "path": "Main.Idle", "value": 6})
        ws.send_json({"type": "unforce_all"})
        log, _ = recv_until(ws, of_type("log", message="released all forces (2)"))


def test_a_line_breakpoint_halts_the_running_scan_there(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Count", "Main.Flag"])
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "line": 2})
        ws.send_json({"type": "run"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"] == {
            "pou": "MAIN",
            "instance": "MAIN",
            "network": None,
            "element": None,
            "line": 2,
            "column": 1,
            "body": None,  # not in an SFC action or transition
        }
        sim = entry(registry, counter).handle
        state = sim.inspect(paths=["Main.Count"])
        scan, count = state["scan_count"], state["values"]["Main.Count"]
        time.sleep(0.05)
        assert sim.inspect()["scan_count"] == scan  # the scan thread waits at the breakpoint
        # statement 1 of the halted scan has run: Count is one ahead of the last complete scan
        values, _ = recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.COUNT") == count)
        assert count == scan + 1
        # writes act at once while halted
        ws.send_json({"type": "write", "path": "Main.Count", "value": 1000})
        recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.COUNT") == 1000)
        ws.send_json({"type": "step", "granularity": "statement"})
        status, _ = recv_until(ws, of_type("status"))
        assert (status["state"], status["at"]["line"]) == ("halted", 3)
        ws.send_json({"type": "breakpoint_clear"})
        ws.send_json({"type": "continue"})
        recv_until(ws, of_type("status", state="running"))
        recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.COUNT", 0) > 1001)


def test_step_from_a_stopped_simulation_and_single_cycle_finish_the_scan(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        recv(ws)
        ws.send_json({"type": "step", "granularity": "statement"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["line"] == 1
        ws.send_json({"type": "single_cycle"})  # the rest of this scan
        recv_until(ws, of_type("status", state="stopped"))
        sim = entry(registry, counter).handle
        assert (sim.inspect()["scan_count"], sim.read("Main.Count")) == (1, 1)
        ws.send_json({"type": "step", "granularity": "cycle"})  # no breakpoint: one whole scan
        wait_for(lambda: sim.info["scan_count"] == 2)
        assert sim.inspect()["halted"] is None


def test_element_breakpoints_and_power_flow_in_ladder(client: TestClient, motor_sim: str) -> None:
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        first = subscribe(
            ws,
            ["Start", "Motor"],
            elements=[{"pou_instance": "Main", "ids": ["start", "seal", "stop", "motor", "ton"]}],
        )
        # nothing ran yet: every element reports "not executed"
        assert first["power"] == {
            "Main/start": None,
            "Main/seal": None,
            "Main/stop": None,
            "Main/motor": None,
            "Main/ton": None,
        }
        ws.send_json({"type": "write", "path": "Start", "value": True})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=1))
        assert values["changed"] == {"START": True, "MOTOR": True}
        assert values["power"] == {
            "Main/start": True,
            "Main/seal": False,
            "Main/stop": True,
            "Main/motor": True,
            "Main/ton": False,
        }
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "element": "motor"})
        ws.send_json({"type": "single_cycle"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["pou"] == "MAIN" and status["at"]["element"] == "motor"
        assert status["at"]["network"] == "seal_in"
        ws.send_json({"type": "breakpoint_clear", "pou": "Main", "element": "motor"})
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "network": "count_starts"})
        ws.send_json({"type": "continue"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert (status["at"]["network"], status["at"]["element"]) == ("count_starts", None)
        ws.send_json({"type": "step", "granularity": "network"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["network"] == "lamp"
        ws.send_json({"type": "breakpoint_clear"})
        ws.send_json({"type": "step", "granularity": "over"})  # the last network of Main: the task's next program
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert (status["at"]["pou"], status["at"]["network"]) == ("SCALING", "speed")
        ws.send_json({"type": "step", "granularity": "over"})  # the last network of the last program: the scan ends
        recv_until(ws, of_type("status", state="stopped"))


def test_every_element_of_an_instance_when_no_ids_are_given(client: TestClient, motor_sim: str) -> None:
    client.post(f"/api/simulations/{motor_sim}/cycle")
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        first = subscribe(ws, [], elements=[{"pou_instance": "MAIN"}])
        assert {"MAIN/start", "MAIN/ton.ET", "MAIN/ctu.CV", "MAIN/lamp_coil"} <= set(first["power"])
        assert first["power"]["MAIN/ton.ET"] == 0


def test_two_clients_have_their_own_subscriptions(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as a, client.websocket_connect(ws_url(counter)) as b:
        assert subscribe(a, ["Main.Count"])["changed"] == {"MAIN.COUNT": 0}
        assert subscribe(b, ["Main.Flag", "Main.Idle"], interval_ms=40)["changed"] == {
            "MAIN.FLAG": False,
            "MAIN.IDLE": 7,
        }
        a.send_json({"type": "single_cycle"})
        va, _ = recv_until(a, of_type("values", scan=1))
        vb, _ = recv_until(b, of_type("values", scan=1))
        assert (va["changed"], vb["changed"]) == ({"MAIN.COUNT": 1}, {"MAIN.FLAG": True})
        a.send_json({"type": "write", "path": "Main.Count", "value": "x"})
        recv_until(a, of_type("error"))
        b.send_json({"type": "single_cycle"})
        vb, seen = recv_until(b, of_type("values", scan=2))
        assert all(m["type"] != "error" for m in seen)  # errors go to the client that asked


def test_forces_and_state_changes_reach_every_client(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as a, client.websocket_connect(ws_url(counter)) as b:
        recv(a), recv(b)
        a.send_json({"type": "force", "path": "Main.Idle", "value": 3})
        assert recv_until(b, of_type("log"))[0]["message"] == "forced MAIN.IDLE := 3"
        a.send_json({"type": "run"})
        recv_until(b, of_type("status", state="running"))
        b.send_json({"type": "stop"})
        recv_until(a, of_type("status", state="stopped"))


def test_a_runtime_error_is_logged_with_its_location_and_the_server_keeps_serving(
    client: TestClient, counter: str
) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        subscribe(ws, ["Main.Count"])
        ws.send_json({"type": "run"})
        recv_until(ws, of_type("status", state="running"))
        ws.send_json({"type": "write", "path": "Main.Divisor", "value": 0})
        log, _ = recv_until(ws, log_of("fault"))
        assert log["level"] == "error"
        assert log["message"].startswith("division by zero: 100 / 0 at POU MAIN, line 3 column 1 (instance MAIN)")
        assert log["at"] == {
            "pou": "MAIN",
            "instance": "MAIN",
            "network": None,
            "element": None,
            "line": 3,
            "column": 1,
            "body": None,  # not in an SFC action or transition
        }
        recv_until(ws, of_type("status", state="faulted"))
        assert client.get("/api/health").status_code == 200
        ws.send_json({"type": "run"})
        error, _ = recv_until(ws, of_type("error"))
        assert error["code"] == "bad_state"
        assert client.post(f"/api/simulations/{counter}/reset").json()["state"] == "stopped"
        recv_until(ws, of_type("status", state="stopped"))


def test_a_watchdog_trip_is_logged(client: TestClient, workspace: Workspace) -> None:
    from ladderlab.model import Project, Task

    from .helpers import st_program

    registry = install(client, SimulationSettings(watchdog_s=0.05))
    try:
        body = "IF Go THEN\n    WHILE TRUE DO\n        n := n + 1;\n    END_WHILE;\nEND_IF;"
        program = st_program("Main", "VAR\n    Go : BOOL;\n    n : DINT;\nEND_VAR", body)
        workspace.create(Project(name="loop", pous=[program], tasks=[Task(name="T", programs=["Main"])]))
        sim_id = client.post("/api/projects/loop/simulations").json()["id"]
        with client.websocket_connect(ws_url(sim_id)) as ws:
            recv(ws)
            ws.send_json({"type": "run"})
            recv_until(ws, of_type("status", state="running"))
            ws.send_json({"type": "write", "path": "Main.Go", "value": True})
            log, _ = recv_until(ws, log_of("watchdog"))
            assert log["level"] == "error" and "watchdog" in log["message"]
            assert log["at"]["pou"] == "MAIN" and log["at"]["line"] in (2, 3)
            recv_until(ws, of_type("status", state="faulted"))
        assert client.get(f"/api/simulations/{sim_id}").json()["fault"]["code"] == "ENGINE-RUNTIME"
    finally:
        registry.close()


def test_a_foreign_origin_is_refused_and_the_served_or_listed_ones_accepted(
    client: TestClient, counter: str, workspace: Workspace
) -> None:
    """Issue 18: the Origin is checked against the allow-list, not against Host (which the page chooses)."""
    for origin, host in [
        ("http://evil.example", "localhost"),
        ("http://evil.example:8000", "evil.example:8000"),  # DNS rebinding: Host and Origin agree, both foreign
        ("http://localhost:3000", "localhost:8000"),  # another local site
        ("null", "localhost"),
    ]:
        with pytest.raises(WebSocketDisconnect) as refused:
            with client.websocket_connect(ws_url(counter), headers={"Origin": origin, "Host": host}):
                pass
        assert refused.value.code == 1008, origin
    for origin, host in [("http://localhost:8000", "localhost:8000"), ("http://127.0.0.1", "127.0.0.1")]:
        with client.websocket_connect(ws_url(counter), headers={"Origin": origin, "Host": host}) as ws:
            assert recv(ws)["type"] == "status"
    dev = api_client(create_app(workspace, security=Security(origins=frozenset({"http://localhost:5173"}))))
    with dev.websocket_connect(ws_url(counter), headers={"Origin": "http://localhost:5173"}) as ws:
        assert recv(ws)["code"] == "bad_path"  # accepted (the Vite dev server); this app has no such simulation


def test_an_unknown_simulation_gets_an_error_and_a_close(client: TestClient, registry: SimulationRegistry) -> None:
    with client.websocket_connect(ws_url("nope")) as ws:
        error = recv(ws)
        assert (error["code"], error["message"][:24]) == ("bad_path", "no simulation 'nope' (it")
        with pytest.raises(WebSocketDisconnect) as closed:
            ws.receive_text()
        assert closed.value.code == 4404


def test_deleting_the_simulation_tells_and_closes_its_clients(client: TestClient, counter: str) -> None:
    with client.websocket_connect(ws_url(counter)) as ws:
        recv(ws)
        assert client.delete(f"/api/simulations/{counter}").status_code == 204
        log, _ = recv_until(ws, of_type("log"))
        assert log["message"] == "the simulation was deleted"
        with pytest.raises(WebSocketDisconnect) as closed:
            while True:
                ws.receive_text()
        assert closed.value.code == 4410


def test_clients_per_simulation_and_paths_per_subscription_are_bounded(
    client: TestClient, workspace: Workspace
) -> None:
    registry = install(client, SimulationSettings(max_clients=1, max_paths=2))
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        with client.websocket_connect(ws_url(sim_id)) as first:
            recv(first)
            first.send_json({"type": "subscribe", "paths": ["Main.Count", "Main.Flag", "Main.Idle"]})
            error, _ = recv_until(first, of_type("error"))
            assert error == {
                "type": "error",
                "code": "too_many",
                "message": "a subscription may hold 2 paths and 32 POU instances, not 3 and 0",
            }
            with client.websocket_connect(ws_url(sim_id)) as second:
                assert recv(second)["code"] == "too_many"
                with pytest.raises(WebSocketDisconnect) as closed:
                    second.receive_text()
                assert closed.value.code == 1013
            assert client.get(f"/api/simulations/{sim_id}").json()["clients"] == 1
        wait_for(lambda: client.get(f"/api/simulations/{sim_id}").json()["clients"] == 0)
    finally:
        registry.close()


def test_composite_and_nested_paths_are_read_through_their_containers(client: TestClient, motor_sim: str) -> None:
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        ws.send_json({"type": "write", "path": "Start", "value": True})
        ws.send_json({"type": "single_cycle"})
        first = subscribe(ws, ["Main.RunTimer", "Main.RunTimer.ET", "Main.Blink.Half.PT", "Motor", "GVL.StartCount"])
        assert first["changed"] == {
            "MAIN.RUNTIMER": {"IN": True, "PT": 5000, "Q": False, "ET": 0},
            "MAIN.RUNTIMER.ET": 0,
            "MAIN.BLINK.HALF.PT": 0,
            "MOTOR": True,
            "STARTCOUNT": 1,
        }
        ws.send_json({"type": "single_cycle"})
        second, _ = recv_until(ws, of_type("values", scan=2))
        assert second["changed"] == {
            "MAIN.RUNTIMER": {"IN": True, "PT": 5000, "Q": False, "ET": 10},
            "MAIN.RUNTIMER.ET": 10,
        }


@pytest.mark.parametrize(
    ("elements", "text"),
    [
        (
            [{"pou_instance": "Main", "ids": ["start", "strat"]}],
            "Main (MAIN) has no element 'strat' (elements: blink, blink.OUT, ctu, ctu.CV, ctu.Q, lamp_coil, motor, "
            "motor_on, reset_count, running, running_on, seal, start, start_edge, start_or_motor, stop, ton, ton.ET, "
            "ton.Q)",
        ),
        (
            [{"pou_instance": "Main.Blink", "ids": ["x"]}],
            "Main.Blink (BLINKER) has no element 'x' (elements: none: it is not a ladder or FBD POU)",
        ),
        ([{"pou_instance": "Main.Lamp"}], "no POU instance 'Main.Lamp' - did you mean 'MAIN.BLINK'?"),
        ([{"pou_instance": "Mian"}], "no POU instance 'Mian' - did you mean 'MAIN'?"),
    ],
)
def test_element_subscriptions_name_existing_instances_and_elements(
    client: TestClient, motor_sim: str, elements: list, text: str
) -> None:
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        ws.send_json({"type": "subscribe", "paths": [], "elements": elements})
        error, _ = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == ("bad_path", text)


def test_an_unknown_name_in_a_subscription_is_refused_alone_and_the_rest_is_watched(
    client: TestClient, motor_sim: str
) -> None:
    """ON-10: one pin the diagram draws and the program does not have (or a misspelt watch row) costs that item
    only, with its reason; every other value and element of the client's views keeps updating."""
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        ws.send_json(
            {
                "type": "subscribe",
                "paths": ["Start", "Strat", "Motor"],
                "elements": [{"pou_instance": "Main", "ids": ["start", "strat", "motor"]}, {"pou_instance": "Mian"}],
            }
        )
        reasons = []
        for _ in range(3):
            error, _ = recv_until(ws, of_type("error"))
            reasons.append((error["code"], error["message"].split(" (elements")[0]))
        assert reasons == [
            ("bad_path", "unknown variable or program 'Strat'"),
            ("bad_path", "Main (MAIN) has no element 'strat'"),
            ("bad_path", "no POU instance 'Mian' - did you mean 'MAIN'?"),
        ]
        first, _ = recv_until(ws, of_type("values"))
        assert first["power"] == {"Main/start": None, "Main/motor": None}
        ws.send_json({"type": "write", "path": "Start", "value": True})
        ws.send_json({"type": "single_cycle"})
        values, _ = recv_until(ws, of_type("values", scan=1))
        assert values["changed"] == {"START": True, "MOTOR": True}
        assert values["power"]["Main/start"] is True and values["power"]["Main/motor"] is True


def test_fbd_elements_and_fb_instances_can_be_watched(client: TestClient, motor_sim: str) -> None:
    client.post(f"/api/simulations/{motor_sim}/cycle")
    with client.websocket_connect(ws_url(motor_sim)) as ws:
        recv(ws)
        first = subscribe(
            ws,
            [],
            elements=[
                {"pou_instance": "Scaling", "ids": ["add.OUT", "gt.OUT", "high"]},
                {"pou_instance": "Main.Blink"},
            ],
        )
        assert first["power"] == {"Scaling/add.OUT": 5, "Scaling/gt.OUT": False, "Scaling/high": False}


def test_an_oversized_message_gets_an_error(client: TestClient, workspace: Workspace) -> None:
    registry = install(client, SimulationSettings(max_message_bytes=200))
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        with client.websocket_connect(ws_url(sim_id)) as ws:
            recv(ws)
            ws.send_text(json.dumps({"type": "subscribe", "paths": ["Main.Count"] * 20}))  # 32 + 20 * 14 characters
            error, _ = recv_until(ws, of_type("error"))
            assert error == {
                "type": "error",
                "code": "too_large",
                "message": "the message has 312 characters, more than the limit of 200",
            }
            assert subscribe(ws, ["Main.Count"])["changed"] == {"MAIN.COUNT": 0}
    finally:
        registry.close()


def test_rest_start_continues_a_halted_scan(client: TestClient, counter: str, registry: SimulationRegistry) -> None:
    sim = entry(registry, counter).handle
    sim.call("breakpoint_set", pou="Main", line=3)
    assert client.post(f"/api/simulations/{counter}/cycle").json()["state"] == "halted"
    sim.call("breakpoint_clear")
    assert client.post(f"/api/simulations/{counter}/start").json()["state"] == "running"
    wait_for(lambda: sim.info["scan_count"] >= 3)
    assert sim.read("Main.Result") == 100


class _RecordingSocket:
    def __init__(self) -> None:
        self.sent: list[dict] = []

    async def send_text(self, text: str) -> None:
        self.sent.append(json.loads(text))


def test_a_client_that_falls_behind_loses_old_log_entries_and_is_told(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    from ladderlab.model import monitor as m
    from ladderlab.server.monitor import MonitorClient

    settings = SimulationSettings(max_queued=5)

    async def scenario() -> list[dict]:
        socket = _RecordingSocket()
        monitor = MonitorClient(socket, entry(registry, counter), settings)  # type: ignore[arg-type]
        monitor._enqueue(m.Error(type="error", code="bad_path", message="not a log"))
        for n in range(8):
            monitor._enqueue(m.Log(type="log", level="info", message=f"entry {n}"))
            monitor._enqueue(m.Status(type="status", state="running" if n % 2 else "stopped"))
        await monitor._drain()
        return socket.sent

    sent = asyncio.run(scenario())
    assert [(s["type"], s.get("message") or s.get("state")) for s in sent] == [
        ("log", "4 messages were dropped: this connection did not keep up"),
        ("error", "not a log"),
        ("log", "entry 4"),
        ("log", "entry 5"),
        ("log", "entry 6"),
        ("log", "entry 7"),
        ("status", "running"),  # only the latest state
    ]


def test_a_halt_publishes_the_values_of_the_halt_point_at_once(client: TestClient, workspace: Workspace) -> None:
    """Issue 9 (debugging: values are those at the halt point). Periodic frames are off (publish_s
    of a minute), so the halted scan's values can only come from the publication at the halt."""
    registry = install(client, SimulationSettings(idle_timeout_s=60.0, reap_every_s=0.05, publish_s=60.0))
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        with client.websocket_connect(ws_url(sim_id)) as ws:
            assert subscribe(ws, ["Main.Count", "Main.Flag"])["changed"] == {"MAIN.COUNT": 0, "MAIN.FLAG": False}
            ws.send_json({"type": "breakpoint_set", "pou": "Main", "line": 3})
            ws.send_json({"type": "run"})
            status, _ = recv_until(ws, of_type("status", state="halted"))
            assert status["at"]["line"] == 3
            sim = entry(registry, sim_id).handle
            scan = sim.inspect()["scan_count"]
            # lines 1 and 2 of the halted scan have run: Count and Flag already hold its values
            values, _ = recv_until(ws, lambda m: m["type"] == "values" and "MAIN.FLAG" in m["changed"])
            assert values["changed"] == {"MAIN.COUNT": scan + 1, "MAIN.FLAG": (scan + 1) % 2 == 1}
            # Stop while halted: the scan stays halted (and says so); Continue ends it and no scan follows
            ws.send_json({"type": "stop"})
            log, _ = recv_until(ws, log_of("state"))
            assert log["message"] == (
                "stopped: the scan stays halted; Continue or a step finishes it, then no further scan runs"
            )
            ws.send_json({"type": "continue"})
            recv_until(ws, of_type("status", state="stopped"))
            time.sleep(0.05)
            assert sim.inspect()["scan_count"] == scan + 1
    finally:
        registry.close()
