"""Statements through the code generator, scan by scan (spec ST-12, ST-27..ST-37, ST-70..ST-80, POU-11..POU-41)."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.ir import nodes as ir
from ladderlab.ir import types as t

from .helpers import reference_wrap
from .irbuild import (
    BOOL,
    DINT,
    INT,
    REAL,
    TIME,
    UDINT,
    USINT,
    T,
    add,
    array,
    assign,
    binop,
    c,
    call,
    case,
    eq,
    exit_,
    fb,
    fbcall,
    fncall,
    for_,
    function,
    g,
    gt,
    if_,
    ix,
    jump,
    lt,
    m,
    mul,
    network,
    pou,
    prog,
    repeat,
    ret,
    slot,
    struct,
    trace,
    v,
    while_,
)


def run(program: ir.Program, paths: list[str], scans: int = 1) -> list[tuple]:
    sim = Simulation(program)
    rows = trace(sim, paths, scans)
    assert sim.fault is None, sim.fault.text()
    return rows


# ------------------------------------------------------------------ selection


@pytest.mark.parametrize(("code", "result"), [(5, 0), (9, 0), (10, 1), (99, 1), (100, 2), (-5, 0)])
def test_if_elsif_else_ex39(code, result):
    """ST-27 (Ex 4.9): IF code >= 100 THEN 2 ELSIF code >= 10 THEN 1 ELSE 0."""
    x, r = v("CODE", INT), v("R", INT)
    body = [
        if_(
            (binop("GE", x, c(100, INT)), [assign(r, c(2, INT))]),
            (binop("GE", x, c(10, INT)), [assign(r, c(1, INT))]),
            orelse=[assign(r, c(0, INT))],
        )
    ]
    program = prog(pou("MAIN", [slot("CODE", INT, initial=code), slot("R", INT, initial=7)], body))
    assert run(program, ["MAIN.R"]) == [(result,)]


@pytest.mark.parametrize(
    ("code", "result"), [(10, 0), (20, 1), (77, 1), (21, 2), (55, 2), (56, 4), (100, 3), (0, 4), (19, 4)]
)
def test_case_lists_ranges_else_ex40(code, result):
    """ST-29 (Ex 4.10): labels, lists, ranges and ELSE; the first matching group runs."""
    x, r = v("CODE", INT), v("R", INT)
    body = [
        case(
            x,
            ([10], [assign(r, c(0, INT))]),
            ([20, 77], [assign(r, c(1, INT))]),
            ([(21, 55)], [assign(r, c(2, INT))]),
            ([100, (21, 30)], [assign(r, c(3, INT))]),
            orelse=[assign(r, c(4, INT))],
        )
    ]
    program = prog(pou("MAIN", [slot("CODE", INT, initial=code), slot("R", INT)], body))
    assert run(program, ["MAIN.R"]) == [(result,)]


def test_case_without_else_runs_nothing():
    x, r = v("CODE", INT), v("R", INT)
    body = [case(x, ([1], [assign(r, c(11, INT))]))]
    program = prog(pou("MAIN", [slot("CODE", INT, initial=2), slot("R", INT, initial=5)], body))
    assert run(program, ["MAIN.R"]) == [(5,)]


# ------------------------------------------------------------------ loops


def test_for_loop_counter_after_the_loop_st75():
    """ST-75: Var1 doubles five times (Erg = 32) and Counter ends at 6 (ST-71)."""
    var1, counter, erg = v("VAR1", INT), v("COUNTER", INT), v("ERG", INT)
    body = [
        assign(var1, c(1, INT)),
        for_(counter, c(1, INT), c(5, INT), [assign(var1, mul(var1, c(2, INT)))]),
        assign(erg, var1),
    ]
    program = prog(pou("MAIN", [slot("VAR1", INT), slot("COUNTER", INT), slot("ERG", INT)], body))
    assert run(program, ["MAIN.ERG", "MAIN.COUNTER"]) == [(32, 6)]


def test_for_counting_down_and_not_at_all():
    """ST-75 [FIG]: FOR i := 5 TO 1 BY -1 visits 5..1 and leaves i = 0; FOR 10 TO 1 never runs (ST-70)."""
    i, j, s, n = v("I", INT), v("J", INT), v("S", DINT), v("N", INT)
    body = [
        for_(i, c(5, INT), c(1, INT), [assign(s, add(mul(s, c(10, DINT)), ir.Convert(i, INT, DINT)))], step=c(-1, INT)),
        for_(j, c(10, INT), c(1, INT), [assign(n, add(n, c(1, INT)))]),
    ]
    program = prog(pou("MAIN", [slot("I", INT), slot("J", INT), slot("S", DINT), slot("N", INT)], body))
    assert run(program, ["MAIN.S", "MAIN.I", "MAIN.J", "MAIN.N"]) == [(54321, 0, 10, 0)]


def test_for_with_variable_step_and_exit_st75():
    """ST-75: J := 101; FOR I := 1 TO 100 BY STEP: first odd index holding 70 (EXIT keeps I)."""
    i, j, arr, step = v("I", INT), v("J", INT), array(INT, (1, 101)), v("STEP", INT)
    a = lambda e: v("ARR", INT, ix(e))  # noqa: E731
    body = [
        assign(j, c(101, INT)),
        for_(i, c(1, INT), c(100, INT), [if_((eq(a(i), c(70, INT)), [assign(j, i), exit_()]))], step=step),
    ]

    def program(values):
        return prog(
            pou(
                "MAIN",
                [slot("I", INT), slot("J", INT), slot("STEP", INT, initial=2), slot("ARR", arr, initial=tuple(values))],
                body,
            )
        )

    with_70 = [70 if k in (7, 8, 9) else 0 for k in range(1, 102)]
    assert run(program(with_70), ["MAIN.J", "MAIN.I"]) == [(7, 7)]
    only_even = [70 if k == 8 else 0 for k in range(1, 102)]
    assert run(program(only_even), ["MAIN.J", "MAIN.I"]) == [(101, 101)]


def test_for_to_the_type_limit_terminates_st31():
    """ST-31 overflow guard: FOR i := 1 TO 255 with i : USINT runs 255 times and ends (i wraps to 0 after)."""
    i, n = v("I", USINT), v("N", DINT)
    body = [for_(i, c(1, USINT), c(255, USINT), [assign(n, add(n, c(1, DINT)))])]
    program = prog(pou("MAIN", [slot("I", USINT), slot("N", DINT)], body))
    assert run(program, ["MAIN.N", "MAIN.I"]) == [(255, 0)]


def test_nested_for_exit_leaves_the_inner_loop_st80():
    """ST-80: SUM = 15 with FLAG = 0, SUM = 6 with FLAG = 1."""
    i, j, total, flag = v("I", INT), v("J", INT), v("SUM", INT), v("FLAG", INT)
    body = [
        assign(total, c(0, INT)),
        for_(
            i,
            c(1, INT),
            c(3, INT),
            [
                for_(j, c(1, INT), c(2, INT), [if_((eq(flag, c(1, INT)), [exit_()])), assign(total, add(total, j))]),
                assign(total, add(total, i)),
            ],
        ),
    ]
    for value, expected in ((0, 15), (1, 6)):
        program = prog(
            pou("MAIN", [slot("I", INT), slot("J", INT), slot("SUM", INT), slot("FLAG", INT, initial=value)], body)
        )
        assert run(program, ["MAIN.SUM"]) == [(expected,)]


def test_while_and_repeat_st78_st79():
    """ST-78: var := 1; WHILE var <= 100 DO var := var + 4 -> 101. ST-79: REPEAT var := var + 2 UNTIL var >= 101."""
    w, r, once = v("W", INT), v("R", INT), v("ONCE", INT)
    body = [
        assign(w, c(1, INT)),
        while_(binop("LE", w, c(100, INT)), [assign(w, add(w, c(4, INT)))]),
        assign(r, c(1, INT)),
        repeat([assign(r, add(r, c(2, INT)))], binop("GE", r, c(101, INT))),
        repeat([assign(once, add(once, c(1, INT)))], c(True, BOOL)),
    ]
    program = prog(pou("MAIN", [slot("W", INT), slot("R", INT), slot("ONCE", INT)], body))
    assert run(program, ["MAIN.W", "MAIN.R", "MAIN.ONCE"], 2) == [(101, 101, 1), (101, 101, 2)]


def test_exit_from_while_and_repeat():
    n, k = v("N", INT), v("K", INT)
    body = [
        while_(c(True, BOOL), [assign(n, add(n, c(1, INT))), if_((eq(n, c(3, INT)), [exit_()]))]),
        repeat([assign(k, add(k, c(1, INT))), if_((eq(k, c(4, INT)), [exit_()]))], c(False, BOOL)),
    ]
    program = prog(pou("MAIN", [slot("N", INT), slot("K", INT)], body))
    assert run(program, ["MAIN.N", "MAIN.K"]) == [(3, 4)]


# ------------------------------------------------------------------ functions, RETURN


def _factorial_with_return():
    """Ex 4.15: FACTORIAL with RETURN when the result would overflow UDINT (ST-37)."""
    code, i, res = v("CODE", USINT), v("I", USINT), v("FACTORIAL", UDINT)
    return function(
        "FACTORIAL",
        UDINT,
        [slot("CODE", USINT, "VAR_INPUT"), slot("I", USINT, "VAR_TEMP")],
        [
            assign(res, c(1, UDINT)),
            if_((gt(code, c(13, USINT)), [assign(res, c(0xFFFFFFFF, UDINT)), ret()])),
            for_(i, c(1, USINT), code, [assign(res, mul(res, ir.Convert(i, USINT, UDINT)))]),
        ],
    )


@pytest.mark.parametrize(
    ("n", "expected"), [(0, 1), (1, 1), (5, 120), (12, 479001600), (13, 1932053504), (14, 4294967295)]
)
def test_function_with_return_ex45(n, expected):
    r = v("R", UDINT)
    main = pou("MAIN", [slot("R", UDINT)], [assign(r, call("FACTORIAL", c(n, USINT), type=UDINT, user=True))])
    assert run(prog(main, _factorial_with_return()), ["MAIN.R"]) == [(expected,)]


def test_functions_calling_functions_and_vars_reset_per_call():
    """VAR-43: a FUNCTION's VAR starts at its initial value in every call; functions call functions."""
    x, acc = v("X", INT), v("ACC", INT)
    twice = function(
        "TWICE",
        INT,
        [slot("X", INT, "VAR_INPUT"), slot("ACC", INT, initial=100)],
        [assign(acc, add(acc, x)), assign(v("TWICE", INT), add(acc, x))],
    )
    quad = function(
        "QUAD",
        INT,
        [slot("X", INT, "VAR_INPUT")],
        [assign(v("QUAD", INT), call("TWICE", call("TWICE", x, type=INT, user=True), type=INT, user=True))],
    )
    r = v("R", INT)
    main = pou("MAIN", [slot("R", INT)], [assign(r, call("QUAD", c(1, INT), type=INT, user=True))])
    # TWICE(1) = 100 + 1 + 1 = 102; TWICE(102) = 100 + 102 + 102 = 304, in every scan
    assert run(prog(main, twice, quad), ["MAIN.R"], 2) == [(304,), (304,)]


