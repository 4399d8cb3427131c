"""REST routes for projects: create, read, save (whole and per POU), rename, delete, check."""

from __future__ import annotations

import errno
import threading
from datetime import datetime

import pytest
from fastapi.testclient import TestClient

from ladderlab.examples import example_names
from ladderlab.model import Project
from ladderlab.model.names import project_name_problem
from ladderlab.server.app import create_app
from ladderlab.server.limits import Limits
from ladderlab.storage import Workspace, journal, load_project_path
from ladderlab.storage.project_folder import project_files, revision_of
from tests.support import EXAMPLES, api_client

from .helpers import detail, folder_bytes, st_program


def motor_example(name: str = "motor") -> Project:
    return load_project_path(EXAMPLES / "motor").model_copy(update={"name": name})


# ----------------------------------------------------------------- create


def test_create_empty_project(client: TestClient) -> None:
    response = client.post("/api/projects", json={"name": "demo"})
    assert response.status_code == 201
    body = response.json()
    revision = revision_of(Project(name="demo"))
    assert (body["name"], body["revision"], body["pou_count"]) == ("demo", revision, 0)
    assert response.headers["ETag"] == f'"{revision}"'
    assert response.headers["Location"] == "/api/projects/demo"
    assert datetime.fromisoformat(body["modified"]).tzinfo is not None
    assert client.get("/api/projects/demo").json()["project"] == Project(name="demo").model_dump(mode="json")
    assert [row["name"] for row in client.get("/api/projects").json()] == ["demo"]


def test_create_copies_the_example_under_the_new_name(client: TestClient) -> None:
    response = client.post("/api/projects", json={"name": "my plant", "example": "motor"})
    assert response.status_code == 201
    expected = motor_example("my plant")
    assert (response.json()["pou_count"], response.json()["revision"]) == (3, revision_of(expected))
    stored = client.get("/api/projects/my plant").json()
    assert stored["project"] == expected.model_dump(mode="json")


def test_create_existing_name_is_409(client: TestClient, motor: str) -> None:
    response = client.post("/api/projects", json={"name": "motor"})
    assert response.status_code == 409
    assert detail(response)["message"] == "project 'motor' already exists"
    assert client.get("/api/projects/motor").json()["revision"] == motor


@pytest.mark.parametrize("name", ["../escape", "..", ".hidden", "a/b", "a\\b", "", "x" * 65, "ends.", "ends "])
def test_create_with_bad_name_is_422_and_touches_nothing(client: TestClient, workspace: Workspace, name: str) -> None:
    response = client.post("/api/projects", json={"name": name})
    assert response.status_code == 422
    assert detail(response)["message"] == f"invalid project name {name!r}: {project_name_problem(name)}"
    assert list(workspace.root.iterdir()) == []
    assert list(workspace.root.parent.iterdir()) == [workspace.root]


def test_create_from_unknown_example_is_422(client: TestClient) -> None:
    for example in ("nope", "../motor", "motor/pous"):
        response = client.post("/api/projects", json={"name": "x", "example": example})
        assert response.status_code == 422
        available = ", ".join(example_names())  # motor and the lab bench's exercises
        assert detail(response)["message"] == f"unknown example {example!r}; available: {available}"
    assert client.get("/api/projects").json() == []


def test_create_refused_when_the_workspace_is_full(workspace: Workspace) -> None:
    client = api_client(create_app(workspace, Limits(max_projects=2)))
    assert [client.post("/api/projects", json={"name": n}).status_code for n in "ab"] == [201, 201]
    response = client.post("/api/projects", json={"name": "c"})
    assert response.status_code == 429
    assert detail(response)["message"] == (
        "the workspace already holds 2 projects, the most this server allows; delete one first"
    )
    assert [row["name"] for row in client.get("/api/projects").json()] == ["a", "b"]


