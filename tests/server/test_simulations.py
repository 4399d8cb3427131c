"""REST routes of live simulations (issue 6, "Simulations"): every endpoint and its error paths."""

from __future__ import annotations

import time

from fastapi.testclient import TestClient

from ladderlab.model import Pou, Project
from ladderlab.simulation.registry import SimulationRegistry, SimulationSettings
from ladderlab.storage import Workspace

from .helpers import detail, st_program
from .test_simulations_support import counter, counter_project, entry, install, registry, wait_for

__all__ = ["counter", "registry"]  # fixtures used below


def test_create_compiles_the_saved_project_into_a_stopped_simulation(client: TestClient, counter: str) -> None:
    info = client.get(f"/api/simulations/{counter}").json()
    assert info["project"] == "counter"
    assert info["revision"] == client.get("/api/projects/counter").json()["revision"]
    assert (info["state"], info["scan_count"], info["time_ms"], info["real_time_ms"]) == ("stopped", 0, 0.0, 0.0)
    assert info["scan_ms"] == {"min": 0.0, "avg": 0.0, "max": 0.0, "last": 0.0}
    assert (info["fault"], info["clients"], info["overruns"]) == (None, 0, 0)
    assert info["instances"] == {"MAIN": ["MAIN"]}
    assert [s["id"] for s in client.get("/api/simulations").json()] == [counter]


