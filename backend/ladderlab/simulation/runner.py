"""One simulation's engine thread: scans paced on the wall clock, commands between two scans.

A ``Simulation`` is a synchronous object for one thread. ``SimRunner.serve`` is that thread's
loop (in a simulation's worker process, ``worker.py``): it runs the scans that are due
(``engine.tasks.Pacer``) and, between two scans, the commands other threads ``submit`` (run,
stop, write, force, breakpoints, steps, watches, traces...), in the order they came, each
answered through its own callback. Nothing else touches the simulation, so it needs no lock,
and the watchdog's clock (the thread's CPU time) measures this thread alone.

What the runner has to say goes to a ``Sink``:

* ``status``: the state (running, stopped, halted with where, faulted) whenever it changes;
* ``log``: entries of the online log (ON-15): run/stop/reset/single cycle, writes, forces,
  releases, panel events and injected faults (as they apply, with their scan), breakpoint hits,
  watchdog trips and runtime errors, with kind, scan and virtual time;
* ``frame``: after scans at most every ``publish_s``, and at once after a command or a change of
  state (so a halt shows the values of the halt point): what changed since the previous frame in
  the values and element states that some client watches, the forced paths, the trace samples
  recorded since, and the figures of ``info``. Only the watched paths and the watched elements
  (the networks a client has in view) are read, never a whole POU (``Simulation.probes``), and only the
  networks some client views record their power flow at all (``Simulation.view``; ``_view_networks``).

Every message is plain data (dicts, lists, strings, numbers), so it can cross a process
boundary or a network (docs/architecture.md, "Online mode").

Every input goes to the engine as an ``InputEvent`` (``engine/inputs.py``); the runner keeps the
last ``journal_size`` applied ones (``inputs``: the lines ``ladderlab run --events`` replays).
Time runs at ``speed`` times real time (0.1 to 100; the virtual clock is the same at any speed),
and ``run_until`` runs until a condition holds after a scan (``conditions.py``) or a virtual time.

The simulation runs the monitor variant and switches to the debug variant only while a
breakpoint is set or a scan is halted (a step), between scans, keeping all state
(``Simulation.use_variant``; ``_fit_variant``).
"""

from __future__ import annotations

import contextlib
import logging
import random
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar, Protocol, cast

from ..engine import call_stack as engine_stack
from ..engine.codegen.faults import Fault
from ..engine.compile import CompiledProgram, CompileError, compile_program
from ..engine.debug import Halt
from ..engine.inputs import AppliedInput, InputEvent, InputRefused
from ..engine.paths import Location, UnknownPath
from ..engine.simulation import ProbeView, Simulation
from ..engine.tasks import Pacer
from ..ir import nodes as ir
from ..ir import types as t
from ..ir.lower_sfc import CONDITION_PROBE
from ..model.monitor import (
    MAX_SPEED,
    MIN_SPEED,
    At,
    CallFrame,
    DisplayType,
    Log,
    LogKind,
    LogLevel,
    StackVariable,
    TraceTrigger,
    Value,
)
from .commands import CommandError, changes
from .conditions import BadCondition, Condition, parse_condition
from .events import events_text, parse_events, scan_inputs
from .history import History, HistoryUnavailable
from .trace import TraceBook, TraceRefused, plan_trace

log = logging.getLogger(__name__)


class Sink(Protocol):
    """Where a runner's messages go (plain data; called on the engine thread)."""

    def status(self, state: str, at: dict[str, Any] | None, stack: list[dict[str, Any]]) -> None: ...

    def log(self, entry: dict[str, Any]) -> None: ...

    def frame(self, frame: dict[str, Any]) -> None: ...


#: How a submitted command is answered: (result, None) or (None, the refusal).
Reply = Callable[[object, CommandError | None], None]


def _at(origin: ir.Origin, instance: str | None, element: str | None) -> At:
    return At(
        pou=origin.pou,
        instance=instance,
        network=origin.network,
        element=element,
        line=origin.line,
        column=origin.column,
        body=origin.body,
    )


def at_halt(halt: Halt) -> At:
    return _at(halt.origin, halt.instance, halt.point.element or halt.origin.element)


def at_origin(origin: ir.Origin | None, pou: str | None, instance: str | None) -> At | None:
    if origin is None:
        return At(pou=pou, instance=instance) if pou else None
    return _at(origin, instance, origin.element)


def read_call_stack(sim: Simulation) -> list[CallFrame]:
    """The call stack of ``sim``'s halted scan (the live one, or a step through a past scan). A bug here must not
    end the engine thread: the halt is then shown without its stack, and the log says why."""
    try:
        return [call_frame(frame) for frame in sim.call_stack()]
    except Exception:
        log.exception("reading the call stack failed")
        return []


def call_frame(frame: engine_stack.CallFrame) -> CallFrame:
    """A call of the halted scan as the status message carries it: its values shown as every online value is."""
    return CallFrame(
        kind=frame.kind,
        at=_at(frame.origin, frame.instance, frame.element),
        variables=[
            StackVariable(
                name=v.name, kind=v.kind, type=display_type(v.type), value=cast("Value", v.value), reason=v.reason
            )
            for v in frame.variables  # (values are plain data: paths.plain)
        ],
    )


def display_type(ty: t.IrType) -> DisplayType:
    """How a client shows a value of ``ty`` (IR types name themselves differently by kind)."""
    if isinstance(ty, t.Subrange):
        ty = ty.base
    if isinstance(ty, t.Enum):
        return DisplayType(name=ty.name, names={str(value): name for name, value in ty.values})
    if isinstance(ty, t.Array):
        return DisplayType(name="ARRAY")
    if isinstance(ty, t.Reference):  # it has no name of its own (ty.name raised AttributeError)
        return DisplayType(name="REF_TO")
    return DisplayType(name=ty.fb if isinstance(ty, t.FbInstance) else ty.name)


def value_text(value: object) -> str:
    """A value as the log shows it: BOOLs as TRUE/FALSE like IEC literals."""
    return ("TRUE" if value else "FALSE") if isinstance(value, bool) else repr(value)


@dataclass(frozen=True)
class _Watch:
    """One client's subscription: variables by canonical path; POU instances with the elements watched."""

    locations: dict[str, Location]
    elements: tuple[tuple[str, tuple[str, ...] | None], ...]  # (canonical instance, ids; None: every element)


