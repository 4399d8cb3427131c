"""Runtime faults: from a Python exception in generated code back to the POU, origin and values.

Each generated line is tagged with the origin of the statement it belongs to
(``Source.line_origins``); the deepest traceback frame in the generated module
gives the line, hence the ST line/column or the network/element. The values
reported are those of the variables the failing statement mentions, read from
that frame (the instance, the function's locals, the globals).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from types import FrameType

from ...ir import nodes as ir
from ...ir import types as t
from ...model.codes import RUNTIME_FAULT
from ...model.diagnostics import Diagnostic
from ...model.places import ProjectPlaces
from ..errors import OUT_OF_MEMORY, WATCHDOG, PlcRuntimeError
from .frame_reader import FrameReader
from .mentions import statement_vars, var_text
from .module import Generated
from .runtime import WatchdogTimeout, reference_text


@dataclass(frozen=True)
class Fault:
    """Why and where a task stopped.

    ``kind``: ``runtime_error`` (an IEC fault: ``code`` is division_by_zero,
    index_out_of_range, subrange_violation, for_step_zero; or out_of_memory), ``watchdog``, or
    ``internal_error`` (an unexpected exception in generated code; ``code`` is
    the exception's class name). ``origin`` is the failing statement's origin,
    ``instance`` the path of the POU instance (None inside a function),
    ``values`` the variables the statement mentions (IEC text -> value).
    """

    kind: str
    code: str
    message: str
    task: str
    time_ms: float
    scan: int
    pou: str | None = None
    instance: str | None = None
    origin: ir.Origin | None = None
    values: dict[str, object] = field(default_factory=dict)
    place: str | None = None  # an LD/FBD origin in the user's words: network 2 "Timer", TON T1

    def where(self) -> str:
        if self.origin is None:
            return f"POU {self.pou}" if self.pou else "unknown location"
        o = self.origin
        parts = [f"POU {o.pou}"]
        if o.body is not None:
            parts.append(o.body.replace("s/", " ", 1))  # actions/Fill -> action Fill
        if o.line is not None:
            parts.append(f"line {o.line}" + (f" column {o.column}" if o.column is not None else ""))
        if self.place is not None:
            parts.append(self.place)
        else:
            parts += [f"network {o.network}"] if o.network is not None else []
            parts += [f"element {o.element}"] if o.element is not None else []
        return ", ".join(parts)

    def text(self) -> str:
        shown = "; ".join(f"{k} = {v!r}" for k, v in self.values.items())
        return (
            f"{self.message} at {self.where()}"
            + (f" (instance {self.instance})" if self.instance else "")
            + f", task {self.task}, scan {self.scan}, t = {self.time_ms:g} ms"
            + (f"; {shown}" if shown else "")
        )

    def diagnostic(self) -> Diagnostic:
        o = self.origin or ir.Origin(self.pou or "")
        return Diagnostic(
            code=RUNTIME_FAULT,
            message=self.text(),
            file=f"{o.pou}/{o.body}" if o.body is not None else None,
            pou=self.pou,
            line=o.line,
            column=o.column,
            end_line=o.end_line,
            end_column=o.end_column,
            network=o.network,
            element=o.element,
            place=self.place,
        )


def make_fault(
    error: BaseException,
    generated: Generated,
    filename: str,
    ns: dict,
    *,
    task: str,
    time_ms: float,
    scan: int,
    instance_path: Callable[[object], str | None],
    places: ProjectPlaces | None = None,
) -> Fault:
    frame, lineno = _deepest_generated_frame(error, filename)
    oid = (
        error.origin
        if isinstance(error, WatchdogTimeout)
        else (
            generated.line_origins[lineno - 1]
            if frame is not None and 0 < lineno <= len(generated.line_origins)
            else None
        )
    )
    origin = generated.origins[oid] if oid is not None else None
    if isinstance(error, PlcRuntimeError):
        kind = "watchdog" if error.code == WATCHDOG else "runtime_error"
        code, message = error.code, error.message
    elif isinstance(error, MemoryError):  # a simulation process runs under a memory limit (simulation/worker.py)
        kind, code, message = "runtime_error", OUT_OF_MEMORY, "out of memory: the scan needs more memory than allowed"
    else:
        kind, code, message = "internal_error", type(error).__name__, f"internal error: {type(error).__name__}: {error}"
    values: dict[str, object] = {}
    instance = None
    if frame is not None and origin is not None:
        reader = FrameReader(generated.context, frame, ns, origin.pou)
        statement = generated.origin_statements[oid] if oid is not None else None
        for var, pointer in _with_pointers(statement_vars(statement) if statement is not None else []):
            try:
                value = reader.read(var)
            except Exception:
                continue
            if pointer or isinstance(var.type, t.Reference):
                values[var_text(var)] = reference_text(value)
            elif not isinstance(value, (list, tuple)) and not hasattr(value, "__slots__"):
                values[var_text(var)] = value
        me = frame.f_locals.get("self")
        instance = instance_path(me) if me is not None else None
    place = None
    if places is not None and origin is not None and origin.network is not None:
        place = places.where(origin.pou, origin.network, origin.element)
    pou = origin.pou if origin else None
    return Fault(kind, code, message, task, time_ms, scan, pou, instance, origin, values, place)


def _deepest_generated_frame(error: BaseException, filename: str) -> tuple[FrameType | None, int]:
    last = deque(generated_lines(error, filename), maxlen=1)
    return last[0] if last else (None, 0)


def generated_lines(error: BaseException, filename: str) -> Iterator[tuple[FrameType, int]]:
    """The frames of the generated module ``error`` went through, outermost first, with the line each stood at
    (the deepest one's fault; in the others, the call under way)."""
    tb = error.__traceback__
    while tb is not None:
        if tb.tb_frame.f_code.co_filename == filename:
            yield tb.tb_frame, tb.tb_lineno
        tb = tb.tb_next


def _with_pointers(variables: list[ir.Var]) -> Iterator[tuple[ir.Var, bool]]:
    """Each variable, after the pointers it is reached through (``p`` for ``p^``, with True): a fault in a
    dereference (NULL, dangling, outside) shows the pointer's own value."""
    seen: set[ir.Var] = set()
    for var in variables:
        for i, selector in enumerate(var.path):
            pointer = ir.Var(var.scope, var.name, var.type, var.path[:i])
            if isinstance(selector, ir.Deref) and pointer not in seen and pointer not in variables:
                seen.add(pointer)
                yield pointer, True
        yield var, False
