"""Checking projects in build worker processes, each check under a wall-time and a memory limit.

The ST editor asks for a check while the user types (``POST /api/check``), and a check parses,
checks and lowers the whole project: on hostile or unlucky input that can take very long or a lot
of memory, which the server must not pay for. ``BuildPool`` keeps ``size`` warm worker processes
(``worker.serve_builds``, forked like the simulations'); a check takes an idle one, sends it the
project as JSON text and waits at most ``timeout_s`` for the diagnostics. A worker that takes longer
is killed and replaced; one that has served ``recycle_after`` checks is replaced too, so no worker
grows without bound.
"""

from __future__ import annotations

import pickle
import threading
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess

from ..model import Diagnostic, Project
from .supervisor import kill, receive, start_process

BUILD_LIMIT = "BUILD-LIMIT"
SERVE_BUILDS = "ladderlab.simulation.worker:serve_builds"  # by name: the server does not import the compiler


class BuildError(Exception):
    """A check that hit a limit or lost its worker; ``message`` says which, in the user's words."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


@dataclass
class _Worker:
    process: BaseProcess
    connection: Connection
    served: int = 0


class BuildPool:
    """Up to ``size`` build workers, started on demand and kept warm between checks."""

    def __init__(
        self, size: int = 2, timeout_s: float = 30.0, memory_bytes: int | None = None, recycle_after: int = 200
    ) -> None:
        self.size, self.timeout_s, self.memory_bytes, self.recycle_after = size, timeout_s, memory_bytes, recycle_after
        self._idle: list[_Worker] = []
        self._started = 0
        self._changed = threading.Condition()
        self._closed = False

    def check(self, project: Project) -> list[Diagnostic]:
        """Every diagnostic of ``project`` (``check.check_project``), computed in a worker; raises ``BuildError``."""
        worker = self._take()
        try:
            worker.connection.send({"op": "check", "project": project.model_dump_json()})
            if not worker.connection.poll(self.timeout_s):
                raise BuildError(
                    f"the check did not finish within {self.timeout_s:g} s (the server's build_timeout_s "
                    "setting): the project is too large, or nested too deeply, to check"
                )
            answer = receive(worker.connection)
        except (EOFError, OSError, pickle.UnpicklingError):
            self._discard(worker)
            raise BuildError("the check ended unexpectedly (its process stopped; e.g. it ran out of memory)") from None
        except BaseException:
            self._discard(worker)
            raise
        self._give_back(worker)
        if "error" in answer:
            raise BuildError(answer["error"])
        return [Diagnostic.model_validate(d) for d in answer["diagnostics"]]

    def warm(self) -> None:
        """Start one build worker now (and so the fork server: ``supervisor.py``), not on the first request."""
        self._give_back(self._take(), served=False)

    def close(self) -> None:
        with self._changed:
            self._closed = True
            idle, self._idle = self._idle, []
        for worker in idle:
            self._discard(worker)

    def _take(self) -> _Worker:
        """An idle worker, or a new one while fewer than ``size`` run; else wait for one."""
        with self._changed:
            while not self._idle and self._started >= self.size:
                self._changed.wait()
            if self._idle:
                return self._idle.pop()
            self._started += 1
        try:
            process, connection = start_process(
                "ladderlab.simulation.worker:serve_builds", self.memory_bytes, name="ladderlab-build"
            )
        except BaseException:
            self._forget_one()
            raise
        return _Worker(process, connection)

    def _give_back(self, worker: _Worker, served: bool = True) -> None:
        worker.served += served
        if self._closed or worker.served >= self.recycle_after:
            self._discard(worker)
            return
        with self._changed:
            self._idle.append(worker)
            self._changed.notify()

    def _discard(self, worker: _Worker) -> None:
        worker.connection.close()
        kill(worker.process)
        self._forget_one()

    def _forget_one(self) -> None:
        with self._changed:
            self._started -= 1
            self._changed.notify()
