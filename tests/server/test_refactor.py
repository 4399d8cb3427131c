"""POST /api/refactor/*: rename, references and duplicate on an unsaved working copy (issue 22, item 1)."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.storage import Workspace

from .helpers import folder_bytes

BLINK = {
    "name": "Blink",
    "kind": "function_block",
    "language": "st",
    "declarations": "VAR_INPUT\n    IN : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Q : BOOL;\nEND_VAR",
    "body": "Q := NOT IN;",
}
MAIN = {
    "name": "Main",
    "kind": "program",
    "language": "st",
    "declarations": "VAR\n    b : Blink;\n    lamp : BOOL;\nEND_VAR",
    "body": "b(IN := lamp);\nlamp := b.Q;",
}
PROJECT = {"name": "draft", "pous": [BLINK, MAIN], "tasks": [{"name": "Fast", "programs": ["Main"]}]}


def test_a_renamed_project_checks_clean_and_nothing_is_stored(client: TestClient, workspace: Workspace) -> None:
    before = folder_bytes(workspace.root) if workspace.root.exists() else {}
    response = client.post("/api/refactor/rename", json={"project": PROJECT, "old_name": "Blink", "new_name": "Flash"})
    assert response.status_code == 200
    result = response.json()
    assert [p["name"] for p in result["project"]["pous"]] == ["Flash", "Main"]
    assert result["project"]["pous"][1]["declarations"] == "VAR\n    b : Flash;\n    lamp : BOOL;\nEND_VAR"
    assert [(c["pou"], c["part"], c["line"], c["text"]) for c in result["changes"]] == [
        ("Main", "declarations", 2, "b : Blink;")
    ]
    check = client.post("/api/check", json=result["project"])
    assert check.json()["diagnostics"] == []
    assert (folder_bytes(workspace.root) if workspace.root.exists() else {}) == before


def test_renaming_a_program_updates_its_task(client: TestClient) -> None:
    response = client.post("/api/refactor/rename", json={"project": PROJECT, "old_name": "main", "new_name": "Plant"})
    assert response.json()["project"]["tasks"][0]["programs"] == ["Plant"]


def test_a_bad_or_taken_new_name_is_refused_with_the_reason(client: TestClient) -> None:
    bad = client.post("/api/refactor/rename", json={"project": PROJECT, "old_name": "Blink", "new_name": "2x"})
    assert bad.status_code == 422
    assert "2x is no IEC name" in bad.json()["detail"]["message"]
    taken = client.post("/api/refactor/rename", json={"project": PROJECT, "old_name": "Blink", "new_name": "MAIN"})
    assert taken.status_code == 422
    assert "there is already a POU called Main" in taken.json()["detail"]["message"]


def test_references_list_what_a_delete_would_break(client: TestClient) -> None:
    response = client.post("/api/refactor/references", json={"project": PROJECT, "name": "Blink"})
    assert response.status_code == 200
    assert [(r["pou"], r["part"], r["line"]) for r in response.json()["references"]] == [("Main", "declarations", 2)]
    main = client.post("/api/refactor/references", json={"project": PROJECT, "name": "Main"})
    assert [(r["part"], r["task"]) for r in main.json()["references"]] == [("task", "Fast")]


def test_duplicate_adds_a_copy_after_the_original(client: TestClient) -> None:
    response = client.post("/api/refactor/duplicate", json={"project": PROJECT, "name": "Blink", "new_name": "Blink2"})
    assert response.status_code == 200
    pous = response.json()["project"]["pous"]
    assert [p["name"] for p in pous] == ["Blink", "Blink2", "Main"]
    assert pous[1]["body"] == BLINK["body"]
    missing = client.post("/api/refactor/duplicate", json={"project": PROJECT, "name": "Nope", "new_name": "X"})
    assert missing.status_code == 404


def test_a_method_renamed_with_its_calls_or_refused_with_the_reason(client: TestClient) -> None:
    """Issue 25 item 5: POST /api/refactor/rename-member renames a function block's method and its calls."""
    blink = {**BLINK, "methods": [{"name": "Toggle", "declarations": "", "body": "Q := NOT Q;"}]}
    main = {**MAIN, "body": "b(IN := lamp);\nb.Toggle();\nlamp := b.Q;"}
    project = {**PROJECT, "pous": [blink, main]}
    body = {"project": project, "pou": "Blink", "old_name": "Toggle", "new_name": "Flip"}
    response = client.post("/api/refactor/rename-member", json=body)
    assert response.status_code == 200
    answer = response.json()
    assert answer["project"]["pous"][0]["methods"][0]["name"] == "Flip"
    assert answer["project"]["pous"][1]["body"] == "b(IN := lamp);\nb.Flip();\nlamp := b.Q;"
    assert [(c["part"], c["pou"], c["line"], c["text"]) for c in answer["changes"]] == [
        ("method", "Blink", None, "METHOD Toggle"),
        ("body", "Main", 2, "b.Toggle();"),
    ]
    refused = client.post("/api/refactor/rename-member", json={**body, "new_name": "q q"})
    assert refused.status_code == 422
    assert "q q is no IEC name" in refused.json()["detail"]["message"]
