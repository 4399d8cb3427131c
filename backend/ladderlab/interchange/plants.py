"""What the ST and PLCopen exports of a project hold: the control program, with its plants only when asked.

A plant models the process for the lab bench; a real PLC runs the control program alone, so
exports leave the plants (and the panels, which no other tool reads) out. ``with_plants`` keeps
them as PROGRAMs run by a task ``PLANTS`` at priority 0 with the shortest control interval, the
closest another IEC runtime comes to LadderLab's plant task (which runs before the control tasks
of every scan).
"""

from __future__ import annotations

from ..iec.literals import decode_duration
from ..model import Project, Resource, Task
from ..model.validate import PLANT_TASK

#: The interval of the default task (ir/lower_project.py: DEFAULT_TASK runs every PROGRAM every 10 ms).
_DEFAULT_INTERVAL = "T#10ms"
_DEFAULT_TASK = "DEFAULT"


def for_export(project: Project, with_plants: bool = False) -> Project:
    """The project an export writes: without plants and panels, or with the plants as programs of their own task."""
    plants = [pou for pou in project.pous if pou.kind == "plant"]
    if not plants:
        return project.model_copy(update={"panels": []})
    if not with_plants:
        return project.model_copy(update={"pous": [p for p in project.pous if p.kind != "plant"], "panels": []})
    pous = [p.model_copy(update={"kind": "program"}) if p.kind == "plant" else p for p in project.pous]
    names = [p.name for p in plants]
    config = project.configuration
    if config is not None:  # the plant task goes into the first resource, beside the configuration's tasks
        resources = list(config.resources) or [Resource()]
        first = resources[0]
        resources[0] = first.model_copy(update={"tasks": [_plant_task(config.tasks(), names), *first.tasks]})
        configuration = config.model_copy(update={"resources": resources})
        return project.model_copy(update={"pous": pous, "configuration": configuration, "panels": []})
    control = [p.name for p in project.pous if p.kind == "program"]
    tasks = list(project.tasks) or (
        [Task(name=_DEFAULT_TASK, interval=_DEFAULT_INTERVAL, priority=0, programs=control)] if control else []
    )
    return project.model_copy(update={"pous": pous, "tasks": [_plant_task(tasks, names), *tasks], "panels": []})


def _plant_task(tasks: list[Task], plants: list[str]) -> Task:
    """The plants' task: priority 0 at the shortest cyclic interval of the control tasks (10 ms without one)."""
    cyclic = [task.interval for task in tasks if task.interval is not None]
    interval = min(cyclic, key=_milliseconds, default=_DEFAULT_INTERVAL)
    return Task(name=PLANT_TASK, interval=interval, priority=0, programs=plants)


def _milliseconds(interval: str) -> float:
    try:
        return float(decode_duration(interval.replace(" ", "")))
    except (ValueError, IndexError):
        return float("inf")
