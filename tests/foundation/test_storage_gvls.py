"""Named global variable lists in a project folder: ``gvls/<name>.st`` per list, its qualified_only pragma as the
first line (as CODESYS shows a GVL), project.json's ``gvls`` order; an old folder without them loads unchanged."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from ladderlab.model import GlobalVariableList, Project
from ladderlab.storage import ProjectLoadError, Workspace, load_project_path
from tests.support import EXAMPLES

IO = GlobalVariableList(name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR")
PLAIN = GlobalVariableList(name="GVL", text="VAR_GLOBAL\n    counter : INT;\nEND_VAR")


@pytest.fixture
def ws(tmp_path: Path) -> Workspace:
    return Workspace(tmp_path / "ws")


def test_each_list_is_one_file_with_its_pragma_and_project_json_keeps_their_order(ws: Workspace) -> None:
    project = Project(name="p", gvls=[IO, PLAIN])
    revision = ws.create(project)
    folder = ws.folder("p")
    assert (folder / "gvls" / "GVL_IO.st").read_text() == (
        "{attribute 'qualified_only'}\nVAR_GLOBAL\n    bStart : BOOL;\nEND_VAR\n"
    )
    assert (folder / "gvls" / "GVL.st").read_text() == "VAR_GLOBAL\n    counter : INT;\nEND_VAR\n"
    assert json.loads((folder / "project.json").read_text())["gvls"] == ["GVL_IO", "GVL"]
    stored = ws.load("p")
    assert (stored.project, stored.revision) == (project, revision)


def test_a_removed_or_renamed_list_leaves_no_file_behind(ws: Workspace) -> None:
    revision = ws.create(Project(name="p", gvls=[IO, PLAIN]))
    ws.save(Project(name="p", gvls=[IO.model_copy(update={"name": "GVL_Inputs"})]), revision)
    assert sorted(p.name for p in (ws.folder("p") / "gvls").iterdir()) == ["GVL_Inputs.st"]


def test_a_folder_without_lists_loads_and_saves_as_before(ws: Workspace, tmp_path: Path) -> None:
    motor = load_project_path(EXAMPLES / "motor")
    assert motor.gvls == []
    ws.create(motor)
    assert not (ws.folder("motor") / "gvls").exists()
    assert "gvls" not in json.loads((ws.folder("motor") / "project.json").read_text())


def test_a_list_file_added_by_hand_is_loaded_after_the_listed_ones(tmp_path: Path) -> None:
    folder = tmp_path / "motor"
    shutil.copytree(EXAMPLES / "motor", folder)
    (folder / "gvls").mkdir()
    (folder / "gvls" / "GVL_Extra.st").write_text(
        "{attribute 'qualified_only'}\r\nVAR_GLOBAL\r\n    a : INT;\r\nEND_VAR\r\n"
    )
    project = load_project_path(folder)
    assert [(g.name, g.qualified_only) for g in project.gvls] == [("GVL_Extra", True)]
    assert project.gvls[0].text == "VAR_GLOBAL\r\n    a : INT;\r\nEND_VAR"


def test_the_pragma_typed_into_a_lists_text_is_its_flag() -> None:
    typed = GlobalVariableList(name="G", text="{attribute 'qualified_only'}\nVAR_GLOBAL\nEND_VAR")
    assert (typed.qualified_only, typed.text) == (True, "VAR_GLOBAL\nEND_VAR")


@pytest.mark.parametrize(
    "listed, message",
    [
        (
            ["Missing"],
            "gvls/Missing.st: error BAD-FILE: global variable list 'Missing' is listed in project.json but has no "
            "file gvls/Missing.st",
        ),
        (
            ["../x"],
            "project.json, $.gvls: error BAD-FILE: '../x' is not a global variable list name: use letters, digits "
            "and '_' and start with a letter or '_'",
        ),
        ("GVL", "project.json, $.gvls: error BAD-FILE: expected a list of global variable list names"),
    ],
)
def test_a_bad_list_entry_is_a_located_load_error(tmp_path: Path, listed: object, message: str) -> None:
    folder = tmp_path / "motor"
    shutil.copytree(EXAMPLES / "motor", folder)
    meta = json.loads((folder / "project.json").read_text())
    meta["gvls"] = listed
    (folder / "project.json").write_text(json.dumps(meta))
    with pytest.raises(ProjectLoadError) as refused:
        load_project_path(folder)
    assert [d.format() for d in refused.value.diagnostics] == [message]


def test_two_lists_of_one_name_are_refused_by_the_model() -> None:
    with pytest.raises(ValueError, match="two global variable lists are called 'gvl'"):
        Project(name="p", gvls=[PLAIN, GlobalVariableList(name="gvl")])
