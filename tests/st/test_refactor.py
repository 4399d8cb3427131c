"""Rename refactoring and references (issue 22, item 1): identifiers only, never comments, strings,
literals, addresses or members; every LD/FBD operand, task and test file."""

from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
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


def test_a_renamed_global_or_program_renames_the_first_name_of_every_panel_path() -> None:
    """Operator panel widgets name variables by path (docs/hmi.md): a path whose first name is the renamed
    global or program follows it, in every binding field (bind, visible, a motion, a trend's paths); a member
    or a longer name that only starts alike keeps its text, as an address does."""
    lamp = {"type": "lamp", "id": "run", "x": 0, "y": 0, "w": 20, "h": 20, "bind": "Go", "visible": "Main.Go"}
    lamp["move_x"] = {"path": "go[2]", "distance": 50}
    trend = {"type": "trend", "id": "t", "x": 0, "y": 40, "w": 200, "h": 100, "paths": ["Main.Level", "GoFast"]}
    trend["paths"].append("%IX0.0")
    project = Project.model_validate(
        {
            "name": "hmi",
            "globals": "VAR_GLOBAL Go : BOOL; GoFast : BOOL; END_VAR",
            "pous": [{"name": "Main", "kind": "program", "language": "st", "declarations": "", "body": ""}],
            "panels": [{"name": "Operator", "widgets": [lamp, trend]}],
        }
    )
    renamed, changes = rename(project, "GO", "Start")
    widgets = renamed.panels[0].widgets
    assert (widgets[0].bind, widgets[0].visible, widgets[0].move_x.path) == ("Start", "Main.Go", "Start[2]")
    assert widgets[1].paths == ["Main.Level", "GoFast", "%IX0.0"]
    assert [(c.part, c.panel, c.element, c.text) for c in changes if c.part == "panel"] == [
        ("panel", "Operator", "run", "Go"),
        ("panel", "Operator", "run", "go[2]"),
    ]
    renamed, changes = rename(project, "Main", "Filler")
    assert (renamed.panels[0].widgets[0].visible, renamed.panels[0].widgets[1].paths[0]) == (
        "Filler.Go",
        "Filler.Level",
    )
    assert [(r.element, r.text) for r in references(project, "main")] == [("run", "Main.Go"), ("t", "Main.Level")]


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


OO_TEXT = """TYPE
  Shape : STRUCT w : INT; END_STRUCT;
END_TYPE
INTERFACE IArea
METHOD Area : INT
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Base
VAR s : Shape; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK Square EXTENDS Base IMPLEMENTS IArea
VAR side : INT := 2; END_VAR
METHOD Area : INT
VAR tmp : Shape; END_VAR
tmp.w := side;
Area := tmp.w * s.w;
END_METHOD
METHOD Copy : Shape
Copy := s;
END_METHOD
PROPERTY Form : Shape
GET
VAR last : Shape; END_VAR
Form := s;
END_GET
SET
s := Form;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR q : Square; a : IArea; n : INT; END_VAR
a := q;
n := a.Area();
END_PROGRAM
"""


