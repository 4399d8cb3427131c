"""Packaging (issue 19, item 6): the wheel carries what the installed app needs, the version is kept in one
place, and the Docker image builds where a Docker engine runs (skipped otherwise)."""

from __future__ import annotations

import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

import ladderlab

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> zipfile.ZipFile:
    out = tmp_path_factory.mktemp("wheel")
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out), str(ROOT)],
        check=True,
        capture_output=True,
    )
    (path,) = out.glob("ladderlab-*.whl")
    return zipfile.ZipFile(path)


def test_wheel_carries_grammar_types_marker_and_app(wheel: zipfile.ZipFile) -> None:
    names = set(wheel.namelist())
    assert "ladderlab/py.typed" in names
    assert "ladderlab/st/iec61131.lark" in names
    if (ROOT / "backend/ladderlab/server/static/index.html").is_file():  # `make test` builds the app first
        assert "ladderlab/server/static/index.html" in names


def test_version_is_kept_in_one_place(wheel: zipfile.ZipFile) -> None:
    (metadata,) = [n for n in wheel.namelist() if n.endswith(".dist-info/METADATA")]
    version = next(line for line in wheel.read(metadata).decode().splitlines() if line.startswith("Version: "))
    assert version == f"Version: {ladderlab.__version__}"
    assert '\nversion = "' not in (ROOT / "pyproject.toml").read_text()
    assert '"version"' not in (ROOT / "frontend/package.json").read_text()


def _docker_engine() -> bool:
    if shutil.which("docker") is None:
        return False
    return subprocess.run(["docker", "info"], capture_output=True).returncode == 0


@pytest.mark.skipif(not _docker_engine(), reason="no Docker engine on this machine")
def test_docker_image_builds_and_runs_as_non_root() -> None:
    tag = "ladderlab-test:latest"
    subprocess.run(["docker", "build", "-t", tag, str(ROOT)], check=True)
    user = subprocess.run(["docker", "run", "--rm", "--entrypoint", "id", tag, "-u"], check=True, capture_output=True)
    assert user.stdout.strip() != b"0"
    version = subprocess.run(
        [
            "docker",
            "run",
            "--rm",
            "--entrypoint",
            "python",
            tag,
            "-c",
            "import ladderlab; print(ladderlab.__version__)",
        ],
        check=True,
        capture_output=True,
    )
    assert version.stdout.decode().strip() == ladderlab.__version__
