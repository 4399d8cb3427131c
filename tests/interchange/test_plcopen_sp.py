"""Series-parallel reduction of LD graphs (issue 8: LD graphs -> series/parallel model, bridges refused).

Graphs are built the way a PLCopen rung draws them: each element an edge from its
input point to its output point, several sources on one input a wired OR (wires
into a junction), outputs nobody reads ending at the right rail, jumps and
returns ending in sinks of their own.
"""

from __future__ import annotations

import random

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.interchange.plcopen.sp import Edge, NotSeriesParallel, Par, reduce_graph

S, T = 0, 1


class Rung:
    """Builds the graph of an abstract rung: items are names, ``Par`` nodes; names starting with J end a branch."""

    def __init__(self) -> None:
        self.edges: list[Edge] = []
        self.next = 2
        self.ends: list[int] = []
        self.junctions: dict[frozenset[int], int] = {}
        self.keys: dict[str, int] = {}

    def node(self) -> int:
        self.next += 1
        return self.next - 1

    def point(self, sources: list[int]) -> int:
        if len(sources) == 1:
            return sources[0]
        key = frozenset(sources)
        if key not in self.junctions:
            self.junctions[key] = self.node()
            self.edges += [Edge(s, self.junctions[key]) for s in sources]
        return self.junctions[key]

    def series(self, items: list, sources: list[int]) -> list[int]:
        for item in items:
            if isinstance(item, Par):
                outs: list[int] = []
                for branch in item.branches:
                    outs += [n for n in self.series(branch, sources) if n not in outs]
                sources = outs
                continue
            self.keys[item] = len(self.keys)
            end = self.node()
            self.edges.append(Edge(self.point(sources), end, [item]))
            if item.startswith("J"):
                self.ends.append(end)
                sources = []
            else:
                sources = [end]
        return sources

    def reduce(self, items: list, shuffle: random.Random | None = None) -> list:
        ends = self.series(items, [S])
        self.edges += [Edge(n, T) for n in ends]
        edges = list(self.edges)
        if shuffle is not None:
            shuffle.shuffle(edges)
        # the importer tries the top row's last jump first: in drawing order that is the last one drawn
        return reduce_graph(edges, S, T, self.keys.__getitem__, self.ends[::-1])


def test_series_and_wired_or():
    """(a OR b) AND c -> coil: the coil's input lists both branch ends."""
    items = [Par([["a"], ["b"]]), "c", "coil"]
    assert Rung().reduce(items) == items


def test_parallel_coils_at_the_end_of_a_rung():
    items = ["a", Par([["c1"], ["b", "c2"]])]
    assert Rung().reduce(items) == items


def test_nested_parallels_and_a_parallel_starting_the_rung():
    items = [Par([["a", Par([["b"], ["c"]])], ["d"]]), "e", Par([["f"], ["g"], ["h"]])]
    assert Rung().reduce(items) == items


def test_a_branch_ending_in_a_jump_runs_to_the_end_of_its_series_list():
    """[a, (b -> jump | c), coil] draws the same graph as [a, (b -> jump | c, coil)]: the latter is what comes back."""
    assert Rung().reduce(["a", Par([["b", "J1"], ["c"]]), "coil"]) == ["a", Par([["b", "J1"], ["c", "coil"]])]


def test_a_rung_ending_in_a_jump_keeps_its_inner_dead_branches():
    items = ["a", Par([["b"], ["c", Par([["d", "J1"], ["e"]])]]), "J2"]
    assert Rung().reduce(items) == items


def test_the_last_element_of_the_top_row_ends_a_rung_of_jumps():
    """A rung whose branches all end in jumps: each jump is tried as its end, the first listed first."""
    items = [Par([["a", "J1"], ["b", "J2"]])]
    assert Rung().reduce(items) == items


def test_a_bridge_is_refused_naming_every_element_of_it():
    """a -> x -> d with a -> c and b -> x: the Wheatstone bridge (x links the two paths)."""
    p, q = 10, 11
    edges = [Edge(S, p, ["a"]), Edge(S, q, ["b"]), Edge(p, q, ["x"]), Edge(p, T, ["c"]), Edge(q, T, ["d"])]
    with pytest.raises(NotSeriesParallel) as caught:
        reduce_graph(edges, S, T, str)
    assert sorted(caught.value.items) == ["a", "b", "c", "d", "x"]


def test_a_dead_branch_fed_from_two_points_is_refused():
    """A jump ORing two points that also go on separately cannot hang off one point of the rung."""
    p, q, j = 10, 11, 12
    edges = [
        Edge(S, p, ["a"]),
        Edge(S, q, ["b"]),
        Edge(p, T, ["c1"]),
        Edge(q, T, ["c2"]),
        Edge(p, 13),
        Edge(q, 13),
        Edge(13, j, ["J1"]),
    ]
    with pytest.raises(NotSeriesParallel) as caught:
        reduce_graph(edges, S, T, str, [j])
    assert "J1" in caught.value.items


def test_only_edges_reachable_from_the_rail_count():
    assert reduce_graph([Edge(S, 5, ["a"]), Edge(5, T), Edge(7, 8, ["orphan"])], S, T, str) == ["a"]


# ------------------------------------------------------------------ property: any canonical tree comes back


@st.composite
def series(draw, depth: int, counter: list[int], dead: bool = True):
    """A canonical series list: no lone-parallel branch, a parallel with a dead branch is last, jumps at ends."""
    items: list = []
    for _ in range(draw(st.integers(1, 3))):
        if depth and draw(st.booleans()):
            branches = draw(st.lists(series(depth - 1, counter, dead), min_size=2, max_size=3))
            branches = [b for b in branches if not (len(b) == 1 and isinstance(b[0], Par))]
            if len(branches) < 2:
                continue
            items.append(Par(branches))
            if any(_dead(b) for b in branches):
                return items
        else:
            counter[0] += 1
            items.append(f"e{counter[0]}")
    if not items:
        counter[0] += 1
        items.append(f"e{counter[0]}")
    if dead and draw(st.integers(0, 3)) == 0:
        counter[0] += 1
        items.append(f"J{counter[0]}")
    return items


def _dead(items: list) -> bool:
    last = items[-1] if items else None
    return (isinstance(last, str) and last.startswith("J")) or (
        isinstance(last, Par) and all(_dead(b) for b in last.branches)
    )


@given(st.builds(list).flatmap(lambda counter: series(3, [0])), st.randoms())
def test_any_canonical_rung_comes_back_whatever_the_order_of_its_edges(items, rnd):
    assert Rung().reduce(items, shuffle=rnd) == items
