"""``collector_paused()``: the cyclic garbage collector off while a whole project is checked, lowered or compiled.

Checking and lowering a large project allocate millions of small objects (AST
nodes, symbols, IR nodes) that stay alive until the build ends, so every
collection the allocations trigger traverses all of them again without freeing
anything: for a 10,000-network diagram about 40 % of the lowering time. The few
reference cycles a build leaves are collected once the collector runs again.
Pausing nests: an inner pause leaves a collector it found off as it was.
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
            gc.enable()
