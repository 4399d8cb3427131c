"""Appendix B of seed 003 (spec §7.4, APB-01..APB-09, IL-04): each operator's IL column against its ST column.

Both forms run as separate programs with the same inputs scan by scan and must give the same outputs; where the
seed (or the spec's ``[DERIVED]`` vectors) states a result, that result is checked too.
"""

from __future__ import annotations

import math

import pytest

from ladderlab.engine.simulation import Simulation
from tests.ir.helpers import lower_ok

# name, declarations, ST, IL, scans (inputs per scan), stated X per scan (None: none stated)
ROWS = [
    ("assign", "A, X : BOOL;", "X := A;", "LD A\nST X", [{"A": True}, {"A": False}], [True, False]),
    ("negated", "A, X : BOOL;", "X := NOT(A);", "LDN A\nST X", [{"A": True}, {"A": False}], [False, True]),
    (
        "S",
        "A, X : BOOL;",
        "IF A THEN X := TRUE; END_IF",
        "LD A\nS X",
        [{"A": False}, {"A": True}, {"A": False}],
        [False, True, True],
    ),
    (
        "R",
        "A : BOOL; X : BOOL := TRUE;",
        "IF A THEN X := FALSE; END_IF",
        "LD A\nR X",
        [{"A": False}, {"A": True}, {"A": False}],
        [True, False, False],
    ),
    ("AND", "A, B : WORD; X : WORD;", "X := A AND B;", "LD A\nAND B\nST X", [{"A": 0x00FF, "B": 0x0F0F}], [0x000F]),
    ("OR", "A, B : WORD; X : WORD;", "X := A OR B;", "LD A\nOR B\nST X", [{"A": 0x00FF, "B": 0x0F0F}], [0x0FFF]),
    ("XOR", "A, B : WORD; X : WORD;", "X := A XOR B;", "LD A\nXOR B\nST X", [{"A": 0x00FF, "B": 0x0F0F}], [0x0FF0]),
    ("NOT", "A : WORD; X : WORD;", "X := NOT(A);", "LD A\nSTN X", [{"A": 0x00FF}], [0xFF00]),
    ("ROL", "A : BYTE := 2#1001_0110; X : BYTE;", "X := ROL(A, 3);", "LD A\nROL 3\nST X", [{}], [0xB4]),
    ("ROR", "A : BYTE := 2#1001_0110; X : BYTE;", "X := ROR(A, 1);", "LD A\nROR 1\nST X", [{}], [0x4B]),
    ("SHR", "A : BYTE := 2#1001_0110; X : BYTE;", "X := SHR(A, 4);", "LD A\nSHR 4\nST X", [{}], [0x09]),
    ("SHL", "A : BYTE := 2#1001_0110; X : BYTE;", "X := SHL(A, 1);", "LD A\nSHL 1\nST X", [{}], [0x2C]),
    *[
        (
            op,
            "A, B : INT; X : BOOL;",
            f"X := (A {symbol} B);",
            f"LD A\n{op} B\nST X",
            [{"A": 3, "B": 5}, {"A": 5, "B": 5}],
            stated,
        )
        for op, symbol, stated in [
            ("LT", "<", [True, False]),
            ("LE", "<=", [True, True]),
            ("GE", ">=", [False, True]),
            ("GT", ">", [False, False]),
            ("NE", "<>", [True, False]),
            ("EQ", "=", [False, True]),
        ]
    ],
    ("compare REAL", "A, B : REAL; X : BOOL;", "X := (A < B);", "LD A\nLT B\nST X", [{"A": 3.0, "B": 5.0}], [True]),
    ("compare TIME", "A, B : TIME; X : BOOL;", "X := (A >= B);", "LD A\nGE B\nST X", [{"A": 5, "B": 5}], [True]),
    (
        "compare STRING",
        "A, B : STRING; X : BOOL;",
        "X := (A <= B);",
        "LD A\nLE B\nST X",
        [{"A": "3", "B": "5"}],
        [True],
    ),
    ("MOD", "X : INT;", "X := 12 MOD 8;", "LD 12\nMOD 8\nST X", [{}], [4]),
    ("MOD negative", "A : INT := -7; X : INT;", "X := A MOD 2;", "LD A\nMOD 2\nST X", [{}], [-1]),
    ("MUL", "A, B, X : INT;", "X := A * B;", "LD A\nMUL B\nST X", [{"A": 6, "B": -7}], [-42]),
    ("DIV", "A, X : INT;", "X := A / 8;", "LD A\nDIV 8\nST X", [{"A": 20}, {"A": -7 * 8 - 7}], [2, -7]),
    ("SUB", "A, X : INT;", "X := A - 4;", "LD A\nSUB 4\nST X", [{"A": 20}], [16]),
    ("ADD", "A, X : INT;", "X := A + 1;", "LD A\nADD 1\nST X", [{"A": 20}], [21]),
    ("SQRT", "A, X : REAL;", "X := SQRT(A);", "LD A\nSQRT\nST X", [{"A": 25.0}], [5.0]),
    ("EXPT", "A, X : REAL;", "X := EXPT(A, 3);", "LD A\nEXPT 3\nST X", [{"A": 2.0}], [8.0]),
    ("TRUNC", "A : REAL; X : DINT;", "X := TRUNC(A);", "LD A\nTRUNC\nST X", [{"A": 4.32}, {"A": -4.32}], [4, -4]),
    ("ABS", "A, X : REAL;", "X := ABS(A);", "LD A\nABS\nST X", [{"A": -12.0}], [12.0]),
    ("LOG", "A, X : REAL;", "X := LOG(A);", "LD A\nLOG\nST X", [{"A": 1000.0}], [3.0]),
    ("LN", "A, X : REAL;", "X := LN(A);", "LD A\nLN\nST X", [{"A": 7.389}], [2.0]),
    ("EXP", "A, X : REAL;", "X := EXP(A);", "LD A\nEXP\nST X", [{"A": 2.0}], [7.389]),
    *[
        (fn, "A, X : REAL;", f"X := {fn}(A);", f"LD A\n{fn}\nST X", [{"A": a}], [x])
        for fn, a, x in [
            ("SIN", 0.0, 0.0),
            ("COS", 0.0, 1.0),
            ("TAN", 0.7853982, 1.0),
            ("ASIN", 1.0, 1.570796),
            ("ACOS", 1.0, 0.0),
            ("ATAN", 1.0, 0.7853982),
        ]
    ],
    (
        "MUX",
        "A : INT; B : INT := 77; X : INT;",
        "X := MUX(A, 0, 10, B);",
        "LD A\nMUX 0, 10, B\nST X",
        [{"A": 0}, {"A": 1}, {"A": 2}],
        [0, 10, 77],
    ),
    (
        "LIMIT",
        "A, X : INT;",
        "X := LIMIT(-8, A, 5);",
        "LD -8\nLIMIT A, 5\nST X",
        [{"A": -20}, {"A": 9}, {"A": 3}],
        [-8, 5, 3],
    ),
    (
        "SEL",
        "A : BOOL; B : INT := 77; X : INT;",
        "X := SEL(A, 10, B);",
        "LD A\nSEL 10, B\nST X",
        [{"A": False}, {"A": True}],
        [10, 77],
    ),
    ("MAX", "A, X : INT;", "X := MAX(A, 1);", "LD A\nMAX 1\nST X", [{"A": -4}], [1]),
    ("MIN", "A, B, X : INT;", "X := MIN(A, B);", "LD A\nMIN B\nST X", [{"A": 7, "B": 2}], [2]),
]


def _program(declarations: str, body: str) -> Simulation:
    return Simulation(lower_ok(f"PROGRAM P\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n"))


def _same(a: object, b: object) -> bool:
    if isinstance(a, float) or isinstance(b, float):
        return math.isclose(a, b, abs_tol=1e-4)  # type: ignore[arg-type]  # APB-07's tolerance
    return a == b


@pytest.mark.parametrize("name, declarations, st, il, scans, stated", ROWS, ids=[row[0] for row in ROWS])
def test_il_column_equals_st_column_apb10_il04(name, declarations, st, il, scans, stated):
    """APB-10 / IL-04: the IL form gives the ST form's outputs scan by scan, and the results the seed states."""
    st_sim, il_sim = _program(declarations, st), _program(declarations, il)
    for inputs, expected in zip(scans, stated, strict=True):
        for sim in (st_sim, il_sim):
            for variable, value in inputs.items():
                sim.write(f"P.{variable}", value)
            sim.cycle()
            assert sim.fault is None, sim.fault
        st_x, il_x = st_sim.read("P.X"), il_sim.read("P.X")
        assert _same(il_x, st_x), (inputs, st_x, il_x)
        assert _same(il_x, expected), (inputs, il_x, expected)
