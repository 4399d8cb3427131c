"""The one door through which anything from outside a program enters a scan: input events.

Writes, forces and releases from a user, a panel's presses, faults injected into plant signals and
warm or cold resets are all ``InputEvent``s given to ``Simulation.submit``; nothing else changes a
variable of a running program. What the engine guarantees (docs/architecture.md, "Inputs"):

1. **Applied at a scan boundary.** An event submitted between scans (the simulation stopped or
   running) is applied at the start of the next scan, before any task runs, in the order submitted.
   Forces, releases and resets act at once (forces are applied again at every scan start, so the next
   scan sees the same either way, and the value shows at once); they are recorded for that next scan.
   While a scan is halted at a breakpoint, a user's ``write`` acts at once on the halted scan too (as
   in CODESYS; so do forces and releases, and a reset ends the halted scan); every other event (a
   panel's, a fault's) waits for the next scan start.
2. **A panel event lasts a scan.** At most one panel event per variable is applied at the start of a
   scan; a later one (a release that followed its press before the scan came) waits for the next
   scan, so a click shorter than a scan is still seen by the program for one scan.
3. **Recorded with its scan.** Each applied event reaches ``Simulation.on_input`` as an
   ``AppliedInput``: the event, the number of the scan it applied in (0 for the first scan) and its
   phase (``start``, or ``halt`` with the pause point and how many halts that scan had so far). Given
   the program, the same applied inputs give the same values in every scan: the clock is virtual and
   the noise of a ``noisy`` fault comes from a generator seeded by the event's ``seed``.

``AppliedInput.to_json()`` is one line of the event files ``ladderlab run --events`` replays.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any, Literal, cast, get_args

from ..ir import types as t
from ..model.faults import FAULT_MODES, SignalKind, fault_refusal, signal_kind

InputKind = Literal["write", "force", "release", "release_all", "panel", "fault", "clear_fault", "reset"]
INPUT_KINDS: tuple[str, ...] = get_args(InputKind)

#: A BOOL with a ``noisy`` fault flips with this probability per crossing unless the event says.
DEFAULT_FLIP_RATE = 0.1
#: How far a number with a ``noisy`` fault strays (plus or minus) unless the event says.
DEFAULT_AMPLITUDE = 1.0

#: Events that act at once (a write too while a scan is halted); the others wait for the next scan start.
_AT_ONCE = frozenset({"force", "release", "release_all", "reset"})


class InputRefused(ValueError):
    """An event that cannot apply (unknown path, value of the wrong type, bad fault): the user's words."""


@dataclass(frozen=True)
class InputEvent:
    """Something from outside the program. ``value`` is as given: a JSON scalar or IEC literal text.

    ``source`` says who sent it for the log (``panel Main/Start``, ``cli``); ``mode``, ``amplitude``,
    ``rate`` and ``seed`` belong to ``fault``; ``cold`` to ``reset``."""

    kind: InputKind
    path: str | None = None
    value: object = None  # a JSON scalar or IEC literal text (checked against the variable when submitted)
    source: str | None = None
    mode: str | None = None  # a FaultMode (checked by ``check``)
    amplitude: float | None = None
    rate: float | None = None
    seed: int | None = None
    cold: bool = False

    def to_json(self) -> dict[str, object]:
        """The event's own fields (defaults left out)."""
        data: dict[str, object] = {"kind": self.kind}
        for name in ("path", "value", "source", "mode", "amplitude", "rate", "seed"):
            value = getattr(self, name)
            if value is not None:
                data[name] = value
        if self.cold:
            data["cold"] = True
        return data

    @classmethod
    def from_json(cls, data: dict[str, object]) -> InputEvent:
        """The event of one ``--events`` line (its ``scan`` and ``phase`` are the caller's); InputRefused."""
        known = {"kind", "path", "value", "source", "mode", "amplitude", "rate", "seed", "cold"}
        unknown = sorted(set(data) - known - {"scan", "phase", "halt"})
        if unknown:
            raise InputRefused(f"unknown field {unknown[0]!r} (expected {', '.join(sorted(known | {'scan'}))})")
        kind = data.get("kind")
        if kind not in INPUT_KINDS:
            raise InputRefused(f"kind must be one of {', '.join(INPUT_KINDS)}, not {kind!r}")
        fields = {name: data[name] for name in known if name in data}
        event = cls(**cast(dict[str, Any], fields))
        event.check()
        return event

    def check(self) -> None:
        """Refuse an event whose fields do not fit its kind (before it is queued)."""
        needs_path = self.kind not in ("release_all", "reset", "clear_fault")
        if needs_path and not (isinstance(self.path, str) and self.path.strip()):
            raise InputRefused(f"a {self.kind} event needs the path of a variable")
        if self.kind in ("write", "force", "panel") and self.value is None:
            raise InputRefused(f"a {self.kind} event needs a value (TRUE, 42, 1.5, 'T#2s')")
        if self.kind == "fault":
            if self.mode not in FAULT_MODES:
                raise InputRefused(f"a fault's mode must be one of {', '.join(FAULT_MODES)}, not {self.mode!r}")
            if self.mode == "noisy" and not isinstance(self.seed, int):
                raise InputRefused("a noisy fault needs a seed (an integer), so its noise is the same on replay")
            for name in ("amplitude", "rate"):
                number = getattr(self, name)
                if number is not None and not (isinstance(number, (int, float)) and math.isfinite(number)):
                    raise InputRefused(f"a fault's {name} must be a finite number, not {number!r}")
            if self.rate is not None and not 0 <= self.rate <= 1:
                raise InputRefused(f"a noisy fault's rate is a probability from 0 to 1, not {self.rate}")


