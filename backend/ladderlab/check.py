"""One entry point for every diagnostic of a project, used by the CLI and the server."""

from __future__ import annotations

from .model import Diagnostic, Project
from .model.validate import validate_project


def check_project(project: Project) -> list[Diagnostic]:
    """All problems of ``project``, most fundamental first."""
    return validate_project(project)
