"""Sequential function chart model: a structured chart, its named actions and named transitions.

The chart is stored the way it is drawn, as nested sequences, not as a graph: a sequence alternates
step-like elements (a step, or a simultaneous divergence whose branches start and end with steps) and
transition-like elements (a transition, or an alternative divergence whose branches start with
transitions), and may end with a jump to a named step. So every chart the editor can make is a
well-formed chart, the editor lays it out by itself (no coordinates are stored) and the files diff
well. The first step of the chart is its initial step. ``model/sfc_graph.py`` turns a chart into the
step/transition graph the engine runs and back (imports of PLCopen and textual SFC arrive as graphs);
docs/sfc.md describes the semantics.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Field, model_validator

from .. import limits
from .base import Model
from .fbd import FbdBody
from .ld import LdBody

Qualifier = Literal["N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL"]

#: Qualifiers that need a TIME (SFC-05); the others take none.
TIMED_QUALIFIERS = frozenset({"L", "D", "SD", "DS", "SL"})
QUALIFIERS: tuple[str, ...] = ("N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL")


class _Item(Model):
    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1, description="Unique within the POU: probes, breakpoints and diagnostics use it.")


class SfcAssociation(_Item):
    """One line of a step's action block: a qualifier (with its TIME where needed) and an action or BOOL variable."""

    qualifier: Qualifier = "N"
    action: str = Field(description="The name of an action of the POU, or a BOOL variable (SFC-04: its value is Q).")
    time: str | None = Field(
        default=None, description="TIME expression (T#5s or a TIME variable) for L, D, SD, DS and SL."
    )


class SfcStep(_Item):
    type: Literal["step"] = "step"
    name: str = Field(description="An IEC identifier; Name.X and Name.T are its implicit variables.")
    actions: list[SfcAssociation] = Field(default_factory=list)
    entry: str | None = Field(default=None, description="Action run once in the first scan the step is active.")
    exit: str | None = Field(default=None, description="Action run once in the scan after the step was left.")
    min_time: str | None = Field(default=None, description="TIME: transitions after the step wait at least this long.")
    max_time: str | None = Field(
        default=None, description="TIME: active longer is an error in SFCError (with SFCEnableLimit)."
    )
    comment: str | None = None


class SfcTransition(_Item):
    type: Literal["transition"] = "transition"
    condition: str = Field(
        default="FALSE",
        description="ST expression (SFC-03: no assignment, no FB call); the name of a named transition reads "
        "its result.",
    )
    priority: int | None = Field(
        default=None, description="Among the transitions after one step, lower first; then left to right."
    )
    comment: str | None = None


class SfcAlternative(_Item):
    """Alternative divergence (single line): one branch is taken, the first whose transition is TRUE (SFC-08)."""

    type: Literal["alternative"] = "alternative"
    branches: list[list[SfcElement]] = Field(description="Two or more sequences, each starting with a transition.")


class SfcParallel(_Item):
    """Simultaneous divergence (double line): every branch starts together; all must end to go on (SFC-08)."""

    type: Literal["parallel"] = "parallel"
    branches: list[list[SfcElement]] = Field(description="Two or more sequences, each starting and ending with a step.")


class SfcJump(_Item):
    type: Literal["jump"] = "jump"
    target: str = Field(description="The name of the step the chart continues at.")


# SfcAlternative and SfcParallel name SfcElement before it exists: their validators, built at first use
# (model/base.py), find it here
SfcElement = Annotated[
    SfcStep | SfcTransition | SfcAlternative | SfcParallel | SfcJump,
    Field(discriminator="type"),
]


class SfcChart(Model):
    """A sequence of chart elements: the POU's chart, or the body of an action written in SFC."""

    model_config = ConfigDict(extra="forbid")

    elements: list[SfcElement] = Field(default_factory=list)

    @model_validator(mode="before")
    @classmethod
    def _not_too_deep(cls, data: Any) -> Any:
        """Branches nested deeper than ``limits.DIAGRAM_DEPTH`` are refused before they are validated."""
        if isinstance(data, dict):
            deep = _deepest(data.get("elements"))
            if deep is not None:
                raise ValueError(limits.DIAGRAM_DEPTH.too_deep(f"element {deep!r}"))
        return data


SfcLanguage = Literal["st", "il", "ld", "fbd", "sfc"]


class SfcAction(Model):
    """A named action (SFC-02): ST statements, IL instructions (text), LD or FBD networks, or a chart of its own."""

    model_config = ConfigDict(extra="forbid")

    name: str
    language: SfcLanguage = "st"
    body: str | LdBody | FbdBody | SfcChart = ""
    comment: str | None = None

    @model_validator(mode="before")
    @classmethod
    def _body_matches_language(cls, data: Any) -> Any:
        return _typed_body(data, {"st": str, "il": str, "ld": LdBody, "fbd": FbdBody, "sfc": SfcChart})


