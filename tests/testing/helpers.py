"""Running test files against small projects written as ST source (issue 20)."""

from __future__ import annotations

from ladderlab.st.project_text import source_to_project
from ladderlab.testing.run import Options, TestResult, prepare, run_tests

FILE = "tests/unit.st"


def project(source: str):
    built, diagnostics = source_to_project(source, "unit")
    assert built is not None, diagnostics
    return built


def run(source: str, tests: str, **options) -> list[TestResult]:
    prepared = prepare(project(source), FILE, tests)
    errors = [d.format() for d in prepared.diagnostics if d.severity == "error"]
    assert prepared.compiled is not None, errors
    return list(run_tests(prepared, Options(**options)))


def outcomes(results: list[TestResult]) -> dict[str, str | None]:
    """Test name -> None when it passed, else its failure's full text and line (``text @line``)."""
    return {r.name: None if r.failure is None else f"{r.failure.text()} @{r.failure.line}" for r in results}


def errors(source: str, tests: str) -> list[str]:
    """The located error diagnostics of a test file that does not compile (``line:column CODE message``)."""
    prepared = prepare(project(source), FILE, tests)
    assert prepared.compiled is None
    return [f"{d.line}:{d.column} {d.code} {d.message}" for d in prepared.diagnostics if d.severity == "error"]


def at(text: str, snippet: str) -> int:
    """The 1-based line of ``text`` where ``snippet`` first appears (where a failure must be reported)."""
    before = text[: text.index(snippet)]
    return before.count("\n") + 1
