"""The IL front end: layout (IL-01..IL-03), every operator of the tables (IL-03, IL-20..IL-24) and the located
diagnostics of the typed accumulator (IL-05, IL-25, IL-26)."""

from __future__ import annotations

import pytest

from ladderlab.st.il_parser import parse_il
from ladderlab.st.il_words import looks_like_il
from ladderlab.st.project_text import source_to_project
from tests.ir.helpers import errors


def test_layout_labels_comments_and_empty_lines_il01_il02_il03():
    """IL-01..03: one instruction per line, a label before an instruction or alone (it labels the next one),
    comments last on a line in both styles, comment-only and empty lines; operands separated by commas."""
    body = parse_il(
        "Step1: LD %X1.2 // load\n"
        "      AND tmp1  (* AND temporary variable *)\n"
        "\n"
        "              (* empty instruction *)\n"
        "Step2:\n"
        "      LIMIT A, 5\n"
        "end:\n"
    )
    assert body.diagnostics == []
    shapes = [
        ([name for name, _ in i.labels], i.operator, len(i.operands), i.span.line, i.span.column)
        for i in body.body.instructions
    ]
    assert shapes == [(["Step1"], "LD", 1, 1, 8), ([], "AND", 1, 2, 7), (["Step2"], "LIMIT", 2, 6, 7)]
    assert [name for name, _ in body.body.trailing_labels] == ["end"]


def test_every_operator_and_modifier_of_the_table_parses_il03():
    """IL-03 (seed 003's table) and IL-24 (MOD(, NOT, &, &N, FB input operators): each word is read with its
    modifiers; ``(`` defers only the operators of the tables."""
    words = [
        "LD",
        "LDN",
        "ST",
        "STN",
        "S",
        "R",
        "AND",
        "ANDN",
        "OR",
        "ORN",
        "XOR",
        "XORN",
        "ADD",
        "SUB",
        "MUL",
        "DIV",
        "MOD",
        "GT",
        "GE",
        "EQ",
        "NE",
        "LE",
        "LT",
        "&",
        "&N",
        "JMP",
        "JMPC",
        "JMPCN",
        "CAL",
        "CALC",
        "CALCN",
        "S1",
        "R1",
        "CLK",
        "CU",
        "CD",
        "PV",
        "IN",
        "PT",
    ]
    text = "\n".join(f"{word} x" for word in words)
    deferred = "AND( x\nANDN( x\nOR( x\nORN( x\nXOR( x\nXORN( x\nADD( x\nSUB( x\nMUL( x\nDIV( x\nMOD( x\n"
    deferred += "GT( x\nGE( x\nEQ( x\nNE( x\nLE( x\nLT( x\n"
    result = parse_il(text + "\n" + deferred + ")\nRET\nRETC\nRETCN\nNOT")
    assert result.diagnostics == []
    instructions = result.body.instructions
    assert [i.operator for i in instructions[: len(words)]] == [w.upper() for w in words]
    assert all(i.deferred for i in instructions[len(words) : len(words) + 17])
    assert [i.operator for i in instructions[-5:]] == [")", "RET", "RETC", "RETCN", "NOT"]


def test_calls_keep_formal_and_informal_arguments_il31_il33():
    result = parse_il("CAL timer( IN := in1, PT := T#10m12s, Q => out1)\nUserFun( Count, 100, 1000)\nCAL t2")
    cal, fun, plain = result.body.instructions
    assert [(a.name, a.output) for a in cal.call.args] == [("IN", False), ("PT", False), ("Q", True)]
    assert [a.name for a in fun.call.args] == [None, None, None] and fun.operator == "USERFUN"
    assert plain.call is None and plain.operands[0].name == "t2"


@pytest.mark.parametrize(
    "body, il",
    [
        ("LD a\nST b", True),
        ("start:\n  LD a", True),
        ("(* header *)\n  CAL t1(IN := a)", True),
        ("  NOT\n", True),
        ("a := b;", False),
        ("IF a THEN b := 1; END_IF", False),
        ("R(x);", False),
        ("LD := 3;", False),
        ("S := a.b;", False),
        ("    r REF= counter;\n    value := r^;", False),  # CODESYS's REF= (ironplc's reference_to.st)
        ("", False),
    ],
)
def test_il_bodies_are_recognised_by_their_first_instruction(body, il):
    """Issue 26: in an IEC source file a POU whose body is IL is recognised as IL, beside ST POUs."""
    assert looks_like_il(body) is il


