"""Scan-level verbs: whole programs run as the configuration runs them, with limits that speak (issue 20).

The configuration: one 10 ms task (the default) running Main. Expected values by hand from the virtual
clock (docs: engine/tasks.py): scan k runs at k * 10 ms.
"""

from __future__ import annotations

from .helpers import at, errors, outcomes, run

PLANT = """
VAR_GLOBAL
    Level : INT;
    Pump AT %QX0.0 : BOOL;
END_VAR

PROGRAM Main
VAR_INPUT Fill : BOOL; END_VAR
VAR
    Scans : DINT;
    Kept : DINT;
    Divisor : INT := 1;
    Spin : BOOL;
    Quotient : INT;
END_VAR
VAR RETAIN Retained : DINT; END_VAR
Scans := Scans + 1;
Retained := Retained + 1;
Pump := Fill AND Level < 5;
IF Pump THEN Level := Level + 1; END_IF;
Quotient := 100 / Divisor;
WHILE Spin DO Kept := Kept + 1; END_WHILE;
END_PROGRAM
"""


def test_run_scans_run_for_and_inputs_by_assignment():
    text = """
TEST 'scans'
  ASSERT_EQ(Main.Scans, 0, 'nothing runs before a verb');
  RUN_SCANS(3);
  ASSERT_EQ(Main.Scans, 3);
  Main.Fill := TRUE;
  RUN_FOR(T#50ms);
  ASSERT_EQ(Main.Scans, 8, 'five more scans in 50 ms');
  ASSERT_EQ(Level, 5, 'the pump stops at 5');
  ASSERT_TRUE(Pump, 'the scan that reached 5 started with 4');
  RUN_SCANS(1);
  ASSERT_FALSE(Pump);
  RUN_SCANS(0);
  ASSERT_EQ(Main.Scans, 9);
END_TEST
"""
    assert outcomes(run(PLANT, text)) == {"scans": None}


def test_run_until_stops_when_the_condition_holds_and_fails_on_timeout():
    text = """
TEST 'until'
  Main.Fill := TRUE;
  RUN_UNTIL(Level >= 3, T#1s);
  ASSERT_EQ(Main.Scans, 3, 'three scans fill to 3');
  RUN_UNTIL(Level >= 3, T#1s);
  ASSERT_EQ(Main.Scans, 3, 'already true: no scan');
END_TEST
TEST 'timeout'
  RUN_UNTIL(Level > 10, T#200ms);
END_TEST
"""
    assert outcomes(run(PLANT, text)) == {
        "until": None,
        "timeout": f"RUN_UNTIL timed out: Level > 10 still FALSE after T#200ms (20 scans run in the test) "
        f"@{at(text, 'RUN_UNTIL(Level > 10')}",
    }


def test_force_holds_a_variable_until_release():
    text = """
TEST 'force'
  FORCE(Level, 2);
  Main.Fill := TRUE;
  RUN_SCANS(4);
  ASSERT_EQ(Level, 2, 'forced: the program cannot change it');
  ASSERT_TRUE(Pump);
  RELEASE(Level);
  RUN_SCANS(3);
  ASSERT_EQ(Level, 5);
  FORCE(Main.Fill, FALSE);
  Main.Fill := TRUE;
  RUN_SCANS(1);
  ASSERT_FALSE(Main.Fill);
END_TEST
"""
    assert outcomes(run(PLANT, text)) == {"force": None}


def test_a_test_starts_cold_and_warm_start_keeps_retain_variables():
    text = """
TEST 'warm'
  RUN_SCANS(4);
  WARM_START;
  ASSERT_EQ(Main.Retained, 4, 'RETAIN survives a warm start');
  ASSERT_EQ(Main.Scans, 0, 'the others start again');
  RUN_SCANS(1);
  COLD_START;
  ASSERT_EQ(Main.Retained, 0);
END_TEST
TEST 'cold'
  ASSERT_EQ(Main.Retained, 0, 'each test starts from a cold start');
END_TEST
"""
    assert outcomes(run(PLANT, text)) == {"warm": None, "cold": None}


def test_the_scan_budget_fails_with_its_reason():
    text = """
TEST 'budget'
  RUN_SCANS(60);
  RUN_SCANS(50);
END_TEST
TEST 'run_for budget'
  RUN_FOR(T#10s);
END_TEST
"""
    assert outcomes(run(PLANT, text, scan_budget=100)) == {
        "budget": "scan budget exceeded: RUN_SCANS would run the test past 100 scans (60 run so far; raise it with "
        f"--max-scans) @{at(text, 'RUN_SCANS(50)')}",
        "run_for budget": "scan budget exceeded: RUN_FOR would run the test past 100 scans (100 run so far; raise it "
        f"with --max-scans) @{at(text, 'RUN_FOR(T#10s)')}",
    }


