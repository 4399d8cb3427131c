"""The server's side of traces (``trace.py`` records them in the simulation's process): chunks merged per client
until its sender takes them. Imports no engine code (the server imports this at start: issue 27)."""

from __future__ import annotations

import threading
from typing import Any

from ..model.monitor import MAX_TRACE_SAMPLES, DisplayType, TraceData, TraceTriggered


class TraceInbox:
    """The server's side: chunks from the simulation's frames, merged per client until its sender takes them.

    Threads: the supervisor adds, the event loop takes; hence the lock."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._running: set[object] = set()
        self._pending: dict[object, dict[str, Any]] = {}

    def open(self, owner: object) -> None:
        """``owner`` starts a trace: what is pending of its previous one is dropped."""
        with self._lock:
            self._running.add(owner)
            self._pending.pop(owner, None)

    def add(self, owner: object, chunk: dict[str, Any]) -> None:
        with self._lock:
            if owner not in self._running:
                return
            pending = self._pending.get(owner)
            if pending is None or pending["id"] != chunk["id"]:
                self._pending[owner] = pending = {**chunk, "values": {p: list(v) for p, v in chunk["values"].items()}}
                pending["scans"], pending["time_ms"] = list(chunk["scans"]), list(chunk["time_ms"])
            else:
                pending["scans"] += chunk["scans"]
                pending["time_ms"] += chunk["time_ms"]
                for path, column in chunk["values"].items():
                    pending["values"][path] += column
                pending["state"] = chunk["state"]
                pending["triggered"] = pending["triggered"] or chunk["triggered"]
                pending["lost"] += chunk["lost"]
            excess = len(pending["scans"]) - MAX_TRACE_SAMPLES
            if excess > 0:  # the client is not taking them: keep the newest
                del pending["scans"][:excess], pending["time_ms"][:excess]
                for column in pending["values"].values():
                    del column[:excess]
                pending["lost"] += excess

    def take(self, owner: object) -> TraceData | None:
        """``owner``'s samples since its previous chunk, or None; a finished trace is forgotten with its last chunk."""
        with self._lock:
            pending = self._pending.pop(owner, None)
            if pending is None:
                return None
            if pending["state"] == "done":
                self._running.discard(owner)
        triggered, types = pending["triggered"], pending.get("types") or {}
        return TraceData.model_construct(
            type="trace_data",
            **{
                **pending,
                "triggered": TraceTriggered(**triggered) if triggered is not None else None,
                "types": {path: DisplayType(**shown) for path, shown in types.items()},
            },
        )

    def active(self, owner: object) -> bool:
        with self._lock:
            return owner in self._running

    def drop(self, owner: object) -> None:
        with self._lock:
            self._running.discard(owner)
            self._pending.pop(owner, None)