def test_function_result_defaults_when_never_assigned():
    noop = function("NOOP", INT, [slot("X", INT, "VAR_INPUT")], [])
    r = v("R", INT)
    main = pou("MAIN", [slot("R", INT, initial=9)], [assign(r, call("NOOP", c(1, INT), type=INT, user=True))])
    assert run(prog(main, noop), ["MAIN.R"]) == [(0,)]


def test_return_in_a_program_skips_the_rest():
    a, b = v("A", INT), v("B", INT)
    main = pou(
        "MAIN",
        [slot("A", INT), slot("B", INT)],
        [assign(a, add(a, c(1, INT))), if_((gt(a, c(1, INT)), [ret()])), assign(b, add(b, c(1, INT)))],
    )
    assert run(prog(main), ["MAIN.A", "MAIN.B"], 3) == [(1, 1), (2, 1), (3, 1)]


# ------------------------------------------------------------------ jumps between networks


def test_forward_jump_skips_networks():
    cond, x, y = v("COND", BOOL), v("X", INT), v("Y", INT)
    blocks = [
        network("N1", [jump("SKIP", cond)]),
        network("N2", [assign(x, add(x, c(1, INT)))]),
        network("N3", [assign(y, add(y, c(1, INT)))], label="SKIP"),
    ]
    sim = Simulation(prog(pou("MAIN", [slot("COND", BOOL), slot("X", INT), slot("Y", INT)], blocks)))
    rows = trace(sim, ["MAIN.X", "MAIN.Y"], 2)
    sim.write("MAIN.COND", True)
    rows += trace(sim, ["MAIN.X", "MAIN.Y"], 2)
    assert rows == [(1, 1), (2, 2), (2, 3), (2, 4)]