def test_source_file_with_il_and_st_pous_and_types():
    """A file with a TYPE, an ST POU, an IL POU and a CONFIGURATION: languages and bodies kept, lines kept."""
    text = (
        "TYPE S : STRUCT a : INT; END_STRUCT; END_TYPE\n"
        "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nTwice := 2 * x;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR r : INT; END_VAR\n  LD 4\n  Twice\n  ST r\nEND_PROGRAM\n"
        "CONFIGURATION C RESOURCE R ON PLC TASK T (INTERVAL := T#20ms); PROGRAM M WITH T : Main; "
        "END_RESOURCE END_CONFIGURATION\n"
    )
    project, diagnostics = source_to_project(text)
    assert diagnostics == []
    assert [(p.name, p.language) for p in project.pous] == [("Twice", "st"), ("Main", "il")]
    assert project.pous[1].body.split("\n")[7:10] == ["  LD 4", "  Twice", "  ST r"]
    (resource,) = project.configuration.resources
    assert [(task.name, [(p.name, p.type) for p in task.programs]) for task in resource.tasks] == [
        ("T", [("M", "Main")])
    ]


def _errors(body: str, declarations: str = "i : INT; b : BOOL; t : TON;", extra: str = "") -> list[str]:
    return errors(f"PROGRAM P\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n{extra}")


@pytest.mark.parametrize(
    "body, expected",
    [
        (
            "LD i\nADD b\nST i",
            "P/body:4:1, POU P: error IL-TYPE: ADD b: the accumulator holds INT, the operand is BOOL",
        ),
        ("LD i\nST b", "P/body:4:1, POU P: error IL-TYPE: ST b: the accumulator holds INT, b is BOOL"),
        (
            "LD i\nADD( IN1 := 2\n)\nST i",
            "P/body:4:6, POU P: error IL-PARSE: IL operands are values, not 'name := value' assignments",
        ),
        ("ST i", "P/body:3:1, POU P: error IL-NO-CR: ST needs a value in the accumulator: load one first (LD)"),
        ("LD b\nJMPC nowhere", "P/body:4:1, POU P: error IL-LABEL: there is no label 'nowhere' in P"),
        ("LD i\nADD( 2", "P/body:4:1, POU P: error IL-PAREN: 'ADD(' is never closed with ')'"),
        ("LD i\n)", "P/body:4:1, POU P: error IL-PAREN: ')' without an operator with '(' before it"),
        (
            "LD i\nADDD 3",
            "P/body:4:1, POU P: error IL-UNKNOWN-OPERATOR: 'ADDD' is not an IL operator or a function"
            " - did you mean 'ADD'?",
        ),
        ("LD i\nS b", "P/body:4:1, POU P: error IL-TYPE: S needs a BOOL accumulator, but it holds INT"),
        ("LD i\nJMPC l\nl:", "P/body:4:1, POU P: error IL-TYPE: JMPC needs a BOOL accumulator, but it holds INT"),
        ("l:\nLD i\nl: ST i", "P/body:5:1, POU P: error IL-LABEL: the label 'l' is already defined on line 3"),
        ("LD i\nADD( 1\nJMP l\n)\nl:", "P/body:5:1, POU P: error IL-PAREN: JMP cannot jump out of '(' ... ')'"),
        ("LDN i\nST i", "P/body:3:1, POU P: error IL-TYPE: LDN negates i, which is INT, not a bit string"),
        ("LD b\nIN i", "P/body:4:1, POU P: error IL-OPERAND: IN needs a function block instance with an input IN"),
        ("LD b\nST", "P/body:4:1, POU P: error IL-OPERAND: ST takes one operand"),
        ("LD i, ,", "P/body:3:7, POU P: error ST-PARSE: expected an expression, found ','"),
        ("LD i\nRET i", "P/body:4:1, POU P: error IL-OPERAND: RET takes no operand, not 1"),
        (
            "LD b\nJMPC l\nLD i\nl: ST i",
            "P/body:6:4, POU P: error IL-CR-TYPE: ST reads the accumulator, but at label l it is INT and BOOL on "
            "different paths: load a value (LD) after the label",
        ),
        (
            "LD i\nl: ST i\nLD b\nJMPC l",
            "P/body:6:1, POU P: error IL-CR-TYPE: JMPC l: the accumulator is BOOL here but INT where label l reads "
            "it: load a value (LD) after the label",
        ),
        (
            "LD t\nST t",
            "P/body:3:1, POU P: error IL-CR-TYPE: the accumulator cannot hold TON: load an elementary or "
            "user-typed value",
        ),
    ],
)
def test_located_diagnostics_name_the_accumulator_type_il25(body, expected):
    """IL-25 / IL-26: one located error per mistake (line and column of the instruction, the accumulator's type)."""
    assert _errors(body) == [expected]


def test_loops_with_a_consistent_accumulator_are_accepted_il25():
    """IL-25: a backward jump whose accumulator type agrees with the label's (here: the label loads) is fine."""
    assert _errors("LD 0\nST i\nl: LD i\nADD 1\nST i\nLT 10\nJMPC l") == []
