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


def test_every_verb_is_documented_and_completed_with_the_arguments_the_checker_takes():
    """The completion list (shared_schema/iec.json test_verbs) shows each verb's arguments: as many required
    and optional ones as the checker accepts, and docs/testing.md describes each verb (issue 20)."""
    from ladderlab.st.testfile import SIGNATURES, VERBS
    from ladderlab.st.vocabulary import vocabulary

    assert [(v["name"], v["signature"]) for v in vocabulary()["test_verbs"]] == list(SIGNATURES.items())
    assert set(VERBS) | {"MOCK", "MOCK_FUNCTION"} == set(SIGNATURES)
    for verb, (fewest, most) in VERBS.items():
        required, _, optional = SIGNATURES[verb].strip("()").partition("[")
        needed = len([a for a in required.split(",") if a.strip()])
        extra = len([a for a in optional.split(",") if a.strip(" ]")])
        assert (needed, needed + extra) == (fewest, most), verb
    doc = (ROOT / "docs" / "testing.md").read_text()
    assert [verb for verb in SIGNATURES if verb not in doc] == []
