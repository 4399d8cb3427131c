"""Expressions through the code generator, checked scan by scan through the Simulation API.

Integer wrap on every store at every width (FUN-90), REAL float32 rounding
(TYP-03, ST-43), conversions (FUN-10/11), operators as standard functions
(ST-04), and a hypothesis property comparing random integer expression trees
with an evaluation by the runtime library's own functions.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.engine.compile import emit_python
from ladderlab.engine.simulation import Simulation
from ladderlab.engine.stdlib import converter, make_function
from ladderlab.iec.values import f32
from ladderlab.ir import nodes as ir
from ladderlab.ir import types as t

from .helpers import INT_TYPES, int_range, is_float32, reference_wrap
from .irbuild import (
    BOOL,
    DINT,
    INT,
    LREAL,
    REAL,
    SINT,
    STRING,
    TIME,
    UDINT,
    USINT,
    T,
    add,
    assign,
    binop,
    c,
    call,
    conv,
    for_,
    mul,
    neg,
    not_,
    pou,
    prog,
    slot,
    string,
    sub,
    v,
)


def one_scan(slots, statements, paths):
    sim = Simulation(prog(pou("MAIN", slots, statements)))
    sim.cycle()
    assert sim.fault is None, sim.fault and sim.fault.text()
    return [sim.read(p) for p in paths]


@pytest.mark.parametrize("name", INT_TYPES)
def test_integer_store_wraps_at_every_width(name):
    """FUN-90: MAX + 1 wraps to MIN and MIN - 1 to MAX on the store, scan after scan."""
    ty = T[name]
    lo, hi = int_range(name)
    up, down = v("UP", ty), v("DOWN", ty)
    sim = Simulation(
        prog(
            pou(
                "MAIN",
                [slot("UP", ty, initial=hi - 1), slot("DOWN", ty, initial=lo + 1)],
                [assign(up, add(up, c(1, ty))), assign(down, sub(down, c(1, ty)))],
            )
        )
    )
    seen = []
    for _ in range(3):
        sim.cycle()
        seen.append((sim.read("MAIN.UP"), sim.read("MAIN.DOWN")))
    assert seen == [(hi, lo), (lo, hi), (lo + 1, hi - 1)]


def test_int_32767_plus_1_is_minus_32768_st90():
    """ST-90: IF i <= max THEN i := i + 1 with max = 32767 wraps to -32768 without an error."""
    i = v("I", INT)
    body = [assign(i, add(i, c(1, INT)))]
    assert one_scan([slot("I", INT, initial=32767)], body, ["MAIN.I"]) == [-32768]


@pytest.mark.parametrize("name", INT_TYPES)
def test_negation_wraps(name):
    ty = T[name]
    lo, _ = int_range(name)
    x = v("X", ty)
    expected = reference_wrap(-lo, name)
    assert one_scan([slot("X", ty, initial=lo)], [assign(x, neg(x))], ["MAIN.X"]) == [expected]


def test_real_results_are_rounded_to_float32_and_equal_the_literal_st43():
    """ST-43: 11.2 stored in a REAL equals the REAL literal 11.2; REAL arithmetic rounds every result."""
    r, s, same = v("R", REAL), v("S", REAL), v("SAME", BOOL)
    body = [
        assign(r, c(11.2, REAL)),
        assign(s, mul(c(0.1, REAL), c(3.0, REAL))),
        assign(same, binop("EQ", r, c(11.2, REAL))),
    ]
    value, product, equal = one_scan(
        [slot("R", REAL), slot("S", REAL), slot("SAME", BOOL)], body, ["MAIN.R", "MAIN.S", "MAIN.SAME"]
    )
    assert value == f32(11.2) != 11.2 and equal is True
    assert product == f32(f32(0.1) * 3.0) and is_float32(product)


def test_lreal_keeps_double_precision():
    x = v("X", LREAL)
    assert one_scan([slot("X", LREAL)], [assign(x, mul(c(0.1, LREAL), c(3.0, LREAL)))], ["MAIN.X"]) == [0.1 * 3.0]


def test_real_overflow_is_infinity_and_nan_is_kept():
    big, nan = v("BIG", REAL), v("NAN", REAL)
    body = [assign(big, mul(c(3e38, REAL), c(10.0, REAL))), assign(nan, call("SQRT", c(-1.0, REAL)))]
    value, not_a_number = one_scan([slot("BIG", REAL), slot("NAN", REAL)], body, ["MAIN.BIG", "MAIN.NAN"])
    assert value == math.inf and math.isnan(not_a_number)


@pytest.mark.parametrize(
    ("function", "source", "value", "target", "expected"),
    [
        ("REAL_TO_INT", REAL, 2.5, INT, 2),  # FUN-11: ties to even
        ("REAL_TO_INT", REAL, 3.5, INT, 4),
        ("REAL_TO_INT", REAL, -1.6, INT, -2),
        ("INT_TO_SINT", INT, 200, SINT, -56),  # narrowing wraps
        ("DINT_TO_USINT", DINT, -1, USINT, 255),
        ("INT_TO_REAL", INT, 8, REAL, 8.0),  # ST-08
        ("INT_TO_BOOL", INT, 7, BOOL, True),
        ("TIME_TO_DINT", TIME, 1500, DINT, 1500),
        ("INT_TO_STRING", INT, -25, STRING, "-25"),
        ("STRING_TO_INT", STRING, "123", INT, 123),
        ("TRUNC", REAL, -4.7, DINT, -4),
    ],
)
def test_conversion_calls(function, source, value, target, expected):
    x, y = v("X", source), v("Y", target)
    out = one_scan(
        [slot("X", source, initial=value), slot("Y", target)], [assign(y, call(function, x, type=target))], ["MAIN.Y"]
    )
    assert out == [expected]


def test_implicit_widening_convert_and_subrange_store_check():
    """A Convert node (implicit widening) keeps the value; storing into a subrange checks the range."""
    sub_t = t.Subrange(INT, 0, 100)
    small, wide, pct = v("SMALL", SINT), v("WIDE", DINT), v("PCT", sub_t)
    out = one_scan(
        [slot("SMALL", SINT, initial=-100), slot("WIDE", DINT), slot("PCT", sub_t)],
        [assign(wide, conv(small, DINT)), assign(pct, c(42, sub_t))],
        ["MAIN.WIDE", "MAIN.PCT"],
    )
    assert out == [-100, 42]


def test_string_store_cuts_to_declared_length_typ04():
    s = v("S", string(3))
    out = one_scan([slot("S", string(3))], [assign(s, call("CONCAT", c("ab", STRING), c("cdef", STRING)))], ["MAIN.S"])
    assert out == ["abc"]


def test_boolean_operators_evaluate_every_operand_and_give_bools():
    a, b, x, y, z = (v(n, BOOL) for n in "ABXYZ")
    body = [assign(x, binop("AND", a, not_(b))), assign(y, binop("XOR", a, b)), assign(z, binop("OR", b, b))]
    assert one_scan(
        [slot("A", BOOL, initial=True), slot("B", BOOL), *(slot(n, BOOL) for n in "XYZ")],
        body,
        ["MAIN.X", "MAIN.Y", "MAIN.Z"],
    ) == [True, True, False]


def test_bit_string_not_and_shift():
    w, n, s = v("W", T["WORD"]), v("N", T["WORD"]), v("S", T["WORD"])
    body = [assign(n, not_(w)), assign(s, call("SHL", w, c(4, INT)))]
    assert one_scan(
        [slot("W", T["WORD"], initial=0x0FF0), slot("N", T["WORD"]), slot("S", T["WORD"])], body, ["MAIN.N", "MAIN.S"]
    ) == [0xF00F, 0xFF00]


def test_constants_are_stored_in_their_type_and_emitted_with_repr():
    """A constant out of its type's range is wrapped at compile time; strings appear via repr only."""
    x, s = v("X", USINT), v("S", STRING)
    text = "'); import os #\n\\"
    program = prog(
        pou("MAIN", [slot("X", USINT), slot("S", STRING)], [assign(x, c(300, USINT)), assign(s, c(text, STRING))])
    )
    source = emit_python(program)
    assert repr(text) in source and "import os #\n" not in source
    sim = Simulation(program)
    sim.cycle()
    assert (sim.read("MAIN.X"), sim.read("MAIN.S")) == (44, text)


