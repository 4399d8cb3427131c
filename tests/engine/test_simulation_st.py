"""From ST text to scans: the project is checked and lowered (ir.lower_project via build_project) and run here.

These complement the IR-built tests with origins as the lowering produces them
(file lines and columns), R_EDGE inputs, EN/ENO in ST and a CONFIGURATION.
"""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project


def simulation(text: str, **options) -> Simulation:
    variant = options.pop("variant", "fast")
    project, diagnostics = source_to_project(text, "test")
    assert project is not None, diagnostics
    build = build_project(project, variant)
    assert build.compiled is not None, [d.message for d in build.diagnostics]
    return build.simulation(**options)


TWO_TASKS = """
VAR_GLOBAL RETAIN kept : INT := 5; END_VAR
VAR_GLOBAL lost : INT := 5; END_VAR
PROGRAM Fast
VAR n : INT; END_VAR
n := n + 1; kept := kept + 1; lost := lost + 1;
END_PROGRAM
PROGRAM Slow
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
CONFIGURATION Plc
  RESOURCE Cpu ON PLC
    TASK FastTask (INTERVAL := T#10ms, PRIORITY := 2);
    TASK SlowTask (INTERVAL := T#25ms, PRIORITY := 1);
    PROGRAM f WITH FastTask : Fast;
    PROGRAM s WITH SlowTask : Slow;
  END_RESOURCE
END_CONFIGURATION
"""


def test_configuration_tasks_and_warm_cold_restart_from_st():
    sim = simulation(TWO_TASKS)
    sim.cycle(6)  # 10 20 25 30 40 50
    assert (sim.time_ms, sim.read("f.n"), sim.read("S.N"), sim.read("kept")) == (50, 5, 2, 10)  # instance names
    sim.reset()
    assert (sim.read("KEPT"), sim.read("LOST"), sim.read("F.N")) == (10, 5, 0)
    sim.reset(cold=True)
    assert sim.read("KEPT") == 5


def test_r_edge_input_counts_rising_edges_per_call():
    sim = simulation("""
FUNCTION_BLOCK Edges
VAR_INPUT clk : BOOL R_EDGE; END_VAR
VAR_OUTPUT count : INT; END_VAR
IF clk THEN count := count + 1; END_IF;
END_FUNCTION_BLOCK
PROGRAM Main
VAR e : Edges; in : BOOL; END_VAR
e(clk := in);
END_PROGRAM
""")
    counts = []
    for value in (True, True, False, True, False, False, True):
        sim.write("MAIN.IN", value)
        sim.cycle()
        counts.append(sim.read("MAIN.E.COUNT"))
    assert counts == [1, 1, 1, 2, 2, 2, 3]


def test_in_out_en_eno_and_struct_fields_from_st():
    sim = simulation("""
TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE
FUNCTION Swap : BOOL
VAR_IN_OUT x : INT; y : INT; END_VAR
VAR t : INT; END_VAR
t := x; x := y; y := t; Swap := TRUE;
END_FUNCTION
PROGRAM Main
VAR p : Pair := (a := 1, b := 2); arr : ARRAY[1..2] OF INT := [10, 20]; en : BOOL; ok : BOOL; r : INT := -1; END_VAR
Swap(p.a, p.b);
Swap(arr[1], arr[2]);
r := ADD(EN := en, IN1 := r, IN2 := 1, ENO => ok);
END_PROGRAM
""")
    sim.cycle()
    assert (sim.read("MAIN.P"), sim.read("MAIN.ARR"), sim.read("MAIN.R"), sim.read("MAIN.OK")) == (
        {"A": 2, "B": 1},
        [20, 10],
        -1,
        False,
    )
    sim.write("MAIN.EN", True)
    sim.cycle()
    assert (sim.read("MAIN.P.A"), sim.read("MAIN.R"), sim.read("MAIN.OK")) == (1, 0, True)


