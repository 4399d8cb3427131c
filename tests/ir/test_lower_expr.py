"""Typed ST expressions -> IR expressions: exact trees, conversions inserted, argument order (docs/ir.md)."""

from __future__ import annotations

from hypothesis import assume, given
from hypothesis import strategies as st

from ladderlab.iec.values import f32
from ladderlab.ir import nodes as ir
from ladderlab.ir.context import PouContext
from ladderlab.ir.lower_expr import lower_expr
from ladderlab.ir.types import Elementary, Enum, Reference, Subrange
from ladderlab.st.checker import check_operand, check_project
from ladderlab.st.project_text import source_to_project
from tests.ir.helpers import (
    BOOL,
    BYTE,
    DATE,
    DINT,
    DT,
    INT,
    LREAL,
    REAL,
    SINT,
    STRING,
    TIME,
    TOD,
    WORD,
    const,
    errors,
    local,
    program_body,
)

DECLS = " ".join(
    [
        "i",
        ":",
        "INT;",
        "j",
        ":",
        "INT;",
        "si",
        ":",
        "SINT;",
        "d",
        ":",
        "DINT;",
        "r",
        ":",
        "REAL;",
        "lr",
        ":",
        "LREAL;",
        "b",
        ":",
        "BOOL;",
        "w",
        ":",
        "WORD;",
        "bt",
        ":",
        "BYTE;",
        "t",
        ":",
        "TIME;",
        "tod1",
        ":",
        "TOD;",
        "dt1",
        ":",
        "DT;",
        "day",
        ":",
        "DATE;",
        "s",
        ":",
        "STRING[10];",
        "s2",
        ":",
        "STRING;",
        "arr",
        ":",
        "ARRAY",
        "[1..3]",
        "OF",
        "INT;",
        "t1",
        ":",
        "TON;",
        "pc",
        ":",
        "INT",
        "(0..100);",
        "c",
        ":",
        "TColor;",
    ]
)  # one line: bodies start on line 3
TYPES = "TYPE TColor : (red, green := 5, blue); END_TYPE"

I, J, D, R, B, W, S = (
    local("I", INT),
    local("J", INT),
    local("D", DINT),
    local("R", REAL),
    local("B", BOOL),
    local("W", WORD),
    local("S", Elementary("STRING", 10)),
)


def value(expression: str, target: str = "i", decls: str = DECLS, extra: str = TYPES) -> ir.Expr:
    """The IR of ``expression`` assigned to ``target`` in a program with the declarations above."""
    (statement,) = program_body(decls, f"{target} := {expression};", extra)
    assert isinstance(statement, ir.Assign)
    return statement.value


def test_operators_on_one_type():
    assert value("i + j * 2") == ir.Binary("ADD", I, ir.Binary("MUL", J, const(2, INT), INT), INT)
    assert value("NOT b AND i > 3", "b") == ir.Binary(
        "AND", ir.Unary("NOT", B, BOOL), ir.Binary("GT", I, const(3, INT), BOOL), BOOL
    )
    assert value("-i") == ir.Unary("NEG", I, INT)
    assert value("i MOD 7 <> 0", "b") == ir.Binary("NE", ir.Binary("MOD", I, const(7, INT), INT), const(0, INT), BOOL)


def test_implicit_widening_inserts_convert():
    assert value("i + d", "d") == ir.Binary("ADD", ir.Convert(I, INT, DINT), D, DINT)
    assert value("i", "d") == ir.Convert(I, INT, DINT)
    assert value("si", "i") == ir.Convert(local("SI", SINT), SINT, INT)
    assert value("r * lr", "lr") == ir.Binary("MUL", ir.Convert(R, REAL, LREAL), local("LR", LREAL), LREAL)
    assert value("bt", "w") == ir.Convert(local("BT", BYTE), BYTE, WORD)


def test_untyped_literals_take_the_other_operand_type():
    assert value("r + 1", "r") == ir.Binary("ADD", R, const(1.0, REAL), REAL)
    assert value("0.1", "r") == const(f32(0.1), REAL)
    assert value("d > 70000", "b") == ir.Binary("GT", D, const(70000, DINT), BOOL)
    assert value("1 < 2", "b") == ir.Binary("LT", const(1, INT), const(2, INT), BOOL)  # alone: INT (ST-24)
    assert value("-32768") == const(-32768, INT)  # folded, not NEG(32768)
    assert value("3 * 4 - 1", "d") == const(11, DINT)
    assert value("16#FF", "w") == const(255, WORD)


