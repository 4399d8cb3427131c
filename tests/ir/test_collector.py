"""collector_paused: the cyclic GC is off inside, back on after; the build's garbage is collected when the pause
ends and what survives is old, not young (issue 18: it leaked into the oldest generation)."""

from __future__ import annotations

import gc
import threading
import weakref

from ladderlab.collector import collector_paused, frozen_start


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


def test_garbage_of_a_pause_is_collected_when_it_ends_without_waiting_for_a_full_collection() -> None:
    """Issue 18: the pause moved each build's garbage into the oldest generation, where full collections
    never came: ~130 KB per check, without bound."""
    gc.collect()
    before = len(gc.get_objects(generation=2))
    gone = []
    for _ in range(200):  # 200 "builds", each leaving a cycle of 50 nodes as garbage
        with collector_paused():
            ring = [_Node() for _ in range(50)]
            for a, b in zip(ring, ring[1:] + ring[:1]):
                a.other = b
            gone.append(weakref.ref(ring[0]))
            del ring, a, b
        assert gone[-1]() is None, "collected as the pause ended"
    assert len(gc.get_objects(generation=2)) - before < 1000, "the oldest generation does not grow"


def test_overlapping_pauses_in_two_threads_keep_the_collector_off_until_the_last_ends() -> None:
    """The server builds in worker threads: a build ending must not switch the collector on under another
    one, and no interleaving may leave it off."""
    entered, leave = threading.Event(), threading.Event()

    def other_build() -> None:
        with collector_paused():
            entered.set()
            leave.wait(5)

    worker = threading.Thread(target=other_build)
    with collector_paused():
        worker.start()
        assert entered.wait(5)
    assert not gc.isenabled()  # this build ended, the other one still runs
    leave.set()
    worker.join(5)
    assert gc.isenabled()


def test_frozen_start_freezes_what_was_made_and_restores_the_collector() -> None:
    """``ladderlab serve`` makes its app under ``frozen_start``: nothing is collected meanwhile, and what it made is then
    out of every collection's way; a cycle made afterwards is collected as usual."""
    gc.collect()
    try:
        with frozen_start():
            assert not gc.isenabled()
            kept = [[n] for n in range(1000)]
        assert gc.isenabled()
        assert gc.get_freeze_count() >= len(kept)
        tracked = {id(o) for o in gc.get_objects()}  # the generations' objects: frozen ones are in none
        assert not any(id(o) in tracked for o in kept)
        a, b = _Node(), _Node()
        a.other, b.other = b, a
        alive = weakref.ref(a)
        del a, b
        gc.collect()
        assert alive() is None
        gc.disable()
        with frozen_start():
            pass
        assert not gc.isenabled(), "a collector that was off stays off"
    finally:
        gc.enable()
        gc.unfreeze()  # the other tests of this process see no frozen objects
