"""Each shipped exercise carries its goal as unit tests (examples/<name>/tests/exercise.st, docs/testing.md)
that drive the plant like a student at the panel: the reference solution passes every one, the student's
starting files (declarations, no logic) fail every test of the goal and pass only those that check that
nothing happens by itself (issue 21, "Done when": the exercises pass their tests)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ladderlab.cli import main
from ladderlab.examples import example_project, list_examples
from ladderlab.storage import Workspace
from tests.support import EXAMPLES

EXERCISES = [example.name for example in list_examples() if example.exercise]

#: The tests an empty program passes: nothing may happen by itself.
AT_REST = {
    "room_lights": {"nobody in the room: the lamp stays off"},
    "tank_filling": {"Off: the pump never runs"},
    "batch_mixer": {"the emergency stop switches everything off and abandons the batch"},
}


def _outcomes(capsys, folder: Path) -> dict[str, str]:
    code = main(["test", str(folder), "--format", "jsonl", "--jobs", "1"])
    out, err = capsys.readouterr()
    outcomes = {r["name"]: r["outcome"] for r in map(json.loads, out.splitlines()) if "outcome" in r}
    assert code == (0 if set(outcomes.values()) == {"passed"} else 1), err
    return outcomes


@pytest.mark.parametrize("name", EXERCISES)
def test_the_reference_solution_reaches_the_goal_and_the_empty_start_does_not(capsys, tmp_path: Path, name: str):
    solution = _outcomes(capsys, EXAMPLES / name)
    assert len(solution) >= 2 and set(solution.values()) == {"passed"}, solution
    Workspace(tmp_path).create(example_project(name, name, "exercise"))
    start = _outcomes(capsys, tmp_path / name)
    assert start.keys() == solution.keys()  # the student's project has the same tests
    assert {test for test, outcome in start.items() if outcome == "passed"} == AT_REST.get(name, set())
