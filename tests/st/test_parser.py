"""Parser: one test per construct (exact AST shapes, spans) and the syntax diagnostics."""

from __future__ import annotations

import pytest

from ladderlab.st import ast
from ladderlab.st.parser import parse_declarations, parse_expression, parse_pou, parse_source, parse_statements
from ladderlab.st.types import typing_rules


def expr(text: str) -> ast.Expr:
    result = parse_expression(text)
    assert result.diagnostics == [], result.diagnostics
    return result.ast


def stmts(text: str) -> list[ast.Stmt]:
    result = parse_statements(text)
    assert result.diagnostics == [], result.diagnostics
    return result.ast


def decl(text: str) -> ast.VarDecl:
    result = parse_declarations(f"VAR\n{text}\nEND_VAR")
    assert result.diagnostics == [], result.diagnostics
    return result.ast[0].decls[0]


N, I, B = ast.Name, ast.IntLit, ast.Binary

# ---------------------------------------------------------------- literals (LEX-2x, LEX-3x, LEX-4x, LEX-5x)


@pytest.mark.parametrize(
    "text, value, base",
    [
        ("14", 14, 10),
        ("12_548_756", 12548756, 10),
        ("2#10110111", 183, 2),
        ("8#127", 87, 8),
        ("16#FF", 255, 16),
        ("16#ffff_FFFF", 0xFFFFFFFF, 16),
        ("0852", 852, 10),
    ],
)
def test_lex23_integer_literals(text, value, base):
    assert expr(text) == I(value, base)


@pytest.mark.parametrize(
    "text, value", [("-18.0", -18.0), ("0.123_4", 0.1234), ("4.47E6", 4.47e6), ("652E-2", 6.52), ("1.5e3", 1500.0)]
)
def test_lex23_real_literals(text, value):
    node = expr(text)
    if value < 0:
        assert node == ast.Unary("-", ast.RealLit(-value))
    else:
        assert node == ast.RealLit(value)


@pytest.mark.parametrize(
    "text, type_name, value",
    [
        ("INT#-9", "INT", I(-9)),
        ("USINT#8#127", "USINT", I(87, 8)),
        ("BYTE#16#FF", "BYTE", I(255, 16)),
        ("REAL#2.0", "REAL", ast.RealLit(2.0)),
        ("BOOL#0", "BOOL", I(0)),
        ("BOOL#TRUE", "BOOL", ast.BoolLit(True)),
        ("TColor#red", "TColor", N("red")),
    ],
)
def test_lex20_typed_literals(text, type_name, value):
    assert expr(text) == ast.TypedLit(type_name, value)


@pytest.mark.parametrize("text, value", [("TRUE", True), ("false", False), ("True", True)])
def test_lex25_booleans_any_case(text, value):
    assert expr(text) == ast.BoolLit(value)


@pytest.mark.parametrize(
    "text, value",
    [
        ("''", ""),
        ("'temperature'", "temperature"),
        ("'Character $'A$''", "Character 'A'"),
        ("' End of text $0D$0A'", " End of text \r\n"),
        ("' Price is 12$$'", " Price is 12$"),
        ("'$01$02$10'", "\x01\x02\x10"),
        ("'$L$l$N$P$R$T'", "\n\n\n\f\r\t"),
    ],
)
def test_lex33_string_escapes(text, value):
    assert expr(text) == ast.StringLit(value)


def test_lex35_double_quoted_wstring():
    assert expr('"a$"b$0041"') == ast.StringLit('a"bA', wide=True)


@pytest.mark.parametrize(
    "text, ms",
    [
        ("T#24ms", 24),
        ("t#6m1s", 361_000),
        ("t#8.3s", 8300),
        ("t#7h_24m_5s", 26_645_000),
        ("TIME#416ms", 416),
        ("TIME#12h20m33s", 44_433_000),
        ("T#3d", 259_200_000),
        ("T#0s", 0),
        ("T#-14ms", -14),
        ("T#25h_15m", 90_900_000),
        ("TIME#12:00:00", 43_200_000),
    ],
)
def test_lex43_durations(text, ms):
    assert expr(text) == ast.TimeLit("TIME", ms)


