"""``THIS^()`` and ``SUPER^()`` in a METHOD (issue 25 item 5; CODESYS "SUPER": "You can use SUPER only in methods and in
the associated function block implementations", ``SUPER^();`` "Call of FB-body of base class"; "THIS": the
function block's own instance). ``THIS^(...)`` in a method runs the instance's body - its own class's, so a derived
instance runs the derived body - with the arguments set as in any FB call; ``SUPER^(...)`` in a method runs the
base's body on the instance. A body that could run itself again through them is refused at compile time as
ST-RECURSION (POU-02: LadderLab refuses every recursion statically, as for methods), located at the call. Expected
values are worked out by hand from the program text, scan by scan."""

from __future__ import annotations

import pytest

from .oo_support import build, run

COUNTER = """
FUNCTION_BLOCK Counter
VAR_INPUT step : INT; END_VAR
VAR_OUTPUT n : INT; END_VAR
METHOD Twice
THIS^();
THIS^(step := 10);
END_METHOD
n := n + step;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Loud EXTENDS Counter
VAR_OUTPUT m : INT; last : INT; END_VAR
METHOD Base_only
SUPER^(step := 100, n => last);
END_METHOD
m := m + 1;
SUPER^();
END_FUNCTION_BLOCK
"""


def test_this_body_call_in_a_method_runs_the_instances_own_class_body_scan_by_scan():
    sim = run(COUNTER + "PROGRAM Main\nVAR c : Counter; l : Loud; END_VAR\nc.Twice();\nl.Twice();\nEND_PROGRAM\n")
    c_n = l_n = l_m = 0
    step = 0
    for scan in range(1, 5):
        sim.cycle(1)
        # c: THIS^() adds the step left by the previous call, THIS^(step := 10) sets it to 10 and adds it
        c_n += step + 10
        # l: the same two body runs, each through Loud's body (m + 1, then the base body through SUPER^())
        l_n += step + 10
        l_m += 2
        step = 10
        assert (sim.read("Main.c.n"), sim.read("Main.c.step")) == (c_n, 10), scan
        assert (sim.read("Main.l.n"), sim.read("Main.l.m")) == (l_n, l_m), scan


def test_super_body_call_in_a_method_runs_the_base_body_on_the_instance():
    sim = run(COUNTER + "PROGRAM Main\nVAR l : Loud; END_VAR\nl.Base_only();\nl();\nEND_PROGRAM\n")
    n = 0
    for scan in range(1, 4):
        sim.cycle(1)
        n += 100  # Base_only: step := 100, the base body adds it (Loud's m is not counted)
        last = n
        n += 100  # l(): Loud's body (m + 1), then the base body again with step still 100
        assert (sim.read("Main.l.n"), sim.read("Main.l.last"), sim.read("Main.l.m")) == (n, last, scan), scan


@pytest.mark.parametrize("variant", ["monitor", "debug"])
def test_this_body_calls_run_alike_in_the_monitor_and_debug_variants(variant):
    from ladderlab.engine.simulation import Simulation
    from ladderlab.ir.lower_project import lower_project
    from ladderlab.st.project_text import source_to_project

    project, _ = source_to_project(COUNTER + "PROGRAM Main\nVAR l : Loud; END_VAR\nl.Twice();\nEND_PROGRAM\n", "oo")
    sim = Simulation(lower_project(project).program, variant=variant)
    sim.cycle(2)
    assert (sim.read("Main.l.n"), sim.read("Main.l.m")) == (10 + 20, 4)


RECURSIVE_BODY = """
FUNCTION_BLOCK F
VAR_OUTPUT n : INT; END_VAR
METHOD Again
THIS^();
END_METHOD
n := n + 1;
IF n < 3 THEN
    Again();
END_IF;
END_FUNCTION_BLOCK
"""

DERIVED_BODY = """
FUNCTION_BLOCK B
METHOD M
THIS^();
END_METHOD
END_FUNCTION_BLOCK
FUNCTION_BLOCK D EXTENDS B
THIS^.M();
END_FUNCTION_BLOCK
"""

OVERRIDE_SUPER = """
FUNCTION_BLOCK B
METHOD M
END_METHOD
THIS^.M();
END_FUNCTION_BLOCK
FUNCTION_BLOCK D EXTENDS B
METHOD M
SUPER^();
END_METHOD
END_FUNCTION_BLOCK
"""


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        (
            RECURSIVE_BODY,
            (
                "ST-RECURSION",
                "F.Again/body",
                5,
                "recursive call F.Again -> F (body) -> F.Again: methods must not call themselves (POU-02)",
            ),
        ),
        (  # B's M runs D's body for a D instance (dispatched), which calls M
            DERIVED_BODY,
            (
                "ST-RECURSION",
                "B.M/body",
                4,
                "recursive call B.M -> D (body) -> B.M: methods must not call themselves (POU-02)",
            ),
        ),
        (  # B's body calls M, dispatched to D.M, whose SUPER^() runs B's body
            OVERRIDE_SUPER,
            (
                "ST-RECURSION",
                "D.M/body",
                9,
                "recursive call D.M -> B (body) -> D.M: methods must not call themselves (POU-02)",
            ),
        ),
        (
            "FUNCTION_BLOCK F\nVAR_OUTPUT n : INT; END_VAR\nn := n + 1;\nTHIS^();\nEND_FUNCTION_BLOCK\n",
            (
                "ST-RECURSION",
                "F/body",
                4,
                "THIS^() in F's own body would run the body again from inside itself (POU-02)",
            ),
        ),
        (
            "FUNCTION_BLOCK F\nVAR x : BOOL; END_VAR\nMETHOD M\nx := THIS^();\nEND_METHOD\nEND_FUNCTION_BLOCK\n",
            ("ST-NOT-CALLABLE", "F.M/body", 4, "THIS^() runs a body: call it as a statement"),
        ),
        (
            "PROGRAM P\nTHIS^();\nEND_PROGRAM\n",
            (
                "ST-NOT-CALLABLE",
                "P/body",
                2,
                "THIS^() runs a function block's body: call it in a function block's body or methods, not here",
            ),
        ),
    ],
)
def test_body_calls_that_could_recurse_or_have_no_body_are_located_errors(source, expected):
    assert located(source) == [expected]


def located(text: str) -> list[tuple[str, str | None, int | None, str]]:
    return [(d.code, d.file, d.line, d.message) for d in build(text).diagnostics if d.severity == "error"]
