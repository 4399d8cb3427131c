"""A simulation's state between scans, as plain data: capture it, restore it into a simulation of the same
program (another one included: a test's failure opened online, a later scan history).

    state = capture(sim)          # every variable of every program instance, global, FB instance (timers,
    restore(other, state)         # counters, edge memories: all their slots), the probes, the process image,
                                  # the clock, the tasks' next due times and stopped flags, the forces, the
                                  # attached instances

The data holds no object of the simulation's generated module: instances are dicts of their slots, arrays
lists, scalars as stored; VAR_IN_OUT references are left out (a call binds them again; an attached
instance's links are bound again by ``attach``), and so are REF_TO / POINTER TO values (restoring starts them as
declared, NULL or ``REF(x)`` of the target's own ``x``; one set by the body is set again when the body runs).
So a state pickles, and restoring needs a simulation of the same compiled program (same declarations), not the
same namespace. Restoring writes values into the target's existing objects, so every reference into them stays
valid.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from .codegen.runtime import UNSET, Ref

if TYPE_CHECKING:
    from .simulation import Simulation


class _Reference:
    """Stands for a VAR_IN_OUT reference or a REF_TO value in captured data (not restored)."""

    __slots__ = ()

    def __reduce__(self) -> str:
        return "REFERENCE"

    def __repr__(self) -> str:
        return "REFERENCE"


REFERENCE = _Reference()
_SCALARS = (bool, int, float, str, bytes)


@dataclass(frozen=True)
class SimState:
    declarations: str  # the program's declarations: a state only fits a simulation with the same ones
    time_ms: float
    now: float
    scan_count: int
    stamp: int  # scans started: the probes' record of what ran in the last scan refers to it
    tasks: tuple[tuple[float, bool, bool], ...]  # each task's next due time, stopped flag and SINGLE input seen
    instances: dict[str, object]  # program or attached instance name -> its slots
    globals: dict[str, object]  # global page -> its slots (program instances among them)
    image: dict[str, bytes] = field(default_factory=dict)  # the process image's buffers (ProcessImage.state)
    forces: dict[str, object] = field(default_factory=dict)  # canonical path -> forced value
    attached: dict[str, tuple[str, dict[str, str]]] = field(default_factory=dict)  # name -> (POU, links)
    #: canonical path -> (the fault's event as JSON, what it carries between scans: Injection.state())
    injections: dict[str, tuple[dict, object]] = field(default_factory=dict)
    pending: tuple[dict, ...] = ()  # inputs waiting for the next scan start, as JSON, in order


def capture(sim: Simulation) -> SimState:
    return sim.state()


def restore(sim: Simulation, state: SimState) -> None:
    sim.restore(state)


def data_of(value: object) -> object:
    """Plain data of a stored value: instances and structures as dicts of their slots, arrays as lists."""
    if isinstance(value, _SCALARS) or value is UNSET:
        return value
    if value.__class__ is list:
        return [data_of(item) for item in value]
    if value.__class__ is tuple or isinstance(value, Ref):  # a VAR_IN_OUT reference (container, key), a REF_TO
        return REFERENCE
    names = [*_slot_names(type(value)), *getattr(value, "__dict__", ())]
    return {name: data_of(getattr(value, name)) for name in names if hasattr(value, name)}


def restore_into(target: object, data: dict) -> None:
    """Write captured slot data into an existing instance or structure, recursively, in place."""
    for name, value in data.items():
        if value is REFERENCE:
            continue
        if isinstance(value, dict):
            restore_into(getattr(target, name), value)
        elif isinstance(value, list):
            _restore_list(getattr(target, name), value)
        else:
            setattr(target, name, value)


def _restore_list(target: list, data: list) -> None:
    for index, value in enumerate(data):
        if isinstance(value, dict):
            restore_into(target[index], value)
        elif isinstance(value, list):
            _restore_list(target[index], value)
        elif value is not REFERENCE:
            target[index] = value


def _slot_names(cls: type) -> list[str]:
    names: list[str] = []
    for klass in reversed(cls.__mro__):
        slots = klass.__dict__.get("__slots__", ())
        names += [slots] if isinstance(slots, str) else [s for s in slots if s not in ("__dict__", "__weakref__")]
    return names
