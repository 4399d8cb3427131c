"""What generated modules call besides the standard library: the names they start with.

``namespace()`` returns the globals every generated module is executed in:
the runtime library's inline helpers (``INLINE_NAMES``), array index and
subrange checks, whole-value copy and assignment for arrays and structures,
FOR ranges, references for VAR_IN_OUT, and the standard FB classes (made
addressable so a reference can point at one of their pins).

VAR_IN_OUT references are ``(container, key)`` pairs: a list and an index, or
an object and an attribute name. Every generated class derives from
``Addressable`` so ``container[key]`` reads and writes either kind alike.
Composite values (arrays as nested lists, structures as objects) keep their
identity for their whole life - assignments copy into them - so a reference
into one stays valid.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from typing import Any

from ..errors import (
    WATCHDOG,
    PlcRuntimeError,
    check_fit,
    check_index,
    check_subrange,
    dangling_reference,
    for_step_zero,
    null_dereference,
    pointer_outside,
    pointers_unordered,
)
from ..process_image import ProcessImage
from ..stdlib import INLINE_NAMES, STANDARD_FBS
from . import names

#: The orderings of pointers (``pointer_order``).
ORDERS: dict[str, Callable[[int, int], bool]] = {
    "<": operator.lt,
    "<=": operator.le,
    ">": operator.gt,
    ">=": operator.ge,
}

#: Loop back-edges between two clock readings of the watchdog (``ll_wb``, statements.py).
WATCHDOG_EVERY = 256


class Addressable:
    """``obj[name]`` reads and ``obj[name] = v`` writes an attribute, so (obj, name) can be a reference."""

    __slots__ = ()

    def __getitem__(self, key: str) -> object:
        return getattr(self, key)

    def __setitem__(self, key: str, value: object) -> None:
        setattr(self, key, value)

    def ll_assign(self, source: Addressable) -> None:
        """Copy an FB instance's whole state into this one (an FB instance passed to a VAR_INPUT: by value).

        Nested instances, pages, arrays and structures are copied into, keeping their identity; probe lists
        (monitoring) stay the target's own."""
        for name in _state_slots(type(self)):
            mine, theirs = getattr(self, name, None), getattr(source, name, None)
            if isinstance(mine, Addressable) or is_composite_value(mine):
                assign_into(mine, theirs)
            else:
                setattr(self, name, theirs)


_NOT_STATE = frozenset({"ll_pr", "ll_px"})


def _state_slots(cls: type) -> tuple[str, ...]:
    """Every ``__slots__`` attribute of an instance class and its bases, but the monitoring ones."""
    found = _STATE_SLOTS.get(cls)
    if found is None:
        slots = [name for klass in cls.__mro__ for name in getattr(klass, "__slots__", ())]
        found = _STATE_SLOTS[cls] = tuple(name for name in slots if name not in _NOT_STATE)
    return found


_STATE_SLOTS: dict[type, tuple[str, ...]] = {}


class Structure(Addressable):
    """Base of generated structure classes: ``ll_fields`` lists the attributes to copy."""

    __slots__ = ()
    ll_fields: tuple[str, ...] = ()

    def ll_copy(self) -> Structure:
        new = self.__class__.__new__(self.__class__)
        for name in self.ll_fields:
            setattr(new, name, deep_copy(getattr(self, name)))
        return new

    def ll_assign(self, source: Structure) -> None:
        for name in self.ll_fields:
            mine = getattr(self, name)
            if is_composite_value(mine):
                assign_into(mine, getattr(source, name))
            else:
                setattr(self, name, getattr(source, name))


class Seen:
    """Base of ``views.ArrayView`` and ``views.StructView`` (an array or a STRUCT seen over other memory through a
    pointer): passed by value, it is copied into a list or a structure of its members' values, never shared with the
    memory it sees."""

    __slots__ = ()

    def ll_copy(self) -> object:
        raise NotImplementedError


def is_composite_value(value: object) -> bool:
    return value.__class__ is list or isinstance(value, Structure)


def deep_copy(value):
    """A copy of an array (nested lists) or structure that shares nothing mutable; scalars as they are."""
    if value.__class__ is list:
        if value and is_composite_value(value[0]):
            return [deep_copy(v) for v in value]
        return value[:]
    if isinstance(value, Structure | Seen):
        return value.ll_copy()
    return value


def assign_into(target, source) -> None:
    """Whole array / structure assignment (ST-21): copy ``source`` into ``target`` in place."""
    if target.__class__ is list:
        if target and is_composite_value(target[0]):
            for mine, theirs in zip(target, source):
                assign_into(mine, theirs)
        else:
            target[:] = source
    else:
        target.ll_assign(source)


