"""A whole project as one IEC ST file: TYPEs, VAR_GLOBAL, the named global variable lists (st/gvl_text.py), every
POU, and the configuration.

The types and globals texts are kept as typed; ST POUs as their text, LD/FBD
POUs as their ST export (st_export). A project's configuration is written as it
is (its VAR_GLOBAL, VAR_ACCESS and VAR_CONFIG texts, ``RESOURCE name ON cpu``,
``TASK name(INTERVAL := ..., SINGLE := ..., PRIORITY := ...)``, ``PROGRAM [RETAIN]
inst WITH task : Type(in := expr, out => var);``); a project's own tasks become
one ``CONFIGURATION`` / ``RESOURCE ... ON PLC`` whose instances are named after
their programs. A project without either runs every PROGRAM in one 10 ms task
(ir/lower_configuration.py DEFAULT_TASK), and the file says so explicitly, so
another tool runs it the same way. The file reads back with
``st.project_text.source_to_project``.
"""

from __future__ import annotations

import textwrap

from ...ir.lower_configuration import DEFAULT_INTERVAL_MS, DEFAULT_TASK
from ...model import Configuration, Diagnostic, ProgramInstance, Project, Resource, Task, has_errors
from ...st.checker import check_project
from ...st.gvl_text import gvl_source
from ...st.printer import INDENT
from ...st.project_text import source_to_project
from ...st.types import typing_rules
from ...storage.st_text import compose_pou_text
from .export import StExport, st_pou, textual_sfc
from .names import Names


def export_project_st(project: Project, *, sfc_text: bool = False) -> StExport:
    """The project's complete ST text; ``source_map`` entries name the network as ``POU/network``."""
    checked = check_project(project)
    parts: list[str] = []
    source_map: list[tuple[int, str, str | None]] = []
    diagnostics: list[Diagnostic] = []
    if project.libraries:  # a .st file has no project.json to list them (docs/st.md "Vendor libraries")
        names = ", ".join(project.libraries)
        options = " ".join(f"--library {name}" for name in project.libraries)
        parts.append(f"(* Uses the vendor libraries {names}: ladderlab check/run ... {options} *)")
    if project.typing != "iec":  # nor its type rules (docs/st.md "CODESYS typing")
        parts.append(
            f"(* Checked with {project.typing.upper()} typing: ladderlab check/run ... --typing {project.typing} *)"
        )
    if project.types.strip():
        parts.append(project.types.strip("\n"))
    if project.globals.strip():
        parts.append(project.globals.strip("\n"))
    parts += [gvl_source(gvl) for gvl in project.gvls]  # after the unnamed globals: st/gvl_text.py
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
    problems = verify_text(text, project)
    return StExport("" if problems else text, [] if problems else source_map, diagnostics + problems)


def verify_text(text: str, project: Project) -> list[Diagnostic]:
    """The exported file must read back into a project (with the same vendor libraries and type rules, which the
    text names in a comment) that checks without errors; else say so."""
    with typing_rules(project.typing):  # parsed as checked: CODESYS's END_IF without ';' before a statement
        read, diagnostics = source_to_project(text, project.name)
    if read is not None:
        read = read.model_copy(update={"libraries": project.libraries, "typing": project.typing})
        diagnostics = diagnostics + check_project(read).diagnostics
    return [
        Diagnostic(
            code="EXPORT-INTERNAL", severity="error", pou=d.pou, message=f"the exported ST does not check: {d.format()}"
        )
        for d in diagnostics
        if d.severity == "error"
    ]


def configuration(project: Project, names: Names) -> str:
    """The CONFIGURATION the project runs as (its own, or one made of its tasks)."""
    if project.configuration is not None:
        return _configuration(project.configuration)
    tasks = project.tasks or [
        Task(
            name=DEFAULT_TASK,
            interval=f"T#{DEFAULT_INTERVAL_MS}ms",
            priority=0,
            programs=[p.name for p in project.pous if p.kind == "program"],
        )
    ]
    made = Configuration(
        name=names.fresh(f"{project.name}_config"),
        resources=[Resource(name=names.fresh("main_resource"), on="PLC", tasks=tasks)],
    )
    return _configuration(made)


def _configuration(config: Configuration) -> str:
    lines = [f"CONFIGURATION {config.name}", *_text(config.globals, 1)]
    for resource in config.resources:
        level = 1 if resource.name is None else 2
        if resource.name is not None:
            lines.append(f"{INDENT}RESOURCE {resource.name}" + (f" ON {resource.on}" if resource.on else ""))
        lines += _text(resource.globals, level)
        lines += [f"{INDENT * level}{_task(task)}" for task in resource.tasks]
        for task in resource.tasks:
            lines += [f"{INDENT * level}{_program(program, task.name)}" for program in task.programs]
        lines += [f"{INDENT * level}{_program(program, None)}" for program in resource.programs]
        if resource.name is not None:
            lines.append(f"{INDENT}END_RESOURCE")
    lines += _text(config.access, 1) + _text(config.config, 1)
    return "\n".join([*lines, "END_CONFIGURATION"])


def _task(task: Task) -> str:
    properties = [("INTERVAL", task.interval), ("SINGLE", task.single), ("PRIORITY", str(task.priority))]
    return f"TASK {task.name}({', '.join(f'{n} := {v}' for n, v in properties if v is not None)});"


def _program(program: str | ProgramInstance, task: str | None) -> str:
    instance = ProgramInstance(name=program, type=program) if isinstance(program, str) else program
    retain = f"{instance.retain} " if instance.retain else ""
    args = [f"{n} := {v}" for n, v in instance.inputs.items()] + [f"{n} => {v}" for n, v in instance.outputs.items()]
    with_task = f" WITH {task}" if task is not None else ""
    return (
        f"PROGRAM {retain}{instance.name}{with_task} : {instance.type}" + (f"({', '.join(args)})" if args else "") + ";"
    )


def _text(text: str, level: int) -> list[str]:
    """A configuration text (VAR blocks as typed) indented into the CONFIGURATION, blank lines around it dropped."""
    lines = textwrap.dedent(text.strip("\n")).splitlines()
    return [INDENT * level + line if line.strip() else "" for line in lines]
