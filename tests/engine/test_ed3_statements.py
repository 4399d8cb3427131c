"""IEC 61131-3 ed. 3 / CODESYS statements and operators (issue 25, item 4): CONTINUE in the three loops, the
short-circuit AND_THEN / OR_ELSE, and enumerations with a base type and explicit values (``E#A``). Expected values
are computed here with Python loops and the declared values."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.simulation.build import build_project
from ladderlab.st.parser import parse_source
from ladderlab.st.printer import print_source
from ladderlab.st.project_text import source_to_project

from .ed3_support import errors, program, scans

VARIANTS = ("fast", "monitor", "debug")

LOOPS = program(
    "i : INT; k : INT; odd : INT; j : INT; late : INT; n : INT; w : INT; rows : INT; inner : INT; x : INT;",
    """
odd := 0;
FOR k := 1 TO 10 DO
    IF k MOD 2 = 0 THEN CONTINUE; END_IF;
    odd := odd + k;
END_FOR;
j := 0; late := 0;
REPEAT
    j := j + 1;
    IF j < 5 THEN CONTINUE; END_IF;
    late := late + j;
UNTIL j >= 8 END_REPEAT;
n := 0; w := 0;
WHILE n < 10 DO
    n := n + 1;
    CASE n OF 3, 4: CONTINUE; END_CASE;
    w := w + n;
END_WHILE;
rows := 0; inner := 0;
FOR i := 1 TO 3 DO
    FOR x := 1 TO 4 DO
        IF x = 2 THEN CONTINUE; END_IF;
        inner := inner + 1;
    END_FOR;
    rows := rows + 1;
END_FOR;
""",
)


@pytest.mark.parametrize("variant", VARIANTS)
def test_continue_skips_the_rest_of_the_innermost_loop_body(variant):
    odd = sum(k for k in range(1, 11) if k % 2)
    late = sum(j for j in range(1, 9) if j >= 5)  # UNTIL is still tested after a CONTINUE: the loop ends at 8
    w = sum(n for n in range(1, 11) if n not in (3, 4))
    expected = [odd, 8, late, 10, w, 3, 3 * 3]
    assert scans(LOOPS, 2, "odd", "j", "late", "n", "w", "rows", "inner", variant=variant) == [expected, expected]


def test_continue_in_a_body_deep_enough_to_be_outlined():
    """Past 60 levels of nesting the code generator moves a body into a function of its own; CONTINUE crosses it."""
    depth = 65
    nested = "IF TRUE THEN " * depth + "IF k = 2 THEN CONTINUE; END_IF; hits := hits + 1;" + " END_IF;" * depth
    text = program("k : INT; hits : INT;", f"hits := 0; FOR k := 1 TO 4 DO {nested} done := done + 1; END_FOR;")
    text = text.replace("hits : INT;", "hits : INT; done : INT;")
    assert scans(text, 1, "hits", "done") == [[3, 3]]


def test_continue_outside_a_loop_is_refused():
    found = errors(program("x : INT;", "IF x = 0 THEN CONTINUE; END_IF;"))
    assert len(found) == 1 and "ST-EXIT-OUTSIDE-LOOP" in found[0], found
    assert "CONTINUE is only allowed inside FOR, WHILE or REPEAT" in found[0]


SHORT = program(
    "d : INT; a : ARRAY[1..3] OF INT := [5, 6, 7]; i : INT := 4; p : BOOL; q : BOOL; r : BOOL; s : BOOL;",
    """