def test_backward_jump_repeats_networks_and_jump_inside_if():
    """A backward jump is a loop between networks: N1 runs until I reaches 5 within one scan."""
    i, done, hits = v("I", INT), v("DONE", BOOL), v("HITS", INT)
    blocks = [
        network("N0", [assign(hits, add(hits, c(1, INT)))]),
        network("N1", [assign(i, add(i, c(1, INT)))], label="LOOP"),
        network("N2", [if_((lt(i, c(5, INT)), [jump("LOOP")]))]),
        network("N3", [assign(done, c(True, BOOL))]),
    ]
    program = prog(pou("MAIN", [slot("I", INT), slot("DONE", BOOL), slot("HITS", INT)], blocks))
    assert run(program, ["MAIN.I", "MAIN.DONE", "MAIN.HITS"], 2) == [(5, True, 1), (6, True, 2)]


def test_return_in_a_network_ends_the_pou():
    x, y = v("X", INT), v("Y", INT)
    blocks = [
        network("N1", [assign(x, add(x, c(1, INT)))]),
        network("N2", [ret()]),
        network("N3", [assign(y, add(y, c(1, INT)))]),
    ]
    assert run(prog(pou("MAIN", [slot("X", INT), slot("Y", INT)], blocks)), ["MAIN.X", "MAIN.Y"]) == [(1, 0)]


