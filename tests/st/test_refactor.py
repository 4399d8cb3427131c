"""Rename refactoring and references (issue 22, item 1): identifiers only, never comments, strings,
literals, addresses or members; every LD/FBD operand, task and test file."""

from __future__ import annotations

import re

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model.project import Project
from ladderlab.simulation.check import check_project
from ladderlab.st.refactor import duplicate_pou, name_spans, references, rename, rename_in_text
from ladderlab.storage import load_project_path
from tests.support import EXAMPLES


def test_only_identifier_uses_are_renamed() -> None:
    text = (
        "(* Blink here *) // Blink too\n"
        "b : Blink; s : STRING := 'Blink';\n"
        "t := T#5s; x := 16#FF; y := %IX0.1; b.Blink := blink_2;\n"
        "BLINK(IN := TRUE);"
    )
    assert rename_in_text(text, "Blink", "Flash") == (
        "(* Blink here *) // Blink too\n"
        "b : Flash; s : STRING := 'Blink';\n"
        "t := T#5s; x := 16#FF; y := %IX0.1; b.Blink := blink_2;\n"
        "Flash(IN := TRUE);"
    )


def test_nested_comments_are_skipped() -> None:
    assert name_spans("(* a (* Main *) Main *) Main", "Main") == [(24, 28)]


def _project() -> Project:
    return Project.model_validate(
        {
            "name": "p",
            "globals": "VAR_GLOBAL\n  g : Blink;\nEND_VAR",
            "pous": [
                {
                    "name": "Blink",
                    "kind": "function_block",
                    "language": "st",
                    "declarations": "VAR_INPUT IN : BOOL; END_VAR",
                    "body": "",
                },
                {
                    "name": "Main",
                    "kind": "program",
                    "language": "st",
                    "declarations": "VAR\n  b : Blink;\nEND_VAR",
                    "body": "b(IN := TRUE);",
                },
                {
                    "name": "Lad",
                    "kind": "program",
                    "language": "ld",
                    "declarations": "VAR\n  c : BLINK;\nEND_VAR",
                    "body": {
                        "networks": [
                            {
                                "id": "n1",
                                "label": "Blinker",
                                "elements": [
                                    {"type": "box", "id": "box1", "call": "Blink", "instance": "c", "inputs": {}},
                                ],
                            }
                        ]
                    },
                },
                {
                    "name": "Fbd",
                    "kind": "program",
                    "language": "fbd",
                    "body": {"networks": [{"id": "f1", "nodes": [{"type": "block", "id": "blk1", "call": "blink"}]}]},
                },
            ],
            "tasks": [{"name": "Fast", "programs": ["Main", "Lad"]}],
            "tests": [{"name": "t", "text": "TEST 'x'\n  ASSERT_TRUE(Main.b.IN, 'x');\nEND_TEST"}],
        }
    )


def test_renaming_a_pou_changes_every_use_and_lists_it() -> None:
    renamed, changes = rename(_project(), "Blink", "Flash")
    assert renamed.pous[0].name == "Flash"
    assert renamed.globals == "VAR_GLOBAL\n  g : Flash;\nEND_VAR"
    assert renamed.pous[1].declarations == "VAR\n  b : Flash;\nEND_VAR"
    assert renamed.pous[2].declarations == "VAR\n  c : Flash;\nEND_VAR"
    assert renamed.pous[2].body.networks[0].elements[0].call == "Flash"
    assert renamed.pous[3].body.networks[0].nodes[0].call == "Flash"
    where = [(c.part, c.pou, c.line, c.network_number, c.element, c.text) for c in changes]
    assert where == [
        ("globals", None, 2, None, None, "g : Blink;"),
        ("declarations", "Main", 2, None, None, "b : Blink;"),
        ("declarations", "Lad", 2, None, None, "c : BLINK;"),
        ("network", "Lad", None, 1, "box1", "Blink"),
        ("network", "Fbd", None, 1, "blk1", "blink"),
    ]
    assert changes[3].network_label == "Blinker"


def test_renaming_a_program_changes_tasks_and_test_files_not_members() -> None:
    renamed, changes = rename(_project(), "main", "Plant")
    assert renamed.pous[1].name == "Plant"
    assert renamed.tasks[0].programs == ["Plant", "Lad"]
    assert renamed.tests[0].text == "TEST 'x'\n  ASSERT_TRUE(Plant.b.IN, 'x');\nEND_TEST"
    assert [(c.part, c.task, c.file, c.line) for c in changes] == [
        ("task", "Fast", None, None),
        ("test", None, "tests/t.st", 2),
    ]


