"""Checker: exact diagnostics (code, location, message) and the resolved program it returns."""

from __future__ import annotations

import pytest

from ladderlab.model import Pou, Project
from ladderlab.st import ast
from ladderlab.st import types as t
from ladderlab.st.checker import check_operand, check_project

TYPES = (
    "TYPE TColor : (red, green, blue); TRec : STRUCT a : INT; s : STRING[10]; END_STRUCT; "
    "TWarm : REAL := 20.0; THome : TWarm; END_TYPE"
)
GLOBALS = "VAR_GLOBAL Start : BOOL; (* start button *) g : INT; END_VAR\nVAR_GLOBAL CONSTANT K : INT := 3; END_VAR"
FB = Pou(
    name="Motor",
    kind="function_block",
    language="st",
    declarations="VAR_INPUT start : BOOL R_EDGE; END_VAR VAR_OUTPUT run : BOOL; END_VAR VAR hidden : INT; END_VAR",
    body="run := start;",
)
FUN = Pou(
    name="Twice",
    kind="function",
    language="st",
    return_type="INT",
    declarations="VAR_INPUT a : INT; END_VAR VAR_IN_OUT io : INT; END_VAR",
    body="Twice := a * 2;",
)
MAIN_DECLS = (
    "VAR t : TON; m : Motor; x, y : INT; r : REAL; d : DINT; c : TColor; rec : TRec; tm : TIME; "
    "arr : ARRAY [1..K] OF INT; w : WORD; b : BOOL; s : STRING; h : THome; END_VAR"
)


def check(body: str, *extra: Pou, declarations: str = MAIN_DECLS):
    main = Pou(name="Main", kind="program", language="st", declarations=declarations, body=body)
    return check_project(Project(name="p", types=TYPES, globals=GLOBALS, pous=[main, FB, FUN, *extra]))


def errors(body: str, *extra: Pou, **kw) -> list[tuple]:
    return [(d.severity, d.code, d.line, d.column, d.message) for d in check(body, *extra, **kw).diagnostics]


def test_clean_program_has_no_diagnostics_and_a_typed_resolved_body():
    result = check(
        "t(IN := Start, PT := T#5s); x := y + 1; r := INT_TO_REAL(x) * 2.0; c := green; "
        "IF t.Q AND NOT b THEN arr[x] := Twice(a := x, io := y); END_IF; m(start := b, run => b);"
    )
    assert result.diagnostics == []
    main = result.pou("Main")
    assign = main.body[1]
    assert assign.value.ty == t.INT and assign.target.ref is main.symbols["X"]
    call = main.body[0].call
    assert call.ref is main.symbols["T"] and call.args[0].value.ref is result.globals["START"]
    assert main.body[3].value.ref.name == "green"
    assert main.body[4].branches[0][1][0].value.ref is result.pou("Twice")


def test_symbol_table_carries_class_type_init_flags_and_comment():
    result = check("")
    start = result.globals["START"]
    assert (start.var_class, start.type, start.comment) == ("VAR_GLOBAL", t.BOOL, "start button")
    assert result.globals["K"].constant and result.globals["K"].init == ast.IntLit(3)
    motor = result.pou("Motor").symbols
    assert (motor["START"].edge, motor["RUN"].var_class, motor["HIDDEN"].var_class) == ("R_EDGE", "VAR_OUTPUT", "VAR")
    main = result.pou("Main").symbols
    assert main["ARR"].type == t.ArrayType(((1, 3),), t.INT)
    assert main["H"].init == ast.RealLit(20.0)  # TYP-11: inherited through THome from TWarm
    assert main["T"].type.std.name == "TON" and main["M"].type.pou is result.pou("Motor")


