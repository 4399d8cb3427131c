"""Simulation routes: build a saved project into a live simulation, run, stop, reset, single cycle, delete.

Each simulation runs in a process of its own (``simulation/remote.py``), built with the monitor
variant: the online LD/FBD views need per-element power flow (probes). Its process switches to
the debug variant (pause points) while breakpoints are set or a step runs (docs/architecture.md,
"Online mode"). Reading a simulation and deleting it never wait for its process; stop waits at
most ``answer_s``, so they answer at once whatever the program does.
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Depends, Request, Response, status

from ..model.api import IoPoint, ResetSimulation, ScanTimes, SimulationInfo
from ..simulation.registry import SimulationEntry, SimulationRegistry
from ..simulation.remote import BuildFailed
from ..simulation.runner import CommandError
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
    """Build the saved project (monitor variant) into a stopped simulation, in a process of its own."""
    registry.check_room()
    stored = workspace.load(name)
    try:
        entry = registry.create(stored.project, stored.revision)
    except BuildFailed as failure:
        errors = [d for d in failure.diagnostics if d.severity == "error"]
        reason = summarise(errors) if errors else failure.message
        raise ApiError(422, f"project {name!r} does not compile: {reason}", failure.diagnostics) from None
    response.headers["Location"] = f"/api/simulations/{entry.id}"
    return simulation_info(entry)


@router.get("/api/simulations", response_model=list[SimulationInfo])
def list_simulations(registry: RegistryDep) -> list[SimulationInfo]:
    return [simulation_info(entry) for entry in registry.list()]


@router.get("/api/simulations/{sim_id}", response_model=SimulationInfo, responses=responses(404))
def get_simulation(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """What the simulation's process last reported (it is not asked: this answers at once)."""
    return simulation_info(registry.get(sim_id))


@router.post("/api/simulations/{sim_id}/start", response_model=SimulationInfo, responses=_DESCRIBED)
def start(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """Run in real time (scans paced by the task intervals); from a halt, continue the scan first."""
    return _command(registry.get(sim_id), "run")


@router.post(
    "/api/simulations/{sim_id}/stop",
    response_model=SimulationInfo,
    responses={**_DESCRIBED, 202: {"model": SimulationInfo, "description": "Stop requested; a scan is still running"}},
)
def stop(sim_id: str, registry: RegistryDep, response: Response) -> SimulationInfo:
    """Stop after the current scan (a halted scan stays halted). Answers within ``answer_s`` (50 ms): 202 with
    the last known state when the scan under way has not ended by then (the status message tells when it has)."""
    entry = registry.get(sim_id)
    try:
        return _command(entry, "stop", timeout=registry.settings.answer_s)
    except TimeoutError:
        response.status_code = status.HTTP_202_ACCEPTED
        return simulation_info(entry)


@router.post("/api/simulations/{sim_id}/reset", response_model=SimulationInfo, responses=_DESCRIBED)
def reset(sim_id: str, registry: RegistryDep, body: Annotated[ResetSimulation | None, Body()] = None) -> SimulationInfo:
    """Stop and restart warm (RETAIN variables keep their values) or cold; clears faults; forces stay.

    A simulation whose process was ended (it stopped answering or crashed) starts again in a new one."""
    entry = registry.get(sim_id)
    if not entry.handle.alive:
        try:
            entry.handle.restart()
        except BuildFailed as failure:
            raise ApiError(409, f"the simulation could not start again: {failure.message}") from None
        return simulation_info(entry)
    return _command(entry, "reset", cold=body.cold if body is not None else False)


@router.post("/api/simulations/{sim_id}/cycle", response_model=SimulationInfo, responses=_DESCRIBED)
def single_cycle(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """One scan of a stopped simulation (409 while running); when halted, the rest of the scan."""
    return _command(registry.get(sim_id), "single_cycle")


@router.delete(
    "/api/simulations/{sim_id}",
    status_code=status.HTTP_204_NO_CONTENT,
    response_class=Response,
    responses=responses(404),
)
def delete_simulation(sim_id: str, registry: RegistryDep) -> Response:
    """End the simulation and its process at once; its websocket clients are told and disconnected."""
    registry.delete(sim_id)
    return Response(status_code=status.HTTP_204_NO_CONTENT)


def _command(entry: SimulationEntry, op: str, timeout: float | None = None, **args: Any) -> SimulationInfo:
    """Run ``op``; the simulation as the command left it."""
    try:
        info = entry.handle.command(op, timeout=timeout, **args)
    except CommandError as error:
        raise ApiError(409 if error.code == "bad_state" else 422, error.message) from None
    return simulation_info(entry, info)


def simulation_info(entry: SimulationEntry, info: dict[str, Any] | None = None) -> SimulationInfo:
    """``info``: the figures a command answered with; else the latest the simulation's process reported."""
    handle = entry.handle
    info = info if info is not None else handle.info
    return SimulationInfo(
        id=entry.id,
        project=entry.project,
        revision=entry.revision,
        state=info["state"],
        scan_count=info["scan_count"],
        time_ms=info["time_ms"],
        real_time_ms=info["real_time_ms"],
        scan_ms=ScanTimes(**info["scan_ms"]),
        overruns=info["overruns"],
        fault=info["fault"],
        clients=entry.clients,
        created=modified_at(entry.created),
        instances=handle.instances,
        io=[IoPoint.model_validate(point) for point in handle.io],
    )
