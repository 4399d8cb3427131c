"""Traces of online mode: up to 20 variables sampled after every scan, handed over in chunks.

In the simulation's process the engine thread calls ``TraceBook.sample`` after every scan (so the
values are those the scan left) and hands each client's samples recorded since the previous frame
to the server with every frame (``take_all``: chunks as plain data). On the server a ``TraceInbox``
merges them per client until the client's sender takes them at its monitor interval. The browser
keeps the ring buffer it draws; the server holds only samples not taken yet, at most
``MAX_TRACE_SAMPLES`` per trace (older ones are dropped and counted in the next chunk's ``lost``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ..engine.paths import AccessorFault, Location
from ..engine.simulation import Simulation
from ..ir import types as t
from ..model.monitor import MAX_TRACE_SAMPLES, TraceTrigger


class TraceRefused(ValueError):
    """A trace request naming a variable that cannot be traced or a trigger that does not fit it."""


def kind_of(location: Location) -> str | None:
    """ "bool" or "number" for what a trace can record (ints, bit strings, reals, times, dates,
    enumerations, subranges); None for STRINGs and composite variables."""
    ty = location.type
    if isinstance(ty, (t.Enum, t.Subrange)):
        return "number"
    if isinstance(ty, t.Elementary) and ty.info.category != "string":
        return "bool" if ty.name == "BOOL" else "number"
    return None


def fired(condition: str, level: float | None, previous: object, current: object) -> bool:
    """Whether a trigger fires on the change from ``previous`` (end of the previous scan) to ``current``."""
    if condition == "rising":
        return bool(current) and not previous
    if condition == "falling":
        return bool(previous) and not current
    if condition == "cross_up":
        return previous < level <= current  # type: ignore[operator]  # level triggers watch numbers
    return previous > level >= current  # type: ignore[operator]  # cross_down: numbers, as above


@dataclass(frozen=True)
class TracePlan:
    """A checked request: distinct traced locations in request order, and the trigger."""

    locations: tuple[Location, ...]
    trigger: Location | None = None
    condition: str = "rising"
    level: float | None = None


def plan_trace(resolve: Callable[[str], Location], paths: list[str], trigger: TraceTrigger | None) -> TracePlan:
    """Resolve and check a ``trace_start`` request (``resolve`` raises for unknown paths)."""
    locations: dict[str, Location] = {}
    for path in paths:
        location = resolve(path)
        if kind_of(location) is None:
            raise TraceRefused(
                f"{location.path} is not a BOOL or numeric variable: a trace records BOOL and "
                f"numeric variables (trace the elements of arrays and structures)"
            )
        locations.setdefault(location.path, location)
    if trigger is None:
        return TracePlan(tuple(locations.values()))
    where = resolve(trigger.path)
    kind = kind_of(where)
    if trigger.condition in ("rising", "falling") and kind != "bool":
        raise TraceRefused(
            f"the trigger {where.path} is not a BOOL: a {trigger.condition} edge needs a BOOL "
            f"(use cross_up or cross_down with a level for numbers)"
        )
    if trigger.condition.startswith("cross") and kind != "number":
        raise TraceRefused(
            f"the trigger {where.path} is not numeric: {trigger.condition} compares a number "
            f"with a level (use rising or falling for a BOOL)"
        )
    return TracePlan(tuple(locations.values()), where, trigger.condition, trigger.level)


def _value(sim: Simulation, location: Location, faults: dict[str, Any]) -> object:
    """The value at ``location`` now; None (no sample) when it is a 'call' property whose GET faults, the fault
    kept in ``faults`` for the log."""
    try:
        return sim.value(location)
    except AccessorFault as error:
        faults[location.path] = error.fault
        return None


@dataclass
class _Recorder:
    id: int
    plan: TracePlan
    samples: int | None  # None: until stopped
    previous: object  # the trigger's value at the end of the previous scan
    state: str = "recording"
    recorded: int = 0
    scans: list[int] = field(default_factory=list)
    times: list[float] = field(default_factory=list)
    columns: list[list[object]] = field(default_factory=list)
    triggered: dict[str, Any] | None = None  # TraceTriggered's fields
    lost: int = 0
    unreported: bool = True  # a state change (or the start) the client has not been told about
    types: dict[str, Any] = field(default_factory=dict)  # each path's DisplayType fields, until the first chunk

    def sample(self, sim: Simulation, faults: dict[str, Any]) -> None:
        plan = self.plan
        if self.state == "waiting":
            current = _value(sim, plan.trigger, faults)  # type: ignore[arg-type]  # waiting: a trigger was set
            previous, self.previous = self.previous, current
            if previous is None or current is None or not fired(plan.condition, plan.level, previous, current):
                return
            self.state, self.unreported = "recording", True
            self.triggered = {"scan": sim.scan_count, "time_ms": sim.time_ms}
        if len(self.scans) >= MAX_TRACE_SAMPLES:  # the client is not taking them: keep the newest
            del self.scans[0], self.times[0]
            for column in self.columns:
                del column[0]
            self.lost += 1
        self.scans.append(sim.scan_count)
        self.times.append(sim.time_ms)
        for column, location in zip(self.columns, plan.locations):
            column.append(_value(sim, location, faults))
        self.recorded += 1
        if self.samples is not None and self.recorded >= self.samples:
            self.state, self.unreported = "done", True

    def chunk(self) -> dict[str, Any] | None:
        """The samples since the previous chunk (and the state) as ``TraceData`` fields, or None when nothing is new."""
        if not self.scans and not self.unreported:
            return None
        values = {location.path: column for location, column in zip(self.plan.locations, self.columns)}
        data = {
            "id": self.id,
            "state": self.state,
            "scans": self.scans,
            "time_ms": self.times,
            "values": values,
            "triggered": self.triggered,
            "lost": self.lost,
            "types": self.types,
        }
        self.scans, self.times = [], []
        self.columns = [[] for _ in self.plan.locations]
        self.triggered, self.lost, self.unreported, self.types = None, 0, False, {}
        return data


class TraceBook:
    """The running trace of each client (its owner key), sampled on the engine thread after every scan."""

    def __init__(self) -> None:
        self._traces: dict[object, _Recorder] = {}
        self.faults: dict[str, Any] = {}  # the last sample's faulting 'call' properties (``sample``)

    def start(
        self,
        owner: object,
        trace_id: int,
        plan: TracePlan,
        samples: int | None,
        sim: Simulation,
        types: dict[str, Any] | None = None,
    ) -> None:
        """Start (or replace) ``owner``'s trace (reads the trigger's value now); ``types``: each path's DisplayType
        fields, which its first chunk carries."""
        previous = _value(sim, plan.trigger, {}) if plan.trigger is not None else None
        self._traces[owner] = _Recorder(
            trace_id,
            plan,
            samples,
            previous,
            state="waiting" if plan.trigger else "recording",
            columns=[[] for _ in plan.locations],
            types=types or {},
        )

    def stop(self, owner: object) -> bool:
        """End ``owner``'s trace; its next chunk is the last. False when it has none running."""
        recorder = self._traces.get(owner)
        if recorder is None or recorder.state == "done":
            return False
        recorder.state, recorder.unreported = "done", True
        return True

    def sample(self, sim: Simulation) -> bool:
        """After every scan: one sample per recording trace. Whether a trace's trigger fired at this scan.
        ``faults``: the traced 'call' properties whose GET faulted at this sample (none recorded for them)."""
        fired = False
        self.faults = {}
        for recorder in self._traces.values():
            if recorder.state != "done":
                waiting = recorder.state == "waiting"
                recorder.sample(sim, self.faults)
                fired |= waiting and recorder.state != "waiting"
        return fired

    def take_all(self) -> dict[object, dict[str, Any]]:
        """Every owner's new samples (a finished trace is forgotten with its last chunk)."""
        chunks = {}
        for owner, recorder in list(self._traces.items()):
            chunk = recorder.chunk()
            if chunk is not None:
                chunks[owner] = chunk
            if recorder.state == "done":
                del self._traces[owner]
        return chunks

    def drop(self, owner: object) -> None:
        self._traces.pop(owner, None)
