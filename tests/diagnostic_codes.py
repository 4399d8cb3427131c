"""Pytest plugin (issue 19 item 5): the diagnostic codes the test run produces, against the catalogue.

Every process of the run - this one, simulation and build workers, test-suite workers, the live servers of the
browser tests - appends each code it produces to one file (``model.codes.RECORD_ENV``). At the end:

- a produced code the catalogue (``model/codes.py``) does not list fails the run, whatever ran;
- after a run of the whole default suite, a catalogued code no test produced fails it too: a code nobody can
  trigger is dead, or its entry in docs/diagnostics.md is untested.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest

from ladderlab.model.codes import CODES, RECORD_ENV

_FILE: list[Path] = []


def pytest_configure(config: pytest.Config) -> None:
    if os.environ.get(RECORD_ENV) or hasattr(config, "workerinput"):
        return
    handle, name = tempfile.mkstemp(prefix="ladderlab-codes-", suffix=".txt")
    os.close(handle)
    _FILE.append(Path(name))
    os.environ[RECORD_ENV] = name


def produced_codes() -> set[str]:
    """The codes the processes of this run have produced so far."""
    path = Path(os.environ.get(RECORD_ENV) or "")
    if not path.name or not path.exists():
        return set()
    return {line.strip() for line in path.read_text(encoding="utf-8").splitlines() if line.strip()}


def _whole_suite(session: pytest.Session) -> bool:
    """Whether this run was the whole default suite (``make test``, ``make test-slow``, a bare ``pytest``).
    Every code has a test that runs without ../shared/external: CI may lack it, and must judge the same."""
    option = session.config.option
    root = Path(session.config.rootpath)
    paths = [Path(a.split("::")[0]).resolve() for a in session.config.args]
    whole = all(p in (root, root / "tests") for p in paths)
    return (
        whole
        and not option.keyword
        and option.markexpr in ("not slow", "slow or not slow")
        and not getattr(option, "deselect", None)
        and not getattr(option, "lf", False)
        and session.testsfailed == 0
        and not session.shouldstop
    )


@pytest.hookimpl(tryfirst=True)
def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    if not _FILE:
        return
    produced = produced_codes()
    _FILE[0].unlink(missing_ok=True)
    problems = []
    unknown = sorted(produced - set(CODES))
    if unknown:
        problems.append(f"produced but not in backend/ladderlab/model/codes.py: {', '.join(unknown)}")
    if _whole_suite(session):
        never = sorted(set(CODES) - produced)
        if never:
            problems.append(
                "catalogued but produced by no test (write one that triggers it, as in docs/diagnostics.md): "
                + ", ".join(never)
            )
    if problems:
        reporter = session.config.pluginmanager.get_plugin("terminalreporter")
        if reporter is not None:
            reporter.section("diagnostic codes", red=True)
            for problem in problems:
                reporter.write_line(problem)
        session.exitstatus = pytest.ExitCode.TESTS_FAILED