def test_subrange_and_string_lengths_need_no_conversion():
    pc = local("PC", Subrange(INT, 0, 100))
    assert value("pc + i") == ir.Binary("ADD", pc, I, INT)
    assert value("i", "pc") == I
    assert value("s", "s2") == S
    assert value("s = s2", "b") == ir.Binary("EQ", S, local("S2", STRING), BOOL)


def test_names_enums_members_and_indices():
    color = Enum("TCOLOR", (("red", 0), ("green", 5), ("blue", 6)))  # the values as declared
    assert value("blue", "c") == const(6, color)
    assert value("c = TColor#green", "b") == ir.Binary("EQ", local("C", color), const(5, color), BOOL)
    assert value("t1.Q", "b") == local("T1", BOOL, ir.Member("Q"))
    assert value("t1.ET", "t") == local("T1", TIME, ir.Member("ET"))
    assert value("arr[i + 1]") == local("ARR", INT, ir.Index((ir.Binary("ADD", I, const(1, INT), INT),)))


def test_bit_access_reads_a_mask_test():
    assert value("w.3", "b") == ir.Binary("NE", ir.Binary("AND", W, const(8, WORD), WORD), const(0, WORD), BOOL)
    as_word = ir.Call("INT_TO_WORD", (I,), (INT,), WORD)  # AND works on bit strings: same width, same bits
    assert value("i.15", "b") == ir.Binary(
        "NE", ir.Binary("AND", as_word, const(0x8000, WORD), WORD), const(0, WORD), BOOL
    )


def test_time_operators_become_fun85_functions():
    tv, tod, dtv, day = local("T", TIME), local("TOD1", TOD), local("DT1", DT), local("DAY", DATE)
    assert value("t + t", "t") == ir.Binary("ADD", tv, tv, TIME)
    assert value("tod1 + t", "tod1") == ir.Call("ADD_TOD_TIME", (tod, tv), (TOD, TIME), TOD)
    assert value("tod1 - tod1", "t") == ir.Call("SUB_TOD_TOD", (tod, tod), (TOD, TOD), TIME)
    assert value("dt1 - t", "dt1") == ir.Call("SUB_DT_TIME", (dtv, tv), (DT, TIME), DT)
    assert value("day - day", "t") == ir.Call("SUB_DATE_DATE", (day, day), (DATE, DATE), TIME)
    assert value("t * 2", "t") == ir.Call("MUL_TIME", (tv, const(2, INT)), (TIME, INT), TIME)
    assert value("2 * t", "t") == ir.Call("MUL_TIME", (tv, const(2, INT)), (TIME, INT), TIME)  # ST-21, swapped
    assert value("t / r", "t") == ir.Call("DIV_TIME", (tv, R), (TIME, REAL), TIME)
    assert value("t < T#1s", "b") == ir.Binary("LT", tv, const(1000, TIME), BOOL)


def test_string_plus_and_power():
    assert value("s + 'ab'", "s") == ir.Call(
        "CONCAT", (S, const("ab", STRING)), (Elementary("STRING", 10),) * 2, Elementary("STRING", 10)
    )
    assert value("r ** 2", "r") == ir.Binary("EXPT", R, const(2.0, REAL), REAL)
    assert value("r ** i", "r") == ir.Call("EXPT", (R, I), (REAL, INT), REAL)
    assert value("2 ** 3", "lr") == ir.Binary("EXPT", const(2.0, LREAL), const(3.0, LREAL), LREAL)  # FUN-33


def test_standard_function_arguments_in_formal_order():
    limit = ir.Call("LIMIT", (const(0, INT), I, const(9, INT)), (INT, INT, INT), INT)
    assert value("LIMIT(0, i, 9)") == limit
    assert value("LIMIT(MX := 9, IN := i, MN := 0)") == limit  # FUN-05: formal order whatever the written one
    assert value("SEL(b, i, 5)") == ir.Call("SEL", (B, I, const(5, INT)), (BOOL, INT, INT), INT)
    assert value("MUX(2, i, j, 7)") == ir.Call("MUX", (const(2, INT), I, J, const(7, INT)), (INT,) * 4, INT)
    assert value("ADD(i, j, 1, 2)") == ir.Call("ADD", (I, J, const(1, INT), const(2, INT)), (INT,) * 4, INT)
    assert value("MAX(IN2 := d, IN1 := i)", "d") == ir.Call("MAX", (ir.Convert(I, INT, DINT), D), (DINT, DINT), DINT)


def test_missing_formal_inputs_are_defaults_st58():
    assert value("LIMIT(IN := i, MX := 9)") == ir.Call("LIMIT", (const(0, INT), I, const(9, INT)), (INT,) * 3, INT)
    assert value("ADD(IN1 := i, IN3 := 2)") == ir.Call("ADD", (I, const(0, INT), const(2, INT)), (INT,) * 3, INT)


