"""Reading the element states of a monitor frame: one pass over rows worked out once per set of elements.

A client showing an LD editor asks for the same elements (its viewed networks) frame after frame, every
``publish_s``. Working out, per call, each element's probe number, groups, constant and network cost more than
the scans of a small program between two frames (0.2-0.4 ms for 20 networks); a ``FramePlan`` does it once per
(POU, elements) and ``Simulation.probes`` then runs one loop of list reads, with the viewed-network check made
once per network instead of once per element.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from .codegen.context import ProbeTable

_NO_CONSTANT = object()


@dataclass(frozen=True, slots=True)
class FramePlan:
    """The probes of some elements of one POU, as ``Simulation.probes`` reads them."""

    #: (number of the probe holding the value: its own or, for an alias, its source's; element id, network run or
    #: None, first group or -1, further groups, constant or _NO_CONSTANT)
    rows: tuple[tuple[int, str, int | None, int, tuple[int, ...], object], ...]
    networks: tuple[int, ...]  # the distinct network runs of the rows
    #: (probe number, network run, first group, further groups) of the rows read after the scan
    deferred: tuple[tuple[int, int | None, int, tuple[int, ...]], ...]

    def read(
        self, values: list[object], stamps: list[int], stamp: int, recorded: dict[int, bool], unset: object
    ) -> tuple[dict[str, object], list[str], list[str]]:
        """(values, executed, unknown) of the rows: ``recorded`` says which network runs the last scan recorded."""
        found: dict[str, object] = {}
        executed: list[str] = []
        unknown: list[str] = []
        for index, name, network, group, more, constant in self.rows:
            if network is not None and not recorded[network]:
                unknown.append(name)
                continue
            value = values[index]
            last = stamps[group] if group >= 0 else -1
            ran, ever = last == stamp, last >= 0
            for g in more:
                last = stamps[g]
                ran, ever = ran or last == stamp, ever or last >= 0
            if value is unset and constant is not _NO_CONSTANT and ever:
                value = constant  # recorded by the group stamp alone
            if value is not unset:
                found[name] = value
            if ran:
                executed.append(name)
        return found, executed, unknown


def frame_plan(table: ProbeTable, elements: Iterable[str] | None, networks: bool) -> FramePlan:
    """The plan of ``elements`` (unknown ones left out; None: every element) of ``table``'s POU; ``networks``: the
    monitor variant records a network's probes only while it is viewed (else no row has a network)."""
    if elements is None:
        indices: Iterable[int] = range(len(table.elements))
    else:
        indices = [index for index in map(table.index, dict.fromkeys(elements)) if index is not None]
    network_of = table.network_of if networks else {}
    aliases = table.aliases  # (stored once, in the same group: ``ProbeTable.aliases``)
    rows = []
    for index in indices:
        groups = table.groups[index]
        constant = table.constants.get(index, _NO_CONSTANT)
        first = groups[0] if groups else -1  # (-1: no group, never ran)
        stored = aliases.get(index, index)
        rows.append((stored, table.elements[index], network_of.get(index), first, tuple(groups[1:]), constant))
    deferred = tuple((row[0], row[2], row[3], row[4]) for row in rows if row[0] in table.deferred_paths)
    return FramePlan(tuple(rows), tuple(sorted({row[2] for row in rows if row[2] is not None})), deferred)