@pytest.mark.parametrize(
    "text, kind, ms",
    [
        ("D#1970-01-02", "DATE", 86_400_000),
        ("DATE#2003-06-21", "DATE", 1_056_153_600_000),
        ("TOD#06:32:15.08", "TIME_OF_DAY", 23_535_080),
        ("TIME_OF_DAY#11:38:52.35", "TIME_OF_DAY", 41_932_350),
        ("DT#2003-06-21-11:38:52.35", "DATE_AND_TIME", 1_056_195_532_350),
        ("DATE_AND_TIME#1970-01-01-00:00:00", "DATE_AND_TIME", 0),
        ("DT#1969-07-21-03:56:00", "DATE_AND_TIME", -14_155_440_000),
    ],
)
def test_lex52_dates_and_times_of_day(text, kind, ms):
    assert expr(text) == ast.TimeLit(kind, ms)


def test_lex34_bad_string_escape_is_a_located_error():
    result = parse_statements("x := 'a$Qb';")
    assert result.ast is None
    [d] = result.diagnostics
    assert (d.code, d.line, d.column) == ("ST-PARSE", 1, 6)
    assert "'$' escape" in d.message


# ---------------------------------------------------------------- expressions and precedence (ST-02, ST-03, ST-33)


@pytest.mark.parametrize(
    "text, shape",
    [
        ("A - B - C", B("-", B("-", N("A"), N("B")), N("C"))),
        ("A ** B ** C", B("**", B("**", N("A"), N("B")), N("C"))),
        ("-x ** 2.0", ast.Unary("-", B("**", N("x"), ast.RealLit(2.0)))),
        ("2 ** -1", B("**", I(2), ast.Unary("-", I(1)))),
        ("a > b AND c < d", B("AND", B(">", N("a"), N("b")), B("<", N("c"), N("d")))),
        ("a < b = c < d", B("=", B("<", N("a"), N("b")), B("<", N("c"), N("d")))),
        ("A OR B AND C", B("OR", N("A"), B("AND", N("B"), N("C")))),
        ("A XOR B AND C", B("XOR", N("A"), B("AND", N("B"), N("C")))),
        ("A OR B XOR C", B("OR", N("A"), B("XOR", N("B"), N("C")))),
        ("NOT A AND B", B("AND", ast.Unary("NOT", N("A")), N("B"))),
        ("A & B", B("AND", N("A"), N("B"))),
        (
            "A + B - C * ABS(D)",
            B("-", B("+", N("A"), N("B")), B("*", N("C"), ast.Call(N("ABS"), [ast.Arg(None, N("D"))]))),
        ),
        ("(A + B - C) * D", B("*", B("-", B("+", N("A"), N("B")), N("C")), N("D"))),
        ("a MOD b / c", B("/", B("MOD", N("a"), N("b")), N("c"))),
    ],
)
def test_st03_precedence_and_associativity(text, shape):
    assert expr(text) == shape


def test_st10_operands_access_paths():
    assert expr("var2.otto[4]") == ast.Index(ast.Member(N("var2"), "otto"), [I(4)])
    assert expr("TON1.Q") == ast.Member(N("TON1"), "Q")
    assert expr("grid[1, i + j]") == ast.Index(N("grid"), [I(1), B("+", N("i"), N("j"))])
    assert expr("p^.x") == ast.Member(ast.Deref(N("p")), "x")
    assert expr("w.3") == ast.Member(N("w"), "3")
    assert expr("%ix0.1") == ast.DirectAddr("%IX0.1")


