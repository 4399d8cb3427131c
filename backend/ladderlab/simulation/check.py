"""One entry point for every diagnostic of a project, used by the CLI and the server."""

from __future__ import annotations

from ..engine.compile import CompileError, compile_program
from ..ir.lower_project import lower_project
from ..model import Diagnostic, Project
from .build import panel_diagnostics


def check_project(project: Project) -> list[Diagnostic]:
    """All problems of ``project``: its structure, ST (declarations of every POU, ST bodies), the LD/FBD networks
    and the bindings of its panels.

    The LD/FBD networks are validated by lowering them, so ``check`` finds exactly what would stop a build; a
    project with panels is compiled too, as its bindings are resolved against the compiled program."""
    lowered = lower_project(project)
    if not project.panels or lowered.program is None:
        return lowered.diagnostics
    try:
        compiled = compile_program(lowered.program, "fast")
    except CompileError as error:
        return lowered.diagnostics + error.diagnostics
    return lowered.diagnostics + panel_diagnostics(project, compiled)
