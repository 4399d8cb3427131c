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

from pydantic import ConfigDict, Field, model_validator

from .base import Model
from .faults import FaultMode

#: A value a client may write or force: a JSON scalar, or IEC literal text (``'T#1s'``, ``'16#FF'``).
WriteValue = bool | int | float | str
#: A value the server reports: elementary values as JSON scalars (TIME and dates as integer ms, non-finite
#: REALs as the strings "NaN", "Infinity", "-Infinity"), arrays as lists, structures and FBs as objects.
Value = bool | int | float | str | None | list[Any] | dict[str, Any]

MIN_INTERVAL_MS = 20
MAX_INTERVAL_MS = 1000
MAX_TRACE_PATHS = 20
MAX_TRACE_SAMPLES = 10_000
#: The time scale of a running simulation, times real time (the virtual clock is the same at any scale).
MIN_SPEED = 0.1
MAX_SPEED = 100.0


class _Request(Model):
    model_config = ConfigDict(extra="forbid")


# --------------------------------------------------------------------------- client -> server


class ElementSubscription(Model):
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
    body: str | None = Field(
        default=None,
        description="In an SFC POU: the action or named transition the network or line is in "
        "(actions/<name>, transitions/<name>); null for the POU's body or chart.",
    )


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
    body: str | None = None

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
    """Run to the next network (LD/FBD), statement (ST; networks in diagrams), SFC transition that fires (over as
    many scans as it takes) or the end of the scan.

    ``statement`` steps into calls; ``over`` goes to the next statement or network of the halted POU
    (or of its caller once it returns), passing over the calls it makes; ``out`` runs until the caller
    of the halted POU goes on. A breakpoint on the way halts first."""

    type: Literal["step"]
    granularity: Literal["network", "statement", "over", "out", "transition", "cycle"] = "statement"


class Run(_Request):
    type: Literal["run"]


class Stop(_Request):
    type: Literal["stop"]


class SingleCycle(_Request):
    """One scan of a stopped simulation (or the rest of the current scan when halted)."""

    type: Literal["single_cycle"]


class PanelInput(_Request):
    """A panel widget's action (a press, a release, a new value): written to ``path`` at the start of the next
    scan, as a recorded input event; queued while the simulation is stopped or halted. At most one panel
    event per variable applies at a scan start, so a click shorter than a scan still lasts one scan."""

    type: Literal["panel"]
    path: str
    value: WriteValue
    panel: str | None = Field(default=None, max_length=64, description="The panel's name (for the log).")
    widget: str | None = Field(default=None, max_length=64, description="The widget's id (for the log).")


class Inject(_Request):
    """Inject a fault into a signal between plant and program, from the next scan on (a recorded input event):
    ``stuck_true``/``stuck_false`` (BOOL), ``stuck`` (a number held at ``value``, default its value now),
    ``open`` (an open circuit reads FALSE or 0), ``noisy`` (a BOOL flips with probability ``rate``, default 0.1;
    a number strays by up to ``amplitude``, default 1.0; from a generator seeded by ``seed``, chosen by the
    server when not given, so the noise is the same on replay)."""

    type: Literal["inject"]
    path: str
    mode: FaultMode
    value: WriteValue | None = None
    amplitude: float | None = Field(default=None, ge=0)
    rate: float | None = Field(default=None, ge=0, le=1)
    seed: int | None = Field(default=None, ge=0, le=2**31 - 1)


class InjectClear(_Request):
    """Remove the fault injected into ``path`` (every injected fault when no path), from the next scan on."""

    type: Literal["inject_clear"]
    path: str | None = None


class Speed(_Request):
    """Pace the scans at ``scale`` times real time (0.1 to 100); the virtual clock and every value are the same."""

    type: Literal["speed"]
    scale: float = Field(ge=MIN_SPEED, le=MAX_SPEED)


class RunUntil(_Request):
    """Run until ``condition`` holds after a scan (``Motor``, ``NOT Alarm``, ``Tank.Level >= 80``, ``T1.ET > T#2s``)
    or until every scan due by virtual ``time_ms`` has run; then stop. Exactly one of them."""

    type: Literal["run_until"]
    condition: str | None = Field(default=None, max_length=400)
    time_ms: float | None = Field(default=None, gt=0)

    @model_validator(mode="after")
    def _one(self) -> RunUntil:
        if (self.condition is None) == (self.time_ms is None):
            raise ValueError("give a condition or a time_ms (one of them)")
        return self


class Seek(_Request):
    """Show scan ``scan`` as it was (issue 23): the values and the power flow that scan computed, recomputed from
    the scan history. Scans are numbered as ``values.scan`` numbers them. The live scans go on; ``live`` returns."""

    type: Literal["seek"]
    scan: int = Field(ge=0)
    branch: int | None = Field(default=None, ge=1, description="An earlier branch of the history (default: live).")


class Fork(_Request):
    """Continue from the scan shown (after a ``seek``): the simulation takes that scan's state, stopped, and
    records a new branch of the history; the branch it leaves stays viewable (``seek`` with its ``branch``)."""

    type: Literal["fork"]


class Live(_Request):
    """Show the live scans again after a ``seek``."""

    type: Literal["live"]


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
    | TraceStop
    | PanelInput
    | Inject
    | InjectClear
    | Speed
    | RunUntil
    | Seek
    | Live
    | Fork,
    Field(discriminator="type"),
]


# --------------------------------------------------------------------------- server -> client


class At(Model):
    """Where the scan halted or a fault happened."""

    pou: str
    instance: str | None = Field(default=None, description="POU instance path; null inside a FUNCTION.")
    network: str | None = None
    element: str | None = None
    line: int | None = None
    column: int | None = None
    body: str | None = Field(default=None, description="In an SFC POU: actions/<name> or transitions/<name>.")


