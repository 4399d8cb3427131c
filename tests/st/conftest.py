"""Prints the external-corpus pass rates collected by test_corpus.py at the end of the run."""

from __future__ import annotations

PASS_RATES: dict[str, tuple[int, int]] = {}


def pytest_terminal_summary(terminalreporter):
    if not PASS_RATES:
        return
    terminalreporter.section("ST corpus pass rates (parse without errors)")
    for corpus, (passed, total) in sorted(PASS_RATES.items()):
        terminalreporter.write_line(f"{corpus:<40} {passed:>5}/{total:<5} {100 * passed / total:6.1f}%")
