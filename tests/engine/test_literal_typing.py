"""Literal typing from context (issue 16; IEC 61131-3 ed. 2 2.4.1, ed. 3 6.4.2; ST-24, LEX-26, FUN-02).

Every expected value comes from the rule as docs/st.md states it, computed here with exact Python integers and
IEEE binary32 (``struct``) / binary64: a generic operation computes in the smallest type that fits its typed
operands and its context, literals take that type and must fit it. The property test builds random expressions
of literals and variables of every integer and real type and checks that the engine agrees with this
independent reference or that the checker refuses the program - never a literal silently wrapped.
"""

from __future__ import annotations

import math
import struct

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def run(declarations: str, body: str, scans: int = 1):
    """(simulation, diagnostics) of a program Main; simulation None when it does not build."""
    project, diagnostics = source_to_project(f"PROGRAM Main\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n", "t")
    assert project is not None, diagnostics
    build = build_project(project)
    if build.compiled is None:
        return None, build.diagnostics
    sim = build.simulation()
    sim.cycle(scans)
    assert sim.fault is None, sim.fault.text()
    return sim, build.diagnostics


def errors(declarations: str, body: str) -> list[tuple]:
    sim, diagnostics = run(declarations, body)
    return [(d.code, d.line, d.column, d.message) for d in diagnostics if d.severity == "error"]


