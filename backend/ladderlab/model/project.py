"""The project: what a user edits and saves (POUs, types, globals, tasks)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator, model_validator

from .fbd import FbdBody
from .ld import LdBody
from .sfc import SfcBody

PROJECT_FORMAT = "ladderlab/1"

PouKind = Literal["program", "function_block", "function"]
Language = Literal["st", "ld", "fbd", "sfc"]

BODY_TYPE_BY_LANGUAGE: dict[str, type] = {"st": str, "ld": LdBody, "fbd": FbdBody, "sfc": SfcBody}


def _strip_trailing_whitespace(value: Any) -> Any:
    """ST texts are kept as typed except trailing whitespace, which files and editors disagree on."""
    return value.rstrip() if isinstance(value, str) else value


class Pou(BaseModel):
    """A program organisation unit. ``body`` is ST text, an ``LdBody``, an ``FbdBody`` or an ``SfcBody`` per
    ``language``."""

    model_config = ConfigDict(extra="forbid")

    name: str
    kind: PouKind
    language: Language
    return_type: str | None = Field(default=None, description="Functions only: the result type.")
    declarations: str = Field(default="", description="ST text of the VAR...END_VAR blocks, as typed.")
    body: str | LdBody | FbdBody | SfcBody = ""

    _normalise_texts = field_validator("declarations", "body", mode="before")(_strip_trailing_whitespace)

    @field_validator("body", mode="wrap")
    @classmethod
    def _body_matches_language(cls, value: Any, handler: Any, info: ValidationInfo) -> Any:
        """Validate ``body`` as the type its ``language`` names, so errors point at the right shape."""
        language = info.data.get("language")
        expected = BODY_TYPE_BY_LANGUAGE.get(language)
        if expected is None:
            return handler(value)
        if expected is str:
            if not isinstance(value, str):
                raise ValueError("an ST POU's body must be a string of ST statements")
            return handler(value)
        if isinstance(value, expected):
            return value
        if not isinstance(value, dict):
            shape = "'chart'" if language == "sfc" else "'networks'"
            raise ValueError(f"an {language.upper()} POU's body must be an object with {shape}")
        return expected.model_validate(value)

    @model_validator(mode="after")
    def _empty_graphical_body(self) -> Pou:
        """A new LD/FBD POU created without a body starts with no networks (an SFC POU with an empty chart)."""
        if self.language != "st" and isinstance(self.body, str):
            self.body = BODY_TYPE_BY_LANGUAGE[self.language]()
        return self


class Task(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    interval: str = Field(default="T#10ms", description="IEC TIME literal, e.g. T#10ms.")
    priority: int = 0
    programs: list[str] = Field(default_factory=list, description="Program names, run in list order.")
    watchdog_ms: int | None = Field(
        default=None,
        ge=1,
        le=60_000,
        description="The task's time budget per scan in ms (its scan's own running time); longer is a watchdog "
        "fault. Null: the default of 100 ms (CODESYS's).",
    )


class TestFile(BaseModel):
    """A file of unit tests, ``tests/<name>.st`` in the project folder (docs/testing.md).

    Tests a teacher hides from students live in ``tests/hidden/`` and are not part of the model: the
    browser never sees them, ``ladderlab test --grade`` runs them."""

    model_config = ConfigDict(extra="forbid")
    name: str = Field(description="File name without the .st suffix (letters, digits, '_' and '-').")
    text: str = Field(default="", description="ST test text: SETUP, TEARDOWN and TEST blocks, as typed.")

    _normalise_texts = field_validator("text", mode="before")(_strip_trailing_whitespace)


class Project(BaseModel):
    model_config = ConfigDict(extra="forbid")

    name: str
    format: Literal["ladderlab/1"] = PROJECT_FORMAT
    types: str = Field(default="", description="ST text of TYPE ... END_TYPE blocks.")
    globals: str = Field(default="", description="ST text of VAR_GLOBAL ... END_VAR blocks.")
    pous: list[Pou] = Field(default_factory=list)
    tasks: list[Task] = Field(default_factory=list)
    tests: list[TestFile] = Field(default_factory=list, description="Unit test files (tests/<name>.st).")

    _normalise_texts = field_validator("types", "globals", mode="before")(_strip_trailing_whitespace)

    def pou(self, name: str) -> Pou | None:
        """The POU called ``name`` (IEC names are case-insensitive)."""
        key = name.upper()
        return next((p for p in self.pous if p.name.upper() == key), None)
