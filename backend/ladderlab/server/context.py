"""What every route needs from the app: the workspace, timestamps and revision headers."""

from __future__ import annotations

import threading
from datetime import UTC, datetime
from typing import Annotated

from fastapi import Depends, FastAPI, Request

from ..simulation.registry import SimulationRegistry
from ..storage import Workspace


def _workspace(request: Request) -> Workspace:
    workspace: Workspace = request.app.state.workspace
    return workspace


WorkspaceDep = Annotated[Workspace, Depends(_workspace)]


def registry_of(app: FastAPI) -> SimulationRegistry:
    """The app's registry (``app.state.simulations``), created with default settings on first use."""
    state = app.state
    registry = getattr(state, "simulations", None)
    if registry is None:
        with _CREATE_LOCK:
            registry = getattr(state, "simulations", None)
            if registry is None:
                registry = state.simulations = SimulationRegistry()
    return registry


_CREATE_LOCK = threading.Lock()


def modified_at(timestamp: float) -> datetime:
    """A file time as an aware UTC datetime (JSON: ISO 8601 with offset, unambiguous in any browser)."""
    return datetime.fromtimestamp(timestamp, tz=UTC)


def etag(revision: str) -> dict[str, str]:
    """The ``ETag`` header of a response about ``revision`` (a strong validator: revisions are content hashes)."""
    return {"ETag": f'"{revision}"'}


def revision_from_header(value: str) -> str:
    """The revision an ``If-Match`` header names; accepts ``abc``, ``"abc"`` and ``W/"abc"``."""
    value = value.strip()
    if value.startswith("W/"):
        value = value[2:]
    if len(value) >= 2 and value[0] == value[-1] == '"':
        value = value[1:-1]
    return value
