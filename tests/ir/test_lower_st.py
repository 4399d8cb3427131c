"""ST statements -> IR statements: exact trees with origins (ST-20..37, ST-50..80, VAR-22, docs/ir.md)."""

from __future__ import annotations

from ladderlab.ir import nodes as ir
from ladderlab.ir.types import Array, Elementary, Enum, FbInstance
from tests.ir.helpers import BOOL, DINT, INT, REAL, TIME, WORD, at, const, errors, local, lower_ok, program_body

I, D, B, Q, R = local("I", INT), local("D", DINT), local("B", BOOL), local("Q", BOOL), local("R", REAL)
T1 = local("T1", FbInstance("TON"))


def test_assignments_to_elements_fields_and_fb_inputs_st20():
    statements = program_body(
        "i : INT; a : ARRAY [0..2] OF INT; p : TPoint; t1 : TON;",
        "a[i] := 1;\np.y := 2.5;\nt1.PT := T#3s;",
        "TYPE TPoint : STRUCT x : REAL; y : REAL; END_STRUCT; END_TYPE",
    )
    assert statements == [
        ir.Assign(local("A", INT, ir.Index((I,))), const(1, INT), at(3, 1, 3, 10)),
        ir.Assign(local("P", REAL, ir.Member("Y")), const(2.5, REAL), at(4, 1, 4, 11)),
        ir.Assign(local("T1", TIME, ir.Member("PT")), const(3000, TIME), at(5, 1, 5, 14)),
    ]


def test_fb_call_with_inputs_outputs_and_positional_arguments_st25():
    statements = program_body(
        "t1 : TON; b : BOOL; et : TIME;", "t1(IN := b, PT := T#5s, Q => b, ET => et);\nt1(b, T#1s);"
    )
    assert statements == [
        ir.FbCall(T1, [("IN", B), ("PT", const(5000, TIME))], [("Q", B), ("ET", local("ET", TIME))], at(3, 1, 3, 42)),
        ir.FbCall(T1, [("IN", B), ("PT", const(1000, TIME))], [], at(4, 1, 4, 12)),
    ]


def test_fb_call_negated_and_widened_outputs_are_assigns_after_the_call():
    statements = program_body("c : CTU; q : BOOL; cv : DINT; go : BOOL;", "c(CU := go, PV := 3, NOT Q => q, CV => cv);")
    counter = local("C", FbInstance("CTU"))
    assert statements == [
        ir.FbCall(counter, [("CU", local("GO", BOOL)), ("PV", const(3, INT))], [], at(3, 1, 3, 43)),
        ir.Assign(Q, ir.Unary("NOT", local("C", BOOL, ir.Member("Q")), BOOL), at(3, 22, 3, 32)),
        ir.Assign(local("CV", DINT), ir.Convert(local("C", INT, ir.Member("CV")), INT, DINT), at(3, 34, 3, 42)),
    ]


def test_fb_call_with_en_eno_guards_the_copies():
    statements = program_body(
        "t1 : TON; b : BOOL; ok : BOOL; n : BOOL;", "t1(EN := b, IN := TRUE, ENO => ok, NOT Q => n);"
    )
    copy = ir.Assign(local("N", BOOL), ir.Unary("NOT", local("T1", BOOL, ir.Member("Q")), BOOL), at(3, 36, 3, 46))
    assert statements == [
        ir.FbCall(T1, [("IN", const(True, BOOL))], [], at(3, 1, 3, 47), B, local("OK", BOOL)),
        ir.If([(local("OK", BOOL), [copy])], [], at(3, 1, 3, 47)),
    ]


def test_user_fb_call_binds_inputs_in_outs_and_outputs():
    program = lower_ok("""FUNCTION_BLOCK Acc
VAR_INPUT x : INT; END_VAR
VAR_IN_OUT total : DINT; END_VAR
VAR_OUTPUT n : INT; END_VAR
total := total + x; n := n + 1;
END_FUNCTION_BLOCK
PROGRAM P
VAR a : Acc; s : DINT; k : INT; END_VAR
a(x := 4, total := s, n => k);
a(7, s);
END_PROGRAM""")
    acc = local("A", FbInstance("ACC"))
    assert program.pous["P"].blocks[0].statements == [
        ir.FbCall(acc, [("X", const(4, INT)), ("TOTAL", local("S", DINT))], [("N", local("K", INT))], at(9, 1, 9, 30)),
        ir.FbCall(acc, [("X", const(7, INT)), ("TOTAL", local("S", DINT))], [], at(10, 1, 10, 8)),
    ]


def test_function_calls_as_statements_and_with_en_eno():
    statements = program_body(
        "i : INT; b : BOOL; ok : BOOL;",
        "i := ADD(EN := b, IN1 := i, IN2 := 1, ENO => ok);\nLIMIT(0, i, 5);\ni := MUL(i, 2, ENO => ok);",
    )
    add = ir.Call("ADD", (I, const(1, INT)), (INT, INT), INT)
    assert statements == [
        ir.FnCall(add, I, at(3, 1, 3, 49), B, local("OK", BOOL)),
        ir.FnCall(ir.Call("LIMIT", (const(0, INT), I, const(5, INT)), (INT,) * 3, INT), None, at(4, 1, 4, 15)),
        ir.FnCall(ir.Call("MUL", (I, const(2, INT)), (INT, INT), INT), I, at(5, 1, 5, 26), None, local("OK", BOOL)),
    ]


