"""Project-level consistency checks that need no parsing: names, kinds, return types, tasks."""

from __future__ import annotations

import re

from .diagnostics import Diagnostic
from .names import pou_name_problem, test_file_name_problem
from .project import Project

_TIME_LITERAL = re.compile(r"^(T|TIME)#-?(\d+(\.\d+)?(d|h|ms|m|s|us|ns)_?)+\Z", re.IGNORECASE)


def validate_project(project: Project) -> list[Diagnostic]:
    out: list[Diagnostic] = []
    seen: dict[str, str] = {}
    for pou in project.pous:
        problem = pou_name_problem(pou.name)
        if problem:
            out.append(Diagnostic(code="BAD-NAME", pou=pou.name, message=f"invalid POU name: {problem}"))
        key = pou.name.upper()
        if key in seen:
            out.append(
                Diagnostic(
                    code="DUPLICATE-POU",
                    pou=pou.name,
                    message=f"POU {pou.name!r} is declared twice (names ignore case: {seen[key]!r})",
                )
            )
        seen.setdefault(key, pou.name)
        if pou.kind == "function" and not pou.return_type:
            out.append(
                Diagnostic(code="MISSING-RETURN-TYPE", pou=pou.name, message=f"function {pou.name} needs a return type")
            )
        if pou.kind != "function" and pou.return_type:
            out.append(
                Diagnostic(
                    code="UNEXPECTED-RETURN-TYPE",
                    pou=pou.name,
                    message=f"only functions have a return type; {pou.name} is a {pou.kind.replace('_', ' ')}",
                )
            )
    out.extend(_validate_tasks(project))
    out.extend(_validate_tests(project))
    return out


def _validate_tests(project: Project) -> list[Diagnostic]:
    out: list[Diagnostic] = []
    seen: set[str] = set()
    for test in project.tests:
        problem = test_file_name_problem(test.name)
        if problem:
            out.append(
                Diagnostic(code="BAD-NAME", file=f"tests/{test.name}.st", message=f"invalid test file name: {problem}")
            )
        elif test.name.lower() in seen:
            out.append(
                Diagnostic(
                    code="DUPLICATE-TEST-FILE",
                    file=f"tests/{test.name}.st",
                    message=f"test file {test.name!r} is there twice",
                )
            )
        seen.add(test.name.lower())
    return out


def _validate_tasks(project: Project) -> list[Diagnostic]:
    out: list[Diagnostic] = []
    names: set[str] = set()
    for i, task in enumerate(project.tasks):
        where = f"$.tasks[{i}]"
        if task.name.upper() in names:
            out.append(
                Diagnostic(code="DUPLICATE-TASK", json_path=where, message=f"task {task.name!r} is declared twice")
            )
        names.add(task.name.upper())
        if not _TIME_LITERAL.match(task.interval.replace(" ", "")):
            out.append(
                Diagnostic(
                    code="BAD-INTERVAL",
                    json_path=f"{where}.interval",
                    message=f"task {task.name}: interval {task.interval!r} is not a TIME literal such as T#10ms",
                )
            )
        for j, program in enumerate(task.programs):
            pou = project.pou(program)
            if pou is None:
                out.append(
                    Diagnostic(
                        code="UNKNOWN-PROGRAM",
                        json_path=f"{where}.programs[{j}]",
                        message=f"task {task.name} runs {program!r}, which is not a POU of this project",
                    )
                )
            elif pou.kind != "program":
                out.append(
                    Diagnostic(
                        code="NOT-A-PROGRAM",
                        json_path=f"{where}.programs[{j}]",
                        pou=pou.name,
                        message=f"task {task.name} can only run programs; {pou.name} is a {pou.kind.replace('_', ' ')}",
                    )
                )
    return out
