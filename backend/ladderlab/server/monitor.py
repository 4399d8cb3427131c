"""The online-mode websocket: each client's subscription, commands, and a sender that never backs up.

One ``MonitorClient`` per connection. Its receive loop parses messages
(``model/monitor.py``) and runs commands on the ``SimRunner`` in a worker thread
(a command may wait for a scan to finish; the event loop must not). Its sender task
is the only writer to the socket:

* values are sampled, not queued: every ``interval_ms`` it takes the runner's latest
  frame and sends what changed since its own previous message. A client that reads
  slowly makes its sender wait in ``send``, so it gets fewer messages, each complete;
  the scan thread and the other clients never wait for it;
* a running trace's new samples are taken from the runner at the same interval
  (``trace_data``), so they wait in the runner's trace book, never in the queue;
* status, log and error messages wait in a bounded queue; only the latest
  status is kept, and when the queue is full the oldest log entries are dropped and
  the client is told how many.

Bad input never closes the connection: it gets an ``error`` message.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import logging
import math
from collections import deque
from typing import Any

from fastapi import APIRouter, WebSocket
from pydantic import BaseModel, TypeAdapter, ValidationError
from starlette.websockets import WebSocketDisconnect

from ..ir import types as t
from ..model import monitor as m
from ..simulation.registry import SimulationEntry, SimulationSettings, UnknownSimulation
from ..simulation.runner import CommandError, Frame, SimRunner, Watch
from .context import registry_of
from .security import websocket_origin_allowed

log = logging.getLogger(__name__)

router = APIRouter(tags=["monitor"])

CLIENT_MESSAGE: TypeAdapter[Any] = TypeAdapter(m.ClientMessage)
_CLIENT_TYPES = ", ".join(sorted(CLIENT_MESSAGE.json_schema()["discriminator"]["mapping"]))
CLOSE_NO_SIMULATION = 4404
CLOSE_DELETED = 4410
CLOSE_TRY_LATER = 1013
_MISSING = object()


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


def _same(a: object, b: object) -> bool:
    """Equal values, NaN equal to NaN (a NaN that stays NaN has not changed)."""
    if a is b:
        return True
    if type(a) is not type(b):
        return False
    if a == b:
        return True
    return isinstance(a, float) and math.isnan(a) and math.isnan(b)  # type: ignore[arg-type]


class MonitorClient:
    def __init__(self, websocket: WebSocket, entry: SimulationEntry, settings: SimulationSettings) -> None:
        self.websocket = websocket
        self.entry = entry
        self.runner: SimRunner = entry.runner
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
        self.last_scan = -1
        # trace: its chunks are taken at the values interval while one runs
        self.tracing = False
        self.trace_due = 0.0

    # ------------------------------------------------------------------ runner listener (any thread)

    def event(self, message: m.Status | m.Log, target: object | None) -> None:
        if target is None or target is self:
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
        self._enqueue(m.Log(type="log", level="warning", message="the simulation was deleted"))
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

    def error(self, code: str, message: str) -> None:
        self._enqueue(m.Error(type="error", code=code, message=message))  # type: ignore[arg-type]

    async def serve(self) -> None:
        self.runner.add_listener(self)
        self._enqueue(self.runner.status())
        sender = asyncio.create_task(self._send_loop())
        try:
            await self._receive_loop(sender)
        finally:
            sender.cancel()
            self.runner.remove_listener(self)
            await asyncio.to_thread(self.runner.unwatch, self)

    async def _receive_loop(self, sender: asyncio.Task) -> None:
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

    async def _dispatch(self, request: BaseModel) -> None:
        runner = self.runner
        match request:
            case m.Subscribe():
                await self._subscribe(request)
            case m.Write(path=path, value=value):
                await asyncio.to_thread(runner.write, path, value)
            case m.Force(path=path, value=value):
                await asyncio.to_thread(runner.force, path, value)
            case m.Unforce(path=path):
                await asyncio.to_thread(runner.unforce, path)
            case m.UnforceAll():
                await asyncio.to_thread(runner.unforce_all)
            case m.BreakpointSet(pou=pou):
                await asyncio.to_thread(runner.set_breakpoint, pou, **_where(request))
            case m.BreakpointClear(pou=pou):
                await asyncio.to_thread(runner.clear_breakpoint, pou, **_where(request))
            case m.Continue():
                await asyncio.to_thread(runner.resume)
            case m.Step(granularity=granularity):
                await asyncio.to_thread(runner.step, granularity)
            case m.Run():
                await asyncio.to_thread(runner.start)
            case m.Stop():
                await asyncio.to_thread(runner.stop)
            case m.SingleCycle():
                await asyncio.to_thread(runner.single_cycle)
            case m.TraceStart(paths=paths, samples=samples, trigger=trigger, id=trace_id):
                await asyncio.to_thread(runner.start_trace, self, paths, samples, trigger, trace_id)
                self.tracing, self.trace_due = True, self.loop.time()  # the first chunk at once
                self.wake.set()
            case m.TraceStop():
                runner.stop_trace(self)
                self.trace_due = self.loop.time()
                self.wake.set()

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
        self.watch = await asyncio.to_thread(self.runner.watch, self, request.paths, elements)
        self.elements = [(e.pou_instance, e.pou_instance.strip().upper(), e.ids) for e in request.elements]
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
                    await self._send_values(self.runner.frame)
                if self.tracing and self.loop.time() >= self.trace_due:
                    await self._send_trace()
        except (WebSocketDisconnect, RuntimeError, OSError):
            return  # the client went away; the receive loop ends too

    async def _sleep(self) -> None:
        if self.outbox or self.status is not None or self.ending:
            return
        if self.waiting_frame and self.runner.frame.seq != self.sent_seq:
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
                await self._send(status)  # type: ignore[arg-type]

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
        chunk = self.runner.trace_chunk(self)
        if chunk is None:
            self.tracing = self.runner.traces.active(self)  # replaced or dropped meanwhile: nothing more
        else:
            await self._send(chunk)
            self.tracing = chunk.state != "done"
        self.trace_due = self.loop.time() + self.interval_s

    def values_message(self, frame: Frame) -> m.Values | None:
        """What changed for this client since its last message (everything after a subscribe); None: nothing."""
        full, changed, power = self.full, {}, {}
        last = self.last_values
        for path in self.watch.locations if self.watch is not None else ():
            value = frame.values.get(path)
            if full or not _same(last.get(path, _MISSING), value):
                changed[path] = last[path] = value
        for label, instance, ids in self.elements:
            view = frame.probes.get(instance)
            if view is None:
                continue
            for element in ids if ids is not None else sorted(view.values.keys() | view.executed):
                state = view.values.get(element) if element in view.executed else None
                key = f"{label}/{element}"
                if full or not _same(self.last_power.get(key, _MISSING), state):
                    power[key] = self.last_power[key] = state
        forced = list(frame.forced)
        if not (full or changed or power or forced != self.last_forced or frame.scan != self.last_scan):
            return None
        types = (
            {path: display_type(loc.type) for path, loc in self.watch.locations.items()}
            if full and self.watch is not None
            else {}
        )
        self.full, self.last_forced, self.last_scan = False, forced, frame.scan
        return m.Values.model_construct(
            type="values",
            scan=frame.scan,
            time_ms=frame.time_ms,
            changed=changed,
            forced=forced,
            power=power,
            types=types,
        )


def display_type(ty: t.IrType) -> m.DisplayType:
    """How a client shows a value of ``ty`` (IR types name themselves differently by kind)."""
    if isinstance(ty, t.Subrange):
        ty = ty.base
    if isinstance(ty, t.Enum):
        return m.DisplayType(name=ty.name, names={str(value): name for name, value in ty.values})
    if isinstance(ty, t.Array):
        return m.DisplayType(name="ARRAY")
    return m.DisplayType(name=ty.fb if isinstance(ty, t.FbInstance) else ty.name)


def _where(request: m.BreakpointSet | m.BreakpointClear) -> dict[str, object]:
    return {key: value for key in ("network", "element", "line") if (value := getattr(request, key)) is not None}


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
