"""Pytest configuration shared by all suites."""

import os

import pytest
from hypothesis import settings

# The diagnostic codes the run produces are checked against the catalogue at the end (issue 19 item 5).
pytest_plugins = ["tests.diagnostic_codes"]

# Detailed assertion messages from shared test helpers (registered here, before any suite imports them).
pytest.register_assert_rewrite("tests.ir.helpers", "tests.ir.invariants")

# Property tests are sized for the 2-core CI budget (40 examples, as fuzz_settings: `make test` took 20.5 min on
# this machine with 60); `make test-slow` (LADDERLAB_HYPOTHESIS=thorough) runs 1,000.
settings.register_profile("ci", max_examples=40, deadline=None)
settings.register_profile("thorough", max_examples=1000, deadline=None)
settings.load_profile(os.environ.get("LADDERLAB_HYPOTHESIS", "ci"))


def pytest_sessionfinish(session):
    """In a pytest-xdist worker, hands this worker's corpus pass rates to the controller, which prints them."""
    from tests.support import PASS_RATES

    output = getattr(session.config, "workeroutput", None)
    if output is not None:
        output["pass_rates"] = dict(PASS_RATES)


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    """pytest-xdist, in the controller: a worker that ended brought the pass rates its tests recorded."""
    from tests.support import PASS_RATES

    PASS_RATES.update(getattr(node, "workeroutput", {}).get("pass_rates", {}))


def pytest_terminal_summary(terminalreporter):
    """Prints the external-corpus pass rates the corpus tests recorded in ``tests.support.PASS_RATES``."""
    from tests.support import PASS_RATES

    if not PASS_RATES:
        return
    terminalreporter.section("external corpus pass rates")
    for corpus, (passed, total) in sorted(PASS_RATES.items()):
        terminalreporter.write_line(f"{corpus:<48} {passed:>5}/{total:<5} {100 * passed / total:6.1f}%")
