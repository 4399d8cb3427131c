"""The websocket protocol of online mode (``/api/simulations/{id}/ws``), one model per message.

Every message is a JSON object whose ``type`` names it; ``ClientMessage`` and
``ServerMessage`` are discriminated unions on that field, so a message with an
unknown ``type`` or a misspelt field is refused with an error naming it. The
browser's types are generated from these models (``shared_schema/monitor.schema.json``).

Variable paths are IEC text (``MAIN.T1.ET``, ``GVL.START`` or ``START``,
``MAIN.ARR[2]``), matched ignoring case. The server names variables in their
canonical spelling (upper-case names, as ``Simulation.location(path).path``)
in ``values.changed``, ``values.forced`` and ``trace_data.values``.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

#: A value a client may write or force: a JSON scalar, or IEC literal text (``'T#1s'``, ``'16#FF'``).
WriteValue = bool | int | float | str
#: A value the server reports: elementary values as JSON scalars (TIME and dates as integer ms, non-finite
#: REALs as the strings "NaN", "Infinity", "-Infinity"), arrays as lists, structures and FBs as objects.
Value = bool | int | float | str | None | list[Any] | dict[str, Any]

MIN_INTERVAL_MS = 20
MAX_INTERVAL_MS = 1000
MAX_TRACE_PATHS = 20
MAX_TRACE_SAMPLES = 10_000


class _Request(BaseModel):
    model_config = ConfigDict(extra="forbid")


# --------------------------------------------------------------------------- client -> server


class ElementSubscription(BaseModel):
    """The power flow of graphical elements of one POU instance (an LD/FBD view)."""

    model_config = ConfigDict(extra="forbid")

    pou_instance: str = Field(description="Instance path, e.g. 'MAIN' or 'MAIN.Blink'; a FUNCTION by its name.")
    ids: list[str] | None = Field(
        default=None,
        description="Element ids (as in the POU's JSON, pins as 'box.Q'); null: every element of the instance.",
    )


class Subscribe(_Request):
    """Replace this client's subscription; the next ``values`` message is a full snapshot of it."""

    type: Literal["subscribe"]
    paths: list[str] = Field(default_factory=list)
    elements: list[ElementSubscription] = Field(default_factory=list)
    interval_ms: int = Field(default=100, ge=MIN_INTERVAL_MS, le=MAX_INTERVAL_MS)


class Write(_Request):
    """Write once, before the next scan (at once while halted); the program may overwrite it."""

    type: Literal["write"]
    path: str
    value: WriteValue


class Force(_Request):
    """Hold a variable at a value before and after every scan until it is released."""

    type: Literal["force"]
    path: str
    value: WriteValue


class Unforce(_Request):
    type: Literal["unforce"]
    path: str


class UnforceAll(_Request):
    type: Literal["unforce_all"]


class _Where(_Request):
    pou: str
    network: str | None = None
    element: str | None = None
    line: int | None = None


class BreakpointSet(_Where):
    """Halt before an LD/FBD network, at an element, or before the ST statement on a line (exactly one)."""

    type: Literal["breakpoint_set"]

    @model_validator(mode="after")
    def _exactly_one(self) -> BreakpointSet:
        if sum(x is not None for x in (self.network, self.element, self.line)) != 1:
            raise ValueError("give exactly one of network, element, line")
        return self


class BreakpointClear(_Request):
    """Clear one breakpoint (``pou`` and one of network/element/line), or every breakpoint (no fields)."""

    type: Literal["breakpoint_clear"]
    pou: str | None = None
    network: str | None = None
    element: str | None = None
    line: int | None = None

    @model_validator(mode="after")
    def _all_or_one(self) -> BreakpointClear:
        given = sum(x is not None for x in (self.network, self.element, self.line))
        if self.pou is None and given:
            raise ValueError("name the pou of the breakpoint to clear")
        if self.pou is not None and given != 1:
            raise ValueError("give exactly one of network, element, line (or no field to clear every breakpoint)")
        return self


class Continue(_Request):
    """Resume a halted scan (to its end or the next breakpoint)."""

    type: Literal["continue"]


class Step(_Request):
    """Run to the next network (LD/FBD), statement (ST; networks in diagrams) or the end of the scan.

    ``statement`` steps into calls; ``over`` goes to the next statement or network of the halted POU
    (or of its caller once it returns), passing over the calls it makes; ``out`` runs until the caller
    of the halted POU goes on. A breakpoint on the way halts first."""

    type: Literal["step"]
    granularity: Literal["network", "statement", "over", "out", "cycle"] = "statement"


class Run(_Request):
    type: Literal["run"]


class Stop(_Request):
    type: Literal["stop"]


class SingleCycle(_Request):
    """One scan of a stopped simulation (or the rest of the current scan when halted)."""

    type: Literal["single_cycle"]


class TraceTrigger(_Request):
    """When a trace starts recording: at the first scan that ends with ``path`` past the condition.

    ``rising``/``falling``: a BOOL that was FALSE/TRUE at the end of the previous scan (or when the
    trace started) and is TRUE/FALSE now. ``cross_up``/``cross_down``: a numeric variable that was
    below/above ``level`` and is now at or above/at or below it. That scan is the first sample."""

    path: str
    condition: Literal["rising", "falling", "cross_up", "cross_down"] = "rising"
    level: float | None = Field(default=None, description="The level of cross_up/cross_down (TIME in ms).")

    @model_validator(mode="after")
    def _level_for_crossings(self) -> TraceTrigger:
        crossing = self.condition.startswith("cross")
        if crossing and self.level is None:
            raise ValueError(f"a {self.condition} trigger needs a level")
        if not crossing and self.level is not None:
            raise ValueError(f"a {self.condition} trigger has no level (it watches a BOOL)")
        return self


