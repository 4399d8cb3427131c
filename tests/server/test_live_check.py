"""POST /api/check: the diagnostics of an unsaved working copy (the ST editor's live check, issue 9)."""

from __future__ import annotations

from pathlib import Path

from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderlab.server.app import create_app
from ladderlab.server.limits import Limits
from ladderlab.storage import Workspace
from tests.support import api_client

from .helpers import detail, folder_bytes, st_program

COUNTER_DECLS = "VAR_INPUT\n    Enable : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Count : INT;\nEND_VAR"


def counter_fb(body: str) -> dict:
    return {"name": "Counter", "kind": "function_block", "language": "st", "declarations": COUNTER_DECLS, "body": body}


def project(*pous: dict) -> dict:
    return {"name": "draft", "pous": list(pous)}


def test_a_typo_in_an_unsaved_body_is_located_and_nothing_is_stored(client: TestClient, workspace: Workspace) -> None:
    before = folder_bytes(workspace.root) if workspace.root.exists() else {}
    body = "IF Enable THEN\n    Count := Cuont + 1;\nEND_IF;"
    response = client.post("/api/check", json=project(counter_fb(body)))
    assert response.status_code == 200
    assert response.json() == {
        "diagnostics": [
            {
                "severity": "error",
                "code": "ST-UNKNOWN-VAR",
                "message": "unknown variable 'Cuont' - did you mean 'Count'?",
                "file": "Counter/body",
                "json_path": None,
                "pou": "Counter",
                "network": None,
                "element": None,
                "pin": None,
                "place": None,
                "line": 2,
                "column": 14,
                "end_line": 2,
                "end_column": 19,
            }
        ]
    }
    assert (folder_bytes(workspace.root) if workspace.root.exists() else {}) == before


def test_the_fixed_body_is_clean(client: TestClient) -> None:
    fixed = counter_fb("IF Enable THEN\n    Count := Count + 1;\nEND_IF;")
    assert client.post("/api/check", json=project(fixed)).json() == {"diagnostics": []}


def test_declaration_and_syntax_errors_are_located_in_their_text(client: TestClient) -> None:
    pou = st_program("Main", "VAR\n    x : INTT;\nEND_VAR", "x := (1 + ;")
    found = [
        (d["code"], d["message"], d["file"], d["line"], d["column"], d["end_column"])
        for d in client.post("/api/check", json=project(pou)).json()["diagnostics"]
    ]
    assert found == [
        ("ST-PARSE", "expected an expression, found ';'", "Main/body", 1, 11, 12),
        ("ST-UNKNOWN-TYPE", "unknown type 'INTT' - did you mean 'INT'?", "Main/declarations", 2, 9, 13),
    ]


def test_model_problems_are_reported_with_their_json_path(client: TestClient) -> None:
    body = project(st_program("Main", "VAR\nEND_VAR", ""))
    body["tasks"] = [{"name": "T", "interval": "T#10ms", "programs": ["Ghost"]}]
    [diagnostic] = client.post("/api/check", json=body).json()["diagnostics"]
    assert (diagnostic["code"], diagnostic["json_path"]) == ("UNKNOWN-PROGRAM", "$.tasks[0].programs[0]")


def test_bad_bodies_get_a_located_422(client: TestClient) -> None:
    response = client.post(
        "/api/check", content=b'{"name": "draft", "pous": [}', headers={"Content-Type": "application/json"}
    )
    assert response.status_code == 422
    [problem] = detail(response)["diagnostics"]
    assert (problem["code"], problem["line"], problem["column"]) == ("BAD-JSON", 1, 28)

    response = client.post("/api/check", json=project({**counter_fb(""), "kind": "class"}))
    assert response.status_code == 422
    assert [(d["code"], d["json_path"]) for d in detail(response)["diagnostics"]] == [("BAD-REQUEST", "$.pous[0].kind")]
    assert "$.pous[0].kind" in detail(response)["message"]

    response = client.post("/api/check", json={"pous": []})
    assert response.status_code == 422
    assert [(d["json_path"], d["message"]) for d in detail(response)["diagnostics"]] == [
        ("$.name", "missing required field 'name'")
    ]


def test_a_project_over_the_size_limit_is_refused(tmp_path: Path) -> None:
    client = api_client(create_app(Workspace(tmp_path / "ws"), Limits(max_project_bytes=200)))
    response = client.post("/api/check", json=project(counter_fb("Count := 1;\n" * 40)))
    assert response.status_code == 413
    assert "more than the limit" in detail(response)["message"]


_STATEMENTS = st.sampled_from(
    [
        "Count := Count + 1;",
        "Count := Cuont;",
        "IF Enable THEN",
        "END_IF;",
        "Count := ;",
        "Enable := NOT Enable;",
        "x := 1;",
        "(* note *)",
    ]
)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(_STATEMENTS, max_size=6))
def test_the_answer_is_what_the_saved_project_check_says(client: TestClient, statements: list[str]) -> None:
    """Unsaved and saved checks are one function: any body gets the same diagnostics either way."""
    draft = project(counter_fb("\n".join(statements)))
    live = client.post("/api/check", json=draft)
    client.delete("/api/projects/draft")
    assert client.post("/api/projects", json={"name": "draft"}).status_code == 201
    revision = client.get("/api/projects/draft").json()["revision"]
    assert client.put("/api/projects/draft", json=draft, headers={"If-Match": revision}).status_code == 200
    assert live.status_code == 200
    assert live.json() == client.post("/api/projects/draft/check").json()
