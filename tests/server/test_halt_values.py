"""A halt publishes its values at once (issue 9: "values are those at the halt point").

With a long publish interval the scan thread publishes only on commands and state changes; a
breakpoint halt must be one of them, since the thread then idles and would otherwise leave clients
with the values of the last frame before the halt.
"""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationSettings
from ladderlab.storage import Workspace

from .test_simulations_support import counter_project, entry, install, of_type, recv_until, subscribe, wait_for

SLOW_PUBLISH = SimulationSettings(idle_timeout_s=60.0, reap_every_s=0.05, publish_s=30.0)


def test_the_values_at_a_breakpoint_reach_the_client(client: TestClient, workspace: Workspace) -> None:
    registry = install(client, SLOW_PUBLISH)
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
            subscribe(ws, ["Main.Count"])
            # Several scans run unpublished first, so the halt's values differ from the last frame.
            ws.send_json({"type": "run"})
            sim = entry(registry, sim_id).handle
            recv_until(ws, of_type("status", state="running"))
            wait_for(lambda: sim.inspect()["scan_count"] >= 3)  # (no periodic frames: ask)
            ws.send_json({"type": "breakpoint_set", "pou": "Main", "line": 2})
            recv_until(ws, of_type("status", state="halted"))
            state = sim.inspect(paths=["Main.Count"])
            halted_count = state["values"]["Main.Count"]
            assert halted_count == state["scan_count"] + 1  # line 1 of the halted scan has run
            recv_until(ws, lambda m: m["type"] == "values" and m["changed"].get("MAIN.COUNT") == halted_count)
    finally:
        registry.close()
