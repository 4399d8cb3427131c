"""Server simulations run the monitor variant and switch to the debug variant only while debugging (issue 5).

A breakpoint (or a step) switches to the debug code between scans; clearing the last breakpoint switches
back. Every variable, FB instance (timers, counters, edge memories) and probe survives both switches: the
run must match a simulation that never switched, scan by scan.
"""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.build import build_project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.simulation.remote import SimulationHandle
from ladderlab.storage import Workspace

from .test_simulations_support import entry, motor_sim, of_type, recv, recv_until, registry, subscribe, wait_for

__all__ = ["motor_sim", "registry"]  # fixtures used below


def _state(sim) -> tuple:
    """Scans, time, every variable and the LD POU's probes: of the reference simulation here, or of the
    server's (through ``inspect``)."""
    if isinstance(sim, SimulationHandle):
        state = sim.inspect(probes=["Main"])
        return state["scan_count"], state["time_ms"], state["snapshot"], state["probes"]["Main"]
    view = sim.probes("Main")
    return sim.scan_count, sim.time_ms, sim.snapshot(), {"values": view.values, "executed": sorted(view.executed)}


def _variant(sim: SimulationHandle) -> str:
    return sim.inspect()["variant"]


def test_a_breakpoint_switches_to_debug_code_and_clearing_it_back_without_losing_state(
    client: TestClient, motor_sim: str, registry: SimulationRegistry, workspace: Workspace
) -> None:
    runner = entry(registry, motor_sim).handle
    reference = build_project(workspace.load("motor").project, "monitor").simulation()
    reference.write("Start", True)
    with client.websocket_connect(f"/api/simulations/{motor_sim}/ws") as ws:
        recv(ws)
        subscribe(ws, ["Start"], elements=[{"pou_instance": "Main"}])
        ws.send_json({"type": "write", "path": "Start", "value": True})
        for scan in (1, 2, 3):
            ws.send_json({"type": "single_cycle"})
            recv_until(ws, of_type("values", scan=scan))
        reference.cycle(3)
        assert _variant(runner) == "monitor"
        assert _state(runner) == _state(reference)

        ws.send_json({"type": "breakpoint_set", "pou": "Main", "element": "motor"})
        wait_for(lambda: _variant(runner) == "debug")
        assert _state(runner) == _state(reference)  # the switch itself changes nothing
        ws.send_json({"type": "single_cycle"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert status["at"]["element"] == "motor"
        ws.send_json({"type": "continue"})
        recv_until(ws, of_type("status", state="stopped"))
        reference.cycle(1)
        ws.send_json({"type": "breakpoint_clear"})
        wait_for(lambda: _variant(runner) == "monitor")
        assert _state(runner) == _state(reference)

        ws.send_json({"type": "step", "granularity": "network"})  # a step debugs until its scan ends
        status, _ = recv_until(ws, of_type("status", state="halted"))
        assert _variant(runner) == "debug"
        ws.send_json({"type": "step", "granularity": "cycle"})
        recv_until(ws, of_type("status", state="stopped"))
        wait_for(lambda: _variant(runner) == "monitor")
        ws.send_json({"type": "write", "path": "Start", "value": False})
        for _ in range(2):
            ws.send_json({"type": "single_cycle"})
        reference.cycle(1)
        reference.write("Start", False)
        reference.cycle(2)
        wait_for(lambda: runner.info["scan_count"] == reference.scan_count)
        assert _state(runner) == _state(reference)