class TraceStart(_Request):
    """Record ``paths`` (BOOL and numeric) after every scan, streamed in ``trace_data`` chunks.

    Recording starts at once, or at the scan that fires ``trigger``; it ends after ``samples``
    samples, or (``samples`` null) at ``trace_stop``. A new trace of a client replaces its
    running one; ``id`` is echoed in every chunk, so the client can ignore chunks of the old one."""

    type: Literal["trace_start"]
    id: int = 0
    paths: list[str] = Field(min_length=1, max_length=MAX_TRACE_PATHS)
    samples: int | None = Field(default=None, ge=1, le=MAX_TRACE_SAMPLES)
    trigger: TraceTrigger | None = None


class TraceStop(_Request):
    """End this client's trace: the next ``trace_data`` chunk holds the last samples and ``state`` done."""

    type: Literal["trace_stop"]


ClientMessage = Annotated[
    Subscribe
    | Write
    | Force
    | Unforce
    | UnforceAll
    | BreakpointSet
    | BreakpointClear
    | Continue
    | Step
    | Run
    | Stop
    | SingleCycle
    | TraceStart
    | TraceStop,
    Field(discriminator="type"),
]


# --------------------------------------------------------------------------- server -> client


class At(BaseModel):
    """Where the scan halted or a fault happened."""

    pou: str
    instance: str | None = Field(default=None, description="POU instance path; null inside a FUNCTION.")
    network: str | None = None
    element: str | None = None
    line: int | None = None
    column: int | None = None


class DisplayType(BaseModel):
    """What a client needs to show a value as IEC text: TIME and dates arrive as ms, enumerations as ints."""

    name: str = Field(
        description="The IEC elementary type (TIME, DATE, WORD...; a subrange's base type), "
        "or the name of the enumeration, structure or FB type."
    )
    names: dict[str, str] | None = Field(default=None, description="An enumeration's value names by value.")


class Values(BaseModel):
    """What changed in this client's subscription since the previous ``values`` message to it.

    The first message after a ``subscribe`` holds every subscribed value. ``power`` is keyed
    ``<pou_instance>/<element id>`` (the instance as subscribed); a null state means the element
    did not execute in the last scan (e.g. skipped by a jump or EN FALSE), else it is the
    element's output: its power flow, or a box pin's value."""

    model_config = ConfigDict(ser_json_inf_nan="strings")

    type: Literal["values"]
    scan: int
    time_ms: float
    changed: dict[str, Value]
    forced: list[str] = Field(description="Every forced variable (canonical paths), whether subscribed or not.")
    power: dict[str, Value]
    types: dict[str, DisplayType] = Field(
        default_factory=dict,
        description="The type of every subscribed path, in the first message after a subscribe (paths as in changed).",
    )


class Status(BaseModel):
    """The simulation's state: sent on connecting and whenever it changes. ``faulted`` is a stop by a fault."""

    type: Literal["status"]
    state: Literal["running", "stopped", "halted", "faulted"]
    at: At | None = None


class TraceTriggered(BaseModel):
    """The scan that fired a trace's trigger (its first sample)."""

    scan: int
    time_ms: float


class TraceData(BaseModel):
    """New samples of this client's trace since its previous chunk, sent at its monitor interval.

    This replaces the single ``trace`` message sent once a trace was complete: a chart must update
    while the trace records. A chunk is sent when there are new samples or the state changed (the
    first one at once, naming the canonical paths). ``values`` holds one list per traced path, in
    the order of ``trace_start`` (repeats removed), each as long as ``scans`` and ``time_ms``.
    ``triggered`` is set in the chunk in which the trigger fired; ``lost`` counts samples dropped
    because the client did not take them in time (more than 10,000 waiting)."""

    model_config = ConfigDict(ser_json_inf_nan="strings")

    type: Literal["trace_data"]
    id: int
    state: Literal["waiting", "recording", "done"] = Field(description="waiting: for the trigger.")
    scans: list[int]
    time_ms: list[float]
    values: dict[str, list[Value]]
    triggered: TraceTriggered | None = None
    lost: int = 0


#: What an online log entry is about, so the log can be filtered (seed ON-15).
LogKind = Literal["state", "write", "force", "release", "breakpoint", "watchdog", "fault", "system"]
LogLevel = Literal["info", "warning", "error"]


class Log(BaseModel):
    """An entry of the online log (ON-15): run/stop, writes, forces set and released, breakpoint hits,
    watchdog trips, runtime errors, and notes of the server (``system``: dropped messages, deletion)."""

    type: Literal["log"]
    kind: LogKind = "system"
    level: LogLevel
    message: str
    at: At | None = None
    scan: int | None = None
    time_ms: float | None = None


#: Why a websocket request was refused (protocol codes, not diagnostics: docs/diagnostics.md).
ErrorCode = Literal["bad_json", "bad_message", "bad_path", "bad_value", "bad_state", "too_large", "too_many"]


class Error(BaseModel):
    """A request of this client was refused; the connection and the simulation carry on."""

    type: Literal["error"]
    code: ErrorCode
    message: str


ServerMessage = Annotated[Values | Status | TraceData | Log | Error, Field(discriminator="type")]


class MonitorProtocol(BaseModel):
    """Container so both directions land in one schema file (``monitor.schema.json``)."""

    client: ClientMessage
    server: ServerMessage
