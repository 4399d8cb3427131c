"""IL POUs in project folders (``pous/<name>.il``) and IL source files on the command line (issue 26 item 1)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from ladderlab.model import Pou, Project
from ladderlab.storage import Workspace, load_project_path

MAIN_IL = """PROGRAM Main
VAR
    count : INT;
    done : BOOL;
END_VAR
    LD    count     (* count the scans *)
    ADD   1
    ST    count
    GE    3
    ST    done
END_PROGRAM
"""


def ladderlab(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ladderlab.cli", *args], capture_output=True, text=True, timeout=60)


def test_il_pou_is_stored_as_iec_text_in_an_il_file(tmp_path: Path) -> None:
    ws = Workspace(tmp_path / "ws")
    pou = Pou(
        name="Main",
        kind="program",
        language="il",
        declarations="VAR\n    count : INT;\n    done : BOOL;\nEND_VAR",
        body=MAIN_IL.split("END_VAR\n")[1].removesuffix("END_PROGRAM\n").rstrip(),
    )
    ws.create(Project(name="p", pous=[pou]))
    assert sorted(p.name for p in (ws.folder("p") / "pous").iterdir()) == ["Main.il"]
    assert (ws.folder("p") / "pous" / "Main.il").read_text() == MAIN_IL
    assert ws.load("p").project.pous == [pou]


def test_an_st_pou_whose_text_reads_as_il_is_kept_as_json(tmp_path: Path) -> None:
    """A ``.st`` file whose body is IL loads as IL, so an ST POU with such a body is stored exactly as JSON."""
    ws = Workspace(tmp_path / "ws")
    pou = Pou(name="Main", kind="program", language="st", body="LD x\nST y")
    ws.create(Project(name="p", pous=[pou]))
    assert sorted(p.name for p in (ws.folder("p") / "pous").iterdir()) == ["Main.st.json"]
    assert ws.load("p").project.pous == [pou]


def test_an_il_body_in_an_st_file_of_a_folder_is_il(tmp_path: Path) -> None:
    folder = tmp_path / "p"
    (folder / "pous").mkdir(parents=True)
    (folder / "project.json").write_text('{"format": "ladderlab/1", "name": "p", "pous": ["Main"], "tasks": []}')
    (folder / "pous" / "Main.st").write_text(MAIN_IL)
    assert load_project_path(folder).pous[0].language == "il"


def test_cli_check_run_and_export_take_an_il_file(tmp_path: Path) -> None:
    """``check``, ``run`` and ``export st`` take a ``.il`` file: 3 scans make done TRUE (count 1, 2, 3 >= 3)."""
    path = tmp_path / "counter.il"
    path.write_text(MAIN_IL)
    checked = ladderlab("check", str(path))
    assert checked.returncode == 0, checked.stderr
    assert "counter: 1 POUs, 0 errors" in checked.stdout
    ran = ladderlab("run", str(path), "--cycles", "3", "--watch", "Main.count", "--watch", "Main.done")
    assert ran.returncode == 0, ran.stderr
    rows = [line.split() for line in ran.stdout.strip().splitlines()[1:]]
    assert [row[-2:] for row in rows] == [["1", "false"], ["2", "false"], ["3", "true"]]
    exported = ladderlab("export", "st", str(path), "--pou", "Main")
    assert exported.returncode == 0, exported.stderr
    assert "CR_INT := count + 1;\ncount := CR_INT;\ndone := CR_INT >= 3;\nEND_PROGRAM" in exported.stdout


def test_cli_check_locates_il_errors_in_the_file(tmp_path: Path) -> None:
    path = tmp_path / "bad.il"
    path.write_text(MAIN_IL.replace("ST    done", "ST    count"))
    checked = ladderlab("check", str(path))
    assert checked.returncode == 1
    assert "Main/body:10:5, POU Main: error IL-TYPE: ST count: the accumulator holds BOOL, count is INT" in (
        checked.stdout
    )
