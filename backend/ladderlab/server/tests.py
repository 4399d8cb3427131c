"""Unit tests from the browser (docs/testing.md): list, check, run with streamed progress, open a failure.

Every route takes the working copy (like ``POST /api/check``), so the Tests panel runs what the user
sees, saved or not. ``/run`` answers a stream of JSON lines (``TestEvent``): one per test file (its
tests, or the diagnostics that keep it from compiling), one per test result as it finishes, then the
summary (and the coverage when asked for). The tests run in worker processes, each test a unit of its
own (no test runs in the server's process); a thread forwards the results to the event loop. ``/open``
has a new simulation's process run the failing test again (``testing/online.py``) and serve the
simulation as it stood at the failure: the project with the test's instance (``TEST__<n>``) in it.
``/list`` only parses; ``/check`` checks and compiles one file in the server's process (for the editor's
live diagnostics: there is no build process for test files yet).
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import AsyncIterator
from typing import TYPE_CHECKING, Any

from fastapi import APIRouter, Request
from fastapi.responses import StreamingResponse

from ..model import Project
from ..model.api import (
    CoverageInfo,
    SimulationInfo,
    TestCaseInfo,
    TestCheckRequest,
    TestEvent,
    TestFileInfo,
    TestListing,
    TestOpenRequest,
    TestResultInfo,
    TestRunRequest,
    TestSummary,
)
from ..simulation.remote import BuildFailed, Maker
from ..storage.project_folder import revision_of
from .context import registry_of
from .errors import ApiError, responses
from .limits import LimitsDep, check_project_size
from .simulations import simulation_info

if TYPE_CHECKING:  # the test runner imports the compiler: imported at the first request (startup, issue 27)
    from ..ir.lower_tests import LoweredTest
    from ..testing.run import Prepared, TestResult
    from ..testing.suite import FileOutcome, SuiteFile

router = APIRouter(prefix="/api/tests", tags=["tests"])


@router.post("/list", response_model=TestListing, responses=responses(413, 422))
def list_tests(project: Project, limits: LimitsDep) -> TestListing:
    """The test files of the working copy and the tests in each (parsed only: nothing runs)."""
    from ..st.parser import parse_tests
    from ..testing.suite import suite_files

    check_project_size(project, limits)
    files = []
    for file in suite_files(project):
        parsed = parse_tests(file.text, file=file.path)
        tests = [TestCaseInfo(name=t.name, line=t.span.line) for t in parsed.ast.tests] if parsed.ast else []
        files.append(TestFileInfo(file=file.path, tests=tests, diagnostics=parsed.diagnostics))
    return TestListing(files=files)


@router.post("/check", response_model=TestFileInfo, responses=responses(404, 413, 422))
def check_tests(body: TestCheckRequest, limits: LimitsDep) -> TestFileInfo:
    """Every diagnostic of one test file with the working copy: the ST editor's live diagnostics."""
    from ..testing.run import prepare

    check_project_size(body.project, limits)
    file = _file(body.project, body.file)
    prepared = prepare(body.project, file.path, file.text)
    return _file_info(prepared, prepared.tests)


_EVENTS: dict[int | str, dict[str, Any]] = {
    200: {"model": TestEvent, "description": "One TestEvent per line (application/x-ndjson)."}
}


@router.post("/run", responses={**_EVENTS, **responses(404, 413, 422)})
async def run_tests(body: TestRunRequest, limits: LimitsDep) -> StreamingResponse:
    """Run every test, one file's or one test; answers a stream of ``TestEvent`` JSON lines."""
    from ..testing.suite import suite_files

    check_project_size(body.project, limits)
    files = [_file(body.project, body.file)] if body.file is not None else suite_files(body.project)
    return StreamingResponse(_stream(body.project, files, body.test, body.coverage), media_type="application/x-ndjson")


@router.post("/open", response_model=SimulationInfo, status_code=201, responses=responses(404, 409, 413, 422, 429))
def open_failure(body: TestOpenRequest, request: Request, limits: LimitsDep) -> SimulationInfo:
    """Run the failing test again in a new simulation's process and open its last state there (stopped)."""
    from ..testing.online import failed_test_simulation

    check_project_size(body.project, limits)
    registry = registry_of(request.app)
    registry.check_room()
    file = _file(body.project, body.file)
    args = {"project_json": body.project.model_dump_json(), "file": file.path, "text": file.text, "test": body.test}
    try:
        entry = registry.create(body.project, revision_of(body.project), Maker(failed_test_simulation, args))
    except BuildFailed as refused:
        raise ApiError(409, refused.message or "the failure cannot be opened", refused.diagnostics) from None
    return simulation_info(entry)


def _file(project: Project, path: str) -> SuiteFile:
    from ..testing.suite import suite_files

    found = next((f for f in suite_files(project) if f.path == path), None)
    if found is None:
        raise ApiError(404, f"project {project.name!r} has no test file {path!r}")
    return found


def _file_info(outcome: FileOutcome | Prepared, tests: list[LoweredTest]) -> TestFileInfo:
    from ..testing.suite import FileOutcome

    return TestFileInfo(
        file=outcome.path if isinstance(outcome, FileOutcome) else outcome.file,
        tests=[TestCaseInfo(name=t.name, line=t.line) for t in tests],
        diagnostics=outcome.diagnostics,
    )


async def _stream(project: Project, files: list[SuiteFile], test: str | None, coverage: bool) -> AsyncIterator[str]:
    from ..testing.run import Options
    from ..testing.suite import run_suite

    loop = asyncio.get_running_loop()
    queue: asyncio.Queue[str | None] = asyncio.Queue()

    def emit(event: TestEvent) -> None:
        line = event.model_dump_json(exclude_none=True) + "\n"
        loop.call_soon_threadsafe(queue.put_nowait, line)

    def work() -> None:
        try:
            outcome = run_suite(
                project,
                files,
                Options(coverage=coverage),
                name=test,
                processes=True,
                file_ready=lambda outcome, tests: emit(TestEvent(type="file", file=_file_info(outcome, tests))),
                progress=lambda result: emit(TestEvent(type="result", result=_result(result))),
            )
            names = {p.name.upper(): p.name for p in project.pous}
            summary = TestSummary(
                passed=outcome.count("passed"),
                failed=outcome.count("failed"),
                skipped=outcome.count("skipped"),
                files_with_errors=sum(1 for f in outcome.files if not f.ok),
                seconds=round(outcome.seconds, 3),
            )
            report = outcome.coverage.report(names) if outcome.coverage is not None else {}
            per_pou = {pou: CoverageInfo.model_validate(info) for pou, info in report.items()}
            emit(TestEvent(type="done", summary=summary, coverage=per_pou if outcome.coverage is not None else None))
        finally:
            loop.call_soon_threadsafe(queue.put_nowait, None)

    threading.Thread(target=work, name="tests", daemon=True).start()
    while (line := await queue.get()) is not None:
        yield line


def _result(result: TestResult) -> TestResultInfo:
    from ..testing.report import result_json

    return TestResultInfo.model_validate(result_json(result))
