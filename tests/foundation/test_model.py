"""The project model: JSON round trip, language/body consistency, schema freshness."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from hypothesis import given
from pydantic import ValidationError

from ladderlab.cli.shared import stale
from ladderlab.model import LdBody, Pou, Project, Wire
from tests.support import ROOT

from .strategies import projects


@given(projects())
def test_model_json_round_trip(project: Project) -> None:
    text = project.model_dump_json()
    assert Project.model_validate_json(text) == project
    assert Project.model_validate(json.loads(text)).model_dump_json() == text


def test_wire_uses_from_in_json() -> None:
    wire = Wire.model_validate({"from": {"node": "a", "pin": "OUT"}, "to": {"node": "b", "pin": "IN"}})
    assert wire.model_dump(mode="json") == {"from": {"node": "a", "pin": "OUT"}, "to": {"node": "b", "pin": "IN"}}


def test_body_is_parsed_by_language() -> None:
    pou = Pou.model_validate(
        {"name": "M", "kind": "program", "language": "ld", "body": {"networks": [{"id": "n1", "elements": []}]}}
    )
    assert isinstance(pou.body, LdBody)
    with pytest.raises(ValidationError, match="ST POU's body must be a string"):
        Pou.model_validate({"name": "M", "kind": "program", "language": "st", "body": {"networks": []}})
    with pytest.raises(ValidationError, match="FBD POU's body must be an object"):
        Pou.model_validate({"name": "M", "kind": "program", "language": "fbd", "body": "x := 1;"})


def test_new_graphical_pou_starts_empty_and_texts_lose_trailing_whitespace() -> None:
    pou = Pou(name="M", kind="program", language="fbd", declarations="VAR x : INT; END_VAR \n\n")
    assert pou.body.networks == []
    assert pou.declarations == "VAR x : INT; END_VAR"


def test_shared_files_are_fresh() -> None:
    """shared_schema/ (schemas, OpenAPI, IEC vocabulary, diagnostics) and the catalogue table of
    docs/diagnostics.md must be regenerated (`make schema`) whenever the models, routes or tables change."""
    assert stale(ROOT) == [], "run `make schema` and commit the result"
    assert (ROOT / "shared_schema" / "api.schema.json").exists() is False, "the API's shapes are in openapi.json"


def test_fbd_positions_must_be_finite() -> None:
    """NaN/inf cannot be written to the JSON project files, so the model refuses them."""
    from pydantic import ValidationError

    from ladderlab.model.fbd import Position

    with pytest.raises(ValidationError, match="finite number"):
        Position(x=float("nan"), y=0)


def test_names_and_literals_ending_in_a_newline_are_refused() -> None:
    """Issue 18: ``$`` in the name patterns matched before a final newline, so "Main\\n" passed validation."""
    from ladderlab.model.names import pou_name_problem, project_name_problem
    from ladderlab.model.validate import validate_project

    assert pou_name_problem("Main\n") is not None
    assert pou_name_problem("Main") is None
    assert project_name_problem("motor\n") is not None
    project = Project(name="p", tasks=[{"name": "T", "interval": "T#10ms\n", "programs": []}])
    assert [d.json_path for d in validate_project(project)] == ["$.tasks[0].interval"]


_BUILT_AT_IMPORT = """
import pydantic
import ladderlab.model.api, ladderlab.model.monitor, ladderlab.model.sfc, ladderlab.server.app
from ladderlab.model.ld import Box, Parallel
from ladderlab.model.sfc import SfcParallel
def ours(cls):
    for sub in cls.__subclasses__():
        if sub.__module__.startswith("ladderlab."):
            yield sub
        yield from ours(sub)
print(sorted({c.__qualname__ for c in ours(pydantic.BaseModel) if c.__pydantic_complete__}))
contact = {"type": "contact", "id": "c", "var": "a"}
print(Parallel.model_validate({"id": "p", "branches": [[contact]]}).branches[0][0].var)
print(Box.model_validate({"id": "b", "call": "TON", "inputs": {"IN": [contact]}}).inputs["IN"][0].var)
print(SfcParallel.model_validate({"id": "p", "branches": [[{"type": "step", "id": "s", "name": "A"}]]}).branches[0][0].name)
"""


def test_importing_the_models_and_the_app_builds_no_validator() -> None:
    """Pydantic builds a model's validator at its first use (model/base.py): a ``model_rebuild()`` at import, or a
    plain ``BaseModel``, cost every ``ladderlab serve`` start its build (issue 27, startup). The recursive models still
    find the element unions they name before those are defined, at their first use."""
    done = subprocess.run(
        [sys.executable, "-c", _BUILT_AT_IMPORT], capture_output=True, text=True, timeout=120, check=True
    )
    assert done.stdout.splitlines() == ["[]", "a", "a", "A"]