def in_range(value, low: int, high: int):
    """``value``, an array (nested lists) assigned whole into an array of the subrange low..high, once every element
    lies in it; the first that does not is the fault of a direct assignment (``check_subrange``)."""
    for element in value:
        if element.__class__ is list:
            in_range(element, low, high)
        else:
            check_subrange(element, low, high)
    return value


def with_values(obj, **attributes):
    """``obj`` with the given attributes set (initial values of structures and FB instances)."""
    for name, value in attributes.items():
        setattr(obj, name, value)
    return obj


def fill(obj: object, attributes: str, value: object) -> None:
    """Set each of the space-separated ``attributes`` of ``obj`` to ``value`` (initialising runs of slots)."""
    for name in attributes.split():
        setattr(obj, name, value)


def pins(obj: object, attributes: str, pin: str, value: object) -> None:
    """Set the input ``pin`` of the FB instance in each of the space-separated ``attributes`` of ``obj`` to ``value``
    (constant inputs stored once, codegen/constant_inputs.py)."""
    for name in attributes.split():
        setattr(getattr(obj, name), pin, value)


def for_range(start: int, end: int, step: int) -> range:
    """The values a FOR loop visits (ST-70): computed up front, so a counter at its type's limit cannot wrap forever."""
    if step > 0:
        return range(start, end + 1, step)
    if step < 0:
        return range(start, end - 1, step)
    raise for_step_zero()


class Ref:
    """A REF_TO / POINTER TO value: the variable it refers to, as its ``(container, key)`` (NULL is None).

    ``r.v`` reads and assigns the variable, so ``r^`` is ``ll_deref(r, 'r').v`` in generated code. Two
    references are equal when they refer to one variable. ``text`` is the REF() it came from, for the online
    views; pickled (a worker's frames, probe values) a reference becomes that text: it never carries the
    simulation's objects out of its process."""

    __slots__ = ("c", "k", "text")

    def __init__(self, container: object, key: object, text: str) -> None:
        self.c, self.k, self.text = container, key, text

    @property
    def v(self) -> object:
        return self.c[self.k]  # type: ignore[index]  # a list, an Addressable or a process image view

    @v.setter
    def v(self, value: object) -> None:
        self.c[self.k] = value  # type: ignore[index]  # as above

    @property
    def pair(self) -> tuple[object, object]:
        """The ``(container, key)`` of a VAR_IN_OUT argument ``r^``."""
        return self.c, self.k

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Ref) and other.c is self.c and other.k == self.k

    def __hash__(self) -> int:
        return hash((id(self.c), self.k))

    def __repr__(self) -> str:
        return self.text

    def __reduce__(self) -> tuple[type[str], tuple[str]]:
        return str, (self.text,)

    def place(self, size: int) -> tuple[object, int]:
        """The variable a pointer points into (by identity) and the byte it points to there: an element of an array
        (a list; ``size`` bytes each) is a place in it, anything else the variable's start."""
        if isinstance(self.c, list) and isinstance(self.k, int):
            return id(self.c), self.k * size
        return (id(self.c), self.k), 0

    def shifted(self, offset: int, size: int, what: str) -> Ref:
        """``p + offset`` (bytes, CODESYS): ``offset / size`` elements further along the array p points into; an
        offset that is no whole number of elements, or a result outside the array (one past its end is allowed) is
        a fault. A pointer to a variable that is no array element moves nowhere: only ``p + 0``."""
        if offset == 0:
            return self
        steps, rest = divmod(offset, size)
        in_array = isinstance(self.c, list) and isinstance(self.k, int)
        length = len(self.c) if in_array else 1  # type: ignore[arg-type]  # a list
        position = (self.k if in_array else 0) + steps  # type: ignore[operator]  # an int key
        if rest or not in_array or not 0 <= position <= length:
            whole = f"{offset} bytes (not a whole number of elements)" if rest else f"{offset} bytes"
            raise pointer_outside(f"{what} moved by {whole}", position, length, size)
        origin, moved = (self.origin, self.moved + offset) if isinstance(self, ElementRef) else (self.text, offset)
        return ElementRef(self.c, position, origin, moved, getattr(self, "frame", None))


def pointer_order(left: Ref | None, right: Ref | None, left_size: int, right_size: int, op: str) -> bool:
    """``p < q`` (and ``<=``, ``>``, ``>=``): the bytes two pointers into one variable point to, compared (CODESYS
    compares addresses); pointers into different variables, or NULL, have no order here: a fault."""
    if left is None or right is None:
        raise pointers_unordered(op, reference_text(left), reference_text(right))
    (mine, at), (theirs, there) = left.place(left_size), right.place(right_size)
    if mine != theirs:
        raise pointers_unordered(op, left.text, right.text)
    return ORDERS[op](at, there)


def reference_text(value: object) -> str:
    """How the online views and snapshots show a reference: ``NULL``, or the REF() it was made by."""
    return "NULL" if value is None else str(value.text if isinstance(value, Ref) else value)