def test_st58_formal_positional_and_output_arguments():
    call = expr("LIMIT(MN := 0, IN := x, MX => y, NOT Q => z)")
    assert call == ast.Call(
        N("LIMIT"),
        [
            ast.Arg("MN", I(0)),
            ast.Arg("IN", N("x")),
            ast.Arg("MX", N("y"), output=True),
            ast.Arg("Q", N("z"), output=True, negated=True),
        ],
    )
    assert expr("f()") == ast.Call(N("f"), [])


def test_spans_are_one_based_and_cover_the_node():
    node = expr("a +\n  foo(1)")
    assert (node.span.line, node.span.column, node.span.end_line) == (1, 1, 2)
    assert node.right.span == ast.Span(2, 3, 2, 9)


# ---------------------------------------------------------------- statements (ST-11, ST-27..ST-37, ST-81)


def test_st11_statement_table():
    body = stmts("""
        A := 22;
        InstanceFB(par1 := 10, par2 := 20);
        IF A > 0 THEN B := 100; ELSE B := 0; END_IF;
        CASE code OF 1 : A := 11; 2 : A := 22; ELSE A := 99; END_CASE;
        FOR i := 0 TO 10 BY 2 DO j := j + i; END_FOR;
        WHILE i > 0 DO n := n * 2; END_WHILE;
        REPEAT k := k + i; UNTIL i < 20; END_REPEAT;
        EXIT; RETURN; ;;
    """)
    assert [type(s).__name__ for s in body] == [
        "Assign",
        "CallStmt",
        "If",
        "Case",
        "For",
        "While",
        "Repeat",
        "Exit",
        "Return",
        "Empty",
        "Empty",
    ]
    assert body[4] == ast.For(N("i"), I(0), I(10), I(2), [ast.Assign(N("j"), B("+", N("j"), N("i")))])


def test_st27_if_elsif_else_shape():
    [node] = stmts("IF c < 10 THEN r := 0; ELSIF c < 100 THEN r := 1; ELSE r := 2; END_IF;")
    assert node == ast.If(
        [(B("<", N("c"), I(10)), [ast.Assign(N("r"), I(0))]), (B("<", N("c"), I(100)), [ast.Assign(N("r"), I(1))])],
        [ast.Assign(N("r"), I(2))],
    )
    [no_else] = stmts("IF c THEN END_IF;")
    assert no_else.else_body is None


def test_st28_case_lists_ranges_enum_labels_and_multi_statement_branches():
    [node] = stmts("""CASE code OF
        10: r := 0;
        20, 77: r := 1; s := 2;
        21..55, -5..-1: r := 2;
        red, TColor#blue: ;
    ELSE r := 4;
    END_CASE;""")
    assert [b.labels for b in node.branches] == [
        [I(10)],
        [I(20), I(77)],
        [ast.CaseRange(I(21), I(55)), ast.CaseRange(ast.Unary("-", I(5)), ast.Unary("-", I(1)))],
        [N("red"), ast.TypedLit("TColor", N("blue"))],
    ]
    assert len(node.branches[1].body) == 2
    assert node.else_body == [ast.Assign(N("r"), I(4))]


def test_st34_semicolon_after_until_is_optional():
    assert stmts("REPEAT i := i + 1; UNTIL i > 5 END_REPEAT;") == stmts("REPEAT i := i + 1; UNTIL i > 5; END_REPEAT;")


def test_kw02_standard_pin_names_are_identifiers():
    body = stmts("IN := S AND R; T1(IN := IN, PT := PT, Q => Q, CLK := CU);")
    assert body[0] == ast.Assign(N("IN"), B("AND", N("S"), N("R")))
    assert [a.name for a in body[1].call.args] == ["IN", "PT", "Q", "CLK"]


def test_lex02_keywords_are_case_insensitive():
    assert stmts("if a then b := 1; end_if;") == stmts("IF a THEN b := 1; END_IF;")


def test_comments_pragmas_and_line_comments_are_ignored():
    assert stmts("a := (* x *) 1; // rest\n{pragma} b := 2; /* c */") == [
        ast.Assign(N("a"), I(1)),
        ast.Assign(N("b"), I(2)),
    ]