def test_if_elsif_else_st27():
    statements = program_body(
        "code : INT; result : INT;",
        "IF code >= 100 THEN result := 2;\nELSIF code >= 10 THEN result := 1;\nELSE result := 0; END_IF;",
    )
    code, result = local("CODE", INT), local("RESULT", INT)
    assert statements == [
        ir.If(
            [
                (ir.Binary("GE", code, const(100, INT), BOOL), [ir.Assign(result, const(2, INT), at(3, 21, 3, 32))]),
                (ir.Binary("GE", code, const(10, INT), BOOL), [ir.Assign(result, const(1, INT), at(4, 23, 4, 34))]),
            ],
            [ir.Assign(result, const(0, INT), at(5, 6, 5, 17))],
            at(3, 1, 5, 25),
        )
    ]  # the span ends with END_IF


def test_case_with_lists_ranges_constants_and_enums_st28():
    statements = program_body(
        "code : INT; c : TColor; r : INT;",
        "CASE code OF\n20, 77: r := 1;\n21..55, LIMIT_A: r := 2;\n-5..-1: r := 3;\nELSE r := 4;\nEND_CASE;\n"
        "CASE c OF red: r := 0; blue: r := 6; END_CASE;",
        "TYPE TColor : (red, green := 5, blue); END_TYPE\nVAR_GLOBAL CONSTANT LIMIT_A : INT := 100; END_VAR",
    )
    r = local("R", INT)
    color = Enum("TCOLOR", (("red", 0), ("green", 5), ("blue", 6)))  # the values as declared
    assert statements == [
        ir.Case(
            local("CODE", INT),
            [
                ([20, 77], [ir.Assign(r, const(1, INT), at(4, 9, 4, 15))]),
                ([(21, 55), 100], [ir.Assign(r, const(2, INT), at(5, 18, 5, 24))]),
                ([(-5, -1)], [ir.Assign(r, const(3, INT), at(6, 9, 6, 15))]),
            ],
            [ir.Assign(r, const(4, INT), at(7, 6, 7, 12))],
            at(3, 1, 8, 9),
        ),
        ir.Case(
            local("C", color),
            [
                ([0], [ir.Assign(r, const(0, INT), at(9, 16, 9, 22))]),
                ([6], [ir.Assign(r, const(6, INT), at(9, 30, 9, 36))]),
            ],
            [],
            at(9, 1, 9, 46),
        ),
    ]


def test_for_loops_with_and_without_by_and_exit_st30():
    statements = program_body(
        "i : INT; d : DINT; n : INT;",
        "FOR i := 1 TO n BY 2 DO d := d + 1; EXIT; END_FOR;\nFOR d := 10 TO 1 BY -1 DO ; END_FOR;",
    )
    assert statements == [
        ir.For(
            I,
            const(1, INT),
            local("N", INT),
            const(2, INT),
            [
                ir.Assign(D, ir.Binary("ADD", D, const(1, DINT), DINT), at(3, 25, 3, 35)),
                ir.Exit(at(3, 37, 3, 41)),
            ],
            at(3, 1, 3, 50),
        ),
        ir.For(
            D, const(10, DINT), const(1, DINT), const(-1, DINT), [], at(4, 1, 4, 36)
        ),  # the empty statement is dropped
    ]


def test_for_without_by_steps_by_one_of_the_variable_type():
    (loop,) = program_body("k : SINT;", "FOR k := 0 TO 3 DO END_FOR;")
    assert loop.step == const(1, Elementary("SINT")) and loop.body == []


def test_while_repeat_return_st32_st36():
    statements = program_body(
        "i : INT; b : BOOL;",
        "WHILE i < 10 DO i := i + 1; END_WHILE;\nREPEAT i := i - 1; UNTIL i <= 0 END_REPEAT;\n"
        "IF b THEN RETURN; END_IF;",
    )
    assert statements == [
        ir.While(
            ir.Binary("LT", I, const(10, INT), BOOL),
            [ir.Assign(I, ir.Binary("ADD", I, const(1, INT), INT), at(3, 17, 3, 27))],
            at(3, 1, 3, 38),
        ),
        ir.Repeat(
            [ir.Assign(I, ir.Binary("SUB", I, const(1, INT), INT), at(4, 8, 4, 18))],
            ir.Binary("LE", I, const(0, INT), BOOL),
            at(4, 1, 4, 43),
        ),
        ir.If([(B, [ir.Return(at(5, 11, 5, 17))])], [], at(5, 1, 5, 25)),
    ]


