"""``WorkerSettings``: what a simulation's process is given and held to.

Apart from ``remote.py`` so the registry makes them without importing the server's side of a simulation (and
the monitor's message models) before the first simulation opens (startup, issue 27).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class WorkerSettings:
    """What a simulation's process is given and held to (``SimulationSettings`` fills it in)."""

    watchdog_s: float
    publish_s: float
    memory_bytes: int | None
    build_timeout_s: float
    grace_s: float
    beat_s: float
    log_entries: int
    history_bytes: int = 256 * 1024 * 1024  # the scan history's budget (0: no history)
    history_timeout_s: float = 30.0  # the longest the server waits for a question to the scan history
