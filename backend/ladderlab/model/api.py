"""Shapes of the HTTP API's JSON bodies that the browser reads (typed from the generated schema)."""

from __future__ import annotations

from datetime import datetime

from pydantic import BaseModel


class ProjectSummary(BaseModel):
    """One row of ``GET /api/projects``."""

    name: str
    revision: str
    modified: datetime
    pou_count: int


class ApiTypes(BaseModel):
    """Container so every API shape lands in one schema file (``api.schema.json``)."""

    project_summary: ProjectSummary
