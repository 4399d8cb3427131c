"""The project: what a user edits and saves (POUs, types, globals, tasks)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from .fbd import FbdBody
from .ld import LdBody

PROJECT_FORMAT = "ladderlab/1"

PouKind = Literal["program", "function_block", "function"]
Language = Literal["st", "ld", "fbd"]

BODY_TYPE_BY_LANGUAGE: dict[str, type] = {"st": str, "ld": LdBody, "fbd": FbdBody}


class Pou(BaseModel):
    """A program organisation unit. ``body`` is ST text, an ``LdBody`` or an ``FbdBody`` per ``language``."""

    model_config = ConfigDict(extra="forbid")

    name: str
    kind: PouKind
    language: Language
    return_type: str | None = Field(default=None, description="Functions only: the result type.")
    declarations: str = Field(default="", description="ST text of the VAR...END_VAR blocks, as typed.")
    body: str | LdBody | FbdBody

    @model_validator(mode="before")
    @classmethod
    def _body_matches_language(cls, data: Any) -> Any:
        """Parse ``body`` as the type its ``language`` names, so errors point at the right shape."""
        if not isinstance(data, dict):
            return data
        language = data.get("language")
        body = data.get("body")
        if language == "st":
            if "body" not in data:
                return {**data, "body": ""}
            if not isinstance(body, str):
                raise ValueError("an ST POU's body must be a string of ST statements")
        elif language in ("ld", "fbd"):
            if "body" not in data:
                return {**data, "body": {"networks": []}}
            expected = BODY_TYPE_BY_LANGUAGE[language]
            if isinstance(body, dict):
                return {**data, "body": expected.model_validate(body)}
            if not isinstance(body, expected):
                raise ValueError(f"an {language.upper()} POU's body must be an object with 'networks'")
        return data


class Task(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    interval: str = Field(default="T#10ms", description="IEC TIME literal, e.g. T#10ms.")
    priority: int = 0
    programs: list[str] = Field(default_factory=list, description="Program names, run in list order.")


class Project(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    format: Literal["ladderlab/1"] = PROJECT_FORMAT
    types: str = Field(default="", description="ST text of TYPE ... END_TYPE blocks.")
    globals: str = Field(default="", description="ST text of VAR_GLOBAL ... END_VAR blocks.")
    pous: list[Pou] = Field(default_factory=list)
    tasks: list[Task] = Field(default_factory=list)

    def pou(self, name: str) -> Pou | None:
        """The POU called ``name`` (IEC names are case-insensitive)."""
        key = name.upper()
        return next((p for p in self.pous if p.name.upper() == key), None)
