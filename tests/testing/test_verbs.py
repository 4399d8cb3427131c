"""Test files run on the engine: every verb, passing and failing, with the exact failure messages (issue 20).

Expected values follow the STruC++ test syntax and IEC 61131-3 semantics (TON: ET counts from the call
that sees IN rise, Q when ET >= PT; CTU counts rising edges), worked out by hand in the comments.
"""

from __future__ import annotations

from ladderlab.testing.run import Options, prepare, run_tests

from .helpers import FILE, at, outcomes, project, run

NL = chr(10)

COUNTER = """
FUNCTION_BLOCK Counter
VAR_INPUT enable : BOOL; END_VAR
VAR_OUTPUT count : INT; END_VAR
VAR hidden_step : INT := 1; END_VAR
IF enable THEN count := count + hidden_step; END_IF;
END_FUNCTION_BLOCK

FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := 2 * x;
END_FUNCTION

FUNCTION_BLOCK UsesTwice
VAR_OUTPUT y : INT; END_VAR
VAR inner : Counter; END_VAR
inner(enable := TRUE);
y := Twice(inner.count);
END_FUNCTION_BLOCK
"""


def test_assertions_pass_and_fail_with_both_values_as_iec_literals():
    TEXT = """
TEST 'passes'
  VAR c : Counter; r : REAL := 2.5; t : TIME := T#1500ms; s : STRING := 'ab'; END_VAR
  c(enable := TRUE);
  ASSERT_EQ(c.count, 1);
  ASSERT_NEQ(c.count, 2);
  ASSERT_GT(c.count, 0); ASSERT_LT(c.count, 2); ASSERT_GE(c.count, 1); ASSERT_LE(c.count, 1);
  ASSERT_NEAR(r, 2.45, 0.1);
  ASSERT_TRUE(c.count = 1); ASSERT_FALSE(c.count = 2); ASSERT(c.enable);
  ASSERT_EQ(t, T#1s500ms); ASSERT_EQ(s, 'ab');
END_TEST
TEST 'eq'
  VAR c : Counter; END_VAR
  c(enable := TRUE);
  ASSERT_EQ(c.count, 2, 'one call counts once');
  ASSERT_EQ(c.count, 99);
END_TEST
TEST 'neq'
  ASSERT_NEQ(3, 3);
END_TEST
TEST 'gt'
  VAR c : Counter; END_VAR
  ASSERT_GT(c.count, 0);
END_TEST
TEST 'le'
  VAR x : DINT := 7; END_VAR
  ASSERT_LE(x, 6, 'at most 6');
END_TEST
TEST 'near'
  VAR r : REAL := 2.5; END_VAR
  ASSERT_NEAR(r, 2.0, 0.25);
END_TEST
TEST 'true'
  VAR c : Counter; END_VAR
  ASSERT_TRUE(c.enable, 'enable starts FALSE');
END_TEST
TEST 'false'
  ASSERT_FALSE(1 < 2);
END_TEST
TEST 'iec assert'
  VAR c : Counter; END_VAR
  ASSERT(c.count > 0);
END_TEST
TEST 'time and string'
  VAR t : TIME := T#1m2s; s : STRING := 'it$'s'; END_VAR
  ASSERT_EQ(s, 'its');
END_TEST
TEST 'time'
  VAR t : TIME := T#1m2s; END_VAR
  ASSERT_EQ(t, T#62s500ms);
END_TEST
"""
    results = run(COUNTER, TEXT)
    assert outcomes(results) == {
        "passes": None,
        "eq": f"ASSERT_EQ failed: c.count expected 2, got 1\nMessage: one call counts once @{at(TEXT, 'ASSERT_EQ(c.count, 2,')}",
        "neq": f"ASSERT_NEQ failed: 3 expected not 3, got 3 @{at(TEXT, 'ASSERT_NEQ(3, 3)')}",
        "gt": f"ASSERT_GT failed: c.count expected > 0, got 0 @{at(TEXT, 'ASSERT_GT(c.count, 0);' + NL + 'END')}",
        "le": f"ASSERT_LE failed: x expected <= 6, got 7\nMessage: at most 6 @{at(TEXT, 'ASSERT_LE(x, 6')}",
        "near": f"ASSERT_NEAR failed: r expected 2.0 +/- 0.25, got 2.5 @{at(TEXT, 'ASSERT_NEAR(r, 2.0')}",
        "true": "ASSERT_TRUE failed: c.enable expected TRUE, got FALSE\nMessage: enable starts FALSE"
        f" @{at(TEXT, 'ASSERT_TRUE(c.enable')}",
        "false": f"ASSERT_FALSE failed: 1 < 2 expected FALSE, got TRUE @{at(TEXT, 'ASSERT_FALSE(1 < 2)')}",
        "iec assert": f"ASSERT failed: c.count > 0 expected TRUE, got FALSE @{at(TEXT, 'ASSERT(c.count > 0)')}",
        "time and string": f"ASSERT_EQ failed: s expected 'its', got 'it$'s' @{at(TEXT, 'ASSERT_EQ(s, ' + chr(39) + 'its')}",
        "time": f"ASSERT_EQ failed: t expected T#1m2s500ms, got T#1m2s @{at(TEXT, 'ASSERT_EQ(t, T#62s500ms)')}",
    }


