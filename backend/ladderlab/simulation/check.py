"""One entry point for every diagnostic of a project, used by the CLI and the server."""

from __future__ import annotations

from ..ir.lower_project import lower_project
from ..model import Diagnostic, Project


def check_project(project: Project) -> list[Diagnostic]:
    """All problems of ``project``: its structure, ST (declarations of every POU, ST bodies) and the LD/FBD networks.

    The LD/FBD networks are validated by lowering them, so ``check`` finds exactly what would stop a build.
    """
    return lower_project(project).diagnostics
