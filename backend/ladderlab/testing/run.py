"""Run the tests of one test file, each in a fresh simulation of the same compiled program.

    prepared = prepare(project, "tests/motor.st", text)     # check, lower, compile once (diagnostics if not)
    for result in run_tests(prepared, Options()):            # one TestResult per TEST, in file order
        ...

A test is one call of its POU's instance (attached to the simulation as ``TEST__<n>``, its program links
bound to the configuration's instances) and, after it whatever its outcome, one call in the TEARDOWN
phase. Its first failure ends it (``host.TestFailure``); a runtime error of its own code or of the
configuration, the watchdog, the scan budget and running out of memory end it with their reason.
"""

from __future__ import annotations

import fnmatch
import time
from collections.abc import Iterator
from dataclasses import dataclass, field, replace

from ..engine.compile import CompiledProgram, CompileError, compile_program
from ..engine.simulation import Simulation
from ..engine.state import SimState, capture
from ..engine.tasks import DEFAULT_WATCHDOG_S
from ..ir.lower_tests import LoweredTest, Site, lower_test_file
from ..model.diagnostics import Diagnostic
from ..model.project import Project
from ..simulation.build import Build, task_watchdogs
from . import DEFAULT_SCAN_BUDGET
from .coverage import Coverage, instrument
from .host import Failure, Host, TestFailure


@dataclass(frozen=True)
class Options:
    scan_budget: int = DEFAULT_SCAN_BUDGET
    watchdog_s: float = DEFAULT_WATCHDOG_S  # the watchdog of tasks that set none, as online
    test_limit_s: float = 60.0  # wall time a test's own code may run between two verbs
    coverage: bool = False
    keep_state: bool = False  # capture the simulation's state when a test fails (to open it online)


@dataclass
class TestResult:
    file: str
    name: str
    line: int
    outcome: str  # passed | failed
    failure: Failure | None = None
    duration_s: float = 0.0
    scans: int = 0
    state: SimState | None = None


@dataclass
class Prepared:
    """A test file checked, lowered and compiled with its project (``compiled`` None: see diagnostics)."""

    file: str
    tests: list[LoweredTest]
    sites: list[Site]
    hosts: list[str]
    compiled: CompiledProgram | None
    diagnostics: list[Diagnostic] = field(default_factory=list)
    watchdogs: dict[str, float] = field(default_factory=dict)  # the tasks' own budgets (Build.watchdogs)


def prepare(project: Project, file: str, text: str, *, coverage: bool = False, monitor: bool = False) -> Prepared:
    """Check, lower and compile ``project`` with one test file; with ``coverage`` the monitor variant with
    line probes in the ST POUs (coverage.instrument), with ``monitor`` the monitor variant (to go online).
    Running out of memory (a worker process's --memory-limit) is a diagnostic of the file."""
    try:
        return _prepare(project, file, text, coverage or monitor, coverage)
    except MemoryError:
        message = (
            "out of memory while checking and compiling this test file with the project: its variables need more "
            "memory than the process may use (--memory-limit)"
        )
        return Prepared(file, [], [], [], None, [Diagnostic(code="TEST-MEMORY", file=file, message=message)])


def _prepare(project: Project, file: str, text: str, monitor: bool, coverage: bool) -> Prepared:
    lowered = lower_test_file(project, text, file)
    if lowered.program is None:
        return Prepared(file, [], [], [], None, lowered.diagnostics)
    if coverage:
        instrument(lowered.program)
    try:
        compiled = compile_program(lowered.program, "monitor" if monitor else "fast")
    except CompileError as error:
        return Prepared(file, [], [], [], None, lowered.diagnostics + error.diagnostics)
    return Prepared(
        file, lowered.tests, lowered.sites, lowered.hosts, compiled, lowered.diagnostics, task_watchdogs(project)
    )


def selected(prepared: Prepared, pattern: str | None, name: str | None = None) -> list[LoweredTest]:
    """The tests whose name matches ``pattern`` (a glob, or a part of the name; case-insensitive), or the one
    called exactly ``name``."""
    if name is not None:
        return [test for test in prepared.tests if test.name == name]
    if not pattern:
        return list(prepared.tests)
    wanted = pattern.lower()
    glob = any(c in wanted for c in "*?[")
    return [
        test
        for test in prepared.tests
        if (fnmatch.fnmatchcase(test.name.lower(), wanted) if glob else wanted in test.name.lower())
    ]


