"""The constant inputs a program's instances hold from their initialisation on, put back after an online change.

The fast and monitor variants leave out the store of a standard FB input that every call gives the same constant
(codegen/constant_inputs.py): the instance is made holding it. IEC's next call would store the constant again
after an online write, force or release of such a pin, so ``Simulation`` tells ``StoredOnce`` what it wrote
(``touched``) and, before a scan runs a program instance it marked, calls ``restore``: the pins get their
constants back before the program runs (and before the forces are applied, so a force still wins). An injected
fault on such a pin (``injected``) is applied before each scan as a force is, and the call would store over it:
``restore_faulted`` puts the constants back after each scan that ran the program. A scan with no write before it
costs one test of an empty set.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable

from .codegen.context import ModuleContext
from .codegen.layout import Place
from .paths import Location


class StoredOnce:
    def __init__(self, context: ModuleContext) -> None:
        self._context = context
        #: the program instances whose pins an online change may have left without their constants
        self.stale: set[str] = set()
        #: those with an injected fault on a pin (applied before each scan, as a force is): restored after the
        #: scan too, where IEC's call stored the constant over the faulted value
        self.faulted: set[str] = set()

    @functools.cached_property
    def _programs(self) -> dict[str, list[tuple[Place, tuple[tuple[str, object], ...]]]]:
        """Program instance (upper case) -> its instances' (slot place, ((PIN, value), ...)) pairs: worked out at the
        first online change, not when every simulation starts (50,000 networks: ~0.05 s)."""
        context, pins = self._context, self._context.constant_pins
        return {
            i.name.upper(): [(_place(context, i.pou, slot), held) for slot, held in pins[i.pou.upper()].items()]
            for i in context.instances
            if i.pou.upper() in pins
        }

    @functools.cached_property
    def _pins(self) -> set[tuple[str, str, str]]:
        return {
            (i, place.slot.name.upper(), pin) for i, held in self._programs.items() for place, h in held for pin, _ in h
        }

    def touched(self, location: Location | None) -> None:
        """An online write, force or release of ``location`` (None: of anything, a release of every force)."""
        if location is None or location.through_pointer:
            self.stale.update(self._programs)
        elif (program := self._program_of(location)) is not None:
            self.stale.add(program)

    def _program_of(self, location: Location) -> str | None:
        """The program instance whose constant pin ``location`` is (or a part of: ``MAIN.K1.PV.%X0``)."""
        parts = location.path.upper().split(".")
        return parts[0] if len(parts) >= 3 and (parts[0], parts[1], parts[2]) in self._pins else None

    def injected(self, locations: Iterable[Location]) -> None:
        """The variables with an injected fault now (after one was injected or cleared)."""
        self.faulted = {p for location in locations if (p := self._program_of(location)) is not None}
        self.stale |= self.faulted

    def everything(self) -> None:
        """Every pin may hold anything (a captured state restored)."""
        self.stale.update(self._programs)

    def restore(self, programs: Iterable[str], instance: Callable[[str], object]) -> None:
        """Put the constants back into the stale ones of ``programs`` (instance names, as the tasks list them),
        before the scan runs them; ``instance(name)`` is the program instance."""
        for name in programs:
            key = name.upper()
            if key in self.stale:
                self.stale.discard(key)
                self._put_back(instance(key), key)

    def restore_faulted(self, programs: Iterable[str], instance: Callable[[str], object]) -> None:
        """After the scan ran ``programs``: the constants back into those with an injected fault on a pin."""
        for name in programs:
            key = name.upper()
            if key in self.faulted:
                self._put_back(instance(key), key)

    def _put_back(self, obj: object, key: str) -> None:
        for place, held in self._programs[key]:
            owner = obj if place.page == 0 else getattr(obj, f"ll_p{place.page}")
            fb = getattr(owner, place.attr)
            for pin, value in held:
                setattr(fb, pin, value)


def _place(context: ModuleContext, pou: str, slot: str) -> Place:
    place = context.layouts[pou.upper()].get(slot)
    assert place is not None  # (constant_inputs.py names the POU's own slots)
    return place
