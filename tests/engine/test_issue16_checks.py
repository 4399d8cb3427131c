"""Correctness items of issue 16 found against third-party IEC programs: each was accepted silently, failed with
an internal error or refused a valid program; now a located diagnostic or the right value, scan by scan.

(Literal typing: tests/engine/test_literal_typing.py; result types: test_function_results.py; configurations:
test_configurations.py; the process image: test_process_image.py; non-UTF-8 files: tests/cli/test_encoding.py.)
"""

from __future__ import annotations

import pytest

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.ir.diagram_support import box, coil, contact, ld_pou, rung


def build(text: str):
    project, diagnostics = source_to_project(text, "t")
    assert project is not None, diagnostics
    return build_project(project)


def errors(text: str) -> list[str]:
    return [d.format() for d in build(text).diagnostics if d.severity == "error"]


def test_a_top_level_var_external_is_a_located_error_not_an_internal_build_error():
    found = errors("VAR_EXTERNAL x : INT; END_VAR\nPROGRAM Main\nVAR y : INT; END_VAR\ny := x;\nEND_PROGRAM\n")
    assert found == [
        "globals:1:1: error ST-DECL: only VAR_GLOBAL blocks belong in the global variables, not VAR_EXTERNAL "
        "(it refers to a global variable from inside a POU)",
        "Main/body:4:6, POU Main: error ST-UNKNOWN-VAR: unknown variable 'x'",
    ]


@pytest.mark.parametrize(
    "declarations, name",
    [
        ("VAR IF : INT; END_VAR", "IF"),
        ("VAR WHILE : BOOL; END_VAR", "WHILE"),
        ("VAR_INPUT end_if : INT; END_VAR", "end_if"),
        ("VAR INT : INT; END_VAR", "INT"),  # elementary type names are reserved (KW-02)
        ("VAR dt : DINT; END_VAR", "dt"),  # the short name of DATE_AND_TIME
        ("VAR a, mod : INT; END_VAR", "mod"),
        ("VAR any_num : INT; END_VAR", "any_num"),
    ],
)
def test_keywords_and_type_names_cannot_be_declared(declarations, name):
    found = errors(f"PROGRAM Main\n{declarations}\nEND_PROGRAM\n")
    assert len(found) == 1 and found[0].startswith("Main/declarations:2:"), found
    assert found[0].endswith(
        f"error ST-NAME: '{name}' is a keyword or type name and cannot be declared as a name (KW-02)"
    )


def test_soft_keywords_and_standard_pin_names_stay_usable():
    assert errors("PROGRAM Main\nVAR in, q, pt, on, task, with : BOOL; END_VAR\nEND_PROGRAM\n") == []


def test_a_pou_named_by_a_keyword_is_refused():
    assert errors("PROGRAM while\nEND_PROGRAM\n")[0] == (
        "while/declarations, POU while: error ST-NAME: 'while' is a keyword and cannot name a POU (KW-02)"
    )


def test_a_type_named_by_a_keyword_is_refused():
    assert errors("TYPE WHILE : INT; END_TYPE\nPROGRAM Main\nEND_PROGRAM\n") == [
        "types:1:6: error ST-NAME: 'WHILE' is a keyword or type name and cannot be declared as a name (KW-02)"
    ]


FB_IN_OUT = """
FUNCTION_BLOCK Fb
VAR_IN_OUT io : INT; END_VAR
io := io + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR f : Fb; a : INT; END_VAR
{}
END_PROGRAM
"""


@pytest.mark.parametrize("statement, column", [("f.io := 2;", 1), ("a := f.io;", 6)])
def test_an_fb_in_out_cannot_be_written_or_read_from_outside(statement, column):
    assert errors(FB_IN_OUT.format(statement)) == [
        f"Main/body:8:{column}, POU Main: error ST-NOT-ACCESSIBLE: 'io' is an in-out of Fb: it stands for the "
        "caller's variable during a call only, so it cannot be read or written from outside (pass the variable "
        "in the call)"
    ]


