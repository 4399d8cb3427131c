"""Fuzzing the build-and-run path (issue 18 item 7): random ST programs, deep ones included, never raise and
run the same in every variant.

Programs mix assignments over INT/DINT/BOOL/REAL variables and an array, IF/ELSIF, CASE, FOR (bounded),
WHILE with a counter, EXIT, RETURN, standard functions, and now and then expressions and statements nested
past the code generator's thresholds (parts computed on lines of their own, bodies outlined). Invariants:
``build_project`` never raises; a program that builds runs 3 scans in the fast, monitor and debug variants
without an exception escaping, and the three agree on every variable and on the fault, if any (an
independent reference: the variants share nothing but the IR).
"""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model import Pou, Project
from ladderlab.simulation.build import build_project
from tests.support import fuzz_settings

INTS = ["i", "j", "k"]
BOOLS = ["b", "c"]
DECLARATIONS = "VAR i, j, k : INT; d : DINT; b, c : BOOL; r : REAL; a : ARRAY[0..7] OF INT; n : INT; END_VAR"

int_leaf = st.sampled_from([*INTS, "d", "a[i MOD 8]", "a[2]"]) | st.integers(-40_000, 40_000).map(str)
bool_leaf = st.sampled_from([*BOOLS, "TRUE", "FALSE"])


def int_expr(depth: int):
    if depth <= 0:
        return int_leaf
    inner = int_expr(depth - 1)
    return st.one_of(
        int_leaf,
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "MOD"]), inner).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
        inner.map(lambda e: f"ABS({e})"),
        st.tuples(inner, inner).map(lambda t: f"MAX({t[0]}, {t[1]})"),
        inner.map(lambda e: f"-({e})"),
    )


def bool_expr(depth: int):
    if depth <= 0:
        return bool_leaf
    inner, ints = bool_expr(depth - 1), int_expr(depth - 1)
    return st.one_of(
        bool_leaf,
        st.tuples(inner, st.sampled_from(["AND", "OR", "XOR"]), inner).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
        inner.map(lambda e: f"NOT ({e})"),
        st.tuples(ints, st.sampled_from(["<", ">", "=", "<>"]), ints).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
    )


deep_int = st.tuples(st.integers(30, 120), int_leaf).map(lambda t: " + ".join([t[1]] * t[0]))
deep_bool = st.integers(30, 120).map(lambda n: "NOT (" * n + "b" + ")" * n)


def statements(depth: int):
    simple = st.one_of(
        st.tuples(st.sampled_from(INTS), int_expr(2) | deep_int).map(lambda t: f"{t[0]} := {t[1]};"),
        st.tuples(st.sampled_from(BOOLS), bool_expr(2) | deep_bool).map(lambda t: f"{t[0]} := {t[1]};"),
        int_expr(2).map(lambda e: f"d := d + {e};"),
        int_expr(1).map(lambda e: f"a[({e}) MOD 8 + 0 * i] := {e};"),
        st.just("r := r * 1.5 + INT_TO_REAL(i);"),
        st.just("RETURN;"),
    )
    if depth <= 0:
        return simple.map(lambda s: [s])
    body = st.lists(statements(depth - 1), min_size=1, max_size=3).map(lambda parts: [s for p in parts for s in p])
    return st.one_of(
        simple.map(lambda s: [s]),
        st.tuples(bool_expr(2) | deep_bool, body, body).map(
            lambda t: [f"IF {t[0]} THEN", *t[1], f"ELSIF {t[0]} = FALSE THEN", *t[2], "END_IF;"]
        ),
        st.tuples(int_expr(1), body, body).map(
            lambda t: [f"CASE {t[0]} OF", "0, 1:", *t[1], "2..5:", *t[2], "ELSE n := n + 1;", "END_CASE;"]
        ),
        st.tuples(st.integers(0, 4), body).map(
            lambda t: [f"FOR k := 0 TO {t[0]} DO", *t[1], "IF k = 3 THEN EXIT; END_IF;", "END_FOR;"]
        ),
        st.tuples(st.integers(1, 25), body).map(  # nested past CPython's 20 loops per function
            lambda t: ["FOR n := 1 TO 1 DO"] * t[0] + t[1] + ["END_FOR;"] * t[0]
        ),
        body.map(lambda b: ["j := 0;", "WHILE j < 3 DO", *b, "j := j + 1;", "END_WHILE;"]),
    )


def run_all(body: str) -> list[tuple]:
    project = Project(
        name="p", pous=[Pou(name="Main", kind="program", language="st", declarations=DECLARATIONS, body=body)]
    )
    outcomes = []
    for variant in ("fast", "monitor", "debug"):
        build = build_project(project, variant)
        if build.compiled is None:
            assert any(d.severity == "error" for d in build.diagnostics)
            outcomes.append(("refused", sorted(d.code for d in build.diagnostics if d.severity == "error")))
            continue
        sim = build.simulation()
        sim.cycle(3)
        fault = sim.fault.diagnostic() if sim.fault is not None else None
        outcomes.append(("ran", sim.snapshot(), (fault.code, fault.line, fault.message) if fault else None))
    return outcomes


@fuzz_settings(fast=25)
@given(parts=st.lists(statements(3), min_size=1, max_size=4))
def test_random_programs_build_and_run_alike_in_every_variant(parts: list[list[str]]) -> None:
    body = "\n".join(line for part in parts for line in part)
    fast, monitor, debug = run_all(body)
    assert fast == monitor == debug, body