# ------------------------------------------------------------------ function blocks


def _accumulator():
    """A user FB: SUM := SUM + IN; CALLS := CALLS + 1; TMP is VAR_TEMP (VAR-41, VAR-42)."""
    x, total, calls, tmp = v("IN", INT), v("SUM", INT), v("CALLS", INT), v("TMP", INT)
    return pou(
        "ACC",
        [
            slot("IN", INT, "VAR_INPUT"),
            slot("SUM", INT, "VAR_OUTPUT"),
            slot("CALLS", INT),
            slot("TMP", INT, "VAR_TEMP"),
        ],
        [assign(total, add(total, x)), assign(calls, add(calls, c(1, INT))), assign(tmp, add(tmp, c(1, INT)))],
        kind="function_block",
    )


def test_user_fb_instances_keep_their_own_state_and_var_temp_resets():
    a, b, out = v("A", fb("ACC")), v("B", fb("ACC")), v("OUT", INT)
    main = pou(
        "MAIN",
        [slot("A", fb("ACC")), slot("B", fb("ACC")), slot("OUT", INT)],
        [fbcall(a, {"IN": c(2, INT)}, {"SUM": out}), fbcall(b, {"IN": c(10, INT)})],
    )
    rows = run(prog(main, _accumulator()), ["MAIN.OUT", "MAIN.A.CALLS", "MAIN.A.TMP", "MAIN.B.SUM"], 3)
    assert rows == [(2, 1, 1, 10), (4, 2, 1, 20), (6, 3, 1, 30)]


def test_fb_inputs_keep_their_last_value_ex38():
    """ST-26 (Ex 4.8): RECTANGLE(A := 2.0, B := 3.0) -> 10, 6; then RECTANGLE(B := 4.0, A := 2.5) -> 13, 10."""
    a, b, circ, surf = v("A", REAL), v("B", REAL), v("CIRC", REAL), v("SURF", REAL)
    rect = pou(
        "RECT",
        [
            slot("A", REAL, "VAR_INPUT"),
            slot("B", REAL, "VAR_INPUT"),
            slot("CIRC", REAL, "VAR_OUTPUT"),
            slot("SURF", REAL, "VAR_OUTPUT"),
        ],
        [assign(circ, mul(c(2.0, REAL), add(a, b))), assign(surf, mul(a, b))],
        kind="function_block",
    )
    r, o, s = v("R", fb("RECT")), v("O", REAL), v("S", REAL)
    main = pou(
        "MAIN",
        [slot("R", fb("RECT")), slot("O", REAL), slot("S", REAL), slot("O2", REAL)],
        [
            fbcall(r, {"A": c(2.0, REAL), "B": c(3.0, REAL)}, {"CIRC": o, "SURF": s}),
            fbcall(r, {"B": c(4.0, REAL)}),
            assign(v("O2", REAL), v("R", REAL, m("CIRC"))),
        ],
    )
    assert run(prog(main, rect), ["MAIN.O", "MAIN.S", "MAIN.O2", "MAIN.R.SURF"]) == [(10.0, 6.0, 12.0, 8.0)]


