"""All the tests of a project: its test files, run serially or spread over worker processes.

    files = suite_files(project, folder, grade=False)   # [SuiteFile("tests/motor.st", text, hidden=False)]
    outcome = run_suite(project, files, Options(), pattern="seal*", jobs=2, progress=print)
    outcome.exit_code                                     # 0 all passed, 1 a test failed, 2 a file has errors

Each worker process checks and compiles a file once for the tests it is given (a file is split into parts
only when there are fewer files than workers, so one big file also uses every core); results come back in
file and test order.
Workers may be given a memory limit (``RLIMIT_AS``): a test that needs more fails with "out of memory".
"""

from __future__ import annotations

import multiprocessing
import os
import re
import time
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import dataclass, field
from pathlib import Path

from ..ir.lower_tests import LoweredTest
from ..model.diagnostics import Diagnostic, has_errors
from ..model.project import Project
from ..storage.project_folder import HIDDEN_TESTS_DIR, hidden_tests, test_path
from .coverage import Coverage
from .run import Options, Prepared, TestResult, prepare, run_test, selected

#: Fewer tests than this run in the calling process: starting workers costs more than it saves.
PARALLEL_FROM = 40
#: How many tests a file has, near enough to choose between one process and several (no parse: it is slow).
_TEST_KEYWORD = re.compile(r"^\s*TEST\s+'", re.IGNORECASE | re.MULTILINE)


@dataclass(frozen=True)
class SuiteFile:
    path: str  # tests/<name>.st or tests/hidden/<name>.st
    text: str
    hidden: bool = False


@dataclass
class FileOutcome:
    path: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    results: list[TestResult] = field(default_factory=list)
    skipped: int = 0  # tests the filter left out

    @property
    def ok(self) -> bool:
        return not has_errors(self.diagnostics)


@dataclass
class SuiteOutcome:
    files: list[FileOutcome]
    seconds: float = 0.0
    coverage: Coverage | None = None

    @property
    def results(self) -> list[TestResult]:
        return [r for f in self.files for r in f.results]

    def count(self, outcome: str) -> int:
        if outcome == "skipped":
            return sum(f.skipped for f in self.files)
        return sum(1 for r in self.results if r.outcome == outcome)

    @property
    def exit_code(self) -> int:
        if any(not f.ok for f in self.files):
            return 2
        return 1 if self.count("failed") else 0


def suite_files(
    project: Project, folder: Path | None = None, *, grade: bool = False, encoding: str | None = None
) -> list[SuiteFile]:
    """The project's test files (``tests/*.st``), and with ``grade`` the hidden ones of its folder too (read in
    ``encoding``, UTF-8 when None)."""
    files = [SuiteFile(test_path(t.name), t.text) for t in project.tests]
    if grade and folder is not None and folder.is_dir():
        hidden = hidden_tests(folder, encoding)
        files += [SuiteFile(f"{HIDDEN_TESTS_DIR}/{t.name}.st", t.text, True) for t in hidden]
    return files


