"""collector_paused: the cyclic GC is off inside, back on after; the build's garbage is collected when the pause
ends and what survives is old, not young (issue 18: it leaked into the oldest generation); a build for the process's
life is frozen instead (issue 27)."""

from __future__ import annotations

import gc
import json
import subprocess
import sys
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


_FOR_LIFE = """
import gc, json, weakref
from ladderlab.collector import collector_paused
from ladderlab.examples import example_names, example_project
from ladderlab.simulation.build import build_project

class Node:
    other = None

with collector_paused(for_life=True):
    sim = build_project(example_project(example_names()[0], "x"), "monitor").simulation()
    sim.cycle(1)
visible, frozen = len(gc.get_objects()), gc.get_freeze_count()
a, b = Node(), Node()
a.other, b.other = b, a
later = weakref.ref(a)
del a, b
with collector_paused():  # a later build that is not for life
    kept = [[n] for n in range(1000)]
gc.collect()
print(json.dumps({"enabled": gc.isenabled(), "visible": visible, "frozen": frozen,
                  "frozen_after": gc.get_freeze_count(), "later_freed": later() is None, "sim": id(sim) in
                  {id(o) for o in gc.get_objects()}}))
"""


def test_a_build_for_the_process_life_is_frozen_out_of_every_later_collection() -> None:
    """A simulation's worker builds one program and runs it until the process ends (simulation/worker.py): what
    it built is frozen, so no later collection traverses it (issue 27: at the first scan of a 50,000-network
    program a full collection over ~3 million objects, ~2.2 s). Run in a process of its own: a freeze lasts as
    long as the process. What is allocated later is collected as usual, and a later pause collects again."""
    done = subprocess.run([sys.executable, "-c", _FOR_LIFE], capture_output=True, text=True, timeout=120, check=True)
    found = json.loads(done.stdout.splitlines()[-1])
    assert found["enabled"]
    assert found["visible"] < 50, "everything alive at the end of the pause is frozen"
    assert found["frozen"] > 10_000  # the interpreter's and the program's objects
    assert not found["sim"]
    assert found["later_freed"], "a cycle dropped after the freeze is collected"
    assert found["frozen_after"] == found["frozen"], "a later pause that is not for life freezes nothing"
