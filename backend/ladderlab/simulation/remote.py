"""The server's side of one simulation: its worker process, what it last said, and requests to it.

``SimulationHandle`` starts the simulation's process (``worker.run_simulation``) with a spec
(the project as JSON text and the settings that apply), waits for it to build, and from then on:

* keeps what the process reports, so the server can answer without asking it: the state
  (``status``), the figures of ``SimulationInfo`` (``info``), the latest ``frame`` (values and
  element states of everything some client watches, rebuilt from the process's diffs), the online
  log (``history``: the last ``log_entries`` entries, with a count of older ones dropped) and the
  trace chunks of each client (``traces``);
* sends commands as requests and hands back their replies (``request``/``call``/``acall``);
* tells its listeners (the websocket clients) about status, log entries and frames, from the
  supervisor's thread: they must only hand them over (e.g. ``loop.call_soon_threadsafe``);
* supervises the process: a build that takes longer than ``build_timeout_s``, a process that sends
  nothing for ``grace_s`` (it beats four times a second while it can run at all), or a command left
  unanswered for ``build_timeout_s`` + ``grace_s`` (the longest a debug build may take) ends the
  process; the simulation is then ``faulted`` with that reason, and a reset starts a new process
  (the clients' subscriptions are sent to it again).
"""

from __future__ import annotations

import asyncio
import itertools
import threading
import time
from collections import deque
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from dataclasses import dataclass, field, replace
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from typing import TYPE_CHECKING, Any, Protocol

from ..model import Diagnostic
from ..model.codes import RUNTIME_FAULT
from ..model.monitor import DisplayType, Log, LogKind, LogLevel, Status
from .commands import CommandError
from .supervisor import WorkerHub, kill, start_process
from .trace_inbox import TraceInbox
from .worker_settings import WorkerSettings

if TYPE_CHECKING:
    from ..engine.simulation import Simulation

#: The simulation process's function, by name: the server does not import the compiler (startup, issue 27).
RUN_SIMULATION = "ladderlab.simulation.worker:run_simulation"


@dataclass(frozen=True)
class Maker:
    """Another way to make a simulation than building the project (a failed test's last state, testing/online.py):
    ``function`` is importable by name (it runs in the simulation's process) and is called with ``args`` and
    ``watchdog_s``; a LookupError or ValueError it raises is the reason the simulation cannot be made."""

    function: Callable[..., Simulation]
    args: dict[str, Any]


