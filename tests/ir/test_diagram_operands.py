"""The short ways of diagram operands (ir/diagram_operands.py, issue 5) answer exactly as the ST checker and
lowering do: a plain variable name read without the checker (``_named_read``), and a coil or output variable
of a kind already written without a word not checked again (``target``).

The property draws LD and FBD POUs whose contacts, coils and output nodes name variables of every kind -
locals, inputs, outputs, in-outs, CONSTANTs, R_EDGE inputs, globals, externals, located variables, FB
outputs, struct fields, non-BOOL and unknown names - and lowers each project with and without the short ways.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.diagram_operands import Operands
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou
from tests.ir.diagram_support import coil, contact, fbd_pou, inp, ld_pou, net, out, project, rung

GLOBALS = "VAR_GLOBAL g : BOOL; gi : INT; END_VAR VAR_GLOBAL CONSTANT gk : BOOL := TRUE; END_VAR"
DECLARATIONS = """VAR_INPUT i : BOOL; e : BOOL R_EDGE; END_VAR
VAR_OUTPUT o : BOOL; END_VAR
VAR_IN_OUT io : BOOL; END_VAR
VAR x, y, z : BOOL; n : INT; t : TON; a : ARRAY [0..1] OF BOOL; at_x AT %IX0.1 : BOOL; END_VAR
VAR CONSTANT k : BOOL := TRUE; END_VAR
VAR_EXTERNAL g : BOOL; gk : BOOL; END_VAR"""
READ = ["i", "e", "o", "io", "x", "y", "z", "n", "t.Q", "a[1]", "at_x", "k", "g", "gk", "gi", "nosuch", "TRUE", "t"]
WRITTEN = ["x", "y", "z", "o", "i", "e", "io", "k", "g", "gk", "gi", "n", "t.Q", "a[0]", "at_x", "nosuch"]

rungs = st.lists(
    st.tuples(
        st.sampled_from(READ),
        st.sampled_from(["no", "nc", "p", "n"]),
        st.sampled_from(WRITTEN),
        st.sampled_from(["normal", "negated", "set", "reset", "p", "n"]),
    ),
    min_size=1,
    max_size=8,
)


def ld_program(drawn: list, kind: str) -> Pou:
    return ld_pou(
        "Main",
        DECLARATIONS,
        *(
            rung(f"n{n}", contact(f"c{n}", read, mode), coil(f"q{n}", written, coil_mode))
            for n, (read, mode, written, coil_mode) in enumerate(drawn)
        ),
        kind=kind,
    )


def fbd_program(drawn: list, kind: str) -> Pou:
    return fbd_pou(
        "Main",
        DECLARATIONS,
        *(
            net(f"n{n}", [inp(f"v{n}", read), out(f"o{n}", written, coil_mode)], [(f"v{n}.OUT", f"o{n}.IN")])
            for n, (read, _, written, coil_mode) in enumerate(drawn)
        ),
        kind=kind,
    )


def lowered(pou: Pou) -> tuple[str, list[str]]:
    result = lower_project(project(pou, globals=GLOBALS))
    return repr(result.program), [repr(d) for d in result.diagnostics]


@given(rungs, st.sampled_from([ld_program, fbd_program]), st.sampled_from(["program", "function_block"]))
def test_property_short_ways_answer_as_the_checker_does(drawn, language, kind):
    pou = language(drawn, kind)
    with pytest.MonkeyPatch.context() as monkeypatch:
        short = lowered(pou)
        monkeypatch.setattr(Operands, "named_variable", lambda *_args: None)  # every operand the long way
        assert short == lowered(pou)


def test_a_written_kind_is_remembered_only_when_nothing_was_reported():
    """Coils on a CONSTANT and on an input are reported at every one, also after clean coils of BOOL locals."""
    pou = ld_program(
        [
            ("x", "no", "y", "normal"),
            ("x", "no", "z", "normal"),
            ("x", "no", "k", "normal"),
            ("x", "no", "k", "set"),
            ("x", "no", "i", "normal"),
            ("x", "no", "e", "reset"),
        ],
        "function_block",
    )
    assert [d.format() for d in lower_project(project(pou, globals=GLOBALS)).diagnostics] == [
        "POU Main, network 3, coil k: error ST-CONST-WRITE: 'k' is a CONSTANT and cannot be assigned",
        "POU Main, network 4, set coil k: error ST-CONST-WRITE: 'k' is a CONSTANT and cannot be assigned",
        "POU Main, network 5, coil i: error LD-INPUT-WRITE: 'i' is an input of Main: assigning it overwrites "
        "the caller's value",
        "POU Main, network 6, reset coil e: error LD-INPUT-WRITE: 'e' is an input of Main: assigning it overwrites "
        "the caller's value",
    ]
