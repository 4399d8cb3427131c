"""collector_paused: the cyclic GC is off inside, back on after, and what the pause allocated is old, not young."""

from __future__ import annotations

import gc
import threading
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
