"""``ladderlab test``: reports, exit codes, JUnit, jsonl, filter, coverage, grading (issue 20)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from ladderlab.cli import main
from ladderlab.storage import load_project_path
from ladderlab.storage.workspace import Workspace
from tests.support import EXAMPLES

FAILING = """TEST 'passes'
  Start := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(Motor);
END_TEST

TEST 'fails'
  RUN_SCANS(2);
  ASSERT_EQ(StartCount, 1, 'no start yet');
END_TEST
"""


@pytest.fixture
def motor(tmp_path):
    folder = tmp_path / "motor"
    shutil.copytree(EXAMPLES / "motor", folder)
    return folder


def test_the_example_project_passes_its_tests(capsys):
    assert main(["test", str(EXAMPLES / "motor")]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "tests/motor.st"
    assert out[1] == "  PASSED  seal-in: Start latches the motor, Stop drops it"
    assert out[-1] == "6 passed, 0 failed"


def test_failures_are_reported_with_their_location_and_exit_1(motor, capsys):
    (motor / "tests" / "more.st").write_text(FAILING)
    assert main(["test", str(motor), "--filter", "*ail*"]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[:6] == [
        "tests/more.st",
        "  FAILED  fails",
        "          ASSERT_EQ failed: StartCount expected 1, got 0",
        "          Message: no start yet",
        "          at tests/more.st:9",
        "tests/motor.st",
    ]
    assert out[-1] == "0 passed, 1 failed, 7 skipped"


def test_a_file_that_does_not_compile_exits_2_with_located_diagnostics(motor, capsys):
    (motor / "tests" / "broken.st").write_text("TEST 'x'\n  ASSERT_EQ(Nothing, 1);\nEND_TEST\n")
    assert main(["test", str(motor)]) == 2
    out = capsys.readouterr().out.splitlines()
    assert out[:3] == [
        "tests/broken.st",
        "  does not compile:",
        "    tests/broken.st:2:13: error ST-UNKNOWN-VAR: unknown variable 'Nothing'",
    ]
    assert out[-1] == "6 passed, 0 failed"


def test_junit_and_jsonl_reports(motor, tmp_path, capsys):
    (motor / "tests" / "more.st").write_text(FAILING)
    junit = tmp_path / "report.xml"
    assert main(["test", str(motor), "--format", "junit", "-o", str(junit)]) == 1
    assert capsys.readouterr().out.splitlines()[-1] == "7 passed, 1 failed"
    root = ET.parse(junit).getroot()
    assert (root.tag, root.get("tests"), root.get("failures")) == ("testsuites", "8", "1")
    failure = root.find("testsuite[@name='tests/more.st']/testcase[@name='fails']/failure")
    assert failure.get("message") == "ASSERT_EQ failed: StartCount expected 1, got 0"
    assert failure.text == "ASSERT_EQ failed: StartCount expected 1, got 0\nMessage: no start yet\nat tests/more.st:9"

    assert main(["test", str(motor), "--format", "jsonl"]) == 1
    lines = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    fails = next(line for line in lines if line.get("name") == "fails")
    assert fails["failure"] == {
        "message": "ASSERT_EQ failed: StartCount expected 1, got 0",
        "line": 9,
        "column": 3,
        "verb": "ASSERT_EQ",
        "actual": "0",
        "expected": "1",
        "note": "no start yet",
        "kind": "assertion",
    }
    assert lines[-1]["summary"] | {"seconds": 0} == {
        "passed": 7,
        "failed": 1,
        "skipped": 0,
        "files_with_errors": 0,
        "seconds": 0,
    }


def test_coverage_names_what_the_tests_never_executed_or_energised(motor, tmp_path, capsys):
    (motor / "tests" / "motor.st").unlink()
    (motor / "tests" / "only.st").write_text(FAILING.split("TEST 'fails'")[0])
    target = tmp_path / "coverage.json"
    assert main(["test", str(motor), "--coverage", "--coverage-json", str(target)]) == 0
    report = json.loads(target.read_text())
    # One scan with Start: the seal-in contact (Motor) is read before the coil sets Motor; the NC Stop contact
    # passes power; the timer ran but never reached 5 s; the counter's Q (CV >= 100) and everything behind
    # MotorRunning stayed FALSE; Scaling never saw Speed > 50 (Speed = 1 * 10 + 5). Blinker ran disabled:
    # body lines 1-4 (IF NOT Enable ... RETURN), never 6-9 (the half-period timer and the toggle).
    assert report["Main"]["never_executed"] == []
    assert report["Main"]["never_energised"] == [
        "seal",
        "ton",
        "ton.Q",
        "running",
        "reset_count",
        "ctu",
        "ctu.Q",
        "running_on",
        "blink",
        "blink.OUT",
        "lamp_coil",
    ]
    assert report["Blinker"] == {"language": "st", "elements": 8, "executed": 4, "never_executed_lines": [6, 7, 8, 9]}
    text = capsys.readouterr().out
    assert "  Main (LD): 19/19 elements executed\n" in text


def test_grading_runs_hidden_tests_and_saves_keep_them(motor, tmp_path, capsys):
    hidden = motor / "tests" / "hidden"
    (hidden / "extra.st").write_text(FAILING)
    workspace = Workspace(tmp_path)
    stored = workspace.load("motor")
    assert [t.name for t in stored.project.tests] == ["motor"]  # the hidden file is not in the model
    workspace.save(stored.project, stored.revision)
    assert (hidden / "extra.st").read_text() == FAILING
    assert main(["test", str(motor), "--grade"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report == {
        "exercise": "motor",
        "passed": 9,
        "total": 10,
        "files": {
            "tests/motor.st": {"passed": 6, "total": 6},
            "tests/hidden/extra.st": {"passed": 1, "total": 2},
            "tests/hidden/grading.st": {"passed": 2, "total": 2},
        },
    }


def test_many_tests_run_in_worker_processes_with_the_same_results_and_a_memory_limit(motor):
    tests = "".join(
        f"TEST 'n{i}'\n  Start := TRUE;\n  RUN_SCANS({i % 3});\n  ASSERT_EQ(Motor, {'TRUE' if i % 3 else 'FALSE'});\n"
        f"  ASSERT_EQ(Main.StartCounter.CV, {1 if i % 3 else 0} + {i % 2});\nEND_TEST\n"
        for i in range(60)
    )
    hog = "TEST 'hog'\n  VAR big : ARRAY[1..200000000] OF LINT; END_VAR\n  ASSERT_EQ(big[1], 0);\nEND_TEST\n"
    (motor / "tests" / "many.st").write_text(tests)
    (motor / "tests" / "hog.st").write_text(hog)
    result = subprocess.run(
        [sys.executable, "-m", "ladderlab.cli", "test", str(motor), "--jobs", "2", "--format", "jsonl"]
        + ["--memory-limit", "700"],
        capture_output=True,
        text=True,
        timeout=300,
        env={**os.environ, "LADDERLAB_MAX_ARRAY_ELEMENTS": "300000000"},  # the memory limit is what refuses it
    )
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    names = [line["name"] for line in lines if line.get("file") == "tests/many.st"]
    assert names == [f"n{i}" for i in range(60)]
    failed = sorted(line["name"] for line in lines if line.get("outcome") == "failed")
    # CV counts one start for any test that scanned (i % 3 > 0), never i % 2 more: odd i fail
    assert failed == sorted(f"n{i}" for i in range(60) if i % 2)
    hog = next(line for line in lines if line.get("file") == "tests/hog.st")
    assert [(d["code"], d["message"]) for d in hog["diagnostics"]] == [
        (
            "TEST-MEMORY",
            "out of memory while checking and compiling this test file with the project: its variables need more "
            "memory than the process may use (--memory-limit)",
        )
    ]
    assert result.returncode == 2
    assert load_project_path(motor).tests[2].name == "motor"


def test_a_worker_process_that_dies_is_reported_for_its_file():
    """TEST-WORKER: the process running a file ended (killed, out of memory outside a test) - said for that file,
    not a traceback; the other files' results stand."""
    from concurrent.futures import Future
    from concurrent.futures.process import BrokenProcessPool

    from ladderlab.testing.suite import SuiteFile, _result

    died: Future = Future()
    died.set_exception(BrokenProcessPool("A child process terminated abruptly, the process pool is not usable anymore"))
    part = _result(died, 1, 0, [SuiteFile("tests/a.st", ""), SuiteFile("tests/b.st", "")])
    assert (part.file, part.results) == (1, [])
    assert [(d.code, d.file, d.message) for d in part.diagnostics] == [
        (
            "TEST-WORKER",
            "tests/b.st",
            "the worker process running this file stopped (BrokenProcessPool: A child process terminated abruptly, "
            "the process pool is not usable anymore); its tests did not run",
        )
    ]
