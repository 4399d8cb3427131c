"""Test results as text (pytest-like), jsonl (one object per test, then a summary) and JUnit XML.

The text report ends with the line ``N passed, N failed`` (``, N skipped`` when a filter left tests
out), which CI systems read; a test file that does not compile is listed with its located diagnostics.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from dataclasses import asdict
from typing import Any

from .run import TestResult
from .suite import SuiteOutcome


def summary_line(outcome: SuiteOutcome) -> str:
    line = f"{outcome.count('passed')} passed, {outcome.count('failed')} failed"
    skipped = outcome.count("skipped")
    return line + (f", {skipped} skipped" if skipped else "")


def result_lines(result: TestResult) -> list[str]:
    """One test: ``PASSED name`` or ``FAILED name`` with its failure, indented, and where it happened."""
    if result.failure is None:
        return [f"  PASSED  {result.name}"]
    lines = [f"  FAILED  {result.name}"]
    lines += [f"          {text}" for text in result.failure.text().splitlines()]
    where = result.failure.line or result.line
    lines.append(f"          at {result.file}:{where}")
    return lines


def text_report(outcome: SuiteOutcome, coverage_text: str | None = None) -> str:
    lines: list[str] = []
    for file in outcome.files:
        lines.append(file.path)
        if not file.ok:
            lines.append("  does not compile:")
            lines += [f"    {d.format()}" for d in file.diagnostics if d.severity == "error"]
        for result in file.results:
            lines += result_lines(result)
    errors = sum(1 for f in outcome.files if not f.ok)
    tests = len(outcome.results)
    lines.append("")
    if coverage_text:
        lines += [coverage_text, ""]
    files = len(outcome.files)
    lines.append(
        f"ran {tests} test{'s' if tests != 1 else ''} from {files} file{'s' if files != 1 else ''} "
        f"in {outcome.seconds:.2f} s"
        + (f"; {errors} test file{'s' if errors != 1 else ''} with errors" if errors else "")
    )
    lines.append(summary_line(outcome))
    return "\n".join(lines) + "\n"


def result_json(result: TestResult) -> dict[str, Any]:
    data: dict[str, Any] = {
        "file": result.file,
        "name": result.name,
        "line": result.line,
        "outcome": result.outcome,
        "duration_s": round(result.duration_s, 6),
        "scans": result.scans,
    }
    if result.failure is not None:
        data["failure"] = asdict(result.failure)
    return data


def jsonl_report(outcome: SuiteOutcome) -> str:
    lines: list[dict[str, Any]] = []
    for file in outcome.files:
        if not file.ok:
            lines.append(
                {
                    "file": file.path,
                    "diagnostics": [d.model_dump(mode="json", exclude_none=True) for d in file.diagnostics],
                }
            )
        lines += [result_json(r) for r in file.results]
    lines.append(
        {
            "summary": {
                "passed": outcome.count("passed"),
                "failed": outcome.count("failed"),
                "skipped": outcome.count("skipped"),
                "files_with_errors": sum(1 for f in outcome.files if not f.ok),
                "seconds": round(outcome.seconds, 3),
            }
        }
    )
    return "".join(json.dumps(line, ensure_ascii=False) + "\n" for line in lines)


def junit_report(outcome: SuiteOutcome, name: str = "ladderlab") -> str:
    root = ET.Element(
        "testsuites",
        name=name,
        tests=str(len(outcome.results)),
        failures=str(outcome.count("failed")),
        errors=str(sum(1 for f in outcome.files if not f.ok)),
        time=f"{outcome.seconds:.3f}",
    )
    for file in outcome.files:
        suite = ET.SubElement(
            root,
            "testsuite",
            name=file.path,
            tests=str(len(file.results)),
            failures=str(sum(1 for r in file.results if r.outcome == "failed")),
            errors="0" if file.ok else "1",
            skipped=str(file.skipped),
            time=f"{sum(r.duration_s for r in file.results):.3f}",
        )
        if not file.ok:
            case = ET.SubElement(suite, "testcase", classname=file.path, name="(compile)")
            error = ET.SubElement(case, "error", message="the test file does not compile", type="CompileError")
            error.text = "\n".join(d.format() for d in file.diagnostics if d.severity == "error")
        for result in file.results:
            case = ET.SubElement(
                suite, "testcase", classname=file.path, name=result.name, time=f"{result.duration_s:.3f}"
            )
            if result.failure is not None:
                failure = ET.SubElement(case, "failure", message=result.failure.message, type=result.failure.kind)
                failure.text = f"{result.failure.text()}\nat {result.file}:{result.failure.line or result.line}"
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
