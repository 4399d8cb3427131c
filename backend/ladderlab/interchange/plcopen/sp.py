"""Series-parallel reduction of a two-terminal power-flow graph (PLCopen LD graph -> nested series lists).

A PLCopen LD rung is a directed graph: elements are edges from their input point
to their output point, wires join points, several connections on one input are a
wired OR. The project model stores rungs as series lists with ``Par`` (parallel)
items. ``reduce_graph`` recovers that structure by the classic reductions: edges
between the same two points become a parallel, a point with one edge in and one
out joins a series. A graph that does not reduce (a bridge) raises
``NotSeriesParallel`` naming the elements that remain.

Branches that end in a jump or return never reach the end of the rung ("dead"
branches). They hang off one point of the live graph and become a parallel
branch there that runs to the end of the series list the point lies in (the one
canonical place, so the result does not depend on the reduction order): the
point is marked while series are merged and the marks are resolved at the end.
Parallel branches are ordered by the key of their first item (the drawing
position: top to bottom); an empty branch (a plain wire) comes last.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

Key = Callable[[Any], Any]


@dataclass
class Par:
    """A parallel of two or more series lists (an OR of their power flows)."""

    branches: list[list[Any]]


@dataclass
class Edge:
    """An element (``items`` holds it) or a wire (no items) from point ``u`` to point ``v``."""

    u: int
    v: int
    items: list[Any] = field(default_factory=list)


@dataclass
class _Mark:
    """Dead branches hanging off a point inside a series list (resolved after the reduction)."""

    branches: list[list[Any]]


class NotSeriesParallel(Exception):
    """The graph is not series-parallel; ``items`` are the elements that could not be reduced."""

    def __init__(self, items: list[Any]):
        super().__init__("the graph is not series-parallel")
        self.items = list(_flatten(items))


def _flatten(items: list[Any]):
    for item in items:
        if isinstance(item, (Par, _Mark)):
            for branch in item.branches:
                yield from _flatten(branch)
        else:
            yield item


def reachable(edges: list[Edge], start: int, *, backwards: bool = False) -> set[int]:
    step: dict[int, list[int]] = defaultdict(list)
    for e in edges:
        (step[e.v] if backwards else step[e.u]).append(e.u if backwards else e.v)
    seen, todo = {start}, [start]
    while todo:
        for n in step[todo.pop()]:
            if n not in seen:
                seen.add(n)
                todo.append(n)
    return seen


def reduce_graph(edges: list[Edge], source: int, sink: int, key: Key, ends: list[int] = ()) -> list[Any]:
    """The series list equivalent to the graph from ``source`` to ``sink``; ``key`` orders parallel branches.

    ``ends`` are the sinks of jumps and returns, one per element. Branches into them
    are dead branches hung off the live graph. When nothing reaches ``sink`` (a rung
    that ends in a jump), one of them is the rung's end: each is tried in the given
    order (the importer lists the top row's last element first).
    Only edges reachable from ``source`` count.
    """
    edges = [e for e in edges if e.u in reachable(edges, source)]
    reducer = _Reducer(key)
    return reducer.resolve(reducer.rung(edges, source, sink, list(ends)))


class _Reducer:
    def __init__(self, key: Key):
        self.key = key

    def first_key(self, items: list[Any]) -> tuple:
        """Sort key of a branch: its first element's (empty branches and marks sort last)."""
        for item in items:
            if isinstance(item, Par):
                return min(self.first_key(b) for b in item.branches)
            if not isinstance(item, _Mark):
                return (0, self.key(item))
        return (1,)

    def parallel(self, branches: list[list[Any]]) -> list[Any]:
        """One series holding the branches in parallel: flattened, sorted, at most one empty branch."""
        flat: list[list[Any]] = []
        for branch in branches:
            if len(branch) == 1 and isinstance(branch[0], Par):
                flat += branch[0].branches
            else:
                flat.append(branch)
        filled = [b for b in flat if b]
        if len(filled) < len(flat):
            filled.append([])
        filled.sort(key=self.first_key)
        return filled[0] if len(filled) == 1 else [Par(filled)]

    def rung(self, edges: list[Edge], source: int, sink: int | None, ends: list[int]) -> list[Any]:
        """Reduce towards ``sink``, or, when nothing reaches it, towards the first end that works."""
        if sink is not None and (source in reachable(edges, sink, backwards=True) or not ends):
            return self.live(edges, source, sink, ends)
        failure: NotSeriesParallel | None = None
        for end in ends:
            try:
                return self.live(edges, source, end, [e for e in ends if e != end])
            except NotSeriesParallel as err:
                failure = failure or err
        raise failure or NotSeriesParallel([item for e in edges for item in e.items])

    def live(self, edges: list[Edge], source: int, sink: int, ends: list[int]) -> list[Any]:
        """Reduce the part that reaches ``sink``; what only reaches ``ends`` hangs off it as dead branches."""
        live = reachable(edges, sink, backwards=True)
        marks: dict[int, list[list[Any]]] = defaultdict(list)
        for anchor, region in self.dead_regions(edges, live, set(ends)):
            region_ends = [e for e in ends if any(edge.v == e for edge in region)]
            marks[anchor].append(self.rung(region, anchor, None, region_ends))
        main = [e for e in edges if e.u in live and e.v in live]
        items = self.reduce(main, source, sink, marks)
        if marks.get(source):
            items = [_Mark(marks.pop(source)), *items]
        if marks:
            raise NotSeriesParallel([item for branches in marks.values() for b in branches for item in b])
        return items

    @staticmethod
    def dead_regions(edges: list[Edge], live: set[int], ends: set[int]) -> list[tuple[int, list[Edge]]]:
        """Parts that reach only jumps/returns, each with the one live point it hangs off."""
        dead_nodes = {n for e in edges for n in (e.u, e.v) if n not in live and n not in ends}
        region_of: dict[int, int] = {}
        for start in dead_nodes:  # weakly connected regions of dead points (end sinks do not join them)
            if start in region_of:
                continue
            region_of[start] = start
            todo = [start]
            while todo:
                n = todo.pop()
                for e in edges:
                    for a, b in ((e.u, e.v), (e.v, e.u)):
                        if a == n and b in dead_nodes and b not in region_of:
                            region_of[b] = start
                            todo.append(b)
        regions: dict[Any, list[Edge]] = defaultdict(list)
        for i, e in enumerate(edges):
            if e.u not in live or e.v not in live:
                regions[region_of.get(e.v, region_of.get(e.u, ("direct", i)))].append(e)
        out = []
        for region in regions.values():
            anchors = {e.u for e in region if e.u in live}
            if len(anchors) != 1:
                raise NotSeriesParallel([item for e in region for item in e.items])
            out.append((anchors.pop(), region))
        return out

    def reduce(self, edges: list[Edge], source: int, sink: int, marks: dict[int, list[list[Any]]]) -> list[Any]:
        """The items of the single edge the graph reduces to (marks left in place); NotSeriesParallel otherwise."""
        if not edges and source == sink:
            return []
        graph = dict(enumerate(edges))
        counter = [len(edges)]
        changed = True
        while changed:
            changed = self.merge_parallels(graph, counter) | self.merge_series(graph, counter, source, sink, marks)
        left = list(graph.values())
        if len(left) != 1 or (left[0].u, left[0].v) != (source, sink):
            raise NotSeriesParallel([item for e in left for item in e.items])
        return left[0].items

    def merge_parallels(self, graph: dict[int, Edge], counter: list[int]) -> bool:
        groups: dict[tuple[int, int], list[int]] = defaultdict(list)
        for i, e in graph.items():
            groups[(e.u, e.v)].append(i)
        changed = False
        for (u, v), ids in groups.items():
            if len(ids) > 1:
                items = self.parallel([graph.pop(i).items for i in ids])
                graph[counter[0]] = Edge(u, v, items)
                counter[0] += 1
                changed = True
        return changed

    @staticmethod
    def merge_series(
        graph: dict[int, Edge], counter: list[int], source: int, sink: int, marks: dict[int, list[list[Any]]]
    ) -> bool:
        """Merge one maximal chain of points with one edge in and one out; a marked point leaves its mark."""
        ins: dict[int, list[int]] = defaultdict(list)
        outs: dict[int, list[int]] = defaultdict(list)
        for i, e in graph.items():
            outs[e.u].append(i)
            ins[e.v].append(i)

        def interior(n: int) -> bool:
            return n not in (source, sink) and len(ins[n]) == 1 and len(outs[n]) == 1

        node = next((n for n in ins if interior(n)), None)
        if node is None:
            return False
        first = ins[node][0]
        while interior(graph[first].u) and graph[first].u != node:
            first = ins[graph[first].u][0]
        chain = [first]
        while interior(graph[chain[-1]].v) and graph[chain[-1]].v != graph[first].u:
            chain.append(outs[graph[chain[-1]].v][0])
        items: list[Any] = []
        for i in chain:
            point = graph[i].u
            if i != first and marks.get(point):
                items.append(_Mark(marks.pop(point)))
            items += graph[i].items
        merged = Edge(graph[first].u, graph[chain[-1]].v, items)
        for i in chain:
            del graph[i]
        graph[counter[0]] = merged
        counter[0] += 1
        return True

    def resolve(self, items: list[Any]) -> list[Any]:
        """Marks become parallels: the dead branches beside the rest of their series list."""
        out: list[Any] = []
        for i, item in enumerate(items):
            if isinstance(item, _Mark):
                return out + self.parallel([*(self.resolve(b) for b in item.branches), self.resolve(items[i + 1 :])])
            if isinstance(item, Par):
                out += self.parallel([self.resolve(b) for b in item.branches])
            else:
                out.append(item)
        return out
