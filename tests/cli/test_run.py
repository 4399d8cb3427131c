"""``ladderlab run`` and ``ladderlab compile`` (issue 4 CLI): scan-by-scan output on the virtual clock."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.cli import main
from ladderlab.cli.run import SetAction, parse_duration, parse_set
from tests.support import EXAMPLES

TIMER = """PROGRAM Main
VAR
  start : BOOL;
  t1 : TON;
  n : INT := 32766;
  lamp : BOOL;
  label : STRING := 'x';
END_VAR
t1(IN := start, PT := T#30ms);
lamp := t1.Q;
n := n + 1;
END_PROGRAM
"""


def run(capsys, tmp_path: Path, source: str, *args: str) -> tuple[int, str, str]:
    path = tmp_path / "prog.st"
    path.write_text(source)
    code = main(["run", str(path), *args])
    out, err = capsys.readouterr()
    return code, out, err


def test_jsonl_reports_every_scan_with_virtual_time_and_the_paths_as_given(capsys, tmp_path):
    code, out, _ = run(
        capsys,
        tmp_path,
        TIMER,
        "--cycles",
        "5",
        "--set",
        "Main.start=TRUE@1",
        "--watch",
        "Main.lamp",
        "--watch",
        "main.T1.et",
        "--watch",
        "Main.n",
        "--format",
        "jsonl",
    )
    assert code == 0
    rows = [json.loads(line) for line in out.splitlines()]
    assert rows == [
        {"scan": 0, "time_ms": 10, "Main.lamp": False, "main.T1.et": 0, "Main.n": 32767},
        {"scan": 1, "time_ms": 20, "Main.lamp": False, "main.T1.et": 0, "Main.n": -32768},  # INT wraps
        {"scan": 2, "time_ms": 30, "Main.lamp": False, "main.T1.et": 10, "Main.n": -32767},
        {"scan": 3, "time_ms": 40, "Main.lamp": False, "main.T1.et": 20, "Main.n": -32766},
        {"scan": 4, "time_ms": 50, "Main.lamp": True, "main.T1.et": 30, "Main.n": -32765},  # ET >= PT
    ]


def test_for_runs_every_scan_due_within_the_duration_and_strings_print_as_strings(capsys, tmp_path):
    code, out, _ = run(
        capsys,
        tmp_path,
        TIMER,
        "--for",
        "T#30ms",
        "--set",
        "Main.label='on'",
        "--watch",
        "Main.label",
        "--format",
        "jsonl",
    )
    assert code == 0
    assert [json.loads(line) for line in out.splitlines()] == [
        {"scan": 0, "time_ms": 10, "Main.label": "on"},
        {"scan": 1, "time_ms": 20, "Main.label": "on"},
        {"scan": 2, "time_ms": 30, "Main.label": "on"},
    ]


LIGHTS = """TYPE TLight : (Red, Yellow, Green := 5); END_TYPE
TYPE TLamp : STRUCT colour : TLight; lit : BOOL; END_STRUCT END_TYPE
FUNCTION_BLOCK Signal
VAR_OUTPUT shown : TLight; END_VAR
shown := Yellow;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
  go : BOOL;
  light : TLight;
  lamp : TLamp;
  row : ARRAY[1..2] OF TLight;
  signal : Signal;
END_VAR
signal();
IF go THEN light := Green; ELSE light := Red; END_IF;
lamp.colour := light;
row[2] := signal.shown;
END_PROGRAM
"""


def test_enumerations_print_as_their_declared_literals_also_inside_structures_arrays_and_instances(capsys, tmp_path):
    """An enumeration's value reads as ``TLIGHT#Green`` (its type, upper case as every name the CLI prints, and the
    value's name as declared: how `ladderlab test` reports print it), not as the number the engine stores, wherever
    it stands in a watched value; a --set takes the same literal."""
    code, out, err = run(
        capsys,
        tmp_path,
        LIGHTS,
        "--cycles",
        "2",
        "--set",
        "Main.go=TRUE@1",
        "--watch",
        "Main.light",
        "--watch",
        "Main.lamp",
        "--watch",
        "Main.row",
        "--watch",
        "Main.signal",
        "--format",
        "jsonl",
    )
    assert (code, err) == (0, "")
    rows = [json.loads(line) for line in out.splitlines()]
    assert rows == [
        {
            "scan": 0,
            "time_ms": 10,
            "Main.light": "TLIGHT#Red",
            "Main.lamp": {"COLOUR": "TLIGHT#Red", "LIT": False},
            "Main.row": ["TLIGHT#Red", "TLIGHT#Yellow"],
            "Main.signal": {"SHOWN": "TLIGHT#Yellow"},
        },
        {
            "scan": 1,
            "time_ms": 20,
            "Main.light": "TLIGHT#Green",
            "Main.lamp": {"COLOUR": "TLIGHT#Green", "LIT": False},
            "Main.row": ["TLIGHT#Red", "TLIGHT#Yellow"],
            "Main.signal": {"SHOWN": "TLIGHT#Yellow"},
        },
    ]
    code, out, _ = run(
        capsys, tmp_path, LIGHTS, "--cycles", "1", "--set", "Main.row[1]=TLight#Green", "--watch", "Main.row"
    )
    assert (code, out.splitlines()) == (
        0,
        ["scan  time_ms  Main.row", '0     10       ["TLIGHT#Green", "TLIGHT#Yellow"]'],
    )


def test_table_format_has_a_header_and_aligned_rows(capsys, tmp_path):
    code, out, _ = run(capsys, tmp_path, TIMER, "--cycles", "2", "--watch", "Main.n", "--watch", "Main.lamp")
    assert code == 0
    assert out.splitlines() == [
        "scan  time_ms  Main.n  Main.lamp",
        "0     10       32767   false",
        "1     20       -32768  false",
    ]


def test_without_watch_every_variable_is_reported(capsys, tmp_path):
    code, out, _ = run(capsys, tmp_path, TIMER, "--format", "jsonl")
    assert code == 0
    assert json.loads(out) == {
        "scan": 0,
        "time_ms": 10,
        "MAIN.START": False,
        "MAIN.T1.IN": False,
        "MAIN.T1.PT": 30,
        "MAIN.T1.Q": False,
        "MAIN.T1.ET": 0,
        "MAIN.N": 32767,
        "MAIN.LAMP": False,
        "MAIN.LABEL": "x",
    }


def test_runtime_error_stops_with_exit_3_and_the_location(capsys, tmp_path):
    source = "PROGRAM Main\nVAR d : INT; q : INT; END_VAR\nq := 10 / d;\nEND_PROGRAM\n"
    code, out, err = run(capsys, tmp_path, source, "--cycles", "3", "--watch", "Main.q", "--format", "jsonl")
    assert code == 3
    assert len(out.splitlines()) == 1  # the faulting scan is reported, then the run stops
    assert "division by zero" in err and "line 3" in err and "POU MAIN" in err


def test_compile_errors_exit_1_with_located_diagnostics(capsys, tmp_path):
    code, _, err = run(capsys, tmp_path, "PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n")
    assert code == 1
    assert "Main/body:3:6" in err and "unknown variable 'y'" in err


@pytest.mark.parametrize(
    "args, message",
    [
        (["--watch", "Main.nope"], "nope"),
        (["--set", "Main.n=40000"], "40000 is out of range for INT"),
        (["--set", "Main.n"], "expected PATH=VALUE"),
        (["--for", "soon"], "expected a duration"),
    ],
)
def test_bad_paths_values_and_options_are_usage_errors(capsys, tmp_path, args, message):
    code, _, err = run(capsys, tmp_path, TIMER, *args)
    assert code == 2
    assert message in err


def test_example_project_runs(capsys):
    code = main(
        [
            "run",
            str(EXAMPLES / "motor"),
            "--cycles",
            "3",
            "--set",
            "Start=TRUE",
            "--watch",
            "Motor",
            "--format",
            "jsonl",
        ]
    )
    out, _ = capsys.readouterr()
    assert code == 0
    assert [json.loads(line)["Motor"] for line in out.splitlines()] == [True, True, True]


def test_compile_emits_the_generated_python(capsys, tmp_path):
    path = tmp_path / "prog.st"
    path.write_text(TIMER)
    assert main(["compile", str(path), "--emit-python"]) == 0
    source = capsys.readouterr().out
    compile(source, "emitted", "exec")
    assert "class P_MAIN" in source and "# line 10" in source


@given(
    path=st.from_regex(r"[A-Za-z_][A-Za-z0-9_.\[\]]{0,20}", fullmatch=True),
    value=st.text(min_size=1, max_size=12).filter(lambda v: v.strip() == v and "=" not in v and "@" not in v),
    scan=st.integers(0, 10_000),
)
def test_parse_set_round_trips(path, value, scan):
    assert parse_set(f"{path}={value}@{scan}") == SetAction(path, value, scan)
    assert parse_set(f"{path}={value}") == SetAction(path, value, 0)


def test_parse_duration_forms():
    assert [parse_duration(t) for t in ("2s", "T#2s", "500ms", "1m30s", "time#1h")] == [
        2000,
        2000,
        500,
        90_000,
        3_600_000,
    ]


def test_direct_addresses_are_set_and_watched_by_address(capsys, tmp_path):
    """Issue 16: ``--set %IX0.1=TRUE`` and ``--watch %QX3.0`` reach the process image; the program uses the
    addresses without declaring them (the seeds' IEC manuals write I/O this way)."""
    source = "PROGRAM Main\n%QX3.0 := %IX0.1 AND NOT %IX0.2;\n%QW4 := %IW2 + 1;\nEND_PROGRAM\n"
    code, out, err = run(
        capsys,
        tmp_path,
        source,
        "--cycles",
        "2",
        "--set",
        "%IX0.1=TRUE",
        "--set",
        "%IX0.2=TRUE@1",
        "--set",
        "%IW2=41",
        "--watch",
        "%QX3.0",
        "--watch",
        "%QW4",
        "--format",
        "jsonl",
    )
    assert (code, err) == (0, "")
    assert [json.loads(line) for line in out.splitlines()] == [
        {"scan": 0, "time_ms": 10, "%QX3.0": True, "%QW4": 42},
        {"scan": 1, "time_ms": 20, "%QX3.0": False, "%QW4": 42},
    ]