def test_runtime_faults_and_the_watchdog_of_the_configuration_fail_the_test():
    text = """
TEST 'division'
  Main.Divisor := 0;
  RUN_SCANS(2);
END_TEST
TEST 'watchdog'
  Main.Spin := TRUE;
  RUN_SCANS(1);
END_TEST
"""
    results = {r.name: r.failure for r in run(PLANT, text, watchdog_s=0.05)}
    assert results["division"].kind == "fault"
    assert results["division"].line == at(text, "RUN_SCANS(2)")
    assert results["division"].message == (
        f"RUN_SCANS: the configuration stopped: division by zero: 100 / 0 at POU MAIN, line "
        f"{at(PLANT, 'Quotient := 100')} column 1 (instance MAIN), task DEFAULT, scan 0, t = 10 ms; QUOTIENT = 0; "
        "DIVISOR = 0"
    )
    assert results["watchdog"].kind == "watchdog"
    assert results["watchdog"].message.startswith(
        f"RUN_SCANS: the configuration stopped: watchdog: scan exceeded 0.05 s at POU MAIN, line {at(PLANT, 'WHILE')}"
    )


def test_errors_of_the_test_code_itself_are_located_in_the_test_file():
    text = """
TEST 'division'
  VAR zero : INT; x : INT; END_VAR
  x := 10 / zero;
END_TEST
TEST 'endless'
  VAR i : INT; END_VAR
  WHILE TRUE DO i := i + 1; END_WHILE;
END_TEST
"""
    results = {r.name: r.failure for r in run(PLANT, text, test_limit_s=0.05)}
    assert (results["division"].message, results["division"].line) == (
        "division by zero: 10 / 0 at line 4; X = 0; ZERO = 0",
        at(text, "x := 10 / zero"),
    )
    assert results["endless"].message == "the test's code ran longer than 0.05 s without a verb (line 8)"


def test_a_test_file_that_does_not_compile_has_located_diagnostics():
    text = """
TEST 'bad'
  VAR c : TON; END_VAR
  ASSERT_EQ(c, 1);
  ASSERT_EQ(Level, 'text');
  RUN_SCANS(T#1s);
  FORCE(c.Q, TRUE);
  MOCK Level;
  MOCK_FUNCTION Nothing RETURNS 1;
  ASSERT_NEAR(Pump, TRUE, 1);
  ASSERT_TRUE(Level);
  RUN_UNTIL(Pump);
  WARM_START(1);
  x := ASSERT_TRUE(TRUE);
END_TEST
"""
    assert errors(PLANT, text) == [
        "4:13 TEST-VERB ASSERT_EQ compares elementary values, not TON",
        "5:3 ST-TYPE-MISMATCH ASSERT_EQ needs operands of the same type: INT and STRING; convert one of them (e.g. a "
        "*_TO_* conversion)",
        "6:13 TEST-VERB RUN_SCANS counts scans with an integer, not TIME",
        "7:9 TEST-FORCE FORCE acts on a variable of a program or a global, not on a test variable",
        "8:8 TEST-MOCK MOCK needs a function block instance, not INT",
        "9:3 TEST-MOCK MOCK_FUNCTION replaces a FUNCTION of the project; 'Nothing' is none",
        "10:3 ST-TYPE-MISMATCH ASSERT_NEAR needs numbers (ANY_NUM), not BOOL",
        "11:15 ST-TYPE-MISMATCH the ASSERT_TRUE condition must be BOOL, not INT",
        "12:3 TEST-VERB RUN_UNTIL takes 2 argument(s), not 1",
        "13:3 TEST-VERB WARM_START takes 0 argument(s), not 1",
        "14:3 ST-UNKNOWN-VAR unknown variable 'x'",
        "14:8 TEST-VERB ASSERT_TRUE is a statement of its own: it has no value",
    ]


def test_a_test_declares_plain_variables_and_has_a_name_of_its_own():
    text = """TEST 'starts'
  VAR_INPUT x : INT; END_VAR
  ASSERT_TRUE(TRUE);
END_TEST
TEST 'starts'
  ASSERT_TRUE(TRUE);
END_TEST
"""
    assert errors(PLANT, text) == [
        "5:1 TEST-DUPLICATE there is already a test called 'starts' in this file",
        "2:3 TEST-DECL a test declares VAR blocks only, not VAR_INPUT",
    ]


