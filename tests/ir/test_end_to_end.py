"""ST lowered to the IR and run by the engine: the spec's worked examples and the lowering's own decisions
(edge inputs, EN lifting, bit access, initial values), scan by scan."""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from tests.ir.helpers import lower_ok


def simulate(text: str) -> Simulation:
    return Simulation(lower_ok(text))


def run_program(declarations: str, body: str, inputs: dict[str, object] | None = None, extra: str = "") -> Simulation:
    """One scan of ``PROGRAM P`` with ``inputs`` written first; read results with ``sim.read("P.x")``."""
    sim = simulate(f"PROGRAM P\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n{extra}")
    for name, value in (inputs or {}).items():
        sim.write(f"P.{name}", value)
    sim.cycle()
    assert sim.fault is None
    return sim


def test_for_doubles_and_leaves_the_counter_past_the_end_st75():
    sim = run_program(
        "Var1 : INT; Counter : INT; Erg : INT;",
        "Var1 := 1; FOR Counter := 1 TO 5 BY 1 DO Var1 := Var1 * 2; END_FOR; Erg := Var1;",
    )
    assert (sim.read("P.Erg"), sim.read("P.Counter")) == (32, 6)


@pytest.mark.parametrize("hit, expected", [(7, (7, 7)), (8, (101, 101)), (None, (101, 101))])
def test_for_by_two_with_exit_st75(hit, expected):
    sim = run_program(
        "ARR : ARRAY [1..101] OF INT; I : INT; J : INT;",
        "J := 101; FOR I := 1 TO 100 BY 2 DO IF ARR[I] = 70 THEN J := I; EXIT; END_IF; END_FOR;",
        {f"ARR[{hit}]": 70} if hit else {},
    )
    assert (sim.read("P.J"), sim.read("P.I")) == expected


@pytest.mark.parametrize("flag, total", [(0, 15), (1, 6)])
def test_exit_leaves_the_innermost_loop_st80(flag, total):
    sim = run_program(
        "SUM : INT; I : INT; J : INT; FLAG : INT;",
        "SUM := 0; FOR I := 1 TO 3 DO FOR J := 1 TO 2 DO IF FLAG = 1 THEN EXIT; END_IF; "
        "SUM := SUM + J; END_FOR; SUM := SUM + I; END_FOR;",
        {"FLAG": flag},
    )
    assert sim.read("P.SUM") == total


@pytest.mark.parametrize(
    "code, result", [(10, 0), (20, 1), (77, 1), (21, 2), (55, 2), (56, 4), (100, 3), (0, 4), (19, 4)]
)
def test_case_lists_and_ranges_st29(code, result):
    sim = run_program(
        "code : INT; result : INT;",
        "CASE code OF 10: result := 0; 20, 77: result := 1; 21..55: result := 2; 100: result := 3; "
        "ELSE result := 4; END_CASE;",
        {"code": code},
    )
    assert sim.read("P.result") == result


FACTORIAL = """FUNCTION FACTORIAL : UDINT
VAR_INPUT code : USINT; END_VAR
VAR i : USINT; END_VAR
FACTORIAL := 1;
FOR i := 2 TO code DO FACTORIAL := FACTORIAL * i; END_FOR;
END_FUNCTION"""


@pytest.mark.parametrize("code, factorial", [(0, 1), (1, 1), (5, 120), (12, 479001600), (13, 1932053504)])
def test_factorial_function_wraps_at_udint_st37(code, factorial):
    sim = run_program("n : USINT; f : UDINT;", "f := FACTORIAL(n);", {"n": code}, FACTORIAL)
    assert sim.read("P.f") == factorial


def test_fb_state_and_outputs_across_calls_st26():
    sim = simulate("""FUNCTION_BLOCK RECTANGLE
VAR_INPUT A : REAL; B : REAL; END_VAR
VAR_OUTPUT circumference : REAL; surface : REAL; END_VAR
circumference := 2.0 * (A + B); surface := A * B;
END_FUNCTION_BLOCK
PROGRAM P
VAR r : RECTANGLE; o : REAL; s : REAL; c2 : REAL; s2 : REAL; END_VAR
r(A := 2.0, B := 3.0, circumference => o, surface => s);
r(B := 4.0, A := 2.5);
c2 := r.circumference; s2 := r.surface;
END_PROGRAM""")
    sim.cycle()
    assert [sim.read(f"P.{x}") for x in ("o", "s", "c2", "s2")] == [10.0, 6.0, 13.0, 10.0]


def test_r_edge_input_sees_each_rising_edge_once_var22():
    """The input keeps the caller's value: a call that does not pass it sees no new edge."""
    sim = simulate("""FUNCTION_BLOCK Count
VAR_INPUT clk : BOOL R_EDGE; END_VAR
VAR_OUTPUT n : INT; END_VAR
IF clk THEN n := n + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM P
VAR c : Count; x : BOOL; pass : BOOL; END_VAR
IF pass THEN c(clk := x); ELSE c(); END_IF;
END_PROGRAM""")
    counts = []
    for x, passed in [
        (True, True),
        (True, True),
        (True, False),
        (False, False),
        (True, False),
        (False, True),
        (True, True),
    ]:
        sim.write("P.x", x)
        sim.write("P.pass", passed)
        sim.cycle()
        counts.append(sim.read("P.c.n"))
    assert counts == [1, 1, 1, 1, 1, 1, 2]


def test_f_edge_input_no_pulse_on_a_first_false_call():
    sim = simulate("""FUNCTION_BLOCK Fall
VAR_INPUT clk : BOOL F_EDGE; END_VAR
VAR_OUTPUT q : BOOL; END_VAR
q := clk;
END_FUNCTION_BLOCK
PROGRAM P
VAR f : Fall; x : BOOL; END_VAR
f(clk := x);
END_PROGRAM""")
    pulses = []
    for x in [False, True, True, False, False]:
        sim.write("P.x", x)
        sim.cycle()
        pulses.append(sim.read("P.f.q"))
    assert pulses == [False, False, False, True, False]


def test_lifted_call_with_en_false_is_skipped():
    body = "y := 100 + ADD(EN := go, IN1 := x, IN2 := 1, ENO => ok);"
    assert [
        run_program("go : BOOL; ok : BOOL; x : INT; y : INT;", body, {"go": go, "x": 5}).read(v)
        for go in (True, False)
        for v in ("P.y", "P.ok")
    ] == [106, True, 100, False]  # the temporary starts at 0


def test_bit_access_reads_and_writes_integers_and_bit_strings():
    sim = run_program(
        "i : INT; w : WORD; b15 : BOOL; b0 : BOOL;", "i := -1; i.15 := FALSE; w.3 := TRUE; b15 := w.3; b0 := i.0;"
    )
    assert [sim.read(f"P.{v}") for v in ("i", "w", "b15", "b0")] == [32767, 8, True, True]


def test_initial_values_of_arrays_structs_and_aliases_read_back():
    sim = run_program(
        "a : ARRAY [1..2, 1..3] OF INT := [1, 2, 3, 4]; p : TPoint := (y := 2.5); h : THome;",
        "",
        extra="TYPE TPoint : STRUCT x : REAL := 1.0; y : REAL; END_STRUCT; THome : REAL := 20.0; END_TYPE",
    )
    assert [sim.read(p) for p in ("P.a[1, 3]", "P.a[2, 1]", "P.a[2, 3]", "P.p.x", "P.p.y", "P.h")] == [
        3,
        4,
        0,
        1.0,
        2.5,
        20.0,
    ]