def test_st04_nested_comments_only_with_the_option():
    text = "a := 1; (* outer (* inner *) still comment *) b := 2;"
    assert parse_statements(text, nested_comments=True).ast == [ast.Assign(N("a"), I(1)), ast.Assign(N("b"), I(2))]
    assert not parse_statements(text).ok


# ---------------------------------------------------------------- declarations and types (VAR-01..22, TYP-1x..4x)


def test_var01_names_addresses_edges_and_initial_values():
    d = decl("sb1 AT %X0.0, sb2 AT %X0.1 : BOOL;")
    assert d.names == [ast.DeclName("sb1", "%X0.0"), ast.DeclName("sb2", "%X0.1")]
    assert decl("AT %MB121 : USINT := 242;") == ast.VarDecl(
        [ast.DeclName(None, "%MB121")], ast.NamedType("USINT"), I(242)
    )
    assert decl("start : BOOL R_EDGE;").edge == "R_EDGE"


def test_var_block_kinds_and_qualifiers():
    blocks = parse_declarations(
        "VAR_GLOBAL RETAIN a : INT; END_VAR VAR CONSTANT PI : REAL := 3.14; END_VAR "
        "VAR_INPUT x : INT; END_VAR VAR_OUTPUT y : INT; END_VAR VAR_IN_OUT z : INT; END_VAR "
        "VAR_EXTERNAL g : INT; END_VAR VAR_TEMP t : INT; END_VAR"
    ).ast
    assert [(b.kind, b.qualifiers) for b in blocks] == [
        ("VAR_GLOBAL", ["RETAIN"]),
        ("VAR", ["CONSTANT"]),
        ("VAR_INPUT", []),
        ("VAR_OUTPUT", []),
        ("VAR_IN_OUT", []),
        ("VAR_EXTERNAL", []),
        ("VAR_TEMP", []),
    ]


def test_declaration_comment_is_attached():
    assert decl("Stop : BOOL;  (* stop button *)").comment == "stop button"
    assert decl("Aux : INT;   // line comment").comment == "line comment"


def test_typ20_arrays_with_repeat_initialisers():
    d = decl("a : ARRAY [1..2, 1..4] OF SINT := [4(11), 12, 3()];")
    assert d.type == ast.ArrayType([(I(1), I(2)), (I(1), I(4))], ast.NamedType("SINT"))
    assert d.init == ast.ArrayInit([ast.RepeatInit(4, I(11)), I(12), ast.RepeatInit(3, None)])


def test_typ33_nested_struct_initialiser():
    d = decl("p : TMeasure := (lim := (low := 10, high := 100.0), failure := false);")
    assert d.init == ast.StructInit(
        [("lim", ast.StructInit([("low", I(10)), ("high", ast.RealLit(100.0))])), ("failure", ast.BoolLit(False))]
    )


def test_type_block_alias_subrange_enum_struct_pointer_string():
    source = parse_source("""TYPE
        TRoomTemp : REAL := 20.0;
        TSmall : INT (1..100);
        TPumpMode : (off, run := 5, fault);
        TRec : STRUCT a : INT; s : STRING[10]; c : (red, green); END_STRUCT;
        TPtr : REF_TO INT;
        TOld : POINTER TO ARRAY [0..3] OF BYTE;
        TLen : WSTRING(20);
    END_TYPE""")
    assert source.ok
    types = {d.name: d for d in source.ast.items[0].decls}
    assert types["TRoomTemp"] == ast.TypeDecl("TRoomTemp", ast.NamedType("REAL"), ast.RealLit(20.0))
    assert types["TSmall"].type == ast.SubrangeType("INT", I(1), I(100))
    assert types["TPumpMode"].type == ast.EnumType(
        [ast.EnumValue("off"), ast.EnumValue("run", I(5)), ast.EnumValue("fault")]
    )
    assert types["TRec"].type.members[1].type == ast.SizedType("STRING", I(10))
    assert types["TPtr"].type == ast.PointerType("REF_TO", ast.NamedType("INT"))
    assert types["TOld"].type.kind == "POINTER TO"
    assert types["TLen"].type == ast.SizedType("WSTRING", I(20))


