"""A whole project as one IEC ST file: TYPEs, VAR_GLOBAL, every POU, and the task configuration.

The types and globals texts are kept as typed; ST POUs as their text, LD/FBD
POUs as their ST export (st_export). The tasks become ``CONFIGURATION`` /
``RESOURCE ... ON PLC`` / ``TASK name(INTERVAL := ..., PRIORITY := ...)`` /
``PROGRAM inst WITH task : Type;``. A project without tasks runs every PROGRAM
in one 10 ms task (ir/lower_project.py DEFAULT_TASK), and the file says so
explicitly, so another tool runs it the same way. The file reads back with
``st.project_text.source_to_project``.
"""

from __future__ import annotations

from ...ir.lower_project import DEFAULT_INTERVAL_MS, DEFAULT_TASK
from ...model import Diagnostic, Project, Task, has_errors
from ...st.checker import check_project
from ...st.printer import INDENT
from ...st.project_text import source_to_project
from ...storage.st_text import compose_pou_text
from .export import StExport, st_pou, textual_sfc
from .names import Names


def export_project_st(project: Project, *, sfc_text: bool = False) -> StExport:
    """The project's complete ST text; ``source_map`` entries name the network as ``POU/network``."""
    checked = check_project(project)
    parts: list[str] = []
    source_map: list[tuple[int, str, str | None]] = []
    diagnostics: list[Diagnostic] = []
    if project.types.strip():
        parts.append(project.types.strip("\n"))
    if project.globals.strip():
        parts.append(project.globals.strip("\n"))
    for pou in project.pous:
        if pou.language == "st":
            parts.append(compose_pou_text(pou).rstrip("\n"))
            continue
        if sfc_text and pou.language == "sfc":
            textual = textual_sfc(project, pou)
            diagnostics += textual.diagnostics
            if textual.text:
                parts.append(textual.text.rstrip("\n"))
            continue
        exported = st_pou(project, pou, checked)
        diagnostics += exported.diagnostics
        if exported.pou is None:
            continue
        text = compose_pou_text(exported.pou).rstrip("\n")
        first = sum(part.count("\n") + 2 for part in parts)  # parts are joined by a blank line
        body_start = text.count("\n", 0, text.index(exported.pou.body)) if exported.pou.body else 0
        source_map += [
            (first + body_start + line, f"{pou.name}/{network}", element)
            for line, network, element in exported.source_map
        ]
        parts.append(text)
    parts.append(configuration(project, Names.for_pou(checked, "")))
    if has_errors(diagnostics):
        return StExport("", [], diagnostics)
    text = "\n\n".join(parts) + "\n"
    problems = verify_text(text, project.name)
    return StExport("" if problems else text, [] if problems else source_map, diagnostics + problems)


def verify_text(text: str, name: str) -> list[Diagnostic]:
    """The exported file must read back into a project that checks without errors; else say so."""
    read, diagnostics = source_to_project(text, name)
    if read is not None:
        diagnostics = diagnostics + check_project(read).diagnostics
    return [
        Diagnostic(
            code="EXPORT-INTERNAL", severity="error", pou=d.pou, message=f"the exported ST does not check: {d.format()}"
        )
        for d in diagnostics
        if d.severity == "error"
    ]


def configuration(project: Project, names: Names) -> str:
    """``CONFIGURATION`` with one resource holding the project's tasks and the programs they run."""
    tasks = project.tasks or [
        Task(
            name=DEFAULT_TASK,
            interval=f"T#{DEFAULT_INTERVAL_MS}ms",
            priority=0,
            programs=[p.name for p in project.pous if p.kind == "program"],
        )
    ]
    lines = [
        f"CONFIGURATION {names.fresh(f'{project.name}_config')}",
        f"{INDENT}RESOURCE {names.fresh('main_resource')} ON PLC",
    ]
    lines += [
        f"{INDENT * 2}TASK {task.name}(INTERVAL := {task.interval}, PRIORITY := {task.priority});" for task in tasks
    ]
    lines += [
        f"{INDENT * 2}PROGRAM {program} WITH {task.name} : {program};" for task in tasks for program in task.programs
    ]
    return "\n".join(lines + [f"{INDENT}END_RESOURCE", "END_CONFIGURATION"])