def test_create_body_with_unknown_field_is_422(client: TestClient) -> None:
    response = client.post("/api/projects", json={"name": "x", "exmaple": "motor"})
    assert response.status_code == 422
    assert detail(response)["diagnostics"][0]["json_path"] == "$.exmaple"
    assert detail(response)["diagnostics"][0]["message"] == "unknown field 'exmaple'"


# ----------------------------------------------------------------- read


def test_get_project_with_etag(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor")
    assert response.status_code == 200
    assert response.headers["ETag"] == f'"{motor}"'
    body = response.json()
    assert (body["name"], body["revision"]) == ("motor", motor)
    assert body["project"] == motor_example().model_dump(mode="json")
    listed = client.get("/api/projects").json()
    assert listed == [
        {"name": "motor", "revision": motor, "modified": body["modified"], "pou_count": 3, "problems": []}
    ]


def test_get_missing_project_is_404(client: TestClient) -> None:
    response = client.get("/api/projects/nope")
    assert response.status_code == 404
    assert detail(response)["message"] == "project 'nope' does not exist"


def test_project_that_fails_to_load_is_422_with_located_diagnostics(
    client: TestClient, workspace: Workspace, motor: str
) -> None:
    (workspace.root / "motor" / "pous" / "Main.ld.json").write_text('{\n  "name": "Main",\n  "kind": \n}\n')
    for response in (
        client.get("/api/projects/motor"),
        client.post("/api/projects/motor/check"),
        client.get("/api/projects/motor/pous/Main/symbols"),
        client.get("/api/library?project=motor"),
    ):
        assert response.status_code == 422
        assert detail(response)["message"] == "project 'motor' cannot be loaded: 1 problem in its files"
        [diagnostic] = detail(response)["diagnostics"]
        assert (diagnostic["code"], diagnostic["file"], diagnostic["line"], diagnostic["column"]) == (
            "BAD-JSON",
            "pous/Main.ld.json",
            4,
            1,
        )
    # issue 18: the list still shows it, with the same located problem, instead of dropping it
    [listed] = client.get("/api/projects").json()
    assert (listed["name"], listed["revision"], listed["pou_count"]) == ("motor", None, 0)
    [problem] = listed["problems"]
    assert (problem["code"], problem["file"], problem["line"], problem["column"]) == (
        "BAD-JSON",
        "pous/Main.ld.json",
        4,
        1,
    )


# ----------------------------------------------------------------- save the whole project


def test_save_without_if_match_is_428_and_changes_nothing(client: TestClient, workspace: Workspace, motor: str) -> None:
    before = folder_bytes(workspace.root / "motor")
    changed = motor_example().model_copy(update={"globals": "VAR_GLOBAL\n    g : INT;\nEND_VAR"})
    response = client.put("/api/projects/motor", json=changed.model_dump(mode="json"))
    assert response.status_code == 428
    assert "If-Match" in detail(response)["message"]
    assert folder_bytes(workspace.root / "motor") == before


@pytest.mark.parametrize("header", ['"{}"', "{}", 'W/"{}"', ' "{}" '])
def test_save_returns_the_new_revision(client: TestClient, motor: str, header: str) -> None:
    changed = motor_example().model_copy(update={"globals": "VAR_GLOBAL\n    g : INT;\nEND_VAR"})
    response = client.put(
        "/api/projects/motor", json=changed.model_dump(mode="json"), headers={"If-Match": header.format(motor)}
    )
    assert response.status_code == 200, response.text
    revision = revision_of(changed)
    assert response.json()["revision"] == revision != motor
    assert response.headers["ETag"] == f'"{revision}"'
    stored = client.get("/api/projects/motor").json()
    assert (stored["revision"], stored["modified"], stored["project"]) == (
        revision,
        response.json()["modified"],
        changed.model_dump(mode="json"),
    )


def test_save_based_on_an_old_revision_is_409_with_both_revisions(client: TestClient, motor: str) -> None:
    first = motor_example().model_copy(update={"types": "TYPE Color : (Red, Green); END_TYPE"})
    second = motor_example().model_copy(update={"globals": ""})
    ok = client.put("/api/projects/motor", json=first.model_dump(mode="json"), headers={"If-Match": motor})
    assert ok.status_code == 200
    response = client.put("/api/projects/motor", json=second.model_dump(mode="json"), headers={"If-Match": motor})
    assert response.status_code == 409
    current = ok.json()["revision"]
    assert response.json()["detail"] == {
        "message": (
            f"project 'motor' was changed by someone else: this save is based on revision {motor}, "
            f"the saved project is now at revision {current}"
        ),
        "base_revision": motor,
        "current_revision": current,
        "current_modified": ok.json()["modified"],
    }
    assert client.get("/api/projects/motor").json()["project"] == first.model_dump(mode="json")


def test_concurrent_saves_from_one_revision_give_exactly_one_409(client: TestClient, motor: str) -> None:
    """Two tabs save different changes at the same moment from the same revision: one wins, one gets 409."""
    for round_ in range(4):
        base = client.get("/api/projects/motor").json()["revision"]
        bodies = [
            motor_example().model_copy(update={"globals": f"VAR_GLOBAL\n    g{round_}_{i} : INT;\nEND_VAR"})
            for i in range(2)
        ]
        barrier = threading.Barrier(2)
        statuses: list[int] = [0, 0]

        def save(i: int, barrier=barrier, statuses=statuses, bodies=bodies, base=base) -> None:
            barrier.wait()
            statuses[i] = client.put(
                "/api/projects/motor", json=bodies[i].model_dump(mode="json"), headers={"If-Match": base}
            ).status_code

        threads = [threading.Thread(target=save, args=(i,)) for i in range(2)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        assert sorted(statuses) == [200, 409]
        winner = bodies[statuses.index(200)]
        assert client.get("/api/projects/motor").json()["project"] == winner.model_dump(mode="json")


def test_invalid_model_is_422_with_json_path_and_files_stay_intact(
    client: TestClient, workspace: Workspace, motor: str
) -> None:
    before = folder_bytes(workspace.root / "motor")
    data = motor_example().model_dump(mode="json")
    data["pous"][0]["body"]["networks"][1]["elements"][1] = {"type": "relay", "id": "r1"}
    data["tasks"][0]["priority"] = "high"
    response = client.put("/api/projects/motor", json=data, headers={"If-Match": motor})
    assert response.status_code == 422
    found = [(d["code"], d["json_path"]) for d in detail(response)["diagnostics"]]
    assert found == [("BAD-REQUEST", "$.pous[0].body.networks[1].elements[1]"), ("BAD-REQUEST", "$.tasks[0].priority")]
    assert detail(response)["diagnostics"][0]["message"].startswith("unknown type 'relay': expected one of")
    assert folder_bytes(workspace.root / "motor") == before


def test_malformed_json_is_422_with_line_and_column(client: TestClient, motor: str) -> None:
    response = client.put(
        "/api/projects/motor",
        content=b'{\n  "name": "motor",\n  "pous": [,]\n}',
        headers={"If-Match": motor, "Content-Type": "application/json"},
    )
    assert response.status_code == 422
    [diagnostic] = detail(response)["diagnostics"]
    assert (diagnostic["code"], diagnostic["line"], diagnostic["column"]) == ("BAD-JSON", 3, 12)
    assert diagnostic["message"] == "invalid JSON: Expecting value"


def test_save_with_another_name_in_the_body_is_422(client: TestClient, motor: str) -> None:
    response = client.put(
        "/api/projects/motor", json=motor_example("other").model_dump(mode="json"), headers={"If-Match": motor}
    )
    assert response.status_code == 422
    assert [d["json_path"] for d in detail(response)["diagnostics"]] == ["$.name"]
    assert client.get("/api/projects/other").status_code == 404


def test_save_with_two_pous_of_one_name_is_refused(client: TestClient, workspace: Workspace, motor: str) -> None:
    """Names ignore case, and one file per POU: storing both would lose one of them."""
    before = folder_bytes(workspace.root / "motor")
    data = motor_example().model_dump(mode="json")
    data["pous"].append(st_program("MAIN"))
    response = client.put("/api/projects/motor", json=data, headers={"If-Match": motor})
    assert response.status_code == 422
    assert [d["code"] for d in detail(response)["diagnostics"]] == ["DUPLICATE-POU"]
    assert folder_bytes(workspace.root / "motor") == before


def test_save_of_a_project_over_the_size_limit_is_413(workspace: Workspace) -> None:
    client = api_client(create_app(workspace, Limits(max_project_bytes=4000)))
    revision = client.post("/api/projects", json={"name": "big"}).json()["revision"]
    before = folder_bytes(workspace.root / "big")
    project = Project(name="big", pous=[st_program("P", body="x := 1;\n" * 600)])
    response = client.put("/api/projects/big", json=project.model_dump(mode="json"), headers={"If-Match": revision})
    assert response.status_code == 413
    size = sum(len(text.encode()) for text in project_files(project).values())
    assert size > 4800
    assert (
        detail(response)["message"]
        == f"project 'big' would take {size} bytes on disk, more than the limit of 4000 bytes"
    )
    assert folder_bytes(workspace.root / "big") == before


def test_save_of_a_missing_project_is_404(client: TestClient) -> None:
    response = client.put("/api/projects/ghost", json={"name": "ghost"}, headers={"If-Match": "0"})
    assert response.status_code == 404
    assert detail(response)["message"] == "project 'ghost' does not exist"


def test_disk_full_is_507_and_the_old_project_stays_listed_and_loadable(
    client: TestClient, workspace: Workspace, motor: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Issue 18: the disk fills up while the new version is staged (after its first file)."""
    before = folder_bytes(workspace.root / "motor")
    real_write = journal._write_synced
    calls = []

    def fills_up(path, data):
        calls.append(path)
        if len(calls) > 1:
            raise OSError(errno.ENOSPC, "No space left on device")
        real_write(path, data)

    monkeypatch.setattr(journal, "_write_synced", fills_up)
    changed = motor_example().model_copy(update={"globals": "", "types": ""})
    response = client.put("/api/projects/motor", json=changed.model_dump(mode="json"), headers={"If-Match": motor})
    assert response.status_code == 507
    assert detail(response)["message"] == (
        "project 'motor' was not saved: No space left on device. The stored project is unchanged; "
        "free some disk space and save again"
    )
    monkeypatch.undo()
    assert len(calls) == 2
    assert folder_bytes(workspace.root / "motor") == before, "no staged file is left behind"
    assert [(p["name"], p["revision"]) for p in client.get("/api/projects").json()] == [("motor", motor)]
    assert client.get("/api/projects/motor").json()["revision"] == motor


def test_io_error_is_a_json_500_and_loses_nothing(
    client: TestClient, workspace: Workspace, motor: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    before = folder_bytes(workspace.root / "motor")

    def denied(path, data):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(journal, "_write_synced", denied)
    changed = motor_example().model_copy(update={"globals": ""})
    response = client.put("/api/projects/motor", json=changed.model_dump(mode="json"), headers={"If-Match": motor})
    assert response.status_code == 500
    assert detail(response)["message"] == (
        "the workspace could not be read or written: Permission denied. Reload the project to see what is stored."
    )
    assert folder_bytes(workspace.root / "motor") == before
    assert client.get("/api/projects/motor").json()["revision"] == motor


def test_unexpected_error_is_a_json_500(workspace: Workspace, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(app, project):
        raise RuntimeError("checker exploded")

    monkeypatch.setattr("ladderlab.server.projects.check_report", broken)
    client = api_client(create_app(workspace), raise_server_exceptions=False)
    client.post("/api/projects", json={"name": "p"})
    response = client.post("/api/projects/p/check")
    assert response.status_code == 500
    assert detail(response)["message"] == "internal server error: RuntimeError: checker exploded"


# ----------------------------------------------------------------- save and delete one POU


def test_save_pou_replaces_it_in_place(client: TestClient, motor: str) -> None:
    blinker = motor_example().pou("Blinker").model_copy(update={"body": "Out := Enable;"})
    response = client.put(
        "/api/projects/motor/pous/Blinker", json=blinker.model_dump(mode="json"), headers={"If-Match": motor}
    )
    assert response.status_code == 200, response.text
    expected = motor_example()
    expected.pous[1] = blinker
    assert response.json()["revision"] == revision_of(expected)
    assert response.headers["ETag"] == f'"{revision_of(expected)}"'
    assert client.get("/api/projects/motor").json()["project"] == expected.model_dump(mode="json")


def test_save_new_pou_appends_it(client: TestClient, motor: str) -> None:
    new = st_program("Extra", "VAR\n    n : INT;\nEND_VAR", "n := n + 1;")
    response = client.put("/api/projects/motor/pous/Extra", json=new, headers={"If-Match": motor})
    assert response.status_code == 200
    pous = client.get("/api/projects/motor").json()["project"]["pous"]
    assert [p["name"] for p in pous] == ["Main", "Blinker", "Scaling", "Extra"]
    oo_defaults = {
        "methods": [],
        "properties": [],
        "actions": [],
        "extends": None,
        "implements": [],
        "abstract": False,
        "final": False,
    }
    assert pous[3] == {**new, "return_type": None, **oo_defaults}


def test_save_pou_error_paths(client: TestClient, workspace: Workspace, motor: str) -> None:
    before = folder_bytes(workspace.root / "motor")
    new = st_program("Extra")
    missing = client.put("/api/projects/motor/pous/Extra", json=new)
    assert missing.status_code == 428
    mismatch = client.put("/api/projects/motor/pous/Other", json=new, headers={"If-Match": motor})
    assert (mismatch.status_code, detail(mismatch)["diagnostics"][0]["json_path"]) == (422, "$.name")
    stale = client.put("/api/projects/motor/pous/Extra", json=new, headers={"If-Match": "0123456789abcdef"})
    assert (stale.status_code, stale.json()["detail"]["current_revision"]) == (409, motor)
    bad = client.put("/api/projects/motor/pous/Bad__name", json=st_program("Bad__name"), headers={"If-Match": motor})
    assert bad.status_code == 422
    assert detail(bad)["diagnostics"][0]["code"] == "BAD-NAME"
    invalid = client.put(
        "/api/projects/motor/pous/Extra", json={**new, "language": "cobol"}, headers={"If-Match": motor}
    )
    assert (invalid.status_code, detail(invalid)["diagnostics"][0]["json_path"]) == (422, "$.language")
    assert client.put("/api/projects/ghost/pous/Extra", json=new, headers={"If-Match": motor}).status_code == 404
    assert folder_bytes(workspace.root / "motor") == before


def test_delete_pou(client: TestClient, workspace: Workspace, motor: str) -> None:
    assert client.delete("/api/projects/motor/pous/Scaling").status_code == 428
    stale = client.delete("/api/projects/motor/pous/Scaling", headers={"If-Match": "0123456789abcdef"})
    assert stale.status_code == 409
    response = client.delete("/api/projects/motor/pous/scaling", headers={"If-Match": motor})
    assert response.status_code == 200
    expected = motor_example()
    expected.pous = expected.pous[:2]
    assert response.json()["revision"] == revision_of(expected)
    assert client.get("/api/projects/motor").json()["project"] == expected.model_dump(mode="json")
    assert sorted(p.name for p in (workspace.root / "motor" / "pous").iterdir()) == ["Blinker.st", "Main.ld.json"]
    gone = client.delete("/api/projects/motor/pous/Scaling", headers={"If-Match": response.json()["revision"]})
    assert (gone.status_code, detail(gone)["message"]) == (404, "POU 'Scaling' does not exist")


# ----------------------------------------------------------------- rename and delete


def test_rename_project(client: TestClient, workspace: Workspace, motor: str) -> None:
    response = client.post("/api/projects/motor/rename", json={"new_name": "plant 2"})
    assert response.status_code == 200
    expected = motor_example("plant 2")
    body = response.json()
    assert (body["name"], body["revision"], body["pou_count"]) == ("plant 2", revision_of(expected), 3)
    assert client.get("/api/projects/motor").status_code == 404
    assert client.get("/api/projects/plant 2").json()["project"] == expected.model_dump(mode="json")
    assert sorted(p.name for p in workspace.root.iterdir() if not p.name.startswith(".")) == ["plant 2"]


def test_rename_error_paths(client: TestClient, motor: str) -> None:
    client.post("/api/projects", json={"name": "other"})
    taken = client.post("/api/projects/motor/rename", json={"new_name": "other"})
    assert (taken.status_code, detail(taken)["message"]) == (409, "project 'other' already exists")
    bad = client.post("/api/projects/motor/rename", json={"new_name": "../up"})
    assert (bad.status_code, detail(bad)["diagnostics"][0]["code"]) == (422, "BAD-NAME")
    stale = client.post("/api/projects/motor/rename", json={"new_name": "new"}, headers={"If-Match": "0" * 16})
    assert (stale.status_code, stale.json()["detail"]["current_revision"]) == (409, motor)
    missing = client.post("/api/projects/ghost/rename", json={"new_name": "new"})
    assert missing.status_code == 404
    assert sorted(r["name"] for r in client.get("/api/projects").json()) == ["motor", "other"]


def test_delete_project(client: TestClient, motor: str) -> None:
    stale = client.delete("/api/projects/motor", headers={"If-Match": "0" * 16})
    assert stale.status_code == 409
    assert client.get("/api/projects/motor").status_code == 200
    response = client.delete("/api/projects/motor", headers={"If-Match": motor})
    assert (response.status_code, response.content) == (204, b"")
    assert client.get("/api/projects").json() == []
    assert client.delete("/api/projects/motor").status_code == 404


# ----------------------------------------------------------------- check


def test_check_reports_a_located_st_error(client: TestClient, motor: str) -> None:
    program = st_program("Prog", "VAR\n    Start : BOOL;\n    x : BOOL;\nEND_VAR", "x := Start;\nx := Strat;")
    client.put("/api/projects/motor/pous/Prog", json=program, headers={"If-Match": motor})
    response = client.post("/api/projects/motor/check")
    assert response.status_code == 200
    assert response.json()["diagnostics"] == [
        {
            "severity": "error",
            "code": "ST-UNKNOWN-VAR",
            "message": "unknown variable 'Strat' - did you mean 'Start'?",
            "file": "Prog/body",
            "json_path": None,
            "pou": "Prog",
            "network": None,
            "element": None,
            "pin": None,
            "place": None,
            "line": 2,
            "column": 6,
            "end_line": 2,
            "end_column": 11,
        }
    ]


def test_check_includes_model_validation(client: TestClient, motor: str) -> None:
    project = motor_example()
    project.tasks[0].programs.append("Blinker")
    saved = client.put("/api/projects/motor", json=project.model_dump(mode="json"), headers={"If-Match": motor})
    assert saved.status_code == 200
    [diagnostic] = client.post("/api/projects/motor/check").json()["diagnostics"]
    assert (diagnostic["code"], diagnostic["json_path"], diagnostic["pou"]) == (
        "NOT-A-PROGRAM",
        "$.tasks[0].programs[2]",
        "Blinker",
    )


def test_check_of_the_example_is_clean(client: TestClient, motor: str) -> None:
    assert client.post("/api/projects/motor/check").json() == {"diagnostics": []}
    assert client.post("/api/projects/ghost/check").status_code == 404
