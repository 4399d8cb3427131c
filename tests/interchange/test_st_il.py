"""IL POUs exported as ST (issue 26 item 4, IL-26): readable (accumulator values written into their use, forward
jumps as IF / ELSE) and equivalent: the exported project gives the same variable trace as the IL one over
200 scans of random writes (``st_support.same_traces``)."""

from __future__ import annotations

import pytest

from ladderlab.interchange.st.export import export_pou_st
from ladderlab.st.project_text import source_to_project
from tests.interchange.st_support import same_traces
from tests.ir import test_il_examples as examples


def project_of(text: str):
    project, diagnostics = source_to_project(text, "il")
    assert project is not None and [d for d in diagnostics if d.severity == "error"] == []
    return project


def body_of(text: str, pou: str = "P") -> str:
    result = export_pou_st(project_of(text), pou)
    assert [d.format() for d in result.diagnostics] == []
    return result.text.split("END_VAR\n")[-1].rsplit("\nEND_", 1)[0]


def test_straight_il_becomes_one_expression_per_store():
    text = "PROGRAM P\nVAR a, b, c, x : BOOL; i, j : INT; END_VAR\nLD a\nAND( b\nOR c\n)\nST x\nLD i\nADD 2\nMUL j\nST j\nEND_PROGRAM"
    assert body_of(text) == "x := a AND (b OR c);\nj := (i + 2) * j;"


def test_forward_jumps_become_if_and_else():
    """The corrected UserFun of EX-32: JMPC / JMP pairs are IF ... ELSE, the accumulator kept where paths meet."""
    assert body_of("PROGRAM P\nVAR r : INT; END_VAR\nLD 1\nST r\nEND_PROGRAM" + examples.USER_FUN, "UserFun") == (
        "IF val >= minVal THEN\n"
        "    IF val > maxVal THEN\n"
        "        CR_INT := maxVal;\n"
        "    ELSE\n"
        "        CR_INT := val;\n"
        "    END_IF;\n"
        "ELSE\n"
        "    CR_INT := minVal;\n"
        "END_IF;\n"
        "UserFun := CR_INT;"
    )


def test_a_backward_jump_is_refused_with_its_line():
    text = "PROGRAM P\nVAR i : INT; END_VAR\nLD 0\nST i\nl: LD i\nADD 1\nST i\nLT 10\nJMPC l\nEND_PROGRAM"
    result = export_pou_st(project_of(text), "P")
    assert result.text == ""
    assert [d.format() for d in result.diagnostics] == [
        "P/body:9:1, POU P: error EXPORT-IL-JUMP: the jump to l goes backwards or out of an enclosing jump: "
        "ST has no jumps, so this IL POU cannot be exported as ST"
    ]


IL_PROGRAMS = {
    "IL-02": (
        "PROGRAM P\nVAR lvar : LINT; idword : DWORD; istruct : S; test : BOOL; start : LINT; END_VAR\n"
        + examples.IL_02.format(load="start")
        + "END_PROGRAM\n"
        + examples.IL_02_TYPES
    ),
    "IL-07": f"PROGRAM P\nVAR BOOL1, BOOL2, ERG : BOOL; END_VAR\n{examples.IL_07}\nEND_PROGRAM\n",
    "IL-21": "PROGRAM P\nVAR x, a, b, r1, r2, r3 : BOOL; END_VAR\n"
    "LD x\nANDN( a\nOR b\n)\nST r1\nLD x\nORN( a\nAND b\n)\nST r2\nLD x\nXORN(\nLD a\n)\nST r3\nS a\nR b\nEND_PROGRAM",
    "EX-32/33": f"PROGRAM P\nVAR count : INT; r1, r2, r3 : INT; END_VAR\n{examples.EX_33}\nEND_PROGRAM\n"
    + examples.USER_FUN,
    "EX-34": "PROGRAM P\nVAR in1, out1 : BOOL; timer : TON; timerValue : TIME; go : BOOL; n : INT; END_VAR\n"
    + examples.EX_34_STYLES["combined"]
    + "\nLD go\nCALC c(CU := TRUE)\nLD c.CV\nST n\nEND_PROGRAM\nPROGRAM Q\nVAR c : CTU; END_VAR\nEND_PROGRAM",
    "IL-08": "PROGRAM P\nVAR INSTANZ : FUB; ERG, F, a, b : INT; QUAD : BOOL; END_VAR\n"
    "LD a\nST INSTANZ.PAR1\nLD b\nST INSTANZ.PAR2\nCAL INSTANZ\nLD INSTANZ.MULERG\nST ERG\nLD INSTANZ.VERGL\n"
    "ST QUAD\nLD a\nFct b, 3\nST F\nLD QUAD\nRETC\nLD 5\nST a\nEND_PROGRAM\n"
    + examples.FUB.split("PROGRAM PRGexample2")[0],
    "IL-08 program calls": "PROGRAM P\nVAR a, erg, erg2 : INT; END_VAR\n"
    "LD a\nST PRGexample2.in_var\nCAL PRGexample2\nLD PRGexample2.out_var\nST erg\n"
    "CAL PRGexample2(in_var := erg, out_var => erg2)\nEND_PROGRAM\n"
    + "PROGRAM PRGexample2"
    + examples.FUB.split("PROGRAM PRGexample2")[1],
}


@pytest.mark.parametrize("name", IL_PROGRAMS)
def test_exported_st_runs_like_the_il(name):
    """Issue 8's equivalence contract for IL POUs: same trace over 200 scans of random writes."""
    text = IL_PROGRAMS[name].replace("PROGRAM Q\nVAR c : CTU; END_VAR\nEND_PROGRAM", "")
    if name == "EX-34":
        text = text.replace("go : BOOL; n : INT;", "go : BOOL; n : INT; c : CTU;")
    trace = same_traces(project_of(text))
    assert len(trace) == 200
