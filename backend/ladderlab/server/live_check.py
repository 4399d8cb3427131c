"""Checking a project the browser has not saved: the ST editor's live diagnostics.

The editor sends its working copy while the user types; the answer is exactly what
``POST /api/projects/{name}/check`` would say once that copy is saved (the same ``check_report``),
and nothing is stored. A body that is no project is refused by FastAPI's validation with a
located 422, like a save. Checks run in build processes under a time and memory limit
(``simulation/builds.py``); a check that hits one answers with a diagnostic naming it.
"""

from __future__ import annotations

from fastapi import APIRouter, FastAPI, Request

from ..model import Diagnostic, Project
from ..model.api import CheckReport
from ..simulation.builds import BUILD_LIMIT, BuildError
from .context import registry_of
from .errors import responses
from .limits import LimitsDep, check_project_size

router = APIRouter(prefix="/api", tags=["check"])


def check_report(app: FastAPI, project: Project) -> CheckReport:
    """Every diagnostic of ``project`` (model validation, declarations, ST, LD/FBD), from a build process."""
    try:
        diagnostics = registry_of(app).check(project)
    except BuildError as error:
        diagnostics = [Diagnostic(code=BUILD_LIMIT, message=error.message)]
    return CheckReport(diagnostics=diagnostics)


@router.post("/check", response_model=CheckReport, responses=responses(413, 422))
def check_unsaved(project: Project, limits: LimitsDep, request: Request) -> CheckReport:
    """Every diagnostic of ``project`` as sent (model validation, declarations, ST, LD/FBD)."""
    check_project_size(project, limits)  # the same bound as a save: checking costs like building
    return check_report(request.app, project)