class BuildFailed(Exception):
    """The project did not build: ``diagnostics`` say why (or ``message``: a limit it hit)."""

    def __init__(self, message: str, diagnostics: list[Diagnostic] | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.diagnostics = diagnostics or []


@dataclass(frozen=True)
class Frame:
    """What the simulation last published of the watched variables and elements; ``seq`` grows with each."""

    seq: int
    scan: int
    time_ms: float
    wall: float  # time.time() when the process read the values
    values: dict[str, object]  # canonical path -> value: the union of every client's watch
    power: dict[str, dict[str, object]]  # canonical instance -> element -> state (None: did not run)
    forced: tuple[str, ...]
    injected: dict[str, str]  # canonical path -> mode of the fault injected there
    history: dict[str, Any] | None = None  # the scan history's range and the scan viewed (runner.history_range)


EMPTY_FRAME = Frame(0, 0, 0.0, 0.0, {}, {}, (), {})


@dataclass(frozen=True)
class Watch:
    """One client's subscription as the simulation resolved it: canonical paths with how to show them."""

    paths: dict[str, DisplayType]
    # per element request: (canonical instance, element ids watched or None for all), None where refused
    elements: tuple[tuple[str, tuple[str, ...] | None] | None, ...] = ()
    refused: tuple[str, ...] = ()  # why each unknown path, instance or element was left out (the rest is watched)


class Listener(Protocol):
    def event(self, message: Status | Log) -> None:
        """A new state or log entry (for every client)."""

    def frame(self) -> None:
        """A new frame was published."""

    def closed(self) -> None:
        """The simulation was deleted: nothing more will come."""


@dataclass
class _Requests:
    """Requests waiting for their reply, by id, with when each was sent."""

    ids: itertools.count[int] = field(default_factory=lambda: itertools.count(1))
    waiting: dict[int, tuple[Future[Any], float]] = field(default_factory=dict)


class SimulationHandle:
    """One simulation, run in its own process (see the module docstring)."""

    def __init__(self, hub: WorkerHub, project_json: str, settings: WorkerSettings, make: Maker | None = None) -> None:
        self.hub = hub
        self.settings = settings
        self.spec = {
            "project": project_json,
            "variant": "monitor",
            "watchdog_s": settings.watchdog_s,
            "publish_s": settings.publish_s,
            "memory_bytes": settings.memory_bytes,
            "history_bytes": settings.history_bytes,
            "beat_s": settings.beat_s,
            "make": make,
        }
        self.instances: dict[str, list[str]] = {}
        self.io: list[dict[str, Any]] = []  # the addresses the program uses (Simulation.io_points), plain data
        self.info: dict[str, Any] = {}
        self.frame = EMPTY_FRAME
        #: the seq of the last frame before this process started: a new process counts its frames from 1 again,
        #: and a client that was sent the old process's frame of that seq would take the new one for it
        self._seq_base = 0
        self.status = Status(type="status", state="stopped")
        self.history: deque[Log] = deque(maxlen=settings.log_entries)
        self.dropped_log_entries = 0
        self.traces = TraceInbox()
        self._lock = threading.RLock()
        self._send_lock = threading.Lock()
        self._listeners: list[Listener] = []
        self._watches: dict[int, dict[str, Any]] = {}  # client key -> its watch request (sent again after a restart)
        self._recording: dict[str, Any] | None = None  # the recording opened (open_recording): opened again by restart
        self._requests = _Requests()
        self._process: BaseProcess | None = None
        self._connection: Connection | None = None
        self._ready: Future[None] | None = None
        self._launched = 0.0
        self._alive = False
        self._closed = False
        self._gone = "the simulation has been deleted"
        self.last_heard = 0.0

    # ------------------------------------------------------------------ the process

    def launch(self) -> None:
        """Start the process and wait until it has built the project; raises ``BuildFailed``."""
        ready: Future[None] = Future()
        process, connection = start_process(
            "ladderlab.simulation.worker:run_simulation", self.spec, name="ladderlab-simulation"
        )
        with self._lock:
            self._process, self._connection, self._ready = process, connection, ready
            self._launched = self.last_heard = time.monotonic()
            self._seq_base = self.frame.seq
        self.hub.watch(connection, self)
        try:
            ready.result()
        except BuildFailed:
            self._end_process()
            raise

    def _end_process(self) -> None:
        with self._lock:
            process, connection = self._process, self._connection
            self._alive = False
        if connection is not None:  # closed when the hub lets go of it (never under the hub's wait)
            self.hub.forget(connection)
        if process is not None:
            kill(process)

    def receive(self, message: dict[str, Any]) -> None:
        """A message from the process (the supervisor's thread)."""
        self.last_heard = time.monotonic()
        kind = message["type"]
        if kind == "frame":
            self._on_frame(message)
        elif kind == "reply":
            self._on_reply(message)
        elif kind == "status":
            status = Status(type="status", state=message["state"], at=message["at"], stack=message["stack"])
            with self._lock:
                self.status = status
                listeners = list(self._listeners)
            for listener in listeners:
                listener.event(status)
        elif kind == "log":
            self._record(Log.model_validate(message["entry"]))
        elif kind == "ready":
            with self._lock:
                self.info, self.instances, self._alive = message["info"], message["instances"], True
                self.io = message.get("io", [])
                self.status = Status(type="status", state=message["info"]["state"])
            _answer(self._ready)
        elif kind == "failed":
            diagnostics = [Diagnostic.model_validate(d) for d in message.get("diagnostics", [])]
            failure = BuildFailed(message.get("message", "the project does not build"), diagnostics)
            _answer(self._ready, error=failure)

    def lost(self, reason: str | None = None) -> None:
        """The process ended, or broke the protocol (``reason``; the supervisor's thread): a crash, unless the
        simulation was being closed."""
        process, connection = self._process, self._connection
        if reason is not None and process is not None:  # still running: end it, and do not hear of it again
            if connection is not None:
                self.hub.forget(connection)
            kill(process)
        code = process.exitcode if process is not None else None
        if process is not None and code is None:
            process.join(0.5)
            code = process.exitcode
        why = reason or f"ended unexpectedly (exit code {code}; e.g. it ran out of memory)"
        with self._lock:
            building = self._ready if not self._alive and not self._closed else None
        if building is not None and not building.done():
            self._end_process()
            _answer(building, error=BuildFailed(f"the build {why}"))
            return
        self._fail(f"the simulation's process {why}: reset the simulation to start it again", kind="fault")

    def supervise(self, now: float) -> None:
        """End a process that builds too long, is silent for ``grace_s``, or leaves a command unanswered."""
        settings = self.settings
        with self._lock:
            if self._closed or self._process is None:
                return
            building = not self._alive and self._ready is not None and not self._ready.done()
            oldest = min((sent for _, sent in self._requests.waiting.values()), default=now)
        if building:
            if now - self._launched > settings.build_timeout_s:
                self._end_process()
                failure = BuildFailed(
                    f"the build did not finish within {settings.build_timeout_s:g} s "
                    "(the server's build_timeout_s setting)"
                )
                _answer(self._ready, error=failure)
            return
        if not self._alive:
            return
        if now - self.last_heard > settings.grace_s:
            self._fail(
                f"watchdog: the simulation did not answer for {settings.grace_s:g} s (one operation of its "
                "scan ran that long without the watchdog seeing it, e.g. a huge copy): its process was "
                "ended; reset the simulation to start it again",
                kind="watchdog",
            )
        elif now - oldest > settings.build_timeout_s + settings.grace_s:
            self._fail(
                f"the simulation left a command unanswered for {now - oldest:.0f} s: its process was ended; "
                "reset the simulation to start it again",
                kind="fault",
            )

    def _fail(self, reason: str, kind: LogKind) -> None:
        """The process is ended or gone: the simulation is faulted with ``reason`` until a reset starts another."""
        with self._lock:
            if self._closed or not self._alive:
                return
            self._alive = False
            self._gone = reason
            waiting, self._requests.waiting = self._requests.waiting, {}
            self.status = Status(type="status", state="faulted")
            fault = Diagnostic(code=RUNTIME_FAULT, message=reason)
            self.info = {**self.info, "state": "faulted", "fault": fault.model_dump(mode="json"), "history": None}
            self.frame = replace(self.frame, seq=self.frame.seq + 1, history=None)  # the history was in the process
            listeners = list(self._listeners)
        self._end_process()
        self.traces = TraceInbox()
        for future, _ in waiting.values():
            _answer(future, error=CommandError("bad_state", reason))
        self._record(Log(type="log", kind=kind, level="error", message=reason))
        for listener in listeners:
            listener.event(self.status)
            listener.frame()

    def restart(self) -> None:
        """Start a new process for a simulation whose process was ended (a reset of a faulted simulation). A
        simulation opened from a recording opens it again: its recorded scans are never lost, and are history only
        again (what ran after a "Continue from here" was in the process that ended)."""
        self.launch()
        with self._lock:
            watches = list(self._watches.items())
            listeners = list(self._listeners)
        for key, watch in watches:  # first: the recording's last scan is then shown with every watched value
            self.call("watch", key=key, **watch)
        recording = self._recording
        if recording is not None:
            try:
                self.command("open_recording", timeout=self.settings.build_timeout_s, **recording)
            except (CommandError, TimeoutError) as error:
                self._end_process()
                reason = error.message if isinstance(error, CommandError) else "it did not run in time"
                raise BuildFailed(f"the recording could not be opened again: {reason}") from None
        with self._lock:
            status = self.status
        self._record(
            Log(
                type="log",
                kind="system",
                level="info",
                message="started again in a new process: "
                + (
                    f"the recording of {recording['scans']} scans is open again, history only (what ran after "
                    "Continue from here is lost); forces and breakpoints are cleared"
                    if recording is not None
                    else "variables have their initial values, forces and breakpoints are cleared"
                ),
            )
        )
        for listener in listeners:
            listener.event(status)

    def open_recording(self, inputs: list[dict[str, Any]], scans: int, timeout: float) -> dict[str, Any]:
        """Run a recording's scans into this new simulation's history (``SimRunner.open_recording``); kept, so a
        ``restart`` after a crash opens it again. The simulation's ``info`` afterwards."""
        info = self.command("open_recording", timeout=timeout, inputs=inputs, scans=scans)
        self._recording = {"inputs": inputs, "scans": scans}
        return info

    @property
    def alive(self) -> bool:
        """The process runs the simulation (False: deleted, or ended and waiting for a reset)."""
        return self._alive

    @property
    def process(self) -> BaseProcess | None:
        return self._process

    def close(self) -> None:
        """End the simulation: its process, and every listener (told ``closed``)."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            self._alive = False
            waiting, self._requests.waiting = self._requests.waiting, {}
            listeners, self._listeners = self._listeners, []
        self._end_process()
        for future, _ in waiting.values():
            _answer(future, error=CommandError("bad_state", "the simulation has been deleted"))
        for listener in listeners:
            listener.closed()

    # ------------------------------------------------------------------ what the process reported

    def _on_frame(self, message: dict[str, Any]) -> None:
        with self._lock:
            old = self.frame
            if message["full"]:
                values = message["values"]
                power = message["power"]
            else:
                values = {**old.values, **message["values"]} if message["values"] else old.values
                power = old.power
                if message["power"]:
                    power = dict(power)
                    for instance, states in message["power"].items():
                        power[instance] = {**power.get(instance, {}), **states}
            forced = tuple(message["forced"]) if message["forced"] is not None else old.forced
            injected = message["injected"] if message.get("injected") is not None else old.injected
            self.frame = Frame(
                self._seq_base + message["seq"],
                message["scan"],
                message["time_ms"],
                message["wall"],
                values,
                power,
                forced,
                injected,
                message.get("history"),
            )
            self.info = message["info"]
            listeners = list(self._listeners)
        for owner, chunk in message["traces"].items():
            self.traces.add(owner, chunk)
        for listener in listeners:
            listener.frame()

    def _on_reply(self, message: dict[str, Any]) -> None:
        with self._lock:
            future, _ = self._requests.waiting.pop(message["id"], (None, 0.0))
        if future is None:
            return
        error = message.get("error")
        _answer(future, message, CommandError(error["code"], error["message"]) if error else None)

    def _record(self, entry: Log) -> None:
        """Keep a log entry and pass it on; the history and the listeners change together (see ``attach``)."""
        with self._lock:
            if len(self.history) == self.history.maxlen:
                self.dropped_log_entries += 1
            self.history.append(entry)
            listeners = list(self._listeners)
        for listener in listeners:
            listener.event(entry)

    def note(self, message: str, level: LogLevel = "info") -> None:
        """A ``system`` entry of the server's own in the log (e.g. why the simulation was stopped)."""
        self._record(Log(type="log", kind="system", level=level, message=message))

    # ------------------------------------------------------------------ listeners

    def attach(self, listener: Listener) -> tuple[Status, list[Log], int]:
        """Add a listener; returns the state, the log so far (oldest first) and how many older entries were
        dropped. Every later entry reaches the listener: none is both in the history and sent live, or in neither."""
        with self._lock:
            self._listeners.append(listener)
            return self.status, list(self.history), self.dropped_log_entries

    def detach(self, listener: Listener) -> None:
        with self._lock:
            if listener in self._listeners:
                self._listeners.remove(listener)

    # ------------------------------------------------------------------ requests

    def request(self, op: str, **args: Any) -> Future[dict[str, Any]]:
        """Send the command ``op``; the future gets the reply (``result``, and ``info``: the simulation's figures
        right after the command), or a ``CommandError``."""
        future: Future[dict[str, Any]] = Future()
        with self._lock:
            if not self._alive:
                future.set_exception(CommandError("bad_state", self._gone))
                return future
            request_id = next(self._requests.ids)
            self._requests.waiting[request_id] = (future, time.monotonic())
            connection = self._connection
        try:
            with self._send_lock:
                connection.send({"id": request_id, "op": op, "args": args})  # type: ignore[union-attr]  # alive: connected
        except (OSError, ValueError):
            with self._lock:
                self._requests.waiting.pop(request_id, None)
            if not future.done():
                future.set_exception(CommandError("bad_state", self._gone))
        return future

    def call(self, op: str, timeout: float | None = None, **args: Any) -> Any:
        """``request`` and wait for the result (``TimeoutError`` after ``timeout`` seconds)."""
        return self.request(op, **args).result(timeout)["result"]

    def command(self, op: str, timeout: float | None = None, **args: Any) -> dict[str, Any]:
        """``request`` and wait; the simulation's ``info`` right after the command (later frames may be newer)."""
        info: dict[str, Any] = self.request(op, **args).result(timeout)["info"]
        return info

    async def acall(self, op: str, **args: Any) -> Any:
        """``request`` from the event loop."""
        return (await asyncio.wrap_future(self.request(op, **args)))["result"]

    async def watch(self, key: int, paths: list[str], elements: list[tuple[str, list[str] | None]]) -> Watch:
        """Set client ``key``'s subscription; when this returns, ``frame`` holds its values."""
        request = {"paths": paths, "elements": elements}
        answer = await self.acall("watch", key=key, **request)
        with self._lock:
            self._watches[key] = request
        return Watch(
            {path: DisplayType.model_construct(**shown) for path, shown in answer["paths"].items()},
            tuple(None if e is None else (e[0], None if e[1] is None else tuple(e[1])) for e in answer["elements"]),
            tuple(answer["refused"]),
        )

    def unwatch(self, key: int) -> None:
        """Drop client ``key``'s subscription and trace (no answer awaited)."""
        with self._lock:
            self._watches.pop(key, None)
        self.traces.drop(key)
        self.request("unwatch", key=key)

    async def start_trace(self, key: int, **request: Any) -> None:
        self.traces.open(key)
        await self.acall("trace_start", owner=key, **request)

    def inputs(self) -> dict[str, Any]:
        """The input events the simulation applied (``SimRunner.inputs``), as ``--events`` lines."""
        inputs: dict[str, Any] = self.call("inputs", timeout=self.settings.build_timeout_s)
        return inputs

    def inspect(self, paths: Sequence[str] = (), probes: Sequence[str] = ()) -> dict[str, Any]:
        """The simulation's whole state (tests, diagnosis): see ``SimRunner.inspect``."""
        state: dict[str, Any] = self.call("inspect", paths=list(paths), probes=list(probes))
        return state

    def read(self, path: str) -> object:
        return self.inspect(paths=[path])["values"][path]


def _answer(future: Future[Any] | None, result: object = None, error: Exception | None = None) -> None:
    """Settle a request's future, unless its waiter gave up (a websocket client that left cancels it)."""
    if future is None or future.done():
        return
    if error is not None:
        future.set_exception(error)
    else:
        future.set_result(result)