def test_an_enumeration_value_in_a_failure_is_named_as_declared():
    """Brief polish25 item 1: ``TYPE Color : (Red, Green, blueIsh := 7)`` - a failure names the values as the
    declaration writes them (the type by its canonical name, as the online types do), whatever case the test used."""
    source = "TYPE Color : (Red, Green, blueIsh := 7); END_TYPE\n"
    TEXT = """
TEST 'color'
  VAR c : Color := Green; END_VAR
  ASSERT_EQ(c, COLOR#BLUEISH);
END_TEST
"""
    assert outcomes(run(source, TEXT)) == {
        "color": f"ASSERT_EQ failed: c expected COLOR#blueIsh, got COLOR#Green @{at(TEXT, 'ASSERT_EQ(c,')}"
    }


def test_the_first_failing_assertion_ends_the_test_and_each_test_starts_fresh():
    TEXT = """
SETUP
  VAR shared : Counter; END_VAR
  shared(enable := TRUE);
END_SETUP
TEST 'first'
  shared(enable := TRUE);
  ASSERT_EQ(shared.count, 2);
  ASSERT_EQ(shared.count, 5);
  ASSERT_EQ(shared.count, 6);
END_TEST
TEST 'second sees a fresh SETUP'
  ASSERT_EQ(shared.count, 1);
END_TEST
"""
    results = run(COUNTER, TEXT)
    assert outcomes(results) == {
        "first": f"ASSERT_EQ failed: shared.count expected 5, got 2 @{at(TEXT, 'ASSERT_EQ(shared.count, 5)')}",
        "second sees a fresh SETUP": None,
    }


def test_teardown_runs_after_a_failed_test_and_its_failure_is_mentioned():
    TEXT = """
SETUP
  VAR c : Counter; END_VAR
END_SETUP
TEARDOWN
  ASSERT_EQ(c.count, 0, 'teardown sees the test$'s state');
END_TEARDOWN
TEST 'body fails'
  c(enable := TRUE);
  ASSERT_TRUE(FALSE);
END_TEST
TEST 'only teardown fails'
  c(enable := TRUE);
END_TEST
TEST 'passes'
  ASSERT_EQ(c.count, 0);
END_TEST
"""
    results = run(COUNTER, TEXT)
    assert outcomes(results) == {
        "body fails": "ASSERT_TRUE failed: FALSE expected TRUE, got FALSE\n(and the TEARDOWN failed: ASSERT_EQ "
        f"failed: c.count expected 0, got 1) @{at(TEXT, 'ASSERT_TRUE(FALSE)')}",
        "only teardown fails": "ASSERT_EQ failed: c.count expected 0, got 1\nMessage: teardown sees the test's state"
        f" @{at(TEXT, 'ASSERT_EQ(c.count, 0, ')}",
        "passes": None,
    }


def test_white_box_access_to_inputs_outputs_and_internals():
    TEXT = """
TEST 'internals'
  VAR c : Counter; END_VAR
  c.hidden_step := 5;
  c.enable := TRUE;
  c();
  ASSERT_EQ(c.count, 5);
  c.count := 100;
  c();
  ASSERT_EQ(c.count, 105);
END_TEST
"""
    results = run(COUNTER, TEXT)
    assert outcomes(results) == {"internals": None}


