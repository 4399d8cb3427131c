"""Starting worker processes and watching all of them from one thread.

Workers are forked from a fork server (``multiprocessing``'s ``forkserver``) that has imported
and warmed up the engine (``preload.py``): a new simulation's process starts in milliseconds with
the parser and code generator ready, without copying the server's own state (its threads, sockets
and event loop) into the child. The fork server is started once, in the background, when the first
``WorkerHub`` is made.

``WorkerHub`` owns one thread that waits on every worker's connection at once
(``multiprocessing.connection.wait``): it hands each message to that worker's ``Peer``, tells the
peer when its process is gone (end of file, or a message that is not plain data), and asks every
peer about ten times a second whether its process still answers (``Peer.supervise``): a peer that
decides it does not kills its process (``kill``), which the hub then reports as lost. Messages
from workers are read with ``receive``: plain data only, never objects.
"""

from __future__ import annotations

import contextlib
import importlib
import io
import logging
import multiprocessing
import os
import pickle
import threading
import time
from collections.abc import Callable
from multiprocessing import spawn
from multiprocessing.connection import Connection, wait
from multiprocessing.context import ForkServerContext
from multiprocessing.process import BaseProcess
from typing import Any, Protocol

log = logging.getLogger(__name__)

PRELOAD = "ladderlab.simulation.preload"
SUPERVISE_EVERY_S = 0.1
MAX_MESSAGE_BYTES = 512 * 1024 * 1024  # a worker that sends more is treated as lost


class _PlainData(pickle.Unpickler):
    """Unpickles dicts, lists, tuples, strings, numbers, booleans and None only.

    A worker process runs a user's program: a message from it may name no class or function (the way pickle
    runs code), so even a worker that was made to run arbitrary code cannot reach into the server this way."""

    def find_class(self, module: str, name: str) -> Any:
        raise pickle.UnpicklingError(f"a worker's message may hold plain data only, not {module}.{name}")


def receive(connection: Connection) -> Any:
    """The next message from a worker (plain data; see ``_PlainData``)."""
    return _PlainData(io.BytesIO(connection.recv_bytes(MAX_MESSAGE_BYTES))).load()


_context_lock = threading.Lock()
_context: ForkServerContext | None = None


def worker_context() -> ForkServerContext:
    """The multiprocessing context workers start from (a warm fork server, started in the background)."""
    global _context
    with _context_lock:
        if _context is None:
            context: ForkServerContext = multiprocessing.get_context("forkserver")
            context.set_forkserver_preload([PRELOAD])
            threading.Thread(target=_start_fork_server, name="ladderlab-forkserver", daemon=True).start()
            _context = context
        return _context


def _start_fork_server() -> None:
    from multiprocessing import forkserver

    try:
        forkserver.ensure_running()
    except Exception:  # the first worker start tries again and reports it
        log.exception("the fork server did not start")


def _with_settings(settings: dict[str, str], target: str, *args: Any) -> None:
    """Run the function ``target`` names with the server's ``LADDERLAB_*`` settings as they are now (the fork
    server's environment is the one it started with; the documented limits are read from these: docs/security.md)."""
    for key in [key for key in os.environ if key.startswith("LADDERLAB_")]:
        del os.environ[key]
    os.environ.update(settings)
    module, function = target.split(":")
    getattr(importlib.import_module(module), function)(*args)


def start_process(target: str, *args: Any, name: str) -> tuple[BaseProcess, Connection]:
    """Start ``target(connection, *args)`` in a worker process; returns it and the server's end of the connection.

    ``target`` is a function's name, ``"package.module:function"``: the worker imports it (the server never
    imports the worker's modules, which import the compiler: startup, issue 27), and the worker does not import
    the server's main module (multiprocessing would run a main script again in every worker, costing time and
    running code not meant to run there)."""
    context = worker_context()
    ours, theirs = context.Pipe()
    settings = {key: value for key, value in os.environ.items() if key.startswith("LADDERLAB_")}
    process = context.Process(target=_with_settings, args=(settings, target, theirs, *args), name=name, daemon=True)
    with _starting:
        prepare = spawn.get_preparation_data
        spawn.get_preparation_data = _without_main(prepare)  # type: ignore[assignment]  # patched while starting
        try:
            process.start()
        finally:
            spawn.get_preparation_data = prepare
    theirs.close()
    return process, ours


