"""The live simulations of one server: ids, limits, their processes, and ending the ones nobody uses.

Each simulation runs in a process of its own (``remote.SimulationHandle``); builds that only check
a project run in a small pool of build processes (``builds.BuildPool``). Both are started from the
same warm fork server and held to the same limits (``SimulationSettings``).

A simulation keeps running with no browser attached while a client may come back: when its last
websocket client leaves (a page reload, a closed tab), it runs on for ``orphan_grace_s`` (a reload
reattaches to it by its id within that time) and is then stopped; one that has no websocket client
and no request for ``idle_timeout_s`` is deleted. A reaper thread does both.
"""

from __future__ import annotations

import secrets
import threading
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..model import Diagnostic, Project
from .builds import BuildPool
from .supervisor import WorkerHub
from .worker_settings import WorkerSettings

if TYPE_CHECKING:
    from .remote import Maker, SimulationHandle

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
    orphan_grace_s: float = 30.0  # after the last client left, a running simulation is stopped after this
    watchdog_s: float = 0.1  # per scan and task, unless the task sets its own (Task.watchdog_ms)
    publish_s: float = 0.02  # newest values are published at most this often while running
    memory_mb: int = 1024  # address space of each simulation's (and build's) process
    history_mb: int = 256  # each simulation's scan history (issue 23): checkpoints and input log; 0: none
    build_timeout_s: float = 30.0  # wall time of one build (a check, or compiling a simulation)
    grace_s: float = 2.0  # a simulation's process that sends nothing for this long is ended
    history_timeout_s: float = 30.0  # a question to the scan history (find, diff, a step through a past scan)
    answer_s: float = 0.05  # REST stop answers within this, even while a long scan runs
    beat_s: float = 0.25  # a simulation's process says it is alive at least this often
    build_workers: int = 2  # processes checking projects (POST /api/check) at the same time
    log_entries: int = 10_000  # online log entries kept per simulation (older ones are counted)
    max_clients: int = 200  # websocket clients per simulation
    max_paths: int = 5_000  # variables per subscription
    max_instances: int = 32  # POU instances with element power flow per subscription
    max_message_bytes: int = 1 * MB  # one client message
    max_queued: int = 256  # status/log/trace/error messages waiting for a slow client; older logs are dropped

    def worker(self) -> WorkerSettings:
        return WorkerSettings(
            watchdog_s=self.watchdog_s,
            publish_s=self.publish_s,
            memory_bytes=self.memory_mb * MB if self.memory_mb else None,
            history_bytes=self.history_mb * MB,
            build_timeout_s=self.build_timeout_s,
            grace_s=self.grace_s,
            history_timeout_s=self.history_timeout_s,
            beat_s=self.beat_s,
            log_entries=self.log_entries,
        )


@dataclass
class SimulationEntry:
    id: str
    project: str
    revision: str
    created: float  # time.time()
    handle: SimulationHandle
    last_active: float  # time.monotonic()
    clients: int = 0
    orphaned: float | None = None  # time.monotonic() when the last client left; None: a client is attached


@dataclass
class SimulationRegistry:
    settings: SimulationSettings = field(default_factory=SimulationSettings)

    def __post_init__(self) -> None:
        self._entries: dict[str, SimulationEntry] = {}
        self._lock = threading.Lock()
        self._starting = 0  # simulations being built, counted against the limit
        self._stop = threading.Event()
        self._reaper: threading.Thread | None = None
        self._hub: WorkerHub | None = None
        self._builds: BuildPool | None = None

    @property
    def hub(self) -> WorkerHub:
        with self._lock:
            if self._hub is None:
                self._hub = WorkerHub()
            return self._hub

    @property
    def builds(self) -> BuildPool:
        with self._lock:
            if self._builds is None:
                worker = self.settings.worker()
                self._builds = BuildPool(self.settings.build_workers, worker.build_timeout_s, worker.memory_bytes)
            return self._builds

    def warm(self) -> None:
        """Start the worker machinery now (the fork server, one build process), so the first simulation and
        the first check do not wait for it (the server calls this in a thread as it starts; a server closed
        meanwhile starts nothing more)."""
        if not self._stop.is_set():
            self.hub  # noqa: B018
        if not self._stop.is_set():
            self.builds.warm()

    def check(self, project: Project) -> list[Diagnostic]:
        """Every diagnostic of ``project``, from a build process (raises ``builds.BuildError`` at a limit)."""
        return self.builds.check(project)

    def check_room(self) -> None:
        with self._lock:
            self._check_room()

    def _check_room(self) -> None:
        count = len(self._entries) + self._starting
        if count >= self.settings.max_simulations:
            raise RegistryFull(f"the server already runs {count} simulations, the most it allows; delete one first")

    def create(self, project: Project, revision: str, make: Maker | None = None) -> SimulationEntry:
        """Build ``project`` in a new simulation process (stopped), or have ``make`` make it there; raises
        ``remote.BuildFailed``, ``RegistryFull``."""
        # the server's side of a simulation (and the monitor's message models) comes with the first one: the server
        # makes its registry as it starts, before it answers /api/health (startup, issue 27)
        from .remote import SimulationHandle

        with self._lock:
            self._check_room()
            self._starting += 1
        try:
            handle = SimulationHandle(self.hub, project.model_dump_json(), self.settings.worker(), make)
            handle.launch()
        finally:
            with self._lock:
                self._starting -= 1
        with self._lock:
            sim_id = secrets.token_hex(6)
            entry = SimulationEntry(sim_id, project.name, revision, time.time(), handle, time.monotonic())
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
            entry.orphaned = None
            return True

    def detach(self, entry: SimulationEntry) -> None:
        with self._lock:
            entry.clients -= 1
            entry.last_active = time.monotonic()
            if entry.clients == 0:
                entry.orphaned = entry.last_active

    def delete(self, sim_id: str) -> None:
        with self._lock:
            entry = self._entries.pop(sim_id, None)
        if entry is None:
            raise UnknownSimulation(f"no simulation {sim_id!r}")
        entry.handle.note("the simulation was deleted", level="warning")
        entry.handle.close()

    def close(self) -> None:
        """Stop every simulation, the build processes and the reaper (server shutdown, tests)."""
        self._stop.set()
        with self._lock:
            entries, self._entries = list(self._entries.values()), {}
            hub, builds = self._hub, self._builds
        for entry in entries:
            entry.handle.close()
        if builds is not None:
            builds.close()
        if hub is not None:
            hub.close()

    def _reap(self) -> None:
        settings = self.settings
        while not self._stop.wait(min(settings.reap_every_s, settings.orphan_grace_s)):
            now = time.monotonic()
            with self._lock:
                idle = [
                    e
                    for e in self._entries.values()
                    if e.clients == 0 and now - e.last_active > settings.idle_timeout_s
                ]
                for entry in idle:
                    del self._entries[entry.id]
                orphans = [
                    e
                    for e in self._entries.values()
                    if e.orphaned is not None and now - e.orphaned > settings.orphan_grace_s
                ]
                for entry in orphans:
                    entry.orphaned = None  # stopped once; a client that comes and goes again restarts the grace
            for entry in idle:
                entry.handle.note(f"the simulation was deleted after {settings.idle_timeout_s:g} s without use")
                entry.handle.close()
            for entry in orphans:
                if entry.handle.status.state in ("running", "halted"):
                    entry.handle.request("stop", reason=f"no client for {settings.orphan_grace_s:g} s")
