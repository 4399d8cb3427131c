"""Export/import over HTTP (issues 6 and 8): ST with its source map, PLCopen download, PLCopen upload."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.server.app import create_app
from ladderlab.server.limits import Limits
from ladderlab.storage import Workspace
from tests.support import api_client


def test_export_st_of_a_pou_maps_lines_to_networks(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor/export/st", params={"pou": "Main"})
    assert response.status_code == 200, response.text
    body = response.json()
    lines = body["text"].splitlines()
    seal_in = next(e for e in body["source_map"] if lines[e["line"] - 1] == "Motor := (Start OR Motor) AND NOT Stop;")
    assert seal_in["network"] == "seal_in"
    assert {e["network"] for e in body["source_map"]} == {"seal_in", "run_timer", "count_starts", "lamp"}


def test_export_st_of_the_whole_project_has_a_configuration(client: TestClient, motor: str) -> None:
    text = client.get("/api/projects/motor/export/st").json()["text"]
    assert "CONFIGURATION" in text and "PROGRAM Scaling" in text and "FUNCTION_BLOCK Blinker" in text


def test_export_st_errors(client: TestClient, motor: str) -> None:
    missing = client.get("/api/projects/motor/export/st", params={"pou": "Nope"})
    assert (missing.status_code, missing.json()["detail"]["message"]) == (404, "project 'motor' has no POU 'Nope'")
    assert client.get("/api/projects/nothing/export/st").status_code == 404


def test_plcopen_download_then_upload_gives_the_same_project(client: TestClient, motor: str) -> None:
    download = client.get("/api/projects/motor/export/plcopen")
    assert download.status_code == 200
    assert download.headers["content-type"].startswith("application/xml")
    assert 'filename="motor.xml"' in download.headers["content-disposition"]
    upload = client.post("/api/import/plcopen", params={"name": "copy"}, content=download.content)
    assert upload.status_code == 201, upload.text
    assert upload.json()["project"]["name"] == "copy" and upload.json()["project"]["pou_count"] == 3
    original = client.get("/api/projects/motor").json()["project"]
    copied = client.get("/api/projects/copy").json()["project"]
    assert copied == {**original, "name": "copy"}
    assert [t["name"] for t in copied["tests"]] == ["motor"]  # carried in LadderLab's addData


def test_plcopen_upload_errors(client: TestClient, motor: str) -> None:
    xml = client.get("/api/projects/motor/export/plcopen").content
    assert client.post("/api/import/plcopen", params={"name": "motor"}, content=xml).status_code == 409
    assert client.post("/api/import/plcopen", params={"name": "../x"}, content=xml).status_code == 422
    bad = client.post("/api/import/plcopen", content=b"<not-closed>")
    assert bad.status_code == 422
    assert bad.json()["detail"]["diagnostics"][0]["file"] == "upload.xml"


def test_plcopen_upload_is_bounded_by_the_body_limit(tmp_path) -> None:
    client = api_client(create_app(Workspace(tmp_path), Limits(max_body_bytes=1000)))
    assert client.post("/api/import/plcopen", content=b"<project>" + b" " * 2000 + b"</project>").status_code == 413
