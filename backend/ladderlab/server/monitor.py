"""The online-mode websocket: each client's subscription, commands, and a sender that never backs up.

One ``MonitorClient`` per connection to a simulation (``simulation/remote.py``: its process
runs the program). On connecting, a client gets the state, then the simulation's online log so far
(oldest first, as ``log`` messages), then everything live. Its receive loop parses messages
(``model/monitor.py``) and sends commands to the simulation's process, awaiting the reply (a
command may wait for a scan to finish; the event loop never does). Its sender task is the only
writer to the socket:

* values are sampled, not queued: every ``interval_ms`` it takes the simulation's latest
  frame and sends what changed since its own previous message. A client that reads
  slowly makes its sender wait in ``send``, so it gets fewer messages, each complete;
  the simulation and the other clients never wait for it;
* a running trace's new samples are taken at the same interval (``trace_data``), so they
  wait in the simulation's trace inbox, never in the queue;
* status, log and error messages wait in a bounded queue; only the latest
  status is kept, and when the queue is full the oldest log entries are dropped and
  the client is told how many.

Bad input never closes the connection: it gets an ``error`` message.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import json
import logging
from collections import deque
from concurrent.futures import Future
from typing import Any

from fastapi import APIRouter, WebSocket
from pydantic import BaseModel, TypeAdapter, ValidationError
from starlette.websockets import WebSocketDisconnect

from ..model import monitor as m
from ..simulation.commands import CommandError, changes
from ..simulation.registry import SimulationEntry, SimulationSettings, UnknownSimulation
from ..simulation.remote import Frame, SimulationHandle, Watch
from .context import registry_of
from .security import websocket_origin_allowed
from .simulations import late_message, seek_late

log = logging.getLogger(__name__)

router = APIRouter(tags=["monitor"])

CLIENT_MESSAGE: TypeAdapter[m.ClientMessage] = TypeAdapter(m.ClientMessage)
_CLIENT_TYPES = ", ".join(sorted(CLIENT_MESSAGE.json_schema()["discriminator"]["mapping"]))
CLOSE_NO_SIMULATION = 4404
CLOSE_DELETED = 4410
CLOSE_TRY_LATER = 1013
_KEYS = itertools.count(1)  # a client's key in its simulation (watches, traces)


@router.websocket("/api/simulations/{sim_id}/ws")
async def monitor(websocket: WebSocket, sim_id: str) -> None:
    registry = registry_of(websocket.app)
    if not websocket_origin_allowed(websocket):
        await websocket.close(code=1008, reason="origin not allowed")  # before accept: HTTP 403
        return
    await websocket.accept()
    try:
        entry = registry.get(sim_id)
    except UnknownSimulation as error:
        refusal = m.Error(type="error", code="bad_path", message=str(error))
        await websocket.send_text(refusal.model_dump_json())
        await websocket.close(code=CLOSE_NO_SIMULATION, reason="no such simulation")
        return
    if not registry.attach(entry):
        message = f"this simulation already has {registry.settings.max_clients} clients, the most allowed"
        await websocket.send_text(m.Error(type="error", code="too_many", message=message).model_dump_json())
        await websocket.close(code=CLOSE_TRY_LATER, reason="too many clients")
        return
    try:
        await MonitorClient(websocket, entry, registry.settings).serve()
    finally:
        registry.detach(entry)


class MonitorClient:
    def __init__(self, websocket: WebSocket, entry: SimulationEntry, settings: SimulationSettings) -> None:
        self.websocket = websocket
        self.entry = entry
        self.simulation: SimulationHandle = entry.handle
        self.key = next(_KEYS)
        self.settings = settings
        self.loop = asyncio.get_running_loop()
        self.wake = asyncio.Event()
        self.outbox: deque[BaseModel] = deque()
        self.status: m.Status | None = None
        self.dropped = 0
        self.ending = False
        # subscription
        self.watch: Watch | None = None
        self.elements: list[tuple[str, str, list[str] | None]] = []  # (label, canonical instance, ids)
        self.interval_s = 0.1
        self.next_due = 0.0
        self.full = True
        self.sent_seq = -1
        self.waiting_frame = False
        self.last_values: dict[str, object] = {}
        self.last_power: dict[str, object] = {}
        self.last_forced: list[str] = []
        self.last_injected: dict[str, str] = {}
        self.last_scan = -1
        self.last_history: dict[str, Any] | None = None
        # trace: its chunks are taken at the values interval while one runs
        self.tracing = False
        self.trace_due = 0.0

    # ------------------------------------------------------------------ simulation listener (any thread)

    def event(self, message: m.Status | m.Log) -> None:
        self.loop.call_soon_threadsafe(self._enqueue, message)

    def frame(self) -> None:
        # Most clients are waiting for their interval, not for a frame: wake only those that are
        # (no syscall per client per frame). A client that starts waiting just after this check
        # sees the new frame itself (``_sleep`` looks again), as the frame is set before the call.
        if self.waiting_frame:
            self.loop.call_soon_threadsafe(self._on_frame)

    def closed(self) -> None:
        self.loop.call_soon_threadsafe(self._on_closed)

    # ------------------------------------------------------------------ event loop side

    def _on_frame(self) -> None:
        if self.waiting_frame:
            self.wake.set()

    def _on_closed(self) -> None:
        self.ending = True
        self.wake.set()

    def _enqueue(self, message: BaseModel) -> None:
        if isinstance(message, m.Status):
            self.status = message  # only the latest state matters
        else:
            if len(self.outbox) >= self.settings.max_queued:
                oldest_log = next((x for x in self.outbox if isinstance(x, m.Log)), None)
                self.outbox.remove(oldest_log if oldest_log is not None else self.outbox[0])
                self.dropped += 1
            self.outbox.append(message)
        self.wake.set()

    def error(self, code: m.ErrorCode, message: str) -> None:
        self._enqueue(m.Error(type="error", code=code, message=message))

    async def serve(self) -> None:
        status, history, dropped = self.simulation.attach(self)
        try:
            await self._send(status)
            if dropped:
                await self._send(
                    m.Log(type="log", kind="system", level="info", message=f"{dropped} older log entries are not kept")
                )
            for entry in history:  # the log so far, then live entries (attach: none in both, none lost)
                await self._send(entry)
        except (WebSocketDisconnect, RuntimeError, OSError):
            self.simulation.detach(self)
            return
        sender = asyncio.create_task(self._send_loop())
        try:
            await self._receive_loop(sender)
        finally:
            sender.cancel()
            self.simulation.detach(self)
            self.simulation.unwatch(self.key)

    async def _receive_loop(self, sender: asyncio.Task[None]) -> None:
        while not sender.done():
            receiving = asyncio.ensure_future(self.websocket.receive())
            await asyncio.wait({receiving, sender}, return_when=asyncio.FIRST_COMPLETED)
            if not receiving.done():
                receiving.cancel()
                return
            try:
                message = receiving.result()
            except (WebSocketDisconnect, RuntimeError):
                return
            if message["type"] == "websocket.disconnect":
                return
            text = message.get("text")
            if text is None:
                self.error("bad_message", "binary frames are not understood: send JSON text")
                continue
            if len(text) > self.settings.max_message_bytes:
                self.error(
                    "too_large",
                    f"the message has {len(text)} characters, more than the limit of {self.settings.max_message_bytes}",
                )
                continue
            await self.handle(text)

    # ------------------------------------------------------------------ requests

    async def handle(self, text: str) -> None:
        try:
            data = json.loads(text)
        except (ValueError, RecursionError) as error:
            self.error("bad_json", f"the message is not JSON: {error}")
            return
        try:
            request = CLIENT_MESSAGE.validate_python(data)
        except ValidationError as error:
            self.error("bad_message", describe_invalid(data, error))
            return
        try:
            await self._dispatch(request)
        except CommandError as error:
            self.error(error.code, error.message)
        except Exception as error:
            log.exception("monitor request %s failed", type(request).__name__)
            self.error("bad_state", f"internal error: {type(error).__name__}: {error}")

    async def _dispatch(self, request: m.ClientMessage) -> None:
        simulation = self.simulation
        match request:
            case m.Subscribe():
                await self._subscribe(request)
            case m.TraceStart(paths=paths, samples=samples, trigger=trigger, id=trace_id):
                trigger_fields = trigger.model_dump() if trigger is not None else None
                await simulation.start_trace(
                    self.key, paths=paths, samples=samples, trigger=trigger_fields, trace_id=trace_id
                )
                self.tracing, self.trace_due = True, self.loop.time()  # the first chunk at once
                self.wake.set()
            case m.TraceStop():
                await simulation.acall("trace_stop", owner=self.key)
                self.trace_due = self.loop.time()
                self.wake.set()
            case m.Seek(scan=scan, branch=branch):
                await self._history(simulation.request("seek", scan=scan, branch=branch), seek_late(scan))
            case m.BreakpointSet(pou=pou) | m.BreakpointClear(pou=pou):
                await simulation.acall(request.type, pou=pou, **_where(request))
            case _:  # the other commands are the simulation's by the same name and fields
                await simulation.acall(request.type, **request.model_dump(exclude={"type"}))

    async def _history(self, request: Future[dict[str, Any]], late: tuple[str, str | None]) -> None:
        """Wait for a request to the scan history at most ``history_timeout_s``, as REST does (``_history_request``),
        then refuse it in the words of ``late``; the simulation's process goes on with it, and this client's next
        messages are read meanwhile."""
        timeout = self.settings.history_timeout_s
        answer = asyncio.wrap_future(request)
        answer.add_done_callback(lambda done: done.cancelled() or done.exception())  # a late failure: seen, dropped
        try:
            await asyncio.wait_for(asyncio.shield(answer), timeout)
        except TimeoutError:
            raise CommandError("bad_state", late_message(late, timeout)) from None

    async def _subscribe(self, request: m.Subscribe) -> None:
        limits = self.settings
        if len(request.paths) > limits.max_paths or len(request.elements) > limits.max_instances:
            raise CommandError(
                "too_many",
                f"a subscription may hold {limits.max_paths} paths and "
                f"{limits.max_instances} POU instances, not {len(request.paths)} "
                f"and {len(request.elements)}",
            )
        elements = [(e.pou_instance, e.ids) for e in request.elements]
        self.watch = await self.simulation.watch(self.key, request.paths, elements)
        for reason in self.watch.refused:  # the rest of the subscription stands
            self.error("bad_path", reason)
        self.elements = [
            (e.pou_instance, watched[0], None if watched[1] is None else list(watched[1]))
            for e, watched in zip(request.elements, self.watch.elements, strict=True)
            if watched is not None
        ]
        self.interval_s = request.interval_ms / 1000.0
        self.full, self.next_due = True, self.loop.time()
        self.last_values, self.last_power = {}, {}
        self.wake.set()

    # ------------------------------------------------------------------ sending

    async def _send_loop(self) -> None:
        try:
            while True:
                await self._sleep()
                await self._drain()
                if self.ending:
                    await self.websocket.close(code=CLOSE_DELETED, reason="simulation deleted")
                    return
                if self.watch is not None and self.loop.time() >= self.next_due:
                    await self._send_values(self.simulation.frame)
                if self.tracing and self.loop.time() >= self.trace_due:
                    await self._send_trace()
        except (WebSocketDisconnect, RuntimeError, OSError):
            return  # the client went away; the receive loop ends too

    async def _sleep(self) -> None:
        if self.outbox or self.status is not None or self.ending:
            return
        if self.waiting_frame and self.simulation.frame.seq != self.sent_seq:
            return
        dues = [self.next_due] if self.watch is not None and not self.waiting_frame else []
        if self.tracing:
            dues.append(self.trace_due)
        timeout = min(dues) - self.loop.time() if dues else None
        if timeout is not None and timeout <= 0:
            return
        self.wake.clear()
        with contextlib.suppress(TimeoutError):
            await asyncio.wait_for(self.wake.wait(), timeout)

    async def _drain(self) -> None:
        while self.outbox or self.status is not None:
            if self.dropped:
                count, self.dropped = self.dropped, 0
                await self._send(
                    m.Log(
                        type="log",
                        level="warning",
                        message=f"{count} messages were dropped: this connection did not keep up",
                    )
                )
            if self.outbox:
                await self._send(self.outbox.popleft())
            else:
                status, self.status = self.status, None
                await self._send(status)  # type: ignore[arg-type]  # the loop runs while outbox or status holds one

    async def _send(self, message: BaseModel) -> None:
        await self.websocket.send_text(message.model_dump_json())

    async def _send_values(self, frame: Frame) -> None:
        if frame.seq == self.sent_seq and not self.full:
            self.waiting_frame = True  # nothing new: wait for the runner's next frame
            return
        self.waiting_frame = False
        self.sent_seq = frame.seq
        message = self.values_message(frame)
        if message is not None:
            await self._send(message)
        self.next_due = self.loop.time() + self.interval_s

    async def _send_trace(self) -> None:
        chunk = self.simulation.traces.take(self.key)
        if chunk is None:
            self.tracing = self.simulation.traces.active(self.key)  # replaced or dropped meanwhile: nothing more
        else:
            await self._send(chunk)
            self.tracing = chunk.state != "done"
        self.trace_due = self.loop.time() + self.interval_s

    def values_message(self, frame: Frame) -> m.Values | None:
        """What changed for this client since its last message (everything after a subscribe); None: nothing."""
        full = self.full
        values = {path: frame.values.get(path) for path in (self.watch.paths if self.watch is not None else ())}
        states = {
            f"{label}/{element}": shown.get(element)
            for label, instance, ids in self.elements
            if (shown := frame.power.get(instance)) is not None
            for element in (ids if ids is not None else sorted(shown))
        }
        changed = values if full else changes(self.last_values, values)
        power = states if full else changes(self.last_power, states)
        self.last_values.update(changed)
        self.last_power.update(power)
        forced = list(frame.forced)
        injected = frame.injected
        news = forced != self.last_forced or injected != self.last_injected
        if not (full or changed or power or news or frame.scan != self.last_scan or frame.history != self.last_history):
            return None
        self.last_history = frame.history
        self.last_injected = injected
        types = dict(self.watch.paths) if full and self.watch is not None else {}
        self.full, self.last_forced, self.last_scan = False, forced, frame.scan
        return m.Values.model_construct(
            type="values",
            scan=frame.scan,
            time_ms=frame.time_ms,
            changed=changed,
            forced=forced,
            injected=injected,
            power=power,
            types=types,
            history=m.HistoryRange(**frame.history) if frame.history is not None else None,
        )


def _where(request: m.BreakpointSet | m.BreakpointClear) -> dict[str, object]:
    return {
        key: value for key in ("network", "element", "line", "body") if (value := getattr(request, key)) is not None
    }


def describe_invalid(data: object, error: ValidationError) -> str:
    """One line naming what is wrong with a client message, e.g. ``subscribe.interval_ms: ...``."""
    kind = data.get("type") if isinstance(data, dict) else None
    problems = []
    for err in error.errors()[:3]:
        if err["type"] == "union_tag_invalid":
            problems.append(f"unknown message type {kind!r} (expected one of {_CLIENT_TYPES})")
        elif err["type"] == "union_tag_not_found":
            problems.append("a message needs a 'type' field")
        elif err["type"] in ("model_attributes_type", "model_type", "dict_type") and not err["loc"]:
            problems.append(f"a message must be a JSON object, not {type(data).__name__}")
        else:
            where = ".".join(str(part) for part in err["loc"])
            problems.append(f"{where}: {err['msg']}" if where else err["msg"])
    return "; ".join(problems)