@pytest.mark.parametrize(
    "body, expected",
    [
        ("x := Strat;", ("error", "ST-UNKNOWN-VAR", 1, 6, "unknown variable 'Strat' - did you mean 'Start'?")),
        (
            "x := r;",
            ("error", "ST-TYPE-MISMATCH", 1, 6, "cannot assign REAL to INT without a conversion such as REAL_TO_INT"),
        ),
        (
            "x := x + r;",
            (
                "error",
                "ST-TYPE-MISMATCH",
                1,
                6,
                "'+' needs operands of the same type: INT and REAL; convert one of them (e.g. REAL_TO_INT)",
            ),
        ),
        ("d := x;", ("warning", "ST-IMPLICIT-CONV", 1, 6, "INT is converted implicitly to DINT")),
        ("x := 40000;", ("error", "ST-RANGE", 1, 6, "40000 is out of range for INT (-32768..32767)")),
        ("K := 4;", ("error", "ST-CONST-WRITE", 1, 1, "'K' is a CONSTANT and cannot be assigned")),
        (
            "t.Q := TRUE;",
            ("error", "ST-READONLY", 1, 1, "'Q' is an output of TON: it can be read but not assigned from outside"),
        ),
        (
            "x := m.hidden;",
            (
                "error",
                "ST-NOT-ACCESSIBLE",
                1,
                6,
                "'hidden' is internal to Motor: only its inputs and outputs can be used from outside",
            ),
        ),
        ("IF x THEN ; END_IF;", ("error", "ST-TYPE-MISMATCH", 1, 4, "the IF condition must be BOOL, not INT")),
        ("EXIT;", ("error", "ST-EXIT-OUTSIDE-LOOP", 1, 1, "EXIT is only allowed inside FOR, WHILE or REPEAT")),
        (
            "FOR x := 1 TO 3 DO x := 2; END_FOR;",
            ("error", "ST-LOOP-VAR", 1, 20, "'x' is the FOR loop variable: it must not be changed inside the loop"),
        ),
        (
            "FOR r := 1 TO 3 DO END_FOR;",
            ("error", "ST-LOOP-VAR", 1, 5, "the FOR variable must be an integer (ANY_INT), not REAL"),
        ),
        (
            "FOR x := 1 TO 3 BY 0 DO END_FOR;",
            ("error", "ST-LOOP-VAR", 1, 20, "the FOR step is 0: the loop would never end"),
        ),
        ("x := arr[r];", ("error", "ST-TYPE-MISMATCH", 1, 10, "an array index must be an integer (ANY_INT), not REAL")),
        ("x := arr[K + 1];", ("error", "ST-INDEX", 1, 10, "constant array index 4 is outside ARRAY [1..3] OF INT")),
        ("x := arr[0];", ("error", "ST-INDEX", 1, 10, "constant array index 0 is outside ARRAY [1..3] OF INT")),
        ("x := arr[K] + arr[1];", None),
        ("x := rec.b;", ("error", "ST-UNKNOWN-MEMBER", 1, 6, "TRec has no field 'b'")),
        ("tm := tm * x; tm := tm / 2; tm := tm + T#1s; tm := x * tm;", None),
        (
            "tm := tm + x;",
            (
                "error",
                "ST-TYPE-MISMATCH",
                1,
                7,
                "'+' needs operands of the same type: TIME and INT; convert one of them (e.g. INT_TO_TIME)",
            ),
        ),
        ("c := 1;", ("error", "ST-TYPE-MISMATCH", 1, 6, "cannot assign ANY_INT literal to TColor")),
        (
            "b := c < green;",
            ("error", "ST-TYPE-MISMATCH", 1, 6, "enumeration values can only be compared with = and <>"),
        ),
        (
            "w := x AND w;",
            (
                "error",
                "ST-TYPE-MISMATCH",
                1,
                6,
                "'AND' needs operands of the same type: INT and WORD; convert one of them (e.g. WORD_TO_INT)",
            ),
        ),
        (
            "r := x ** 2;",
            (
                "error",
                "ST-TYPE-MISMATCH",
                1,
                6,
                "the base of '**' must be REAL or LREAL, not INT; convert it (e.g. INT_TO_REAL)",
            ),
        ),
        ("s := s + 'x'; r := 2 ** 3;", None),
        (
            "x;",
            (
                "error",
                "ST-NO-EFFECT",
                1,
                1,
                "this statement does nothing: expected an assignment ':=' or a call '(...)'",
            ),
        ),
    ],
)
def test_single_statement_diagnostics(body, expected):
    assert errors(body) == ([expected] if expected else [])


