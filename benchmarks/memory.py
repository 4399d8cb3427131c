"""Memory benchmark (issue 18 item 4): RSS of a server after 3,000 live checks and 3,000 simulations.

The ST editor posts its working copy to ``POST /api/check`` while the user types, and a class of
students creates and deletes simulations all day: neither may grow the server's memory. One
server app in this process (starlette's TestClient, no sockets) over a temporary workspace with
the example project; the resident set size (``/proc/self/statm``, Linux) is read after the first
100 operations of each kind (the allocator's working set is in place by then) and after all of
them. Target: within 20 MB of the level after the first 100. Prints one line per kind.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT)]

from ladderlab.server.app import create_app  # noqa: E402
from ladderlab.storage import Workspace, load_project_path  # noqa: E402
from tests.support import EXAMPLES, api_client  # noqa: E402

WARM_UP = 100


def rss_mb() -> float:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def operations(client):
    """The two operations measured: one live check of the example, one simulation created and deleted."""
    body = load_project_path(EXAMPLES / "motor").model_dump(mode="json")

    def check() -> None:
        assert client.post("/api/check", json=body).status_code == 200

    def simulation() -> None:
        sim_id = client.post("/api/projects/motor/simulations").json()["id"]
        assert client.delete(f"/api/simulations/{sim_id}").status_code == 204

    return {"check": check, "simulation create/delete": simulation}


def measure(count: int) -> list[tuple[str, float, float, float]]:
    """(kind, RSS after the warm-up, RSS after ``count`` operations, seconds per operation) per kind."""
    client = api_client(create_app(Workspace(pathlib.Path(tempfile.mkdtemp()) / "workspace")))
    assert client.post("/api/projects", json={"name": "motor", "example": "motor"}).status_code == 201
    rows = []
    for kind, operation in operations(client).items():
        for _ in range(WARM_UP):
            operation()
        base, started = rss_mb(), time.perf_counter()
        for _ in range(count - WARM_UP):
            operation()
        rows.append((kind, base, rss_mb(), (time.perf_counter() - started) / (count - WARM_UP)))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=3_000, help="operations of each kind (default 3,000)")
    args = parser.parse_args()
    for kind, base, end, seconds in measure(args.count):
        print(
            f"{kind}: RSS {base:.1f} MB after {WARM_UP}, {end:.1f} MB after {args.count}: "
            f"{end - base:+.1f} MB (target within 20 MB); {seconds * 1000:.1f} ms each"
        )


if __name__ == "__main__":
    main()
