"""collector_paused: the cyclic GC is off inside, back on after, and what the pause allocated is old, not young."""

from __future__ import annotations

import gc
import weakref

from ladderlab.collector import collector_paused


class _Node:
    def __init__(self) -> None:
        self.other: _Node | None = None


def test_pause_restores_the_collector_and_hands_survivors_to_the_oldest_generation() -> None:
    assert gc.isenabled()
    with collector_paused():
        assert not gc.isenabled()
        with collector_paused():  # nested: the inner pause leaves the collector off
            pass
        assert not gc.isenabled()
        survivors = [[n] for n in range(1000)]
    assert gc.isenabled()
    assert gc.get_count()[0] < 100  # no young backlog for the next collection to traverse
    oldest = {id(o) for o in gc.get_objects(generation=2)}
    assert all(id(item) in oldest for item in survivors[:3])
    assert gc.get_freeze_count() == 0  # nothing stays frozen


def test_a_cycle_built_during_the_pause_is_still_collected() -> None:
    with collector_paused():
        a, b = _Node(), _Node()
        a.other, b.other = b, a
        alive = weakref.ref(a)
    del a, b
    gc.collect()
    assert alive() is None
