"""The FastAPI application: serves the browser app and the JSON API.

This module only assembles the app; routes live in one module per resource
(projects, symbols, library, simulations and the monitor websocket).
"""

from __future__ import annotations

import asyncio
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from pathlib import Path

from fastapi import FastAPI
from fastapi.responses import HTMLResponse
from fastapi.staticfiles import StaticFiles

from .. import __version__
from ..storage import Workspace
from . import fbd, interchange, library, live_check, monitor, projects, simulations, symbols
from .context import registry_of
from .errors import install_error_handlers
from .limits import BodySizeLimit, Limits

STATIC_DIR = Path(__file__).parent / "static"

_PLACEHOLDER = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>LadderLab</title></head>
<body><h1>LadderLab</h1><p>The browser app has not been built yet: run <code>make run</code>.</p></body></html>
"""


@asynccontextmanager
async def _lifespan(app: FastAPI) -> AsyncIterator[None]:
    await asyncio.to_thread(registry_of(app).warm)  # the first simulation opens fast (docs/architecture.md)
    yield
    registry = getattr(app.state, "simulations", None)
    if registry is not None:  # end the simulations' and builds' processes with the server
        registry.close()


def create_app(workspace: Workspace, limits: Limits | None = None) -> FastAPI:
    app = FastAPI(title="LadderLab", version=__version__, lifespan=_lifespan)
    app.state.workspace = workspace
    app.state.limits = limits or Limits()
    install_error_handlers(app)
    app.add_middleware(BodySizeLimit, max_bytes=app.state.limits.max_body_bytes)

    @app.get("/api/health")
    async def health() -> dict[str, str]:  # on the event loop: answers whatever the worker threads are doing
        return {"status": "ok", "version": __version__}

    for module in (projects, symbols, library, simulations, monitor, interchange, fbd, live_check):
        app.include_router(module.router)

    if (STATIC_DIR / "index.html").is_file():
        app.mount("/", StaticFiles(directory=STATIC_DIR, html=True), name="app")
    else:

        @app.get("/", response_class=HTMLResponse)
        def placeholder() -> str:
            return _PLACEHOLDER

    return app
