"""The warnings of reading a .st file (issue 25 polish): what the check of the project cannot repeat - a pragma
outside every POU or TYPE, which the project does not keep - is printed on stderr, located in the file
(``file:line:col: warning CODE: message``), by ``check``, ``run`` and ``compile``, and does not fail the command; a
warning the check repeats (a pragma inside the globals, ST-65's missing ``;`` before END_PROGRAM) is printed once,
by the check. The pragma's message is tests/st/test_pack_mode.py's; its place is the file's."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from ladderlab.cli import main

from ..st.test_pack_mode import NO_EFFECT

SOURCE = """TYPE A : STRUCT a : BYTE; b : DINT; END_STRUCT; END_TYPE
VAR_GLOBAL
  {attribute 'pack_mode' := '1'} g : A;
END_VAR
   {attribute 'pack_mode' := '1'}
PROGRAM Main
VAR n : DINT; END_VAR
n := n + 1;
IF n > 5 THEN n := 0; END_IF
END_PROGRAM
CONFIGURATION One
  TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);
  PROGRAM Line WITH Fast : Main;
END_CONFIGURATION
{attribute 'pack_mode' := '2'}
"""
ABOVE_PROGRAM = f"plant.st:5:4: warning ST-PRAGMA: {NO_EFFECT}"
AT_THE_END = f"plant.st:15:1: warning ST-PRAGMA: {NO_EFFECT}"
IN_GLOBALS = f"globals:2:3: warning ST-PRAGMA: {NO_EFFECT}"  # the check's own, in the globals text
END_IF = "Main/body:9:29, POU Main: warning ST-PARSE: expected ';' after END_IF"


@pytest.fixture
def st_file(tmp_path: Path) -> Path:
    path = tmp_path / "plant.st"
    path.write_text(SOURCE, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("command", "out"),
    [
        (["check"], [IN_GLOBALS, END_IF, "plant: 1 POUs, 0 errors, 2 warnings"]),
        (
            ["run", "--cycles", "2", "--watch", "Line.n"],
            ["scan  time_ms  Line.n", "0     10       1", "1     20       2"],
        ),
        (["compile"], []),
    ],
)
def test_a_st_files_warnings_are_printed_located_on_stderr_and_do_not_fail(capsys, st_file, command, out):
    code = main([*command, str(st_file)])
    printed, err = capsys.readouterr()
    assert code == 0
    assert printed.splitlines() == out
    import_warnings = [ABOVE_PROGRAM, AT_THE_END]
    check_warnings = [] if command == ["check"] else [IN_GLOBALS, END_IF]  # run and compile: the build's, on stderr
    assert err.splitlines() == import_warnings + check_warnings


def test_the_command_line_program_prints_them_too(st_file):
    """The installed entry point, as a subprocess: the same stderr, exit 0."""
    done = subprocess.run(
        [sys.executable, "-m", "ladderlab.cli", "check", str(st_file)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert (done.returncode, done.stderr.splitlines()) == (0, [ABOVE_PROGRAM, AT_THE_END])


def test_a_file_without_such_warnings_prints_none(capsys, tmp_path: Path):
    path = tmp_path / "clean.st"
    path.write_text("PROGRAM Main\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n", encoding="utf-8")
    assert main(["check", str(path)]) == 0
    assert capsys.readouterr().err == ""