def test_ton_on_the_virtual_clock():
    """SFB-17: with a 10 ms task, TON(PT := T#30ms) started in the scan at 10 ms has Q from the scan at 40 ms."""
    t1, q, et = v("T1", fb("TON")), v("Q", BOOL), v("ET", TIME)
    main = pou(
        "MAIN",
        [slot("T1", fb("TON")), slot("Q", BOOL), slot("ET", TIME), slot("RUN", BOOL, initial=True)],
        [fbcall(t1, {"IN": v("RUN", BOOL), "PT": c(30, TIME)}, {"Q": q, "ET": et})],
    )
    sim = Simulation(prog(main))
    rows = trace(sim, ["MAIN.Q", "MAIN.ET"], 5)
    sim.write("MAIN.RUN", False)
    rows += trace(sim, ["MAIN.Q", "MAIN.ET"], 1)
    assert rows == [(False, 0), (False, 10), (False, 20), (True, 30), (True, 30), (False, 0)]


def test_ctu_counts_rising_edges_past_pv():
    """SFB-13: CU rising edges count; Q := CV >= PV; counting goes on past PV."""
    counter, pulse = v("C", fb("CTU")), v("P", BOOL)
    main = pou(
        "MAIN",
        [slot("C", fb("CTU")), slot("P", BOOL)],
        [assign(pulse, binop("XOR", pulse, c(True, BOOL))), fbcall(counter, {"CU": pulse, "PV": c(2, INT)})],
    )
    rows = run(prog(main), ["MAIN.C.CV", "MAIN.C.Q"], 6)
    assert rows == [(1, False), (1, False), (2, True), (2, True), (3, True), (3, True)]


def test_fb_instance_initial_values_and_arrays_of_fbs():
    timers = array(fb("TON"), (1, 2))
    main = pou(
        "MAIN",
        [slot("T", fb("TON"), initial=(("PT", 50),)), slot("TS", timers)],
        [fbcall(v("TS", fb("TON"), ix(c(2, INT))), {"IN": c(True, BOOL), "PT": c(10, TIME)})],
    )
    rows = run(prog(main), ["MAIN.T.PT", "MAIN.TS[1].Q", "MAIN.TS[2].Q"], 2)
    assert rows == [(50, False, False), (50, False, True)]


# ------------------------------------------------------------------ EN / ENO


def test_fncall_en_eno_standard_function_pou40_pou41():
    """EN FALSE: not called, target kept, ENO FALSE; EN TRUE: ENO TRUE unless the checked form warns (overflow)."""
    en, eno, a, x = v("EN", BOOL), v("ENO", BOOL), v("A", INT), v("X", INT)
    main = pou(
        "MAIN",
        [slot("EN", BOOL), slot("ENO", BOOL, initial=True), slot("A", INT, initial=5), slot("X", INT, initial=-1)],
        [ir.FnCall(call("ADD", a, c(1, INT)), x, ir.Origin("?", line=1), en, eno)],
    )
    sim = Simulation(prog(main))
    rows = trace(sim, ["MAIN.X", "MAIN.ENO"], 1)
    sim.write("MAIN.EN", True)
    rows += trace(sim, ["MAIN.X", "MAIN.ENO"], 1)
    sim.write("MAIN.A", 32767)
    rows += trace(sim, ["MAIN.X", "MAIN.ENO"], 1)
    assert rows == [(-1, False), (6, True), (-32768, False)]


def test_fncall_eno_without_en_and_user_function():
    eno, x = v("ENO", BOOL), v("X", INT)
    double = function("DOUBLE", INT, [slot("X", INT, "VAR_INPUT")], [assign(v("DOUBLE", INT), add(x, x))])
    main = pou(
        "MAIN",
        [slot("ENO", BOOL), slot("X", INT, initial=3), slot("ENO2", BOOL), slot("Y", REAL)],
        [
            fncall(call("DOUBLE", x, type=INT, user=True), x, eno=eno),
            fncall(call("SQRT", c(-1.0, REAL)), v("Y", REAL), eno=v("ENO2", BOOL)),
        ],
    )
    assert run(prog(main, double), ["MAIN.X", "MAIN.ENO", "MAIN.ENO2"], 2) == [(6, True, False), (12, True, False)]


