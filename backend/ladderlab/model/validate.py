"""Project-level consistency checks that need no parsing: names, kinds, return types, tasks."""

from __future__ import annotations

import re

from .diagnostics import Diagnostic
from .names import pou_name_problem, test_file_name_problem
from .project import ProgramInstance, Project, Task

#: The task that runs the plants (engine/tasks.py uses the same name).
PLANT_TASK = "PLANTS"
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
    """Tasks of either form: task names once, an INTERVAL and/or a SINGLE, programs that are PROGRAMs, instance
    names once (CFG-04..06)."""
    out: list[Diagnostic] = []
    if project.configuration is not None and project.tasks:
        out.append(
            Diagnostic(
                code="TASKS-AND-CONFIGURATION",
                json_path="$.tasks",
                message="a project with a configuration keeps its tasks in the configuration's resources, not in tasks",
            )
        )
    places: list[tuple[str, Task]] = [(f"$.tasks[{i}]", task) for i, task in enumerate(project.tasks)]
    unscheduled: list[tuple[str, ProgramInstance]] = []
    if project.configuration is not None:
        for r, resource in enumerate(project.configuration.resources):
            where = f"$.configuration.resources[{r}]"
            places += [(f"{where}.tasks[{i}]", task) for i, task in enumerate(resource.tasks)]
            unscheduled += [(f"{where}.programs[{j}]", instance) for j, instance in enumerate(resource.programs)]
    names: set[str] = set()
    instances: dict[str, str] = {}
    if project.configuration is not None:  # each plant has its instance, named after it, in the plant task
        instances.update((pou.name.upper(), "the plant task") for pou in project.pous if pou.kind == "plant")
    for where, task in places:
        if task.name.upper() in names:
            out.append(
                Diagnostic(code="DUPLICATE-TASK", json_path=where, message=f"task {task.name!r} is declared twice")
            )
        names.add(task.name.upper())
        if task.name.upper() == PLANT_TASK:
            out.append(
                Diagnostic(
                    code="RESERVED-TASK",
                    json_path=f"{where}.name",
                    message=f"the task name {PLANT_TASK} is reserved for the plant task; choose another name",
                )
            )
        out.extend(_validate_timing(task, where))
        for j, program in enumerate(task.programs):
            out.extend(_validate_instance(project, program, f"{where}.programs[{j}]", f"task {task.name}", instances))
    for where, instance in unscheduled:
        out.extend(_validate_instance(project, instance, where, "the resource", instances))
    return out


def _validate_timing(task: Task, where: str) -> list[Diagnostic]:
    if task.interval is None and not task.single:
        return [
            Diagnostic(
                code="BAD-INTERVAL",
                json_path=f"{where}.interval",
                message=f"task {task.name} needs an INTERVAL (cyclic) or a SINGLE variable (on its rising edges)",
            )
        ]
    if task.interval is not None and not _TIME_LITERAL.match(task.interval.replace(" ", "")):
        return [
            Diagnostic(
                code="BAD-INTERVAL",
                json_path=f"{where}.interval",
                message=f"task {task.name}: interval {task.interval!r} is not a TIME literal such as T#10ms",
            )
        ]
    return []


def _validate_instance(
    project: Project, program: str | ProgramInstance, where: str, runner: str, instances: dict[str, str]
) -> list[Diagnostic]:
    """A task's program: a PROGRAM of the project; an instance's name used once in the whole configuration."""
    name, type_name = (program, program) if isinstance(program, str) else (program.name, program.type)
    out = []
    where_type = where if isinstance(program, str) else f"{where}.type"
    pou = project.pou(type_name)
    if pou is None:
        out.append(
            Diagnostic(
                code="UNKNOWN-PROGRAM",
                json_path=where_type,
                message=f"{runner} runs {type_name!r}, which is not a POU of this project",
            )
        )
    elif pou.kind != "program":
        why = (
            "a plant: plants run in the plant task, before the control tasks of every scan"
            if pou.kind == "plant"
            else f"a {pou.kind.replace('_', ' ')}"
        )
        out.append(
            Diagnostic(
                code="NOT-A-PROGRAM",
                json_path=where_type,
                pou=pou.name,
                message=f"{runner} can only run programs; {pou.name} is {why}",
            )
        )
    key = name.upper()
    if key in instances:
        out.append(
            Diagnostic(
                code="DUPLICATE-INSTANCE",
                json_path=where,
                message=f"the program instance {name} is run twice ({instances[key]} and {runner}): "
                "an instance runs in one task only; declare a second instance to run the program twice",
            )
        )
    instances.setdefault(key, runner)
    return out
