"""Security and limits: body size, names that try to leave the workspace, JSON for every error."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from ladderlab.model import Pou
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


# ----------------------------------------------------------------- issue 18: nothing that saves can fail to load


def nested_parallels(depth: int) -> dict:
    """One network: ``depth`` parallels each holding the previous one (p0 the innermost) and a contact."""
    inner = [{"type": "contact", "id": "k", "var": "a"}]
    for level in range(depth):
        inner = [
            {
                "type": "parallel",
                "id": f"p{level}",
                "branches": [inner, [{"type": "contact", "id": f"q{level}", "var": "b"}]],
            }
        ]
    return {"networks": [{"id": "n1", "elements": [*inner, {"type": "coil", "id": "c", "var": "x"}]}]}


def ld_main(depth: int) -> dict:
    return {
        "name": "Main",
        "kind": "program",
        "language": "ld",
        "declarations": "VAR a, b, x : BOOL; END_VAR",
        "body": nested_parallels(depth),
    }


def test_ld_branches_at_the_limit_save_load_check_and_run(client: TestClient, workspace: Workspace) -> None:
    """LD parallels nested 84 deep saved with 200 and then the project could not be read (500)."""
    client.post("/api/projects", json={"name": "deep"})
    revision = client.get("/api/projects/deep").json()["revision"]
    saved = client.put("/api/projects/deep/pous/Main", json=ld_main(50), headers={"If-Match": revision})
    assert saved.status_code == 200
    loaded = client.get("/api/projects/deep")
    assert loaded.status_code == 200
    assert loaded.json()["project"]["pous"][0] == Pou.model_validate(ld_main(50)).model_dump(mode="json", by_alias=True)
    assert client.post("/api/projects/deep/check").json() == {"diagnostics": []}
    sim = client.post("/api/projects/deep/simulations")
    assert sim.status_code == 201
    assert client.post(f"/api/simulations/{sim.json()['id']}/cycle").json()["scan_count"] == 1


@pytest.mark.parametrize("depth", [51, 84])
def test_ld_branches_beyond_the_limit_are_refused_at_save_with_the_element(
    client: TestClient, workspace: Workspace, depth: int
) -> None:
    client.post("/api/projects", json={"name": "deep"})
    revision = client.get("/api/projects/deep").json()["revision"]
    before = folder_bytes(workspace.root / "deep")
    refused = client.put("/api/projects/deep/pous/Main", json=ld_main(depth), headers={"If-Match": revision})
    assert refused.status_code == 422
    [problem] = detail(refused)["diagnostics"]
    crossing = depth - 51  # the parallel at level 51, counted from the outside
    assert problem["json_path"] == "$.body.networks[0]"
    assert problem["message"] == (
        f"element 'p{crossing}' nests deeper than the limit of 50 levels for the nesting of LD branches "
        "(the setting LADDERLAB_MAX_DIAGRAM_DEPTH raises it)"
    )
    assert folder_bytes(workspace.root / "deep") == before


def test_a_project_file_with_branches_too_deep_is_listed_with_the_problem(
    client: TestClient, workspace: Workspace
) -> None:
    """Written by hand or by an older version: the project is listed and its load error located, never a 500."""
    client.post("/api/projects", json={"name": "deep"})
    folder = workspace.root / "deep"
    (folder / "pous").mkdir(exist_ok=True)
    (folder / "pous" / "Main.ld.json").write_text(json.dumps(ld_main(84)))
    response = client.get("/api/projects/deep")
    assert response.status_code == 422
    [problem] = detail(response)["diagnostics"]
    assert (problem["file"], problem["json_path"]) == ("pous/Main.ld.json", "$.body.networks[0]")
    [listed] = client.get("/api/projects").json()
    assert listed["revision"] is None and listed["problems"][0]["file"] == "pous/Main.ld.json"
