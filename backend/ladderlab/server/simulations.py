"""Simulation routes: compile a saved project into a live simulation, run, stop, reset, single cycle, delete.

Simulations are built with the monitor variant: the online LD/FBD views need per-element
power flow (probes). The runner switches to the debug variant (pause points) while
breakpoints are set or a step runs (docs/architecture.md, "Online mode").
"""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Body, Depends, Request, Response, status

from ..model import has_errors
from ..model.api import IoPoint, ResetSimulation, ScanTimes, SimulationInfo
from ..simulation.build import build_project
from ..simulation.registry import SimulationEntry, SimulationRegistry
from ..simulation.runner import CommandError, SimRunner
from .context import WorkspaceDep, modified_at, registry_of
from .errors import ApiError, responses, summarise

router = APIRouter(tags=["simulations"])


def _registry(request: Request) -> SimulationRegistry:
    return registry_of(request.app)


RegistryDep = Annotated[SimulationRegistry, Depends(_registry)]

_DESCRIBED = responses(404, 409, 422)


@router.post(
    "/api/projects/{name}/simulations",
    status_code=status.HTTP_201_CREATED,
    response_model=SimulationInfo,
    responses=responses(404, 422, 429),
)
def create_simulation(name: str, workspace: WorkspaceDep, registry: RegistryDep, response: Response) -> SimulationInfo:
    """Compile the saved project (monitor variant) into a stopped simulation."""
    registry.check_room()
    stored = workspace.load(name)
    build = build_project(stored.project, variant="monitor")
    if build.compiled is None or has_errors(build.diagnostics):
        errors = [d for d in build.diagnostics if d.severity == "error"]
        raise ApiError(422, f"project {name!r} does not compile: {summarise(errors)}", build.diagnostics)
    sim = build.simulation(watchdog_s=registry.settings.watchdog_s)
    entry = registry.add(name, stored.revision, SimRunner(sim, publish_s=registry.settings.publish_s))
    response.headers["Location"] = f"/api/simulations/{entry.id}"
    return simulation_info(entry)


@router.get("/api/simulations", response_model=list[SimulationInfo])
def list_simulations(registry: RegistryDep) -> list[SimulationInfo]:
    return [simulation_info(entry) for entry in registry.list()]


@router.get("/api/simulations/{sim_id}", response_model=SimulationInfo, responses=responses(404))
def get_simulation(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    return simulation_info(registry.get(sim_id))


@router.post("/api/simulations/{sim_id}/start", response_model=SimulationInfo, responses=_DESCRIBED)
def start(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """Run in real time (scans paced by the task intervals); from a halt, continue the scan first."""
    return _command(registry.get(sim_id), lambda runner: runner.start())


@router.post("/api/simulations/{sim_id}/stop", response_model=SimulationInfo, responses=_DESCRIBED)
def stop(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """Stop after the current scan (a halted scan stays halted)."""
    return _command(registry.get(sim_id), lambda runner: runner.stop())


@router.post("/api/simulations/{sim_id}/reset", response_model=SimulationInfo, responses=_DESCRIBED)
def reset(sim_id: str, registry: RegistryDep, body: Annotated[ResetSimulation | None, Body()] = None) -> SimulationInfo:
    """Stop and restart warm (RETAIN variables keep their values) or cold; clears faults; forces stay."""
    cold = body.cold if body is not None else False
    return _command(registry.get(sim_id), lambda runner: runner.reset(cold=cold))


@router.post("/api/simulations/{sim_id}/cycle", response_model=SimulationInfo, responses=_DESCRIBED)
def single_cycle(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """One scan of a stopped simulation (409 while running); when halted, the rest of the scan."""
    return _command(registry.get(sim_id), lambda runner: runner.single_cycle())


@router.delete(
    "/api/simulations/{sim_id}",
    status_code=status.HTTP_204_NO_CONTENT,
    response_class=Response,
    responses=responses(404),
)
def delete_simulation(sim_id: str, registry: RegistryDep) -> Response:
    """End the simulation; its websocket clients are told and disconnected."""
    registry.delete(sim_id)
    return Response(status_code=status.HTTP_204_NO_CONTENT)


def _command(entry: SimulationEntry, action) -> SimulationInfo:
    try:
        action(entry.runner)
    except CommandError as error:
        raise ApiError(409 if error.code == "bad_state" else 422, error.message) from None
    return simulation_info(entry)


def simulation_info(entry: SimulationEntry) -> SimulationInfo:
    runner = entry.runner
    with runner.lock:
        sim = runner.sim
        stats = sim.stats
        fault = sim.fault
        return SimulationInfo(
            id=entry.id,
            project=entry.project,
            revision=entry.revision,
            state=runner.state,  # type: ignore[arg-type]
            scan_count=sim.scan_count,
            time_ms=sim.time_ms,
            real_time_ms=runner.real_time_ms(),
            scan_ms=ScanTimes(min=stats.min_ms, avg=stats.avg_ms, max=stats.max_ms, last=stats.last_ms),
            overruns=runner.overruns,
            fault=fault.diagnostic() if fault is not None else None,
            clients=entry.clients,
            created=modified_at(entry.created),
            instances=sim.instances(),
            io=[IoPoint(area=p.area, address=p.address, type=p.type, names=p.names) for p in sim.io_points()],  # type: ignore[arg-type]
        )