# ------------------------------------------------------------------ property: random integer expressions


@st.composite
def _tree(draw, name: str, depth: int):
    ty = T[name]
    lo, hi = int_range(name)
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        if draw(st.booleans()):
            return c(draw(st.integers(lo, hi)), ty)
        return v(draw(st.sampled_from(["X0", "X1", "X2"])), ty)
    kind = draw(st.sampled_from(["ADD", "SUB", "MUL", "DIV", "MOD", "NEG", "ABS", "MAX", "LIMIT", "SEL", "WIDEN"]))
    sub_tree = lambda: draw(_tree(name, depth - 1))  # noqa: E731
    if kind in ("ADD", "SUB", "MUL", "DIV", "MOD"):
        return binop(kind, sub_tree(), sub_tree())
    if kind == "NEG":
        return neg(sub_tree())
    if kind in ("ABS", "MAX", "LIMIT"):
        args = [sub_tree() for _ in range({"ABS": 1, "MAX": 2, "LIMIT": 3}[kind])]
        return call(kind, *args, type=ty)
    if kind == "SEL":
        return call("SEL", binop("GT", sub_tree(), sub_tree()), sub_tree(), sub_tree(), type=ty)
    narrower = [n for n in INT_TYPES if int_range(n)[0] >= lo and int_range(n)[1] <= hi and n != name]
    if not narrower:
        return sub_tree()
    source = draw(st.sampled_from(narrower))
    slo, shi = int_range(source)
    return ir.Convert(c(draw(st.integers(slo, shi)), T[source]), T[source], ty)


