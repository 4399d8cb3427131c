"""Project routes: list, create, read, save (whole or one POU), rename, delete, check.

Every save names the revision it is based on (``If-Match``); storage compares it under the
project's lock, so of two concurrent saves from the same revision exactly one wins and the
other gets a 409 with both revisions.
"""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Header, Request, Response, status

from ..examples import EXAMPLES_DIR
from ..model import Diagnostic, Pou, Project
from ..model.api import CheckReport, CreateProject, ProjectDocument, ProjectSummary, RenameProject, SaveResult
from ..model.validate import validate_project
from ..storage import ConflictError, NotFoundError, Workspace
from ..storage.names import check_project_name
from ..storage.project_folder import PROJECT_FILE, read_project_folder
from .context import WorkspaceDep, etag, modified_at, revision_from_header
from .errors import ApiError, responses
from .limits import Limits, LimitsDep, check_project_size, check_room_for_project
from .live_check import check_report

router = APIRouter(prefix="/api/projects", tags=["projects"])

IfMatch = Annotated[str | None, Header(description="The revision this change is based on (from ETag).")]

#: Problems that would lose data if stored: a POU name that is no file name, or two POUs in one file.
_UNSTORABLE = {"BAD-NAME", "DUPLICATE-POU"}


@router.get("", response_model=list[ProjectSummary])
def list_projects(workspace: WorkspaceDep) -> list[ProjectSummary]:
    return [
        ProjectSummary(
            name=info.name,
            revision=info.revision,
            pou_count=info.pou_count,
            modified=modified_at(info.modified),
            problems=info.problems,
        )
        for info in workspace.list()
    ]


@router.post(
    "", status_code=status.HTTP_201_CREATED, response_model=ProjectSummary, responses=responses(409, 413, 422, 429)
)
def create_project(
    body: CreateProject, workspace: WorkspaceDep, limits: LimitsDep, response: Response
) -> ProjectSummary:
    """An empty project, or a copy of a shipped example under the new name."""
    check_project_name(body.name)
    check_room_for_project(workspace, limits)
    project = _example(body.example, body.name) if body.example else Project(name=body.name)
    revision = workspace.create(project)
    stored = workspace.load(body.name)
    response.headers.update(etag(revision))
    response.headers["Location"] = f"/api/projects/{body.name}"
    return ProjectSummary(
        name=body.name, revision=revision, modified=modified_at(stored.modified), pou_count=len(project.pous)
    )


def _example(example: str, name: str) -> Project:
    available = (
        sorted(d.name for d in EXAMPLES_DIR.iterdir() if (d / PROJECT_FILE).is_file()) if EXAMPLES_DIR.is_dir() else []
    )
    if example not in available:
        raise ApiError(422, f"unknown example {example!r}; available: {', '.join(available) or 'none'}")
    return read_project_folder(EXAMPLES_DIR / example).model_copy(update={"name": name})


@router.get("/{name}", response_model=ProjectDocument, responses=responses(404, 422))
def get_project(name: str, workspace: WorkspaceDep, response: Response) -> ProjectDocument:
    stored = workspace.load(name)
    response.headers.update(etag(stored.revision))
    return ProjectDocument(
        name=name, revision=stored.revision, modified=modified_at(stored.modified), project=stored.project
    )


@router.put("/{name}", response_model=SaveResult, responses=responses(404, 409, 413, 422, 428))
def save_project(
    name: str,
    project: Project,
    workspace: WorkspaceDep,
    limits: LimitsDep,
    response: Response,
    if_match: IfMatch = None,
) -> SaveResult:
    """Replace the whole project; its ``name`` must be the URL's (renaming has its own route)."""
    base = _required(if_match)
    if project.name != name:
        raise ApiError(
            422,
            f"the project in the body is called {project.name!r} but the URL names {name!r}; "
            "use POST /api/projects/{name}/rename to rename",
            [Diagnostic(code="BAD-REQUEST", json_path="$.name", message="does not match the URL")],
        )
    return _save(workspace, limits, project, base, response)


