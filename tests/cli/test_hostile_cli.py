"""Hostile input on the command line (issue 18: 54 of 133 hostile CLI runs printed a traceback).

Each case is run as a user would (``main(argv)``; two through a real process) and must end with a
located message on stderr and the documented exit code: 1 for diagnostics of a project that loads,
2 for input that cannot be loaded. Exit 70 (internal error) is a bug in every case. A fuzzer feeds
random files and options to every command (a few dozen cases in ``make test``, 10,000 in
``make test-slow``).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.cli import EXIT_INTERNAL, main
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.storage import load_project_path
from tests.support import EXAMPLES, fuzz_settings


def cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    assert code != EXIT_INTERNAL, err
    assert "Traceback" not in err
    return code, out, err


def motor_xml() -> bytes:
    return export_plcopen(load_project_path(EXAMPLES / "motor"))


def test_deeply_nested_json_is_a_located_load_error(capsys, tmp_path: Path) -> None:
    path = tmp_path / "deep.json"
    path.write_text('{"name": "p", "pous": ' + "[" * 100_000 + "]" * 100_000 + "}")
    code, _, err = cli(capsys, "check", str(path))
    assert code == 2
    # the object is level 1, so the 400th "[" is level 401: column 22 (the prefix) + 400
    assert err.startswith("deep.json:1:422: error BAD-JSON: the JSON nests deeper than the limit of 400 levels")


def test_a_lone_surrogate_in_a_json_project_is_a_located_load_error(capsys, tmp_path: Path) -> None:
    path = tmp_path / "p.json"
    path.write_text('{\n  "name": "p",\n  "globals": "\\udcff"\n}\n')
    code, _, err = cli(capsys, "run", str(path))
    assert code == 2
    assert err.startswith("p.json:3:15: error BAD-JSON: the escape \\udcff is half of a UTF-16 surrogate pair")


@pytest.mark.parametrize(
    ("literal", "reason"),
    [
        ("D#2024-02-30", "day is out of range for month"),
        ("DT#2024-13-01-00:00:00", "month must be in 1..12"),
        ("TOD#25:00:00", "the time of day must lie between 00:00:00 and 23:59:59.999"),
    ],
)
@pytest.mark.parametrize("command", ["check", "run", "compile", "export"])
def test_an_impossible_date_is_a_located_error(capsys, tmp_path: Path, literal: str, reason: str, command: str) -> None:
    path = tmp_path / "dates.st"
    path.write_text(f"PROGRAM Main\nVAR\n  d : DATE;\nEND_VAR\nd := {literal};\nEND_PROGRAM\n")
    argv = ["export", "st", str(path)] if command == "export" else [command, str(path)]
    code, _, err = cli(capsys, *argv)
    assert code == 2
    assert err.strip() == f"dates.st:5:6, POU Main: error ST-PARSE: {literal} is not a valid date or time: {reason}"


@pytest.mark.parametrize(
    ("document", "expected"),
    [
        (
            "UTF-7",
            "error XML-ENCODING: the document's encoding cannot be read (multi-byte encodings are not supported)",
        ),
        ("klingon", "error XML-ENCODING: the document's encoding cannot be read (unknown encoding: klingon)"),
        ("deep", "error XML-TOO-DEEP: the document nests deeper than the limit of 200 levels"),
    ],
)
def test_hostile_plcopen_documents_are_located_errors(capsys, tmp_path: Path, document: str, expected: str) -> None:
    data = motor_xml()
    if document == "deep":
        at = data.index(b"<documentation>") + len(b"<documentation>")
        data = data[:at] + b"<xhtml:p>" * 100_000 + b"</xhtml:p>" * 100_000 + data[at:]
    else:
        data = f'<?xml version="1.0" encoding="{document}"?>'.encode() + data.split(b"?>", 1)[1]
    path = tmp_path / "plc.xml"
    path.write_bytes(data)
    code, _, err = cli(capsys, "import", "plcopen", str(path), "--into", str(tmp_path / "ws"))
    assert code == 1
    assert err.startswith("plc.xml:")
    assert expected in err
    assert not (tmp_path / "ws" / "motor").exists()


def test_nesting_past_the_limit_is_a_located_error_not_a_recursion_error(capsys, tmp_path: Path) -> None:
    path = tmp_path / "deep.st"
    path.write_text("PROGRAM Main\nVAR b : BOOL; END_VAR\nb := " + "NOT " * 5000 + "TRUE;\nEND_PROGRAM\n")
    code, _, err = cli(capsys, "run", str(path))
    assert code == 2
    assert "deep.st:3:" in err and "error ST-TOO-DEEP: this expression nests deeper than the limit of 1,000" in err


def test_an_unwritable_output_is_a_message_not_a_traceback(capsys, tmp_path: Path) -> None:
    (tmp_path / "a-file").write_text("")
    code, _, err = cli(capsys, "export", "st", str(EXAMPLES / "motor"), "-o", str(tmp_path / "a-file" / "x.st"))
    assert code == 2
    assert err == f"ladderlab: {tmp_path / 'a-file'}: File exists\n"  # mkdir of the folder the output needs


def test_a_bug_is_one_line_with_exit_70(capsys, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("ladderlab.simulation.check.check_project", lambda project: 1 / 0)
    assert main(["check", str(EXAMPLES / "motor")]) == EXIT_INTERNAL
    err = capsys.readouterr().err
    assert err == "ladderlab: internal error: ZeroDivisionError: division by zero (please report it)\n"


def test_a_real_process_prints_no_traceback(tmp_path: Path) -> None:
    path = tmp_path / "deep.json"
    path.write_text("[" * 200_000)
    result = subprocess.run(
        [sys.executable, "-m", "ladderlab.cli", "check", str(path)],
        capture_output=True,
        text=True,
        timeout=60,
        env={**os.environ, "LADDERLAB_TRACEBACK": ""},
    )
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    assert "error BAD-JSON" in result.stderr


# ----------------------------------------------------------------- the CLI fuzzer

FRAGMENTS = [
    "PROGRAM Main\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n",
    "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n",
    "TYPE T : STRUCT a : INT; END_STRUCT; END_TYPE\n",
    "VAR_GLOBAL g : BOOL; END_VAR\n",
    "D#2024-02-30",
    "ARRAY[0..999999999] OF BOOL",
    "NOT " * 300,
    "(" * 250,
    "\udcff",
    '{"name": "p", "pous": [',
    "]}",
    "<?xml version='1.0' encoding='UTF-7'?>",
    "IF TRUE THEN\n" * 30,
    "END_IF;\n" * 30,
    "CONFIGURATION C RESOURCE R ON PLC TASK T(INTERVAL := T#10ms); PROGRAM P WITH T : Main; END_RESOURCE END_CONFIGURATION\n",
]
texts = st.lists(st.sampled_from(FRAGMENTS) | st.text(max_size=30), max_size=6).map("".join)
options = st.lists(
    st.sampled_from(["--cycles", "3", "--for", "T#30ms", "--set", "Main.x=5", "--watch", "Main.x", "--format", "jsonl"])
    | st.text(max_size=8),
    max_size=4,
)


@fuzz_settings(fast=30)
@given(
    command=st.sampled_from(["check", "run", "compile", "export st", "export plcopen", "import plcopen"]),
    suffix=st.sampled_from([".st", ".json", ".xml"]),
    text=texts | st.binary(max_size=80).map(lambda b: b.decode("latin-1")),
    extra=options,
)
def test_random_files_and_options_never_print_a_traceback(tmp_path_factory, command, suffix, text, extra) -> None:
    folder = tmp_path_factory.mktemp("fuzz")
    path = folder / f"input{suffix}"
    path.write_bytes(text.encode("utf-8", "surrogatepass"))
    argv = [*command.split(), str(path), *extra]
    if command == "import plcopen":
        argv += ["--into", str(folder / "ws")]
    try:
        code = main(argv)
    except SystemExit as stop:  # argparse refusing an option: its usage message, exit 2
        code = stop.code
    assert code in (0, 1, 2, 3), code


def test_a_file_that_is_not_utf8_is_a_message_with_exit_2(capsys, tmp_path: Path) -> None:
    """(Found by the fuzzer: a lone surrogate written to a .st file is no UTF-8.)"""
    path = tmp_path / "bad.st"
    path.write_bytes(b"PROGRAM Main\nVAR x : INT; END_VAR\n\xed\xb3\xbf\nEND_PROGRAM\n")  # 13 + 21 bytes, then it
    code, _, err = cli(capsys, "check", str(path))
    assert code == 2
    assert (
        err
        == "bad.st:3:1: error BAD-ENCODING: not UTF-8 at byte 34 (0xED); re-save as UTF-8 or pass --encoding cp1251\n"
    )
