"""``GET /api/library``: the box picker's catalogue (simulation/library.py)."""

from __future__ import annotations

from fastapi import APIRouter, Query

from ..model.api import LibraryEntry
from .context import WorkspaceDep
from .errors import responses

router = APIRouter(prefix="/api/library", tags=["library"])


@router.get("", response_model=list[LibraryEntry], responses=responses(404, 422))
def get_library(
    workspace: WorkspaceDep,
    project: str | None = Query(default=None, description="Add this project's functions and FBs."),
) -> list[LibraryEntry]:
    from ..simulation.library import standard_entries, user_entries

    entries = list(standard_entries())
    if project is not None:
        entries += user_entries(workspace.load(project).project)
    return entries
