"""``collector_paused()``: the cyclic garbage collector off while a whole project is checked, lowered or compiled;
``frozen_start()``: off while the server starts, its objects frozen after.

Checking and lowering a large project allocate millions of small objects (AST
nodes, symbols, IR nodes) that stay alive until the build ends, so every
collection the allocations trigger traverses all of them again without freeing
anything: for a 10,000-network diagram about 40 % of the lowering time. The few
reference cycles a build leaves are collected once the collector runs again.
Pauses nest and overlap across threads (the server builds in worker threads): they are
counted under a lock, the first turns the collector off (when it was on) and the last one
to end turns it back on, so no interleaving of two builds can leave it off for good.

When the last pause ends, one collection of the two young generations (``gc.collect(1)``) runs over
everything allocated meanwhile: what cyclic garbage the build left is freed at once, and what
survives (the IR, the compiled program of a simulation) moves to the oldest generation the way
CPython counts it, so its own rule for full collections stays in force. The lowering leaves no
cycles (tests/ir/test_build_memory.py): the check it drops is freed by reference counts as it ends,
so this collection traverses mostly what survives. That collection costs what one pass over the
build's objects costs (about 0.1-0.15 s for a 10,000-network diagram, a few milliseconds for a
typical project), once per build and in the build's own thread, instead of at a random later moment
(in a scan, say). An earlier version handed the build's objects to the oldest generation without a
collection (``gc.freeze()`` + ``gc.unfreeze()``): CPython does not count objects moved that way, so
full collections never came and every check leaked its garbage (~130 KB per ``/api/check``; issue
18).

``collector_paused(for_life=True)`` is for a process that builds one program and runs it until the process
ends (a simulation's worker, simulation/worker.py): the last pause then ends in ``gc.freeze()`` instead of a
collection. What it built lives as long as the process, so no collection needs to traverse it: neither the
end-of-pause one nor the full collection CPython's rule starts soon after (the build's survivors outnumber a
quarter of the old objects), ~2.2 s at the first scan of a 50,000-network program. Objects allocated later
are collected as usual (a frozen object is still freed by its reference count); what stays until the process
ends is the few cycles the build dropped (~150 objects at 50,000 networks) and a cycle alive at the freeze
that dies later (the first instances' after a cold reset, say): once, not per build. A process that builds
again (the build workers' checks, the CLI's test runner, a test session) must not freeze: each build's cycles
would stay.
"""

from __future__ import annotations

import gc
import threading
from collections.abc import Iterator
from contextlib import contextmanager

_lock = threading.Lock()
_pauses = 0  # pauses running now, in any thread
_restore = False  # the collector was on when the first of them began
_freeze = False  # one of them is a build for the process's life: the last to end freezes


@contextmanager
def collector_paused(for_life: bool = False) -> Iterator[None]:
    global _pauses, _restore, _freeze
    with _lock:
        if _pauses == 0:
            _restore = gc.isenabled()
            gc.disable()
        _pauses += 1
        _freeze = _freeze or for_life
    try:
        yield
    finally:
        with _lock:
            _pauses -= 1
            if _pauses == 0:
                if _freeze:
                    gc.freeze()  # kept until the process ends: no collection traverses it again
                    _freeze = False
                else:
                    gc.collect(1)  # the build's garbage goes now; its survivors become old, and are counted
                if _restore:
                    gc.enable()


@contextmanager
def frozen_start() -> Iterator[None]:
    """The collector off while ``ladderlab serve`` imports the server and makes its app, whose objects are then frozen
    (``gc.freeze``) rather than collected: they live as long as the process, so no collection would free them.

    Without the pause, ~75 collections traverse these ~60,000 objects as they are made (~35 ms of CPU at every start,
    a tenth of what a bare FastAPI app takes to answer), and every later full collection traverses them again. The
    price is the little garbage the start leaves (~1 MB: argparse's parser, pydantic's class construction), which
    stays frozen with them. Objects made later are collected as usual: frozen ones are not counted, so full
    collections come as CPython's rule says for the rest.
    """
    restore = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if restore:
            gc.enable()
