"""Export (ST text, PLCopen XML), PLCopen import and an LD network as IL over HTTP: thin routes over
``interchange/``.

The import body is the raw XML document (bounded by the body-size limit, which
also keeps oversize documents from reaching the parser).
"""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Query, Request, Response, status

from ..model import has_errors
from ..model.api import ImportReport, LdAsIl, ProjectSummary, SourceMapEntry, StExport
from ..model.ld import LdNetwork
from ..storage.names import check_project_name
from .context import WorkspaceDep, etag, modified_at
from .errors import ApiError, responses
from .limits import LimitsDep, check_project_size, check_room_for_project

router = APIRouter(tags=["interchange"])


@router.get("/api/projects/{name}/export/st", response_model=StExport, responses=responses(404, 422))
def export_st(
    name: str,
    workspace: WorkspaceDep,
    pou: Annotated[str | None, Query(description="one POU; default: the whole project")] = None,
    with_plants: Annotated[bool, Query(description="the whole project: keep its plants (as programs)")] = False,
    sfc_text: Annotated[bool, Query(description="SFC POUs as IEC textual SFC instead of the ST of their scan")] = False,
) -> StExport:
    """The saved project (or one POU) as IEC ST that runs identically; each exported line maps to its network.
    The whole project's control program leaves the plants out unless ``with_plants``."""
    from ..interchange.plants import for_export
    from ..interchange.st.export import export_pou_st
    from ..interchange.st.project import export_project_st

    project = workspace.load(name).project
    if pou is not None and project.pou(pou) is None:
        raise ApiError(404, f"project {name!r} has no POU {pou!r}")
    result = (
        export_pou_st(project, pou, sfc_text=sfc_text)
        if pou is not None
        else export_project_st(for_export(project, with_plants), sfc_text=sfc_text)
    )
    if has_errors(result.diagnostics):
        raise ApiError(422, "the project cannot be exported as ST until these errors are fixed", result.diagnostics)
    return StExport(
        text=result.text,
        diagnostics=result.diagnostics,
        source_map=[
            SourceMapEntry(line=line, network=network, element=element) for line, network, element in result.source_map
        ],
    )


@router.get("/api/projects/{name}/export/plcopen", response_class=Response, responses=responses(404, 422))
def export_xml(
    name: str,
    workspace: WorkspaceDep,
    with_plants: Annotated[bool, Query(description="keep the project's plants (as programs)")] = False,
) -> Response:
    """The saved project as a PLCopen TC6 v2.01 document, as a download (its plants only ``with_plants``)."""
    from ..interchange.plants import for_export
    from ..interchange.plcopen.exporter import PlcopenExportError, export_plcopen

    project = workspace.load(name).project
    try:
        data = export_plcopen(for_export(project, with_plants))
    except PlcopenExportError as error:
        raise ApiError(422, "the project cannot be exported as PLCopen XML", error.diagnostics) from None
    return Response(
        data, media_type="application/xml", headers={"Content-Disposition": f'attachment; filename="{name}.xml"'}
    )


@router.post("/api/ld/il", response_model=LdAsIl, responses=responses(422))
def ld_as_il(network: LdNetwork) -> LdAsIl:
    """One LD network as IL, for the editor's read-only "View as IL" (issue 26); stateless."""
    from ..interchange.ld_il import network_il

    made = network_il(network)
    return LdAsIl(text=made.text, reason=made.reason)


@router.post(
    "/api/import/plcopen",
    status_code=status.HTTP_201_CREATED,
    response_model=ImportReport,
    responses=responses(409, 413, 422, 429),
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {"application/xml": {"schema": {"type": "string", "description": "a PLCopen TC6 XML document"}}},
        }
    },
)
async def import_xml(
    request: Request,
    workspace: WorkspaceDep,
    limits: LimitsDep,
    response: Response,
    name: Annotated[str | None, Query(description="project name (default: the document's)")] = None,
) -> ImportReport:
    """Store a PLCopen XML document (the request body) as a new project; warnings come back with it."""
    from ..interchange.plcopen.importer import import_plcopen

    if name is not None:
        check_project_name(name)
    result = import_plcopen(await request.body(), name=name, file="upload.xml")
    if result.project is None or has_errors(result.diagnostics):
        raise ApiError(422, "the document cannot be imported", result.diagnostics)
    project = result.project
    check_project_name(project.name)
    check_room_for_project(workspace, limits)
    check_project_size(project, limits)
    revision = workspace.create(project)
    stored = workspace.load(project.name)
    response.headers.update(etag(revision))
    response.headers["Location"] = f"/api/projects/{project.name}"
    return ImportReport(
        diagnostics=result.diagnostics,
        project=ProjectSummary(
            name=project.name, revision=revision, modified=modified_at(stored.modified), pou_count=len(project.pous)
        ),
    )