def test_renaming_rewrites_extends_implements_and_method_and_property_texts() -> None:
    """Issue 25: a POU, an interface and a type used by EXTENDS, IMPLEMENTS and inside methods and properties are
    renamed there too, and each place is listed with its method or property; the renamed project builds and runs."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project

    def line(start: str) -> int:  # (the texts keep the lines of the file they were read from)
        return next(n for n, text in enumerate(OO_TEXT.splitlines(), 1) if text.startswith(start))

    project, _ = source_to_project(OO_TEXT, "oo")
    renamed, changes = rename(project, "Base", "Root")
    square = renamed.pou("Square")
    assert square.extends == "Root" and renamed.pou("Root") is not None
    assert [(c.part, c.pou, c.text) for c in changes] == [("extends", "Square", "EXTENDS Base")]

    renamed, changes = rename(renamed, "IArea", "IMeasured")
    assert renamed.pou("Square").implements == ["IMeasured"]
    assert "INTERFACE IMeasured" in renamed.types
    assert [(c.part, c.pou, c.member, c.line, c.text) for c in changes] == [
        ("types", None, None, 4, "INTERFACE IArea"),
        ("implements", "Square", None, None, "IMPLEMENTS IArea"),
        ("declarations", "Main", None, line("VAR q : Square;"), "VAR q : Square; a : IArea; n : INT; END_VAR"),
    ]

    renamed, changes = rename(renamed, "Shape", "Form2D")
    square = renamed.pou("Square")
    assert square.methods[0].declarations.strip() == "VAR tmp : Form2D; END_VAR"
    assert square.methods[1].return_type == "Form2D"
    assert square.properties[0].type == "Form2D"
    assert square.properties[0].get.declarations.strip() == "VAR last : Form2D; END_VAR"
    assert [(c.part, c.pou, c.member, c.line) for c in changes] == [
        ("types", None, None, line("  Shape : STRUCT")),
        ("declarations", "Root", None, line("VAR s : Shape;")),
        ("declarations", "Square", "Area", line("VAR tmp : Shape;")),
        ("return type", "Square", "Copy", 1),  # (a result type is a text of its own)
        ("return type", "Square", "Form", 1),
        ("declarations", "Square", "Form.GET", line("VAR last : Shape;")),
    ]
    assert "Form2D" not in square.methods[0].body  # tmp.w: a member, never renamed
    sim = build_project(renamed).simulation()
    sim.write("Main.q.s.w", 3)
    sim.cycle(1)
    assert sim.read("Main.n") == 2 * 3


COUNTERS = """
TYPE
  Other : STRUCT Bump : INT; END_STRUCT;
