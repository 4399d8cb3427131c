"""JSON Schemas generated from the pydantic models; the browser's TypeScript types come from them."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from .api import ApiTypes
from .monitor import MonitorProtocol
from .project import Project

#: File name in shared_schema/ -> model. Later parts add theirs (e.g. the monitor protocol).
SCHEMA_MODELS: dict[str, type[BaseModel]] = {
    "project.schema.json": Project,
    "api.schema.json": ApiTypes,
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


def write_schemas(folder: Path) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name, text in schema_texts().items():
        path = folder / name
        path.write_text(text, encoding="utf-8")
        written.append(path)
    return written