def test_fbcall_en_false_does_not_execute_or_copy_outputs():
    t1, en, eno, q = v("T1", fb("TON")), v("EN", BOOL), v("ENO", BOOL), v("Q", BOOL)
    main = pou(
        "MAIN",
        [slot("T1", fb("TON")), slot("EN", BOOL, initial=True), slot("ENO", BOOL), slot("Q", BOOL)],
        [fbcall(t1, {"IN": c(True, BOOL), "PT": c(20, TIME)}, {"Q": q}, en=en, eno=eno)],
    )
    sim = Simulation(prog(main))
    rows = trace(sim, ["MAIN.Q", "MAIN.ENO", "MAIN.T1.ET"], 2)
    sim.write("MAIN.EN", False)
    rows += trace(sim, ["MAIN.Q", "MAIN.ENO", "MAIN.T1.ET"], 2)
    assert rows == [(False, True, 0), (False, True, 10), (False, False, 10), (False, False, 10)]


# ------------------------------------------------------------------ VAR_IN_OUT by reference (VAR-51..53)


def _inc():
    x = v("X", INT)
    return function(
        "INC",
        BOOL,
        [slot("X", INT, "VAR_IN_OUT")],
        [assign(x, add(x, c(1, INT))), assign(v("INC", BOOL), c(True, BOOL))],
    )


def _inc_call(target: ir.Var) -> ir.FnCall:
    return fncall(ir.Call("INC", (), (), BOOL, True, (target,)))


def test_var_in_out_reaches_scalars_elements_fields_and_globals():
    arr, pt = array(INT, (1, 3)), struct("PT", ("X", INT), ("Y", INT))
    targets = [v("A", INT), v("ARR", INT, ix(c(2, INT))), v("S", INT, m("Y")), g("G", INT)]
    main = pou("MAIN", [slot("A", INT), slot("ARR", arr), slot("S", pt)], [_inc_call(x) for x in targets])
    rows = run(
        prog(main, _inc(), globals=[slot("G", INT, "VAR_GLOBAL", initial=40)]), ["MAIN.A", "MAIN.ARR", "MAIN.S", "G"], 2
    )
    assert rows == [(1, [0, 1, 0], {"X": 0, "Y": 1}, 41), (2, [0, 2, 0], {"X": 0, "Y": 2}, 42)]


def test_var_in_out_cascades_and_boxes_function_locals():
    """VAR-52: an in-out passed on to another POU's in-out; a function's local passed by reference."""
    y = v("Y", INT)
    outer = function("OUTER", BOOL, [slot("Y", INT, "VAR_IN_OUT")], [_inc_call(y), _inc_call(y)])
    loc = v("L", INT)
    local = function("LOCAL", INT, [slot("L", INT, initial=5)], [_inc_call(loc), assign(v("LOCAL", INT), loc)])
    main = pou(
        "MAIN",
        [slot("A", INT), slot("B", INT)],
        [
            fncall(ir.Call("OUTER", (), (), BOOL, True, (v("A", INT),))),
            assign(v("B", INT), ir.Call("LOCAL", (), (), INT, True)),
        ],
    )
    assert run(prog(main, _inc(), outer, local), ["MAIN.A", "MAIN.B"], 2) == [(2, 6), (4, 6)]


def test_var_in_out_array_whole_ex20():
    """EX-20 / VAR-53: Suma2(buffer, 10) sums through the reference (55) and writes through it."""
    buf = array(INT, (1, 10))
    _vec, length, i, total = v("VECTOR", buf), v("LENGTH", INT), v("I", INT), v("SUMA2", INT)
    suma2 = function(
        "SUMA2",
        INT,
        [slot("VECTOR", buf, "VAR_IN_OUT"), slot("LENGTH", INT, "VAR_INPUT"), slot("I", INT, "VAR_TEMP")],
        [
            assign(total, c(0, INT)),
            for_(i, c(1, INT), length, [assign(total, add(total, v("VECTOR", INT, ix(i))))]),
            assign(v("VECTOR", INT, ix(c(1, INT))), c(100, INT)),
        ],
    )
    main = pou(
        "MAIN",
        [slot("BUFFER", buf, initial=tuple(range(1, 11))), slot("R", INT)],
        [assign(v("R", INT), ir.Call("SUMA2", (c(10, INT),), (INT,), INT, True, (v("BUFFER", buf),)))],
    )
    assert run(prog(main, suma2), ["MAIN.R", "MAIN.BUFFER[1]"], 2) == [(55, 100), (154, 100)]


