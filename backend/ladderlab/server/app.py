"""The FastAPI application: serves the browser app and the JSON API.

This module only assembles the app; routes live in one module per resource
(projects, symbols, library, simulations and the monitor websocket).
"""

from __future__ import annotations

import threading
import warnings
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI, Request, Response
from fastapi.responses import HTMLResponse
from fastapi.staticfiles import StaticFiles
from pydantic.warnings import UnsupportedFieldAttributeWarning

from .. import __version__
from ..model.answers import Health
from ..model.base import build_all
from ..storage import Workspace
from . import STATIC_DIR
from .context import registry_of
from .errors import install_error_handlers
from .limits import BodySizeLimit, JsonGuard, Limits, WebsocketLimit
from .routes import HEALTH, LazyRoutes
from .security import Security, SecurityMiddleware

_PLACEHOLDER = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>LadderLab</title></head>
<body><h1>LadderLab</h1><p>The browser app has not been built yet: run <code>make run</code>.</p></body></html>
"""


@asynccontextmanager
async def _lifespan(app: FastAPI) -> AsyncIterator[None]:
    # the worker machinery starts beside the server, which answers meanwhile: a first simulation asked for before
    # it is ready waits for it (docs/architecture.md; startup, issue 27)
    threading.Thread(target=registry_of(app).warm, name="ladderlab-warm", daemon=True).start()
    yield
    registry = getattr(app.state, "simulations", None)
    if registry is not None:  # end the simulations' and builds' processes with the server
        registry.close()


def create_app(workspace: Workspace, limits: Limits | None = None, security: Security | None = None) -> FastAPI:
    """The app over ``workspace``; ``security`` says how it is reached (default: this machine only, no sign-in)."""
    app = FastAPI(title="LadderLab", version=__version__, lifespan=_lifespan, separate_input_output_schemas=False)
    app.state.workspace = workspace
    app.state.limits = limits or Limits()
    app.state.security = security or Security()
    install_error_handlers(app)
    # the ~50 API routes build their validators when their modules are imported (~0.25 s of CPU): they are included
    # at the first request other than /api/health, or the first OpenAPI document (startup, issue 27)
    LazyRoutes.install(app, lambda: _include_routes(app))
    # the last added runs first: security checks, open websockets, body size, JSON guard, the lazy routes
    app.add_middleware(JsonGuard)
    app.add_middleware(BodySizeLimit, max_bytes=app.state.limits.max_body_bytes)
    app.add_middleware(WebsocketLimit, max_open=app.state.limits.max_websockets)
    app.add_middleware(SecurityMiddleware, security=app.state.security)

    # a plain route: FastAPI's typed one (documented, below) checks its answer's model against pydantic.v1 as it is
    # declared, which imports pydantic.v1 (~60 ms of CPU)
    app.router.add_route(HEALTH, _health_answer, methods=["GET"], include_in_schema=False)
    return app


async def health() -> Health:  # on the event loop: answers whatever the worker threads are doing
    return Health(status="ok", version=__version__)


async def _health_answer(request: Request) -> Response:
    return Response((await health()).model_dump_json(), media_type="application/json")


def _include_routes(app: FastAPI) -> None:
    """The API's routes (``/api/health`` again, for the OpenAPI document), then the browser app under ``/`` (a
    catch-all mount, so last)."""
    build_all()  # the deferred models (model/base.py), here with the routes rather than in the first answers
    # FastAPI wraps a body parameter's model in ``Annotated[Model, Field(alias=...)]`` and silences pydantic's warning
    # about that alias while it builds the validator; over a deferred model the validator is built at the first request
    # instead, outside FastAPI's filter, so the filter is the app's (fastapi/_compat/v2.py ModelField.__post_init__)
    warnings.filterwarnings("ignore", category=UnsupportedFieldAttributeWarning)
    from . import (
        fbd,
        interchange,
        library,
        live_check,
        login,
        monitor,
        projects,
        refactor,
        simulations,
        symbols,
        tests,
        xref,
    )

    app.get(HEALTH)(health)
    for module in (
        projects,
        symbols,
        library,
        simulations,
        monitor,
        interchange,
        fbd,
        live_check,
        refactor,
        login,
        tests,
        xref,
    ):
        app.include_router(module.router)
    app.include_router(projects.examples_router)
    if (STATIC_DIR / "index.html").is_file():
        app.mount("/", StaticFiles(directory=STATIC_DIR, html=True), name="app")
    else:

        @app.get("/", response_class=HTMLResponse, include_in_schema=False)
        def placeholder() -> str:
            return _PLACEHOLDER
