"""``GET /api/projects/{name}/xref``: the cross-reference list of the saved project (simulation/xref.py)."""

from __future__ import annotations

from fastapi import APIRouter

from ..model.xref import XrefList
from ..simulation.xref import cross_reference
from .context import WorkspaceDep
from .errors import responses

router = APIRouter(prefix="/api/projects", tags=["xref"])


@router.get("/{name}/xref", response_model=XrefList, responses=responses(404, 422))
def get_xref(name: str, workspace: WorkspaceDep) -> XrefList:
    """Every variable and direct address: where it is declared, read, written and (FB instances) called."""
    return cross_reference(workspace.load(name).project)
