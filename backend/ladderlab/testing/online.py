"""A failed test's last state as an online simulation (the Tests panel's "Open failure online").

``failed_test_simulation`` runs in the new simulation's own process (``simulation.remote.Maker``): it runs
the test again (the virtual clock makes it repeat exactly) and returns a simulation of the project and the
test's program restored to the state it had when the test failed, so no test runs in the server's process.
"""

from __future__ import annotations

from ..engine.simulation import Simulation
from ..model.project import Project
from ..simulation.build import Build
from .run import failure_state


def failed_test_simulation(*, project_json: str, file: str, text: str, test: str, watchdog_s: float) -> Simulation:
    """LookupError: no such test, or the file does not compile; ValueError: the test passes."""
    project = Project.model_validate_json(project_json)
    prepared, state = failure_state(project, file, text, test)
    sim = Build(prepared.compiled, [], prepared.watchdogs).simulation(watchdog_s=watchdog_s)
    sim.restore(state)
    return sim
