"""What the ST and PLCopen exports of a project hold: the control program, with its plants only when asked.

A plant models the process for the lab bench; a real PLC runs the control program alone, so
exports leave the plants (and the panels, which no other tool reads) out. ``with_plants`` keeps
them as PROGRAMs run by a task ``PLANTS`` at priority 0 with the shortest control interval, the
closest another IEC runtime comes to LadderLab's plant task (which runs before the control tasks
of every scan).
"""

from __future__ import annotations

from ..iec.literals import decode_duration
from ..model import Project, Task
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
    control = [p.name for p in project.pous if p.kind == "program"]
    tasks = list(project.tasks) or (
        [Task(name=_DEFAULT_TASK, interval=_DEFAULT_INTERVAL, priority=0, programs=control)] if control else []
    )
    interval = min((task.interval for task in tasks), key=_milliseconds, default=_DEFAULT_INTERVAL)
    plant_task = Task(name=PLANT_TASK, interval=interval, priority=0, programs=[p.name for p in plants])
    pous = [p.model_copy(update={"kind": "program"}) if p.kind == "plant" else p for p in project.pous]
    return project.model_copy(update={"pous": pous, "tasks": [plant_task, *tasks], "panels": []})


def _milliseconds(interval: str) -> float:
    try:
        return float(decode_duration(interval.replace(" ", "")))
    except (ValueError, IndexError):
        return float("inf")