@pytest.mark.parametrize(
    "body, expected",
    [
        ("t(IN := b, PTT := T#1s);", ("ST-CALL-ARGS", 1, 12, "TON has no parameter 'PTT' - did you mean 'PT'?")),
        ("t(IN := b, IN := b);", ("ST-CALL-ARGS", 1, 12, "parameter 'IN' is given twice")),
        ("t(Q := b);", ("ST-CALL-ARGS", 1, 3, "'Q' is an output of TON: write Q => variable")),
        ("t(IN => b);", ("ST-CALL-ARGS", 1, 3, "'IN' is an input of TON: write IN := value")),
        (
            "t(IN := b, T#1s);",
            ("ST-CALL-ARGS", 1, 1, "do not mix formal (name := value) and positional arguments in a call to TON"),
        ),
        ("x := Twice(1, 2, 3);", ("ST-CALL-ARGS", 1, 6, "Twice takes 2 input(s), got 3")),
        ("x := Twice(a := 1);", ("ST-CALL-ARGS", 1, 6, "missing in-out parameter(s) io in the call to Twice")),
        (
            "x := Twice(a := 1, io := 5);",
            ("ST-NOT-LVALUE", 1, 26, "in-out parameter io of Twice needs a variable, not an expression or literal"),
        ),
        (
            "x := Twice(a := 1, io := K);",
            ("ST-CONST-WRITE", 1, 26, "the CONSTANT 'K' cannot be passed as in-out parameter io"),
        ),
        (
            "b := t.Q AND t(IN := b);",
            (
                "ST-NOT-CALLABLE",
                1,
                14,
                "the function block instance 't' cannot be called inside an "
                "expression: call it as a statement and read its outputs (e.g. inst.Q)",
            ),
        ),
        (
            "TON(IN := b);",
            (
                "ST-NOT-CALLABLE",
                1,
                1,
                "TON is a function block type: declare an instance (e.g. t1 : TON;) and call the instance",
            ),
        ),
        ("x := Sqr(2);", ("ST-UNKNOWN-POU", 1, 6, "unknown function 'Sqr' - did you mean 'SQRT'?")),
        (
            "x := MAX(x, r);",
            (
                "ST-TYPE-MISMATCH",
                1,
                13,
                "MAX needs inputs of one type: got INT and REAL; convert one of them with a *_TO_* function",
            ),
        ),
        ("r := SQRT(x);", ("ST-TYPE-MISMATCH", 1, 6, "SQRT works on ANY_REAL, not on INT")),
        ("x := LIMIT(MN := 0, IN := x, MX := 100) + MUX(1, 10, 20, 30) + SEL(b, 1, 2);", None),
        ("x := LEN(s) + FIND(s, 'a'); s := CONCAT(s, 'a', 'b'); w := SHL(w, 2); tm := MUL_TIME(tm, 2);", None),
    ],
)
def test_call_diagnostics(body, expected):
    assert [e[1:] for e in errors(body)] == ([expected] if expected else [])


def test_case_rules():
    assert errors("CASE x OF 1, 2..5: ; 4: ; ELSE ; END_CASE;") == [
        ("warning", "ST-CASE-OVERLAP", 1, 22, "CASE label 4 overlaps 2..5: only the first matching branch runs")
    ]
    assert errors("CASE c OF red: ; green, blue: ; END_CASE;") == []
    assert [e[1] for e in errors("CASE r OF 1: ; END_CASE;")] == ["ST-TYPE-MISMATCH"]
    assert errors("CASE x OF y: ; END_CASE;") == [("error", "ST-CONST-EXPR", 1, 11, "CASE label y must be a constant")]


def test_declaration_rules():
    bad = Pou(
        name="F",
        kind="function",
        language="st",
        return_type="INT",
        declarations="VAR_OUTPUT o : INT; END_VAR VAR_INPUT e : BOOL R_EDGE; END_VAR VAR t : TON; END_VAR "
        "VAR_IN_OUT io : INT := 1; END_VAR VAR_EXTERNAL Start : INT; nope : INT; END_VAR "
        "VAR q : Tcolr; e : INT; END_VAR",
        body="F := 1;",
    )
    found = [(d.code, d.message) for d in check("", bad).diagnostics if d.pou == "F"]
    assert found == [
        ("ST-DECL", "VAR_OUTPUT is not allowed in a function (VAR-11)"),
        ("ST-DECL", "R_EDGE is only allowed on BOOL inputs of function blocks and programs (VAR-22)"),
        ("ST-DECL", "a function has no memory, so it cannot contain the instance of TON (ST-57)"),
        ("ST-DECL", "a VAR_IN_OUT variable cannot have an initial value (VAR-83)"),
        ("ST-EXTERNAL", "VAR_EXTERNAL 'Start' is INT but the global is BOOL"),
        ("ST-EXTERNAL", "VAR_EXTERNAL 'nope' does not match any global variable"),
        ("ST-UNKNOWN-TYPE", "unknown type 'Tcolr' - did you mean 'TColor'?"),
        ("ST-DUPLICATE", "'e' is declared twice"),
    ]


