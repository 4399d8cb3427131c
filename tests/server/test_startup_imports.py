"""``ladderlab serve`` starts without the compiler (issue 27, startup): the web process imports lark, the IR, the
code generator and the interchange code at their first use, never to answer ``/api/health``; nor the API's and the
monitor's models, the server's side of a simulation or the JSON Schemas, which the routes bring along.

The serve command runs for real in a fresh interpreter, up to the point where uvicorn would start serving; what
it imported by then is read from ``sys.modules``. The second test makes sure the check is not vacuous: a request
that needs the compiler does import it, in the same kind of process.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

#: What only a build, a worker or an export needs (the fork server imports them for the workers).
COMPILER = ("lark", "ladderlab.ir", "ladderlab.engine.codegen", "ladderlab.interchange", "ladderlab.st.parser")
#: What the routes need, included at the first request other than /api/health (server/routes.py).
ROUTES = ("ladderlab.model.api", "ladderlab.model.monitor", "ladderlab.model.schema", "ladderlab.simulation.remote")

_SERVE_UNTIL_UVICORN_RUNS = """
import gc, json, sys
import uvicorn
HEAVY = tuple(sys.argv[2].split(","))
def report(self):
    loaded = [m for m in sys.modules if any(m == c or m.startswith(c + ".") for c in HEAVY)]
    print("LOADED " + json.dumps(sorted(loaded)))
    print("GC " + json.dumps([gc.isenabled(), gc.get_freeze_count()]))
uvicorn.Server.run = report
from ladderlab.cli import main
main(["serve", "--port", "8765", "--workspace", sys.argv[1]])
"""


def _serve_until_uvicorn_runs(workspace: Path) -> dict[str, list[object]]:
    done = subprocess.run(
        [sys.executable, "-c", _SERVE_UNTIL_UVICORN_RUNS, str(workspace), ",".join(COMPILER + ROUTES)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    return {
        line.split(" ", 1)[0]: json.loads(line.split(" ", 1)[1])
        for line in done.stdout.splitlines()
        if line.startswith(("LOADED ", "GC "))
    }


def test_serve_imports_no_compiler_and_no_route_models_before_it_answers(tmp_path: Path) -> None:
    assert _serve_until_uvicorn_runs(tmp_path / "workspace")["LOADED"] == []


def test_serve_freezes_what_it_made_to_start_and_collects_again(tmp_path: Path) -> None:
    """collector.frozen_start: the start's objects are out of every later collection's way, and the collector is on
    again when the server runs (it was off while they were made)."""
    enabled, frozen = _serve_until_uvicorn_runs(tmp_path / "workspace")["GC"]
    assert enabled is True
    assert isinstance(frozen, int) and frozen > 10_000  # FastAPI's, uvicorn's and the app's objects: ~75,000


def test_the_first_export_imports_the_compiler_in_the_web_process(tmp_path: Path) -> None:
    """The same probe sees the compiler and the routes' modules once a route needs them (the check above can fail)."""
    code = (
        "import sys; from fastapi.testclient import TestClient; from ladderlab.server.app import create_app;"
        "from ladderlab.storage import Workspace; from ladderlab.examples import seed_workspace;"
        "w = Workspace(sys.argv[1]); name = seed_workspace(w); client = TestClient(create_app(w), base_url='http://127.0.0.1');"
        "assert client.get(f'/api/projects/{name}/export/st').status_code == 200;"
        "print(sorted({m.split('.')[0] if m.startswith('lark') else '.'.join(m.split('.')[:2]) for m in sys.modules"
        " if m.startswith(('lark', 'ladderlab.ir', 'ladderlab.interchange'))}));"
        "print(sorted(m for m in sys.argv[2].split(',') if m in sys.modules))"
    )
    done = subprocess.run(
        [sys.executable, "-c", code, str(tmp_path / "ws"), ",".join(ROUTES)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    compiler, routes = done.stdout.splitlines()
    assert compiler == "['ladderlab.interchange', 'ladderlab.ir', 'lark']"
    # the JSON Schemas are the CLI's (ladderlab schema, make schema): no route imports them
    assert routes == str(sorted(set(ROUTES) - {"ladderlab.model.schema"}))