def test_renaming_a_global_or_a_program_changes_task_triggers_and_program_instances() -> None:
    """A global used as a task's SINGLE trigger and in a program instance's bindings (CFG-06), and the program
    an instance runs, are renamed like every other use; nothing else in the task changes."""
    project = Project.model_validate(
        {
            "name": "cfg",
            "globals": "VAR_GLOBAL Go : BOOL; Level : INT; END_VAR",
            "pous": [
                {
                    "name": "Main",
                    "kind": "program",
                    "language": "st",
                    "declarations": "VAR_INPUT lvl : INT; END_VAR VAR_OUTPUT full : BOOL; END_VAR",
                    "body": "full := lvl > 10;",
                }
            ],
            "tasks": [
                {
                    "name": "OnGo",
                    "interval": None,
                    "single": "Go",
                    "programs": [{"name": "Tank1", "type": "Main", "inputs": {"lvl": "Level + 1"}, "outputs": {}}],
                }
            ],
        }
    )
    renamed, changes = rename(project, "go", "Start")
    assert renamed.tasks[0].single == "Start"
    assert [(c.part, c.task, c.text) for c in changes if c.part == "task"] == [("task", "OnGo", "Go")]
    renamed, changes = rename(project, "LEVEL", "Height")
    assert renamed.tasks[0].programs[0].inputs == {"lvl": "Height + 1"}
    assert [(c.part, c.text) for c in changes if c.part == "task"] == [("task", "Tank1.lvl := Level + 1")]
    renamed, changes = rename(project, "Main", "Filler")
    assert (renamed.tasks[0].programs[0].name, renamed.tasks[0].programs[0].type) == ("Tank1", "Filler")
    assert renamed.pous[0].name == "Filler"
    assert [(c.part, c.text) for c in changes] == [("task", "Tank1 : Main")]


def test_references_leave_out_the_definition() -> None:
    found = references(_project(), "Main")
    assert [(r.part, r.task, r.file) for r in found] == [("task", "Fast", None), ("test", None, "tests/t.st")]
    assert references(_project(), "Unused") == []


def test_a_duplicate_renames_its_own_uses_only() -> None:
    project = Project.model_validate(
        {
            "name": "p",
            "pous": [
                {
                    "name": "Twice",
                    "kind": "function",
                    "language": "st",
                    "return_type": "INT",
                    "declarations": "VAR_INPUT x : INT; END_VAR",
                    "body": "Twice := 2 * x;",
                },
                {"name": "Main", "kind": "program", "language": "st", "body": "y := Twice(3);"},
            ],
        }
    )
    copied = duplicate_pou(project, "Twice", "Twice2")
    assert [p.name for p in copied.pous] == ["Twice", "Twice2", "Main"]
    assert copied.pous[1].body == "Twice2 := 2 * x;"
    assert copied.pous[2].body == "y := Twice(3);"


NAMES = st.from_regex(r"[A-Za-z][A-Za-z0-9]{0,6}", fullmatch=True)


@given(
    st.lists(st.sampled_from(["Abc", "abc", "x", "Abcd", "'Abc'", "(*Abc*)", ".Abc", "T#1s", " ", ";"]), max_size=12),
    NAMES,
)
def test_rename_matches_a_reference_tokeniser(parts: list[str], new: str) -> None:
    """Independent reference: a name token is Abc in any case, outside quotes and comments, not after '.'."""
    text = " ".join(parts)
    expected = re.sub(
        r"('[^']*'|\(\*.*?\*\)|\.\s*[A-Za-z_]\w*|[A-Za-z_#]\w*)",
        lambda m: new if m.group().upper() == "ABC" else m.group(),
        text,
    )
    assert rename_in_text(text, "Abc", new) == expected


def test_an_sfc_chart_is_renamed_in_its_conditions_and_associations() -> None:
    """SFC POUs (issue 24) have no networks: a rename reaches their transition conditions and the BOOL variables
    their steps' associations name, and the renamed project still checks clean."""
    project = load_project_path(EXAMPLES / "car_wash_sfc")
    renamed, found = rename(project, "Premium", "Deluxe")
    wash = renamed.pou("Wash")
    branches = [branch for e in wash.body.chart.elements if e.type == "alternative" for branch in e.branches]
    conditions = [e.condition for branch in branches for e in branch if e.type == "transition"]
    assert "Deluxe" in conditions and "NOT Deluxe" in conditions
    assert {r.part for r in found} >= {"declarations", "transition"}
    renamed, found = rename(project, "Water", "Shower")
    assert sum(r.part == "step" for r in found) == 3
    assert [d.format() for d in check_project(renamed) if d.severity == "error"] == []
