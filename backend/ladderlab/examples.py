"""The shipped example projects (examples/ at the repository root): "New from example".

Each example is a project folder. An exercise (a lab bench example) also has ``example.json``
(``title``, ``summary``) and ``exercise/pous/``: the student's starting files of the POUs to
write (declarations, an empty body), which replace the reference solution's when a project starts
``exercise``. The statement of the exercise is the project's ``EXERCISE.md``.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .model import Project
from .storage import Workspace
from .storage.project_folder import POUS_DIR, PROJECT_FILE, read_pou_file, read_project_folder

#: The repository's examples/ folder; LADDERLAB_EXAMPLES overrides it (e.g. in the Docker image).
EXAMPLES_DIR = Path(os.environ.get("LADDERLAB_EXAMPLES", Path(__file__).resolve().parents[2] / "examples"))
DEFAULT_EXAMPLE = "motor"
META_FILE = "example.json"
EXERCISE_DIR = "exercise"


@dataclass(frozen=True)
class Example:
    name: str
    title: str
    summary: str = ""
    exercise: bool = False
    plants: list[str] = field(default_factory=list)
    panels: list[str] = field(default_factory=list)


class UnknownExample(LookupError):
    """No shipped example of that name; ``available`` lists them."""

    def __init__(self, name: str, available: list[str]) -> None:
        super().__init__(f"unknown example {name!r}; available: {', '.join(available) or 'none'}")
        self.available = available


def example_names(root: Path = EXAMPLES_DIR) -> list[str]:
    return sorted(d.name for d in root.iterdir() if (d / PROJECT_FILE).is_file()) if root.is_dir() else []


def list_examples(root: Path = EXAMPLES_DIR) -> list[Example]:
    """Every example, exercises first in their ``order``, then the others by name."""
    found = []
    for name in example_names(root):
        folder = root / name
        meta = _meta(folder)
        project = read_project_folder(folder)
        found.append(
            (
                meta.get("order", 1000),
                Example(
                    name=name,
                    title=meta.get("title", name),
                    summary=meta.get("summary", ""),
                    exercise=(folder / EXERCISE_DIR / POUS_DIR).is_dir(),
                    plants=[p.name for p in project.pous if p.kind == "plant"],
                    panels=[p.name for p in project.panels],
                ),
            )
        )
    return [example for _, example in sorted(found, key=lambda item: (item[0], item[1].name))]


def example_project(name: str, new_name: str, start: str = "solution", root: Path = EXAMPLES_DIR) -> Project:
    """The example as a new project called ``new_name``; ``start="exercise"`` takes the student's files."""
    available = example_names(root)
    if name not in available:
        raise UnknownExample(name, available)
    folder = root / name
    project = read_project_folder(folder).model_copy(update={"name": new_name})
    student = folder / EXERCISE_DIR / POUS_DIR
    if start != "exercise" or not student.is_dir():
        return project
    replaced = {pou.name.upper(): pou for pou in map(read_pou_file, sorted(student.iterdir()))}
    pous = [replaced.pop(pou.name.upper(), pou) for pou in project.pous] + list(replaced.values())
    return project.model_copy(update={"pous": pous})


def _meta(folder: Path) -> dict[str, Any]:
    path = folder / META_FILE
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}


def seed_workspace(workspace: Workspace) -> str | None:
    """Copy the example project into an empty workspace; returns its name, or None if nothing was done."""
    source = EXAMPLES_DIR / DEFAULT_EXAMPLE
    if workspace.names() or not source.is_dir():  # names: loading every project would slow each serve start
        return None
    workspace.create(read_project_folder(source).model_copy(update={"name": DEFAULT_EXAMPLE}))
    return DEFAULT_EXAMPLE
