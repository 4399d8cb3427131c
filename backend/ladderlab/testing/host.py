"""The test verbs as the generated code of a test calls them (ir/lower_tests.py: host functions).

One ``Host`` serves one test in one simulation. Every host call passes the number of its ``Site`` first;
``dispatch`` hands the call to the verb's method. A failed assertion, a timed-out RUN_UNTIL, a scan budget
spent or a runtime fault of the configuration raise ``TestFailure``, which ends the test's body (the
runner then runs the TEARDOWN and reports it).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NoReturn

from ..engine.inputs import InputEvent, InputRefused
from ..engine.simulation import Simulation
from ..iec.value_text import format_time
from ..ir.lower_tests import Site
from ..ir.types import BOOL, Elementary
from .values import literal

_OPERATORS: dict[str, tuple[str, Callable[[Any, Any], bool]]] = {
    "ASSERT_EQ": ("=", lambda a, e: a == e),
    "ASSERT_NEQ": ("<>", lambda a, e: a != e),
    "ASSERT_GT": (">", lambda a, e: a > e),
    "ASSERT_LT": ("<", lambda a, e: a < e),
    "ASSERT_GE": (">=", lambda a, e: a >= e),
    "ASSERT_LE": ("<=", lambda a, e: a <= e),
}
_BOOL = Elementary("BOOL")


@dataclass(frozen=True)
class Failure:
    """Why a test failed and where: ``line``/``column`` in the test file (None: not at a statement of it),
    ``actual``/``expected`` as IEC literals for assertions, ``note`` the assertion's own message."""

    message: str
    line: int | None = None
    column: int | None = None
    verb: str | None = None
    actual: str | None = None
    expected: str | None = None
    note: str | None = None
    kind: str = "assertion"  # assertion | timeout | budget | fault | memory | error

    def text(self) -> str:
        return self.message + (f"\nMessage: {self.note}" if self.note else "")


class TestFailure(Exception):
    def __init__(self, failure: Failure) -> None:
        super().__init__(failure.message)
        self.failure = failure


