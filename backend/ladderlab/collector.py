"""``collector_paused()``: the cyclic garbage collector off while a whole project is checked, lowered or compiled.

Checking and lowering a large project allocate millions of small objects (AST
nodes, symbols, IR nodes) that stay alive until the build ends, so every
collection the allocations trigger traverses all of them again without freeing
anything: for a 10,000-network diagram about 40 % of the lowering time. The few
reference cycles a build leaves are collected once the collector runs again.
Pauses nest and overlap across threads (the server builds in worker threads): they are
counted under a lock, the first turns the collector off (when it was on) and the last one
to end turns it back on, so no interleaving of two builds can leave it off for good.

A paused collector still counts the objects allocated meanwhile as young, so the
first collection after the pause would traverse all of them at once (0.3-0.4 s
for a 10,000-network diagram) only to find them alive. They are the build's
long-lived result, so they are handed to the oldest generation instead
(``gc.freeze`` + ``gc.unfreeze``: two list splices, no traversal), which the
collector visits only in its rare full collections - where any cycle among them
is still found. (LadderLab itself never freezes objects for good, so unfreezing
releases nothing frozen elsewhere.)
"""

from __future__ import annotations

import gc
import threading
from collections.abc import Iterator
from contextlib import contextmanager

_lock = threading.Lock()
_pauses = 0  # pauses running now, in any thread
_restore = False  # the collector was on when the first of them began


@contextmanager
def collector_paused() -> Iterator[None]:
    global _pauses, _restore
    with _lock:
        if _pauses == 0:
            _restore = gc.isenabled()
            gc.disable()
        _pauses += 1
    try:
        yield
    finally:
        with _lock:
            _pauses -= 1
            if _pauses == 0 and _restore:
                gc.freeze()  # every tracked object -> the permanent generation ...
                gc.unfreeze()  # ... -> the oldest one
                gc.enable()