def test_non_generic_pins_keep_their_own_types():
    assert value("SHL(w, 3)", "w") == ir.Call("SHL", (W, const(3, INT)), (WORD, INT), WORD)
    assert value("SHL(w, d)", "w") == ir.Call("SHL", (W, D), (WORD, DINT), WORD)
    assert value("LEFT(s, 2)", "s") == ir.Call("LEFT", (S, const(2, INT)), (STRING, INT), STRING)
    assert value("LEN(s)") == ir.Call("LEN", (S,), (Elementary("STRING", 10),), INT)  # ANY_STRING: as it is
    assert value("MUL_TIME(t, 1.5)", "t") == ir.Call(
        "MUL_TIME", (local("T", TIME), const(1.5, LREAL)), (TIME, LREAL), TIME
    )


def test_conversions_are_calls_and_move_is_its_operand():
    assert value("REAL_TO_INT(r)") == ir.Call("REAL_TO_INT", (R,), (REAL,), INT)
    assert value("INT_TO_REAL(si)", "r") == ir.Call(
        "INT_TO_REAL", (ir.Convert(local("SI", SINT), SINT, INT),), (INT,), REAL
    )
    assert value("TRUNC(r)", "d") == ir.Call("TRUNC", (R,), (REAL,), DINT)
    assert value("MOVE(j)") == J


FUNCTIONS = """FUNCTION Scale : REAL
VAR_INPUT x : REAL; k : REAL := 2.0; n : INT; END_VAR
VAR_IN_OUT acc : DINT; END_VAR
Scale := x * k;
acc := acc + 1;
END_FUNCTION"""


def test_user_function_arguments_in_input_order_with_initial_values_and_in_outs():
    call = ir.Call("SCALE", (R, const(2.0, REAL), const(0, INT)), (REAL, REAL, INT), REAL, True, (D,))
    assert value("Scale(acc := d, x := r)", "r", extra=TYPES + "\n" + FUNCTIONS) == call
    assert value("Scale(r, 2.0, 0, d)", "r", extra=TYPES + "\n" + FUNCTIONS) == call
    assert value("Scale(n := i, x := 1, acc := d)", "r", extra=TYPES + "\n" + FUNCTIONS) == ir.Call(
        "SCALE", (const(1.0, REAL), const(2.0, REAL), I), (REAL, REAL, INT), REAL, True, (D,)
    )


def test_call_with_en_is_lifted_into_a_fncall_before_the_statement():
    first, second = program_body(DECLS, "i := j + ADD(EN := b, IN1 := i, IN2 := 1);", TYPES)
    temp = local("__ADD_RESULT", INT)
    assert first == ir.FnCall(
        ir.Call("ADD", (I, const(1, INT)), (INT, INT), INT), temp, ir.Origin("P", 3, 10, 3, 42), B
    )
    assert second == ir.Assign(I, ir.Binary("ADD", J, temp, INT), ir.Origin("P", 3, 1, 3, 42))


def test_call_with_en_that_cannot_keep_its_order_is_refused():
    body = "WHILE i < LIMIT(EN := b, MN := 0, IN := i, MX := 5) DO i := i + 1; END_WHILE;"
    text = f"PROGRAM P\nVAR {DECLS} END_VAR\n{body}\nEND_PROGRAM\n{TYPES}"
    assert errors(text) == [
        "P/body:3:11, POU P: error IR-EN-CALL: a call with EN or ENO cannot be evaluated here in "
        "the right order: assign its result to a variable in a statement of its own first"
    ]
    user = (
        f"PROGRAM P\nVAR {DECLS} END_VAR\nr := r + Scale(EN := b, x := r, acc := d);\nEND_PROGRAM\n{TYPES}\n{FUNCTIONS}"
    )
    assert errors(user) == [
        "P/body:3:10, POU P: error IR-EN-CALL: a call with EN or ENO cannot be evaluated after "
        "the values this statement computes before it in the right order: assign its result to a "
        "variable in a statement of its own first"
    ]


