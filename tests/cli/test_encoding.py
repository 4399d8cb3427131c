"""Files that are not UTF-8 (issue 16): a located error, never a traceback, and ``--encoding`` to read them.

CoDeSys 2.3 exports from Russian courses are usually Windows-1251: ``'Пуск'`` in cp1251 is bytes E0-FF that are
not UTF-8. Every command that reads files takes ``--encoding``; without it such a file is refused at its first bad
byte with file, line, column and what to do, and the command exits 2.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ladderlab.cli import main
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace
from ladderlab.storage.project_folder import project_files

SOURCE = "PROGRAM Main\nVAR label : STRING := 'Пуск насоса'; n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n"
BAD_AT = SOURCE.encode("cp1251").index("Пуск".encode("cp1251"))  # the first Cyrillic byte
HINT = "re-save as UTF-8 or pass --encoding cp1251"


def call(capsys, *args: str) -> tuple[int, str, str]:
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def st_file(tmp_path: Path) -> Path:
    path = tmp_path / "kurs.st"
    path.write_bytes(SOURCE.encode("cp1251"))
    return path


@pytest.mark.parametrize("command", [["check"], ["run"], ["compile"], ["export", "st"], ["export", "plcopen"]])
def test_a_cp1251_st_file_is_a_located_error_with_exit_2(capsys, st_file, command):
    code, out, err = call(capsys, *command, str(st_file))
    assert code == 2 and out == ""
    assert err == f"kurs.st:2:24: error BAD-ENCODING: not UTF-8 at byte {BAD_AT} (0xCF); {HINT}\n"
    assert "Traceback" not in err


def test_encoding_cp1251_reads_it(capsys, st_file):
    code, out, err = call(
        capsys, "run", str(st_file), "--encoding", "cp1251", "--watch", "Main.label", "--format", "jsonl"
    )
    assert code == 0, err
    assert json.loads(out)["Main.label"] == "Пуск насоса"
    code, out, err = call(capsys, "check", str(st_file), "--encoding", "cp1251")
    assert (code, out) == (0, "kurs: 1 POUs, 0 errors, 0 warnings\n")


def test_an_unknown_encoding_is_a_usage_error(capsys, st_file):
    code, out, err = call(capsys, "check", str(st_file), "--encoding", "klingon")
    assert (code, out) == (2, "")
    assert err == "error BAD-OPTION: --encoding: unknown encoding 'klingon' (e.g. utf-8, cp1251, latin-1)\n"


def test_a_project_json_and_a_project_folder_in_cp1251(capsys, tmp_path):
    project, _ = source_to_project(SOURCE, "kurs")
    whole = tmp_path / "kurs.json"
    whole.write_bytes(json.dumps(project.model_dump(mode="json"), ensure_ascii=False).encode("cp1251"))
    code, _, err = call(capsys, "check", str(whole))
    assert code == 2 and err.startswith("kurs.json:1:") and "error BAD-ENCODING: not UTF-8 at byte" in err
    assert call(capsys, "check", str(whole), "--encoding", "cp1251")[0] == 0
    folder = tmp_path / "folder"
    folder.mkdir()
    for rel, content in project_files(project).items():
        (folder / rel).parent.mkdir(parents=True, exist_ok=True)
        (folder / rel).write_bytes(content.encode("cp1251"))
    code, _, err = call(capsys, "check", str(folder))
    assert code == 2 and err.startswith("pous/Main.st:3:24, POU Main: error BAD-ENCODING: not UTF-8 at byte")
    assert call(capsys, "check", str(folder), "--encoding", "cp1251")[0] == 0


def test_a_plcopen_file_in_cp1251_without_a_declaration(capsys, tmp_path):
    project, _ = source_to_project(SOURCE, "kurs")
    xml = export_plcopen(project).decode("utf-8").split("\n", 1)[1]  # without its XML declaration
    path = tmp_path / "kurs.xml"
    path.write_bytes(xml.encode("cp1251"))
    workspace = tmp_path / "ws"
    code, out, err = call(capsys, "import", "plcopen", str(path), "--into", str(workspace))
    assert code == 2 and out == "" and "kurs.xml:" in err and "error BAD-ENCODING: not UTF-8 at byte" in err
    code, out, err = call(capsys, "import", "plcopen", str(path), "--into", str(workspace), "--encoding", "cp1251")
    assert code == 0, err
    loaded = Workspace(workspace).load("kurs").project
    assert "'Пуск насоса'" in loaded.pou("Main").declarations


def test_a_plcopen_file_that_declares_its_encoding_is_read_as_declared(capsys, tmp_path):
    project, _ = source_to_project(SOURCE, "kurs")
    xml = '<?xml version="1.0" encoding="windows-1251"?>\n' + export_plcopen(project).decode("utf-8").split("\n", 1)[1]
    path = tmp_path / "kurs.xml"
    path.write_bytes(xml.encode("cp1251"))
    code, out, err = call(capsys, "import", "plcopen", str(path), "--into", str(tmp_path / "ws"))
    assert code == 0, err
    assert "'Пуск насоса'" in Workspace(tmp_path / "ws").load("kurs").project.pou("Main").declarations


def test_ladderlab_test_reads_a_cp1251_project_with_its_tests_and_hidden_tests(capsys, tmp_path):
    """``ladderlab test`` reads files too: test files and a teacher's hidden tests in cp1251 need --encoding."""
    project, _ = source_to_project(SOURCE, "kurs")
    folder = tmp_path / "kurs"
    for rel, content in project_files(project).items():
        (folder / rel).parent.mkdir(parents=True, exist_ok=True)
        (folder / rel).write_bytes(content.encode("cp1251"))
    test = "TEST 'подпись'\n  ASSERT_EQ(Main.label, 'Пуск насоса');\nEND_TEST\n"
    (folder / "tests" / "hidden").mkdir(parents=True)
    (folder / "tests" / "kurs.st").write_bytes(test.encode("cp1251"))
    (folder / "tests" / "hidden" / "grade.st").write_bytes(test.replace("подпись", "скрытый").encode("cp1251"))
    code, out, err = call(capsys, "test", str(folder))
    assert code == 2 and out == "" and err.startswith("pous/Main.st:3:24, POU Main: error BAD-ENCODING")
    code, out, err = call(capsys, "test", str(folder), "--encoding", "cp1251")
    assert code == 0, err
    assert "PASSED  подпись" in out and "1 passed" in out
    code, out, err = call(capsys, "test", str(folder), "--encoding", "cp1251", "--grade")
    assert code == 0, err
    graded = json.loads(out)
    assert (graded["passed"], graded["total"]) == (2, 2), graded
