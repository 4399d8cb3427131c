"""All the tests of a project: its test files, run serially or spread over worker processes.

    files = suite_files(project, folder, grade=False)   # [SuiteFile("tests/motor.st", text, hidden=False)]
    outcome = run_suite(project, files, Options(), pattern="seal*", jobs=2, progress=print)
    outcome.exit_code                                     # 0 all passed, 1 a test failed, 2 a file has errors

Each worker process checks and compiles a file once for the tests it is given (a file with many tests is
split into chunks, so one big file also uses every core); results come back in file and test order.
Workers may be given a memory limit (``RLIMIT_AS``): a test that needs more fails with "out of memory".
"""

from __future__ import annotations

import multiprocessing
import os
import time
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import dataclass, field
from pathlib import Path

from ..model.diagnostics import Diagnostic, has_errors
from ..model.project import Project
from ..storage.project_folder import HIDDEN_TESTS_DIR, hidden_tests, test_path
from .coverage import Coverage
from .run import Options, Prepared, TestResult, prepare, run_test, selected

#: Fewer tests than this run in the calling process: starting workers costs more than it saves.
PARALLEL_FROM = 40
CHUNK = 25


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


def suite_files(project: Project, folder: Path | None = None, *, grade: bool = False) -> list[SuiteFile]:
    """The project's test files (``tests/*.st``), and with ``grade`` the hidden ones of its folder too."""
    files = [SuiteFile(test_path(t.name), t.text) for t in project.tests]
    if grade and folder is not None and folder.is_dir():
        files += [SuiteFile(f"{HIDDEN_TESTS_DIR}/{t.name}.st", t.text, True) for t in hidden_tests(folder)]
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
    prepared_files: Callable[[list[Prepared]], None] | None = None,
) -> SuiteOutcome:
    """Run the tests of ``files`` matching ``pattern``; ``prepared_files`` hears of the compiled files (their
    tests or diagnostics) before any runs, ``progress`` of each result as it comes."""
    started = time.perf_counter()
    coverage = Coverage() if options.coverage else None
    prepared = [prepare(project, f.path, f.text, coverage=options.coverage) for f in files]
    if prepared_files is not None:
        prepared_files(prepared)
    outcomes = [FileOutcome(p.file, p.diagnostics) for p in prepared]
    work = [(i, selected(p, pattern)) for i, p in enumerate(prepared) if p.compiled is not None]
    for index, tests in work:
        outcomes[index].skipped = len(prepared[index].tests) - len(tests)
    total = sum(len(tests) for _, tests in work)
    jobs = jobs or os.cpu_count() or 1
    if total < PARALLEL_FROM or jobs < 2:
        for index, tests in work:
            for test in tests:
                result = run_test(prepared[index], test, options, coverage)
                outcomes[index].results.append(result)
                if progress is not None:
                    progress(result)
    else:
        _run_parallel(project, files, work, outcomes, options, jobs, progress, coverage, memory_limit_mb)
    return SuiteOutcome(outcomes, time.perf_counter() - started, coverage)


def _run_parallel(project, files, work, outcomes, options, jobs, progress, coverage, memory_limit_mb) -> None:
    chunks = [
        (index, [t.pou for t in tests[start : start + CHUNK]])
        for index, tests in work
        for start in range(0, len(tests), CHUNK)
    ]
    slots: dict[tuple[int, int], list[TestResult]] = {}
    context = multiprocessing.get_context("spawn")  # the server calls this from threads: never fork them
    with ProcessPoolExecutor(
        max_workers=min(jobs, len(chunks)),
        mp_context=context,
        initializer=_worker_start,
        initargs=(project, files, memory_limit_mb),
    ) as pool:
        pending: dict[Future, tuple[int, int]] = {
            pool.submit(_run_chunk, index, pous, options): (index, number)
            for number, (index, pous) in enumerate(chunks)
        }
        while pending:
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                key = pending.pop(future)
                results, chunk_coverage = future.result()
                slots[key] = results
                if coverage is not None and chunk_coverage is not None:
                    coverage.merge(chunk_coverage)
                if progress is not None:
                    for result in results:
                        progress(result)
    for index, number in sorted(slots):
        outcomes[index].results.extend(slots[(index, number)])


_worker: dict[str, object] = {}


def _worker_start(project: Project, files: list[SuiteFile], memory_limit_mb: int | None) -> None:
    if memory_limit_mb:
        import resource

        limit = memory_limit_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    _worker.update(project=project, files=files, prepared={})


def _run_chunk(index: int, pous: list[str], options: Options) -> tuple[list[TestResult], Coverage | None]:
    cache: dict[int, Prepared] = _worker["prepared"]  # type: ignore[assignment]
    if index not in cache:
        file: SuiteFile = _worker["files"][index]  # type: ignore[index]
        cache[index] = prepare(_worker["project"], file.path, file.text, coverage=options.coverage)  # type: ignore[arg-type]
    prepared = cache[index]
    coverage = Coverage() if options.coverage else None
    tests = {t.pou: t for t in prepared.tests}
    return [run_test(prepared, tests[pou], options, coverage) for pou in pous], coverage
