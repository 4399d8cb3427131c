"""Splitting ST text into POUs, declarations and body without losing a character."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model import Pou
from ladderlab.storage.st_text import StTextError, compose_pou_text, parse_pou_text, split_source

var_blocks = st.lists(
    st.sampled_from(
        [
            "VAR\n    x : INT := 5;\nEND_VAR",
            "VAR_INPUT a : BOOL; END_VAR  (* same line comment *)",
            "(* before *)\nVAR_OUTPUT\n    q : BOOL;  // END_VAR in a comment\nEND_VAR",
            "VAR CONSTANT\n    s : STRING := 'END_VAR $' END_PROGRAM';\nEND_VAR",
            "VAR_TEMP t : TIME; END_VAR",
        ]
    ),
    max_size=3,
).map("\n".join)
bodies = st.lists(
    st.sampled_from(
        [
            "x := x + 1;",
            "    IF a THEN\n        q := TRUE;\n    END_IF;",
            "(* END_PROGRAM *)",
            's := "END_VAR";',
            "",
            "// trailing comment",
            "CASE x OF 1: y := 2; END_CASE;",
        ]
    ),
    max_size=4,
).map("\n".join)


@given(kind=st.sampled_from(["program", "function_block", "function"]), decls=var_blocks, body=bodies)
def test_compose_then_parse_is_identity(kind: str, decls: str, body: str) -> None:
    pou = Pou(
        name="P1",
        kind=kind,
        language="st",
        return_type="INT" if kind == "function" else None,
        declarations=decls,
        body=body,
    )
    assert parse_pou_text(compose_pou_text(pou)) == pou


def test_split_file_with_types_globals_and_pous() -> None:
    text = """(* header comment *)
TYPE Color : (Red, Green); END_TYPE
VAR_GLOBAL g : INT; END_VAR
FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := x * 2;
END_FUNCTION
PROGRAM Main
VAR y : INT; END_VAR
y := Twice(g);
END_PROGRAM
"""
    parsed = split_source(text)
    assert parsed.types == "TYPE Color : (Red, Green); END_TYPE"
    assert parsed.globals == "VAR_GLOBAL g : INT; END_VAR"
    assert [(p.name, p.kind, p.return_type) for p in parsed.pous] == [
        ("Twice", "function", "INT"),
        ("Main", "program", None),
    ]
    assert parsed.pous[1].declarations == "VAR y : INT; END_VAR"
    assert parsed.pous[1].body == "y := Twice(g);"


@pytest.mark.parametrize(
    "text, message, line, column",
    [
        ("PROGRAM Main\nx := 1;\n", "PROGRAM without END_PROGRAM", 1, 1),
        ("PROGRAM Main\nVAR x : INT;\nx := 1;\nEND_PROGRAM\n", "VAR without END_VAR", 2, 1),
        ("x := 1;\n", "unexpected 'x' outside any POU or TYPE block", 1, 1),
        ("FUNCTION F\nEND_FUNCTION\n", "FUNCTION F needs a return type ': TYPE' on its first line", 1, 1),
    ],
)
def test_structure_errors_are_located(text: str, message: str, line: int, column: int) -> None:
    with pytest.raises(StTextError) as err:
        split_source(text)
    assert (err.value.reason, err.value.line, err.value.column) == (message, line, column)