class Frame:
    """One call of a FUNCTION whose body takes REF()/ADR() of its own variables, or of a PROGRAM /
    FUNCTION_BLOCK whose body takes them of its VAR_TEMP: ``alive`` until the call returns (``end``), after which
    a reference into it dangles. POUs that take no such reference have none. ``kind``: the POU's, for the fault."""

    __slots__ = ("alive", "kind", "name")

    def __init__(self, name: str, kind: str = "FUNCTION") -> None:
        self.alive, self.name, self.kind = True, name, kind

    def end(self, result: object) -> object:
        """The call returns ``result``: its variables are gone."""
        self.alive = False
        return result


class FrameRef(Ref):
    """A reference to a variable of a FUNCTION call or a VAR_TEMP of a PROGRAM / FUNCTION_BLOCK call (``frame``):
    reading or writing it after the call returned is the fault ``dangling_reference``, never the stale value."""

    __slots__ = ("frame",)

    def __init__(self, container: object, key: object, text: str, frame: Frame) -> None:
        super().__init__(container, key, text)
        self.frame = frame

    @property
    def v(self) -> object:
        if not self.frame.alive:
            raise dangling(self.text, self.frame)
        return self.c[self.k]  # type: ignore[index]  # a list or an Addressable

    @v.setter
    def v(self, value: object) -> None:
        if not self.frame.alive:
            raise dangling(self.text, self.frame)
        self.c[self.k] = value  # type: ignore[index]  # as above

    @property
    def pair(self) -> tuple[object, object]:
        if not self.frame.alive:
            raise dangling(self.text, self.frame)
        return FramedPair(self.c, self.k, self.frame)


class FramedPair(tuple):
    """A VAR_IN_OUT argument ``(container, key)`` naming a variable of a call that has a ``frame`` (a function's
    local, a program's or FB's VAR_TEMP): a REF() the callee takes of its in-out refers to the caller's variable,
    so it dies with the caller's call (``in_out_ref``), not the callee's. A plain tuple everywhere else."""

    frame: Frame

    def __new__(cls, container: object, key: object, frame: Frame) -> FramedPair:
        pair = super().__new__(cls, (container, key))
        pair.frame = frame
        return pair


def in_out_ref(source: object, container: object, key: object, text: str) -> Ref:
    """``REF()`` of a variable reached through ``source`` (a VAR_IN_OUT's ``(container, key)``, or the pair of
    the pointer a path dereferences last): a ``FrameRef`` when that variable belongs to a call with a frame, so it
    dangles once that call returned, else a plain ``Ref``."""
    frame = getattr(source, "frame", None)
    return Ref(container, key, text) if frame is None else FrameRef(container, key, text, frame)


def dangling(text: str, frame: Frame) -> PlcRuntimeError:
    return dangling_reference(text, f"{frame.kind} {frame.name}")


class ElementRef(Ref):
    """A pointer moved by arithmetic (``p + SIZEOF(x)``) along the array (a list) its element belongs to: it may
    point one past the last element (a loop's end), but reading or writing there is a fault, never a Python error;
    ``frame``: the FUNCTION call whose variable the array is (FrameRef), or None."""

    __slots__ = ("frame", "moved", "origin")

    def __init__(self, container: list, key: int, origin: str, moved: int, frame: Frame | None = None) -> None:
        sign = "+" if moved >= 0 else "-"
        super().__init__(container, key, f"{origin} {sign} {abs(moved)}")
        self.origin, self.moved, self.frame = origin, moved, frame  # the REF()/ADR() it started from, bytes since

    @property
    def v(self) -> object:
        return self.c[self._checked()]  # type: ignore[index]  # a list

    @v.setter
    def v(self, value: object) -> None:
        self.c[self._checked()] = value  # type: ignore[index]  # a list

    @property
    def pair(self) -> tuple[object, object]:
        key = self._checked()
        return (self.c, key) if self.frame is None else FramedPair(self.c, key, self.frame)

    def _checked(self) -> int:
        if self.frame is not None and not self.frame.alive:
            raise dangling(self.text, self.frame)
        length = len(self.c)  # type: ignore[arg-type]  # a list
        if not 0 <= self.k < length:  # type: ignore[operator]  # an int key
            raise pointer_outside(f"the pointer {self.text}", self.k, length)  # type: ignore[arg-type]  # an int key
        return self.k  # type: ignore[return-value]  # an int key


def deref(ref: Ref | None, what: str) -> Ref:
    """``ref`` itself, to be read or written through; a NULL ``ref`` is a fault naming ``what``."""
    if ref is None:
        raise null_dereference(what)
    return ref


