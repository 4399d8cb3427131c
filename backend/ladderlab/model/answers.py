"""The answers the server gives before its routes are included: error details and ``/api/health``.

The security middleware, the body limits and the error handlers are part of the app from its start, so these
shapes are kept apart from ``api.py``, which imports the project, monitor and cross-reference models (startup,
issue 27: ``ladderlab serve`` answers ``/api/health`` without them).
"""

from __future__ import annotations

from datetime import datetime

from pydantic import Field

from .base import Model
from .diagnostics import Diagnostic


class ErrorDetail(Model):
    """The ``detail`` of every error response except save conflicts."""

    message: str
    diagnostics: list[Diagnostic] = Field(default_factory=list)


class ConflictDetail(Model):
    """The ``detail`` of a 409 from a save based on an old revision."""

    message: str
    base_revision: str | None
    current_revision: str
    current_modified: datetime | None


class Health(Model):
    """``GET /api/health``: the server answers, and which version it is."""

    status: str = Field(description='"ok" while the server answers.')
    version: str
