"""Bounds that keep one client from exhausting the server: body size, project size, project count.

The body limit is checked while the body streams in (and up front from ``Content-Length``),
so an oversized upload is refused before it is held in memory.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Annotated

from fastapi import Depends, Request
from starlette.datastructures import Headers
from starlette.exceptions import HTTPException
from starlette.responses import JSONResponse
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from ..json_guard import json_problem
from ..model import Diagnostic, Project
from ..model.answers import ErrorDetail
from ..storage import Workspace
from ..storage.project_folder import project_files
from .errors import ApiError

MB = 1024 * 1024
log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Limits:
    max_body_bytes: int = 5 * MB
    max_project_bytes: int = 4 * MB  # stored files; below the body limit so any stored project can be sent back
    max_projects: int = 200
    max_websockets: int = 500  # open websocket connections of the whole server (each holds a file descriptor)


def _limits(request: Request) -> Limits:
    limits: Limits = request.app.state.limits
    return limits


LimitsDep = Annotated[Limits, Depends(_limits)]


def describe_size(size: int) -> str:
    return f"{size / MB:.1f} MB" if size >= MB else f"{size} bytes"


def _too_large_message(limit: int) -> str:
    return f"the request body is larger than the limit of {describe_size(limit)}"


class BodySizeLimit:
    """ASGI middleware: 413 for a request body over ``max_bytes``."""

    def __init__(self, app: ASGIApp, max_bytes: int) -> None:
        self.app = app
        self.max_bytes = max_bytes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        declared = Headers(scope=scope).get("content-length", "")
        if declared.isdigit() and int(declared) > self.max_bytes:
            detail = ErrorDetail(message=_too_large_message(self.max_bytes))
            await JSONResponse({"detail": detail.model_dump(mode="json")}, 413)(scope, receive, send)
            return
        received = 0

        async def limited_receive() -> Message:
            nonlocal received
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_bytes:
                    # An HTTPException is what FastAPI lets through from body reading (others become 400).
                    raise HTTPException(413, _too_large_message(self.max_bytes))
            return message

        await self.app(scope, limited_receive, send)


class WebsocketLimit:
    """ASGI middleware: at most ``max_open`` websocket connections at once; more are refused before the
    handshake (HTTP 403), so a flood of connections cannot exhaust the server's file descriptors.
    It logs once when the limit is reached and once when there is room again, not per refusal."""

    def __init__(self, app: ASGIApp, max_open: int) -> None:
        self.app = app
        self.max_open = max_open
        self.open = 0
        self.refused = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "websocket":
            await self.app(scope, receive, send)
            return
        if self.open >= self.max_open:
            if not self.refused:
                log.warning("%d websocket connections are open, the most allowed: refusing more", self.open)
            self.refused += 1
            await send({"type": "websocket.close", "code": 1013, "reason": "too many connections"})
            return
        self.open += 1
        try:
            await self.app(scope, receive, send)
        finally:
            self.open -= 1
            if self.refused and self.open < self.max_open:
                log.warning("websocket connections below the limit again; %d were refused", self.refused)
                self.refused = 0


class JsonGuard:
    """ASGI middleware: a JSON body nested deeper than the limit or holding a lone surrogate escape is a
    located 422 before any parser sees it (json_guard.py); the body is read once and passed on."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or media_type(Headers(scope=scope)) != "application/json":
            await self.app(scope, receive, send)
            return
        chunks, more = [], True
        try:
            while more:
                message = await receive()
                if message["type"] != "http.request":
                    break
                chunks.append(message.get("body", b""))
                more = message.get("more_body", False)
        except HTTPException as error:  # the body size limit, raised while reading
            detail = ErrorDetail(message=str(error.detail))
            await JSONResponse({"detail": detail.model_dump(mode="json")}, error.status_code)(scope, receive, send)
            return
        body = b"".join(chunks)
        problem = json_problem(body)
        if problem is not None:
            reason, line, column = problem
            diagnostic = Diagnostic(code="BAD-JSON", line=line, column=column, message=reason)
            detail = ErrorDetail(message=f"invalid request: {line}:{column}: {reason}", diagnostics=[diagnostic])
            await JSONResponse({"detail": detail.model_dump(mode="json")}, 422)(scope, receive, send)
            return
        sent = False

        async def replay() -> Message:
            nonlocal sent
            if sent:
                return await receive()
            sent = True
            return {"type": "http.request", "body": body, "more_body": False}

        await self.app(scope, replay, send)


def media_type(headers: Headers) -> str:
    """The media type of a request body, lower case, without parameters."""
    return headers.get("content-type", "").split(";", 1)[0].strip().lower()


def check_project_size(project: Project, limits: Limits) -> None:
    """Refuse a project whose stored files would exceed the project size limit."""
    size = sum(len(text.encode("utf-8")) for text in project_files(project).values())
    if size > limits.max_project_bytes:
        raise ApiError(
            413,
            f"project {project.name!r} would take {describe_size(size)} on disk, more than the "
            f"limit of {describe_size(limits.max_project_bytes)}",
        )


def check_room_for_project(workspace: Workspace, limits: Limits) -> None:
    """Refuse to create a project when the workspace already holds the maximum number."""
    count = len(workspace.names())
    if count >= limits.max_projects:
        raise ApiError(
            429, f"the workspace already holds {count} projects, the most this server allows; delete one first"
        )
