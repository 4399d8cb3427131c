"""A simulation's state between scans, as plain data: capture it, restore it into a simulation of the same
program (another one included: a test's failure opened online, a later scan history).

    state = capture(sim)          # every variable of every program instance, global, FB instance (timers,
    restore(other, state)         # counters, edge memories: all their slots), the probes, the process image,
                                  # the clock, the tasks' next due times and stopped flags, the forces, the
                                  # attached instances

The data holds no object of the simulation's generated module: instances are their slots' paths and values
(read and written by code generated per class: ``_Plan``, ``_setter``), arrays lists, scalars as stored, and
the FUNCTION POUs' probe lists; VAR_IN_OUT references are left out (a call binds them again; an attached
instance's links are bound again by ``attach``), and so are REF_TO / POINTER TO values (restoring starts them as
declared, NULL or ``REF(x)`` of the target's own ``x``; one set by the body is set again when the body runs).
So a state pickles, and restoring needs a simulation of the same compiled program (same declarations), not the
same namespace. Restoring writes values into the target's existing objects, so every reference into them stays
valid.
"""

from __future__ import annotations

import functools
import keyword
import operator
import weakref
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from .codegen.runtime import UNSET, FramedPair, Ref

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
    declarations: str  # the digest of the program's declarations: a state only fits a program with the same ones
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
    functions: dict[str, object] = field(default_factory=dict)  # FUNCTION POUs' probe lists by name (monitoring)
    #: probe-view key -> the elements a fault stopped in the last scan (``engine/stopped.py``; monitoring)
    stopped: dict[str, frozenset[str]] = field(default_factory=dict)


def capture(sim: Simulation) -> SimState:
    return sim.state()


def restore(sim: Simulation, state: SimState) -> None:
    sim.restore(state)


def data_of(value: object) -> object:
    """Plain data of a stored value: arrays as lists; instances and structures as ``(names, values, nested)``
    (see ``_Plan``) or, with a ``__dict__``, as a dict of their attributes' data."""
    if value.__class__ in _SCALAR_TYPES:
        return value
    if value.__class__ is list:
        if _SCALAR_TYPES.issuperset(map(type, value)):  # in C: an array of scalars or a probe list, copied whole
            return value.copy()
        return [data_of(item) for item in value]
    if value.__class__ is tuple or isinstance(value, (Ref, FramedPair)):  # a VAR_IN_OUT reference, a REF_TO
        return REFERENCE
    if isinstance(value, _SCALARS):
        return value
    if hasattr(value, "__dict__"):
        names = [*_slot_names(type(value)), *value.__dict__]
        return {name: data_of(getattr(value, name)) for name in names if hasattr(value, name)}
    return _slots_data(value)


def _slots_data(value: object) -> tuple[tuple[str, ...], tuple[object, ...], dict[str, object]]:
    plan = _PLANS.get(value.__class__)
    values = plan.read(value) if plan is not None else None
    if values is None:
        plan = _learn(value, plan)
        values = plan.read(value)
        assert values is not None  # the plan was learnt from this value
    nested = {}
    for path in plan.structured:
        item = _follow(value, path)
        nested[path] = REFERENCE if item is _MISSING else data_of(item)  # never assigned: not restored either
    return plan.leaves, values, nested


def holds_references(data: object) -> bool:
    """Whether captured data left a value out (a reference, a slot never assigned): restoring it then needs the
    target initialised first, so what was left out starts as declared whatever the target did before."""
    if data is REFERENCE:
        return True
    if isinstance(data, tuple):
        return any(holds_references(item) for item in data[2].values())
    if isinstance(data, dict):
        return any(holds_references(item) for item in data.values())
    if isinstance(data, list) and not _SCALAR_TYPES.issuperset(map(type, data)):
        return any(holds_references(item) for item in data)
    return False


class _Plan:
    """How to read an instance class's state fast: ``leaves``, the paths of its scalar slots and of the scalar
    slots of the instances nested in it (``T1.Q``: an FB instance's outputs), all read by one generated
    function (``_generated``; no Python call per FB instance: the generic walk made a checkpoint of 10,000 LD
    networks cost 50 ms), and ``structured``, the paths read one by one (arrays, references, slots never
    assigned).

    The plan is learnt from the values met: when a leaf holds something else than a scalar, the plan is learnt
    again with that path structured, so plans only widen and every instance of a class soon shares one
    (and one ``leaves`` tuple, which a history pickles once: simulation/history.py)."""

    __slots__ = ("_get", "leaves", "structured")

    def __init__(self, leaves: list[str], structured: list[str]) -> None:
        self.leaves = tuple(leaves)
        self.structured = tuple(structured)
        self._get = _generated("def get(o):\n    return (" + "".join(f"o.{path}, " for path in leaves) + ")\n", leaves)

    def read(self, value: object) -> tuple[object, ...] | None:
        """The leaves' values, or None when one is missing or no longer a scalar (learn the plan again)."""
        try:
            values: tuple[object, ...] = self._get(value)  # type: ignore[assignment]  # the generated getter
        except AttributeError:
            return None
        return values if {*map(type, values)} <= _SCALAR_TYPES else None  # (issuperset of an iterator is slower)


def _learn(value: object, old: _Plan | None) -> _Plan:
    """A plan for ``value``'s class: its leaves as they hold now, without those an earlier plan found to vary."""
    varying = set(old.structured) if old is not None else set()
    if old is not None:
        varying |= {path for path in old.leaves if _follow(value, path).__class__ not in _SCALAR_TYPES}
    leaves: list[str] = []
    structured: list[str] = []
    _walk(value, "", varying, leaves, structured)
    plan = _PLANS[value.__class__] = _Plan(leaves, structured)
    return plan


