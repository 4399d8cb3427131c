"""The CODESYS typing setting (``Project.typing``, issue 25) travels with the project: the project folder's
project.json, PLCopen XML (LadderLab's addData, docs/plcopen.md), the ST export's header and the command line's
``--typing`` (docs/st.md "CODESYS typing"). The rules themselves: tests/engine/test_codesys_typing.py."""

from __future__ import annotations

import json
from pathlib import Path

from ladderlab.cli import main
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.st.project_text import source_to_project
from ladderlab.st.types import typing_rules
from ladderlab.storage import load_project_path
from ladderlab.storage.project_folder import project_files

#: BYTE arithmetic: CODESYS typing only (ST-20 refuses it); 200 + 100 cut to a BYTE is 44.
SOURCE = "PROGRAM Main\nVAR a : BYTE := 200; b : BYTE;\nEND_VAR\nb := a + 100;\nEND_PROGRAM\n"


def _project(typing: str = "codesys"):
    project, diagnostics = source_to_project(SOURCE, "p")
    assert project is not None and diagnostics == []
    return project.model_copy(update={"typing": typing})


def _write(folder: Path, project) -> None:
    for name, text in project_files(project).items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text, encoding="utf-8")


def test_a_project_folder_keeps_its_typing_and_an_iec_one_writes_none(tmp_path: Path) -> None:
    _write(tmp_path / "cs", _project())
    assert json.loads((tmp_path / "cs" / "project.json").read_text())["typing"] == "codesys"
    assert load_project_path(tmp_path / "cs").typing == "codesys"
    _write(tmp_path / "iec", _project("iec"))
    assert "typing" not in json.loads((tmp_path / "iec" / "project.json").read_text())
    assert load_project_path(tmp_path / "iec").typing == "iec"


def test_an_unknown_typing_in_project_json_is_a_located_error(tmp_path: Path, capsys) -> None:
    _write(tmp_path, _project())
    meta = json.loads((tmp_path / "project.json").read_text())
    (tmp_path / "project.json").write_text(json.dumps({**meta, "typing": "twincat"}), encoding="utf-8")
    assert main(["check", str(tmp_path)]) == 2
    assert capsys.readouterr().err.strip() == (
        "project.json, $.typing: error BAD-FILE: expected 'iec' or 'codesys', got 'twincat'"
    )


def test_plcopen_xml_carries_the_typing_and_reports_unknown_rules() -> None:
    document = export_plcopen(_project())
    assert b'typing rules="codesys"' in document
    imported = import_plcopen(document)
    assert imported.project is not None and imported.diagnostics == []
    assert imported.project.typing == "codesys"
    assert b"typing" not in export_plcopen(_project("iec"))
    unknown = import_plcopen(document.replace(b'rules="codesys"', b'rules="s7"'))
    assert unknown.project is not None and unknown.project.typing == "iec"
    assert [d.code for d in unknown.diagnostics] == ["PLCOPEN-UNSUPPORTED"]
    assert "type rules 's7'" in unknown.diagnostics[0].message


def test_the_command_line_checks_and_runs_a_st_file_with_codesys_typing(tmp_path: Path, capsys) -> None:
    path = tmp_path / "main.st"
    path.write_text(SOURCE, encoding="utf-8")
    assert main(["check", str(path)]) != 0  # IEC: a BYTE is no number
    assert "ST-TYPE-MISMATCH" in capsys.readouterr().out
    assert main(["run", str(path), "--typing", "codesys", "--watch", "Main.b"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", "44"]


def test_the_st_export_names_the_typing_and_reads_back_with_it(tmp_path: Path, capsys) -> None:
    export = export_project_st(_project())
    assert [d for d in export.diagnostics if d.severity == "error"] == []
    assert export.text.splitlines()[0] == "(* Checked with CODESYS typing: ladderlab check/run ... --typing codesys *)"
    path = tmp_path / "exported.st"
    path.write_text(export.text, encoding="utf-8")
    assert main(["run", str(path), "--typing", "codesys", "--watch", "Main.b"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", "44"]


def test_the_command_line_parses_a_st_file_by_its_typing(tmp_path: Path, capsys) -> None:
    """ST-40's ';' after END_IF: a .st file is refused when it is missing before a statement, unless ``--typing
    codesys`` says to read it as CODESYS does (a warning, and b is 44 as with the ';')."""
    path = tmp_path / "main.st"
    path.write_text(SOURCE.replace("b := a + 100;", "IF a > 0 THEN b := 1; END_IF\nb := a + 100;"), encoding="utf-8")
    assert main(["check", str(path)]) == 2
    assert capsys.readouterr().err.strip() == "main.st:4:29, POU Main: error ST-PARSE: expected ';' after END_IF"
    assert main(["run", str(path), "--typing", "codesys", "--watch", "Main.b"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", "44"]


def test_the_st_export_keeps_an_end_if_without_semicolon_under_codesys_typing(tmp_path: Path, capsys) -> None:
    """The export writes the body as it is and checks that it reads back by the project's rules: CODESYS's END_IF
    without ';' before a statement (a warning there) stays, and the file runs with ``--typing codesys`` (b is 44)."""
    text = SOURCE.replace("b := a + 100;", "IF a > 0 THEN b := 1; END_IF\nb := a + 100;")
    with typing_rules("codesys"):
        project, _ = source_to_project(text, "p")
    export = export_project_st(project.model_copy(update={"typing": "codesys"}))
    assert [d.format() for d in export.diagnostics if d.severity == "error"] == []
    assert "IF a > 0 THEN b := 1; END_IF\nb := a + 100;" in export.text
    path = tmp_path / "exported.st"
    path.write_text(export.text, encoding="utf-8")
    assert main(["run", str(path), "--typing", "codesys", "--watch", "Main.b"]) == 0
    assert capsys.readouterr().out.splitlines()[-1].split() == ["0", "10", "44"]
