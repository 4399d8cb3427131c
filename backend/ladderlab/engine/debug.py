"""Breakpoints and stepping for the debug variant of the generated code.

Generated debug code is made of generators: at every pause point it runs
``if ll_halt[id]: yield (id, instance)``, and calls of user POUs are
``yield from``. The simulation drives the scan generator; a yield means
"halt here", so ``cycle()`` returns with the simulation halted and
``resume()`` / ``step()`` continue the same generator. This module decides
which pause points are armed in ``ll_halt``:

* breakpoints, always;
* while stepping ``statement`` (step into), ``over`` and ``out``: every ST statement and
  every network boundary (LD/FBD step by network, ON-04) - in IL every load, jump and call
  (the other lines are ``line`` points, which only breakpoints arm); ``network``: every network
  boundary; ``transition``: every SFC transition that fires, in this scan and the
  following ones until one does (``waiting_for_transition``); ``cycle``: nothing more
  (run to the end of the scan, or the next breakpoint).

``over`` and ``out`` arm what ``statement`` arms; the simulation passes over the points
inside calls made from the halted POU (``over``) or inside that POU itself (``out``):
``STEP_ENDS`` says which halts end such a step.

Breakpoints name an ST line, a network or an element of a POU; in an SFC POU also
the action or named transition (``body``: ``actions/<name>``, ``transitions/<name>``)
the line or network is in.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..ir import nodes as ir
from .codegen.context import PausePoint

GRANULARITIES = ("statement", "over", "out", "network", "transition", "cycle")
_STEPS_INTO = ("statement", "network")
_STEP_KINDS = {
    "statement": _STEPS_INTO,
    "over": _STEPS_INTO,
    "out": _STEPS_INTO,
    "network": ("network",),
    "transition": ("transition",),
    "cycle": (),
}
_ELEMENT_KINDS = ("element", "transition")
_LINE_KINDS = ("statement", "line")  # a breakpoint on a line: any statement of it, in IL the stepped-over ones too


def _within(frames: tuple, start: tuple) -> bool:
    """Whether ``frames`` (the POU calls a halt is in, outermost first) are those of ``start`` or its callers."""
    return frames == start[: len(frames)]


def _over(frames: tuple, start: tuple) -> bool:
    """Whether a step ``over`` that started in ``start`` ends at a halt in ``frames`` (both begin with the task's
    frame): in the POU call where it started, or in a caller once that call returned (not in calls made from it,
    nor in a sibling call); once the program it started in returned, in the next program its task runs. As in
    CODESYS: after a called POU's last statement the caller's next one, after a program's the next program's."""
    return _within(frames, start) or (len(frames) == 2 and frames[0] is start[0])


#: Which halts end a step ``over`` (``_over``) or ``out`` (in a caller).
STEP_ENDS = {
    "over": _over,
    "out": lambda frames, start: len(frames) < len(start) and _within(frames, start),
}


@dataclass(frozen=True)
class Halt:
    """Where a halted scan stands: the pause point, the POU instance (path, None in a function), why."""

    point: PausePoint
    instance: str | None
    reason: str  # "breakpoint" | "step"

    @property
    def origin(self) -> ir.Origin:
        return self.point.origin


class Debugger:
    def __init__(self, points: list[PausePoint], flags: list[bool]) -> None:
        self.points = points
        self.flags = flags  # the generated module's ll_halt, shared
        self.breakpoints: set[int] = set()
        self.waiting_for_transition = False  # a "transition" step: armed from scan to scan until one fires

    def pause_points(self, pou: str | None = None) -> list[PausePoint]:
        return [p for p in self.points if pou is None or p.origin.pou.upper() == pou.upper()]

    def find(
        self,
        pou: str,
        *,
        line: int | None = None,
        network: str | None = None,
        element: str | None = None,
        body: str | None = None,
    ) -> list[int]:
        """Pause points of a breakpoint on an ST line, an LD/FBD network or an element (exactly one given), in the
        POU's body or chart, or (``body``) in one of an SFC POU's actions or named transitions."""
        if sum(x is not None for x in (line, network, element)) != 1:
            raise ValueError("give exactly one of line, network, element")
        points = self.pause_points(pou)
        if points:
            points = [p for p in points if p.origin.body == body]
            if not points:
                raise ValueError(f"{pou} has no pause points in {body or 'its body'}")
        if not points:
            known = sorted({p.origin.pou for p in self.points})
            raise ValueError(f"no POU {pou!r} with pause points (known: {', '.join(known) or 'none'})")
        if line is not None:
            found = [p.id for p in points if p.kind in _LINE_KINDS and p.origin.line == line]
            what, options = (
                f"statement at line {line}",
                sorted({p.origin.line for p in points if p.kind in _LINE_KINDS}),
            )
        elif network is not None:
            found = [p.id for p in points if p.kind == "network" and p.origin.network == network]
            what, options = f"network {network!r}", sorted({p.origin.network for p in points if p.kind == "network"})
        else:
            found = [p.id for p in points if p.kind in _ELEMENT_KINDS and element in (p.element, p.origin.element)]
            what, options = (
                f"element {element!r}",
                sorted({p.element for p in points if p.kind in _ELEMENT_KINDS and p.element}),
            )
        if not found:
            shown = ", ".join(map(str, options[:20])) or "none"
            raise ValueError(f"{pou} has no {what} (possible: {shown})")
        return found

    def add_breakpoint(self, pou: str, **where) -> list[int]:
        ids = self.find(pou, **where)
        self.breakpoints.update(ids)
        self.arm(None)
        return ids

    def remove_breakpoint(self, pou: str, **where) -> None:
        self.breakpoints.difference_update(self.find(pou, **where))
        self.arm(None)

    def clear_breakpoints(self) -> None:
        self.breakpoints.clear()
        self.arm(None)

    def arm(self, step: str | None) -> None:
        """Arm the breakpoints, plus the pause points of a step of this granularity (and the transitions while a
        transition step waits)."""
        if step is not None and step not in GRANULARITIES:
            raise ValueError(f"step granularity must be one of {', '.join(GRANULARITIES)}, not {step!r}")
        if step == "transition":
            self.waiting_for_transition = True
        kinds = _STEP_KINDS[step] if step else ()
        if self.waiting_for_transition:
            kinds = (*kinds, "transition")
        for point in self.points:
            self.flags[point.id] = point.id in self.breakpoints or point.kind in kinds

    def reason(self, pid: int) -> str:
        return "breakpoint" if pid in self.breakpoints else "step"

    def halted_at(self, pid: int) -> None:
        """A scan halted at pause point ``pid``: a transition step that waited is over when any halt comes."""
        self.waiting_for_transition = False
