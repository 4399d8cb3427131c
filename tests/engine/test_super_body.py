"""``SUPER^()`` (issue 25, item 5; CODESYS "SUPER" help: "SUPER^(); calls the body of the basic function block"): a
derived function block's body runs its base's body on the same instance, where it writes; arguments set the
inherited inputs and ``=>`` reads the outputs, as in any FB call. Expected values are worked out by hand: the base
counts rising edges of ``start`` (IEC R_TRIG / an R_EDGE input), the derived block adds its own work around it.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.st.project_text import source_to_project

from .oo_support import errors, run

COUNTING = """
FUNCTION_BLOCK Base
VAR_INPUT start : BOOL R_EDGE; END_VAR
VAR_OUTPUT count : INT; END_VAR
IF start THEN
    count := count + 1;
END_IF;
END_FUNCTION_BLOCK
FUNCTION_BLOCK Derived EXTENDS Base
VAR_INPUT reset : BOOL R_EDGE; END_VAR
VAR_OUTPUT doubled : INT; before : INT; END_VAR
before := count;
SUPER^();
IF reset THEN
    count := 0;
END_IF;
doubled := count * 2;
END_FUNCTION_BLOCK
"""

STARTS = (False, True, True, False, True, False, True)


def test_the_derived_body_runs_the_base_body_on_its_own_instance_scan_by_scan():
    """Both have an R_EDGE input (each a hidden edge memory): the base's and the derived's stay apart."""
    sim = run(
        COUNTING
        + """PROGRAM Main
VAR d : Derived; b : Base; go : BOOL; clear : BOOL; x : INT; END_VAR
d(start := go, reset := clear, doubled => x);
b(start := go);
END_PROGRAM
"""
    )
    count = plain = 0
    previous = False
    for scan, go in enumerate(STARTS):
        clear = scan == 4
        sim.write("Main.go", go)
        sim.write("Main.clear", clear)
        sim.cycle(1)
        before = count
        edge = go and not previous  # rising edge of start, counted by the base's body
        count += edge
        plain += edge  # the plain base instance: every rising edge, no reset
        if clear:
            count = 0  # after SUPER^(): the derived body's reset wins
        previous = go
        assert (sim.read("Main.d.before"), sim.read("Main.d.count"), sim.read("Main.x")) == (before, count, 2 * count)
        assert sim.read("Main.b.count") == plain
    assert plain == 3


def test_super_call_with_arguments_sets_inherited_inputs_and_reads_outputs():
    """``SUPER^(step := step * 10, total => last)``: the inherited input is set on the instance itself (so it keeps
    10 after the call), the output is copied out after the base's body."""
    sim = run(
        """FUNCTION_BLOCK Adder
VAR_INPUT step : INT; END_VAR
VAR_OUTPUT total : INT; END_VAR
total := total + step;
END_FUNCTION_BLOCK
FUNCTION_BLOCK TenfoldAdder EXTENDS Adder
VAR_OUTPUT last : INT; END_VAR
SUPER^(step := step * 10, total => last);
END_FUNCTION_BLOCK
PROGRAM Main
VAR d : TenfoldAdder; END_VAR
d(step := 1);
END_PROGRAM
"""
    )
    for scan in (1, 2, 3):
        sim.cycle(1)
        assert (sim.read("Main.d.total"), sim.read("Main.d.last"), sim.read("Main.d.step")) == (10 * scan,) * 2 + (10,)


def _ld_base_project():
    """An LD base (a rung counting with CTU) and an ST derived body calling it."""
    from tests.ir.diagram_support import box, contact, ld_pou, rung

    project, _ = source_to_project(
        "FUNCTION_BLOCK Derived EXTENDS Base\nVAR_OUTPUT seen : INT; END_VAR\nSUPER^();\nseen := c.CV;\n"
        "END_FUNCTION_BLOCK\nPROGRAM Main\nVAR d : Derived; b : Base; go : BOOL; END_VAR\n"
        "d(pulse := go);\nb(pulse := go);\nEND_PROGRAM\n",
        "ld",
    )
    counter = box("k1", "CTU", instance="c", en=False, PV="100")
    base = ld_pou(
        "Base",
        "VAR_INPUT pulse : BOOL; END_VAR VAR c : CTU; END_VAR",
        rung("n1", contact("p", "pulse"), counter),
        kind="function_block",
    )
    project.pous.insert(0, base)
    return project


@pytest.mark.parametrize("variant", ["fast", "monitor"])
def test_an_ld_base_body_runs_through_super_and_the_probes_stay_the_instances_own(variant):
    """The LD base's power-flow probes of the plain instance are its own; the derived instance's probes are those
    of its own ST body (the base's run through SUPER^() goes to the base class's spare probes)."""
    sim = Simulation(lower_project(_ld_base_project()).program, variant=variant)
    for scan, go in enumerate((True, False, True, False, True), start=1):
        sim.write("Main.go", go)
        sim.cycle(1)
    assert (sim.read("Main.d.seen"), sim.read("Main.d.c.CV"), sim.read("Main.b.c.CV")) == (3, 3, 3)
    if variant == "monitor":
        base = sim.probes("Main.b")
        assert base.values["p"] is True  # the last scan: pulse TRUE at the contact
        derived = sim.probes("Main.d")
        assert "p" not in derived.values  # (the derived POU's own body is ST: no LD element of the base)


def test_a_breakpoint_in_the_base_body_halts_also_when_run_through_super():
    text = COUNTING + "PROGRAM Main\nVAR d : Derived; b : Base; END_VAR\nd(start := TRUE);\nb();\nEND_PROGRAM\n"
    project, _ = source_to_project(text, "oo")
    sim = Simulation(lower_project(project).program, variant="debug")
    line = text.splitlines().index("    count := count + 1;") + 1
    assert len(sim.set_breakpoint("BASE", line=line)) == 1
    sim.cycle(1)
    halts = []
    while sim.halted is not None:
        halts.append((sim.halted.origin.pou, sim.halted.origin.line))
        sim.resume()
    assert halts == [("BASE", line)]  # d has a rising edge (b is called without one)
    assert sim.read("MAIN.D.DOUBLED") == 2


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        (
            "FUNCTION_BLOCK F\nSUPER^();\nEND_FUNCTION_BLOCK\n",
            ("ST-UNKNOWN-VAR", "F/body", "SUPER^: F does not extend another function block"),
        ),
        (
            "PROGRAM P\nSUPER^();\nEND_PROGRAM\n",
            (
                "ST-NOT-CALLABLE",
                "P/body",
                "SUPER^() runs a function block's body: call it in a function block's body or methods, not here",
            ),
        ),
    ],
)
def test_super_and_this_body_calls_that_are_refused(source, expected):
    assert errors(source) == [expected]
