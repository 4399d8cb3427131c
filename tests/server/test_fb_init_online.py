"""FB_init online (issue 25; docs/st.md "FB_init and FB_exit"): a simulation starts with every instance's FB_init run,
and a runtime error in one faults the simulation at its start, located in the method's body, over real HTTP."""

from __future__ import annotations

import time

from fastapi.testclient import TestClient

from ladderlab.simulation.build import build_project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.simulation.runner import SimRunner
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

from .helpers import detail
from .test_simulations_support import entry, registry

__all__ = ["registry"]  # fixture used below

SOURCE = """FUNCTION_BLOCK Scale
VAR_OUTPUT k : INT; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; d : INT; END_VAR
k := 100 / d;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Scale(d := {d}); k : INT; END_VAR
k := s.k;
END_PROGRAM
"""


def simulation(client: TestClient, workspace: Workspace, d: int) -> str:
    project, diagnostics = source_to_project(SOURCE.format(d=d), "scaled")
    assert diagnostics == []
    workspace.create(project)
    response = client.post("/api/projects/scaled/simulations")
    assert response.status_code == 201, response.text
    return response.json()["id"]


def test_the_first_scan_sees_what_fb_init_computed(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim = simulation(client, workspace, 4)
    info = client.post(f"/api/simulations/{sim}/cycle").json()
    assert (info["state"], info["fault"]) == ("stopped", None)
    assert entry(registry, sim).handle.read("Main.k") == 25


def test_a_fault_in_fb_init_faults_the_simulation_at_its_start_and_again_after_a_reset(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    sim = simulation(client, workspace, 0)
    info = client.get(f"/api/simulations/{sim}").json()
    assert info["state"] == "faulted"
    fault = info["fault"]
    assert (fault["code"], fault["pou"], fault["line"], fault["column"]) == ("ENGINE-RUNTIME", "SCALE.FB_INIT", 5, 1)
    assert fault["message"].startswith("division by zero: 100 / 0 at POU SCALE.FB_INIT, line 5 column 1")
    assert ", task (initialisation), scan 0" in fault["message"]
    refused = client.post(f"/api/simulations/{sim}/start")
    assert refused.status_code == 409
    assert detail(refused)["message"] == "the simulation stopped on a fault: reset it before running"
    reset = client.post(f"/api/simulations/{sim}/reset", json={"cold": True}).json()
    assert reset["state"] == "faulted"


def test_the_ready_message_of_a_simulation_whose_fb_init_faulted_says_faulted() -> None:
    """The process sends its runner's info ("ready") before the engine thread first accounts for what the engine
    did: a fault of FB_init at the start is in it already (it said "stopped" until the next frame, and the test
    above failed now and then)."""

    class Sink:
        def status(self, *args: object) -> None: ...
        def log(self, entry: object) -> None: ...
        def frame(self, *args: object, **kwargs: object) -> None: ...

    project, _ = source_to_project(SOURCE.format(d=0), "scaled")
    build = build_project(project, variant="monitor")
    runner = SimRunner(build.simulation(), Sink())
    info = runner.info()
    assert (info["state"], info["fault"]["pou"]) == ("faulted", "SCALE.FB_INIT")


AFTER_INIT = """{attribute 'call_after_init'}
FUNCTION_BLOCK Scale
VAR_INPUT d : INT; END_VAR
VAR_OUTPUT k : INT; END_VAR
{attribute 'call_after_init'}
METHOD Setup
k := 100 / d;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Scale := (d := D_VALUE); k : INT; END_VAR
k := s.k;
END_PROGRAM
"""


def test_a_call_after_init_method_runs_with_the_declarations_values_and_its_fault_is_located_in_its_body(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """CODESYS's "Attribute: call_after_init": the method runs after the declaration's values (d 4: k 25; d 0: a
    division by zero in its body, line 7 of the file, before any task runs)."""
    for name, d in (("fine", 4), ("broken", 0)):
        project, diagnostics = source_to_project(AFTER_INIT.replace("D_VALUE", str(d)), name)
        assert diagnostics == []
        workspace.create(project)
    fine = client.post("/api/projects/fine/simulations").json()["id"]
    client.post(f"/api/simulations/{fine}/cycle")
    assert entry(registry, fine).handle.read("Main.k") == 25
    broken = client.post("/api/projects/broken/simulations").json()["id"]
    info = client.get(f"/api/simulations/{broken}").json()
    for _ in range(50):  # the worker may report the initialisation's fault a moment after the answer
        if info["fault"] is not None:
            break
        time.sleep(0.1)
        info = client.get(f"/api/simulations/{broken}").json()
    fault = info["fault"]
    assert (info["state"], fault["code"], fault["pou"], fault["line"], fault["column"]) == (
        "faulted",
        "ENGINE-RUNTIME",
        "SCALE.SETUP",
        7,
        1,
    )
    assert ", task (initialisation), scan 0" in fault["message"]
