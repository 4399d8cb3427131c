"""The websocket protocol of online mode (``/api/simulations/{id}/ws``), one model per message.

Every message is a JSON object whose ``type`` names it; ``ClientMessage`` and
``ServerMessage`` are discriminated unions on that field, so a message with an
unknown ``type`` or a misspelt field is refused with an error naming it. The
browser's types are generated from these models (``shared_schema/monitor.schema.json``).

Variable paths are IEC text (``MAIN.T1.ET``, ``GVL.START`` or ``START``,
``MAIN.ARR[2]``), matched ignoring case. The server names variables in their
canonical spelling (upper-case names, as ``Simulation.location(path).path``)
in ``values.changed``, ``values.forced`` and ``trace.values``.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, Union

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
    ids: list[str] | None = Field(default=None, description="Element ids (as in the POU's JSON, pins as "
                                                            "'box.Q'); null: every element of the instance.")


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
    """Run to the next network (LD/FBD), statement (ST; networks in diagrams) or the end of the scan."""

    type: Literal["step"]
    granularity: Literal["network", "statement", "cycle"] = "statement"


class Run(_Request):
    type: Literal["run"]


class Stop(_Request):
    type: Literal["stop"]


class SingleCycle(_Request):
    """One scan of a stopped simulation (or the rest of the current scan when halted)."""

    type: Literal["single_cycle"]


class TraceStart(_Request):
    """Record ``paths`` once per scan; one ``trace`` message is sent when ``samples`` scans are recorded."""

    type: Literal["trace_start"]
    paths: list[str] = Field(min_length=1, max_length=MAX_TRACE_PATHS)
    samples: int = Field(ge=1, le=MAX_TRACE_SAMPLES)
    trigger: str | None = Field(default=None, description="A BOOL path: recording starts at the first scan "
                                                          "that ends with it TRUE after a scan with it FALSE.")


ClientMessage = Annotated[
    Union[Subscribe, Write, Force, Unforce, UnforceAll, BreakpointSet, BreakpointClear, Continue, Step, Run, Stop,
          SingleCycle, TraceStart],
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


class Status(BaseModel):
    """The simulation's state: sent on connecting and whenever it changes. ``faulted`` is a stop by a fault."""

    type: Literal["status"]
    state: Literal["running", "stopped", "halted", "faulted"]
    at: At | None = None


class Trace(BaseModel):
    """A finished trace: one value per recorded scan for every traced path."""

    model_config = ConfigDict(ser_json_inf_nan="strings")

    type: Literal["trace"]
    values: dict[str, list[Value]]
    scans: list[int]
    time_ms: list[float]


class Log(BaseModel):
    """An entry of the online log: runtime errors, watchdog trips, forces set and released."""

    type: Literal["log"]
    level: Literal["info", "warning", "error"]
    message: str
    at: At | None = None
    scan: int | None = None
    time_ms: float | None = None


class Error(BaseModel):
    """A request of this client was refused; the connection and the simulation carry on."""

    type: Literal["error"]
    code: Literal["bad_json", "bad_message", "bad_path", "bad_value", "bad_state", "too_large", "too_many"]
    message: str


ServerMessage = Annotated[Union[Values, Status, Trace, Log, Error], Field(discriminator="type")]


class MonitorProtocol(BaseModel):
    """Container so both directions land in one schema file (``monitor.schema.json``)."""

    client: ClientMessage
    server: ServerMessage
