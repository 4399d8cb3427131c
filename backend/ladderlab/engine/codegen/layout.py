"""Where each slot of a PROGRAM / FUNCTION_BLOCK instance (or of the globals) lives.

A slot is an attribute of a ``__slots__`` class. CPython reads such an
attribute in a few nanoseconds only while the object is small: on objects with
thousands of slots the attribute caches stop working and a scan of 10,000 LD
networks becomes ten times slower. So slots are split into pages of
``PAGE_SIZE``: page 0 is the instance itself, page k is the object in its
attribute ``ll_pk``. Ordinary POUs have one page and read as ``self.v_MOTOR``.
"""

from __future__ import annotations

from typing import NamedTuple

from ...ir import nodes as ir
from . import names

PAGE_SIZE = 512


class Place(NamedTuple):  # (not a frozen dataclass: a 10,000-network POU has 40,000, built per compile)
    slot: ir.Slot
    attr: str
    page: int


class Layout:
    """The slots of one POU (or of the globals) by upper-case name, with their attribute and page."""

    def __init__(self, slots: list[ir.Slot], page_size: int = PAGE_SIZE) -> None:
        stored = [s for s in slots if s.var_class != "VAR_EXTERNAL" and s.address is None]
        #: located variables: no attribute, they live in the process image (engine/process_image.py)
        self.located: dict[str, ir.Slot] = {ir.upper_name(s.name): s for s in slots if s.address is not None}
        self.places: dict[str, Place] = {
            ir.upper_name(s.name): Place(s, names.slot(s.name), i // page_size) for i, s in enumerate(stored)
        }
        self.pages = max(1, -(-len(stored) // page_size))
        self._places: list[list[Place]] = [[] for _ in range(self.pages)]
        for place in self.places.values():
            self._places[place.page].append(place)
        self._attrs = [[place.attr for place in places] for places in self._places]

    def get(self, name: str) -> Place | None:
        return self.places.get(name.upper())

    def page_attrs(self, page: int) -> list[str]:
        return self._attrs[page]

    def page_places(self, page: int) -> list[Place]:
        return self._places[page]

    def owner(self, instance: str, place: Place) -> str:
        """Source of the object holding ``place`` when the instance is ``instance``."""
        return instance if place.page == 0 else f"{instance}.ll_p{place.page}"


def slots_source(attrs: list[str]) -> str:
    """Source of a ``__slots__`` value: one string split at run time, which compiles far faster than a tuple of
    hundreds of strings (the attributes are identifiers, so never contain a space)."""
    return f"tuple({' '.join(attrs)!r}.split())"