# ---------------------------------------------------------------- POUs and configuration (POU-xx, CFG-xx)


def test_pou_kinds_return_type_blocks_and_body():
    pou = parse_pou("FUNCTION F : INT VAR_INPUT x : INT; END_VAR F := x; END_FUNCTION").ast
    assert (pou.kind, pou.name, pou.return_type) == ("FUNCTION", "F", ast.NamedType("INT"))
    assert pou.body == [ast.Assign(N("F"), N("x"))]
    assert parse_pou("FUNCTION_BLOCK FB END_FUNCTION_BLOCK").ast == ast.Pou("FUNCTION_BLOCK", "FB", None, [], [])


def test_cfg_configuration_resource_task_and_program_instances():
    source = parse_source("""CONFIGURATION PLC1
        RESOURCE CPM ON PLC
            TASK FreeWheeling(Number := 0);
            TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);
            PROGRAM prg WITH FreeWheeling : Test ();
            PROGRAM p2 : Other(x := 1, y => z);
        END_RESOURCE
    END_CONFIGURATION""")
    assert source.ok, source.diagnostics
    [config] = source.ast.items
    [resource] = config.items
    assert resource.on == "PLC"
    assert resource.items[1] == ast.TaskConfig("Fast", [("INTERVAL", ast.TimeLit("TIME", 10)), ("PRIORITY", I(1))])
    assert resource.items[2] == ast.ProgramConfig("prg", "FreeWheeling", "Test", [])
    assert resource.items[3].args == [ast.Arg("x", I(1)), ast.Arg("y", N("z"), output=True)]


# ---------------------------------------------------------------- diagnostics and recovery


def test_st40_missing_semicolon_is_reported_where_it_belongs_and_parsing_goes_on():
    result = parse_statements("x := 1\ny := 2\nz := 3;", file="Main/body", pou="Main")
    assert [(d.severity, d.code, d.message, d.line, d.column, d.file, d.pou) for d in result.diagnostics] == [
        ("error", "ST-PARSE", "expected ';' after statement", 1, 7, "Main/body", "Main"),
        ("error", "ST-PARSE", "expected ';' after statement", 2, 7, "Main/body", "Main"),
    ]
    assert len(result.ast) == 3


def test_st65_missing_semicolon_after_last_end_if_is_a_warning():
    result = parse_statements("IF a THEN x := 1; END_IF")
    assert [(d.severity, d.message) for d in result.diagnostics] == [("warning", "expected ';' after END_IF")]
    assert result.ok and isinstance(result.ast[0], ast.If)


@pytest.mark.parametrize(
    "block, keyword",
    [
        ("IF a THEN x := 1; END_IF", "END_IF"),
        ("CASE x OF 1: y := 2; END_CASE", "END_CASE"),
        ("FOR i := 1 TO 3 DO x := i; END_FOR", "END_FOR"),
        ("WHILE a DO a := FALSE; END_WHILE", "END_WHILE"),
        ("REPEAT a := FALSE; UNTIL NOT a END_REPEAT", "END_REPEAT"),
    ],
)
@pytest.mark.parametrize("between", ["\n", " "])
def test_st40_end_keyword_before_a_statement_is_an_error_but_under_codesys_typing_a_warning(block, keyword, between):
    """ST-40: ``END_IF;`` ... ``END_REPEAT;`` are followed by ``;``. CODESYS accepts them without it before another
    statement (OSCAT's REAL_TO_FRAC), so under CODESYS typing the ``;`` is inserted with a warning at the keyword's
    end, as ST-65's last statement of a body; IEC typing keeps the error (on the same line, the unit ends there)."""
    text = f"{block}{between}y := 5;"
    expected = [("ST-PARSE", f"expected ';' after {keyword}", 1, len(block) + 1, "Main/body", "Main")]
    iec = parse_statements(text, file="Main/body", pou="Main")
    assert [(d.code, d.message, d.line, d.column, d.file, d.pou) for d in iec.diagnostics] == expected
    assert [d.severity for d in iec.diagnostics] == ["error"]
    with typing_rules("codesys"):
        codesys = parse_statements(text, file="Main/body", pou="Main")
    assert [(d.code, d.message, d.line, d.column, d.file, d.pou) for d in codesys.diagnostics] == expected
    assert [d.severity for d in codesys.diagnostics] == ["warning"]
    assert codesys.ast == stmts(f"{block};{between}y := 5;")


