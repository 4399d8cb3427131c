"""Grading exercises: each project is an exercise, scored by its visible and hidden tests.

A teacher keeps the tests students must not see in ``tests/hidden/`` of the exercise's folder (not part
of the project model, so never shown in the browser); ``ladderlab test --grade`` runs both. The report is
one JSON object per exercise: ``{"exercise", "passed", "total", "files": {path: {"passed", "total"}}}``.
A test file that does not compile scores 0 of the tests it declares.
"""

from __future__ import annotations

from typing import Any

from ..st.parser import parse_tests
from .suite import SuiteFile, SuiteOutcome


def grade(exercise: str, files: list[SuiteFile], outcome: SuiteOutcome) -> dict[str, Any]:
    per_file: dict[str, dict[str, int]] = {}
    for file, result in zip(files, outcome.files):
        parsed = parse_tests(file.text, file=file.path).ast
        declared = len(parsed.tests) if parsed is not None else 0
        total = max(declared - result.skipped, len(result.results))
        per_file[file.path] = {"passed": sum(r.outcome == "passed" for r in result.results), "total": total}
    return {
        "exercise": exercise,
        "passed": sum(f["passed"] for f in per_file.values()),
        "total": sum(f["total"] for f in per_file.values()),
        "files": per_file,
    }
