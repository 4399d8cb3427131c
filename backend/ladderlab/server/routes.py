"""The API's routes included at their first use (startup, issue 27).

FastAPI builds a route's validators (pydantic TypeAdapters of its body and answer) when the route is declared, so
importing the route modules costs about as much CPU as starting a bare FastAPI app. ``/api/health`` is declared
with the app and answers without them; any other request, websocket or OpenAPI document includes them first.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from fastapi import FastAPI
from starlette.types import ASGIApp, Receive, Scope, Send

#: The one path served before the routes are included.
HEALTH = "/api/health"


class LazyRoutes:
    """Runs ``include`` once, before the first request (other than ``/api/health``) reaches the router."""

    def __init__(self, include: Callable[[], None]) -> None:
        self._include: Callable[[], None] | None = include
        self._lock = threading.Lock()

    @classmethod
    def install(cls, app: FastAPI, include: Callable[[], None]) -> None:
        """Adds the middleware to ``app`` (innermost of those added so far); ``app.openapi()`` includes them too."""
        lazy = cls(include)
        openapi = app.openapi

        def openapi_with_routes() -> dict[str, Any]:
            lazy.ensure()
            return openapi()

        app.openapi = openapi_with_routes  # type: ignore[method-assign]  # FastAPI documents replacing it
        app.add_middleware(_Middleware, lazy=lazy)

    def ensure(self) -> None:
        if self._include is None:
            return
        with self._lock:
            if self._include is not None:
                self._include()
                self._include = None


class _Middleware:
    """Includes the routes before the first request that may need them reaches the router."""

    def __init__(self, app: ASGIApp, lazy: LazyRoutes) -> None:
        self.app = app
        self.lazy = lazy

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "lifespan" and scope["path"] != HEALTH:
            self.lazy.ensure()
        await self.app(scope, receive, send)