class SimRunner:
    """Runs ``sim`` (monitor variant, debug while debugging; or any variant it was built with) on ``serve``'s thread."""

    def __init__(
        self,
        sim: Simulation,
        sink: Sink,
        *,
        speed: float = 1.0,
        publish_s: float = 0.02,
        clock: Callable[[], float] = time.monotonic,
        journal_size: int = 100_000,
        history_bytes: int = 0,
    ) -> None:
        self.sim = sim
        self.sink = sink
        self.speed = speed
        self.publish_s = publish_s
        self.clock = clock
        self.traces = TraceBook()
        #: the watched (traced) 'call' properties whose GET faulted at the last frame (sample)
        self._faulting_watched: set[str] = set()
        self._faulting_traced: set[str] = set()
        self._seen_accessor_faults = 0
        self._ctx = sim.compiled.generated.context
        self._cv = threading.Condition()
        self._commands: deque[tuple[str, dict[str, Any], Reply]] = deque()
        self._running = False
        self._to_transition = False  # a "transition" step runs scans until an SFC transition fires
        self._run_after_transition = False  # it was asked for from a halt of a running simulation: keep running
        self._faulted = False
        self._seen_faults = 0
        self._seen_scans = sim.scan_count
        self._pacer: Pacer | None = None
        self._delay: float | None = None
        self._overruns = 0  # pacer skips of finished runs
        self._real_s = 0.0
        self._run_since: float | None = None
        self._last_publish = float("-inf")
        self._status: tuple[str, At | None, list[CallFrame]] = (self._state(), None, [])
        self._halt_seen: Halt | None = None  # the halt ``_status`` is about (a new one is logged, its stack read)
        self._fault_report: tuple[Fault | None, dict[str, Any] | None] = (None, None)
        # watches: each client's, and their union (what a frame reads)
        self._watches: dict[object, _Watch] = {}
        self._reader = sim.reader({})
        self._union: dict[str, tuple[bool, tuple[str, ...]]] = {}  # instance -> (every element?, ids)
        self._full = True  # the next frame holds every watched value (the union changed)
        self._sent_values: dict[str, object] = {}
        self._sent_power: dict[str, dict[str, object]] = {}
        self._sent_forced: list[str] | None = None
        self._sent_injected: dict[str, str] | None = None
        self._seq = 0
        # inputs: the journal of applied ones; run until
        self.journal: deque[AppliedInput] = deque(maxlen=journal_size)
        self.journal_dropped = 0
        sim.on_input = self._applied
        # scan history (history.py): the replayed scan shown instead of the live one, while viewing
        self.history = History(sim, budget_bytes=history_bytes) if history_bytes else None
        self._budget_bytes = history_bytes  # shared by every branch of the history
        self.branches: list[History] = []  # earlier branches of the history, oldest first (fork)
        self._view_history: History | None = None  # the history the scan shown comes from
        self._view: Simulation | None = None
        self._viewing: int | None = None  # the scan shown, numbered as frames number them (scans completed)
        #: the steps taken through the scan shown (history_step), by granularity; while any, the view is their stepper
        self._steps: list[str] = []
        self._step_point_of: tuple[Halt, dict[str, Any]] | None = None  # the halt of a step and what frames say of it
        self._debug_program: CompiledProgram | None = None  # what a step through a past scan runs (compiled once)
        self._union_locations: dict[str, Location] = {}
        self._view_reader = self._reader
        self._until: Condition | None = None
        self._until_ms: float | None = None
        self._recording_only = False  # an opened recording: history only until a fork (open_recording)
        #: the history's replays of the last scan, by instance, for networks viewed since it (``_replayed``)
        self._replayed_views: tuple[tuple[History | None, int], dict[str, ProbeView]] = ((None, -1), {})
        self._view_networks()  # nobody watches yet: no network records its power flow

    # ------------------------------------------------------------------ other threads

    def submit(self, op: str, args: dict[str, Any], reply: Reply) -> None:
        """Run the command ``op`` between two scans; ``reply`` gets its result (on the engine thread)."""
        with self._cv:
            self._commands.append((op, args, reply))
            self._cv.notify()

    # ------------------------------------------------------------------ the engine thread

    def serve(self) -> None:
        """Scan and run commands, for the life of the process (it ends when the server goes or ends it)."""
        self._settle(publish=True)
        while True:
            with self._cv:
                if not self._commands or self._holding():
                    self._cv.wait(self._delay if self._running else None)
            self.turn()

    def turn(self) -> None:
        """One turn of ``serve``'s loop after its wait: the commands that came (unless they wait for the next
        scan: ``_holding``), then the scans that are due."""
        with self._cv:
            if self._holding():  # the scan that runs next is recorded, and then the commands run
                commands: deque[tuple[str, dict[str, Any], Reply]] = deque()
            else:
                commands, self._commands = self._commands, deque()
        for op, args, reply in commands:
            self._execute(op, args, reply)
        if self._running and self._pacer is not None:  # halted: the pacer idles and re-anchors after
            try:
                self._delay = self._pacer.poll()
            except Exception as error:
                log.exception("simulation thread failed")
                self._set_running(False)
                self._log("system", "error", f"internal error, simulation stopped: {error!r}")
            self._settle()

    def _holding(self) -> bool:
        """Whether commands wait for the next scan: the simulation runs and its last scan recorded no network's
        power flow (``_records_next``), so the frame a command publishes could not show it. The next scan is less
        than ``publish_s`` away (else that one would have recorded), and records (commands wait)."""
        return self._running and self.sim.quiet and self.sim.halted is None

    def _records_next(self) -> bool:
        """Whether the scan the pacer runs next records the power flow of the viewed networks: only a scan a frame
        may show does (docs/runtime.md, "Scans no frame shows"). A frame goes out after a scan when one is due
        (``publish_s`` after the last: it is due before the scan, or the scan records nothing and the next one,
        less than ``publish_s`` away, shows it), and after a command (commands waiting record the next scan, and
        while the last one recorded nothing they wait for the next: ``_holding``). So a scan records when a frame
        is due, when commands wait, or when the scan after it is ``publish_s`` away or more. Every scan records
        while a run until is set (its condition stops the run after any scan), of a program that checks the
        watchdog (a trip's moment depends on the machine's speed: that scan could not be recomputed), or without
        a history (which recomputes the power flow of a scan that ended with a runtime error: ``History.seek``)."""
        pacer, sim = self._pacer, self.sim
        if pacer is None or self.history is None or self._commands or sim.variant != "monitor":
            return True
        if self._until is not None or self._until_ms is not None or sim.compiled.watched:
            return True
        now = self.clock()
        return (
            now - self._last_publish >= self.publish_s
            or pacer.wall_time(sim.following_scan_time()) - now >= self.publish_s
        )

    def _execute(self, op: str, args: dict[str, Any], reply: Reply) -> None:
        handler = self._OPS.get(op)
        result: object = None
        failure: CommandError | None = None
        try:
            if handler is None:
                raise CommandError("bad_state", f"unknown command {op!r}")
            if self._recording_only and op in self._LIVE_OPS:
                raise CommandError(
                    "bad_state",
                    "this simulation shows a recording, history only: go to one of its scans and continue from "
                    "there (Continue from here) to run it or change its inputs",
                )
            result = handler(self, **args)
        except CommandError as error:
            failure = error
        except Exception as error:
            log.exception("simulation command %s failed", op)
            failure = CommandError("bad_state", f"internal error: {type(error).__name__}: {error}")
        self._settle(publish=True)  # before the reply: the server has the command's values when it answers
        reply(result, failure)

    # ------------------------------------------------------------------ state

    def _state(self) -> str:
        if self.sim.halted is not None:
            return "halted"
        if self._faulted or len(self.sim.faults) > self._seen_faults:  # (a fault _settle has not seen yet: FB_init's,
            return "faulted"  # before the first _settle, is in the "ready" message's info)
        return "running" if self._running else "stopped"

    def info(self) -> dict[str, Any]:
        """The figures of the simulation (``SimulationInfo`` less what the server knows itself)."""
        sim, stats = self.sim, self.sim.stats
        running = self.clock() - self._run_since if self._run_since is not None else 0.0
        fault = sim.fault
        if fault is not self._fault_report[0]:
            self._fault_report = (fault, fault.diagnostic().model_dump(mode="json") if fault is not None else None)
        return {
            "state": self._state(),
            "scan_count": sim.scan_count,
            "time_ms": sim.time_ms,
            "real_time_ms": (self._real_s + running) * 1000.0,
            "scan_ms": {"min": stats.min_ms, "avg": stats.avg_ms, "max": stats.max_ms, "last": stats.last_ms},
            "overruns": self._overruns + (self._pacer.overruns if self._pacer is not None else 0),
            "fault": self._fault_report[1],
            "variant": sim.variant,
            "speed": self.speed,
            "pending_inputs": len(sim.pending),
            "until": self._until_text(),
            "history": self.history_range(),
        }

    def _settle(self, publish: bool = False) -> None:
        """Account for what the engine did since the last call: scans, faults, halts, state; publish when due."""
        sim = self.sim
        self._fit_variant()
        if sim.scan_count != self._seen_scans:
            self._seen_scans = sim.scan_count
            if self.traces.sample(sim) and self.history is not None:
                self.history.mark(sim.scan_count - 1, "trigger")  # the scan that completed last
            self._faulting_traced = self._log_getter_faults(self.traces.faults, self._faulting_traced)
        if len(sim.accessor_faults) > self._seen_accessor_faults:  # an online write's SET: logged, the tasks go on
            for fault in sim.accessor_faults[self._seen_accessor_faults :]:
                self._fault_log(fault)
            self._seen_accessor_faults = len(sim.accessor_faults)
        if len(sim.faults) > self._seen_faults:
            for fault in sim.faults[self._seen_faults :]:
                self._fault_log(fault)
            self._seen_faults = len(sim.faults)
            self._faulted = True
            self._set_running(False)
        if self._to_transition and (sim.halted is not None or not self._running):
            self._to_transition = False  # reached (or stopped): no further scans after this halt
            self._set_running(self._run_after_transition and sim.halted is not None)
            if sim.halted is None and sim.debugger is not None:
                sim.debugger.waiting_for_transition = False  # stopped before a transition fired
        state = self._state()
        halt = sim.halted
        new_halt = halt is not None and halt is not self._halt_seen
        self._halt_seen = halt
        status = (state, at_halt(halt) if halt is not None else None, self._call_stack(new_halt or publish))
        changed = status != self._status
        if changed:
            self._status = status
            at = status[1].model_dump() if status[1] is not None else None
            if new_halt and halt is not None and halt.reason == "breakpoint":  # (not again after a write)
                self._log("breakpoint", "info", f"halted at the breakpoint at {_where(status[1])}", at=at)
                if self.history is not None:
                    self.history.mark(sim.scan_count, "breakpoint")  # the scan halted in (not completed yet)
            self.sink.status(state, at, [frame.model_dump() for frame in status[2]])
        # A new state (above all a halt) is followed at once by the values of that moment, so a client
        # shows the values at the halt point, not those of the last periodic frame.
        now = self.clock()
        if publish or changed or (now - self._last_publish >= self.publish_s and not sim.quiet):
            self._publish(now)

    def _call_stack(self, read: bool) -> list[CallFrame]:
        """The halted scan's call stack, read (``read``) at a new halt and after a command (a write while halted
        may change a value a call's VAR_IN_OUT refers to); nothing else changes it while the scan stays halted."""
        if self.sim.halted is None:
            return []
        if not read:
            return self._status[2]
        return read_call_stack(self.sim)

    def _fit_variant(self) -> None:
        """Debug code only while debugging: a breakpoint is set or a scan is halted; else the monitor code."""
        sim = self.sim
        if sim.variant not in ("monitor", "debug"):
            return
        waiting = sim.debugger is not None and (bool(sim.debugger.breakpoints) or sim.debugger.waiting_for_transition)
        debugging = sim.halted is not None or waiting
        if debugging != (sim.variant == "debug"):
            sim.use_variant("debug" if debugging else "monitor")

    def _needs_debug(self) -> None:
        """Switch to the debug variant before a breakpoint or step command (compiled on first use)."""
        if self.sim.variant == "monitor":
            try:
                self.sim.use_variant("debug")
            except CompileError as error:
                raise CommandError("bad_state", f"cannot debug this program: {error}") from None

    def _log(
        self, kind: LogKind, level: LogLevel, message: str, at: dict[str, Any] | None = None, scan: int | None = None
    ) -> None:
        entry = Log(
            type="log",
            kind=kind,
            level=level,
            message=message,
            scan=self.sim.scan_count if scan is None else scan,
            time_ms=self.sim.time_ms,
        )
        data = entry.model_dump()
        data["at"] = at
        self.sink.log(data)

    def _fault_log(self, fault: Fault) -> None:
        where = at_origin(fault.origin, fault.pou, fault.instance)
        entry = Log(
            type="log",
            kind="watchdog" if fault.kind == "watchdog" else "fault",
            level="error",
            message=fault.text(),
            at=where,
            scan=fault.scan,
            time_ms=fault.time_ms,
        )
        self.sink.log(entry.model_dump())

    def _log_getter_faults(self, faults: dict[str, Any], logged: set[str]) -> set[str]:
        """Log each watched or traced 'call' property whose GET faults when run to show it (``faults``: path -> its
        Fault), once until it reads again (``logged``: those faulting before); its value is none meanwhile, never a
        wrong one. The paths faulting now."""
        for path, fault in faults.items():
            if path not in logged:
                where = at_origin(fault.origin, fault.pou, fault.instance)
                at = where.model_dump() if where is not None else None
                self._log("fault", "error", f"{path}: its GET faulted: {fault.text()}", at, fault.scan)
        return set(faults)

    # ------------------------------------------------------------------ frames

    def _publish(self, now: float) -> None:
        self._last_publish = now
        full, sim = self._full, self.shown
        reader = self._reader if self._view is None else self._view_reader
        values = reader.read()
        self._faulting_watched = self._log_getter_faults(reader.faults, self._faulting_watched)
        if full:
            changed = values
            self._sent_values = dict(values)
        else:
            changed = changes(self._sent_values, values)
            self._sent_values.update(changed)
        power: dict[str, dict[str, object]] = {}
        for instance, (every, ids) in self._union.items():
            states = self._states(instance, every, ids)
            if full:
                self._sent_power[instance] = dict(states)
                power[instance] = states
                continue
            sent = self._sent_power.setdefault(instance, {})
            diff = changes(sent, states)
            if diff:
                sent.update(diff)
                power[instance] = diff
        forced = list(sim.forced)
        new_forced = full or forced != self._sent_forced
        self._sent_forced = forced
        injected = sim.injected
        new_injected = full or injected != self._sent_injected
        self._sent_injected = injected
        self._full = False
        self._seq += 1
        self.sink.frame(
            {
                "seq": self._seq,
                "scan": self._viewing if self._steps else sim.scan_count,  # halted within the scan shown
                "time_ms": sim.time_ms,
                "history": self.history_range(),
                "wall": time.time(),  # when these values were read (latency measurements)
                "full": full,
                "values": changed,
                "power": power,
                "forced": forced if new_forced else None,
                "injected": injected if new_injected else None,
                "traces": self.traces.take_all(),
                "info": self.info(),
            }
        )

    def _states(self, instance: str, every: bool, ids: tuple[str, ...]) -> dict[str, object]:
        """Each watched element's state: its value when it ran in the last scan, else None. An SFC transition's
        condition is its last computed value: a scan halted before the transitions has not computed it yet, and the
        chart shows the value of the scan before, not "?" (docs/sfc.md). Elements of a network viewed only since the
        last scan are left out (not recorded yet: the next scan records them)."""
        view = self.shown.probes(instance, None if every else ids)
        if view.unknown and not self._running and self._view is None:
            view = self._replayed(instance, view)
        elements = sorted((view.values.keys() | view.executed).union(ids)) if every else ids
        return {
            e: (view.values.get(e) if e in view.executed or e.endswith(CONDITION_PROBE) else None)
            for e in elements
            if e not in view.unknown
        }

    def _replayed(self, instance: str, view: ProbeView) -> ProbeView:
        """``view`` with its unknown elements (networks viewed only since the last scan) read from the replay of that
        scan in the history; a running simulation's next scan records them anyway."""
        scan = self.sim.scan_count - 1
        if self.history is None or not self.history.first <= scan <= self.history.last:
            return view
        if self._replayed_views[0] != (self.history, scan):  # (commands while stopped: one replay per scan)
            self._replayed_views = ((self.history, scan), {})
        views = self._replayed_views[1]
        if instance not in views:
            views[instance] = self.history.seek(scan).probes(instance)
        replayed = views[instance]
        values = {e: replayed.values[e] for e in view.unknown if e in replayed.values}
        return ProbeView(
            {**view.values, **values},
            view.executed | (replayed.executed & view.unknown),
            view.unknown & replayed.unknown,
        )

    # ------------------------------------------------------------------ run control

    def _set_running(self, running: bool) -> None:
        now = self.clock()
        if not running:
            self._until, self._until_ms = None, None
        if running and not self._running:
            self._run_since = now
            self._pacer = Pacer(
                _Scans(self),
                speed=self.speed,
                clock=self.clock,
                interrupted=lambda: bool(self._commands) and not self.sim.quiet,  # (``_holding``)
            )
            self._delay = 0.0
        elif not running and self._running:
            self._real_s += now - (self._run_since or now)
            self._run_since = None
            if self._pacer is not None:
                self._overruns += self._pacer.overruns
            self._pacer = None
        self._running = running

    def start(self) -> None:
        if self._faulted:
            raise CommandError("bad_state", "the simulation stopped on a fault: reset it before running")
        halted = self.sim.halted is not None
        self._log("state", "info", "run: continued the halted scan, then scans run" if halted else "run")
        self._set_running(True)
        if halted:
            self.sim.resume()

    def stop(self, reason: str | None = None) -> None:
        """Stop after the scan under way; ``reason`` is logged (e.g. the last client left)."""
        if self._running and self.sim.halted is not None:  # the state stays "halted": say what Stop did
            self._log(
                "state",
                "info",
                "stopped: the scan stays halted; Continue or a step finishes it, then no further scan runs",
            )
        elif self._running:
            self._log("state", "info", f"stopped: {reason}" if reason else "stopped")
        self._set_running(False)

    def reset(self, cold: bool = False) -> None:
        """Warm or cold restart: stops, ends a halted scan, clears the faults (forces stay)."""
        self._set_running(False)
        self.sim.reset(cold=cold)
        self._faulted = False
        self._seen_faults = self._seen_accessor_faults = 0
        self._log("state", "info", "reset (cold: RETAIN variables too)" if cold else "reset (warm)")

    def single_cycle(self) -> None:
        """One scan of a stopped simulation; when halted, the rest of the current scan."""
        if self.sim.halted is not None:
            self._log("state", "info", "single cycle: finished the halted scan")
            self.sim.resume()
            return
        if self._running:
            raise CommandError("bad_state", "the simulation is running: stop it before a single cycle")
        if self._faulted:
            raise CommandError("bad_state", "the simulation stopped on a fault: reset it first")
        self._log("state", "info", "single cycle")
        self.sim.cycle(1)

    def resume(self) -> None:
        if self.sim.halted is None:
            raise CommandError("bad_state", "the simulation is not halted")
        self.sim.resume()

    def step(self, granularity: str = "statement") -> None:
        """Halted: continue to the next pause point of this granularity. Else halt in the next scan.

        ``transition``: when no SFC transition fires in that scan, scans run on (paced) until one does; the
        simulation then halts there, and Continue goes back to what it was doing: stopped, or running when the step
        was asked for at a halt of a running simulation (as after any other step)."""
        if self._faulted and self.sim.halted is None:
            raise CommandError("bad_state", "the simulation stopped on a fault: reset it first")
        if granularity == "transition" and self._running and self.sim.halted is None:
            raise CommandError("bad_state", "the simulation is running: stop it before stepping to a transition")
        self._needs_debug()
        running = self._running
        self.sim.step(granularity)
        if granularity == "transition" and self.sim.halted is None and not self._faulted:
            self._run_after_transition = running
            self._log("state", "info", "running until an SFC transition fires")
            self._to_transition = True
            self._set_running(True)

    def set_breakpoint(self, pou: str, **where: Any) -> None:
        self._debug("set_breakpoint", pou, **where)

    def clear_breakpoint(self, pou: str | None = None, **where: Any) -> None:
        if pou is None:
            if self.sim.debugger is not None:
                self.sim.clear_breakpoints()
        else:
            self._debug("clear_breakpoint", pou, **where)

    def _debug(self, method: str, pou: str, **where: Any) -> None:
        self._needs_debug()
        try:
            getattr(self.sim, method)(pou, **where)
        except ValueError as error:
            raise CommandError("bad_path", str(error)) from None

    # ------------------------------------------------------------------ variables

    def _location(self, path: str) -> Location:
        try:
            return self.sim.location(path)
        except (UnknownPath, ValueError) as error:
            raise CommandError("bad_path", str(error)) from None

    def write(self, path: str, value: object) -> None:
        location = self._location(path)
        _coerced(self.sim.write, path, value)
        when = "" if self.sim.halted is not None else " (before the next scan)"
        self._log("write", "info", f"wrote {location.path} := {_written(value)}{when}")

    def force(self, path: str, value: object) -> None:
        location = self._location(path)
        _coerced(self.sim.force, path, value)
        forced, named = self.sim.read(path), display_type(location.type).names or {}
        self._log("force", "info", f"forced {location.path} := {named.get(str(forced)) or value_text(forced)}")

    def unforce(self, path: str) -> None:
        location = self._location(path)
        if location.path not in self.sim.forced:
            raise CommandError("bad_path", f"{location.path} is not forced")
        self.sim.unforce(path)
        self._log("release", "info", f"released the force on {location.path}")

    def unforce_all(self) -> None:
        count = len(self.sim.forced)
        self.sim.unforce_all()
        if count:
            self._log("release", "info", f"released all forces ({count})")

    # ------------------------------------------------------------------ panels, injected faults, time

    def _submit(self, event: InputEvent) -> None:
        try:
            self.sim.submit(event)
        except (UnknownPath, InputRefused) as error:
            raise CommandError("bad_path" if isinstance(error, UnknownPath) else "bad_value", str(error)) from None
        except ValueError as error:
            raise CommandError("bad_value", str(error)) from None

    def panel(self, path: str, value: object, panel: str | None = None, widget: str | None = None) -> None:
        """A panel widget's action (press, release, a new value): applied at the start of the next scan."""
        source = f"panel {panel or '?'}/{widget}" if widget else (f"panel {panel}" if panel else "panel")
        self._submit(InputEvent("panel", path, value, source=source))

    def inject(
        self,
        path: str,
        mode: str,
        value: object = None,
        amplitude: float | None = None,
        rate: float | None = None,
        seed: int | None = None,
    ) -> None:
        """Inject a fault into a signal from the next scan on; a noisy fault without a seed gets one (recorded)."""
        if mode == "noisy" and seed is None:
            seed = random.SystemRandom().randrange(1 << 31)
        event = InputEvent("fault", path, value, mode=mode, amplitude=amplitude, rate=rate, seed=seed)
        self._submit(event)

    def inject_clear(self, path: str | None = None) -> None:
        """Remove the fault from a signal (every fault: no path) from the next scan on."""
        if path is not None and self._location(path).path not in self.sim.injected:
            raise CommandError("bad_path", f"{self._location(path).path} has no injected fault")
        self._submit(InputEvent("clear_fault", path))

    def _applied(self, applied: AppliedInput) -> None:
        """Every input the engine applies: kept in the journal; panel events and faults logged with their scan."""
        if len(self.journal) == self.journal.maxlen:
            self.journal_dropped += 1
        self.journal.append(applied)
        if self.history is not None:
            self.history.applied(applied)
        event = applied.event
        if event.kind == "panel":
            self._log("panel", "info", f"{event.source}: {event.path} := {_written(event.value)}", scan=applied.scan)
        elif event.kind == "fault":
            self._log("inject", "warning", f"fault injected: {_fault_text(event)}", scan=applied.scan)
        elif event.kind == "clear_fault":
            what = f"the fault on {event.path}" if event.path else "every injected fault"
            self._log("inject", "info", f"removed {what}", scan=applied.scan)

    def inputs(self) -> dict[str, Any]:
        """The applied inputs kept (oldest first, as ``--events`` lines) and how many older ones were dropped;
        ``scans``: the scans completed, ``forked``: whether the simulation continued from a past scan (then the
        inputs are no longer one run from scan 0)."""
        return {
            "inputs": [applied.to_json() for applied in self.journal],
            "dropped": self.journal_dropped,
            "scans": self.sim.scan_count,
            "forked": bool(self.branches),
        }

    # ------------------------------------------------------------------ scan history (history.py)

    def history_range(self) -> dict[str, Any] | None:
        """The scans that can be viewed and the one viewed (None: live), numbered as frames number scans:
        scans completed, so scan n shows what the live view showed as scan n. None without a history."""
        history = self.history
        if history is None:
            return None
        viewed = self._view_history
        return {
            "first": history.first + 1,
            "last": history.last + 1,
            "viewing": self._viewing,
            "bytes": history.size + sum(branch.size for branch in self.branches),
            "budget_bytes": self._budget_bytes,
            "marked": history.marked,
            "branch": len(self.branches) + 1,
            "viewing_branch": self._branch_number(viewed) if viewed is not None else None,
            "recording": self._recording_only,
            "stepping": self._step_point(),
        }

    def _step_point(self) -> dict[str, Any] | None:
        """Where the step through the scan shown stands (``at`` null: the scan ran to its end); None: no step."""
        if not self._steps or self._view is None:
            return None
        halted = self._view.halted
        if halted is None:
            return {"at": None, "stack": []}
        if self._step_point_of is None or self._step_point_of[0] is not halted:  # (every frame asks: read it once)
            stack = [f.model_dump() for f in read_call_stack(self._view)]
            self._step_point_of = (halted, {"at": at_halt(halted).model_dump(), "stack": stack})
        return self._step_point_of[1]

    def open_recording(self, inputs: list[dict[str, Any]], scans: int) -> dict[str, Any] | None:
        """Run a recording's ``scans`` at once, each one's recorded ``inputs`` (``AppliedInput.to_json()`` lines)
        submitted before it as ``ladderlab replay`` does, into the history of this new simulation; then show its
        last scan. The simulation stays history only (``_LIVE_OPS`` are refused) until a ``fork``."""
        history = self._recorded()
        if self.sim.scan_count != 0 or self.journal:
            raise CommandError("bad_state", "a recording opens in a new simulation, before its first scan")
        try:
            scheduled = parse_events(events_text(inputs), "the recording's inputs")
        except ValueError as error:
            raise CommandError("bad_value", str(error)) from None
        try:
            for _ in scan_inputs(self.sim, scheduled, cycles=scans):
                self._settle()
                if self.sim.fault is not None:
                    break  # as ladderlab replay: the scan that faulted is the recording's last
        except (UnknownPath, InputRefused, ValueError) as error:
            raise CommandError("bad_value", f"the recording's inputs do not fit this project: {error}") from None
        self._recording_only = True
        self._log("state", "info", f"opened a recording of {self.sim.scan_count} scans: history only")
        if history.last < history.first:
            return self.history_range()  # no scan: nothing to show
        return self.seek(history.last + 1)

    def _branch_number(self, history: History) -> int:
        return self.branches.index(history) + 1 if history in self.branches else len(self.branches) + 1

    @property
    def shown(self) -> Simulation:
        """The simulation the frames show: a past scan's replay while one is viewed, else the live one."""
        return self._view or self.sim

    def _recorded(self) -> History:
        if self.history is None:
            raise CommandError("bad_state", "this simulation keeps no scan history (the server's history_mb is 0)")
        return self.history

    def seek(self, scan: int, branch: int | None = None) -> dict[str, Any] | None:
        """Show scan ``scan`` as it was (every watched value and element); the live scans go on unseen. ``branch``:
        an earlier branch of the history (1 for the first; default: the live one)."""
        history = self._recorded()
        if branch is not None and branch != len(self.branches) + 1:
            if not 1 <= branch <= len(self.branches):
                raise CommandError("bad_value", f"there is no branch {branch} (branches 1 to {len(self.branches) + 1})")
            history = self.branches[branch - 1]
        try:
            view = history.seek(scan - 1)
        except HistoryUnavailable:
            raise CommandError("bad_value", _shown_numbers(scan, history)) from None
        self._view, self._viewing, self._view_history, self._full = view, scan, history, True
        self._view_reader = view.reader(self._union_locations)
        self._steps = []
        return self.history_range()

    def live(self) -> None:
        """Show the live scans again."""
        self._view, self._viewing, self._view_history, self._full = None, None, None, True
        self._steps = []

    def history_step(self, granularity: str = "statement") -> dict[str, Any] | None:
        """Step through the scan shown: the first step replays it in the debug variant from the state the scan
        before it left, its recorded inputs applied at its start (``History.stepper``), and halts at its first
        network or line (``statement``; ``over`` and ``out`` as live); each further step halts at the next one,
        and after the last the scan is complete, as the seek showed it. ``back`` goes to the point before the one
        reached: the scan replayed again with one step less. The frames show the values and power flow of the
        point reached; the history and the live simulation stay as they are. A seek or live leaves."""
        history, scan = self._view_history, self._viewing
        if history is None or scan is None:
            raise CommandError("bad_state", "go to a past scan first: a step goes through the scan shown")
        if granularity not in ("statement", "over", "out", "network", "back"):
            raise CommandError(
                "bad_value",
                f"a step through a past scan is statement, over, out, network or back, not {granularity!r}",
            )
        if granularity == "back":
            if len(self._steps) < 2:
                raise CommandError(
                    "bad_state",
                    f"scan {scan} is halted before its first network or line: go one scan back to see the one before"
                    if self._steps
                    else "step into the scan shown first: a step back goes to the point before the one reached",
                )
            steps = self._steps[:-1]
        elif self._steps and (self._view is None or self._view.halted is None):
            raise CommandError("bad_state", f"scan {scan} ran to its end: go to a scan to step through it")
        else:
            steps = [*self._steps, granularity]
        view = self._view if self._steps and granularity != "back" else None
        if view is None:
            try:
                view = history.stepper(scan - 1, self._debug_variant())
            except HistoryUnavailable as error:
                raise CommandError("bad_state", f"scan {scan} cannot be stepped through: {error}") from None
            for taken in steps[:-1]:  # the steps before the last again (none on the first step)
                view.step(taken)
        view.step(steps[-1])
        self._view, self._steps, self._full = view, steps, True
        self._view_reader = view.reader(self._union_locations)
        return self.history_range()

    def _debug_variant(self) -> CompiledProgram:
        if self._debug_program is None:
            program = self.sim.variant_program("debug")
            self._debug_program = program or compile_program(self.sim.compiled.program, "debug")
        return self._debug_program

    #: Earlier branches kept beside the live one; a fork beyond them drops the oldest.
    MAX_BRANCHES = 3

    def fork(self) -> dict[str, Any] | None:
        """Continue from the scan shown: the live simulation takes that scan's state (stopped) and records a new
        branch of the history; the branch it leaves is kept and viewable (``seek`` with ``branch``)."""
        history, view = self._recorded(), self._view
        if view is None or self._viewing is None:
            raise CommandError("bad_state", "go to a past scan first: continue from here starts from the scan shown")
        if view.halted is not None:
            raise CommandError("bad_state", "the scan shown is halted in a step through it: step to its end first")
        if self.sim.halted is not None:
            raise CommandError(
                "bad_state", "the live scan is halted: continue or reset it before continuing from another"
            )
        scan, origin = self._viewing, self._branch_number(self._view_history or history)
        state = view.state()
        self._set_running(False)
        history.end()
        self.sim.restore(state)
        self.branches.append(history)
        budget = self._budget_bytes
        while len(self.branches) > self.MAX_BRANCHES or (
            self.branches and budget - sum(b.size for b in self.branches) < budget // 4
        ):
            self.branches.pop(0)  # the oldest branch goes: all branches share the one budget
        self.history = History(self.sim, budget_bytes=budget - sum(b.size for b in self.branches))
        self.history.viewed = history.viewed
        self._seen_scans, self._seen_faults, self._faulted = self.sim.scan_count, 0, False
        self._recording_only = False
        self.live()
        self._log(
            "state", "info", f"continued from scan {scan} of branch {origin}: branch {len(self.branches) + 1} is live"
        )
        return self.history_range()

    def history_find(
        self, scan: int, direction: int = 1, path: str | None = None, condition: str | None = None
    ) -> int | None:
        """The nearest scan after (``direction`` 1) or before (-1) ``scan`` where ``path`` changed (its end value
        differs from the scan before) or ``condition`` became TRUE; numbered as frames number scans; None when
        the history holds none."""
        history = self._recorded()
        if (path is None) == (condition is None):
            raise CommandError("bad_value", "give a path or a condition to find (one of them)")
        if direction not in (-1, 1):
            raise CommandError("bad_value", f"direction is -1 (back) or 1 (forward), not {direction}")
        self._in_history(scan)
        if path is not None:
            location = self._location(path)
            if location.called:
                raise CommandError(
                    "bad_path",
                    f"{location.path} is a property monitored as 'call': finding its changes would run its GET on "
                    "every recorded scan; use 'variable' (its last value is recorded) or the variables its GET reads",
                )
            found = history.changed(location.path, scan - 1, direction)
        else:
            try:
                until = parse_condition(condition or "", self.sim)
            except BadCondition as error:
                raise CommandError("bad_value", str(error)) from None
            found = history.find(until.holds, lambda before, now: bool(now) and not before, scan - 1, direction)
        self._back_to_view()
        return found + 1 if found is not None else None

    def history_diff(self, first: int, second: int) -> dict[str, list[object]]:
        """The variables that differ between the ends of two scans (numbered as frames number them): path ->
        [value in ``first``, value in ``second``], by path."""
        history = self._recorded()
        self._in_history(first)
        self._in_history(second)
        differences = history.diff(first - 1, second - 1)
        self._back_to_view()
        return {path: list(differences[path]) for path in sorted(differences)}

    def history_marks(self) -> list[dict[str, Any]]:
        """The newest scans with an input or an error (numbered as frames number them), for the timeline."""
        return [{"scan": scan + 1, "kinds": kinds} for scan, kinds in self._recorded().marks()]

    def _in_history(self, scan: int) -> None:
        history = self._recorded()
        if not history.first + 1 <= scan <= history.last + 1:
            raise CommandError(
                "bad_value", f"scan {scan} is not in the history (scans {history.first + 1} to {history.last + 1})"
            )

    def _back_to_view(self) -> None:
        """A search moved the replay: back to the scan shown."""
        if self._viewing is not None and self._view_history is not None and not self._steps:
            self._view = self._view_history.seek(self._viewing - 1)

    def set_speed(self, scale: float) -> None:
        """Pace the scans at ``scale`` times real time; the virtual clock and every value stay the same."""
        if not MIN_SPEED <= scale <= MAX_SPEED:
            raise CommandError(
                "bad_value", f"the time scale goes from {MIN_SPEED:g}x to {MAX_SPEED:g}x, not {scale:g}x"
            )
        self.speed = scale
        if self._pacer is not None:
            self._pacer.set_speed(scale)
        self._log("state", "info", f"time scale {scale:g}x real time")

    def run_until(self, condition: str | None = None, time_ms: float | None = None) -> None:
        """Run until ``condition`` holds after a scan, or until every scan due by virtual ``time_ms`` has run."""
        if (condition is None) == (time_ms is None):
            raise CommandError("bad_value", "run until needs a condition or a virtual time (one of them)")
        until = None
        if condition is not None:
            try:
                until = parse_condition(condition, self.sim)
            except BadCondition as error:
                raise CommandError("bad_value", str(error)) from None
        elif time_ms is not None and not time_ms > self.sim.time_ms:
            raise CommandError("bad_value", f"virtual time is already {self.sim.time_ms:g} ms, past {time_ms:g} ms")
        self.start()
        self._until, self._until_ms = until, time_ms
        self._log("state", "info", f"run until {self._until_text()}")

    def _until_text(self) -> str | None:
        if self._until is not None:
            return self._until.text
        return f"{self._until_ms:g} ms" if self._until_ms is not None else None

    def _reached(self) -> str | None:
        """Why a run until ends after this scan (None: it goes on)."""
        if self._until is not None and self._until.holds(self.sim):
            return f"{self._until.text} holds"
        if self._until_ms is not None and self.sim.next_scan_time() > self._until_ms:
            return f"virtual time {self._until_ms:g} ms reached"
        return None

    def inspect(self, paths: Sequence[str] = (), probes: Sequence[str] = ()) -> dict[str, Any]:
        """The whole state, for tests and diagnosis: every variable, forces, breakpoints, the halt, the variant."""
        sim = self.sim
        return {
            **self.info(),
            "snapshot": sim.snapshot(),
            "forced": sim.forced,
            "injected": sim.injected,
            "pending": [event.to_json() for event in sim.pending],
            "breakpoints": sorted(sim.debugger.breakpoints) if sim.debugger is not None else [],
            "halted": at_halt(sim.halted).model_dump() if sim.halted is not None else None,
            "values": {path: self._read(path) for path in paths},
            "probes": {
                instance: {"values": view.values, "executed": sorted(view.executed)}
                for instance in probes
                for view in [sim.probes(instance)]
            },
        }

    def _read(self, path: str) -> object:
        self._location(path)
        return self.sim.read(path)

    # ------------------------------------------------------------------ watching

    def watch(self, key: object, paths: list[str], elements: list[tuple[str, list[str] | None]]) -> dict[str, Any]:
        """Set ``key``'s subscription (replacing its previous one); the next frame holds every watched value.

        ``elements``: (POU instance, element ids or None for all) whose states to publish. Returns the
        canonical paths with their display types, per element request the canonical instance with the ids
        watched (None: refused), and ``refused``: why each path, instance or element id that the simulation does
        not know was left out. One unknown name in a
        client's views (a pin the diagram draws and the program does not have) must not stop every other value."""
        locations: dict[str, Location] = {}
        refused: list[str] = []
        for path in paths:
            try:
                location = self._location(path)
            except CommandError as error:
                refused.append(error.message)
                continue
            locations.setdefault(location.path, location)
        accepted: list[tuple[str, tuple[str, ...] | None] | None] = []  # one per element request, None: refused
        for instance, ids in elements:
            try:
                self.sim.probes(instance, ())
                known, unknown = self._elements(instance, ids or [])
            except (KeyError, CommandError) as error:
                refused.append(error.message if isinstance(error, CommandError) else str(error.args[0]))
                accepted.append(None)
                continue
            if unknown is not None:
                refused.append(unknown)
            accepted.append((instance.strip().upper(), tuple(known) if ids is not None else None))
        self._watches[key] = _Watch(locations, tuple(a for a in accepted if a is not None))
        self._rebuild_union()
        return {
            "paths": {path: display_type(location.type).model_dump() for path, location in locations.items()},
            "elements": accepted,
            "refused": refused,
        }

    def _elements(self, instance: str, ids: list[str]) -> tuple[list[str], str | None]:
        """The ids that are probed elements (or pins, ``box.Q``) of the instance's POU, and why the others are not
        watched (None: every id is known)."""
        pou = self._pou_of(instance)
        elements = set(self._ctx.probes_of(pou).elements)
        known = [element for element in ids if element in elements]
        unknown = [element for element in ids if element not in elements]
        if not unknown:
            return known, None
        listed = ", ".join(sorted(elements)[:30]) or "none: it is not a ladder or FBD POU"
        return known, f"{instance} ({pou}) has no element {unknown[0]!r} (elements: {listed})"

    def _pou_of(self, instance: str) -> str:
        name = instance.strip().upper()
        pou = self._ctx.pous.get(name)
        if pou is not None and pou.kind in ("program", "function"):
            return pou.name
        location = self._location(instance)
        if isinstance(location.type, t.FbInstance):
            return location.type.fb
        raise CommandError("bad_path", f"{location.path} is not a POU instance")

    def unwatch(self, key: object) -> None:
        if self._watches.pop(key, None) is not None:
            self._rebuild_union()
        self.traces.drop(key)

    def _rebuild_union(self) -> None:
        union = {path: loc for watch in self._watches.values() for path, loc in watch.locations.items()}
        self._reader = self.sim.reader(union)
        self._union_locations = union
        if self._view is not None:
            self._view_reader = self._view.reader(union)
        instances: dict[str, tuple[bool, dict[str, None]]] = {}
        for watch in self._watches.values():
            for instance, ids in watch.elements:
                every, known = instances.get(instance, (False, {}))
                instances[instance] = (every or ids is None, {**known, **dict.fromkeys(ids or ())})
        self._union = {instance: (every, tuple(ids)) for instance, (every, ids) in instances.items()}
        self._view_networks()
        self._full = True

    def _view_networks(self) -> None:
        """The live simulation records the power flow of the networks some client views, no other
        (``Simulation.view``). A network viewed after the last scan shows that scan from its replay in the history
        (``_states``), so without a history every network is recorded. The histories' replays record the same
        networks (``History.viewed``: the others' probed code is compiled at first use), and a past scan shown
        is replayed again when they change, so what a client views of it is recorded, never unknown."""
        if self.sim.variant not in ("monitor", "debug") or self.history is None:
            return
        viewed: dict[str, Iterable[str] | None] = {
            instance: None if every else ids for instance, (every, ids) in self._union.items()
        }
        self.sim.view(viewed)
        changed = viewed != self.history.viewed
        for history in (*self.branches, self.history):
            history.viewed = viewed
        if changed:  # the replays of the last scan kept recorded only the networks viewed then
            self._replayed_views = ((None, -1), {})
        shown, scan = self._view_history, self._viewing
        if changed and self._view is not None and not self._steps and shown is not None and scan is not None:
            with contextlib.suppress(HistoryUnavailable):  # dropped from the history meanwhile: shown as it was
                self._view = shown.seek(scan - 1)
                self._view_reader = self._view.reader(self._union_locations)

    # ------------------------------------------------------------------ traces

    def start_trace(
        self,
        owner: object,
        paths: list[str],
        samples: int | None = None,
        trigger: dict[str, Any] | None = None,
        trace_id: int = 0,
    ) -> None:
        """Record ``paths`` after every scan for ``owner`` (replacing its running trace); see ``trace.py``."""
        try:
            plan = plan_trace(self._location, paths, TraceTrigger(**trigger) if trigger else None)
        except TraceRefused as error:
            raise CommandError("bad_path", str(error)) from None
        types = {location.path: display_type(location.type).model_dump() for location in plan.locations}
        self.traces.start(owner, trace_id, plan, samples, self.sim, types)

    def stop_trace(self, owner: object) -> None:
        if not self.traces.stop(owner):
            raise CommandError("bad_state", "no trace is running: start one with trace_start")

    #: The commands ``submit`` accepts, by name (the wire protocol's ``op``, worker.py).
    _OPS: ClassVar[dict[str, Callable[..., object]]] = {
        "run": start,
        "stop": stop,
        "reset": reset,
        "single_cycle": single_cycle,
        "continue": resume,
        "step": step,
        "breakpoint_set": set_breakpoint,
        "breakpoint_clear": clear_breakpoint,
        "write": write,
        "force": force,
        "unforce": unforce,
        "unforce_all": unforce_all,
        "watch": watch,
        "unwatch": unwatch,
        "trace_start": start_trace,
        "trace_stop": stop_trace,
        "inspect": inspect,
        "panel": panel,
        "inject": inject,
        "inject_clear": inject_clear,
        "inputs": inputs,
        "speed": set_speed,
        "run_until": run_until,
        "seek": seek,
        "live": live,
        "history_find": history_find,
        "history_diff": history_diff,
        "history_marks": history_marks,
        "fork": fork,
        "open_recording": open_recording,
        "history_step": history_step,
    }

    #: What runs scans or applies inputs: refused while an opened recording is shown (history only).
    _LIVE_OPS: ClassVar[frozenset[str]] = frozenset(
        {"run", "reset", "single_cycle", "continue", "step", "write", "force", "unforce", "unforce_all", "panel"}
        | {"inject", "inject_clear", "run_until"}
    )