@router.put("/{name}/pous/{pou}", response_model=SaveResult, responses=responses(404, 409, 413, 422, 428))
def save_pou(
    name: str,
    pou: str,
    body: Pou,
    workspace: WorkspaceDep,
    limits: LimitsDep,
    response: Response,
    if_match: IfMatch = None,
) -> SaveResult:
    """Replace one POU (matched ignoring case, as IEC names are), or add it at the end when it is new."""
    base = _required(if_match)
    if body.name != pou:
        raise ApiError(
            422,
            f"the POU in the body is called {body.name!r} but the URL names {pou!r}",
            [Diagnostic(code="BAD-REQUEST", json_path="$.name", message="does not match the URL")],
        )
    project = _at_revision(workspace, name, base)
    pous = list(project.pous)
    index = next((i for i, p in enumerate(pous) if p.name.upper() == pou.upper()), None)
    if index is None:
        pous.append(body)
    else:
        pous[index] = body
    return _save(workspace, limits, project.model_copy(update={"pous": pous}), base, response)


@router.delete("/{name}/pous/{pou}", response_model=SaveResult, responses=responses(404, 409, 422, 428))
def delete_pou(
    name: str, pou: str, workspace: WorkspaceDep, limits: LimitsDep, response: Response, if_match: IfMatch = None
) -> SaveResult:
    base = _required(if_match)
    project = _at_revision(workspace, name, base)
    if project.pou(pou) is None:
        raise NotFoundError("POU", pou)
    pous = [p for p in project.pous if p.name.upper() != pou.upper()]
    return _save(workspace, limits, project.model_copy(update={"pous": pous}), base, response)


@router.post("/{name}/rename", response_model=ProjectSummary, responses=responses(404, 409, 422))
def rename_project(
    name: str, body: RenameProject, workspace: WorkspaceDep, response: Response, if_match: IfMatch = None
) -> ProjectSummary:
    """Rename the project's folder and its ``name``; ``If-Match`` is optional here."""
    base = revision_from_header(if_match) if if_match is not None else None
    revision = workspace.rename(name, body.new_name, base)
    stored = workspace.load(body.new_name)
    response.headers.update(etag(revision))
    return ProjectSummary(
        name=body.new_name, revision=revision, modified=modified_at(stored.modified), pou_count=len(stored.project.pous)
    )


@router.delete(
    "/{name}", status_code=status.HTTP_204_NO_CONTENT, response_class=Response, responses=responses(404, 409, 422)
)
def delete_project(name: str, workspace: WorkspaceDep, if_match: IfMatch = None) -> Response:
    """Delete the project folder; with ``If-Match`` only if nobody saved since that revision."""
    workspace.delete(name, revision_from_header(if_match) if if_match is not None else None)
    return Response(status_code=status.HTTP_204_NO_CONTENT)


@router.post("/{name}/check", response_model=CheckReport, responses=responses(404, 422))
def check(name: str, workspace: WorkspaceDep, request: Request) -> CheckReport:
    """Every diagnostic of the saved project (model validation, declarations, ST; LD/FBD via check.py)."""
    return check_report(request.app, workspace.load(name).project)


def _required(if_match: str | None) -> str:
    if if_match is None or not if_match.strip():
        raise ApiError(
            428,
            "this change needs an If-Match header with the revision it is based on "
            "(the ETag of GET /api/projects/{name})",
        )
    return revision_from_header(if_match)


def _at_revision(workspace: Workspace, name: str, base: str) -> Project:
    """The stored project, if it is still at ``base`` (else the 409 comes now, not after building the change)."""
    stored = workspace.load(name)
    if stored.revision != base:
        raise ConflictError(name, base, stored.revision)
    return stored.project


def _save(workspace: Workspace, limits: Limits, project: Project, base: str, response: Response) -> SaveResult:
    unstorable = [d for d in validate_project(project) if d.code in _UNSTORABLE]
    if unstorable:
        raise ApiError(422, "the project cannot be stored: " + "; ".join(d.message for d in unstorable), unstorable)
    check_project_size(project, limits)
    revision = workspace.save(project, base)
    response.headers.update(etag(revision))
    return SaveResult(revision=revision, modified=modified_at(workspace.load(project.name).modified))
