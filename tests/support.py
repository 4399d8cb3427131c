"""Paths and helpers shared by the test suites (import as ``from tests.support import ...``)."""

from __future__ import annotations

import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
EXTERNAL = (ROOT / ".." / "shared" / "external").resolve()
SPEC = (ROOT / ".." / "shared" / "spec").resolve()
EXAMPLES = ROOT / "examples"


def external(*parts: str) -> pathlib.Path:
    """Path under ../shared/external; skips the calling test when it is absent."""
    path = EXTERNAL.joinpath(*parts)
    if not path.exists():
        pytest.skip(f"{path} not present (../shared/external is optional)")
    return path


#: External-corpus pass rates (name -> (passed, total)), printed at the end of the run by tests/conftest.py.
PASS_RATES: dict[str, tuple[int, int]] = {}
