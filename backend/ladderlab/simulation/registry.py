"""The live simulations of one server: ids, limits, and ending the ones nobody uses.

A simulation keeps running with no browser attached (a user may close the tab and
come back); one that has no websocket client and no request for ``idle_timeout_s``
is deleted by a reaper thread, so forgotten simulations do not run forever.
"""

from __future__ import annotations

import secrets
import threading
import time
from dataclasses import dataclass, field

from .runner import SimRunner

MB = 1024 * 1024


class RegistryFull(Exception):
    """No room for another simulation (the server maps it to 429)."""


class UnknownSimulation(LookupError):
    """No simulation with that id (the server maps it to 404)."""


@dataclass(frozen=True)
class SimulationSettings:
    """Bounds and timings of online mode (tests shorten them)."""

    max_simulations: int = 16
    idle_timeout_s: float = 15 * 60.0
    reap_every_s: float = 5.0
    watchdog_s: float = 1.0  # per scan and task; a longer scan is a fault
    publish_s: float = 0.02  # newest values are published at most this often while running
    max_clients: int = 200  # websocket clients per simulation
    max_paths: int = 5_000  # variables per subscription
    max_instances: int = 32  # POU instances with element power flow per subscription
    max_message_bytes: int = 1 * MB  # one client message
    max_queued: int = 256  # status/log/trace/error messages waiting for a slow client; older logs are dropped


@dataclass
class SimulationEntry:
    id: str
    project: str
    revision: str
    created: float  # time.time()
    runner: SimRunner
    last_active: float  # time.monotonic()
    clients: int = 0


@dataclass
class SimulationRegistry:
    settings: SimulationSettings = field(default_factory=SimulationSettings)

    def __post_init__(self) -> None:
        self._entries: dict[str, SimulationEntry] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._reaper: threading.Thread | None = None

    def check_room(self) -> None:
        with self._lock:
            self._check_room()

    def _check_room(self) -> None:
        if len(self._entries) >= self.settings.max_simulations:
            raise RegistryFull(
                f"the server already runs {len(self._entries)} simulations, the most it allows; delete one first"
            )

    def add(self, project: str, revision: str, runner: SimRunner) -> SimulationEntry:
        with self._lock:
            try:
                self._check_room()
            except RegistryFull:
                runner.close()
                raise
            sim_id = secrets.token_hex(6)
            entry = SimulationEntry(sim_id, project, revision, time.time(), runner, time.monotonic())
            self._entries[sim_id] = entry
            if self._reaper is None:
                self._reaper = threading.Thread(target=self._reap, name="ladderlab-sim-reaper", daemon=True)
                self._reaper.start()
        return entry

    def get(self, sim_id: str) -> SimulationEntry:
        """The simulation, marked active now; 404 when there is none."""
        with self._lock:
            entry = self._entries.get(sim_id)
            if entry is None:
                raise UnknownSimulation(
                    f"no simulation {sim_id!r} (it may have been deleted or ended after "
                    f"{self.settings.idle_timeout_s:g} s without use)"
                )
            entry.last_active = time.monotonic()
            return entry

    def list(self) -> list[SimulationEntry]:
        with self._lock:
            return sorted(self._entries.values(), key=lambda e: e.created)

    def attach(self, entry: SimulationEntry) -> bool:
        """Count a websocket client; False when the simulation already has the most allowed."""
        with self._lock:
            if entry.clients >= self.settings.max_clients:
                return False
            entry.clients += 1
            entry.last_active = time.monotonic()
            return True

    def detach(self, entry: SimulationEntry) -> None:
        with self._lock:
            entry.clients -= 1
            entry.last_active = time.monotonic()

    def delete(self, sim_id: str) -> None:
        with self._lock:
            entry = self._entries.pop(sim_id, None)
        if entry is None:
            raise UnknownSimulation(f"no simulation {sim_id!r}")
        entry.runner.close()

    def close(self) -> None:
        """Stop every simulation and the reaper (server shutdown, tests)."""
        self._stop.set()
        with self._lock:
            entries, self._entries = list(self._entries.values()), {}
        for entry in entries:
            entry.runner.close()

    def _reap(self) -> None:
        while not self._stop.wait(self.settings.reap_every_s):
            now = time.monotonic()
            with self._lock:
                idle = [
                    e
                    for e in self._entries.values()
                    if e.clients == 0 and now - e.last_active > self.settings.idle_timeout_s
                ]
                for entry in idle:
                    del self._entries[entry.id]
            for entry in idle:
                entry.runner.close()