def test_function_result_slot_and_assignment_st22():
    program = lower_ok("FUNCTION Half : REAL\nVAR_INPUT x : REAL; END_VAR\nHalf := x / 2.0;\nEND_FUNCTION\n")
    half = program.pous["HALF"]
    assert (half.kind, half.return_type, half.slots[-1]) == ("function", REAL, ir.Slot("HALF", "VAR_OUTPUT", REAL, 0.0))
    assert half.blocks == [
        ir.Block(
            [
                ir.Assign(
                    local("HALF", REAL),
                    ir.Binary("DIV", local("X", REAL), const(2.0, REAL), REAL),
                    at(3, 1, 3, 16, "HALF"),
                )
            ],
            at(3, 1, 3, 16, "HALF"),
        )
    ]


def test_bit_assignment_of_an_integer_goes_through_its_bit_string():
    (statement,) = program_body("d : DINT; b : BOOL;", "d.31 := b;")
    bits = ir.Call("DINT_TO_DWORD", (D,), (DINT,), Elementary("DWORD"))
    dword = Elementary("DWORD")
    updated = ir.Call(
        "SEL",
        (
            B,
            ir.Binary("AND", bits, const(0x7FFFFFFF, dword), dword),
            ir.Binary("OR", bits, const(0x80000000, dword), dword),
        ),
        (BOOL, dword, dword),
        dword,
    )
    assert statement == ir.Assign(D, ir.Call("DWORD_TO_DINT", (updated,), (dword,), DINT), at(3, 1, 3, 10))


def test_bit_assignment_st20():
    (statement,) = program_body("w : WORD; b : BOOL;", "w.2 := b;")
    w = local("W", WORD)
    assert statement == ir.Assign(
        w,
        ir.Call(
            "SEL",
            (B, ir.Binary("AND", w, const(0xFFFB, WORD), WORD), ir.Binary("OR", w, const(4, WORD), WORD)),
            (BOOL, WORD, WORD),
            WORD,
        ),
        at(3, 1, 3, 9),
    )


def test_edge_inputs_read_a_hidden_edge_flag_var22():
    program = lower_ok("""FUNCTION_BLOCK Edges
VAR_INPUT up : BOOL R_EDGE; down : BOOL F_EDGE; END_VAR
VAR_OUTPUT n : INT; END_VAR
IF up OR down THEN n := n + 1; END_IF;
END_FUNCTION_BLOCK""")
    pou = program.pous["EDGES"]
    hidden = [(s.name, s.var_class, s.initial) for s in pou.slots if s.hidden]
    assert hidden == [
        ("__UP_R_EDGE_M", "VAR", False),
        ("__UP_R_EDGE", "VAR_TEMP", False),
        ("__DOWN_F_EDGE_M", "VAR", False),
        ("__DOWN_F_EDGE", "VAR_TEMP", False),
    ]
    up, down = local("UP", BOOL), local("DOWN", BOOL)
    up_m, up_e, down_m, down_e = (local(name, BOOL) for name, *_ in hidden)
    bare = ir.Origin("EDGES")
    n = local("N", INT)
    assert pou.blocks[0].statements == [
        ir.Assign(up_e, ir.Binary("AND", up, ir.Unary("NOT", up_m, BOOL), BOOL), bare),
        ir.Assign(up_m, up, bare),
        ir.Assign(down_e, ir.Binary("AND", ir.Unary("NOT", down, BOOL), down_m, BOOL), bare),
        ir.Assign(down_m, down, bare),
        ir.If(
            [
                (
                    ir.Binary("OR", up_e, down_e, BOOL),
                    [ir.Assign(n, ir.Binary("ADD", n, const(1, INT), INT), at(4, 20, 4, 30, "EDGES"))],
                )
            ],
            [],
            at(4, 1, 4, 38, "EDGES"),
        ),
    ]


def test_globals_and_externals_are_global_accesses():
    program = lower_ok("""VAR_GLOBAL g : INT; arr : ARRAY [1..2] OF BOOL; END_VAR
PROGRAM P
VAR_EXTERNAL g : INT; END_VAR
g := g + 1;
arr[2] := TRUE;
END_PROGRAM""")
    g = ir.Var("global", "G", INT)
    assert program.pous["P"].slots == []
    assert program.pous["P"].blocks[0].statements == [
        ir.Assign(g, ir.Binary("ADD", g, const(1, INT), INT), at(4, 1, 4, 11)),
        ir.Assign(ir.Var("global", "ARR", BOOL, (ir.Index((const(2, INT),)),)), const(True, BOOL), at(5, 1, 5, 15)),
    ]
    assert Array(BOOL, ((1, 2),)) == program.globals[1].type


def test_a_bad_statement_is_dropped_with_a_diagnostic_and_the_rest_lowers():
    text = (
        "PROGRAM P\nVAR i : INT; b : BOOL; END_VAR\ni := 1;\n"
        "IF b THEN i := 2; ELSIF LIMIT(EN := b, MN := 0, IN := i, MX := 3) > 1 THEN i := 3; END_IF;\n"
        "i := 4;\nEND_PROGRAM\n"
    )
    assert errors(text) == [
        "P/body:4:25, POU P: error IR-EN-CALL: a call with EN or ENO cannot be evaluated here in "
        "the right order: assign its result to a variable in a statement of its own first"
    ]
