"""Every failure becomes a JSON ``{"detail": {...}}`` response with a message a user can act on.

Routes raise ``ApiError`` or let storage errors propagate; the handlers here map them to
status codes in one place, so no route repeats the mapping and no exception reaches a
client as an HTML page or a bare string.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from datetime import datetime
from http import HTTPStatus
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from pydantic import BaseModel
from pydantic_core import ErrorDetails
from starlette.exceptions import HTTPException

from ..model import Diagnostic
from ..model.answers import ConflictDetail, ErrorDetail
from ..model.base import Model
from ..simulation.registry import RegistryFull, UnknownSimulation
from ..storage import (
    AlreadyExistsError,
    ConflictError,
    InvalidNameError,
    NotFoundError,
    ProjectLoadError,
    StorageError,
    StorageFullError,
)
from ..storage.errors import expectation, json_path
from .context import modified_at

log = logging.getLogger(__name__)


class ApiError(Exception):
    """A request the server refuses, with the HTTP status, a message and optional located diagnostics."""

    def __init__(self, status: int, message: str, diagnostics: list[Diagnostic] | None = None) -> None:
        super().__init__(message)
        self.status = status
        self.detail = ErrorDetail(message=message, diagnostics=diagnostics or [])


class ErrorResponse(Model):
    detail: ErrorDetail


class ConflictResponse(Model):
    detail: ConflictDetail


def responses(*codes: int) -> dict[int | str, dict[str, Any]]:
    """OpenAPI documentation of a route's error statuses (a 409 is either shape)."""
    return {
        code: {
            "model": ErrorResponse | ConflictResponse if code == 409 else ErrorResponse,
            "description": _DESCRIPTIONS[code],
        }
        for code in codes
    }


_DESCRIPTIONS = {
    404: "No such project or POU.",
    409: "The project already exists, or a save is based on an old revision (ConflictDetail).",
    413: "The request body or the project is too large.",
    422: "Bad name, invalid model or a project that does not load; see the diagnostics.",
    428: "The save needs an If-Match header naming the revision it is based on.",
    429: "Too many projects in the workspace.",
    507: "The disk is full: nothing was saved and the stored project is unchanged.",
}

_STORAGE_STATUS: list[tuple[type[StorageError], int]] = [
    (NotFoundError, 404),
    (AlreadyExistsError, 409),
    (InvalidNameError, 422),
    (ProjectLoadError, 422),
    (StorageFullError, 507),
]


def install_error_handlers(app: FastAPI) -> None:
    app.add_exception_handler(ApiError, _api_error)
    app.add_exception_handler(RegistryFull, _simulation_error)
    app.add_exception_handler(UnknownSimulation, _simulation_error)
    app.add_exception_handler(ConflictError, _conflict)
    app.add_exception_handler(StorageError, _storage_error)
    app.add_exception_handler(RequestValidationError, _request_invalid)
    app.add_exception_handler(HTTPException, _http_error)
    app.add_exception_handler(OSError, _os_error)
    app.add_exception_handler(Exception, _internal_error)


def _json(status: int, detail: BaseModel, headers: Mapping[str, str] | None = None) -> JSONResponse:
    return JSONResponse({"detail": detail.model_dump(mode="json")}, status, headers=headers)


async def _api_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, ApiError)
    return _json(exc.status, exc.detail)


async def _simulation_error(request: Request, exc: Exception) -> JSONResponse:
    status = 429 if isinstance(exc, RegistryFull) else 404
    return _json(status, ErrorDetail(message=str(exc)))


async def _conflict(request: Request, exc: Exception) -> JSONResponse:
    """409 with both revisions and when the stored one was written, for the "someone else saved" dialog."""
    assert isinstance(exc, ConflictError)
    current_modified: datetime | None = None
    name = request.path_params.get("name")
    if name is not None:
        try:
            current_modified = modified_at(request.app.state.workspace.load(name).modified)
        except (StorageError, OSError):
            current_modified = None  # deleted or broken meanwhile: the revisions still say what happened
    detail = ConflictDetail(
        message=exc.diagnostics[0].message,
        base_revision=exc.base_revision,
        current_revision=exc.current_revision,
        current_modified=current_modified,
    )
    return _json(409, detail)