class Host:
    """Carries out the verbs of one test in ``sim``; ``scan_budget`` bounds the scans it may run."""

    def __init__(
        self, sim: Simulation, sites: list[Site], scan_budget: int, collect: Callable[[], None] | None = None
    ) -> None:
        self.sim, self.sites, self.scan_budget = sim, sites, scan_budget
        self.teardown = False
        self.collect = collect  # coverage: called after every scan and before every verb
        self._faults = 0
        self._methods: dict[str, Callable[..., object]] = {}

    def dispatch(self, site: int, *args: object) -> object:
        if self.collect is not None:
            self.collect()
        where = self.sites[site]
        method = self._methods.get(where.verb)
        if method is None:
            method = self._methods[where.verb] = getattr(self, "_" + where.verb.lower())
        return method(where, *args)

    # ------------------------------------------------------------ failing
    def fail(self, site: Site, message: str, kind: str = "assertion", **values: str | None) -> NoReturn:
        raise TestFailure(Failure(message, site.line, site.column, site.verb, kind=kind, **values))

    # ------------------------------------------------------------ assertions
    def _phase(self, site: Site) -> bool:
        return self.teardown

    def _compare(self, site: Site, actual: Any, expected: Any, message: Any = None) -> bool:
        symbol, holds = _OPERATORS[site.verb]
        if holds(actual, expected):
            return True
        shown, wanted = literal(actual, site.types[0]), literal(expected, site.types[1])
        relation = "" if symbol == "=" else "not " if symbol == "<>" else f"{symbol} "
        self.fail(
            site,
            f"{site.verb} failed: {site.operands[0]} expected {relation}{wanted}, got {shown}",
            actual=shown,
            expected=wanted,
            note=message,
        )
        return False

    _assert_eq = _assert_neq = _assert_gt = _assert_lt = _assert_ge = _assert_le = _compare

    def _assert_near(self, site: Site, actual: Any, expected: Any, tolerance: Any, message: Any = None) -> bool:
        if abs(actual - expected) <= tolerance:
            return True
        shown, wanted = literal(actual, site.types[0]), literal(expected, site.types[1])
        self.fail(
            site,
            f"ASSERT_NEAR failed: {site.operands[0]} expected {wanted} +/- {literal(tolerance, site.types[2])}, "
            f"got {shown}",
            actual=shown,
            expected=wanted,
            note=message,
        )
        return False

    def _assert_true(self, site: Site, condition: Any, message: Any = None) -> bool:
        return self._condition(site, condition, True, message)

    def _assert_false(self, site: Site, condition: Any, message: Any = None) -> bool:
        return self._condition(site, condition, False, message)

    def _assert(self, site: Site, condition: Any) -> bool:
        return self._condition(site, condition, True, None)

    def _condition(self, site: Site, condition: Any, wanted: bool, message: Any) -> bool:
        if bool(condition) is wanted:
            return True
        shown, expected = literal(condition, _BOOL), literal(wanted, _BOOL)
        self.fail(
            site,
            f"{site.verb} failed: {site.operands[0]} expected {expected}, got {shown}",
            actual=shown,
            expected=expected,
            note=message,
        )
        return False

    # ------------------------------------------------------------ time and scans
    def _advance_time(self, site: Site, ms: Any) -> bool:
        self.sim.advance_clock(ms)
        return True

    def _run_scans(self, site: Site, count: Any) -> bool:
        if count < 0:
            self.fail(site, f"RUN_SCANS needs a count of zero or more, not {count}", kind="error")
        self._budget(site, count)
        if self.collect is None:
            self.sim.cycle(count)
        else:
            for _ in range(count):
                self.sim.cycle(1)
                self.collect()
        self._scanned(site)
        return True

    def _run_for(self, site: Site, ms: Any) -> bool:
        end = self.sim.time_ms + ms
        while self.sim.next_scan_time() <= end:
            self._budget(site, 1)
            self.sim.cycle(1)
            self._scanned(site)
        return True

    def _run_until(self, site: Site, *args: Any) -> object:
        if not args:  # the start: the time the timeout counts from
            return self.sim.time_ms
        start, timeout = args
        if self.sim.time_ms - start >= timeout:
            self.fail(
                site,
                f"RUN_UNTIL timed out: {site.operands[0]} still FALSE after {format_time(timeout)} "
                f"({self.sim.scan_count} scans run in the test)",
                kind="timeout",
            )
        self._budget(site, 1)
        self.sim.cycle(1)
        self._scanned(site)
        return True

    def _warm_start(self, site: Site) -> bool:
        self.sim.reset(cold=False)
        self._faults = 0
        return True

    def _cold_start(self, site: Site) -> bool:
        self.sim.reset(cold=True)
        self._faults = 0
        return True

    def _budget(self, site: Site, count: int) -> None:
        if self.sim.scan_count + count > self.scan_budget:
            self.fail(
                site,
                f"scan budget exceeded: {site.verb} would run the test past {self.scan_budget:,} scans "
                f"({self.sim.scan_count:,} run so far; raise it with --max-scans)",
                kind="budget",
            )

    def _scanned(self, site: Site) -> None:
        if self.collect is not None:
            self.collect()
        self._check_faults(site)

    def _check_faults(self, site: Site) -> None:
        faults = self.sim.faults
        if len(faults) > self._faults:
            fault = faults[self._faults]
            self._faults = len(faults)
            kind = "watchdog" if fault.kind == "watchdog" else "fault"
            self.fail(site, f"{site.verb}: the configuration stopped: {fault.text()}", kind=kind)

    # ------------------------------------------------------------ forcing
    def _force(self, site: Site, value: Any) -> bool:
        self.sim.force(site.path, value)  # type: ignore[arg-type]  # a FORCE site has its path
        return True

    def _release(self, site: Site) -> bool:
        self.sim.unforce(site.path)  # type: ignore[arg-type]  # a RELEASE site has its path
        return True

    # ------------------------------------------------------------ faults
    def _fault(self, site: Site, value: Any = None) -> bool:
        """A fault on a signal from the next scan on, as the lab bench injects it; noise is seeded by the
        verb's line, so a test sees the same noise on every run."""
        mode, path = site.mode, site.path or ""  # a FAULT site has both
        flips = self.sim.location(path).type == BOOL  # a BOOL's noise is a flip rate, a number's an amplitude
        noise = {"rate" if flips else "amplitude": value} if mode == "noisy" and value is not None else {}
        event = InputEvent(
            "fault",
            path,
            value if mode == "stuck" else None,
            source=f"test line {site.line}",
            mode=mode,
            seed=site.line if mode == "noisy" else None,
            **noise,
        )
        try:
            self.sim.submit(event)
        except InputRefused as error:
            self.fail(site, f"FAULT on {path}: {error}")
        return True

    def _clear_fault(self, site: Site) -> bool:
        self.sim.submit(InputEvent("clear_fault", site.path, source=f"test line {site.line}"))
        return True

    # ------------------------------------------------------------ mocks
    def _mock(self, site: Site, reference: Any) -> bool:
        self.sim.mock(_target(reference))
        return True

    def _mock_function(self, site: Site, value: Any) -> bool:
        self.sim.replace_function(site.function, lambda *args: value)  # type: ignore[arg-type]  # a MOCK_FUNCTION site names it
        return True

    def _mock_verify_called(self, site: Site, reference: Any) -> bool:
        calls = self._calls(site, reference)
        if calls == 0:
            self.fail(site, f"MOCK_VERIFY_CALLED failed: {site.operands[0]} was never called")
        return True

    def _mock_verify_call_count(self, site: Site, expected: Any, reference: Any) -> bool:
        calls = self._calls(site, reference)
        if calls != expected:
            self.fail(
                site,
                f"MOCK_VERIFY_CALL_COUNT failed: {site.operands[0]} expected {expected} call(s), got {calls}",
                actual=str(calls),
                expected=str(expected),
            )
        return True

    def _calls(self, site: Site, reference: Any) -> int:
        calls = self.sim.mocks.count(_target(reference))
        if calls is None:
            self.fail(site, f"{site.verb}: {site.operands[0]} is not mocked (write MOCK {site.operands[0]}; first)")
        return calls


def _target(reference: Any) -> object:
    container, key = reference
    return container[key]