FB_INPUT = """
FUNCTION_BLOCK Watch
VAR_INPUT t : TON; END_VAR
VAR_OUTPUT q : BOOL; et : TIME; END_VAR
q := t.Q; et := t.ET;
END_FUNCTION_BLOCK
PROGRAM Main
VAR t1 : TON; w : Watch; END_VAR
t1(IN := TRUE, PT := T#30ms);
w(t := t1);
END_PROGRAM
"""


def test_an_fb_instance_passes_to_an_fb_input_of_the_same_type():
    result = build(FB_INPUT)
    assert result.diagnostics == []  # was: "input t of Watch: expected TON, got TON"
    sim = result.simulation()
    trace = []
    for _ in range(4):
        sim.cycle(1)
        trace.append((sim.read("Main.w.q"), sim.read("Main.w.et")))
    assert trace == [(False, 0), (False, 10), (False, 20), (True, 30)]  # a copy of t1 taken at each call


def test_an_fb_instance_input_cannot_be_called_inside():
    text = FB_INPUT.replace("q := t.Q;", "t(IN := FALSE); q := t.Q;")
    assert errors(text) == [
        "Watch/body:5:1, POU Watch: error ST-NOT-CALLABLE: 't' is an input: a function block instance passed as "
        "an input is a copy whose outputs can be read, but it cannot be called (declare it VAR_IN_OUT to call the "
        "caller's instance)"
    ]


def test_an_fb_input_of_another_type_is_refused():
    text = FB_INPUT.replace("t1 : TON;", "t1 : TOF;").replace("t1(IN := TRUE, PT := T#30ms);", "")
    assert errors(text) == ["Main/body:10:8, POU Main: error ST-TYPE-MISMATCH: input t of Watch: expected TON, got TOF"]


RETAINED = """
FUNCTION_BLOCK Cnt
VAR_INPUT go : BOOL; END_VAR
VAR_OUTPUT n : INT; END_VAR
VAR t : TON; END_VAR
IF go THEN n := n + 1; END_IF;
t(IN := go, PT := T#1s);
END_FUNCTION_BLOCK
VAR_GLOBAL RETAIN gc : Cnt; END_VAR
FUNCTION_BLOCK Outer
VAR RETAIN inner : Cnt; END_VAR
VAR plain : Cnt; END_VAR
inner(go := TRUE); plain(go := TRUE);
END_FUNCTION_BLOCK
PROGRAM Main
VAR RETAIN c : Cnt; arr : ARRAY [1..2] OF Cnt; t2 : TON; END_VAR
VAR lost : Cnt; o : Outer; END_VAR
c(go := TRUE); arr[2](go := TRUE); t2(IN := TRUE, PT := T#1s); lost(go := TRUE); gc(go := TRUE); o();
END_PROGRAM
"""
PATHS = ["Main.c.n", "Main.c.t.ET", "Main.arr[2].n", "Main.t2.ET", "gc.n", "Main.o.inner.n", "Main.lost.n"]


def test_retain_fb_instances_keep_their_whole_state_on_a_warm_restart():
    sim = build(RETAINED).simulation()
    sim.cycle(4)
    assert [sim.read(p) for p in PATHS] == [4, 30, 4, 30, 4, 4, 4]
    sim.reset()  # warm (VAR-82)
    assert [sim.read(p) for p in PATHS] == [4, 30, 4, 30, 4, 4, 0]
    assert sim.read("Main.o.plain.n") == 0
    sim.reset(cold=True)
    assert [sim.read(p) for p in PATHS] == [0, 0, 0, 0, 0, 0, 0]


def test_a_retain_fb_instance_in_an_ld_program_keeps_its_state():
    ld = ld_pou(
        "Main",
        "VAR RETAIN t : TON; END_VAR VAR go : BOOL := TRUE; q : BOOL; END_VAR",
        rung("N1", contact("C1", "go"), box("B1", "TON", instance="t", PT="T#1s"), coil("Q", "q")),
    )
    from tests.ir.diagram_support import project

    sim = build_project(project(ld)).simulation()
    sim.cycle(3)
    assert sim.read("Main.t.ET") == 20
    sim.reset()
    assert sim.read("Main.t.ET") == 20
