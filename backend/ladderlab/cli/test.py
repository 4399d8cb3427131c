"""``ladderlab test PROJECT...``: run a project's unit tests (docs/testing.md) and report them.

Exit 0 when every test passed, 1 when one failed, 2 when a test file does not compile (its located
diagnostics are printed) or a project cannot be loaded. ``--grade`` scores each PROJECT as an exercise
(hidden tests included) and prints one JSON line per exercise instead; it exits 0 once every exercise is
graded.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ..storage import load_project_path
from ..storage.atomic import write_atomic
from ..testing import DEFAULT_SCAN_BUDGET
from .encoding import add_encoding_option, encoding_of

if TYPE_CHECKING:  # the test runner imports the compiler: imported when a command runs tests (issue 27)
    from ..testing.run import Options


def add_test_command(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    test = sub.add_parser("test", help="run the project's unit tests (tests/*.st) and report them")
    test.add_argument("projects", nargs="+", type=Path, metavar="PROJECT", help="project folder or project .json file")
    add_encoding_option(test)
    test.add_argument("--filter", default=None, metavar="PATTERN", help="only tests whose name matches (glob or part)")
    test.add_argument("--format", choices=["text", "jsonl", "junit"], default="text")
    test.add_argument("-o", "--output", type=Path, default=None, metavar="FILE", help="write the report to FILE")
    test.add_argument("--coverage", action="store_true", help="report what the tests never executed or energised")
    test.add_argument(
        "--coverage-json", type=Path, default=None, metavar="FILE", help="with --coverage: write it as JSON to FILE"
    )
    test.add_argument("--grade", action="store_true", help="grade each PROJECT as an exercise, hidden tests included")
    test.add_argument("--max-scans", type=int, default=DEFAULT_SCAN_BUDGET, metavar="N", help="scan budget per test")
    test.add_argument("--jobs", type=int, default=None, metavar="N", help="worker processes (default: one per core)")
    test.add_argument(
        "--memory-limit", type=int, default=2048, metavar="MB", help="memory of each worker process (default 2048)"
    )
    test.set_defaults(func=run_test_command)


def run_test_command(args: argparse.Namespace) -> int:
    from ..testing.report import jsonl_report, junit_report, result_lines, text_report
    from ..testing.run import Options
    from ..testing.suite import run_suite, suite_files

    if args.max_scans < 1:
        print("ladderlab test: --max-scans must be at least 1", file=sys.stderr)
        return 2
    options = Options(scan_budget=args.max_scans, coverage=args.coverage)
    if args.grade:
        return _grade(args, options)
    if len(args.projects) != 1:
        print("ladderlab test: give one PROJECT (several only with --grade)", file=sys.stderr)
        return 2
    folder = args.projects[0]
    project = load_project_path(folder, encoding_of(args))
    files = suite_files(project, folder if folder.is_dir() else None)
    live = args.format == "text" and args.output is None and sys.stdout.isatty()
    outcome = run_suite(
        project,
        files,
        options,
        pattern=args.filter,
        jobs=args.jobs,
        memory_limit_mb=args.memory_limit,
        progress=(lambda result: print("\n".join(result_lines(result)), flush=True)) if live else None,
    )
    names = {p.name.upper(): p.name for p in project.pous}
    coverage_text = outcome.coverage.text(names) if outcome.coverage is not None else None
    if outcome.coverage is not None and args.coverage_json is not None:
        write_atomic(args.coverage_json, (json.dumps(outcome.coverage.report(names), indent=2) + "\n").encode())
    if args.format == "jsonl":
        report = jsonl_report(outcome)
        if outcome.coverage is not None:
            report += json.dumps({"coverage": outcome.coverage.report(names)}) + "\n"
    elif args.format == "junit":
        report = junit_report(outcome, project.name)
    else:
        report = text_report(outcome, coverage_text)
    if args.output is not None:
        write_atomic(args.output, report.encode("utf-8"))
        if args.format != "text":
            print(text_report(outcome, coverage_text), end="")
    else:
        print(report, end="")
    return outcome.exit_code


def _grade(args: argparse.Namespace, options: Options) -> int:
    from ..testing.grade import grade
    from ..testing.suite import run_suite, suite_files

    lines = []
    for folder in args.projects:
        project = load_project_path(folder, encoding_of(args))
        files = suite_files(project, folder if folder.is_dir() else None, grade=True, encoding=encoding_of(args))
        outcome = run_suite(
            project, files, options, pattern=args.filter, jobs=args.jobs, memory_limit_mb=args.memory_limit
        )
        for file in outcome.files:
            for diagnostic in file.diagnostics:
                if diagnostic.severity == "error":
                    print(diagnostic.format(), file=sys.stderr)
        lines.append(json.dumps(grade(project.name, files, outcome)))
    report = "".join(line + "\n" for line in lines)
    if args.output is not None:
        write_atomic(args.output, report.encode("utf-8"))
    else:
        print(report, end="")
    return 0
