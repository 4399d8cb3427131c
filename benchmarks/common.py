"""What every benchmark prints with its figures: the machine's load, and timings that have settled.

A figure measured while other processes compete for the 2 cores is not comparable with one measured
on a quiet machine, so every figure line carries the load average. A timing is repeated in batches
until the medians of two consecutive batches agree within 20 %, so a figure is never taken while
the interpreter is still warming up (specialisation, caches) or the machine is in a burst.
"""

from __future__ import annotations

import os
import statistics
from collections.abc import Callable
from dataclasses import dataclass

AGREE = 0.20


def load_average() -> str:
    """``load 1.92/1.40/1.12 on 2 cores`` (1, 5 and 15 minutes)."""
    one, five, fifteen = os.getloadavg()
    return f"load {one:.2f}/{five:.2f}/{fifteen:.2f} on {os.cpu_count()} cores"


@dataclass(frozen=True)
class Settled:
    """The median of the last batch, and whether it agreed with the batch before it."""

    median: float
    spread: float  # (max - min) / median within the last batch
    batches: int
    settled: bool

    def note(self) -> str:
        state = "settled" if self.settled else f"NOT settled within {AGREE:.0%}"
        return f"{state} after {self.batches} batches, spread {self.spread:.0%}"


def settle(measure: Callable[[], float], batch: int = 5, max_batches: int = 12) -> Settled:
    """Run ``measure`` (one timing, any unit) in batches until two consecutive batch medians agree within 20 %."""
    previous: float | None = None
    for n in range(1, max_batches + 1):
        samples = [measure() for _ in range(batch)]
        median = statistics.median(samples)
        spread = (max(samples) - min(samples)) / median if median else 0.0
        if previous is not None and abs(median - previous) <= AGREE * previous:
            return Settled(median, spread, n, True)
        previous = median
    return Settled(median, spread, max_batches, False)