async def _storage_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, StorageError)
    status = next((code for kind, code in _STORAGE_STATUS if isinstance(exc, kind)), 500)
    message = "; ".join(d.message for d in exc.diagnostics) or "storage error"
    if isinstance(exc, ProjectLoadError):
        name = request.path_params.get("name") or request.query_params.get("project")
        count = len(exc.diagnostics)
        message = f"project {name!r} cannot be loaded: {count} problem{'s' * (count != 1)} in its files"
    return _json(status, ErrorDetail(message=message, diagnostics=exc.diagnostics))


async def _request_invalid(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    diagnostics = [_request_diagnostic(err, exc.body) for err in exc.errors()]
    return _json(422, ErrorDetail(message=f"invalid request: {summarise(diagnostics)}", diagnostics=diagnostics))


def summarise(diagnostics: list[Diagnostic], shown: int = 3) -> str:
    """The first few problems as one line, for clients that show only ``message``."""
    parts = [f"{d.location()}: {d.message}" if d.location() else d.message for d in diagnostics[:shown]]
    more = len(diagnostics) - shown
    return "; ".join(parts) + (f" (and {more} more)" if more > 0 else "")


def _request_diagnostic(err: ErrorDetails, body: Any) -> Diagnostic:
    """A located diagnostic for one validation error: JSON path into the body, or the parameter's name."""
    where, *loc = err["loc"]
    if err["type"] == "json_invalid":
        text = body if isinstance(body, str) else ""
        offset = loc[0] if loc and isinstance(loc[0], int) else 0
        line = text.count("\n", 0, offset) + 1
        column = offset - (text.rfind("\n", 0, offset) + 1) + 1
        reason = (err.get("ctx") or {}).get("error", "syntax error")
        return Diagnostic(code="BAD-JSON", line=line, column=column, message=f"invalid JSON: {reason}")
    if where == "body":
        if not loc and err["type"] == "missing":
            return Diagnostic(code="BAD-REQUEST", json_path="$", message="the request needs a JSON body")
        return Diagnostic(code="BAD-REQUEST", json_path=json_path(body, tuple(loc)), message=expectation(err))
    name = ".".join(str(part) for part in loc)
    return Diagnostic(code="BAD-REQUEST", message=f"{where} parameter {name!r}: {expectation(err)}")


async def _http_error(request: Request, exc: Exception) -> JSONResponse:
    """Framework errors (unknown route 404, 405, ...) in the same shape as ours."""
    assert isinstance(exc, HTTPException)
    message = str(exc.detail)
    if message == HTTPStatus(exc.status_code).phrase:  # the framework's bare "Not Found": say what was not found
        message = f"{message}: {request.method} {request.url.path}"
    return _json(exc.status_code, ErrorDetail(message=message), headers=exc.headers)


async def _os_error(request: Request, exc: Exception) -> JSONResponse:
    """A read or write of the workspace failed (disk full, permissions). Saves write each file
    atomically, so every file still holds either its previous or its new content."""
    assert isinstance(exc, OSError)
    log.exception("workspace I/O error on %s %s", request.method, request.url.path)
    reason = exc.strerror or str(exc) or type(exc).__name__
    return _json(
        500,
        ErrorDetail(
            message=f"the workspace could not be read or written: {reason}. Reload the project to see what is stored."
        ),
    )


async def _internal_error(request: Request, exc: Exception) -> JSONResponse:
    log.exception("internal error on %s %s", request.method, request.url.path)
    return _json(500, ErrorDetail(message=f"internal server error: {type(exc).__name__}: {exc}"))