class SfcNamedTransition(Model):
    """A transition condition written on its own (SFC-03): an ST expression, IL instructions whose accumulator at the
    end gives its value (as in CODESYS), or LD/FBD networks whose coil or output named like the transition gives its
    value. A chart transition whose condition is this name reads it."""

    model_config = ConfigDict(extra="forbid")

    name: str
    language: Literal["st", "il", "ld", "fbd"] = "st"
    body: str | LdBody | FbdBody = "FALSE"
    comment: str | None = None

    @model_validator(mode="before")
    @classmethod
    def _body_matches_language(cls, data: Any) -> Any:
        return _typed_body(data, {"st": str, "il": str, "ld": LdBody, "fbd": FbdBody})


class SfcBody(Model):
    """The body of an SFC POU: the chart (its first step is the initial step), the actions, the named transitions."""

    model_config = ConfigDict(extra="forbid")

    chart: SfcChart = Field(default_factory=SfcChart)
    actions: list[SfcAction] = Field(default_factory=list)
    transitions: list[SfcNamedTransition] = Field(default_factory=list)

    def calls(self) -> set[str]:
        """The names (upper case) of the functions and FB types the LD/FBD actions and transitions call."""
        out: set[str] = set()
        bodies: list[object] = [*(a.body for a in self.actions), *(t.body for t in self.transitions)]
        for body in bodies:
            if isinstance(body, (LdBody, FbdBody)):
                out |= body.calls()
        return out

    def action(self, name: str) -> SfcAction | None:
        key = name.upper()
        return next((a for a in self.actions if a.name.upper() == key), None)

    def transition(self, name: str) -> SfcNamedTransition | None:
        key = name.upper()
        return next((t for t in self.transitions if t.name.upper() == key), None)

    def charts(self) -> Iterator[tuple[str | None, SfcChart]]:
        """The POU's chart (None) and every action's chart (its name)."""
        yield None, self.chart
        for action in self.actions:
            if isinstance(action.body, SfcChart):
                yield action.name, action.body


def _typed_body(data: Any, types: dict[str, Any]) -> Any:
    """Validate ``body`` as the type ``language`` names, so errors point at the right shape."""
    if not isinstance(data, dict):
        return data
    language = data.get("language", "st")
    expected = types.get(language) if isinstance(language, str) else None
    body = data.get("body")
    if expected is None or body is None:
        return data
    if expected is str:
        if not isinstance(body, str):
            raise ValueError(f"a body in {str(language).upper()} must be a string of {str(language).upper()}")
        return {**data, "body": body.rstrip()}
    if isinstance(body, str) and not body.strip():
        return {**data, "body": expected()}
    if isinstance(body, dict):
        return {**data, "body": expected.model_validate(body)}
    if not isinstance(body, expected):
        raise ValueError(f"a body in {str(language).upper()} must be an object")
    return data


def walk(elements: list[SfcElement]) -> Iterator[SfcElement]:
    """Every element of a sequence, branch contents included, in drawing order (top to bottom, left to right)."""
    for element in elements:
        yield element
        if isinstance(element, (SfcAlternative, SfcParallel)):
            for branch in element.branches:
                yield from walk(branch)


def steps(elements: list[SfcElement]) -> Iterator[SfcStep]:
    return (e for e in walk(elements) if isinstance(e, SfcStep))


def prefix_ids(chart: SfcChart, prefix: str) -> SfcChart:
    """``chart`` with ``prefix`` before every element and association id: an action's chart read from a file whose
    ids restart in every body (PLCopen, textual SFC) keeps ids unique in the POU (probes and breakpoints name
    elements by id)."""
    for element in walk(chart.elements):
        element.id = prefix + element.id
        for association in element.actions if isinstance(element, SfcStep) else []:
            association.id = prefix + association.id
    return chart


def _deepest(elements: Any) -> str | None:
    """The id of the first element (in raw data) whose branches cross the nesting limit."""
    limit = limits.DIAGRAM_DEPTH.value
    todo = [(elements, 0)]
    while todo:
        series, depth = todo.pop()
        if not isinstance(series, list):
            continue
        for element in series:
            if not isinstance(element, dict) or element.get("type") not in ("alternative", "parallel"):
                continue
            branches = element.get("branches")
            if not isinstance(branches, list):
                continue
            if depth + 1 > limit:
                return str(element.get("id"))
            todo.extend((branch, depth + 1) for branch in branches)
    return None