IMAGE = """
PROGRAM Main
VAR
    Start AT %IX0.0 : BOOL;
    Motor AT %QX0.1 : BOOL;
    Count AT %MW4 : INT;
END_VAR
Motor := Start OR %IX0.2;
Count := Count + 1;
END_PROGRAM
"""


def test_direct_addresses_and_located_variables_in_test_code():
    """Issue 20 item 2 with issue 16's process image: a test sets inputs by address (as the world does) and reads
    outputs and memory by address or by the program's located variable; %MW4 overlaps %MB4/%MB5 and %MX4.x
    (little-endian, docs/runtime.md)."""
    text = """
TEST 'by address'
  %IX0.0 := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(%QX0.1, 'the motor runs');
  ASSERT_TRUE(Main.Motor);
  ASSERT_TRUE(Main.Start);
  %IX0.0 := FALSE;
  %IX0.2 := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(%QX0.1, 'the second input runs it too');
  ASSERT_EQ(Main.Count, 2);
  ASSERT_EQ(%MB4, 2);
  ASSERT_EQ(%MB5, 0);
  ASSERT_TRUE(%MX4.1);
  ASSERT_FALSE(%MX4.0);
END_TEST
TEST 'failing'
  RUN_SCANS(3);
  ASSERT_EQ(%MW4, 4, 'three scans');
END_TEST
"""
    assert outcomes(run(IMAGE, text)) == {
        "by address": None,
        "failing": f"ASSERT_EQ failed: %MW4 expected 4, got 3\nMessage: three scans @{at(text, 'ASSERT_EQ(%MW4, 4')}",
    }


def test_fault_injects_a_stuck_or_noisy_signal_until_cleared():
    """FAULT acts as the lab bench's faults do (docs/hmi.md): from the next scan on, where the program reads."""
    text = """
TEST 'stuck level'
  Main.Fill := TRUE;
  FAULT(Level, 'stuck', 0);
  RUN_SCANS(10);
  ASSERT_TRUE(Pump, 'every scan reads level 0, so the pump never stops');
  CLEAR_FAULT(Level);
  RUN_SCANS(10);
  ASSERT_FALSE(Pump, 'without the fault the level reaches 5');
  ASSERT_EQ(Level, 5);
END_TEST
TEST 'broken wire'
  Main.Fill := TRUE;
  FAULT(Main.Fill, 'stuck_false');
  RUN_SCANS(3);
  ASSERT_EQ(Level, 0, 'the program never saw Fill');
END_TEST
TEST 'always flipping'
  Main.Fill := TRUE;
  FAULT(Main.Fill, 'noisy', 1.0);
  RUN_SCANS(3);
  ASSERT_EQ(Level, 0, 'a flip rate of 1 turns every TRUE into FALSE');
  CLEAR_FAULT(Main.Fill);
  RUN_SCANS(2);
  ASSERT_EQ(Level, 2);
END_TEST
TEST 'rate out of range'
  FAULT(Main.Fill, 'noisy', 2.0);
END_TEST
"""
    assert outcomes(run(PLANT, text)) == {
        "stuck level": None,
        "broken wire": None,
        "always flipping": None,
        "rate out of range": "FAULT on Main.Fill: a noisy fault's rate is a probability from 0 to 1, not 2.0 "
        f"@{at(text, 'FAULT(Main.Fill, ' + chr(39) + 'noisy' + chr(39) + ', 2.0)')}",
    }


def test_faults_that_cannot_act_are_compile_errors():
    text = """
TEST 'bad faults'
  VAR local : BOOL; END_VAR
  FAULT(Level, 'stuck_true');
  FAULT(Pump, 'stuck', TRUE);
  FAULT(Level, 'broken');
  FAULT(local, 'open');
  FAULT(Level, 'open', 3);
  CLEAR_FAULT(local);
END_TEST
"""
    assert errors(PLANT, text) == [
        "4:3 TEST-FORCE FAULT on Level: stuck_true is for BOOL signals; hold a number with stuck and a value",
        "5:3 TEST-FORCE FAULT on Pump: hold a BOOL with stuck_true or stuck_false",
        "6:16 TEST-VERB FAULT's mode is a STRING literal, one of 'stuck_true', 'stuck_false', 'stuck', 'open', 'noisy'",
        "7:9 TEST-FORCE FAULT acts on a variable of a program or a global, not on a test variable",
        "8:24 TEST-VERB FAULT 'open' takes no value: only 'stuck' and 'noisy' do",
        "9:15 TEST-FORCE CLEAR_FAULT acts on a variable of a program or a global, not on a test variable",
    ]
