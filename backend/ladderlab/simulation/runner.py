"""The thread that runs one simulation in real time; the only way anything touches it.

A ``Simulation`` is a synchronous object for one thread at a time. ``SimRunner``
owns it: a scan thread paces scans against the wall clock (``engine.tasks.Pacer``)
while it is running, and every command (write, force, breakpoint, step, reset...)
takes the same lock, so commands from the server's worker threads never interleave
with a scan. A scan that takes long (up to its watchdog) holds the lock; callers on
the event loop therefore run commands in a worker thread, never on the loop.

Readers never take the lock: after scans the scan thread publishes an immutable
``Frame`` (the values of everything any client watches, the probes of the watched
POU instances, the forced paths) at most every ``publish_s`` seconds, and at once
after a command. Each websocket client diffs the latest frame against what it sent
last, so the cost of a scan does not grow with the number of clients.

The simulation runs the monitor variant (probes, no pause points) and switches to
the debug variant only while a breakpoint is set or a scan is halted (a step),
between scans, keeping all state (``Simulation.use_variant``; ``_fit_variant``).

Listeners hear about state changes, log entries (faults, forces) and new frames,
from whichever thread made them: they must only hand them over (e.g.
``loop.call_soon_threadsafe``). Traces are sampled after every scan into
``self.traces`` (``trace.py``), which clients read in chunks without the lock.
"""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from ..engine.codegen.faults import Fault
from ..engine.compile import CompileError
from ..engine.debug import Halt
from ..engine.paths import Location, UnknownPath
from ..engine.simulation import ProbeView, Simulation
from ..engine.tasks import Pacer
from ..ir import nodes as ir
from ..ir import types as t
from ..model.monitor import At, Log, Status, TraceData, TraceTrigger
from .trace import TraceBook, TraceRefused, plan_trace

log = logging.getLogger(__name__)

State = str  # "running" | "stopped" | "halted" | "faulted"


