"""A server over a fresh temporary workspace for every test."""

from __future__ import annotations

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
def client(workspace: Workspace) -> TestClient:
    return api_client(create_app(workspace))


@pytest.fixture
def motor(client: TestClient) -> str:
    """The example project stored as 'motor'; returns its revision."""
    response = client.post("/api/projects", json={"name": "motor", "example": "motor"})
    assert response.status_code == 201, response.text
    return response.json()["revision"]
