"""The API's routes are included at their first use (issue 27, startup): ``/api/health`` answers before the route
modules are imported; the first other request, the OpenAPI document and the browser app see every route.

Each case runs in a fresh interpreter, since the route modules stay imported once any test has used them.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

_PROBE = """
import sys
from fastapi.testclient import TestClient
from ladderlab.server.app import create_app
from ladderlab.storage import Workspace
client = TestClient(create_app(Workspace(sys.argv[1])), base_url="http://127.0.0.1")
def loaded():
    return "ladderlab.server.projects" in sys.modules
assert client.get("/api/health").json()["status"] == "ok"
print("after health", loaded())
print(sys.argv[2], client.get(sys.argv[2]).status_code, loaded())
"""


def _probe(workspace: Path, path: str) -> list[str]:
    done = subprocess.run(
        [sys.executable, "-c", _PROBE, str(workspace), path], capture_output=True, text=True, timeout=120, check=True
    )
    return done.stdout.splitlines()


def test_health_answers_without_the_routes_and_the_first_api_request_includes_them(tmp_path: Path) -> None:
    assert _probe(tmp_path / "ws", "/api/projects") == ["after health False", "/api/projects 200 True"]


def test_the_openapi_document_lists_the_routes_included_lazily(tmp_path: Path) -> None:
    code = (
        "import sys; from fastapi.testclient import TestClient; from ladderlab.server.app import create_app;"
        "from ladderlab.storage import Workspace; client = TestClient(create_app(Workspace(sys.argv[1])),"
        " base_url='http://127.0.0.1'); paths = client.get('/openapi.json').json()['paths'];"
        "print('/api/health' in paths, '/api/projects' in paths, '/api/simulations/{sim_id}' in paths)"
    )
    done = subprocess.run(
        [sys.executable, "-c", code, str(tmp_path / "ws")], capture_output=True, text=True, timeout=120, check=True
    )
    assert done.stdout.split() == ["True", "True", "True"]


def test_the_browser_app_is_served_after_the_api_routes(tmp_path: Path) -> None:
    """``/`` (the catch-all mount of the browser app) is included last: it must not hide an API route."""
    lines = _probe(tmp_path / "ws", "/")
    assert lines == ["after health False", "/ 200 True"]
