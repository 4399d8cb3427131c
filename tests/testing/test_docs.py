"""docs/testing.md stays true: its example test file passes on examples/motor (issue 20)."""

from __future__ import annotations

import re

from ladderlab.storage import load_project_path
from ladderlab.testing.run import Options, prepare, run_tests
from tests.support import EXAMPLES, ROOT


def test_the_documented_example_runs_and_passes():
    text = re.search(r"```iecst\n(.*?)```", (ROOT / "docs" / "testing.md").read_text(), re.S).group(1)
    prepared = prepare(load_project_path(EXAMPLES / "motor"), "tests/doc.st", text)
    assert [d.format() for d in prepared.diagnostics if d.severity == "error"] == []
    results = list(run_tests(prepared, Options()))
    assert [(r.name, r.failure) for r in results] == [
        ("seal-in: Start latches the motor, Stop drops it", None),
        ("timer: MotorRunning 5 s after the motor starts", None),
        ("Blinker toggles every half period (a function block on its own)", None),
    ]