class DisplayType(Model):
    """What a client needs to show a value as IEC text: TIME and dates arrive as ms, enumerations as ints."""

    name: str = Field(
        description="The IEC elementary type (TIME, DATE, WORD...; a subrange's base type), "
        "or the name of the enumeration, structure or FB type."
    )
    names: dict[str, str] | None = Field(
        default=None, description="An enumeration's value names by value, spelled as declared (writes take any case)."
    )


class StackVariable(Model):
    """A variable of a FUNCTION's or METHOD's call in a halted scan: it lives for that call only, so no path
    reaches it. ``value`` as in ``values.changed`` (shown as ``type`` says); none, with ``reason``, when it
    cannot be read exactly."""

    model_config = ConfigDict(ser_json_inf_nan="strings")

    name: str = Field(description="As declared; the result is named like the function, method or property.")
    kind: Literal["input", "output", "in_out", "var", "temp", "result"]
    type: DisplayType
    value: Value = None
    reason: str | None = Field(default=None, description="Why no value is shown.")


class CallFrame(Model):
    """One POU call a halted scan stands in (the call stack, outermost first; ON-03): ``at`` is where it stands -
    the halt point in the last one, the call it makes in the others - in its POU (a method as ``<FB>.<M>``) and
    instance (a method's too); ``variables`` are a FUNCTION's or METHOD's own."""

    kind: Literal["program", "function_block", "function", "method"]
    at: At
    variables: list[StackVariable] = Field(
        default_factory=list, description="A FUNCTION's or METHOD's inputs, outputs, in-outs, VAR, VAR_TEMP, result."
    )


class HistoryStepPoint(Model):
    """Where a step through the scan shown (``POST .../history/step``) stands."""

    at: At | None = Field(default=None, description="The network or line it halted before; null: the scan ended.")
    stack: list[CallFrame] = Field(
        default_factory=list, description="The POU calls the step stands in, outermost first (as a halt's ``stack``)."
    )


class HistoryRange(Model):
    """The scans the scan history can show (numbered as ``values.scan``), and the one shown (null: live)."""

    first: int = Field(description="The oldest scan kept (older ones were dropped for the memory budget).")
    last: int = Field(description="The newest scan: the live one.")
    viewing: int | None = Field(default=None, description="The scan shown instead of the live one; null: live.")
    bytes: int = Field(default=0, description="Memory the history holds: checkpoints and input log.")
    budget_bytes: int = Field(default=0, description="Its budget (the server's history_mb).")
    marked: int = Field(default=0, description="Grows when a scan gets a mark: fetch history/marks again.")
    branch: int = Field(default=1, description="The live branch (a fork, continue from here, starts a new one).")
    viewing_branch: int | None = Field(default=None, description="The branch of the scan shown; null: live.")
    recording: bool = Field(
        default=False,
        description="An opened recording, history only: no scan runs and no input applies until a continue from "
        "one of its scans (fork).",
    )
    stepping: HistoryStepPoint | None = Field(
        default=None, description="The scan shown is being stepped through; null: it is shown complete."
    )


class Values(Model):
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
    injected: dict[str, str] = Field(
        default_factory=dict, description="Every variable with an injected fault (canonical paths): the fault's mode."
    )
    power: dict[str, Value]
    types: dict[str, DisplayType] = Field(
        default_factory=dict,
        description="The type of every subscribed path, in the first message after a subscribe (paths as in changed).",
    )
    history: HistoryRange | None = Field(
        default=None,
        description="The scan history; while ``viewing`` is set, scan, time_ms, changed, power, forced and "
        "injected are those of that past scan.",
    )


class Status(Model):
    """The simulation's state: sent on connecting and whenever it changes. ``faulted`` is a stop by a fault."""

    type: Literal["status"]
    state: Literal["running", "stopped", "halted", "faulted"]
    at: At | None = None
    stack: list[CallFrame] = Field(
        default_factory=list, description="While halted: the POU calls the scan stands in, outermost first."
    )


class TraceTriggered(Model):
    """The scan that fired a trace's trigger (its first sample)."""

    scan: int
    time_ms: float


class TraceData(Model):
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
    types: dict[str, DisplayType] = Field(
        default_factory=dict,
        description="In a trace's first chunk: how to show each path's values (an enumeration's names), as the "
        "first values message after a subscribe says; empty in the others.",
    )


#: What an online log entry is about, so the log can be filtered (seed ON-15).
LogKind = Literal["state", "write", "force", "release", "panel", "inject", "breakpoint", "watchdog", "fault", "system"]
LogLevel = Literal["info", "warning", "error"]


class Log(Model):
    """An entry of the online log (ON-15): run/stop, writes, forces set and released, panel events and injected
    faults (``panel``, ``inject``: at the scan they applied), breakpoint hits, watchdog trips, runtime errors,
    and notes of the server (``system``: dropped messages, deletion)."""

    type: Literal["log"]
    kind: LogKind = "system"
    level: LogLevel
    message: str
    at: At | None = None
    scan: int | None = None
    time_ms: float | None = None


#: Why a websocket request was refused (protocol codes, not diagnostics: docs/diagnostics.md).
ErrorCode = Literal["bad_json", "bad_message", "bad_path", "bad_value", "bad_state", "too_large", "too_many"]


class Error(Model):
    """A request of this client was refused; the connection and the simulation carry on."""

    type: Literal["error"]
    code: ErrorCode
    message: str


ServerMessage = Annotated[Values | Status | TraceData | Log | Error, Field(discriminator="type")]


class MonitorProtocol(Model):
    """Container so both directions land in one schema file (``monitor.schema.json``)."""

    client: ClientMessage
    server: ServerMessage
