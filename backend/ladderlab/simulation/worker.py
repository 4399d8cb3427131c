"""The processes that run user programs: one per simulation, and the build workers that check projects.

The server never runs a user's program in its own process. ``supervisor.py`` starts these
functions in child processes (forked from a warm fork server) and talks to each over one
connection; every message is plain data (dicts, lists, strings, numbers), so the same
functions could run on another machine behind a job queue (docs/architecture.md, "Online mode").

``run_simulation(connection, spec)``: limits its address space to ``spec["memory_bytes"]``,
builds the project (``spec["project"]``, JSON text) and answers ``ready`` (the runner's
``info``, the POU instances and the addresses the program uses) or ``failed`` (the build's
diagnostics, or the limit it hit).
Then the main thread runs the ``SimRunner`` while a link thread passes requests
``{"id", "op", "args"}`` to it, sends ``beat`` at least every ``beat_s`` (the supervisor ends a
process that goes quiet) and ends the process when the server goes away. The runner's status,
log entries, frames and replies go out as ``{"type": ...}`` messages.

``serve_builds(connection, memory_bytes)``: answers ``{"op": "check", "project"}`` requests with
the project's diagnostics, one at a time, until the server closes the connection.
"""

from __future__ import annotations

import logging
import os
import resource
import threading
import time
from multiprocessing.connection import Connection
from typing import Any

from ..collector import collector_paused
from ..model import Diagnostic, Project, has_errors
from .build import build_project
from .check import check_project
from .commands import CommandError
from .runner import Reply, SimRunner

log = logging.getLogger(__name__)

MB = 1024 * 1024


class Link:
    """The worker's end of its connection: one sender at a time (engine and link threads both send)."""

    def __init__(self, connection: Connection) -> None:
        self.connection = connection
        self._lock = threading.Lock()
        self.last_sent = time.monotonic()

    def send(self, message: dict[str, Any]) -> None:
        with self._lock:
            try:
                self.connection.send(message)
            except (OSError, EOFError):  # the server is gone: nothing left to do for
                os._exit(0)
            self.last_sent = time.monotonic()

    # the runner's Sink
    def status(self, state: str, at: dict[str, Any] | None, stack: list[dict[str, Any]]) -> None:
        self.send({"type": "status", "state": state, "at": at, "stack": stack})

    def log(self, entry: dict[str, Any]) -> None:
        self.send({"type": "log", "entry": entry})

    def frame(self, frame: dict[str, Any]) -> None:
        self.send({"type": "frame", **frame})


def limit_memory(memory_bytes: int | None) -> None:
    """Cap this process's address space: a program that needs more gets MemoryError, a located fault."""
    if memory_bytes:
        resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))


def memory_message(memory_bytes: int | None, what: str) -> str:
    limit = f"{memory_bytes // MB} MB" if memory_bytes else "what the machine has"
    return f"{what} needs more memory than a simulation may use ({limit}; the server's memory_mb setting)"


def run_simulation(connection: Connection, spec: dict[str, Any]) -> None:
    """The body of a simulation's process (see the module docstring)."""
    link = Link(connection)
    limit_memory(spec.get("memory_bytes"))
    try:
        make = spec.get("make")
        if make is not None:  # another way in (remote.Maker): e.g. a failed test's last state (it runs scans)
            sim = make.function(watchdog_s=spec["watchdog_s"], **make.args)
        else:
            with collector_paused(for_life=True):  # this process runs this one program until it ends: frozen
                project = Project.model_validate_json(spec["project"])
                build = build_project(project, variant=spec.get("variant", "monitor"))
                if build.compiled is None or has_errors(build.diagnostics):
                    link.send({"type": "failed", "diagnostics": _dumped(build.diagnostics)})
                    return
                sim = build.simulation(watchdog_s=spec["watchdog_s"])
    except (LookupError, ValueError) as refused:  # a Maker's reason, in the user's words
        link.send({"type": "failed", "message": str(refused)})
        return
    except MemoryError:
        link.send({"type": "failed", "message": memory_message(spec.get("memory_bytes"), "building this project")})
        return
    except Exception as error:  # a bug of ours: say so instead of vanishing
        log.exception("building the simulation failed")
        link.send({"type": "failed", "message": f"internal error while building: {type(error).__name__}: {error}"})
        return
    runner = SimRunner(sim, link, publish_s=spec["publish_s"], history_bytes=spec.get("history_bytes", 0))
    io = [{"area": p.area, "address": p.address, "type": p.type, "names": p.names} for p in sim.io_points()]
    link.send({"type": "ready", "info": runner.info(), "instances": sim.instances(), "io": io})
    threading.Thread(target=_receive, args=(link, runner, spec["beat_s"]), name="ladderlab-link", daemon=True).start()
    runner.serve()


def _receive(link: Link, runner: SimRunner, beat_s: float) -> None:
    """Requests to the runner; a beat whenever nothing was sent for ``beat_s``; the end when the server goes."""
    connection = link.connection
    while True:
        try:
            waiting = connection.poll(beat_s)
            request = connection.recv() if waiting else None
        except (OSError, EOFError):
            os._exit(0)
        if request is not None:
            runner.submit(request["op"], request["args"], _replier(link, runner, request["id"]))
        if time.monotonic() - link.last_sent >= beat_s:
            link.send({"type": "beat"})


def _replier(link: Link, runner: SimRunner, request_id: int) -> Reply:
    """The answer to one request, with the simulation's figures right after it (what a REST command returns)."""

    def reply(result: object, error: CommandError | None) -> None:
        answer = {"type": "reply", "id": request_id, "info": runner.info()}
        if error is None:
            link.send({**answer, "result": result})
        else:
            link.send({**answer, "error": {"code": error.code, "message": error.message}})

    return reply


def serve_builds(connection: Connection, memory_bytes: int | None) -> None:
    """The body of a build worker: check projects one at a time (see the module docstring)."""
    limit_memory(memory_bytes)
    while True:
        try:
            request = connection.recv()
        except (OSError, EOFError):
            return
        try:
            project = Project.model_validate_json(request["project"])
            answer: dict[str, Any] = {"diagnostics": _dumped(check_project(project))}
        except MemoryError:
            answer = {"error": memory_message(memory_bytes, "checking this project")}
        except Exception as error:  # a bug of ours: say so instead of vanishing
            log.exception("checking a project failed")
            answer = {"error": f"internal error while checking: {type(error).__name__}: {error}"}
        try:
            connection.send(answer)
        except (OSError, EOFError):
            return


def _dumped(diagnostics: list[Diagnostic]) -> list[dict[str, Any]]:
    return [d.model_dump(mode="json") for d in diagnostics]
