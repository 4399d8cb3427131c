"""Stepping to the next SFC transition over the websocket (issue 24 item 4, SFC-09): from a stopped simulation the
scans run until a transition fires, halt there and stay stopped after it; from a halt of a running simulation the
halt is reached the same way and Continue runs on, as after any other step."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace
from tests.sfc.support import jump, project, sfc_pou, step, tr

from .test_simulations_support import entry, of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixture used below


def chart_simulation(client: TestClient, workspace: Workspace) -> tuple[str, dict[str, str]]:
    """S0 (N Count: n := n + 1) -go-> S1 -back-> S0; returns the simulation id and the element ids."""
    s0, t1, s1, t2 = step("S0", "N Count"), tr("go"), step("S1"), tr("back")
    pou = sfc_pou(
        "Main", "VAR go, back : BOOL; n : INT; END_VAR", [s0, t1, s1, t2, jump("S0")], {"Count": "n := n + 1;"}
    )
    workspace.create(project(pou))
    response = client.post("/api/projects/sfc_test/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"], {"S1": s1["id"], "T1": t1["id"], "T2": t2["id"]}


def test_step_to_the_next_transition_from_stopped_and_from_a_running_halt(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim_id, ids = chart_simulation(client, workspace)
    handle = entry(registry, sim_id).handle
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        assert recv(ws)["state"] == "stopped"
        subscribe(ws, ["Main.n", "Main.S1.X"])

        # Stopped, nothing fires yet: scans run on; go := TRUE lets t1 fire, where the scan halts.
        ws.send_json({"type": "step", "granularity": "transition"})
        recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.N", 0) >= 3)
        ws.send_json({"type": "write", "path": "Main.go", "value": True})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert (status["at"]["pou"], status["at"]["element"]) == ("MAIN", ids["T1"])
        assert handle.read("Main.S1.X") is False  # it fires at the end of the scan: S1 is not active yet
        ws.send_json({"type": "continue"})
        recv_until(ws, of_type("status", state="stopped"))  # it was stopped: it stays so
        assert handle.read("Main.S1.X") is True
        scans = handle.inspect()["scan_count"]

        # Running with a breakpoint on S1 (active now): halted there; then stepping to the transition back.
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "element": ids["S1"]})
        ws.send_json({"type": "run"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["element"] == ids["S1"] and handle.inspect()["scan_count"] == scans
        ws.send_json({"type": "breakpoint_clear"})
        ws.send_json({"type": "step", "granularity": "transition"})  # back is FALSE: scans run on
        recv_until(ws, of_type("status", state="running"))
        ws.send_json({"type": "write", "path": "Main.back", "value": True})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["element"] == ids["T2"] and handle.inspect()["scan_count"] > scans
        ws.send_json({"type": "continue"})
        recv_until(ws, of_type("status", state="running"))  # it was running: it runs on
        n = handle.read("Main.n")
        recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.N", 0) > n + 2)  # S0 counts again


def test_while_halted_before_the_transitions_a_condition_shows_its_last_computed_value(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """Issue 24 item 3: a breakpoint on S1 halts scan 1 before its transitions are evaluated; the frame of the halt
    gives t1's condition as computed in scan 0 (go TRUE: TRUE, t1 fired), not None (the chart showed "?")."""
    sim_id, ids = chart_simulation(client, workspace)
    condition = f"Main/{ids['T1']}.COND"
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        assert recv(ws)["state"] == "stopped"
        subscribe(ws, [], elements=[{"pou_instance": "Main", "ids": [f"{ids['T1']}.COND"]}])
        ws.send_json({"type": "write", "path": "Main.go", "value": True})
        ws.send_json({"type": "single_cycle"})  # scan 0: t1 = go = TRUE fires, S1 active
        recv_until(ws, lambda m: m["type"] == "values" and m["power"].get(condition) is True)
        ws.send_json({"type": "write", "path": "Main.go", "value": False})
        ws.send_json({"type": "breakpoint_set", "pou": "Main", "element": ids["S1"]})
        ws.send_json({"type": "single_cycle"})  # scan 1 halts at S1, before its conditions
        _, seen = recv_until(ws, of_type("status", state="halted"))
        frame, more = recv_until(ws, of_type("values"))
        frames = [m for m in [*seen, *more, frame] if m["type"] == "values"]
        # the frames are changes: t1's condition is not sent again as None (unknown), it stays scan 0's TRUE
        assert [m["power"].get(condition, "unchanged") for m in frames] == ["unchanged"] * len(frames)