def f32(x: float) -> float:
    """Round to IEEE binary32 (ties to even); beyond its range: infinity."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


# ---------------------------------------------------------------- the cases, scan by scan


@pytest.mark.parametrize(
    "declarations, body, variable, expected",
    [
        ("m : DINT;", "m := MAX(1, 100000);", "m", 100000),  # was 1: 100000 wrapped to INT
        ("l : LINT;", "l := LIMIT(1000000000, 4000000000, 3000000000);", "l", 3000000000),  # was -1294967296
        ("u : UDINT;", "u := LIMIT(1000000000, 4000000000, 3000000000);", "u", 3000000000),
        ("r : REAL;", "r := SQRT(25.0);", "r", 5.0),  # was refused: cannot assign LREAL to REAL
        ("r : REAL;", "r := EXPT(2.0, 3.0);", "r", 8.0),
        ("r : REAL;", "r := SEL(FALSE, 10.5, 20.5);", "r", 10.5),
        ("r : REAL;", "r := MUX(2, 10.5, 20.5, 30.1);", "r", f32(30.1)),
        ("s : SINT;", "s := MAX(1, 2);", "s", 2),  # was refused: cannot assign INT to SINT
        ("s : SINT;", "s := -128;", "s", -128),
        ("d : DINT; i : INT := 300;", "d := i * i;", "d", 90000),  # computed in DINT, the target's type
        ("d : DINT; i : INT := 30000;", "d := i + 30000;", "d", 60000),
        ("x : INT; i : INT := 300;", "x := i * i;", "x", 90000 - 65536),  # INT wraps at run time (FUN-90)
        ("r : REAL;", "r := 0.1 + 0.2;", "r", f32(f32(0.1) + f32(0.2))),  # each REAL step is binary32
        ("lr : LREAL;", "lr := 0.1 + 0.2;", "lr", 0.1 + 0.2),
        ("lr : LREAL; r : REAL := 0.5;", "lr := r * 0.1;", "lr", 0.5 * 0.1),  # 0.1 as LREAL, r widened
        ("r : REAL;", "r := 1 / 4;", "r", 0.25),  # integer literals in a REAL context are REAL
        ("b : BOOL;", "b := 5 < 300;", "b", True),  # alone: the smallest type that fits both (INT)
        ("b : BOOL; si : SINT := 5;", "b := MAX(si, 7) > 6;", "b", True),
        ("w : WORD;", "w := 16#FFFF AND 16#0F0F;", "w", 0x0F0F),
        ("x : INT;", "x := 32767 + 1;", "x", -32768),  # wraps as at run time; the checker warns
        ("v : ULINT;", "v := 18446744073709551615;", "v", 2**64 - 1),
    ],
)
def test_literals_take_the_type_of_their_context(declarations, body, variable, expected):
    sim, _ = run(declarations, body)
    assert sim is not None
    value = sim.read(f"Main.{variable}")
    assert value == expected and type(value) is type(expected)


def test_constants_fold_exactly_as_the_scan_computes():
    """CONSTANT arithmetic (array bounds, CASE labels) divides integers exactly, truncating toward zero."""
    project, _ = source_to_project(
        "PROGRAM Main\nVAR CONSTANT big : LINT := 1000000000000000001; END_VAR\n"
        "VAR a : ARRAY[0..(big / 3) - 333333333333333330] OF INT; n : INT; k : LINT := 333333333333333333; END_VAR\n"
        "CASE k OF big / 3: n := SIZEOF(a) / 2; END_CASE;\nEND_PROGRAM\n",
        "t",
    )
    build = build_project(project)
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    assert (len(sim.read("Main.a")), sim.read("Main.n")) == (4, 4)  # was refused: 10**18 / 3 through a float


def test_a_call_statement_settles_its_generic_arguments():
    """A standard function called as a statement (its result unused) still computes in one type (FUN-02): in
    ``SEL(i0, c0, MAX(1, 2));`` the literal call MAX(1, 2) takes SEL's INT (c0), as it does in ``x := SEL(...)``; its
    ENO is TRUE. (It was left untyped and the lowering failed, IR-INTERNAL: the FBD export property test found it.)"""
    sim, diagnostics = run(
        "i0 : BOOL; c0 : INT; ok : BOOL; sum_ok : BOOL;",
        "SEL(G := i0, IN0 := c0, IN1 := MAX(1, 2), ENO => ok);\nADD(EN := TRUE, IN1 := 1, IN2 := 2, ENO => sum_ok);",
    )
    assert [d.format() for d in diagnostics if d.severity == "error"] == []
    assert (sim.read("Main.ok"), sim.read("Main.sum_ok")) == (True, True)


def test_a_constant_expression_that_wraps_is_warned_about():
    _, diagnostics = run("x : INT;", "x := 32767 + 1;")
    assert [(d.severity, d.code, d.line, d.column, d.message) for d in diagnostics] == [
        (
            "warning",
            "ST-RANGE",
            3,
            6,
            "this constant expression is 32768, out of range for INT: it wraps to -32768",
        )
    ]


@pytest.mark.parametrize(
    "declarations, body, expected",
    [
        ("x : INT;", "x := 16#FFFF;", ("ST-RANGE", 3, 6, "65535 is out of range for INT (-32768..32767)")),
        ("x : INT;", "x := MAX(x, 100000);", ("ST-RANGE", 3, 13, "100000 is out of range for INT (-32768..32767)")),
        ("s : SINT;", "s := MAX(1, 200);", ("ST-RANGE", 3, 13, "200 is out of range for SINT (-128..127)")),
        ("b : BYTE;", "b := -1;", ("ST-RANGE", 3, 6, "-1 is out of range for BYTE (0..255)")),
        ("si : SINT;", "si := si + 1000;", ("ST-RANGE", 3, 12, "1000 is out of range for SINT (-128..127)")),
        ("r : REAL;", "r := 1.0E39;", ("ST-RANGE", 3, 6, "1e+39 is out of range for REAL")),
        ("x : INT;", "x := 10 / 0;", ("ST-RANGE", 3, 6, "division by zero in a constant expression")),
        (
            "x : INT; r : REAL;",
            "x := r + 1;",
            ("ST-TYPE-MISMATCH", 3, 6, "cannot assign REAL to INT without a conversion such as REAL_TO_INT"),
        ),
        (
            "x : INT;",
            "x := 2.5;",
            ("ST-TYPE-MISMATCH", 3, 6, "cannot assign ANY_REAL literal to INT"),
        ),
    ],
)
def test_a_literal_that_does_not_fit_its_type_is_a_located_error(declarations, body, expected):
    found = errors(declarations, body)
    assert len(found) == 1
    code, line, column, message = found[0]
    assert (code, line, column, message) == expected


# ---------------------------------------------------------------- the property: engine == reference or refused

INTEGERS = {
    "SINT": (8, True),
    "INT": (16, True),
    "DINT": (32, True),
    "LINT": (64, True),
    "USINT": (8, False),
    "UINT": (16, False),
    "UDINT": (32, False),
    "ULINT": (64, False),
}
REALS = ("REAL", "LREAL")
TYPES = (*INTEGERS, *REALS)
_SIGNED = ["SINT", "INT", "DINT", "LINT"]
_UNSIGNED = ["USINT", "UINT", "UDINT", "ULINT"]


def widens(source: str, target: str) -> bool:
    """IEC lossless widening as docs/st.md states it: along one chain, unsigned into a larger signed, REAL->LREAL."""
    if source == target:
        return True
    for chain in (_SIGNED, _UNSIGNED):
        if source in chain and target in chain:
            return chain.index(source) < chain.index(target)
    if source in _UNSIGNED and target in _SIGNED:
        return _UNSIGNED.index(source) < _SIGNED.index(target)
    return (source, target) == ("REAL", "LREAL")


def in_range(type_name: str, value: int) -> bool:
    bits, signed = INTEGERS[type_name]
    low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
    return low <= value <= high


def wrap(type_name: str, value: int) -> int:
    bits, signed = INTEGERS[type_name]
    value &= (1 << bits) - 1
    return value - (1 << bits) if signed and value >> (bits - 1) else value


class Refused(Exception):
    """The checker must refuse this program."""


class Fault(Exception):
    """The scan must stop with a runtime error (integer division by zero)."""


# Expressions as trees: ("lit", text, value) | ("var", name, type) | (op, children...).
@st.composite
def expressions(draw, names: dict[str, str], depth: int = 0):
    if depth >= 3 or draw(st.integers(0, 2)) == 0:
        if draw(st.booleans()):
            name = draw(st.sampled_from(sorted(names)))
            return ("var", name, names[name])
        if draw(st.integers(0, 7)) == 0:
            value = draw(st.sampled_from([0.5, 2.25, 1.0e20, 0.1, 3.0, 1.0e39, 100.75]))
            return ("lit", repr(value).upper().replace("E+", "E"), value)
        value = draw(
            st.one_of(
                st.integers(0, 300), st.sampled_from([32767, 32768, 65535, 100000, 2**31, 2**40, 2**63, 2**64 - 1])
            )
        )
        return ("lit", str(value), value)
    kind = draw(st.sampled_from(["+", "-", "*", "/", "neg", "MAX", "MIN", "LIMIT", "ABS", "SEL"]))
    sub = expressions(names, depth + 1)
    if kind in ("+", "-", "*", "/", "MAX", "MIN"):
        return (kind, draw(sub), draw(sub))
    if kind == "LIMIT":
        return (kind, draw(sub), draw(sub), draw(sub))
    if kind == "SEL":
        return (kind, draw(st.booleans()), draw(sub), draw(sub))
    return (kind, draw(sub))


def render(e) -> str:
    kind = e[0]
    if kind in ("lit", "var"):
        return e[1]
    if kind in ("+", "-", "*", "/"):
        return f"({render(e[1])} {kind} {render(e[2])})"
    if kind == "neg":
        return f"-({render(e[1])})"
    if kind == "SEL":
        return f"SEL({'TRUE' if e[1] else 'FALSE'}, {render(e[2])}, {render(e[3])})"
    return f"{kind}({', '.join(render(x) for x in e[1:])})"


def leaves(e):
    """Literals (``-(128)`` is the signed literal -128, as in IEC) and variables."""
    if e[0] in ("lit", "var"):
        yield e
    elif e[0] == "neg" and e[1][0] == "lit":
        yield ("lit", "", -e[1][2])
    else:
        for child in e[1:]:
            if isinstance(child, tuple):
                yield from leaves(child)


def literal_only(e) -> bool:
    return e[0] in ("lit", "+", "-", "*", "/", "neg") and all(x[0] == "lit" or literal_only(x) for x in e[1:])


def reference(e, target: str, values: dict[str, object]):
    """The value ``target := e`` stores, by the rule of docs/st.md, or Refused / Fault."""
    types = {x[2] for x in leaves(e) if x[0] == "var"}
    if not all(widens(ty, target) for ty in types):
        raise Refused("a variable does not widen to the target (no common type, or narrowing)")
    for leaf in leaves(e):  # what the checker refuses comes before anything the scan would do
        if leaf[0] == "lit":
            evaluate(leaf, target, values)
    for constant in literal_subtrees(e):
        evaluate(constant, target, values)
    return evaluate(e, target, values)


def literal_subtrees(e):
    if literal_only(e):
        yield e
    elif e[0] not in ("lit", "var"):
        for child in e[1:]:
            if isinstance(child, tuple):
                yield from literal_subtrees(child)


def evaluate(e, ty: str, values: dict[str, object]):
    """``e`` computed in ``ty``: every operation of one expression computes in the same type (its typed operands
    widened, its literals taking the type); integers wrap, REAL rounds to binary32 at each step."""
    kind = e[0]
    real = ty in REALS
    if kind == "lit":
        value = e[2]
        if isinstance(value, float) and not real:
            raise Refused("a real literal in an integer context")
        if real:
            stored = f32(float(value)) if ty == "REAL" else float(value)
            if math.isinf(stored):
                raise Refused("literal out of REAL range")
            return stored
        if not in_range(ty, value):
            raise Refused("literal out of range")
        return value
    if kind == "var":
        return values[e[1]]  # widening keeps the value
    if kind == "neg" and e[1][0] == "lit":  # -(literal) is the signed literal
        return evaluate(("lit", "", -e[1][2]), ty, values)
    args = [evaluate(x, ty, values) if isinstance(x, tuple) else x for x in e[1:]]
    if kind == "SEL":
        return args[2] if args[0] else args[1]
    if kind in ("MAX", "MIN", "LIMIT") and any(a != a for a in args):
        return math.nan  # of REALs, a NaN argument gives NaN whatever its place (IEEE 754-2019 maximum/minimum)
    if kind == "MAX":
        return max(args)
    if kind == "MIN":
        return min(args)
    if kind == "LIMIT":
        return min(max(args[1], args[0]), args[2])
    if kind == "ABS":
        result = abs(args[0])
    elif kind == "neg":
        result = -args[0]
    elif kind == "+":
        result = args[0] + args[1]
    elif kind == "-":
        result = args[0] - args[1]
    elif kind == "*":
        result = args[0] * args[1]
    elif real:
        if args[1] == 0:
            if literal_only(e):
                raise Refused("division by zero in a constant expression")
            result = (
                math.nan
                if args[0] == 0 or math.isnan(args[0])
                else math.copysign(math.inf, args[0]) * (math.copysign(1.0, args[1]))
            )
        else:
            result = args[0] / args[1]
    else:
        if args[1] == 0:
            if literal_only(e):
                raise Refused("division by zero in a constant expression")
            raise Fault
        quotient = abs(args[0]) // abs(args[1])
        result = quotient if (args[0] < 0) == (args[1] < 0) else -quotient
    if real:
        return f32(result) if ty == "REAL" else result
    return wrap(ty, result)


VARIABLE_VALUES = {
    "SINT": st.integers(-128, 127),
    "INT": st.integers(-32768, 32767),
    "DINT": st.integers(-(2**31), 2**31 - 1),
    "LINT": st.integers(-(2**63), 2**63 - 1),
    "USINT": st.integers(0, 255),
    "UINT": st.integers(0, 65535),
    "UDINT": st.integers(0, 2**32 - 1),
    "ULINT": st.integers(0, 2**64 - 1),
    "REAL": st.floats(-1e6, 1e6, allow_nan=False).map(f32),
    "LREAL": st.floats(-1e12, 1e12, allow_nan=False),
}


@st.composite
def programs(draw):
    target = draw(st.sampled_from(TYPES))
    fitting = st.sampled_from([ty for ty in TYPES if widens(ty, target)])  # half the time: a type the target takes
    kinds = draw(st.sets(st.one_of(fitting, st.sampled_from(TYPES)), min_size=1, max_size=3))
    names = {f"v_{ty.lower()}": ty for ty in kinds}
    values = {name: draw(VARIABLE_VALUES[ty]) for name, ty in names.items()}
    return target, names, values, draw(expressions(names))


def literal(value, ty: str) -> str:
    return repr(value) if ty in REALS else str(value)


@given(programs())
@settings(  # a few ms each: more than the profile's default, so that some hundred programs really run
    max_examples=max(400, settings.default.max_examples), suppress_health_check=[HealthCheck.too_slow]
)
def test_random_expressions_agree_with_the_reference_or_are_refused(program):
    target, names, values, expression = program
    declarations = " ".join(f"{n} : {ty} := {literal(values[n], ty)};" for n, ty in names.items()) + f" y : {target};"
    text = render(expression)
    try:
        expected = reference(expression, target, values)
    except Refused as reason:
        event(f"refused: {reason}")
        sim, diagnostics = run(declarations, f"y := {text};")
        assert sim is None, f"y : {target} := {text} was accepted"
        assert any(d.severity == "error" for d in diagnostics)
        return
    except Fault:
        expected = Fault
    event(f"runs: {'fault' if expected is Fault else target}")
    project, _ = source_to_project(f"PROGRAM Main\nVAR {declarations} END_VAR\ny := {text};\nEND_PROGRAM\n", "t")
    build = build_project(project)
    assert build.compiled is not None, (text, [d.format() for d in build.diagnostics if d.severity == "error"])
    sim = build.simulation()
    sim.cycle(1)
    if expected is Fault:
        assert sim.fault is not None and sim.fault.code == "division_by_zero"
        return
    assert sim.fault is None, sim.fault.text()
    actual = sim.read("Main.y")
    if isinstance(expected, float) and math.isnan(expected):
        assert isinstance(actual, float) and math.isnan(actual), (text, actual)
    else:
        assert actual == expected and type(actual) is type(expected), (text, target, values, actual, expected)