def test_mocks_count_calls_skip_bodies_and_last_one_test():
    TEXT = """
TEST 'mocked inner instance'
  VAR u : UsesTwice; END_VAR
  MOCK u.inner;
  u.inner.count := 21;
  u();
  u();
  ASSERT_EQ(u.y, 42, 'the mocked body does not count');
  MOCK_VERIFY_CALLED(u.inner);
  MOCK_VERIFY_CALL_COUNT(u.inner, 2);
  MOCK_VERIFY_CALL_COUNT(u.inner, 3);
END_TEST
TEST 'mocked function'
  VAR u : UsesTwice; END_VAR
  MOCK_FUNCTION Twice RETURNS 7;
  u();
  ASSERT_EQ(u.y, 7);
  ASSERT_EQ(u.inner.count, 1, 'the inner counter still runs');
END_TEST
TEST 'real again in the next test'
  VAR u : UsesTwice; END_VAR
  u();
  ASSERT_EQ(u.y, 2);
END_TEST
TEST 'never called'
  VAR c : Counter; END_VAR
  MOCK c;
  MOCK_VERIFY_CALLED(c);
END_TEST
TEST 'not mocked'
  VAR c : Counter; END_VAR
  c();
  MOCK_VERIFY_CALLED(c);
END_TEST
"""
    results = run(COUNTER, TEXT)
    assert outcomes(results) == {
        "mocked inner instance": "MOCK_VERIFY_CALL_COUNT failed: u.inner expected 3 call(s), got 2"
        f" @{at(TEXT, 'MOCK_VERIFY_CALL_COUNT(u.inner, 3)')}",
        "mocked function": None,
        "real again in the next test": None,
        "never called": f"MOCK_VERIFY_CALLED failed: c was never called @{at(TEXT, 'MOCK_VERIFY_CALLED(c)')}",
        "not mocked": f"MOCK_VERIFY_CALLED: c is not mocked (write MOCK c; first) @{at(TEXT, 'c();' + NL + '  MOCK_VERIFY') + 1}",
    }


def test_advance_time_moves_the_clock_frozen_within_a_call():
    # TON (IEC 61131-3 table 45): ET counts from the call that sees IN rise; Q once ET >= PT.
    TEXT = """
TEST 'ton'
  VAR t : TON; END_VAR
  t(IN := TRUE, PT := T#1s);
  ADVANCE_TIME(T#999ms);
  t(IN := TRUE);
  ASSERT_FALSE(t.Q);
  ASSERT_EQ(t.ET, T#999ms);
  ADVANCE_TIME(T#1ms);
  t(IN := TRUE);
  ASSERT_TRUE(t.Q);
  t(IN := TRUE);
  ASSERT_EQ(t.ET, T#1s, 'two calls without ADVANCE_TIME see the same time');
END_TEST
"""
    results = run("", TEXT)
    assert outcomes(results) == {"ton": None}


TIMED = """
PROGRAM Main
VAR go : BOOL; t : TON; done : BOOL; END_VAR
t(IN := go, PT := T#20ms);
done := t.Q;
END_PROGRAM
"""


def test_a_mocked_standard_timer_keeps_its_inputs_and_never_runs_its_body():
    """A standard FB's body is pasted in place of its call (docs/runtime.md); a mocked TON must still skip it:
    IN and PT are written, Q and ET stay what the test set (docs/testing.md, MOCK)."""
    text = """
TEST 'mocked timer'
  MOCK Main.t;
  Main.go := TRUE;
  RUN_FOR(T#50ms);
  ASSERT_FALSE(Main.done, 'the mocked TON never sets Q');
  ASSERT_EQ(Main.t.ET, T#0ms);
  ASSERT_TRUE(Main.t.IN, 'callers still write its inputs');
  ASSERT_EQ(Main.t.PT, T#20ms);
  Main.t.Q := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(Main.done, 'the output the test set is read');
END_TEST
TEST 'real timer'
  Main.go := TRUE;
  RUN_FOR(T#50ms);
  ASSERT_TRUE(Main.done, 'IEC TON: Q once IN has been TRUE for PT');
END_TEST
"""
    for monitor in (False, True):  # the fast and the monitor variant both paste the body
        prepared = prepare(project(TIMED), FILE, text, monitor=monitor)
        assert prepared.compiled is not None
        assert outcomes(list(run_tests(prepared, Options()))) == {"mocked timer": None, "real timer": None}


SHAPES = """
INTERFACE I_Shape
METHOD Area : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Square IMPLEMENTS I_Shape
METHOD Area : INT
Area := 4;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Base
VAR_OUTPUT n : INT; END_VAR
n := n + 1;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Derived EXTENDS Base
SUPER^();
n := n + 10;
END_FUNCTION_BLOCK
PROGRAM Main
VAR s : Square; i : I_Shape; a : INT; d : Derived; END_VAR
i := s;
a := i.Area();
d();
END_PROGRAM
"""


def test_a_unit_test_runs_interface_dispatch_and_super_body_calls_as_the_simulation_does():
    """Regression: the program a test file runs lost the project's method dispatch table and SUPER^() bodies, so
    ``i.Area()`` through an interface gave 0 in a test while the simulation gave 4."""
    text = """
TEST 'object orientation'
  RUN_SCANS(1);
  ASSERT_EQ(Main.a, 4, 'Square.Area through I_Shape');
  ASSERT_EQ(Main.d.n, 11, 'the base body (+1) then the derived one (+10)');
END_TEST
"""
    assert outcomes(run(SHAPES, text)) == {"object orientation": None}
