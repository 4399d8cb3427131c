"""Property: an assertion passes exactly when its comparison holds, and a failure names both values
(issue 20). The expected outcome is computed here with Python's integers, independently of the runner."""

from __future__ import annotations

import operator

from hypothesis import given, settings
from hypothesis import strategies as st

from .helpers import run

OPERATORS = {
    "ASSERT_EQ": (operator.eq, ""),
    "ASSERT_NEQ": (operator.ne, "not "),
    "ASSERT_GT": (operator.gt, "> "),
    "ASSERT_LT": (operator.lt, "< "),
    "ASSERT_GE": (operator.ge, ">= "),
    "ASSERT_LE": (operator.le, "<= "),
}
DINT = st.integers(-(2**31), 2**31 - 1)
cases = st.lists(st.tuples(st.sampled_from(sorted(OPERATORS)), DINT, DINT), min_size=1, max_size=12)


@settings(max_examples=15, deadline=None)
@given(cases)
def test_assertions_hold_exactly_when_their_comparison_does(triples):
    text = "".join(
        f"TEST 't{i}'\n  VAR a : DINT := {a}; END_VAR\n  {verb}(a, DINT#{b});\nEND_TEST\n"
        for i, (verb, a, b) in enumerate(triples)
    )
    results = run("", text)
    for (verb, a, b), result in zip(triples, results):
        holds, relation = OPERATORS[verb]
        if holds(a, b):
            assert result.failure is None, (verb, a, b, result.failure)
        else:
            assert result.failure.message == f"{verb} failed: a expected {relation}{b}, got {a}"
            assert (result.failure.actual, result.failure.expected) == (str(a), str(b))


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10_000), st.integers(0, 10_000), st.integers(0, 500))
def test_assert_near_on_time_and_advance_time(start, delta, tolerance):
    """ADVANCE_TIME moves a TON's elapsed time by exactly the duration (IEC TON: ET counts from the call
    that saw IN rise, up to PT); ASSERT_NEAR passes when |ET - expected| <= tolerance."""
    text = (
        "TEST 'near'\n  VAR t : TON; END_VAR\n  t(IN := TRUE, PT := T#1h);\n"
        f"  ADVANCE_TIME(T#{delta}ms);\n  t(IN := TRUE);\n"
        f"  ASSERT_NEAR(t.ET, T#{start}ms, T#{tolerance}ms);\nEND_TEST\n"
    )
    (result,) = run("", text)
    assert (result.failure is None) == (abs(delta - start) <= tolerance)
