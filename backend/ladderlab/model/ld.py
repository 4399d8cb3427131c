"""Ladder diagram model: networks as series/parallel lists of elements.

A series list runs from the left rail to the right rail; ``parallel`` ORs its
branches. There are no stored coordinates: the editor computes the layout, so
every edit reflows cleanly and the files diff well in git.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Field, model_validator

from .. import limits
from .base import Model

ContactMode = Literal["no", "nc", "p", "n"]
CoilMode = Literal["normal", "negated", "set", "reset", "p", "n"]
CompareOp = Literal["GT", "GE", "EQ", "LE", "LT", "NE"]


class _Element(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1, description="Unique within the POU; the probe id for live power flow.")


class Contact(_Element):
    type: Literal["contact"] = "contact"
    var: str = Field(description="ST operand text of a BOOL variable, e.g. Start or %IX0.1.")
    mode: ContactMode = "no"


class Compare(_Element):
    type: Literal["compare"] = "compare"
    op: CompareOp
    left: str
    right: str


class Coil(_Element):
    type: Literal["coil"] = "coil"
    var: str
    mode: CoilMode = "normal"


class Parallel(_Element):
    type: Literal["parallel"] = "parallel"
    branches: list[list[LdElement]] = Field(description="Two or more series lists, ORed.")


class Box(_Element):
    type: Literal["box"] = "box"
    call: str = Field(description="Function or function block type name, e.g. TON or ADD.")
    instance: str | None = Field(default=None, description="FB instance variable (function blocks only).")
    inputs: dict[str, str | list[LdElement]] = Field(
        default_factory=dict,
        description="Formal input name -> operand text, or a series list fed from the left rail.",
    )
    outputs: dict[str, str] = Field(default_factory=dict, description="Formal output name -> variable.")
    en: bool = False


class Jump(_Element):
    type: Literal["jump"] = "jump"
    target: str


class Return(_Element):
    type: Literal["return"] = "return"


# Parallel and Box name LdElement before it exists: their validators, built at first use (model/base.py), find it here
LdElement = Annotated[
    Contact | Compare | Coil | Parallel | Box | Jump | Return,
    Field(discriminator="type"),
]


class LdNetwork(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1)
    label: str | None = None
    comment: str | None = None
    elements: list[LdElement] = Field(default_factory=list)

    @model_validator(mode="before")
    @classmethod
    def _not_too_deep(cls, data: Any) -> Any:
        """Branches nested deeper than ``limits.DIAGRAM_DEPTH`` are refused before they are validated (they
        saved, then could not be sent back: issue 18). Measured on the raw data, without recursion."""
        if isinstance(data, dict):
            deep = _deepest(data.get("elements"))
            if deep is not None:
                raise ValueError(limits.DIAGRAM_DEPTH.too_deep(f"element {deep!r}"))
        return data


class LdBody(Model):
    model_config = ConfigDict(extra="forbid")

    networks: list[LdNetwork] = Field(default_factory=list)

    def calls(self) -> set[str]:
        """The names (upper case) of the functions and FB types the boxes call: the body's edges of the call graph."""
        boxes = (e for n in self.networks for e in walk(n.elements) if e.type == "box")  # (the tag: see walk)
        return {box.call.upper() for box in boxes}


def _deepest(elements: Any) -> str | None:
    """The id of the first element (in raw data) whose parallels or box inputs cross the nesting limit."""
    limit = limits.DIAGRAM_DEPTH.value
    todo = [(elements, 0)]
    while todo:
        series, depth = todo.pop()
        if not isinstance(series, list):
            continue
        for element in series:
            if not isinstance(element, dict):
                continue
            nested = element.get("branches") if element.get("type") == "parallel" else None
            inputs = element.get("inputs") if element.get("type") == "box" else None
            children = list(nested) if isinstance(nested, list) else []
            children += [v for v in inputs.values() if isinstance(v, list)] if isinstance(inputs, dict) else []
            if children and depth + 1 > limit:
                return str(element.get("id"))
            todo.extend((child, depth + 1) for child in children)
    return None


def walk(elements: list[LdElement]) -> list[LdElement]:
    """Every element of a series list, nested ones (parallel branches, box inputs) included, left to right. (A list
    gathered by plain recursion: nested generators cost ~0.25 s over the 50,000 networks of issue 27's build.)"""
    found: list[LdElement] = []
    _gather(elements, found)
    return found


def _gather(elements: list[LdElement], found: list[LdElement]) -> None:
    for element in elements:
        found.append(element)
        kind = element.type  # (the tag, not isinstance: the pydantic classes check through ABCMeta)
        if kind == "parallel":
            for branch in element.branches:  # type: ignore[union-attr]  # the tag says Parallel
                _gather(branch, found)
        elif kind == "box":
            for value in element.inputs.values():  # type: ignore[union-attr]  # the tag says Box
                if isinstance(value, list):
                    _gather(value, found)