def test_a_global_cannot_take_a_program_name():
    """ST-08: a program instance and a global variable both name an instance of the resource (a watch-list path
    ``Pump`` could mean either); a global named like a function block type is not an instance and stays legal."""
    pump = Pou(name="Pump", kind="program", language="st", declarations="VAR n : INT; END_VAR", body="n := n + 1;")
    project = Project(
        name="p", types=TYPES, globals="VAR_GLOBAL x : INT;\n  PUMP : BOOL; Motor : INT; END_VAR", pous=[pump, FB, FUN]
    )
    assert [(d.file, d.line, d.column, d.code, d.message) for d in check_project(project).diagnostics] == [
        (
            "globals",
            2,
            3,
            "ST-DUPLICATE",
            "'PUMP' is the name of the program Pump: a global variable and a program instance cannot share a name",
        )
    ]


def test_diagnostics_point_into_the_right_text():
    result = check("x := 1;\n  y := nope;", declarations=MAIN_DECLS.replace("w : WORD;", "w : WORDS;"))
    assert [(d.file, d.pou, d.line, d.column) for d in result.diagnostics] == [
        ("Main/declarations", "Main", 1, 123),
        ("Main/body", "Main", 2, 8),
    ]


def test_recursion_is_reported():
    a = Pou(
        name="A",
        kind="function",
        language="st",
        return_type="INT",
        declarations="VAR_INPUT n : INT; END_VAR",
        body="A := B(n);",
    )
    b = Pou(
        name="B",
        kind="function",
        language="st",
        return_type="INT",
        declarations="VAR_INPUT n : INT; END_VAR",
        body="B := A(n);",
    )
    found = [(d.code, d.message) for d in check("", a, b).diagnostics]
    assert found == [("ST-RECURSION", "recursive call A -> B -> A: POUs must not call themselves")]


def test_function_without_result_assignment_warns():
    f = Pou(name="F", kind="function", language="st", return_type="INT", body=";")
    assert [(d.severity, d.code) for d in check("", f).diagnostics] == [("warning", "ST-NO-RESULT")]


def test_ld_pou_declarations_are_callable_from_st():
    ld = Pou(
        name="Lamp",
        kind="function_block",
        language="ld",
        declarations="VAR_INPUT on : BOOL; END_VAR VAR_OUTPUT lit : BOOL; END_VAR",
    )
    result = check("lamp1(on := b, lit => b);", ld, declarations=MAIN_DECLS + " VAR lamp1 : Lamp; END_VAR")
    assert result.diagnostics == [] and result.pou("Lamp").body is None


def test_check_operand_for_ld_fbd_texts():
    result = check("")
    expr, diagnostics = check_operand(result, "Main", "t.Q", "BOOL")
    assert diagnostics == [] and expr.ty == t.BOOL
    expr, diagnostics = check_operand(result, "Main", "arr[x] + 1", "INT")
    assert diagnostics == [] and isinstance(expr, ast.Binary)
    _, diagnostics = check_operand(result, "Main", "r", "BOOL")
    assert [(d.code, d.pou, d.message) for d in diagnostics] == [
        ("ST-TYPE-MISMATCH", "Main", "operand 'r': expected BOOL, got REAL without a conversion such as REAL_TO_BOOL")
    ]
    assert check_operand(result, "Main", "x +", None)[0] is None


