"""The shipped example projects (examples/ at the repository root)."""

from __future__ import annotations

import os
from pathlib import Path

from .storage import Workspace
from .storage.project_folder import read_project_folder

#: The repository's examples/ folder; LADDERLAB_EXAMPLES overrides it (e.g. in the Docker image).
EXAMPLES_DIR = Path(os.environ.get("LADDERLAB_EXAMPLES", Path(__file__).resolve().parents[2] / "examples"))
DEFAULT_EXAMPLE = "motor"


def seed_workspace(workspace: Workspace) -> str | None:
    """Copy the example project into an empty workspace; returns its name, or None if nothing was done."""
    source = EXAMPLES_DIR / DEFAULT_EXAMPLE
    if workspace.list() or not source.is_dir():
        return None
    workspace.create(read_project_folder(source).model_copy(update={"name": DEFAULT_EXAMPLE}))
    return DEFAULT_EXAMPLE