def run_tests(
    prepared: Prepared,
    options: Options,
    tests: list[LoweredTest] | None = None,
    coverage: Coverage | None = None,
) -> Iterator[TestResult]:
    for test in prepared.tests if tests is None else tests:
        yield run_test(prepared, test, options, coverage)


def run_test(prepared: Prepared, test: LoweredTest, options: Options, coverage: Coverage | None = None) -> TestResult:
    assert prepared.compiled is not None
    started = time.perf_counter()
    result = TestResult(prepared.file, test.name, test.line, "passed")
    try:
        _run(prepared, test, options, coverage, result)
    except MemoryError:
        result.failure = Failure(_OUT_OF_MEMORY, kind="memory")
    result.outcome = "failed" if result.failure is not None else "passed"
    result.duration_s = time.perf_counter() - started
    return result


_OUT_OF_MEMORY = "out of memory: the test needed more memory than its process may use (--memory-limit)"


def _run(
    prepared: Prepared, test: LoweredTest, options: Options, coverage: Coverage | None, result: TestResult
) -> None:
    sim = Build(prepared.compiled, [], prepared.watchdogs).simulation(watchdog_s=options.watchdog_s)
    collect = (lambda: coverage.collect(sim)) if coverage is not None else None
    host = Host(sim, prepared.sites, options.scan_budget, collect)
    for name in prepared.hosts:
        sim.replace_function(name, host.dispatch)
    instance = sim.attach(test.pou, test.pou, test.links)
    failure = _phase(sim, instance, test, options)
    if failure is not None and options.keep_state:
        result.state = capture(sim)
    host.teardown = True
    teardown = _phase(sim, instance, test, options)
    result.failure = teardown if failure is None else failure_after_teardown(failure, teardown)
    result.scans = sim.scan_count
    if collect is not None:
        collect()


def failure_after_teardown(failure: Failure, teardown: Failure | None) -> Failure:
    """The test's own failure is the one reported; a TEARDOWN that fails too is mentioned after it."""
    if teardown is None:
        return failure
    return replace(failure, message=f"{failure.message}\n(and the TEARDOWN failed: {teardown.message})")


def _phase(sim: Simulation, instance: object, test: LoweredTest, options: Options) -> Failure | None:
    try:
        fault = sim.call(instance, limit_s=options.test_limit_s, passthrough=(TestFailure, MemoryError))
    except TestFailure as failure:
        return failure.failure
    except MemoryError:
        return Failure(_OUT_OF_MEMORY, kind="memory")
    if fault is None:
        return None
    origin = fault.origin
    line = origin.line if origin is not None and origin.pou == test.pou else None
    where = f"line {line}" if line is not None else fault.where()
    values = "; ".join(f"{k} = {v!r}" for k, v in fault.values.items())
    kind = "watchdog" if fault.kind == "watchdog" else "fault"
    message = f"{fault.message} at {where}" + (f"; {values}" if values else "")
    if fault.kind == "watchdog":
        message = f"the test's code ran longer than {options.test_limit_s:g} s without a verb ({where})"
    return Failure(message, line, origin.column if line is not None and origin else None, kind=kind)


def failure_state(project: Project, file: str, text: str, name: str) -> tuple[Prepared, SimState]:
    """Run the test ``name`` again (the virtual clock makes it repeat exactly) in the monitor variant and
    return its program and the state the simulation had when it failed (to open online).
    LookupError: no such test or the file does not compile; ValueError: the test passes."""
    prepared = prepare(project, file, text, monitor=True)
    test = next((t for t in prepared.tests if t.name == name), None)
    if prepared.compiled is None or test is None:
        raise LookupError(f"{file} has no test {name!r}" if prepared.compiled else f"{file} does not compile")
    result = run_test(prepared, test, Options(keep_state=True))
    if result.state is None:
        raise ValueError(f"the test {name!r} passes: there is no failure to open")
    return prepared, result.state