def test_enum_used_in_a_struct_is_not_ambiguous_and_typed_enum_literals_are_case_labels():
    """ST-28/TYP-13: a bare enum value stays unambiguous when its type is also a struct field type;
    ``TColor#blue`` is a constant CASE label."""
    types = "TYPE TColor : (red, green, blue); TRec : STRUCT c : TColor; END_STRUCT; END_TYPE"
    main = Pou(
        name="Main",
        kind="program",
        language="st",
        declarations="VAR x : TColor; r : TRec; END_VAR",
        body="x := red; r.c := blue;\nCASE x OF TColor#blue: x := green; red: x := blue; END_CASE;",
    )
    assert check_project(Project(name="p", types=types, pous=[main])).diagnostics == []


@pytest.mark.parametrize(
    "name, expected",
    [
        (
            "a__b",
            ("error", "ST-NAME", "'a__b' is not a valid identifier: IEC identifiers may not contain two '_' in a row"),
        ),
        (
            "__x",
            ("error", "ST-NAME", "'__x' is not a valid identifier: IEC identifiers may not contain two '_' in a row"),
        ),
        ("x" * 65, ("error", "ST-NAME", f"'{'x' * 65}' is not a valid identifier: at most 64 characters")),
        ("c_", ("warning", "ST-NAME", "'c_' ends with '_', which IEC 61131-3 edition 2 does not allow")),
        ("x" * 64, None),
    ],
)
def test_lex13_lex15_identifier_rules_on_declarations(name, expected):
    main = Pou(name="Main", kind="program", language="st", declarations=f"VAR {name} : INT; END_VAR", body="")
    found = [(d.severity, d.code, d.message) for d in check_project(Project(name="p", pous=[main])).diagnostics]
    assert found == ([expected] if expected else [])


def test_fb_instance_initialised_before_its_fb_is_declared():
    """VAR-13: ``f : Fb := (n := 4)`` checks the same whatever the order of the POUs."""
    main = Pou(name="Main", kind="program", language="st", declarations="VAR f : Fb := (n := 4); END_VAR", body="f();")
    fb = Pou(name="Fb", kind="function_block", language="st", declarations="VAR_INPUT n : INT; END_VAR", body="")
    for pous in ([main, fb], [fb, main]):
        assert check_project(Project(name="p", pous=pous)).diagnostics == []
    bad = main.model_copy(update={"declarations": "VAR f : Fb := (m := 4); END_VAR"})
    assert [d.code for d in check_project(Project(name="p", pous=[bad, fb])).diagnostics] == ["ST-UNKNOWN-MEMBER"]


def test_an_enumeration_value_of_several_types_must_be_named_with_its_type():
    """ST-AMBIGUOUS: without a target that says which enumeration is meant, ``Idle`` could be either."""
    main = Pou(name="Main", kind="program", language="st", declarations="VAR m : TMode; END_VAR")
    types = "TYPE TMode : (Idle, Run); TState : (Idle, Stop); END_TYPE"
    found = check_project(
        Project(name="p", types=types, pous=[main.model_copy(update={"body": "IF Idle = m THEN m := Run; END_IF;"})])
    ).diagnostics
    assert [(d.code, d.line, d.column, d.message) for d in found] == [
        ("ST-AMBIGUOUS", 1, 4, "'Idle' is a value of several enumerations: write TMode#Idle, TState#Idle")
    ]
    clear = main.model_copy(update={"body": "IF TMode#Idle = m THEN m := Run; END_IF;"})
    assert check_project(Project(name="p", types=types, pous=[clear])).diagnostics == []


def test_more_initial_values_than_array_elements():
    found = errors("", declarations="VAR a : ARRAY[1..3] OF INT := [1, 2, 3, 4]; END_VAR")
    assert found == [("error", "ST-INIT", 1, 32, "4 initial values for an array of 3 elements")]


def test_a_pou_that_assigns_its_own_input_is_warned():
    """ST-INPUT-WRITE (docs/diagnostics.md): legal ST, but the caller's value is lost; a warning, not an error."""
    pump = Pou(name="Pump", kind="function_block", language="st", declarations="VAR_INPUT speed : INT; END_VAR")
    found = check_project(Project(name="p", pous=[pump.model_copy(update={"body": "speed := 0;"})])).diagnostics
    assert [(d.severity, d.code, d.pou, d.line, d.column, d.message) for d in found] == [
        (
            "warning",
            "ST-INPUT-WRITE",
            "Pump",
            1,
            1,
            "'speed' is an input of Pump: assigning it overwrites the caller's value",
        )
    ]
