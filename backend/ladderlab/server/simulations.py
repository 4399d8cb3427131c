"""Simulation routes: build a saved project into a live simulation, run, stop, reset, single cycle, delete.

Each simulation runs in a process of its own (``simulation/remote.py``), built with the monitor
variant: the online LD/FBD views need per-element power flow (probes). Its process switches to
the debug variant (pause points) while breakpoints are set or a step runs (docs/architecture.md,
"Online mode"). Reading a simulation and deleting it never wait for its process; stop waits at
most ``answer_s``, so they answer at once whatever the program does.
"""

from __future__ import annotations

import json
from typing import Annotated, Any

from fastapi import APIRouter, Body, Depends, Query, Request, Response, status
from starlette.concurrency import run_in_threadpool

from ..model.api import (
    HistoryDiff,
    HistoryFound,
    HistoryMark,
    HistoryStep,
    IoPoint,
    ResetSimulation,
    ScanTimes,
    SeekScan,
    SimulationInfo,
)
from ..simulation.commands import CommandError
from ..simulation.recording import Recording, parse_recording
from ..simulation.registry import SimulationEntry, SimulationRegistry
from ..simulation.remote import BuildFailed
from ..storage.workspace import StoredProject, Workspace
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
    entry = _built(name, workspace.load(name), registry)
    response.headers["Location"] = f"/api/simulations/{entry.id}"
    return simulation_info(entry)


def _built(name: str, stored: StoredProject, registry: SimulationRegistry) -> SimulationEntry:
    """A new simulation of the saved project ``stored``; 422 with the diagnostics when it does not compile."""
    try:
        return registry.create(stored.project, stored.revision)
    except BuildFailed as failure:
        errors = [d for d in failure.diagnostics if d.severity == "error"]
        reason = summarise(errors) if errors else failure.message
        raise ApiError(422, f"project {name!r} does not compile: {reason}", failure.diagnostics) from None


@router.post(
    "/api/projects/{name}/recordings",
    status_code=status.HTTP_201_CREATED,
    response_model=SimulationInfo,
    responses=responses(404, 409, 413, 422, 429),
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {"application/json": {"schema": {"type": "string", "description": "a recording file"}}},
        }
    },
)
async def open_recording(
    name: str,
    request: Request,
    workspace: WorkspaceDep,
    registry: RegistryDep,
    response: Response,
    file: Annotated[str, Query(description="the file's name, for the messages")] = "the recording",
) -> SimulationInfo:
    """Open a recording (the file ``ladderlab run --record`` writes or "Download recording" gives) as a
    history-only simulation of the saved project: its scans are run at once with their recorded inputs, as
    ``ladderlab replay`` runs them, so every one can be viewed, compared and continued from. 409 when the project
    is not at the recording's revision, 422 when the file is not a recording."""
    data = await request.body()
    return await run_in_threadpool(_open_recording, name, data, file, workspace, registry, response)