_starting = threading.Lock()


def _without_main(prepare: Callable[[str], dict[str, Any]]) -> Callable[[str], dict[str, Any]]:
    def preparation_data(name: str) -> dict[str, Any]:
        data = prepare(name)
        data.pop("init_main_from_path", None)
        data.pop("init_main_from_name", None)
        return data

    return preparation_data


def kill(process: BaseProcess) -> None:
    """End a worker at once (SIGKILL: it may be stuck where nothing else reaches it) and reap it in the background."""
    try:
        process.kill()
    except (OSError, ValueError, AttributeError):
        return  # already gone or never started
    threading.Thread(target=process.join, args=(5.0,), name="ladderlab-reap", daemon=True).start()


class Peer(Protocol):
    """The server's side of one worker, as the hub sees it."""

    def receive(self, message: dict[str, Any]) -> None: ...

    def lost(self, reason: str | None = None) -> None:
        """The connection ended: the process is gone (crashed, killed or exited); or ``reason``: it broke the
        protocol (its process is to be ended)."""

    def supervise(self, now: float) -> None:
        """Called about every 0.1 s: kill the process if it no longer answers."""


class WorkerHub:
    """One thread reading every worker's connection and supervising the workers."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._peers: dict[Connection, Peer] = {}
        self._wake_r, self._wake_w = multiprocessing.Pipe(duplex=False)
        self._stop = False
        self._thread: threading.Thread | None = None
        worker_context()

    def watch(self, connection: Connection, peer: Peer) -> None:
        """Read ``connection`` for ``peer`` from now on (until it ends or ``forget``)."""
        with self._lock:
            self._peers[connection] = peer
            if self._thread is None:
                self._thread = threading.Thread(target=self._loop, name="ladderlab-workers", daemon=True)
                self._thread.start()
        self._wake()

    def forget(self, connection: Connection) -> None:
        with self._lock:
            self._peers.pop(connection, None)
        self._wake()

    def close(self) -> None:
        self._stop = True
        self._wake()

    def _wake(self) -> None:
        with contextlib.suppress(OSError):
            self._wake_w.send_bytes(b".")

    def _loop(self) -> None:
        next_check = time.monotonic()
        while not self._stop:
            with self._lock:
                connections = [*self._peers, self._wake_r]
            for ready in wait(connections, timeout=SUPERVISE_EVERY_S):
                if ready is self._wake_r:
                    while self._wake_r.poll():
                        self._wake_r.recv_bytes()
                    continue
                self._read(ready)  # type: ignore[arg-type]  # every waitable but the wake pipe is a Connection
            now = time.monotonic()
            if now >= next_check:
                next_check = now + SUPERVISE_EVERY_S
                with self._lock:
                    peers = list(self._peers.values())
                for peer in peers:
                    self._guarded(peer.supervise, now)

    def _read(self, connection: Connection) -> None:
        with self._lock:
            peer = self._peers.get(connection)
        if peer is None:
            return
        try:
            message = receive(connection)
        except (EOFError, OSError, pickle.UnpicklingError) as error:
            with self._lock:
                self._peers.pop(connection, None)
            broken = None if isinstance(error, EOFError) else f"its process sent what the server refuses ({error})"
            self._guarded(peer.lost, broken)
            return
        self._guarded(peer.receive, message)

    @staticmethod
    def _guarded(action: Callable[..., None], *args: object) -> None:
        try:
            action(*args)
        except Exception:  # one worker's trouble must not stop the thread that serves them all
            log.exception("handling a worker message failed")
