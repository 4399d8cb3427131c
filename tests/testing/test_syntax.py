"""The test-file syntax STruC++ documents, accepted verbatim by the grammar's start_tests rule (issue 20).

The texts below follow STruC++'s docs (docs/implementation-phases/phase-9.x: TEST/END_TEST with VAR
blocks, SETUP/TEARDOWN, ASSERT_* with messages, MOCK, MOCK_FUNCTION ... RETURNS, MOCK_VERIFY_*).
"""

from __future__ import annotations

from ladderlab.st import ast
from ladderlab.st.parser import parse_statements, parse_tests

STRUCPP = """
(* test_motor.st *)
SETUP
  VAR
    motor : MotorControl;
    sensor : TemperatureSensor;
  END_VAR
  motor.max_speed := 1500;
  motor.enabled := FALSE;
END_SETUP

TEARDOWN
  motor.enabled := FALSE;
END_TEARDOWN

TEST 'Counter increments by 1 each cycle'
  VAR uut : Counter; END_VAR
  uut();
  ASSERT_EQ(uut.count, 1);
END_TEST

TEST 'Motor controller uses PID output as speed'
  VAR ctrl : MotorController; END_VAR
  MOCK ctrl.sensor;
  MOCK ctrl.subsystem.valve;
  MOCK_FUNCTION ReadSensorRaw RETURNS 4200;
  ctrl.sensor.value := 25.0;
  ctrl(setpoint := 100.0);
  ASSERT_NEAR(ctrl.motor_speed, 75.0, 0.001);
  ASSERT_NEAR(ctrl.pid.actual, 30.0, 0.001, 'PID should receive sensor value');
  MOCK_VERIFY_CALLED(ctrl.sensor);
  MOCK_VERIFY_CALL_COUNT(ctrl.sensor, 1);
END_TEST

test 'lower case keywords'
  assert_true(TRUE, 'message');
end_test
"""


def test_strucpp_test_files_parse_verbatim():
    result = parse_tests(STRUCPP, file="tests/motor.st")
    assert result.diagnostics == []
    tests = result.ast
    assert [t.name for t in tests.tests] == [
        "Counter increments by 1 each cycle",
        "Motor controller uses PID output as speed",
        "lower case keywords",
    ]
    assert [d.names[0].name for d in tests.setup.var_blocks[0].decls] == ["motor", "sensor"]
    assert len(tests.setup.body) == 2 and len(tests.teardown.body) == 1
    body = tests.tests[1].body
    assert isinstance(body[0], ast.MockStmt) and body[0].target == ast.Member(ast.Name("ctrl"), "sensor")
    assert body[2] == ast.MockFunctionStmt("ReadSensorRaw", ast.IntLit(4200, 10))
    assert tests.tests[1].span.line == 22


def test_test_keywords_stay_names_in_programs():
    result = parse_statements("test := setup + teardown; mock := returns; end_test := TRUE;")
    assert result.diagnostics == []


def test_mock_is_a_declaration_of_the_test_not_a_nested_statement():
    result = parse_tests("TEST 'x'\n  IF TRUE THEN\n    MOCK a;\n  END_IF;\nEND_TEST\n")
    assert [(d.line, d.column) for d in result.diagnostics] == [(3, 10)]


def test_one_setup_and_one_teardown_per_file():
    result = parse_tests("SETUP END_SETUP\nSETUP END_SETUP\n")
    assert [(d.line, d.message) for d in result.diagnostics] == [(2, "a test file has at most one SETUP block")]


def test_a_test_needs_a_quoted_name():
    result = parse_tests("TEST Name\nEND_TEST\n")
    assert result.ast is None and result.diagnostics[0].line == 1