def test_unsupported_expressions_are_located_errors():
    """A pointer may see another type's bytes only where LadderLab lays them out as CODESYS does (ir/byte_layout.py:
    not a TIME, whose bytes in CODESYS are not the value LadderLab keeps); an INT seen as bytes is a View."""
    text = (
        "PROGRAM P\nVAR i : INT; t : TIME; b : BOOL; q : POINTER TO BYTE; END_VAR\n"
        "b := ADR(i) = ADR(i);\nq := ADR(i);\nq := ADR(t);\nb := q < q;\nEND_PROGRAM\n"
    )
    assert errors(text) == [
        "P/body:5:6, POU P: error IR-UNSUPPORTED: a REF_TO BYTE cannot see a TIME as bytes: a TIME (its bytes in "
        "CODESYS are not the value LadderLab keeps)",
    ]
    compare, view, order = program_body(
        "i : INT; b : BOOL; q : POINTER TO BYTE;", "b := i = i;\nq := ADR(i);\nb := q < q;"
    )
    to_int, to_byte = Reference(INT), Reference(BYTE)
    assert view.value == ir.View(
        ir.AddressOf(local("I", INT), to_int, "ADR(i)"), to_byte, ("int", 2, True), ("int", 1, False)
    )
    assert order.value == ir.Binary("LT", local("Q", to_byte), local("Q", to_byte), BOOL)


def test_sizeof_is_a_constant_in_bytes():
    """TYP-45 as CODESYS counts (ironplc end_to_end_sizeof): widths, STRING[n] n + 1, arrays summed, a STRUCT with
    its padding (ir/byte_layout.py: TPair's a INT at 0..1, padding 2..3, c DINT at 4..7; an enumeration member is
    its base type, INT: a at 0..1, c at 2..3); a STRUCT whose bytes are not the values LadderLab keeps (a TIME
    member) has no SIZEOF."""
    assert value("SIZEOF(i)", "d") == const(2, DINT)
    assert value("SIZEOF(arr)", "d") == const(6, DINT)
    assert value("SIZEOF(LREAL)", "d") == const(8, DINT)
    assert value("SIZEOF(s) + SIZEOF(b)", "d") == ir.Binary("ADD", const(11, DINT), const(1, DINT), DINT)
    assert value(
        "SIZEOF(TPair)", "d", extra=TYPES + "\nTYPE TPair : STRUCT a : INT; c : DINT; END_STRUCT; END_TYPE"
    ) == const(8, DINT)
    assert value(
        "SIZEOF(TPair)", "d", extra=TYPES + "\nTYPE TPair : STRUCT a : INT; c : TColor; END_STRUCT; END_TYPE"
    ) == const(4, DINT)
    refused = "PROGRAM P\nVAR d : DINT; END_VAR\nd := SIZEOF(TPair);\nEND_PROGRAM\n" + TYPES
    assert errors(refused + "\nTYPE TPair : STRUCT a : INT; c : TIME; END_STRUCT; END_TYPE") == [
        "P/body:3:6, POU P: error IR-UNSUPPORTED: SIZEOF is refused for the STRUCT TPAIR, whose member C is a TIME "
        "(its bytes in CODESYS are not the value LadderLab keeps)"
    ]


def test_operand_of_a_diagram_lowers_through_check_operand():
    """The LD/FBD path: check_operand then lower_expr in the POU's context."""
    project, _ = source_to_project("PROGRAM Main\nVAR t1 : TON; n : ARRAY [0..3] OF DINT; END_VAR\nEND_PROGRAM\n")
    checked = check_project(project)
    ctx = PouContext(checked, checked.pou("Main"))
    expr, diagnostics = check_operand(checked, "Main", "n[2]", "DINT")
    assert diagnostics == []
    assert lower_expr(expr, ctx) == ir.Var("local", "N", DINT, (ir.Index((const(2, INT),)),))
    expr, _ = check_operand(checked, "Main", "T#5s", "TIME")
    assert lower_expr(expr, ctx) == const(5000, TIME)
    expr, _ = check_operand(checked, "Main", "3", "DINT")
    assert lower_expr(expr, ctx, DINT) == const(3, DINT)
    assert ctx.diagnostics == []


_INT_OPERANDS = st.sampled_from(["i", "j", "si", "d", "pc", "arr[2]", "5", "-3", "16#7F"])


@given(
    st.recursive(
        _INT_OPERANDS,
        lambda inner: st.builds(
            lambda op, a, b: f"({a} {op} {b})", st.sampled_from(["+", "-", "*", "/", "MOD"]), inner, inner
        ),
        max_leaves=8,
    )
)
def test_integer_expressions_lower_to_one_operand_type(expression):
    """Any mix of SINT/INT/DINT/subrange operands: every Binary's operands are of one type (checked by
    ``lower_ok``'s invariant checker), and the value is widened to the DINT target. (A constant expression
    that divides by zero, ``5 / (5 - 5)``, is refused at compile time: not this test's subject.)"""
    refused = errors(f"PROGRAM P\nVAR {DECLS} END_VAR\nd := {expression};\nEND_PROGRAM\n{TYPES}\n")
    assume(not any("division by zero in a constant expression" in e for e in refused))
    assert value(expression, "d").type == DINT