def _shown_numbers(scan: int, history: History) -> str:
    """A refused seek in the frames' numbering (the history counts scans from 0, frames count completed ones)."""
    if scan - 1 > history.last:
        return f"scan {scan} has not run yet (the last scan is {history.last + 1})"
    return f"scan {scan} is no longer in the history: it starts at scan {history.first + 1}"


def _coerced(method: Callable[[str, object], None], path: str, value: object) -> None:
    try:
        method(path, value)
    except ValueError as error:
        raise CommandError("bad_value", str(error)) from None


def _written(value: object) -> str:
    """A written value as the user gave it (IEC literal text as typed, JSON values as IEC literals)."""
    return value if isinstance(value, str) else value_text(value)


def _fault_text(event: InputEvent) -> str:
    """An injected fault as the log says it: ``LEVELHIGH stuck FALSE``, ``LEVEL noisy (seed 7)``."""
    mode = {"stuck_true": "stuck TRUE", "stuck_false": "stuck FALSE", "open": "open circuit"}.get(event.mode or "")
    if mode is None and event.mode == "stuck":
        mode = f"stuck at {_written(event.value)}"
    if mode is None:
        extra = [f"seed {event.seed}"]
        extra += [f"amplitude {event.amplitude:g}"] if event.amplitude is not None else []
        extra += [f"rate {event.rate:g}"] if event.rate is not None else []
        mode = f"noisy ({', '.join(extra)})"
    return f"{event.path} {mode}"


def _where(at: At | None) -> str:
    if at is None:
        return "an unknown place"
    parts = [at.pou]
    if at.body is not None:
        parts.append(at.body.replace("s/", " ", 1))
    if at.network is not None:
        parts.append(f"network {at.network}")
    if at.element is not None:
        parts.append(f"element {at.element}")
    if at.line is not None:
        parts.append(f"line {at.line}")
    return ", ".join(parts) + (f" (instance {at.instance})" if at.instance and at.instance != at.pou else "")


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
        runner = self.runner
        self.sim.record(runner._records_next())
        try:
            done = self.sim.cycle(n)
        finally:
            self.sim.record(True)  # (single cycles, steps, replays record)
        reached = runner._reached() if done and (runner._until or runner._until_ms is not None) else None
        if reached is not None:
            runner._log("state", "info", f"run until: {reached} after scan {self.sim.scan_count - 1}: stopped")
            runner._set_running(False)
        runner._settle()
        return done
