"""The spec's worked ST examples (data/spec_examples.json) parse and check as the spec states.

Their run-time expectations (``expect``) are kept in the same data file for the
engine tests; here only the front end's verdict is asserted.
"""

from __future__ import annotations

import json
import pathlib

import pytest

from ladderlab.st.checker import check_project
from ladderlab.st.project_text import source_to_project

DATA = json.loads((pathlib.Path(__file__).parent / "data" / "spec_examples.json").read_text(encoding="utf-8"))
EXAMPLES = {example["id"]: example for example in DATA["examples"]}


def _diagnostics(example):
    project, diagnostics = source_to_project(example["source"], example["id"])
    if project is not None:
        diagnostics = diagnostics + check_project(project).diagnostics
    return [d for d in diagnostics if d.severity == "error"]


@pytest.mark.parametrize("example_id", [k for k, v in EXAMPLES.items() if v["check"] == "ok"])
def test_example_parses_and_checks_without_errors(example_id):
    assert [d.format() for d in _diagnostics(EXAMPLES[example_id])] == []


@pytest.mark.parametrize("example_id", [k for k, v in EXAMPLES.items() if v["check"] == "errors"])
def test_example_as_printed_gives_the_stated_error(example_id):
    found = [
        {"code": d.code, "line": d.line, "column": d.column, "message": d.message}
        for d in _diagnostics(EXAMPLES[example_id])
    ]
    assert found == EXAMPLES[example_id]["diagnostics"]


def test_every_runnable_example_keeps_its_expected_values_for_the_engine():
    runnable = [e for e in EXAMPLES.values() if e["check"] == "ok"]
    assert all("expect" in e for e in runnable)
    assert EXAMPLES["EX-40"]["expect"]["calls"][5] == {"function": "EXAMPLE", "args": {"code": 56}, "result": 4}
