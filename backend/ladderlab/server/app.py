"""The FastAPI application: serves the browser app and the JSON API."""

from __future__ import annotations

from datetime import datetime, timezone
from pathlib import Path

from fastapi import FastAPI
from fastapi.responses import HTMLResponse
from fastapi.staticfiles import StaticFiles

from .. import __version__
from ..model.api import ProjectSummary
from ..storage import Workspace

STATIC_DIR = Path(__file__).parent / "static"

_PLACEHOLDER = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>LadderLab</title></head>
<body><h1>LadderLab</h1><p>The browser app has not been built yet: run <code>make run</code>.</p></body></html>
"""


def create_app(workspace: Workspace) -> FastAPI:
    app = FastAPI(title="LadderLab", version=__version__)
    app.state.workspace = workspace

    @app.get("/api/health")
    def health() -> dict[str, str]:
        return {"status": "ok", "version": __version__}

    @app.get("/api/projects", response_model=list[ProjectSummary])
    def list_projects() -> list[ProjectSummary]:
        return [
            ProjectSummary(name=info.name, revision=info.revision, pou_count=info.pou_count,
                           modified=datetime.fromtimestamp(info.modified, tz=timezone.utc))
            for info in workspace.list()
        ]

    if (STATIC_DIR / "index.html").is_file():
        app.mount("/", StaticFiles(directory=STATIC_DIR, html=True), name="app")
    else:
        @app.get("/", response_class=HTMLResponse)
        def placeholder() -> str:
            return _PLACEHOLDER

    return app
