"""Unit tests of a project with global variable lists (docs/testing.md): a test names a list's variable as the
program does, ``GVL_IO.bStart``, in statements, assertions and FORCE; a bare use of a qualified_only list's variable
is the same located error as in a POU."""

from __future__ import annotations

from ladderlab.model import GlobalVariableList, Pou, Project, Task
from ladderlab.testing.run import Options, prepare, run_tests

PROJECT = Project(
    name="unit",
    gvls=[
        GlobalVariableList(
            name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\n    n : INT;\nEND_VAR"
        )
    ],
    pous=[
        Pou(name="Main", kind="program", language="st", body="IF GVL_IO.bStart THEN GVL_IO.n := GVL_IO.n + 1; END_IF;")
    ],
    tasks=[Task(name="T", programs=["Main"])],
)


def test_a_test_sets_asserts_and_forces_a_lists_variable():
    tests = """TEST 'counts while started'
  GVL_IO.bStart := TRUE;
  RUN_SCANS(3);
  ASSERT_EQ(GVL_IO.n, 3);
  FORCE(GVL_IO.bStart, FALSE);
  RUN_SCANS(2);
  ASSERT_EQ(GVL_IO.n, 3);
  ASSERT_EQ(GVL_IO.n, 4, 'fails: forced off');
END_TEST
"""
    prepared = prepare(PROJECT, "tests/unit.st", tests)
    assert [d.format() for d in prepared.diagnostics] == []
    [result] = run_tests(prepared, Options())
    assert (result.failure.text(), result.failure.line) == (
        "ASSERT_EQ failed: GVL_IO.n expected 4, got 3\nMessage: fails: forced off",
        8,
    )


def test_a_bare_use_of_a_qualified_only_lists_variable_in_a_test_is_located():
    prepared = prepare(PROJECT, "tests/unit.st", "TEST 't'\n  bStart := TRUE;\nEND_TEST\n")
    assert prepared.compiled is None
    assert [d.format() for d in prepared.diagnostics] == [
        "tests/unit.st:2:3: error ST-QUALIFIED-ONLY: 'bStart' belongs to the global variable list GVL_IO, which is "
        "qualified_only: write GVL_IO.bStart"
    ]


SHARED = Project(
    name="shared",
    gvls=[
        GlobalVariableList(name="GVL_A", text="VAR_GLOBAL\n    n : INT;\nEND_VAR"),
        GlobalVariableList(name="GVL_B", text="VAR_GLOBAL\n    n : INT;\nEND_VAR"),
    ],
    pous=[Pou(name="Main", kind="program", language="st", body="GVL_A.n := GVL_A.n + 1;\nGVL_B.n := GVL_B.n + 2;")],
    tasks=[Task(name="T", programs=["Main"])],
)


def test_a_test_names_each_lists_variable_of_a_shared_name_apart():
    tests = """TEST 'two lists'
  RUN_SCANS(2);
  ASSERT_EQ(GVL_A.n, 2);
  ASSERT_EQ(GVL_B.n, 4);
  FORCE(GVL_B.n, 10);
  RUN_SCANS(1);
  ASSERT_EQ(GVL_A.n, 3);
  ASSERT_EQ(GVL_B.n, 10);
  ASSERT_EQ(GVL_B.n, 3, 'fails: forced');
END_TEST
"""
    prepared = prepare(SHARED, "tests/unit.st", tests)
    assert [d.format() for d in prepared.diagnostics] == []
    [result] = run_tests(prepared, Options())
    assert (result.failure.text(), result.failure.line) == (
        "ASSERT_EQ failed: GVL_B.n expected 3, got 10\nMessage: fails: forced",
        9,
    )


def test_a_bare_use_of_a_shared_name_in_a_test_is_located():
    prepared = prepare(SHARED, "tests/unit.st", "TEST 't'\n  ASSERT_EQ(n, 0);\nEND_TEST\n")
    assert prepared.compiled is None
    assert [d.format() for d in prepared.diagnostics] == [
        "tests/unit.st:2:13: error ST-AMBIGUOUS: 'n' is declared in the global variable lists GVL_A and GVL_B: write "
        "GVL_A.n or GVL_B.n"
    ]