END_TYPE
FUNCTION_BLOCK Counter
VAR_OUTPUT n : INT; END_VAR
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
n := n + step;
Bump := n;
END_METHOD
METHOD Twice : INT
Twice := THIS^.Bump(step := 1) + Bump(step := 1);
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Fast EXTENDS Counter
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
Bump := SUPER^.Bump(step := step * 10);
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : Counter; f : Fast; cs : ARRAY[1..2] OF Counter; r : INT; t : INT; other : Other; END_VAR
r := c.Bump(step := 2) + cs[1].Bump(step := 1);
t := f.Twice();
other.Bump := 5; (* c.Bump in a comment *)
END_PROGRAM
"""


def test_renaming_a_method_renames_its_overrides_and_every_call() -> None:
    """Issue 25 item 5: a method renamed in the Methods tab takes its calls along: ``inst.Old(...)`` through an
    instance, an array element and an LD box ``inst.Old``, ``THIS^.Old``, ``SUPER^.Old`` and a bare ``Old(...)`` in
    the function block and those extending it, whose override is renamed too; a structure's member of the same name
    and a comment keep their text. The renamed project builds and computes what the original computed."""
    from ladderlab.model.project import Pou
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from ladderlab.st.refactor import member_name_problem, rename_member
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, _ = source_to_project(COUNTERS, "counters")
    bump = box("b1", "k.Bump", en=True, step="3", outputs={"OUT": "got"})
    project.pous.append(ld_pou("Lad", "VAR k : Counter; got : INT; END_VAR", rung("n1", contact("c1", "TRUE"), bump)))
    renamed, changes = rename_member(project, "Counter", "bump", "Add")
    counter, fast, main, lad = (renamed.pou(n) for n in ("Counter", "Fast", "Main", "Lad"))
    assert [m.name for m in counter.methods] == ["Add", "Twice"] and [m.name for m in fast.methods] == ["Add"]
    assert counter.methods[1].body.strip() == "Twice := THIS^.Add(step := 1) + Add(step := 1);"
    assert counter.methods[0].body.strip() == "n := n + step;\nAdd := n;"  # its result variable too
    assert fast.methods[0].body.strip() == "Add := SUPER^.Add(step := step * 10);"
    assert main.body.strip().splitlines() == [
        "r := c.Add(step := 2) + cs[1].Add(step := 1);",
        "t := f.Twice();",
        "other.Bump := 5; (* c.Bump in a comment *)",
    ]
    assert Pou.model_validate(lad).body.networks[0].elements[1].call == "k.Add"
    assert [(c.part, c.pou, c.member, c.text) for c in changes] == [
        ("method", "Counter", "Bump", "METHOD Bump"),
        ("body", "Counter", "Bump", "Bump := n;"),
        ("body", "Counter", "Twice", "Twice := THIS^.Bump(step := 1) + Bump(step := 1);"),
        ("method", "Fast", "Bump", "METHOD Bump"),
        ("body", "Fast", "Bump", "Bump := SUPER^.Bump(step := step * 10);"),
        ("body", "Main", None, "r := c.Bump(step := 2) + cs[1].Bump(step := 1);"),
        ("network", "Lad", None, "k.Bump"),
    ]
    for before_after in (project, renamed):
        sim = build_project(before_after).simulation()
        sim.cycle(1)
        # c: 0 + 2; cs[1]: 0 + 1; f.Twice: two Fast bumps of 10 each -> 10 + 20; k: 3
        assert (sim.read("Main.r"), sim.read("Main.t"), sim.read("Lad.got")) == (2 + 1, 10 + 20, 3)
    assert member_name_problem(project, "Counter", "Bump", "twice") == "Counter already has a member called Twice"
    assert member_name_problem(project, "Counter", "Nope", "X") == "Counter has no method or property called Nope"
    assert member_name_problem(project, "Counter", "Bump", "1x").startswith("1x is no IEC name")


INTERFACED = """
INTERFACE IBump
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Counter IMPLEMENTS IBump
VAR n : INT; END_VAR
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
n := n + step;
Bump := n;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Other IMPLEMENTS IBump
VAR total : INT; END_VAR
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
total := total + 100 * step;
Bump := total;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Unrelated
VAR k : INT; END_VAR
METHOD Bump : INT
VAR_INPUT step : INT; END_VAR
k := k + 1000;
Bump := k;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Holder
VAR_OUTPUT inner : Counter; END_VAR
END_FUNCTION_BLOCK
FUNCTION_BLOCK Outer
VAR_OUTPUT holder : Holder; pair : ARRAY[1..2] OF Holder; END_VAR
METHOD Poke : INT
Poke := THIS^.holder.inner.Bump(step := 0);
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR o : Outer; h : Holder; i : IBump; x : Other; u : Unrelated; a, b, c, d, e : INT; END_VAR
a := h.inner.Bump(step := 1);
b := o.holder.inner.Bump(step := 2) + o . pair[2].inner.Bump(step := 3);
i := x;
c := i.Bump(step := 1);
d := u.Bump(step := 1);
e := x.Bump(step := 1);
END_PROGRAM
"""


@pytest.mark.parametrize("start", ["Counter", "Other", "IBump"])
def test_renaming_an_interface_method_renames_implementations_member_chains_and_interface_calls(start) -> None:
    """Issue 25 item 5 (rename): Bump of IBump, of Counter and of Other is one member (both FBs implement IBump), so
    renaming it from any of the three renames all three declarations and every call: through member paths
    (``h.inner.Bump``, ``o.holder.inner.Bump``, ``o.pair[2].inner.Bump``, ``THIS^.holder.inner.Bump``, typed by each
    step's declaration), through
    the interface variable ``i`` and the instance ``x``; Unrelated's own Bump keeps its name. The project computes
    the same before and after."""
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from ladderlab.st.refactor import member_name_problem, rename_member

    project, diagnostics = source_to_project(INTERFACED, "itf")
    assert diagnostics == [] and project is not None
    assert member_name_problem(project, start, "bump", "Add") is None
    clash = project.model_copy(deep=True)
    clash.pou("Other").methods[0].name = "Add"  # Other's Bump would then be Add twice
    if start != "Other":
        assert (
            member_name_problem(clash, start, "Bump", "add")
            == "Other, renamed with it, already has a member called add"
        )
    renamed, changes = rename_member(project, start, "bump", "Add")
    assert renamed.types == project.types.replace("METHOD Bump", "METHOD Add")
    assert [(p.name, [m.name for m in p.methods]) for p in renamed.pous if p.methods] == [
        ("Counter", ["Add"]),
        ("Other", ["Add"]),
        ("Unrelated", ["Bump"]),
        ("Outer", ["Poke"]),
    ]
    assert renamed.pou("Outer").methods[0].body.strip() == "Poke := THIS^.holder.inner.Add(step := 0);"
    assert renamed.pou("Main").body.strip().splitlines() == [
        "a := h.inner.Add(step := 1);",
        "b := o.holder.inner.Add(step := 2) + o . pair[2].inner.Add(step := 3);",
        "i := x;",
        "c := i.Add(step := 1);",
        "d := u.Bump(step := 1);",
        "e := x.Add(step := 1);",
    ]
    assert [(c.part, c.pou, c.member, c.text) for c in changes] == [
        ("types", None, "IBump.Bump", "METHOD Bump : INT"),
        ("method", "Counter", "Bump", "METHOD Bump"),
        ("body", "Counter", "Bump", "Bump := n;"),
        ("method", "Other", "Bump", "METHOD Bump"),
        ("body", "Other", "Bump", "Bump := total;"),
        ("body", "Outer", "Poke", "Poke := THIS^.holder.inner.Bump(step := 0);"),
        ("body", "Main", None, "a := h.inner.Bump(step := 1);"),
        ("body", "Main", None, "b := o.holder.inner.Bump(step := 2) + o . pair[2].inner.Bump(step := 3);"),
        ("body", "Main", None, "c := i.Bump(step := 1);"),
        ("body", "Main", None, "e := x.Bump(step := 1);"),
    ]
    assert changes[0].line == 2  # the types text's line of IBump's METHOD Bump
    for before_after in (project, renamed):
        result = build_project(before_after)
        assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
        sim = result.simulation()
        sim.cycle(1)
        # h.inner: 0 + 1; o.holder.inner 2, o.pair[2].inner 3; x through i: 100, then x directly: 200; u: 1000
        assert [sim.read(f"Main.{v}") for v in "abcde"] == [1, 2 + 3, 100, 1000, 200]


def test_renaming_an_override_renames_the_base_method_it_overrides() -> None:
    """An override and the method it overrides are one member: renaming it in the derived FB renames the base's
    (and the base's bare calls of it), as renaming the base's renames the override; the FB beside them keeps its own."""
    from ladderlab.st.project_text import source_to_project
    from ladderlab.st.refactor import rename_member

    source = """
FUNCTION_BLOCK Base
METHOD Area : INT
Area := 1;
END_METHOD
METHOD Twice : INT
Twice := Area() * 2;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Square EXTENDS Base
METHOD Area : INT
Area := 4;
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK Beside
METHOD Area : INT
Area := 9;
END_METHOD
END_FUNCTION_BLOCK
"""
    project, diagnostics = source_to_project(source, "over")
    assert diagnostics == [] and project is not None
    renamed, _ = rename_member(project, "Square", "Area", "Size")
    assert [(p.name, [m.name for m in p.methods]) for p in renamed.pous] == [
        ("Base", ["Size", "Twice"]),
        ("Square", ["Size"]),
        ("Beside", ["Area"]),
    ]
    assert renamed.pou("Base").methods[1].body.strip() == "Twice := Size() * 2;"


def _holders() -> str:
    """H1 holds a Counter (``inner``) and an Unrelated (``other``), both with a method Bump; Hk holds an H(k-1)."""
    parts = [INTERFACED.split("FUNCTION_BLOCK Holder")[0]]
    parts.append("FUNCTION_BLOCK H1\nVAR_OUTPUT inner : Counter; other : Unrelated; END_VAR\nEND_FUNCTION_BLOCK\n")
    for k in range(2, 5):
        parts.append(f"FUNCTION_BLOCK H{k}\nVAR_OUTPUT inner : H{k - 1}; END_VAR\nEND_FUNCTION_BLOCK\n")
    return "".join(parts)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.tuples(st.integers(1, 4), st.sampled_from(["inner", "other"]), st.sampled_from([".", " . ", ".\n"])),
        min_size=1,
        max_size=6,
    )
)
def test_a_member_path_is_renamed_exactly_when_its_declared_type_shares_the_member(calls) -> None:
    """Issue 25 item 5 (rename): ``hK.inner...inner.leaf.Bump()`` through K nested holders (any spacing around the
    dots) ends at a Counter when the leaf is ``inner`` (renamed with Counter's Bump) and at an Unrelated when it is
    ``other`` (kept): the expected text is built from that rule, not from the refactoring."""
    from ladderlab.st.project_text import source_to_project
    from ladderlab.st.refactor import rename_member

    def call(k: int, leaf: str, dot: str, method: str) -> str:
        return f"x := h{k}{(dot + 'inner') * (k - 1)}{dot}{leaf}{dot}{method}(step := 1);"

    declarations = " ".join(f"h{k} : H{k};" for k in range(1, 5))
    body = "\n".join(call(k, leaf, dot, "Bump") for k, leaf, dot in calls)
    source = _holders() + f"PROGRAM Main\nVAR {declarations} x : INT; END_VAR\n{body}\nEND_PROGRAM\n"
    project, diagnostics = source_to_project(source, "paths")
    assert diagnostics == [] and project is not None
    renamed, _ = rename_member(project, "Counter", "Bump", "Add")
    expected = [call(k, leaf, dot, "Add" if leaf == "inner" else "Bump") for k, leaf, dot in calls]
    assert renamed.pou("Main").body.strip() == "\n".join(expected)


PROGRAM_METHOD = """
PROGRAM Store
VAR total : INT; END_VAR
METHOD Put : INT
VAR_INPUT n : INT; END_VAR
total := total + n;
Put := total;
END_METHOD
METHOD Twice : INT
Twice := THIS^.Put(1) + Put(1);
END_METHOD
Put(n := 1);
END_PROGRAM
FUNCTION_BLOCK Other
VAR_OUTPUT q : INT; END_VAR
METHOD Put : INT
Put := 100;
END_METHOD
q := Put() + Store.Put(2);
END_FUNCTION_BLOCK
PROGRAM Main
VAR o : Other; r : INT; t : INT; END_VAR
o();
r := Store.Put(n := 3) + o.q; (* Store.Put in a comment *)
t := Store.Twice();
END_PROGRAM
PROGRAM Hiding
VAR Store : Other; x : INT; END_VAR
Store();
x := Store.Put();
END_PROGRAM
"""


def test_renaming_a_program_method_renames_its_calls_inside_and_through_the_programs_name() -> None:
    """Issue 25 item 5 (CODESYS: methods of PROGRAMs): ``Put(...)``, ``THIS^.Put`` and the method's result variable
    in the program, ``Store.Put(...)`` in other POUs and an LD box ``Store.Put``; an FB's own method of that name, a
    variable that hides the program's name and a comment keep their text. The renamed project computes what the
    original computed (one scan, by hand: Store +1 -> 1; Main: o: 100 + (1 + 2 = 3) -> q 103, Store.Put(3) -> 6,
    r = 6 + 103 = 109; Twice: 7 + 8 = 15; Hiding: its own Other instance, Put() = 100, whose body's Store.Put(2) is
    the program's -> 10; the LD box: Put(5) -> 15)."""
    from ladderlab.model.project import Pou
    from ladderlab.simulation.build import build_project
    from ladderlab.st.project_text import source_to_project
    from ladderlab.st.refactor import member_name_problem, rename_member
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, diagnostics = source_to_project(PROGRAM_METHOD, "store")
    assert diagnostics == [] and project is not None
    put = box("b1", "Store.Put", en=True, n="5", outputs={"OUT": "got"})
    project.pous.append(ld_pou("Lad", "VAR got : INT; END_VAR", rung("n1", contact("c1", "TRUE"), put)))
    renamed, changes = rename_member(project, "Store", "put", "Add")
    store, other, main, hiding, lad = (renamed.pou(n) for n in ("Store", "Other", "Main", "Hiding", "Lad"))
    assert [m.name for m in store.methods] == ["Add", "Twice"] and [m.name for m in other.methods] == ["Put"]
    assert store.methods[0].body.strip() == "total := total + n;\nAdd := total;"
    assert store.methods[1].body.strip() == "Twice := THIS^.Add(1) + Add(1);"
    assert store.body.strip() == "Add(n := 1);"
    assert other.body.strip() == "q := Put() + Store.Add(2);"
    assert main.body.strip().splitlines() == [
        "o();",
        "r := Store.Add(n := 3) + o.q; (* Store.Put in a comment *)",
        "t := Store.Twice();",
    ]
    assert hiding.body.strip() == "Store();\nx := Store.Put();"
    assert Pou.model_validate(lad).body.networks[0].elements[1].call == "Store.Add"
    assert [(c.part, c.pou, c.member) for c in changes] == [
        ("body", "Store", None),
        ("method", "Store", "Put"),
        ("body", "Store", "Put"),
        ("body", "Store", "Twice"),
        ("body", "Other", None),
        ("body", "Main", None),
        ("network", "Lad", None),
    ]
    for before_after in (project, renamed):
        sim = build_project(before_after).simulation()
        sim.cycle(1)
        got = (sim.read("Main.r"), sim.read("Main.t"), sim.read("Hiding.x"), sim.read("Lad.got"))
        assert got == (109, 15, 100, 15)
    assert member_name_problem(project, "Store", "Put", "twice") == "Store already has a member called Twice"