def _open_recording(
    name: str, data: bytes, file: str, workspace: Workspace, registry: SimulationRegistry, response: Response
) -> SimulationInfo:
    registry.check_room()
    stored = workspace.load(name)
    try:
        record = parse_recording(data, file)
    except ValueError as error:
        raise ApiError(422, str(error)) from None
    if record.revision != stored.revision:
        raise ApiError(
            409,
            f"{file} was recorded with revision {record.revision} of {record.project}; project {name!r} is now at "
            f"revision {stored.revision}: open it in the project as it was when it was recorded",
        )
    entry = _built(name, stored, registry)
    timeout = entry.handle.settings.build_timeout_s  # the scans run at once: as long as a history question
    try:
        info = simulation_info(entry, entry.handle.open_recording(record.inputs, record.scans, timeout))
    except CommandError as error:
        registry.delete(entry.id)
        raise ApiError(409 if error.code == "bad_state" else 422, error.message) from None
    except TimeoutError:
        registry.delete(entry.id)
        raise ApiError(
            422, f"{file}: its {record.scans} scans did not run within {timeout:g} s (the server's build_timeout_s)"
        ) from None
    response.headers["Location"] = f"/api/simulations/{entry.id}"
    return info


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

    A simulation whose process was ended (it stopped answering or crashed) starts again in a new one; one opened from
    a recording opens it again there (history only). A recording shown history only is not reset (409)."""
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


@router.get(
    "/api/simulations/{sim_id}/inputs",
    response_class=Response,
    responses={**responses(404, 409), 200: {"content": {"application/x-ndjson": {}}}},
)
def inputs(sim_id: str, registry: RegistryDep) -> Response:
    """The input events the simulation applied (writes, forces, releases, panel events, injected faults, resets),
    oldest first, one JSON object per line with the scan each applied in: ``ladderlab run --events`` replays them,
    so a panel session reproduces on the command line. The last 100,000 are kept."""
    entry = registry.get(sim_id)
    try:
        answer = entry.handle.inputs()
    except CommandError as error:
        raise ApiError(409, error.message) from None
    text = "".join(json.dumps(line) + "\n" for line in answer["inputs"])
    headers = {"Content-Disposition": f'attachment; filename="{entry.project}-inputs.jsonl"'}
    if answer["dropped"]:
        headers["X-Dropped-Inputs"] = str(answer["dropped"])
    return Response(text, media_type="application/x-ndjson", headers=headers)


@router.get(
    "/api/simulations/{sim_id}/recording",
    response_class=Response,
    responses={**responses(404, 409), 200: {"content": {"application/json": {}}}},
)
def recording(sim_id: str, registry: RegistryDep, workspace: WorkspaceDep) -> Response:
    """The session as a recording ``ladderlab replay`` prints again scan for scan: the project's folder and
    revision, the inputs applied with their scans, the scans run (409 when it cannot be one run from scan 0:
    inputs dropped, a scan changed at a breakpoint, a continue from a past scan)."""
    entry = registry.get(sim_id)
    try:
        answer = entry.handle.inputs()
    except CommandError as error:
        raise ApiError(409, error.message) from None
    halted = [line["scan"] for line in answer["inputs"] if line.get("phase") == "halt"]
    reason = (
        f"{answer['dropped']} older inputs were dropped"
        if answer["dropped"]
        else "it continued from a past scan"
        if answer["forked"]
        else f"scan {halted[0]} was changed while halted at a breakpoint"
        if halted
        else None
    )
    if reason is not None:
        raise ApiError(409, f"this session cannot be replayed from scan 0 by ladderlab replay: {reason}")
    record = Recording(str(workspace.folder(entry.project)), entry.revision, answer["scans"], None, answer["inputs"])
    headers = {"Content-Disposition": f'attachment; filename="{entry.project}-recording.json"'}
    return Response(record.to_bytes(), media_type="application/json", headers=headers)


@router.post("/api/simulations/{sim_id}/seek", response_model=SimulationInfo, responses=_DESCRIBED)
def seek(sim_id: str, registry: RegistryDep, body: Annotated[SeekScan, Body()]) -> SimulationInfo:
    """Show a past scan (issue 23): its values and power flow, recomputed from the scan history, until
    ``POST .../live``; the live scans go on. Scans are numbered as ``scan_count`` (422 outside the history).
    409 when the replay does not end within ``history_timeout_s``: it goes on, and shows the scan once it ends."""
    entry = registry.get(sim_id)
    return simulation_info(entry, _history_request(entry, "seek", seek_late(body.scan), scan=body.scan)["info"])


def seek_late(scan: int) -> tuple[str, str]:
    """What a seek that does not end within ``history_timeout_s`` is refused with (REST and websocket)."""
    return f"the seek to scan {scan} did not end", f"scan {scan} is shown once it ends"


@router.post("/api/simulations/{sim_id}/live", response_model=SimulationInfo, responses=_DESCRIBED)
def live(sim_id: str, registry: RegistryDep) -> SimulationInfo:
    """Show the live scans again after a seek."""
    return _command(registry.get(sim_id), "live")


@router.post("/api/simulations/{sim_id}/history/step", response_model=SimulationInfo, responses=_DESCRIBED)
def history_step(
    sim_id: str, registry: RegistryDep, body: Annotated[HistoryStep | None, Body()] = None
) -> SimulationInfo:
    """Step through the scan shown (after a seek): the first step replays it in the debug variant from the scan
    before it and halts at its first network or line, each next one at the next; the values and power flow are
    those of that point (``history.stepping`` says where). The history and the live simulation stay as they are."""
    granularity = body.granularity if body is not None else "statement"
    entry = registry.get(sim_id)
    late = ("the step did not end", "the scan shown shows where it stands once it ends")  # the first compiles too
    return simulation_info(entry, _history_request(entry, "history_step", late, granularity=granularity)["info"])


@router.get("/api/simulations/{sim_id}/history/find", response_model=HistoryFound, responses=_DESCRIBED)
def history_find(
    sim_id: str,
    registry: RegistryDep,
    scan: int,
    direction: int = 1,
    path: str | None = None,
    condition: str | None = None,
) -> HistoryFound:
    """The next (``direction`` 1) or previous (-1) scan from ``scan`` where the value of ``path`` changed, or
    where ``condition`` (as run until takes it: ``Motor``, ``Tank.Level >= 80``) became TRUE, from the scan
    history; ``scan`` null when the history holds none."""
    args = {"scan": scan, "direction": direction, "path": path, "condition": condition}
    return HistoryFound(scan=_history_call(registry.get(sim_id), "history_find", args))


@router.get("/api/simulations/{sim_id}/history/diff", response_model=HistoryDiff, responses=_DESCRIBED)
def history_diff(sim_id: str, registry: RegistryDep, first: int, second: int) -> HistoryDiff:
    """The variables whose values differ between the ends of two scans of the history, with both values."""
    differences = _history_call(registry.get(sim_id), "history_diff", {"first": first, "second": second})
    return HistoryDiff(first=first, second=second, differences=differences)


@router.get("/api/simulations/{sim_id}/history/marks", response_model=list[HistoryMark], responses=_DESCRIBED)
def history_marks(sim_id: str, registry: RegistryDep) -> list[HistoryMark]:
    """The newest 1,000 scans of the history with an input or a runtime error: the timeline's marks."""
    return [HistoryMark(**mark) for mark in _history_call(registry.get(sim_id), "history_marks", {})]


