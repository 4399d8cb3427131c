"""``ladderlab export`` / ``ladderlab import`` (issue 8 CLI) wired to the exporters and the workspace."""

from __future__ import annotations

from pathlib import Path

from ladderlab.cli import main
from ladderlab.storage import Workspace, load_project_path
from tests.support import EXAMPLES


def test_export_plcopen_then_import_gives_the_same_project(tmp_path: Path, capsys) -> None:
    xml = tmp_path / "plc.xml"
    assert main(["export", "plcopen", str(EXAMPLES / "motor"), "-o", str(xml)]) == 0
    assert xml.read_bytes().startswith(b"<?xml")
    assert main(["import", "plcopen", str(xml), "--into", str(tmp_path / "ws")]) == 0
    assert "imported 'motor' (3 POUs)" in capsys.readouterr().out
    imported = Workspace(tmp_path / "ws").load("motor").project
    assert imported == load_project_path(EXAMPLES / "motor")


def test_import_refuses_to_overwrite_an_existing_project(tmp_path: Path, capsys) -> None:
    xml = tmp_path / "plc.xml"
    main(["export", "plcopen", str(EXAMPLES / "motor"), "-o", str(xml)])
    assert main(["import", "plcopen", str(xml), "--into", str(tmp_path)]) == 0
    assert main(["import", "plcopen", str(xml), "--into", str(tmp_path)]) == 2
    assert "already" in capsys.readouterr().err


def test_import_reports_hostile_xml_with_its_file(tmp_path: Path, capsys) -> None:
    bomb = tmp_path / "bomb.xml"
    bomb.write_text('<?xml version="1.0"?><!DOCTYPE l [<!ENTITY a "aaaa"><!ENTITY b "&a;&a;">]><project>&b;</project>')
    assert main(["import", "plcopen", str(bomb), "--into", str(tmp_path / "ws")]) == 1
    assert "bomb.xml" in capsys.readouterr().err
    assert not (tmp_path / "ws").exists() or not any((tmp_path / "ws").iterdir())


def test_export_plcopen_to_stdout(capsys) -> None:
    assert main(["export", "plcopen", str(EXAMPLES / "motor")]) == 0
    assert '<pou name="Main"' in capsys.readouterr().out


def test_export_st_of_one_pou_and_of_the_whole_project(tmp_path: Path, capsys) -> None:
    assert main(["export", "st", str(EXAMPLES / "motor"), "--pou", "main"]) == 0
    assert "Motor := (Start OR Motor) AND NOT Stop;" in capsys.readouterr().out
    out = tmp_path / "motor.st"
    assert main(["export", "st", str(EXAMPLES / "motor"), "-o", str(out)]) == 0
    text = out.read_text()
    assert text.count("END_PROGRAM") == 2 and "CONFIGURATION" in text
    # the exported file is itself a project that runs like the original
    runs = []
    for project in (EXAMPLES / "motor", out):
        capsys.readouterr()
        assert (
            main(
                [
                    "run",
                    str(project),
                    "--cycles",
                    "520",
                    "--set",
                    "Start=TRUE",
                    "--set",
                    "Start=FALSE@3",
                    "--watch",
                    "Motor",
                    "--watch",
                    "Main.MotorRunning",
                    "--watch",
                    "StartCount",
                    "--format",
                    "jsonl",
                ]
            )
            == 0
        )
        runs.append(capsys.readouterr().out)
    assert runs[0] == runs[1]
    assert '"Main.MotorRunning": true' in runs[0]  # 5 s of Motor reached within the run


def test_export_st_of_an_unknown_pou_is_an_error(capsys) -> None:
    assert main(["export", "st", str(EXAMPLES / "motor"), "--pou", "Nope"]) == 1
    assert "no POU 'Nope'" in capsys.readouterr().err
