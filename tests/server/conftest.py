"""A server over a fresh temporary workspace for every test."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from ladderlab.server.app import create_app
from ladderlab.storage import Workspace
from tests.support import api_client


@pytest.fixture
def workspace(tmp_path: Path) -> Workspace:
    return Workspace(tmp_path / "workspace")


@pytest.fixture
def client(workspace: Workspace) -> Iterator[TestClient]:
    app = create_app(workspace)
    yield api_client(app)
    registry = getattr(app.state, "simulations", None)
    if registry is not None:  # end the build and simulation processes a test started
        registry.close()


@pytest.fixture
def motor(client: TestClient) -> str:
    """The example project stored as 'motor'; returns its revision."""
    response = client.post("/api/projects", json={"name": "motor", "example": "motor"})
    assert response.status_code == 201, response.text
    return response.json()["revision"]
