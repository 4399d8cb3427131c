"""The symbols and the instance tree of a project with global variable lists: each global says its list (what
completion after ``GVL_IO.`` needs), ``GVL_IO.tOn`` opens in the Variables view like any global instance."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import GlobalVariableList, Project, Task
from ladderlab.storage import Workspace

from .helpers import detail, st_program

PROJECT = Project(
    name="lists",
    globals="VAR_GLOBAL\n    g : INT;\nEND_VAR",
    gvls=[
        GlobalVariableList(
            name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\n    tOn : TON;\nEND_VAR"
        ),
        GlobalVariableList(name="GVL_Bad", text="VAR_GLOBAL\n    x : NOPE;\nEND_VAR"),
    ],
    pous=[st_program("Main", "", "GVL_IO.tOn(IN := GVL_IO.bStart, PT := T#1s);")],
    tasks=[Task(name="T", programs=["Main"])],
)


def test_each_global_names_its_list_and_the_lists_problems_come_with_the_symbols(
    client: TestClient, workspace: Workspace
) -> None:
    workspace.create(PROJECT)
    body = client.get("/api/projects/lists/pous/Main/symbols").json()
    assert [(s["name"], s["gvl"]) for s in body["globals"]] == [
        ("g", None),
        ("bStart", "GVL_IO"),
        ("tOn", "GVL_IO"),
        ("x", "GVL_Bad"),
    ]
    assert [(d["file"], d["line"], d["code"]) for d in body["diagnostics"]] == [("gvls/GVL_Bad", 2, "ST-UNKNOWN-TYPE")]


def test_a_lists_instance_opens_in_the_instance_tree_by_its_qualified_path(
    client: TestClient, workspace: Workspace
) -> None:
    workspace.create(PROJECT.model_copy(update={"gvls": PROJECT.gvls[:1]}))
    response = client.get("/api/projects/lists/variables", params={"path": "GVL_IO.tOn"})
    assert response.status_code == 200, response.text
    assert [(n["name"], n["path"], n["type"]) for n in response.json()["children"]] == [
        ("IN", "GVL_IO.tOn.IN", "BOOL"),
        ("PT", "GVL_IO.tOn.PT", "TIME"),
        ("Q", "GVL_IO.tOn.Q", "BOOL"),
        ("ET", "GVL_IO.tOn.ET", "TIME"),
    ]
    missing = client.get("/api/projects/lists/variables", params={"path": "GVL_IO.nope"})
    assert (missing.status_code, detail(missing)["message"]) == (
        404,
        "the global variable list GVL_IO has no variable 'nope'",
    )