def test_the_info_lists_the_instances_of_every_function_block_for_the_online_views(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """The instance picker of an FB's online view offers these (nested and arrays of instances included)."""
    fb = Pou(name="Pulse", kind="function_block", language="st", declarations="VAR_INPUT x : BOOL; END_VAR", body="")
    outer = Pou(name="Pair", kind="function_block", language="st", declarations="VAR a, b : Pulse; END_VAR", body="")
    main = st_program(
        "Main", "VAR\n    p : Pulse;\n    q : ARRAY[1..2] OF Pulse;\n    two : Pair;\nEND_VAR", "p(x := TRUE);"
    )
    workspace.create(Project(name="fbs", pous=[fb, outer, main]))
    info = client.post("/api/projects/fbs/simulations").json()
    assert info["instances"] == {
        "MAIN": ["MAIN"],
        "PAIR": ["MAIN.TWO"],
        "PULSE": ["MAIN.P", "MAIN.Q[1]", "MAIN.Q[2]", "MAIN.TWO.A", "MAIN.TWO.B"],
    }


def test_create_answers_201_with_the_location(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(counter_project("c2"))
    response = client.post("/api/projects/c2/simulations")
    assert response.status_code == 201
    assert response.headers["Location"] == f"/api/simulations/{response.json()['id']}"


def test_a_project_with_errors_is_a_422_with_located_diagnostics(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    program = st_program("Main", "VAR\n    x : INT;\nEND_VAR", "x := 1;\nx := y + 1;")
    workspace.create(Project(name="broken", pous=[program]))
    response = client.post("/api/projects/broken/simulations")
    assert response.status_code == 422
    body = detail(response)
    assert body["message"].startswith("project 'broken' does not compile: ")
    errors = [d for d in body["diagnostics"] if d["severity"] == "error"]
    assert [(d["pou"], d["line"]) for d in errors] == [("Main", 2)]
    assert "'y'" in errors[0]["message"]
    assert client.get("/api/simulations").json() == []


def test_unknown_project_and_unknown_simulation_are_404(client: TestClient, registry: SimulationRegistry) -> None:
    assert client.post("/api/projects/nope/simulations").status_code == 404
    for method, url in (
        ("GET", "/api/simulations/abc"),
        ("POST", "/api/simulations/abc/start"),
        ("POST", "/api/simulations/abc/stop"),
        ("POST", "/api/simulations/abc/reset"),
        ("POST", "/api/simulations/abc/cycle"),
        ("DELETE", "/api/simulations/abc"),
    ):
        response = client.request(method, url)
        assert response.status_code == 404, (method, url)
        assert detail(response)["message"].startswith("no simulation 'abc'")


def test_single_cycles_advance_one_scan_of_the_task_each(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    for scan in (1, 2, 3):
        info = client.post(f"/api/simulations/{counter}/cycle").json()
        assert (info["state"], info["scan_count"], info["time_ms"]) == ("stopped", scan, 10.0 * scan)
        assert entry(registry, counter).handle.read("Main.Count") == scan
    assert 0 < info["scan_ms"]["min"] <= info["scan_ms"]["avg"] <= info["scan_ms"]["max"]


def test_start_paces_scans_against_the_wall_clock_and_stop_holds(client: TestClient, counter: str) -> None:
    started = client.post(f"/api/simulations/{counter}/start").json()
    assert started["state"] == "running"
    time.sleep(0.4)
    info = client.get(f"/api/simulations/{counter}").json()
    # virtual time tracks real time: never ahead; behind by at most the pacer's lag, plus what it gave up
    # when a busy machine held the scans back longer than that (an overrun, max 200 ms lag each)
    behind = 100 + 250 * info["overruns"]
    assert info["real_time_ms"] - behind <= info["time_ms"] <= info["real_time_ms"] + 10, info
    assert info["scan_count"] == info["time_ms"] / 10 - started["time_ms"] / 10
    stopped = client.post(f"/api/simulations/{counter}/stop").json()
    assert stopped["state"] == "stopped"
    time.sleep(0.1)
    assert client.get(f"/api/simulations/{counter}").json()["scan_count"] == stopped["scan_count"]


def test_a_slower_task_runs_at_its_own_interval(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(counter_project("slow", interval="T#50ms"))
    sim_id = client.post("/api/projects/slow/simulations").json()["id"]
    client.post(f"/api/simulations/{sim_id}/start")
    time.sleep(0.5)
    info = client.post(f"/api/simulations/{sim_id}/stop").json()
    assert 5 <= info["scan_count"] <= 11, info  # 10 at exactly 50 ms
    assert info["time_ms"] == 50.0 * info["scan_count"]


def test_single_cycle_while_running_is_a_409(client: TestClient, counter: str) -> None:
    client.post(f"/api/simulations/{counter}/start")
    response = client.post(f"/api/simulations/{counter}/cycle")
    assert response.status_code == 409
    assert detail(response)["message"] == "the simulation is running: stop it before a single cycle"


def test_reset_warm_keeps_retain_and_cold_clears_it(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    sim = entry(registry, counter).handle
    client.post(f"/api/simulations/{counter}/cycle")
    client.post(f"/api/simulations/{counter}/cycle")
    sim.call("write", path="Main.Kept", value=42)
    client.post(f"/api/simulations/{counter}/cycle")
    warm = client.post(f"/api/simulations/{counter}/reset").json()  # no body: warm
    assert warm["state"] == "stopped"
    assert (sim.read("Main.Kept"), sim.read("Main.Count")) == (42, 0)
    cold = client.post(f"/api/simulations/{counter}/reset", json={"cold": True})
    assert cold.status_code == 200
    assert (sim.read("Main.Kept"), sim.read("Main.Count")) == (0, 0)


def test_reset_with_a_bad_body_is_a_422(client: TestClient, counter: str) -> None:
    response = client.post(f"/api/simulations/{counter}/reset", json={"cold": "very"})
    assert response.status_code == 422
    assert detail(response)["diagnostics"][0]["json_path"] == "$.cold"
    assert client.post(f"/api/simulations/{counter}/reset", json={"hot": True}).status_code == 422


def test_a_runtime_fault_stops_the_simulation_with_its_location(
    client: TestClient, counter: str, registry: SimulationRegistry
) -> None:
    entry(registry, counter).handle.call("write", path="Main.Divisor", value=0)
    info = client.post(f"/api/simulations/{counter}/cycle").json()
    assert info["state"] == "faulted"
    fault = info["fault"]
    assert (fault["code"], fault["pou"], fault["line"]) == ("ENGINE-RUNTIME", "MAIN", 3)
    assert fault["message"].startswith("division by zero: 100 / 0 at POU MAIN, line 3")
    refused = client.post(f"/api/simulations/{counter}/start")
    assert refused.status_code == 409
    assert detail(refused)["message"] == "the simulation stopped on a fault: reset it before running"
    assert client.get("/api/health").status_code == 200
    reset = client.post(f"/api/simulations/{counter}/reset").json()
    assert (reset["state"], reset["fault"]) == ("stopped", None)


def test_delete_ends_the_simulation(client: TestClient, counter: str) -> None:
    client.post(f"/api/simulations/{counter}/start")
    assert client.delete(f"/api/simulations/{counter}").status_code == 204
    assert client.get(f"/api/simulations/{counter}").status_code == 404
    assert client.delete(f"/api/simulations/{counter}").status_code == 404
    assert client.get("/api/simulations").json() == []


def test_the_number_of_simulations_is_bounded_with_a_429(client: TestClient, workspace: Workspace) -> None:
    registry = install(client, SimulationSettings(max_simulations=2))
    try:
        workspace.create(counter_project())
        ids = [client.post("/api/projects/counter/simulations").json()["id"] for _ in range(2)]
        refused = client.post("/api/projects/counter/simulations")
        assert refused.status_code == 429
        assert detail(refused)["message"].startswith("the server already runs 2 simulations")
        client.delete(f"/api/simulations/{ids[0]}")
        assert client.post("/api/projects/counter/simulations").status_code == 201
    finally:
        registry.close()


def test_an_unused_simulation_ends_after_the_idle_time_even_running(client: TestClient, workspace: Workspace) -> None:
    registry = install(client, SimulationSettings(idle_timeout_s=0.2, reap_every_s=0.02))
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        client.post(f"/api/simulations/{sim_id}/start")
        handle = entry(registry, sim_id).handle
        wait_for(lambda: client.get("/api/simulations").json() == [], timeout=2.0)
        wait_for(lambda: handle.process.exitcode is not None)  # its process has ended
    finally:
        registry.close()


def test_requests_keep_a_simulation_alive(client: TestClient, workspace: Workspace) -> None:
    # requests 0.25 s apart over 2 s keep alive a simulation idle after 1 s (a shorter idle time failed at load 10,
    # where a request itself may take a good part of it)
    registry = install(client, SimulationSettings(idle_timeout_s=1.0, reap_every_s=0.02))
    try:
        workspace.create(counter_project())
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        for _ in range(8):
            time.sleep(0.25)
            assert client.get(f"/api/simulations/{sim_id}").status_code == 200
    finally:
        registry.close()


def test_default_settings_are_used_when_the_app_has_no_registry(client: TestClient, workspace: Workspace) -> None:
    workspace.create(counter_project())
    response = client.post("/api/projects/counter/simulations")
    assert response.status_code == 201
    registry = client.app.state.simulations  # type: ignore[attr-defined]
    try:
        assert registry.settings == SimulationSettings()
    finally:
        registry.close()