def _reference(e: ir.Expr, env: dict[str, int]) -> object:
    """Evaluate with the runtime library's functions, one call per node (no code generation involved)."""
    if isinstance(e, ir.Const):
        return e.value
    if isinstance(e, ir.Var):
        return env[e.name]
    if isinstance(e, ir.Unary):
        return reference_wrap(-_reference(e.operand, env), e.type.name)
    if isinstance(e, ir.Convert):
        return converter(e.source.name, e.type.name)(_reference(e.operand, env))
    if isinstance(e, ir.Binary):
        args = (_reference(e.left, env), _reference(e.right, env))
        return make_function(e.op, (e.left.type.name, e.right.type.name), e.type.name)(*args)
    args = [_reference(a, env) for a in e.args]
    return make_function(e.function, tuple(a.name for a in e.arg_types), e.type.name)(*args)


@st.composite
def _case(draw):
    name = draw(st.sampled_from(INT_TYPES))
    lo, hi = int_range(name)
    env = {f"X{i}": draw(st.integers(lo, hi)) for i in range(3)}
    return name, env, draw(_tree(name, 4))


@given(_case())
def test_random_integer_expressions_match_the_runtime_library(case):
    name, env, expression = case
    ty = T[name]
    slots = [slot(k, ty, initial=value) for k, value in env.items()] + [slot("R", ty)]
    sim = Simulation(prog(pou("MAIN", slots, [assign(v("R", ty), expression)])))
    try:
        expected = _reference(expression, env)
    except Exception as error:
        sim.cycle()
        assert sim.fault is not None and sim.fault.code == getattr(error, "code", None)
        assert sim.read("MAIN.R") == 0
        return
    sim.cycle()
    assert sim.fault is None, sim.fault.text()
    assert sim.read("MAIN.R") == expected
    assert int_range(name)[0] <= expected <= int_range(name)[1]


def test_udint_factorial_wraps_like_st37():
    """ST-37: 13! wraps in UDINT to 1 932 053 504."""
    r, i = v("R", UDINT), v("I", UDINT)
    body = [assign(r, c(1, UDINT)), for_(i, c(1, UDINT), c(13, UDINT), [assign(r, mul(r, i))])]
    assert one_scan([slot("R", UDINT), slot("I", UDINT)], body, ["MAIN.R"]) == [1_932_053_504]