def test_force_beats_the_program_write_does_not():
    sim = simulation("""
PROGRAM Main
VAR lamp : BOOL; n : INT; END_VAR
lamp := FALSE; n := n + 1;
END_PROGRAM
""")
    sim.write("MAIN.LAMP", True)
    sim.cycle()
    assert sim.read("MAIN.LAMP") is False
    sim.force("MAIN.LAMP", "TRUE")
    sim.cycle(2)
    assert sim.read("MAIN.LAMP") is True and sim.read("MAIN.N") == 3


def test_faults_and_watchdog_point_at_st_lines_and_columns():
    sim = simulation("""
PROGRAM Main
VAR a : INT := 1; b : INT; q : INT; END_VAR
a := a + 1;
IF a > 2 THEN
    q := a / b;
END_IF;
END_PROGRAM
""")
    sim.cycle(2)
    fault = sim.fault
    assert (fault.code, fault.origin.line, fault.origin.column, fault.values) == (
        "division_by_zero",
        6,
        5,
        {"Q": 0, "A": 3, "B": 0},
    )
    looping = simulation(
        """
PROGRAM Main
VAR x : INT; END_VAR
x := 1;
WHILE TRUE DO END_WHILE;
END_PROGRAM
""",
        watchdog_s=0.1,
    )
    looping.cycle()
    assert (looping.fault.kind, looping.fault.pou, looping.fault.origin.line) == ("watchdog", "MAIN", 5)
    assert looping.read("MAIN.X") == 1


def test_breakpoints_on_st_lines_from_source():
    sim = simulation(
        """
PROGRAM Main
VAR i : INT; total : INT; END_VAR
total := 0;
FOR i := 1 TO 3 DO
    total := total + i;
END_FOR;
END_PROGRAM
""",
        variant="debug",
    )
    sim.set_breakpoint("Main", line=6)
    sim.cycle()
    seen = []
    while sim.halted is not None:
        seen.append((sim.read("MAIN.I"), sim.read("MAIN.TOTAL")))
        sim.resume()
    assert seen == [(1, 0), (2, 1), (3, 3)] and sim.read("MAIN.TOTAL") == 6 and sim.read("MAIN.I") == 4


GLOBAL_INSTANCE = """
FUNCTION_BLOCK Doubler
VAR_INPUT in1 : INT; END_VAR
VAR_OUTPUT q : INT; END_VAR
VAR n : INT := 1; END_VAR
q := in1 * 2 + n;
END_FUNCTION_BLOCK
VAR_GLOBAL g : Doubler := (in1 := 11); END_VAR
PROGRAM Main
VAR_EXTERNAL g : Doubler; END_VAR
VAR x : INT; END_VAR
x := g.q;
g(in1 := g.in1 + 1);
END_PROGRAM
"""


def test_a_global_fb_instance_takes_its_declarations_initial_values():
    """A global instance's structured initialiser names the FB's inputs (IEC 61131-3 ed.3 6.5.2.2, initial values of
    FB instances; TYP-33): the globals were checked before the FB's variables were declared, so it was refused as
    "Doubler has no field 'in1'"."""
    sim = simulation(GLOBAL_INSTANCE)
    seen = []
    for _ in range(3):
        sim.cycle(1)
        seen.append((sim.read("MAIN.x"), sim.read("g.in1"), sim.read("g.q")))
    # scan 1: x reads q before the first call (0), the call takes in1 12: q = 25; scan 2: x 25, in1 13, q 27 ...
    assert seen == [(0, 12, 25), (25, 13, 27), (27, 14, 29)]


def test_an_unknown_name_in_a_global_instances_initialiser_is_located():
    project, _ = source_to_project(GLOBAL_INSTANCE.replace("(in1 := 11)", "(inl := 11)"), "test")
    build = build_project(project, "fast")
    assert [(d.code, d.message, d.file, d.line) for d in build.diagnostics if d.severity == "error"] == [
        ("ST-UNKNOWN-MEMBER", "Doubler has no field 'inl'", "globals", 1)
    ]
