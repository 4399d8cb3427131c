"""Workspace storage: folder round trip, byte-stable saves, atomicity, conflicts, names, bad files."""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

import pytest
from hypothesis import example, given

from ladderlab.examples import seed_workspace
from ladderlab.model import Pou, Project
from ladderlab.storage import (
    AlreadyExistsError,
    ConflictError,
    InvalidNameError,
    ProjectLoadError,
    Workspace,
    atomic,
    load_project_path,
)
from ladderlab.storage import workspace as workspace_module
from tests.support import EXAMPLES

from .strategies import projects


def snapshot(folder: Path) -> dict[str, tuple[bytes, int]]:
    return {
        str(p.relative_to(folder)): (p.read_bytes(), p.stat().st_mtime_ns)
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


@pytest.fixture
def ws(tmp_path: Path) -> Workspace:
    return Workspace(tmp_path / "ws")


@pytest.fixture
def motor() -> Project:
    return load_project_path(EXAMPLES / "motor")


@given(projects())
@example(Project(name="cr", pous=[Pou(name="A", kind="program", language="st", body="\r0")]))
def test_folder_round_trip_and_byte_stable_resave(project: Project) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        ws = Workspace(tmp)
        revision = ws.create(project)
        stored = ws.load(project.name)
        assert stored.project == project
        assert stored.revision == revision
        before = snapshot(ws.folder(project.name))
        assert ws.save(stored.project, revision) == revision
        assert snapshot(ws.folder(project.name)) == before


def test_example_round_trips_to_identical_files(ws: Workspace, motor: Project) -> None:
    ws.create(motor)
    copy = {p.relative_to(EXAMPLES / "motor"): p.read_bytes() for p in (EXAMPLES / "motor").rglob("*") if p.is_file()}
    saved = {p.relative_to(ws.folder("motor")): p.read_bytes() for p in ws.folder("motor").rglob("*") if p.is_file()}
    hidden = {path for path in copy if path.parts[:2] == ("tests", "hidden")}  # a teacher's: not in the model
    assert hidden == {Path("tests/hidden/grading.st")}
    assert saved == {path: data for path, data in copy.items() if path not in hidden}


def test_st_pou_is_stored_as_iec_text(ws: Workspace, motor: Project) -> None:
    ws.create(motor)
    text = (ws.folder("motor") / "pous" / "Blinker.st").read_text()
    assert text.startswith("FUNCTION_BLOCK Blinker\nVAR_INPUT\n")
    assert text.endswith("END_IF;\nEND_FUNCTION_BLOCK\n")


def test_unsplittable_st_text_is_kept_as_json(ws: Workspace) -> None:
    """A VAR block still being typed (no END_VAR) cannot be stored as IEC text; it is kept exactly."""
    pou = Pou(name="Draft", kind="program", language="st", declarations="VAR\n  x : INT;", body="x := 1;")
    ws.create(Project(name="p", pous=[pou]))
    assert (ws.folder("p") / "pous" / "Draft.st.json").is_file()
    assert ws.load("p").project.pous == [pou]
    fixed = pou.model_copy(update={"declarations": "VAR\n  x : INT;\nEND_VAR"})
    ws.save(Project(name="p", pous=[fixed]), ws.load("p").revision)
    assert sorted(p.name for p in (ws.folder("p") / "pous").iterdir()) == ["Draft.st"]


def test_a_program_with_methods_is_stored_as_json_and_comes_back_running(ws: Workspace) -> None:
    """Issue 25 item 5: a PROGRAM with a METHOD and a PROPERTY (CODESYS) is ``pous/<name>.st.json`` (its IEC file
    would not carry them) and loads back equal; the loaded project runs: Main: Add(2) then THIS^.Add(3) and the
    property's SET ``Half := 1`` (count := 1 * 2) each scan, so count is 0 + 2 + 3 -> 2 after scan 1 (the SET runs
    last), 2 + 5 -> 2 again; ``got`` reads the GET: 2 / 2 = 1."""
    from ladderlab.model.project import Accessor, Method, Property
    from ladderlab.simulation.build import build_project

    main = Pou(
        name="Main",
        kind="program",
        language="st",
        declarations="VAR count : INT; got : INT; END_VAR",
        body="Add(2);\nTHIS^.Add(n := 3);\nHalf := 1;\ngot := Half;",
        methods=[
            Method(name="Add", access="PRIVATE", declarations="VAR_INPUT n : INT; END_VAR", body="count := count + n;")
        ],
        properties=[
            Property(
                name="Half",
                type="INT",
                get=Accessor(body="Half := count / 2;"),
                set=Accessor(body="count := Half * 2;"),
            )
        ],
    )
    project = Project(name="p", pous=[main])
    ws.create(project)
    assert sorted(p.name for p in (ws.folder("p") / "pous").iterdir()) == ["Main.st.json"]
    loaded = ws.load("p").project
    assert loaded == project
    sim = build_project(loaded).simulation()
    for _ in range(2):
        sim.cycle(1)
        assert (sim.read("Main.count"), sim.read("Main.got")) == (2, 1)


def test_cfc_chart_is_stored_as_cfc_json_and_comes_back_a_chart(ws: Workspace) -> None:
    """Issue 26: a CFC POU is pous/<name>.cfc.json, its one chart with its execution order (CFC-01, CFC-02)."""
    from ladderlab.model.cfc import CfcBody

    chart = {"id": "chart", "nodes": [{"type": "return", "id": "r"}], "order": ["r"]}
    pou = Pou(name="Chart", kind="program", language="cfc", body={"networks": [chart]})
    ws.create(Project(name="p", pous=[pou]))
    assert sorted(p.name for p in (ws.folder("p") / "pous").iterdir()) == ["Chart.cfc.json"]
    loaded = ws.load("p").project.pous
    assert loaded == [pou] and isinstance(loaded[0].body, CfcBody)


def test_removed_pou_file_is_deleted(ws: Workspace, motor: Project) -> None:
    revision = ws.create(motor)
    ws.save(motor.model_copy(update={"pous": motor.pous[:1]}), revision)
    assert sorted(p.name for p in (ws.folder("motor") / "pous").iterdir()) == ["Main.ld.json"]


def test_failure_mid_write_leaves_old_file_intact(ws: Workspace, motor: Project, monkeypatch) -> None:
    revision = ws.create(motor)
    before = snapshot(ws.folder("motor"))
    changed = motor.model_copy(update={"globals": "VAR_GLOBAL\n    Other : BOOL;\nEND_VAR"})

    def crash(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr(atomic.os, "replace", crash)
    with pytest.raises(OSError, match="disk full"):
        ws.save(changed, revision)
    monkeypatch.undo()
    assert snapshot(ws.folder("motor")) == before, "old files intact, no temporary files left behind"
    assert ws.load("motor").project == motor


def test_partial_write_is_never_visible(tmp_path: Path, monkeypatch) -> None:
    target = tmp_path / "f.json"
    target.write_bytes(b"old")
    real_fsync = os.fsync

    def crash_after_partial_write(fd):
        raise OSError("power cut")

    monkeypatch.setattr(atomic.os, "fsync", crash_after_partial_write)
    with pytest.raises(OSError):
        atomic.write_atomic(target, b"new content")
    monkeypatch.setattr(atomic.os, "fsync", real_fsync)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["f.json"]


def test_save_on_old_revision_is_a_conflict_naming_both(ws: Workspace, motor: Project) -> None:
    base = ws.create(motor)
    tab1 = motor.model_copy(update={"globals": "VAR_GLOBAL\n    A : BOOL;\nEND_VAR"})
    tab2 = motor.model_copy(update={"globals": "VAR_GLOBAL\n    B : BOOL;\nEND_VAR"})
    new = ws.save(tab1, base)
    with pytest.raises(ConflictError) as err:
        ws.save(tab2, base)
    assert (err.value.base_revision, err.value.current_revision) == (base, new)
    assert base in str(err.value) and new in str(err.value)
    assert ws.load("motor").project == tab1


def test_create_refuses_existing(ws: Workspace, motor: Project) -> None:
    ws.create(motor)
    with pytest.raises(AlreadyExistsError):
        ws.create(motor)


def test_rename_and_delete(ws: Workspace, motor: Project) -> None:
    revision = ws.create(motor)
    new_revision = ws.rename("motor", "conveyor", revision)
    assert [i.name for i in ws.list()] == ["conveyor"]
    stored = ws.load("conveyor")
    assert stored.project.name == "conveyor" and stored.revision == new_revision
    ws.delete("conveyor", new_revision)
    assert ws.list() == []


def test_the_list_reads_again_only_a_project_changed_on_disk(ws: Workspace, motor: Project, monkeypatch) -> None:
    """``GET /api/projects`` lists every project: a folder unchanged since the last list is not parsed and hashed
    again, and a change on disk is still seen, whoever made it: a save by another workspace (another server
    process) or an edit by hand that keeps the file's size."""
    revision = ws.create(motor)
    loads: list[str] = []
    read = workspace_module.read_project_folder
    monkeypatch.setattr(
        workspace_module, "read_project_folder", lambda folder: loads.append(folder.name) or read(folder)
    )
    [first] = ws.list()
    assert (first.revision, first.pou_count, loads) == (revision, 3, ["motor"])
    assert ws.list() == [first] and loads == ["motor"]

    saved = Workspace(ws.root).save(motor.model_copy(update={"pous": motor.pous[:2]}), revision)
    [listed] = ws.list()
    assert (listed.revision, listed.pou_count, len(loads)) == (saved, 2, 3)  # (the save read its base revision)

    blinker = ws.root / "motor" / "pous" / "Blinker.st"
    text = blinker.read_text()
    blinker.write_text(text.replace("(* full on/off cycle *)", "(* full on/off cycles*)"))
    moved = blinker.stat().st_mtime_ns + 1_000_000_000  # (as an edit a second later: see Workspace._fingerprint)
    os.utime(blinker, ns=(moved, moved))
    [edited] = ws.list()
    assert edited.revision == ws.load("motor").revision not in (revision, saved)
    assert ws.list() == [edited] and len(loads) == 5  # the list's read and the load above

    shutil.rmtree(ws.root / "motor")
    assert ws.list() == []


@pytest.mark.parametrize(
    "name", ["../evil", "..", ".", "/etc", "a/b", "a\\b", ".hidden", "", "x" * 65, "trailing.", "motor\n", "a\nb"]
)
def test_project_names_cannot_escape_the_workspace(ws: Workspace, name: str) -> None:
    with pytest.raises(InvalidNameError):
        ws.create(Project(name=name))
    with pytest.raises(InvalidNameError):
        ws.load(name)
    assert list(ws.root.parent.iterdir()) == [ws.root]


@pytest.mark.parametrize("name", ["../../x", "a/b", "1abc", "a__b", "", "x y", "Main\n", "Main\r\n"])
def test_pou_names_are_iec_identifiers(ws: Workspace, name: str) -> None:
    with pytest.raises(InvalidNameError):
        ws.create(Project(name="p", pous=[Pou(name=name, kind="program", language="st", body="")]))
    assert not (ws.root / "x").exists()


# --- malformed folders: each names the file, the JSON path and what was expected ---------------


def broken_copy(tmp_path: Path) -> Path:
    folder = tmp_path / "motor"
    shutil.copytree(EXAMPLES / "motor", folder)
    return folder


def load_error(folder: Path) -> str:
    with pytest.raises(ProjectLoadError) as err:
        load_project_path(folder)
    return "\n".join(d.format() for d in err.value.diagnostics)


def edit_json(path: Path, change) -> None:
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))


