"""IL online (issue 26 item 3): the accumulator after every line is a probe ``L<line>`` (its value this scan, or
not executed when a jump skipped the line), and a single step stops at the next load, jump or call (ON-04).
Expected values are worked out by hand from the IL semantics (IL-05: ST, jumps and calls keep the CR)."""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from ladderlab.model.project import Pou
from tests.ir.diagram_support import lower_ok

BODY = """LD a
ADD 1
ST a
LD a
GT 2
JMPC done
CAL t(IN := TRUE, PT := T#1s)
LD t.Q
ST q
done:
LD a
MUL 10
ST b"""
DECLS = "VAR a, b : INT; q : BOOL; t : TON; END_VAR"


def il_pou(body: str = BODY) -> Pou:
    return Pou(name="Main", kind="program", language="il", declarations=DECLS, body=body)


def test_accumulator_after_every_line_and_lines_a_jump_skipped():
    sim = Simulation(lower_ok(il_pou()), variant="monitor")
    sim.cycle(1)
    view = sim.probes("Main")
    # a 0 -> 1; 1 > 2 is FALSE: no jump; the CAL and the ST keep the CR (IL-05); t.Q FALSE; 1 * 10
    assert view.values == {
        "L1:INT": 0, "L2:INT": 1, "L3:INT": 1, "L4:INT": 1, "L5:BOOL": False, "L6:BOOL": False,
        "L7:BOOL": False, "L8:BOOL": False, "L9:BOOL": False, "L11:INT": 1, "L12:INT": 10, "L13:INT": 10,
    }  # fmt: skip
    sim.write("Main.a", 5)
    sim.cycle(1)
    view = sim.probes("Main")
    # 5 -> 6 > 2: the jump skips lines 7..9, which keep last scan's values and are not executed
    assert {line: view.values[line] for line in ("L2:INT", "L5:BOOL", "L6:BOOL", "L11:INT", "L12:INT")} == {
        "L2:INT": 6, "L5:BOOL": True, "L6:BOOL": True, "L11:INT": 6, "L12:INT": 60,
    }  # fmt: skip
    assert {"L7:BOOL", "L8:BOOL", "L9:BOOL"}.isdisjoint(view.executed)
    assert {"L6:BOOL", "L11:INT"} <= view.executed


def test_single_step_stops_at_the_next_load_jump_or_call_ON_04():
    sim = Simulation(lower_ok(il_pou()), variant="debug")
    sim.set_breakpoint("Main", line=2)  # a breakpoint halts on any line, an ADD too
    sim.cycle()
    where = []
    halt = sim.halted
    while halt is not None:
        where.append((halt.origin.line, halt.reason))
        halt = sim.step("statement")
    assert where == [(2, "breakpoint"), (4, "step"), (6, "step"), (7, "step"), (8, "step"), (11, "step")]
    assert sim.read("Main.b") == 10
