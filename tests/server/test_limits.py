"""Security and limits: body size, names that try to leave the workspace, JSON for every error."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from ladderlab.server.app import create_app
from ladderlab.server.limits import Limits
from ladderlab.storage import Workspace
from tests.support import api_client

from .helpers import detail, folder_bytes


def test_oversized_body_is_413(client: TestClient, workspace: Workspace, motor: str) -> None:
    """The default limit is 5 MB; the body is refused from its Content-Length, before it is read."""
    before = folder_bytes(workspace.root / "motor")
    payload = b'{"name": "motor", "globals": "' + b"x" * (5 * 1024 * 1024) + b'"}'
    response = client.put(
        "/api/projects/motor", content=payload, headers={"If-Match": motor, "Content-Type": "application/json"}
    )
    assert response.status_code == 413
    assert detail(response)["message"] == "the request body is larger than the limit of 5.0 MB"
    assert folder_bytes(workspace.root / "motor") == before


def test_streamed_body_without_length_is_cut_at_the_limit(workspace: Workspace) -> None:
    client = api_client(create_app(workspace, Limits(max_body_bytes=1000)))

    def chunks() -> Iterator[bytes]:
        yield b'{"name": "x", "example": "'
        for _ in range(100):
            yield b"y" * 100
        yield b'"}'

    response = client.post("/api/projects", content=chunks(), headers={"Content-Type": "application/json"})
    assert response.status_code == 413
    assert detail(response)["message"] == "the request body is larger than the limit of 1000 bytes"
    assert client.get("/api/projects").json() == []


def test_body_at_the_limit_is_accepted(workspace: Workspace) -> None:
    body = b'{"name": "ok"}'
    client = api_client(create_app(workspace, Limits(max_body_bytes=len(body))))
    assert client.post("/api/projects", content=body, headers={"Content-Type": "application/json"}).status_code == 201


@pytest.mark.parametrize(
    "path",
    [
        "/api/projects/..",
        "/api/projects/%2E%2E",
        "/api/projects/.locks",
        "/api/projects/%2e%2e%2fetc",
        "/api/projects/..%2F..%2Fetc",
        "/api/projects/a%00b",
    ],
)
def test_traversal_names_never_reach_outside_the_workspace(
    client: TestClient, workspace: Workspace, tmp_path: Path, path: str
) -> None:
    (tmp_path / "secret").mkdir()
    (tmp_path / "secret" / "project.json").write_text('{"name": "secret", "format": "ladderlab/1"}')
    for method in ("GET", "DELETE"):
        response = client.request(method, path)
        # the client normalises '..' away, so some of these reach the browser app's mount (405 for DELETE)
        assert response.status_code in (404, 405, 422), (method, path, response.text)
        detail(response)
    response = client.put(path, json={"name": "secret"}, headers={"If-Match": "0"})
    assert response.status_code in (404, 405, 422)
    assert (tmp_path / "secret" / "project.json").is_file()


def test_traversal_pou_names_are_refused(client: TestClient, workspace: Workspace, motor: str) -> None:
    pou = {"name": "../../evil", "kind": "program", "language": "st"}
    response = client.put("/api/projects/motor/pous/..%2F..%2Fevil", json=pou, headers={"If-Match": motor})
    assert response.status_code in (404, 405, 422)  # 405: normalised to /evil, the browser app's mount
    response = client.put("/api/projects/motor", headers={"If-Match": motor}, json={"name": "motor", "pous": [pou]})
    assert response.status_code == 422
    assert [d["code"] for d in detail(response)["diagnostics"]] == ["BAD-NAME"]
    assert not any(p.name == "evil.st" for p in workspace.root.parent.rglob("*"))


def test_unknown_routes_and_methods_answer_json(client: TestClient) -> None:
    missing = client.get("/api/nothing/here")
    assert (missing.status_code, detail(missing)["message"]) == (404, "Not Found: GET /api/nothing/here")
    wrong = client.patch("/api/projects")
    assert (wrong.status_code, detail(wrong)["message"]) == (405, "Method Not Allowed: PATCH /api/projects")


def test_openapi_documents_the_routes(client: TestClient) -> None:
    paths = client.get("/openapi.json").json()["paths"]
    assert {
        "/api/projects",
        "/api/projects/{name}",
        "/api/projects/{name}/pous/{pou}",
        "/api/projects/{name}/rename",
        "/api/projects/{name}/check",
        "/api/projects/{name}/pous/{pou}/symbols",
        "/api/library",
    } <= set(paths)
    assert set(paths["/api/projects/{name}"]["put"]["responses"]) == {"200", "404", "409", "413", "422", "428"}
    assert client.get("/docs").status_code == 200