def test_fb_in_out_pin_writes_the_callers_variable():
    x = v("X", INT)
    bump = pou("BUMP", [slot("X", INT, "VAR_IN_OUT")], [assign(x, add(x, c(10, INT)))], kind="function_block")
    main = pou(
        "MAIN",
        [slot("B", fb("BUMP")), slot("A", INT), slot("C", INT)],
        [fbcall(v("B", fb("BUMP")), {"X": v("A", INT)}), fbcall(v("B", fb("BUMP")), {"X": v("C", INT)})],
    )
    assert run(prog(main, bump), ["MAIN.A", "MAIN.C"], 2) == [(10, 10), (20, 20)]


# ------------------------------------------------------------------ whole arrays and structures (ST-21, TYP-36)


def test_whole_structure_and_array_assignment_copies():
    pt = struct("PT", ("X", INT, 1), ("Y", INT, 2))
    arr = array(pt, (0, 1))
    body = [
        assign(v("B", pt), v("A", pt)),
        assign(v("A", pt, m("X")), c(50, INT)),
        assign(v("BB", arr), v("AA", arr)),
        assign(v("AA", INT, ix(c(0, INT)), m("Y")), c(60, INT)),
    ]
    main = pou("MAIN", [slot("A", pt), slot("B", pt, initial=(7, 8)), slot("AA", arr), slot("BB", arr)], body)
    rows = run(prog(main), ["MAIN.A", "MAIN.B", "MAIN.AA[0].Y", "MAIN.BB[0].Y"])
    assert rows == [({"X": 50, "Y": 2}, {"X": 1, "Y": 2}, 60, 2)]


def test_multidimensional_array_initial_values_row_major():
    """TYP-26: [1..2, 1..3] initialised ((11, 12, 13), (21, 22, 23)); the last index varies fastest."""
    grid = array(INT, (1, 2), (1, 3))
    main = pou(
        "MAIN",
        [slot("G", grid, initial=((11, 12, 13), (21, 22, 23))), slot("X", INT)],
        [assign(v("X", INT), v("G", INT, ix(c(2, INT), c(1, INT))))],
    )
    assert run(prog(main), ["MAIN.X", "MAIN.G[1, 3]", "MAIN.G"]) == [(21, 13, [[11, 12, 13], [21, 22, 23]])]


def test_global_fb_instance_and_udint_arithmetic():
    counter = g("GC", fb("CTU_UDINT"))
    main = pou(
        "MAIN",
        [slot("P", BOOL)],
        [
            assign(v("P", BOOL), binop("XOR", v("P", BOOL), c(True, BOOL))),
            fbcall(counter, {"CU": v("P", BOOL), "PV": c(1, UDINT)}),
        ],
    )
    rows = run(prog(main, globals=[slot("GC", fb("CTU_UDINT"), "VAR_GLOBAL")]), ["GC.CV", "GVL.GC.Q"], 3)
    assert rows == [(1, True), (1, True), (2, True)]


def test_subrange_stores_are_checked():
    """A subrange target is checked on every store (TYP-14 [IEC]); a store inside the range passes."""
    pct = t.Subrange(INT, 0, 100)
    x = v("X", pct)
    main = pou("MAIN", [slot("X", pct)], [assign(x, add(x, c(40, INT)))])
    sim = Simulation(prog(main))
    assert trace(sim, ["MAIN.X"], 2) == [(40,), (80,)]
    sim.cycle()
    assert sim.fault.code == "subrange_violation" and sim.read("MAIN.X") == 80


@given(st.integers(-128, 127), st.integers(-128, 127), st.integers(-128, 127).filter(bool))
def test_for_loops_match_the_st70_model(start, end, step):
    """ST-70/71 as a model: test before each iteration, end and step read once, afterwards last + step (wrapped)."""
    sint = T["SINT"]
    i, n, total = v("I", sint), v("N", DINT), v("TOTAL", DINT)
    body = [
        for_(
            i,
            c(start, sint),
            c(end, sint),
            [assign(n, add(n, c(1, DINT))), assign(total, add(total, ir.Convert(i, sint, DINT)))],
            step=c(step, sint),
        )
    ]
    program = prog(pou("MAIN", [slot("I", sint), slot("N", DINT), slot("TOTAL", DINT)], body))
    visited, value = [], start
    while (value <= end) if step > 0 else (value >= end):
        visited.append(value)
        value += step
    after = reference_wrap(value, "SINT") if visited else start
    assert run(program, ["MAIN.N", "MAIN.TOTAL", "MAIN.I"]) == [(len(visited), sum(visited), after)]