@dataclass(frozen=True)
class AppliedInput:
    """An event as applied: the scan it applied in and where (``start``; ``halt`` at pause point ``pause``,
    the ``halts``-th halt of that scan)."""

    event: InputEvent
    scan: int
    phase: Literal["start", "halt"] = "start"
    pause: int | None = None
    halts: int | None = None

    def to_json(self) -> dict[str, object]:
        data: dict[str, object] = {"scan": self.scan, **self.event.to_json()}
        if self.phase == "halt":
            data["phase"] = "halt"
            data["halt"] = {"pause": self.pause, "count": self.halts}
        return data


@dataclass
class Injection:
    """A fault held on one variable: what is read there instead of the signal, where plant and program meet.

    ``coerce`` stores a number as a value of the variable (REAL rounding, the type's range)."""

    event: InputEvent
    type: t.IrType
    coerce: Callable[[object], object]
    frozen: object = None  # the value ``stuck`` holds
    rng: random.Random = field(default_factory=random.Random)
    clean: object = None  # the signal as its writer last left it
    last: tuple[object, ...] = ()  # (what this fault left there at the previous crossing,), () before the first

    def value(self, current: object, fresh: bool = False) -> object:
        """What is read where the signal crosses, given the variable's value now; a noisy fault draws once
        (seeded). Noise strays around the signal as its writer (the plant, a panel) last wrote it: a variable
        that still holds what the fault left at the previous crossing has not been written since."""
        signal = current if fresh else self.lifted(current)
        self.clean = signal
        self.last = (self._faulted(signal),)
        return self.last[0]

    def lifted(self, current: object) -> object:
        """The signal without the fault: as its writer last left it, when nothing wrote it since the fault."""
        unwritten = bool(self.last) and current == self.last[0] and type(current) is type(self.last[0])
        return self.clean if unwritten else current

    def state(self) -> tuple[object, object, tuple[object, ...]]:
        """What the fault carries from scan to scan (its generator, the signal, its last value): plain data."""
        return self.rng.getstate(), self.clean, self.last

    def set_state(self, state: tuple[object, object, tuple[object, ...]]) -> None:
        rng, self.clean, last = state
        self.rng.setstate(_tuples(rng))
        self.last = tuple(cast(Iterable[object], last))

    def _faulted(self, signal: object) -> object:
        mode, kind = self.event.mode, _kind(self.type)
        if mode == "stuck_true":
            return True
        if mode == "stuck_false" or (mode == "open" and kind == "bool"):
            return False
        if mode == "open":
            return self.coerce(_within(0, self.type))
        if mode == "stuck":
            return self.frozen
        draw = self.rng.random()
        if kind == "bool":
            rate = self.event.rate if self.event.rate is not None else DEFAULT_FLIP_RATE
            return (not signal) if draw < rate else signal
        amplitude = self.event.amplitude if self.event.amplitude is not None else DEFAULT_AMPLITUDE
        assert isinstance(signal, (int, float))  # a number: ``injection`` refuses faults on other types
        noisy = signal + (2.0 * draw - 1.0) * amplitude
        return self.coerce(_within(noisy if kind == "real" else math.floor(noisy + 0.5), self.type))


def injection(event: InputEvent, ty: t.IrType, coerce: Callable[[object], object]) -> Injection:
    """The fault ``event`` injects into a variable of type ``ty``; InputRefused."""
    refused = fault_refusal(event.mode or "", _kind(ty), _type_name(ty))
    if refused is not None:
        raise InputRefused(refused)
    frozen = coerce(event.value) if event.mode == "stuck" else None
    return Injection(event, ty, coerce, frozen, random.Random(event.seed))


def _tuples(value: object) -> object:
    """A generator state back from plain data (lists, as JSON or a copy may make of its tuples)."""
    return tuple(_tuples(v) for v in value) if isinstance(value, (list, tuple)) else value


def _kind(ty: t.IrType) -> SignalKind | None:
    """bool, int or real for the types a fault acts on; None for the others."""
    if isinstance(ty, t.Subrange):
        return "int"
    if not isinstance(ty, t.Elementary):
        return None
    return signal_kind(ty.info.category)


def _within(number: float, ty: t.IrType) -> float:
    """``number`` held within the range of ``ty`` (a subrange's, an integer type's; REALs as they are)."""
    if isinstance(ty, t.Subrange):
        return max(ty.low, min(ty.high, number))
    assert isinstance(ty, t.Elementary)  # ``_kind`` let only elementary types and subranges through
    info = ty.info
    if info.min is None or info.max is None:
        return number
    return max(info.min, min(info.max, number))


def _type_name(ty: t.IrType) -> str:
    return getattr(ty, "name", None) or getattr(ty, "fb", None) or type(ty).__name__.lower()


def immediate(event: InputEvent, halted: bool) -> bool:
    """Whether the event acts at once instead of at the next scan start (guarantee 1)."""
    return event.kind in _AT_ONCE or (halted and event.kind == "write")
