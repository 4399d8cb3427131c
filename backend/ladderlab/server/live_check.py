"""Checking a project the browser has not saved: the ST editor's live diagnostics.

The editor sends its working copy while the user types; the answer is exactly what
``POST /api/projects/{name}/check`` would say once that copy is saved (the same ``check_project``),
and nothing is stored. A body that is no project is refused by FastAPI's validation with a
located 422, like a save.
"""

from __future__ import annotations

from fastapi import APIRouter

from ..model import Project
from ..model.api import CheckReport
from ..simulation.check import check_project
from .errors import responses
from .limits import LimitsDep, check_project_size

router = APIRouter(prefix="/api", tags=["check"])


@router.post("/check", response_model=CheckReport, responses=responses(413, 422))
def check_unsaved(project: Project, limits: LimitsDep) -> CheckReport:
    """Every diagnostic of ``project`` as sent (model validation, declarations, ST, LD/FBD)."""
    check_project_size(project, limits)  # the same bound as a save: checking costs like building
    return CheckReport(diagnostics=check_project(project))