def test_bad_json_names_file_line_and_column(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    (folder / "pous" / "Main.ld.json").write_text('{\n  "name": "Main",\n  "kind": }')
    assert load_error(folder) == ("pous/Main.ld.json:3:11: error BAD-JSON: invalid JSON: Expecting value")


def test_unknown_element_type_names_json_path(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    edit_json(
        folder / "pous" / "Main.ld.json", lambda d: d["body"]["networks"][1]["elements"][0].update(type="contcat")
    )
    message = load_error(folder)
    assert message.startswith(
        "pous/Main.ld.json, $.body.networks[1].elements[0]: error BAD-FILE: "
        "unknown type 'contcat': expected one of 'contact', 'compare'"
    )


def test_missing_field_names_json_path(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    edit_json(
        folder / "pous" / "Main.ld.json", lambda d: d["body"]["networks"][0]["elements"][0]["branches"][1][0].pop("var")
    )
    assert load_error(folder) == (
        "pous/Main.ld.json, $.body.networks[0].elements[0].branches[1][0].var: "
        "error BAD-FILE: missing required field 'var'"
    )


def test_wrong_field_type_in_fbd(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    edit_json(folder / "pous" / "Scaling.fbd.json", lambda d: d["body"]["networks"][0]["wires"][2]["to"].pop("pin"))
    assert load_error(folder) == (
        "pous/Scaling.fbd.json, $.body.networks[0].wires[2].to.pin: error BAD-FILE: missing required field 'pin'"
    )


def test_bad_task_in_project_json(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    edit_json(folder / "project.json", lambda d: d["tasks"][0].update(priority="high"))
    assert load_error(folder).startswith(
        "project.json, $.tasks[0].priority: error BAD-FILE: Input should be a valid integer"
    )


def test_missing_pou_file(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    (folder / "pous" / "Blinker.st").unlink()
    assert "POU 'Blinker' is listed in project.json but has no file" in load_error(folder)


def test_st_pou_without_end(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    path = folder / "pous" / "Blinker.st"
    path.write_text(path.read_text().replace("END_FUNCTION_BLOCK", ""))
    assert load_error(folder) == (
        "pous/Blinker.st:1:1, POU Blinker: error BAD-FILE: FUNCTION_BLOCK without END_FUNCTION_BLOCK"
    )


def test_pou_file_declaring_another_name(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    path = folder / "pous" / "Blinker.st"
    path.write_text(path.read_text().replace("FUNCTION_BLOCK Blinker", "FUNCTION_BLOCK Flasher"))
    assert "the file is named for POU 'Blinker' but declares 'Flasher'" in load_error(folder)


def test_language_must_match_file_suffix(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    edit_json(folder / "pous" / "Main.ld.json", lambda d: d.update(language="fbd"))
    assert "pous/Main.ld.json" in load_error(folder)


def test_hand_added_pou_file_is_loaded(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    (folder / "pous" / "Extra.st").write_text("PROGRAM Extra\nx := 1;\nEND_PROGRAM\n")
    project = load_project_path(folder)
    assert [p.name for p in project.pous] == ["Main", "Blinker", "Scaling", "Extra"]


def test_nothing_is_overwritten_by_a_failed_load(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    (folder / "project.json").write_text("{")
    before = snapshot(folder)
    load_error(folder)
    assert snapshot(folder) == before


# --- symbolic links (issue 18: followed outside the workspace) ---------------------------------


@pytest.mark.skipif(os.name == "nt", reason="symlinks need privileges on Windows")
def test_a_link_out_of_the_project_folder_is_refused_with_its_file(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    ws.create(load_project_path(EXAMPLES / "motor"))
    secret = tmp_path / "secret.st"
    secret.write_text("PROGRAM Blinker\nVAR\n  password : STRING := 'hunter2';\nEND_VAR\nEND_PROGRAM\n")
    link = ws.root / "motor" / "pous" / "Blinker.st"
    link.unlink()
    link.symlink_to(secret)
    with pytest.raises(ProjectLoadError) as err:
        ws.load("motor")
    [problem] = err.value.diagnostics
    assert (problem.file, problem.pou) == ("pous/Blinker.st", "Blinker")
    assert problem.message == "is a symbolic link that leads out of the project folder; LadderLab does not follow it"
    [listed] = ws.list()
    assert (listed.name, listed.revision, listed.problems) == ("motor", None, [problem])
    assert "hunter2" not in str(err.value)


@pytest.mark.skipif(os.name == "nt", reason="symlinks need privileges on Windows")
def test_a_linked_pous_folder_or_project_file_is_refused(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    ws.create(load_project_path(EXAMPLES / "motor"))
    outside = tmp_path / "elsewhere"
    shutil.move(ws.root / "motor" / "pous", outside)
    (ws.root / "motor" / "pous").symlink_to(outside)
    assert "pous: error BAD-FILE: is a symbolic link that leads out" in load_error(ws.root / "motor")
    with pytest.raises(ProjectLoadError):
        ws.save(load_project_path(EXAMPLES / "motor"), "0")
    assert sorted(p.name for p in outside.iterdir()) == ["Blinker.st", "Main.ld.json", "Scaling.fbd.json"]


@pytest.mark.skipif(os.name == "nt", reason="symlinks need privileges on Windows")
def test_a_link_inside_the_project_folder_is_followed(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path)
    (folder / "shared.st").write_text((folder / "pous" / "Blinker.st").read_text())
    (folder / "pous" / "Blinker.st").unlink()
    (folder / "pous" / "Blinker.st").symlink_to(folder / "shared.st")
    assert load_project_path(folder) == load_project_path(EXAMPLES / "motor")


def test_a_save_returns_the_revision_the_saved_folder_loads_with(ws: Workspace, motor: Project) -> None:
    """Test files have no order of their own (a folder lists them by name): a browser that added 'faults' after
    'motor' saves, and its next save, based on the revision the first returned, is no conflict."""
    from ladderlab.model import TestFile

    base = ws.create(motor)
    added = motor.model_copy(update={"tests": [*motor.tests, TestFile(name="faults", text="TEST 'x'\nEND_TEST\n")]})
    assert [t.name for t in added.tests][-1] == "faults" and len(added.tests) > 1
    saved = ws.save(added, base)
    assert ws.load("motor").revision == saved
    without = added.model_copy(update={"tests": added.tests[:-1]})
    assert ws.save(without, saved) == ws.load("motor").revision


def test_names_lists_project_folders_without_loading_them(ws: Workspace, motor: Project, monkeypatch) -> None:
    """``ladderlab serve`` asks whether the workspace is empty before it adds the example (examples.seed_workspace):
    loading every project for that made each start of a full workspace slower (issue 27, startup)."""
    ws.create(motor.model_copy(update={"name": "b"}))
    ws.create(motor.model_copy(update={"name": "a"}))
    (ws.root / "broken").mkdir()
    (ws.root / "broken" / "project.json").write_text("{", encoding="utf-8")
    (ws.root / "no_project").mkdir()
    (ws.root / ".trash").mkdir()

    def no_load(name: str) -> None:
        raise AssertionError(f"{name} was loaded")

    monkeypatch.setattr(ws, "load", no_load)
    assert ws.names() == ["a", "b", "broken"]
    assert seed_workspace(ws) is None