#: What a question to the history that does not end in time is refused with (it goes on; its answer is lost).
_UNANSWERED = ("the scan history did not answer", None)


def _history_call(entry: SimulationEntry, op: str, args: dict[str, Any]) -> Any:
    """A question to the scan history (find, diff, marks): its ``result``."""
    return _history_request(entry, op, _UNANSWERED, **args)["result"]


def _history_request(entry: SimulationEntry, op: str, late: tuple[str, str | None], **args: Any) -> dict[str, Any]:
    """Run ``op`` on the scan history: it replays scans, so it may take longer than a command, up to
    ``history_timeout_s``; then 409 in the words of ``late`` (what did not end, what happens once it does): the
    simulation's process goes on with it, the live scans wait meanwhile and are not changed. The reply: ``result``
    and ``info``."""
    timeout = entry.handle.settings.history_timeout_s
    try:
        return entry.handle.request(op, **args).result(timeout)
    except CommandError as error:
        raise ApiError(409 if error.code == "bad_state" else 422, error.message) from None
    except TimeoutError:
        raise ApiError(409, late_message(late, timeout)) from None


def late_message(late: tuple[str, str | None], timeout: float) -> str:
    """The words of a refusal after ``timeout`` seconds: what did not end (and what happens once it does)."""
    what, then = late
    return f"{what} within {timeout:g} s (the server's history_timeout_s)" + (f": {then}" if then else "")


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
        speed=info.get("speed", 1.0),
        pending_inputs=info.get("pending_inputs", 0),
        until=info.get("until"),
        history=info.get("history"),
        io=[IoPoint.model_validate(point) for point in handle.io],
    )