p := d <> 0 AND_THEN 10 / d > 1;
q := d = 0 OR_ELSE 10 / d > 1;
r := i <= 3 AND_THEN a[i] > 5;
s := TRUE OR FALSE AND_THEN FALSE;
""",
)


@pytest.mark.parametrize("variant", VARIANTS)
def test_and_then_or_else_do_not_evaluate_the_right_operand_when_the_left_decides(variant):
    # 10 / 0 and a[4] would stop the task: they are not evaluated. AND_THEN binds like AND, tighter than OR.
    assert scans(SHORT, 1, "p", "q", "r", "s", variant=variant) == [[False, True, False, True]]  # TRUE OR (...)


def test_and_then_evaluates_the_right_operand_when_needed():
    text = program(
        "d : INT := 2; p : BOOL; q : BOOL;", "p := d <> 0 AND_THEN 10 / d > 1; q := d = 0 OR_ELSE 10 / d > 9;"
    )
    assert scans(text, 1, "p", "q") == [[True, False]]


def test_and_then_needs_bool_operands():
    found = errors(program("w : WORD; b : BOOL;", "b := w AND_THEN b;"))
    assert len(found) == 1 and "AND_THEN needs BOOL operands, not WORD" in found[0], found


TYPES = """TYPE Level : INT (Low := -10, Mid := 0, High := 10) := Mid; END_TYPE
TYPE Mode : UDINT (Off := 16#F0000000, Run := 1, Step); END_TYPE"""


def test_enumerations_with_a_base_type_and_explicit_values():
    text = program(
        "lv : Level; top : Level := Level#High; m : Mode := Mode#Step; code : INT; on : BOOL;",
        "CASE top OF Level#High: code := 3; Level#Low: code := 1; END_CASE; on := m <> Mode#Off; lv := Level#Low;",
        TYPES,
    )
    # Step follows Run (1): 2; the type's initial value Mid is the default of lv on the first scan's start
    assert scans(text, 1, "lv", "top", "m", "code", "on") == [[-10, 10, 2, 3, True]]


@pytest.mark.parametrize("variant", ["fast", "debug"])
def test_codesys_qualified_enumeration_values_are_the_typed_literals(variant):
    """CODESYS writes Level.High where IEC writes Level#High (in bodies, CASE labels and initial values): the same
    values as the test above, worked out from the declaration (High 10, Low -10, Mode.Step after Run 1: 2)."""
    text = program(
        "lv : Level; top : Level := Level.High; m : Mode := Mode.Step; code : INT; on : BOOL;",
        "CASE top OF Level.High: code := 3; Level.Low: code := 1; END_CASE; on := m <> Mode.Off; lv := Level.Low;",
        TYPES,
    )
    assert scans(text, 1, "lv", "top", "m", "code", "on", variant=variant) == [[-10, 10, 2, 3, True]]


def test_codesys_writes_the_base_type_after_the_values_and_the_printer_keeps_it():
    """CODESYS's "Enumeration" page: `(white := 16#FFFFFF00, ..., black := 16#88000000) DWORD := black` is a DWORD
    enumeration whose variables start as black; `(A, B, C) BYTE` counts from 0 in one byte. The ST text printed
    from the tree parses back to the same tree (the form without a first value stays CODESYS's)."""
    types = (
        "TYPE Color : (white := 16#FFFFFF00, yellow := 16#FFFF0000, black := 16#88000000) DWORD := black; END_TYPE\n"
        "TYPE Small : (A, B, C) BYTE; END_TYPE"
    )
    text = program("c : Color; s : Small := Small.C; n : DINT; m : DINT;", "n := SIZEOF(c); m := SIZEOF(s);", types)
    assert scans(text, 1, "c", "s", "n", "m") == [[0x88000000, 2, 4, 1]]
    parsed = parse_source(types)
    printed = print_source(parsed.ast)
    assert "(A, B, C) BYTE" in printed and "DWORD (white := 16#FFFFFF00" in printed, printed
    assert parse_source(printed).ast == parsed.ast


def test_a_variable_named_like_an_enumeration_keeps_its_members_and_unknown_values_are_named():
    """A declared variable wins over the type of the same name (its member is read); Level.Hihg is no value."""
    shadowed = program(
        "Level : Point; x : INT;",
        "Level.y := 4; x := Level.y;",
        "TYPE Point : STRUCT y : INT; END_STRUCT; END_TYPE\n" + TYPES,
    )
    assert scans(shadowed, 1, "x") == [[4]]
    found = errors(program("lv : Level;", "lv := Level.Hihg;", TYPES))
    assert len(found) == 1 and "ST-UNKNOWN-VAR: 'Hihg' is not a value of Level - did you mean 'High'?" in found[0], (
        found
    )


@pytest.mark.parametrize(
    "types, message",
    [
        ("TYPE E : SINT (A := 200); END_TYPE", "ST-RANGE: 200 does not fit the enumeration's base type SINT"),
        (
            "TYPE E : REAL (A := 1); END_TYPE",
            "an enumeration's base type must be an integer or BYTE/WORD/DWORD/LWORD, not REAL",
        ),
    ],
)
def test_enumeration_base_type_and_values_are_checked(types, message):
    found = errors(program("x : INT;", "x := 1;", types))
    assert any(message in e for e in found), found


def test_st_export_keeps_the_base_type_continue_and_short_circuit():
    source = TYPES + "\n" + SHORT.replace("p := d", "FOR d := 1 TO 2 DO CONTINUE; END_FOR;\np := d")
    parsed = parse_source(source)
    assert parsed.ok, parsed.diagnostics
    printed = print_source(parsed.ast)
    assert "INT (Low := -10, Mid := 0, High := 10)" in printed and "CONTINUE;" in printed and "AND_THEN" in printed
    assert parse_source(printed).ast == parsed.ast


def test_plcopen_round_trip_keeps_the_base_type_and_runs_the_same():
    text = program("top : Level := Level#High; m : Mode := Mode#Step;", "top := Level#Low;", TYPES)
    project, _ = source_to_project(text, "ed3")
    data = export_plcopen(project)
    enums = [e for e in ET.fromstring(data).iter() if e.tag.endswith("}enum")]
    assert [[c.tag.split("}")[1] for c in e if c.tag.endswith("}baseType")] for e in enums] == [["baseType"]] * 2
    assert [next(iter(next(c for c in e if c.tag.endswith("}baseType")))).tag.split("}")[1] for e in enums] == [
        "INT",
        "UDINT",
    ]
    imported = import_plcopen(data)
    assert [d.format() for d in imported.diagnostics if d.severity == "error"] == []
    sim = build_project(imported.project).simulation()
    sim.cycle(1)
    assert [sim.read("Main.top"), sim.read("Main.m")] == [-10, 2]