def run_suite(
    project: Project,
    files: list[SuiteFile],
    options: Options,
    *,
    pattern: str | None = None,
    jobs: int | None = None,
    progress: Callable[[TestResult], None] | None = None,
    memory_limit_mb: int | None = None,
    file_ready: Callable[[FileOutcome, list[LoweredTest]], None] | None = None,
    name: str | None = None,
    processes: bool = False,
) -> SuiteOutcome:
    """Run the tests of ``files`` matching ``pattern`` (or the one called ``name``). ``file_ready`` hears of each
    file once it is compiled (its diagnostics and tests), ``progress`` of each result as it comes. Worker
    processes run the tests when ``processes`` is set (the server: no test runs in its process; each test is a
    unit of its own, so results still come one by one), or with ``jobs`` > 1 and ``PARALLEL_FROM`` tests or more."""
    started = time.perf_counter()
    jobs = jobs or os.cpu_count() or 1
    counts = [len(_TEST_KEYWORD.findall(f.text)) for f in files]
    if files and (processes or (jobs > 1 and sum(counts) >= PARALLEL_FROM)):
        parts = [max(1, count) if processes and name is None else max(1, -(-jobs // len(files))) for count in counts]
        run = _Parallel(project, files, options, (pattern, name), progress, file_ready)
        outcomes, coverage = run.run(parts, jobs, memory_limit_mb)
        return SuiteOutcome(outcomes, time.perf_counter() - started, coverage)
    coverage = Coverage() if options.coverage else None
    prepared = [prepare(project, f.path, f.text, coverage=options.coverage) for f in files]
    outcomes = [FileOutcome(p.file, p.diagnostics) for p in prepared]
    for index, file in enumerate(prepared):
        tests = selected(file, pattern, name) if file.compiled is not None else []
        outcomes[index].skipped = len(file.tests) - len(tests)
        if file_ready is not None:
            file_ready(outcomes[index], file.tests)
        for test in tests:
            result = run_test(file, test, options, coverage)
            outcomes[index].results.append(result)
            if progress is not None:
                progress(result)
    return SuiteOutcome(outcomes, time.perf_counter() - started, coverage)


@dataclass
class _Part:
    """What a worker sends back for one part of one file."""

    file: int
    part: int
    diagnostics: list[Diagnostic]
    tests: list[LoweredTest]
    skipped: int
    results: list[TestResult]
    coverage: Coverage | None


class _Parallel:
    """Worker processes: each runs parts of files, preparing a file once for all the parts it gets. Part ``k`` of
    ``n`` runs the tests ``k::n`` (a file has several parts when there are fewer files than workers, so one big
    file still uses every core, or one per test when results must come one by one)."""

    def __init__(
        self,
        project: Project,
        files: list[SuiteFile],
        options: Options,
        choice: tuple[str | None, str | None],
        progress: Callable[[TestResult], None] | None,
        file_ready: Callable[[FileOutcome, list[LoweredTest]], None] | None,
    ) -> None:
        self.project, self.files, self.options, self.choice = project, files, options, choice
        self.progress, self.file_ready = progress, file_ready

    def run(
        self, parts: list[int], jobs: int, memory_limit_mb: int | None
    ) -> tuple[list[FileOutcome], Coverage | None]:
        files = self.files
        work = [(index, part, parts[index]) for index in range(len(files)) for part in range(parts[index])]
        outcomes = [FileOutcome(f.path) for f in files]
        coverage = Coverage() if self.options.coverage else None
        done: dict[tuple[int, int], _Part] = {}
        context = multiprocessing.get_context("spawn")  # the server calls this from threads: never fork them
        with ProcessPoolExecutor(
            max_workers=min(jobs, len(work)),
            mp_context=context,
            initializer=_worker_start,
            initargs=(self.project, files, memory_limit_mb),
        ) as pool:
            units = {pool.submit(_run_part, i, k, n, self.options, self.choice): (i, k) for i, k, n in work}
            pending = set(units)
            while pending:
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in finished:
                    part = _result(future, *units[future], files)
                    self._arrived(part, outcomes[part.file], done)
                    if coverage is not None and part.coverage is not None:
                        coverage.merge(part.coverage)
        for outcome in outcomes:  # parts ran tests k::n: back to file order
            outcome.results.sort(key=lambda r: r.line)
        return outcomes, coverage

    def _arrived(self, part: _Part, outcome: FileOutcome, done: dict[tuple[int, int], _Part]) -> None:
        first = not any(key[0] == part.file for key in done)
        done[(part.file, part.part)] = part
        if first:
            outcome.diagnostics, outcome.skipped = part.diagnostics, part.skipped
            if self.file_ready is not None:
                self.file_ready(outcome, part.tests)
        outcome.results.extend(part.results)
        if self.progress is not None:
            for result in part.results:
                self.progress(result)


def _result(future: Future[_Part], index: int, number: int, files: list[SuiteFile]) -> _Part:
    """A part's outcome; a worker process that died (killed, out of memory outside a test) says so for its file."""
    try:
        return future.result()
    except Exception as error:  # BrokenProcessPool and whatever a worker could not report itself
        reason = f"{type(error).__name__}: {error}" if str(error) else type(error).__name__
        message = f"the worker process running this file stopped ({reason}); its tests did not run"
        diagnostics = [Diagnostic(code="TEST-WORKER", file=files[index].path, message=message)]
        return _Part(index, number, diagnostics, [], 0, [], None)


@dataclass
class _Worker:
    """What a worker process keeps between its parts: the project, the files, each file prepared once."""

    project: Project
    files: list[SuiteFile]
    prepared: dict[int, Prepared] = field(default_factory=dict)


_worker: list[_Worker] = []  # the worker process's one _Worker, set by _worker_start


def _worker_start(project: Project, files: list[SuiteFile], memory_limit_mb: int | None) -> None:
    if memory_limit_mb:
        import resource

        limit = memory_limit_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    _worker[:] = [_Worker(project, files)]


def _run_part(index: int, part: int, parts: int, options: Options, choice: tuple[str | None, str | None]) -> _Part:
    worker = _worker[0]
    cache = worker.prepared
    if index not in cache:
        file = worker.files[index]
        cache[index] = prepare(worker.project, file.path, file.text, coverage=options.coverage)
    prepared = cache[index]
    coverage = Coverage() if options.coverage else None
    tests = selected(prepared, *choice) if prepared.compiled is not None else []
    mine = tests[part::parts]
    results = [run_test(prepared, test, options, coverage) for test in mine]
    return _Part(index, part, prepared.diagnostics, prepared.tests, len(prepared.tests) - len(tests), results, coverage)