def test_missing_semicolon_in_declarations():
    result = parse_declarations("VAR\n  a : INT\n  b : BOOL;\nEND_VAR")
    assert [(d.message, d.line, d.column) for d in result.diagnostics] == [("expected ';' after declaration", 2, 10)]


def test_ex44_missing_do_says_what_is_expected():
    result = parse_statements("FOR i := 1 TO code\n  IF i > 13 THEN EXIT; END_IF;\nEND_FOR;")
    [d] = result.diagnostics
    assert (d.message, d.line, d.column, d.end_column) == ("expected BY or DO, found 'IF'", 2, 3, 5)


def test_incomplete_expression_and_unterminated_comment():
    [d] = parse_statements("x := 1 +;").diagnostics
    assert (d.message, d.column) == ("expected an expression, found ';'", 9)
    [d] = parse_statements("x := (* open").diagnostics
    assert d.message == "unterminated comment: '(*' without a matching '*)'"


def test_one_error_per_pou_and_good_pous_survive():
    result = parse_source(
        "PROGRAM A\nx := ;\nEND_PROGRAM\nPROGRAM B\ny := 1 1;\nEND_PROGRAM\nPROGRAM C\nz := 1;\nEND_PROGRAM\n",
        file="lib.st",
    )
    assert [(d.pou, d.line, d.column, d.file) for d in result.diagnostics] == [
        ("A", 2, 6, "lib.st"),
        ("B", 5, 8, "lib.st"),
    ]
    assert [p.name for p in result.ast.pous] == ["C"]


def test_case_statement_before_first_label():
    [d] = parse_statements("CASE x OF y := 1; END_CASE;").diagnostics
    assert (d.message, d.line, d.column) == ("expected a CASE label such as '1:' before the first statement", 1, 11)


@pytest.mark.parametrize("text", ["\x00\xff", "END_IF;", "x := ((((1", "VAR :=", "'", "(*", "FUNCTION(", "a.b.c := ;"])
def test_garbage_gives_diagnostics_not_exceptions(text):
    for parse in (parse_source, parse_pou, parse_declarations, parse_statements, parse_expression):
        result = parse(text)
        assert result.diagnostics and all(d.code == "ST-PARSE" and d.line for d in result.diagnostics)


def test_compound_statement_spans_end_with_their_end_keyword():
    """Spans of IF/CASE/FOR/WHILE/REPEAT cover their END_x (breakpoints and monitoring highlight the whole statement)."""
    from ladderlab.st.parser import parse_statements

    result = parse_statements(
        "IF a THEN\n  b := 1;\nEND_IF;\nWHILE a DO\n x:=1;\nEND_WHILE;\n"
        "CASE x OF 1: y := 2; END_CASE;\nFOR i := 1 TO 2 DO END_FOR;\n"
        "REPEAT x := 1; UNTIL TRUE END_REPEAT;"
    )
    assert [(s.span.line, s.span.end_line, s.span.end_column) for s in result.ast] == [
        (1, 3, 7),
        (4, 6, 10),
        (7, 7, 30),
        (8, 8, 27),
        (9, 9, 37),
    ]
