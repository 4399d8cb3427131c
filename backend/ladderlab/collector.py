"""``collector_paused()``: the cyclic garbage collector off while a whole project is checked, lowered or compiled.

Checking and lowering a large project allocate millions of small objects (AST
nodes, symbols, IR nodes) that stay alive until the build ends, so every
collection the allocations trigger traverses all of them again without freeing
anything: for a 10,000-network diagram about 40 % of the lowering time. The few
reference cycles a build leaves are collected once the collector runs again.
Pausing nests: an inner pause leaves a collector it found off as it was.

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
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def collector_paused() -> Iterator[None]:
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.freeze()  # every tracked object -> the permanent generation ...
            gc.unfreeze()  # ... -> the oldest one
            gc.enable()