class CommandError(Exception):
    """A command the simulation refuses; ``code`` is an ``Error`` message code (bad_path, bad_value, bad_state)."""

    def __init__(self, code: str, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message


@dataclass(frozen=True)
class Frame:
    """Values published after a scan or a command: ``seq`` grows with every publication."""

    seq: int
    scan: int
    time_ms: float
    values: dict[str, object]  # canonical path -> value
    probes: dict[str, ProbeView]  # canonical instance path (upper case) -> its probes
    forced: tuple[str, ...]


EMPTY_FRAME = Frame(0, 0, 0.0, {}, {}, ())


@dataclass(frozen=True)
class Watch:
    """One client's resolved subscription: variables by canonical path, POU instances to probe."""

    locations: dict[str, Location]
    instances: tuple[str, ...] = ()  # canonical (upper-case) instance paths


class Listener(Protocol):
    def event(self, message: Status | Log, target: object | None) -> None:
        """A message for every client (``target`` None) or for the client that asked for it."""

    def frame(self) -> None:
        """A new frame was published."""

    def closed(self) -> None:
        """The simulation was deleted: nothing more will come."""


def at_halt(halt: Halt) -> At:
    origin = halt.origin
    return At(
        pou=origin.pou,
        instance=halt.instance,
        network=origin.network,
        element=halt.point.element or origin.element,
        line=origin.line,
        column=origin.column,
    )


def at_origin(origin: ir.Origin | None, pou: str | None, instance: str | None) -> At | None:
    if origin is None:
        return At(pou=pou, instance=instance) if pou else None
    return At(
        pou=origin.pou,
        instance=instance,
        network=origin.network,
        element=origin.element,
        line=origin.line,
        column=origin.column,
    )


class SimRunner:
    """Runs ``sim`` (monitor variant, debug while debugging; or any variant it was built with) in its own thread."""

    def __init__(
        self,
        sim: Simulation,
        *,
        speed: float = 1.0,
        publish_s: float = 0.02,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.sim = sim
        self.lock = threading.RLock()
        self.speed = speed
        self.publish_s = publish_s
        self.clock = clock
        self.frame: Frame = EMPTY_FRAME
        self._overruns = 0  # pacer skips of finished runs
        self.after_scan: list[Callable[[Simulation], None]] = []  # called in the scan's thread, lock held
        self._ctx = sim.compiled.generated.context
        self._listeners: list[Listener] = []
        self._watches: dict[object, Watch] = {}
        self._reader = sim.reader({})
        self._instances: tuple[str, ...] = ()
        self.traces = TraceBook()
        self._running = False
        self._faulted = False
        self._seen_faults = 0
        self._seen_scans = sim.scan_count
        self._pacer: Pacer | None = None
        self._real_s = 0.0
        self._run_since: float | None = None
        self._last_publish = float("-inf")
        self._status: tuple[State, At | None] = (self._state(), None)
        self._wake = threading.Condition(self.lock)
        self._woken = False
        self._closed = False
        self._thread = threading.Thread(target=self._loop, name="ladderlab-sim", daemon=True)
        self._thread.start()

    # ------------------------------------------------------------------ listeners

    def add_listener(self, listener: Listener) -> None:
        with self.lock:
            self._listeners.append(listener)

    def remove_listener(self, listener: Listener) -> None:
        with self.lock:
            if listener in self._listeners:
                self._listeners.remove(listener)

    def _emit(self, message: Status | Log, target: object | None = None) -> None:
        for listener in list(self._listeners):
            listener.event(message, target)

    # ------------------------------------------------------------------ state

    def _state(self) -> State:
        if self.sim.halted is not None:
            return "halted"
        if self._faulted:
            return "faulted"
        return "running" if self._running else "stopped"

    @property
    def state(self) -> State:
        with self.lock:
            return self._state()

    def status(self) -> Status:
        with self.lock:
            state, at = self._status
            return Status(type="status", state=state, at=at)  # type: ignore[arg-type]

    @property
    def overruns(self) -> int:
        """Times the scans fell more than the pacer's lag behind the wall clock and skipped ahead."""
        with self.lock:
            return self._overruns + (self._pacer.overruns if self._pacer is not None else 0)

    def real_time_ms(self) -> float:
        with self.lock:
            running = self.clock() - self._run_since if self._run_since is not None else 0.0
            return (self._real_s + running) * 1000.0

    # ------------------------------------------------------------------ the scan thread

    def _loop(self) -> None:
        with self.lock:
            while not self._closed:
                delay: float | None = None
                if self._running and self._pacer is not None:  # halted: the pacer idles and re-anchors after
                    try:
                        delay = self._pacer.poll()
                    except Exception as error:
                        log.exception("simulation thread failed")
                        self._set_running(False)
                        self._emit(
                            Log(type="log", level="error", message=f"internal error, simulation stopped: {error!r}")
                        )
                    self._settle()
                if not self._woken:
                    self._wake.wait(delay)
                self._woken = False

    def _poke(self) -> None:
        """Wake the scan thread (lock held): the state or the schedule changed."""
        self._woken = True
        self._wake.notify()

    def close(self) -> None:
        """End the scan thread and tell the listeners; every later command is refused."""
        with self.lock:
            if self._closed:
                return
            self._closed = True
            self._set_running(False)
            self._poke()
            listeners, self._listeners = self._listeners, []
        for listener in listeners:
            listener.closed()
        if threading.current_thread() is not self._thread:
            self._thread.join(timeout=5)

    # ------------------------------------------------------------------ after every step of the engine

    def _settle(self, publish: bool = False) -> None:
        """Account for what the engine did since the last call (lock held): scans, faults, halts, state."""
        sim = self.sim
        self._fit_variant()
        if sim.scan_count != self._seen_scans:
            self._seen_scans = sim.scan_count
            self.traces.sample(sim)
            for hook in self.after_scan:
                hook(sim)
        if len(sim.faults) > self._seen_faults:
            for fault in sim.faults[self._seen_faults :]:
                self._emit(self._fault_log(fault))
            self._seen_faults = len(sim.faults)
            self._faulted = True
            self._set_running(False)
        state = self._state()
        status = (state, at_halt(sim.halted) if sim.halted is not None else None)
        now = self.clock()
        # A new state (above all a halt) is published with the values of that moment, so a client
        # shows the values at the halt point at once, not those of the last periodic frame.
        if publish or status != self._status or now - self._last_publish >= self.publish_s:
            self._publish(now)
        if status != self._status:
            self._status = status
            self._emit(Status(type="status", state=state, at=status[1]))  # type: ignore[arg-type]

    def _fit_variant(self) -> None:
        """Debug code only while debugging: a breakpoint is set or a scan is halted; else the monitor code.

        Called with the lock held."""
        sim = self.sim
        if sim.variant not in ("monitor", "debug"):
            return
        debugging = sim.halted is not None or (sim.debugger is not None and bool(sim.debugger.breakpoints))
        if debugging != (sim.variant == "debug"):
            sim.use_variant("debug" if debugging else "monitor")

    def _needs_debug(self) -> None:
        """Switch to the debug variant before a breakpoint or step command (compiled on first use; lock held)."""
        if self.sim.variant == "monitor":
            try:
                self.sim.use_variant("debug")
            except CompileError as error:
                raise CommandError("bad_state", f"cannot debug this program: {error}") from None

    def _fault_log(self, fault: Fault) -> Log:
        return Log(
            type="log",
            kind="watchdog" if fault.kind == "watchdog" else "fault",
            level="error",
            message=fault.text(),
            at=at_origin(fault.origin, fault.pou, fault.instance),
            scan=fault.scan,
            time_ms=fault.time_ms,
        )

    def _publish(self, now: float) -> None:
        self._last_publish = now
        values = self._reader.read()
        probes = {}
        for instance in self._instances:
            try:
                probes[instance] = self.sim.probes(instance)
            except KeyError:
                probes[instance] = ProbeView({}, frozenset())
        self.frame = Frame(
            self.frame.seq + 1, self.sim.scan_count, self.sim.time_ms, values, probes, tuple(self.sim.forced)
        )
        for listener in list(self._listeners):
            listener.frame()

    def _set_running(self, running: bool) -> None:
        now = self.clock()
        if running and not self._running:
            self._run_since = now
            self._pacer = Pacer(_Scans(self), speed=self.speed, clock=self.clock)
        elif not running and self._running:
            self._real_s += now - (self._run_since or now)
            self._run_since = None
            if self._pacer is not None:
                self._overruns += self._pacer.overruns
            self._pacer = None
        self._running = running

    def _command(self, action: Callable[[], object]) -> object:
        """Run ``action`` on the engine under the lock, then publish and report what changed."""
        with self.lock:
            self._check_open()
            try:
                return action()
            finally:
                self._settle(publish=True)
                self._poke()

    def _check_open(self) -> None:
        if self._closed:
            raise CommandError("bad_state", "the simulation has been deleted")

    # ------------------------------------------------------------------ run control

    def start(self) -> None:
        def action() -> None:
            if self._faulted:
                raise CommandError("bad_state", "the simulation stopped on a fault: reset it before running")
            self._set_running(True)
            if self.sim.halted is not None:
                self.sim.resume()

        self._command(action)

    def stop(self) -> None:
        def action() -> None:
            if self._running and self.sim.halted is not None:  # the state stays "halted": say what Stop did
                self._emit(
                    Log(
                        type="log",
                        kind="state",
                        level="info",
                        scan=self.sim.scan_count,
                        time_ms=self.sim.time_ms,
                        message="stopped: the scan stays halted; Continue or a step finishes it, "
                        "then no further scan runs",
                    )
                )
            self._set_running(False)

        self._command(action)

    def reset(self, cold: bool = False) -> None:
        """Warm or cold restart: stops, ends a halted scan, clears the faults (forces stay)."""

        def action() -> None:
            self._set_running(False)
            self.sim.reset(cold=cold)
            self._faulted = False
            self._seen_faults = 0

        self._command(action)

    def single_cycle(self) -> None:
        """One scan of a stopped simulation; when halted, the rest of the current scan."""

        def action() -> None:
            if self.sim.halted is not None:
                self.sim.resume()
                return
            if self._running:
                raise CommandError("bad_state", "the simulation is running: stop it before a single cycle")
            if self._faulted:
                raise CommandError("bad_state", "the simulation stopped on a fault: reset it first")
            self.sim.cycle(1)

        self._command(action)

    def resume(self) -> None:
        def action() -> None:
            if self.sim.halted is None:
                raise CommandError("bad_state", "the simulation is not halted")
            self.sim.resume()

        self._command(action)

    def step(self, granularity: str) -> None:
        """Halted: continue to the next pause point of this granularity. Else halt in the next scan."""

        def action() -> None:
            if self._faulted and self.sim.halted is None:
                raise CommandError("bad_state", "the simulation stopped on a fault: reset it first")
            self._needs_debug()
            self.sim.step(granularity)

        self._command(action)

    def set_breakpoint(self, pou: str, **where: object) -> None:
        self._command(lambda: self._debug("set_breakpoint", pou, **where))

    def clear_breakpoint(self, pou: str | None = None, **where: object) -> None:
        if pou is None:
            self._command(lambda: self.sim.debugger is not None and self.sim.clear_breakpoints())
        else:
            self._command(lambda: self._debug("clear_breakpoint", pou, **where))

    def _debug(self, method: str, pou: str, **where: object) -> object:
        self._needs_debug()
        try:
            return getattr(self.sim, method)(pou, **where)
        except ValueError as error:
            raise CommandError("bad_path", str(error)) from None

    # ------------------------------------------------------------------ variables

    def location(self, path: str) -> Location:
        """Resolve a path (no lock: the resolver only reads the compiled program)."""
        try:
            return self.sim.location(path)
        except (UnknownPath, ValueError) as error:
            raise CommandError("bad_path", str(error)) from None

    def write(self, path: str, value: object) -> None:
        self.location(path)
        self._command(lambda: self._coerced(self.sim.write, path, value))

    def force(self, path: str, value: object) -> None:
        location = self.location(path)

        def action() -> None:
            self._coerced(self.sim.force, path, value)
            self._emit(
                Log(
                    type="log",
                    kind="force",
                    level="info",
                    message=f"forced {location.path} := {_text(self.sim.read(path))}",
                    scan=self.sim.scan_count,
                    time_ms=self.sim.time_ms,
                )
            )

        self._command(action)

    def unforce(self, path: str) -> None:
        location = self.location(path)

        def action() -> None:
            if location.path not in self.sim.forced:
                raise CommandError("bad_path", f"{location.path} is not forced")
            self.sim.unforce(path)
            self._emit(
                Log(
                    type="log",
                    kind="release",
                    level="info",
                    message=f"released the force on {location.path}",
                    scan=self.sim.scan_count,
                    time_ms=self.sim.time_ms,
                )
            )

        self._command(action)

    def unforce_all(self) -> None:
        def action() -> None:
            count = len(self.sim.forced)
            self.sim.unforce_all()
            if count:
                self._emit(
                    Log(
                        type="log",
                        kind="release",
                        level="info",
                        message=f"released all forces ({count})",
                        scan=self.sim.scan_count,
                        time_ms=self.sim.time_ms,
                    )
                )

        self._command(action)

    @staticmethod
    def _coerced(method: Callable[[str, object], None], path: str, value: object) -> None:
        try:
            method(path, value)
        except ValueError as error:
            raise CommandError("bad_value", str(error)) from None

    # ------------------------------------------------------------------ watching

    def watch(self, key: object, paths: list[str], elements: list[tuple[str, list[str] | None]]) -> Watch:
        """Set ``key``'s subscription (replacing its previous one); the next frame carries its values.

        ``elements``: (POU instance, element ids or None for all) whose probes to publish."""
        locations = {}
        for path in paths:
            location = self.location(path)
            locations.setdefault(location.path, location)
        canonical = []
        for instance, ids in elements:
            with self.lock:
                try:
                    self.sim.probes(instance)
                except KeyError as error:
                    raise CommandError("bad_path", str(error.args[0])) from None
            self._check_elements(instance, ids or [])
            canonical.append(instance.strip().upper())
        watch = Watch(locations, tuple(dict.fromkeys(canonical)))

        def action() -> None:
            self._watches[key] = watch
            self._rebuild_union()

        self._command(action)
        return watch

    def _check_elements(self, instance: str, ids: list[str]) -> None:
        """Every id must be a probed element (or pin, ``box.Q``) of the instance's POU."""
        pou = self._pou_of(instance)
        known = set(self._ctx.probes_of(pou).elements)
        unknown = [element for element in ids if element not in known]
        if unknown:
            listed = ", ".join(sorted(known)[:30]) or "none: it is not a ladder or FBD POU"
            raise CommandError("bad_path", f"{instance} ({pou}) has no element {unknown[0]!r} (elements: {listed})")

    def _pou_of(self, instance: str) -> str:
        name = instance.strip().upper()
        pou = self._ctx.pous.get(name)
        if pou is not None and pou.kind in ("program", "function"):
            return pou.name
        location = self.location(instance)
        if isinstance(location.type, t.FbInstance):
            return location.type.fb
        raise CommandError("bad_path", f"{location.path} is not a POU instance")

    def unwatch(self, key: object) -> None:
        with self.lock:
            if self._watches.pop(key, None) is not None:
                self._rebuild_union()
        self.traces.drop(key)

    def _rebuild_union(self) -> None:
        union = {path: loc for watch in self._watches.values() for path, loc in watch.locations.items()}
        self._reader = self.sim.reader(union)
        self._instances = tuple(dict.fromkeys(i for watch in self._watches.values() for i in watch.instances))

    # ------------------------------------------------------------------ traces

    def start_trace(
        self,
        owner: object,
        paths: list[str],
        samples: int | None = None,
        trigger: TraceTrigger | None = None,
        trace_id: int = 0,
    ) -> None:
        """Record ``paths`` after every scan for ``owner`` (replacing its running trace); see ``trace.py``."""
        try:
            plan = plan_trace(self.location, paths, trigger)
        except TraceRefused as error:
            raise CommandError("bad_path", str(error)) from None
        self._command(lambda: self.traces.start(owner, trace_id, plan, samples, self.sim))

    def stop_trace(self, owner: object) -> None:
        if not self.traces.stop(owner):
            raise CommandError("bad_state", "no trace is running: start one with trace_start")

    def trace_chunk(self, owner: object) -> TraceData | None:
        """``owner``'s samples since its previous chunk (no runner lock: a scan may be running)."""
        return self.traces.take(owner)


def _text(value: object) -> str:
    """A value as the log shows it: BOOLs as TRUE/FALSE like IEC literals."""
    return ("TRUE" if value else "FALSE") if isinstance(value, bool) else repr(value)


class _Scans:
    """What the pacer drives: one scan at a time, accounted for at once, until the runner stops."""

    def __init__(self, runner: SimRunner) -> None:
        self.runner = runner
        self.sim = runner.sim

    @property
    def halted(self) -> bool:
        return self.sim.halted is not None or not self.runner._running

    @property
    def time_ms(self) -> float:
        return self.sim.time_ms

    def next_scan_time(self) -> float:
        return self.sim.next_scan_time()

    def cycle(self, n: int = 1) -> int:
        done = self.sim.cycle(n)
        self.runner._settle()
        return done
