"""JSON Schemas of the project files and the websocket protocol, generated from the pydantic models.

The HTTP API's shapes are in the server's OpenAPI document (``cli/shared.py`` writes both to shared_schema/)."""

from __future__ import annotations

import json
from typing import Any

from pydantic import BaseModel

from .monitor import MonitorProtocol
from .project import Project

#: File name in shared_schema/ -> model.
SCHEMA_MODELS: dict[str, type[BaseModel]] = {
    "project.schema.json": Project,
    "monitor.schema.json": MonitorProtocol,
}


def schema_of(model: type[BaseModel]) -> dict[str, Any]:
    schema = model.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema


def schema_texts() -> dict[str, str]:
    """File name -> the exact text that belongs in shared_schema/."""
    return {
        name: json.dumps(schema_of(model), indent=2, sort_keys=True) + "\n" for name, model in SCHEMA_MODELS.items()
    }
