"""One entry point for every diagnostic of a project, used by the CLI and the server."""

from __future__ import annotations

from .model import Diagnostic, Project
from .model.validate import validate_project
from .st.checker import check_project as check_st


def check_project(project: Project) -> list[Diagnostic]:
    """All problems of ``project``: project structure first, then ST (declarations of every POU, ST bodies)."""
    return validate_project(project) + check_st(project).diagnostics
