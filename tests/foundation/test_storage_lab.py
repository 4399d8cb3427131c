"""Lab bench files in a project folder (issue 21): plants as pous/<name>.plant.st (a PROGRAM in IEC text),
panels as hmi/<name>.json (sorted keys, defaults left out, order in project.json), the exercise as
EXERCISE.md; removed ones disappear from the folder; bad files give located errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ladderlab.examples import example_names, example_project
from ladderlab.model import Panel, Pou, Project
from ladderlab.storage import ProjectLoadError, Workspace
from ladderlab.storage.project_folder import read_project_folder

PLANT = Pou(
    name="Tank",
    kind="plant",
    language="st",
    declarations="VAR\n    Level : REAL;\nEND_VAR",
    body="Level := Level + 1.0;",
)
PANEL = Panel.model_validate(
    {
        "name": "Desk",
        "title": "Desk",
        "widgets": [
            {"type": "lamp", "id": "run", "x": 10, "y": 20, "w": 30, "h": 30, "bind": "Main.Run", "blink": True},
            {"type": "label", "id": "t", "x": 0, "y": 0, "w": 100, "h": 20, "text": "Tank"},
        ],
    }
)


def test_plants_panels_and_the_exercise_are_files_that_load_back_the_same(tmp_path: Path):
    ws = Workspace(tmp_path)
    project = Project(
        name="lab", pous=[PLANT], panels=[PANEL, Panel(name="Alpha")], exercise="# Fill it\n\nUp to 80 %."
    )
    revision = ws.create(project)
    folder = tmp_path / "lab"
    assert (folder / "pous/Tank.plant.st").read_text() == (
        "PROGRAM Tank\nVAR\n    Level : REAL;\nEND_VAR\nLevel := Level + 1.0;\nEND_PROGRAM\n"
    )
    assert json.loads((folder / "project.json").read_text())["panels"] == ["Desk", "Alpha"]
    assert (folder / "hmi/Desk.json").read_text() == json.dumps(
        {
            "name": "Desk",
            "title": "Desk",
            "widgets": [
                {"bind": "Main.Run", "blink": True, "h": 30, "id": "run", "type": "lamp", "w": 30, "x": 10, "y": 20},
                {"h": 20, "id": "t", "text": "Tank", "type": "label", "w": 100, "x": 0, "y": 0},
            ],
        },
        indent=2,
        sort_keys=True,
    ) + "\n"
    assert (folder / "EXERCISE.md").read_text() == "# Fill it\n\nUp to 80 %.\n"
    stored = ws.load("lab")
    assert stored.project == project and stored.revision == revision

    ws.save(project.model_copy(update={"panels": [PANEL], "exercise": ""}), revision)
    assert sorted(p.name for p in (folder / "hmi").iterdir()) == ["Desk.json"]
    assert not (folder / "EXERCISE.md").exists()


def test_a_panel_file_added_by_hand_loads_after_the_listed_ones(tmp_path: Path):
    ws = Workspace(tmp_path)
    ws.create(Project(name="lab", panels=[PANEL]))
    (tmp_path / "lab/hmi/Extra.json").write_text(json.dumps({"name": "Extra"}))
    assert [p.name for p in ws.load("lab").project.panels] == ["Desk", "Extra"]


@pytest.mark.parametrize(
    ("file", "text", "expected"),
    [
        (
            "hmi/Desk.json",
            '{"name": "Desk", "widgets": [{"type": "lamp", "id": "x"}]}',
            ("hmi/Desk.json", "$.widgets[0]"),
        ),
        ("hmi/Desk.json", '{"name": "Other"}', ("hmi/Desk.json", "$.name")),
        ("hmi/Desk.json", '{"name": "Desk",', ("hmi/Desk.json", None)),
        ("pous/Tank.plant.st", "FUNCTION_BLOCK Tank\nEND_FUNCTION_BLOCK\n", ("pous/Tank.plant.st", None)),
    ],
)
def test_bad_lab_files_are_located(tmp_path: Path, file: str, text: str, expected: tuple[str, str | None]):
    ws = Workspace(tmp_path)
    ws.create(Project(name="lab", pous=[PLANT], panels=[PANEL]))
    (tmp_path / "lab" / file).write_text(text)
    with pytest.raises(ProjectLoadError) as raised:
        ws.load("lab")
    found = [(d.file, d.json_path) for d in raised.value.diagnostics]
    assert found[0][0] == expected[0] and (expected[1] is None or found[0][1].startswith(expected[1])), found


def test_widget_ids_and_panel_names_are_unique():
    with pytest.raises(ValueError, match="two widgets are called 'a'"):
        Panel.model_validate(
            {"name": "P", "widgets": [{"type": "label", "id": "a", "x": 0, "y": 0, "w": 9, "h": 9, "text": "x"}] * 2}
        )
    with pytest.raises(ValueError, match="two panels are called 'p'"):
        Project(name="x", panels=[Panel(name="P"), Panel(name="p")])


@pytest.mark.parametrize("name", [n for n in example_names() if n != "motor"])
def test_every_exercise_is_a_project_folder_that_stores_as_it_is_shipped(tmp_path: Path, name: str):
    """What storage writes for a shipped example is byte for byte what is shipped (the files are canonical)."""
    from tests.support import EXAMPLES

    project = read_project_folder(EXAMPLES / name)
    Workspace(tmp_path).create(project)
    for path in (EXAMPLES / name).rglob("*"):
        rel = path.relative_to(EXAMPLES / name)
        if path.is_file() and rel.parts[0] not in ("exercise",) and rel.name != "example.json":
            assert (tmp_path / name / rel).read_bytes() == path.read_bytes(), rel
    student = example_project(name, name, "exercise")
    assert [p.name for p in student.pous] == [p.name for p in project.pous]
