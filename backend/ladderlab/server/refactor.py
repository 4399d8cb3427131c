"""Refactoring the browser's working copy: rename a name everywhere (or a function block's method or property with
its calls), list what uses a name, duplicate a POU.

Stateless like the live check: the browser sends its (unsaved) project and gets the changed project back
for a preview; nothing is stored until the user saves. The logic lives in ``st/refactor.py``.
"""

from __future__ import annotations

from fastapi import APIRouter

from ..model import Diagnostic
from ..model.api import (
    DuplicateRequest,
    MemberRenameRequest,
    ReferenceList,
    ReferencesRequest,
    RenameRequest,
    RenameResult,
)
from ..storage import NotFoundError
from .errors import ApiError, responses
from .limits import LimitsDep, check_project_size

router = APIRouter(prefix="/api/refactor", tags=["refactor"])


@router.post("/rename", response_model=RenameResult, responses=responses(413, 422))
def rename(body: RenameRequest, limits: LimitsDep) -> RenameResult:
    """The project with ``old_name`` renamed to ``new_name`` in every POU, diagram, task and test file."""
    from ..st import refactor

    check_project_size(body.project, limits)
    _refuse(refactor.new_name_problem(body.project, body.old_name, body.new_name), "$.new_name")
    project, changes = refactor.rename(body.project, body.old_name, body.new_name)
    return RenameResult(project=project, changes=changes)


@router.post("/rename-member", response_model=RenameResult, responses=responses(413, 422))
def rename_member(body: MemberRenameRequest, limits: LimitsDep) -> RenameResult:
    """The project with a function block's method or property renamed, with its overrides and every call."""
    from ..st import refactor

    check_project_size(body.project, limits)
    _refuse(refactor.member_name_problem(body.project, body.pou, body.old_name, body.new_name), "$.new_name")
    project, changes = refactor.rename_member(body.project, body.pou, body.old_name, body.new_name)
    return RenameResult(project=project, changes=changes)


@router.post("/references", response_model=ReferenceList, responses=responses(413, 422))
def references(body: ReferencesRequest, limits: LimitsDep) -> ReferenceList:
    """Every place that uses ``name`` (what deleting it would break)."""
    from ..st import refactor

    check_project_size(body.project, limits)
    return ReferenceList(references=refactor.references(body.project, body.name))


@router.post("/duplicate", response_model=RenameResult, responses=responses(404, 413, 422))
def duplicate(body: DuplicateRequest, limits: LimitsDep) -> RenameResult:
    """The project with a copy of POU ``name`` called ``new_name`` (nothing else changes)."""
    from ..st import refactor

    check_project_size(body.project, limits)
    if body.project.pou(body.name) is None:
        raise NotFoundError("POU", body.name)
    _refuse(refactor.new_name_problem(body.project, "", body.new_name), "$.new_name")
    return RenameResult(project=refactor.duplicate_pou(body.project, body.name, body.new_name), changes=[])


def _refuse(problem: str | None, path: str) -> None:
    if problem:
        raise ApiError(422, problem, [Diagnostic(code="BAD-NAME", json_path=path, message=problem)])
