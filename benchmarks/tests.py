"""``ladderlab test`` at scale (issue 20): 1,000 tests with 100,000 assertions on the motor example.

Ten test files of 100 tests each; every test runs the configuration for 10 scans and asserts 100 times
(values of the seal-in rung, the timer and the counter, one assertion per scan-level check), so the run
executes 10,000 scans and 100,000 assertions. Reported: wall time, tests/second, assertions/second, for
the serial runner (one process) and for worker processes (one per core), with the load average before
and after. Run: ``.venv/bin/python benchmarks/tests.py`` (part of ``make bench``).
"""

from __future__ import annotations

import os
import resource
import time
from pathlib import Path

from ladderlab.model import TestFile
from ladderlab.storage import load_project_path
from ladderlab.testing.run import Options
from ladderlab.testing.suite import run_suite, suite_files

ROOT = Path(__file__).resolve().parents[1]
FILES, TESTS, ASSERTS = 10, 100, 100


def test_text(file: int) -> str:
    tests = []
    for n in range(TESTS):
        checks = []
        for i in range(ASSERTS // 4):
            checks += [
                f"  ASSERT_TRUE(Motor, 'check {i}');",
                f"  ASSERT_EQ(Main.RunTimer.ET, T#{(9 + n % 7) * 10}ms);",
                "  ASSERT_GE(StartCount, 1);",
                "  ASSERT_LE(Speed, 15);",
            ]
        tests.append(
            f"TEST 'file {file} test {n}'\n  Start := TRUE;\n  RUN_SCANS({10 + n % 7});\n"
            + "\n".join(checks)
            + "\nEND_TEST\n"
        )
    return "\n".join(tests)


def _cpu() -> float:
    """CPU seconds of this process and of its finished worker processes."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def main() -> None:
    project = load_project_path(ROOT / "examples" / "motor")
    project.tests = [TestFile(name=f"bench{f}", text=test_text(f)) for f in range(FILES)]
    files = [f for f in suite_files(project) if f.path.startswith("tests/bench")]
    total = FILES * TESTS
    for label, jobs in (("serial", 1), (f"{os.cpu_count()} worker processes", os.cpu_count() or 1)):
        load_before = os.getloadavg()[0]
        started, cpu = time.perf_counter(), _cpu()
        outcome = run_suite(project, files, Options(), jobs=jobs)
        seconds, cpu = time.perf_counter() - started, _cpu() - cpu
        passed = outcome.count("passed")
        assert passed == total, (passed, [r.failure for r in outcome.results if r.failure][:3])
        print(
            f"{label}: {total} tests, {total * ASSERTS:,} assertions, {sum(r.scans for r in outcome.results):,} scans "
            f"in {seconds:.2f} s ({cpu:.1f} s CPU): {total / seconds:.0f} tests/s, "
            f"{total * ASSERTS / seconds:,.0f} assertions/s "
            f"(load average {load_before:.1f} -> {os.getloadavg()[0]:.1f})"
        )


if __name__ == "__main__":
    main()
