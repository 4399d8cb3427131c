"""``GET /api/projects/{name}/xref``: the cross-reference list of the saved project (simulation/xref.py), and
``GET /api/projects/{name}/document``: what the print view draws (simulation/document.py)."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Query

from ..model.api import PrintDocument
from ..model.xref import XrefList
from ..storage import NotFoundError
from .context import WorkspaceDep
from .errors import responses

router = APIRouter(prefix="/api/projects", tags=["xref"])


@router.get("/{name}/xref", response_model=XrefList, responses=responses(404, 422))
def get_xref(name: str, workspace: WorkspaceDep) -> XrefList:
    """Every variable and direct address: where it is declared, read, written and (FB instances) called."""
    from ..simulation.xref import cross_reference

    return cross_reference(workspace.load(name).project)


@router.get("/{name}/document", response_model=PrintDocument, responses=responses(404, 422))
def get_document(name: str, workspace: WorkspaceDep, pou: Annotated[list[str] | None, Query()] = None) -> PrintDocument:
    """What the print view draws: the saved project (or the POUs named by ``pou``, repeatable), its revision,
    each POU's declarations, the block catalogue and the cross-reference list."""
    from ..simulation.document import UnknownPou, print_document

    try:
        return print_document(workspace.load(name).project, pou)
    except UnknownPou as error:
        raise NotFoundError("POU", ", ".join(pou or [])) from error
