"""Printer: exact IEC text, minimal parentheses, and parse(print(ast)) == ast on hand-picked cases."""

from __future__ import annotations

import pytest

from ladderlab.st.parser import parse_expression, parse_source
from ladderlab.st.printer import print_expression, print_source


@pytest.mark.parametrize(
    "text",
    [
        "A + B - C * ABS(D)",
        "(A + B - C) * ABS(D)",
        "A - (B - C)",
        "A ** B ** C",
        "A ** (B ** C)",
        "-2 ** 2",
        "(-2) ** 2",
        "2 ** -1",
        "NOT (A AND B)",
        "NOT A AND B",
        "(A OR B) AND C",
        "a < b = c < d",
        "T1.Q",
        "arr[i, j + 1].f^",
        "f(IN1 := 1, IN2 := x)",
        "t(IN := s, Q => q, NOT ET => e)",
        "INT#-9",
        "16#FF",
        "2#101",
        "8#17",
        "T#1h30m",
        "T#-500ms",
        "TOD#06:32:15.080",
        "D#2003-06-21",
        "DT#2003-06-21-11:38:52.350",
        "'it$'s $$5$N'",
        '"wide $"x$"" ',
        "%IX0.1",
    ],
)
def test_expressions_print_canonically(text):
    printed = print_expression(parse_expression(text).ast)
    assert printed == text.strip()


@pytest.mark.parametrize(
    "text, canonical",
    [
        ("((a))", "a"),
        ("(A ** B) ** C", "A ** B ** C"),
        ("-(2 ** 2)", "-2 ** 2"),
        ("a < b = (c < d)", "a < b = c < d"),
        ("a & b", "a AND b"),
        ("not a", "NOT a"),
        ("t#7h_24m_5s", "T#7h24m5s"),
        ("12_548_756", "12548756"),
        ("TIME#0.5s", "T#500ms"),
        ("+x", "x"),
        ("16#ff", "16#FF"),
        ("4.47E6", "4470000.0"),
        ("TOD#10:30:00.0", "TOD#10:30:00"),
    ],
)
def test_equivalent_spellings_normalise(text, canonical):
    assert print_expression(parse_expression(text).ast) == canonical


SOURCE = """\
TYPE
    TColor : (red, green := 5);
    TRec : STRUCT
        a : INT := 1;
        b : ARRAY [1..2, 0..3] OF STRING[10] := [3('x'), 2()];
    END_STRUCT;
END_TYPE

VAR_GLOBAL RETAIN
    sb1 AT %IX0.0, AT %QX0.1 : BOOL; (* start button *)
END_VAR

FUNCTION_BLOCK Motor
VAR_INPUT
    start : BOOL R_EDGE;
END_VAR
VAR
    t : TON;
    p : REF_TO INT;
    r : TRec := (a := 2, b := [1(''), 'y']);
END_VAR
    t(IN := start, PT := T#12s);
    IF t.Q THEN
        p^ := 1;
    ELSIF NOT start THEN
        ;
    ELSE
        RETURN;
    END_IF;
    CASE p^ OF
        1, 2..5:
            r.a := -r.a;
        red:
    ELSE
        EXIT;
    END_CASE;
    FOR i := 10 TO 1 BY -1 DO
        WHILE i > 0 DO
            i := i - 1;
        END_WHILE;
    END_FOR;
    REPEAT
        i := i + 1;
    UNTIL i >= 5
    END_REPEAT;
END_FUNCTION_BLOCK

CONFIGURATION PLC1
    RESOURCE CPM ON PLC
        TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM prg WITH Fast : Main(x := 1);
    END_RESOURCE
END_CONFIGURATION
"""


def test_source_prints_exactly_with_standard_indentation():
    result = parse_source(SOURCE)
    assert result.diagnostics == []
    assert print_source(result.ast) == SOURCE


def test_print_then_parse_gives_the_same_ast():
    tree = parse_source(SOURCE).ast
    assert parse_source(print_source(tree)).ast == tree


OO_SOURCE = """INTERFACE IBump EXTENDS IBase
    METHOD Bump : INT
    VAR_INPUT
        k : INT;
    END_VAR
    END_METHOD
    PROPERTY Level : INT
        GET
        END_GET
    END_PROPERTY
END_INTERFACE

FUNCTION_BLOCK ABSTRACT Counter EXTENDS Base IMPLEMENTS IBump, IOther
VAR
    n : INT;
END_VAR
    METHOD PUBLIC FINAL Bump : INT
    VAR_INPUT
        k : INT;
    END_VAR
        n := n + k;
        Bump := n;
    END_METHOD
    PROPERTY PROTECTED Level : INT
        GET
        VAR
            x : INT;
        END_VAR
            x := n;
            Level := x;
        END_GET
        SET
            n := Level;
        END_SET
    END_PROPERTY
    ACTION Reset:
        n := 0;
    END_ACTION
    n := n + 1;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    c : Counter;
END_VAR
    METHOD Add : INT
    VAR_INPUT
        k : INT;
    END_VAR
        Add := c.Bump(k := k);
    END_METHOD
    c.Reset();
END_PROGRAM
"""


def test_methods_properties_actions_and_interfaces_print_exactly():
    """IEC 61131-3 ed. 3, 6.6.5-6.6.6 (CODESYS's PROPERTY and FB ACTION): a POU's members stand between its VAR
    blocks and its body (the grammar's order), one level in, with FINAL/ABSTRACT, EXTENDS and IMPLEMENTS in the
    head; an INTERFACE prints its prototypes. The printed text parses back to the same tree."""
    result = parse_source(OO_SOURCE)
    assert result.diagnostics == []
    assert print_source(result.ast) == OO_SOURCE
    assert parse_source(print_source(result.ast)).ast == result.ast