def _walk(value: object, prefix: str, varying: set[str], leaves: list[str], structured: list[str]) -> None:
    for name in _slot_names(type(value)):
        path = prefix + name
        item = getattr(value, name, _MISSING)
        if path in varying or item is _MISSING:
            structured.append(path)
        elif item.__class__ in _SCALAR_TYPES:
            leaves.append(path)
        elif _nestable(item):
            _walk(item, path + ".", varying, leaves, structured)
        else:
            structured.append(path)


def _nestable(item: object) -> bool:
    """An instance whose slots can be leaves of the one holding it (an FB instance, a structure)."""
    return not (
        isinstance(item, (list, tuple, Ref, *_SCALARS)) or hasattr(item, "__dict__")  # Ref: and a moved pointer
    ) and bool(_slot_names(type(item)))


def _follow(value: object, path: str) -> object:
    """The value at a dotted slot path, or _MISSING."""
    try:
        return operator.attrgetter(path)(value)
    except AttributeError:
        return _MISSING


class PathTable:
    """Slot-path tuples (``_Plan.leaves``) by number, for a store of many states of one program (a scan history):
    ``shared`` states name them by their number instead of holding them, as every pickle would hold them whole
    (in a large program, most of a checkpoint's bytes and of its pickling time)."""

    def __init__(self) -> None:
        self._paths: list[tuple[str, ...]] = []
        self._numbers: dict[int, int] = {}  # id of a tuple in _paths -> its number

    def shared(self, state: SimState) -> SimState:
        """``state`` with the slot paths of its instances and their nested instances replaced by numbers."""
        return replace(
            state,
            instances={name: self._share(data) for name, data in state.instances.items()},
            globals={page: self._share(data) for page, data in state.globals.items()},
        )

    def unshared(self, state: SimState) -> SimState:
        """The state ``shared`` was given."""
        return replace(
            state,
            instances={name: self._unshare(data) for name, data in state.instances.items()},
            globals={page: self._unshare(data) for page, data in state.globals.items()},
        )

    def _share(self, data: object) -> object:
        if not isinstance(data, tuple):
            return data
        paths, values, nested = data
        number = self._numbers.get(id(paths))
        if number is None:
            number = self._numbers[id(paths)] = len(self._paths)
            self._paths.append(paths)  # kept, so its id stays its own
        return number, values, {path: self._share(item) for path, item in nested.items()}

    def _unshare(self, data: object) -> object:
        if not isinstance(data, tuple):
            return data
        number, values, nested = data
        return self._paths[number], values, {path: self._unshare(item) for path, item in nested.items()}


def restore_into(target: object, data: object) -> None:
    """Write captured instance data (``data_of``'s) into an existing instance or structure, recursively, in
    place."""
    if isinstance(data, tuple):
        names, values, nested = data
        _setter(names)(target, values)
        items = nested.items()
    else:
        items = data.items()  # type: ignore[attr-defined]  # the data of an instance with a __dict__
    for path, value in items:
        if value is REFERENCE:
            continue
        if isinstance(value, (tuple, dict)):
            restore_into(operator.attrgetter(path)(target), value)
        elif isinstance(value, list):
            restore_list(operator.attrgetter(path)(target), value)
        else:
            owner, _, name = path.rpartition(".")
            setattr(operator.attrgetter(owner)(target) if owner else target, name, value)


def restore_list(target: list, data: list) -> None:
    """Write captured list data (an array, a probe list) into an existing list, in place."""
    if _SCALAR_TYPES.issuperset(map(type, data)):
        target[:] = data  # in place: references into the list stay valid
        return
    for index, value in enumerate(data):
        if isinstance(value, (tuple, dict)):
            restore_into(target[index], value)
        elif isinstance(value, list):
            restore_list(target[index], value)
        elif value is not REFERENCE:
            target[index] = value


@functools.lru_cache(maxsize=4096)  # one per class of the programs restored lately
def _setter(paths: tuple[str, ...]) -> Callable[[object, tuple[object, ...]], None]:
    """A function assigning ``values`` to the slot paths ``paths`` in one statement (``o.a, o.T1.Q, ... =
    values``): ten times faster than a setattr per slot."""
    body = "".join(f"o.{path}, " for path in paths) + "= values" if paths else "pass"
    return _generated(f"def set(o, values):\n    {body}\n", paths)


def _generated(source: str, paths: Iterable[str]) -> Callable[..., Any]:
    """The function ``source`` defines, reading or writing slots by their paths: generated code, because
    CPython specialises each attribute access of it (the inline caches of 3.11), where ``getattr`` by name
    misses the type attribute cache on a program of thousands of slots and costs ten times more."""
    if not all(part.isidentifier() and not keyword.iskeyword(part) for path in paths for part in path.split(".")):
        raise ValueError("a captured state's slot paths are not identifiers")
    namespace: dict[str, object] = {}
    exec(source, namespace)  # the paths are identifiers (checked above)
    # the one function the generated source defines (exec's namespace is typed dict[str, object])
    function: Callable[..., Any] = next(v for k, v in namespace.items() if k != "__builtins__")  # type: ignore[assignment]  # see above
    return function


class _Missing:
    """A slot never assigned (not a scalar: its slot is read one by one)."""


_MISSING = _Missing()
_SCALAR_TYPES = frozenset({bool, int, float, str, bytes, type(None), type(UNSET)})
_PLANS: weakref.WeakKeyDictionary[type, _Plan] = weakref.WeakKeyDictionary()  # a recompiled program's go


def _slot_names(cls: type) -> list[str]:
    names: list[str] = []
    for klass in reversed(cls.__mro__):
        slots = klass.__dict__.get("__slots__", ())
        names += [slots] if isinstance(slots, str) else [s for s in slots if s not in ("__dict__", "__weakref__")]
    return names