def dummy_reference(value: object) -> tuple[list, int]:
    """What an unbound VAR_IN_OUT refers to until a call binds it: a private cell holding the default."""
    return [value], 0


class WatchdogTimeout(PlcRuntimeError):
    """A task ran longer than its watchdog allows; ``origin`` is the loop or jump that noticed."""

    def __init__(self, origin: int, limit_s: float) -> None:
        super().__init__(WATCHDOG, f"watchdog: scan exceeded {limit_s:g} s")
        self.origin = origin
        self.limit_s = limit_s


class Watchdog:
    """The time budget of the running task.

    Generated loops count ``countdown[0]`` (the module's ``ll_wb``) down at every back-edge, one count
    per task scan however the loops nest or call each other, and call ``check`` when it runs out: every
    ``WATCHDOG_EVERY`` back-edges the clock is read against the deadline. ``clock`` is the time the
    scan's own thread has run (CPU time, ``time.thread_time``) unless a test passes another: a scan
    that the operating system holds back on a loaded machine is not the program's fault."""

    def __init__(self, clock: Callable[[], float], countdown: list[int]) -> None:
        self.clock = clock
        self.countdown = countdown
        self.deadline = math.inf
        self.limit_s = math.inf

    def arm(self, limit_s: float) -> None:
        self.limit_s = limit_s
        self.deadline = self.clock() + limit_s
        self.countdown[0] = WATCHDOG_EVERY

    def pause(self) -> float:
        """Time left; the clock does not run for a halted task."""
        return self.deadline - self.clock()

    def resume(self, left: float) -> None:
        self.deadline = self.clock() + left

    def check(self, origin: int) -> int:
        if self.clock() > self.deadline:
            raise WatchdogTimeout(origin, self.limit_s)
        return WATCHDOG_EVERY


class _Unset:
    """The value of a probe whose element has never executed."""

    __slots__ = ()

    def __repr__(self) -> str:
        return "UNSET"

    def __reduce__(self) -> str:
        return "UNSET"  # pickles as the one module-level UNSET (engine/state.py)


#: ``ll_unset``: what a probe list holds for an element that has not executed yet.
UNSET = _Unset()


def virtual_call(table: dict[type, Callable], inputs: int, *args: Any) -> object:
    """Call a METHOD as implemented by the function block of the instance it is called on: that instance is the
    method's first in-out (``THIS``, a ``(container, key)`` reference after its ``inputs`` input values)."""
    container, key = args[inputs]
    return table[type(container[key])](*args)


def attempt(reference: Ref | None, classes: tuple[type, ...]) -> Ref | None:
    """``?=``: ``reference`` when the instance it refers to is of one of ``classes``, else NULL (None)."""
    return reference if reference is not None and type(reference.v) in classes else None


def _addressable_fbs() -> dict[str, type]:
    return {
        name: type(name, (Addressable, cls), {"__slots__": (), "__doc__": cls.__doc__})
        for name, cls in STANDARD_FBS.items()
    }


#: The standard FB classes generated code instantiates (same behaviour, plus ``Addressable``).
FB_CLASSES: dict[str, type] = _addressable_fbs()


def namespace() -> dict[str, object]:
    """Fresh globals for executing one generated module."""
    from .addresses import AddressSpace  # (as views: it imports this module)
    from .views import pointer_add, view  # views.ViewRef derives from Ref: it imports this module

    ns: dict[str, object] = dict(INLINE_NAMES)
    ns.update(
        ll_ix=check_index,
        ll_sub=check_subrange,
        ll_in_range=in_range,
        ll_fit=check_fit,
        ll_copy=deep_copy,
        ll_assign=assign_into,
        ll_with=with_values,
        ll_fill=fill,
        ll_pins=pins,
        ll_for_range=for_range,
        ll_ref=dummy_reference,
        ll_Ref=Ref,
        ll_FrameRef=FrameRef,
        ll_Frame=Frame,
        ll_Pair=FramedPair,
        ll_io_ref=in_out_ref,
        ll_deref=deref,
        ll_ptr_add=pointer_add,
        ll_addr=AddressSpace(),  # the simulation's synthetic addresses (a pointer as a number)
        ll_seen=view,  # (not ll_view: a monitored network's local, statements.py)
        ll_inf=math.inf,
        ll_nan=math.nan,
        ll_Addressable=Addressable,
        ll_ProcessImage=ProcessImage,
        ll_Structure=Structure,
        ll_now=0,
        ll_scan=0,  # the stamp of the running scan, for probe groups (context.ProbeTable)
        ll_wb=[WATCHDOG_EVERY],  # the watchdog countdown of the running task (Watchdog, statements.py)
        ll_unset=UNSET,
        ll_virtual=virtual_call,
        ll_attempt=attempt,
    )
    ns.update({names.std_fb(name): cls for name, cls in FB_CLASSES.items()})
    return ns
