"""CODESYS's ``{attribute 'monitoring'}`` on a PROPERTY (issue 25): 'variable' shows the value of the property's last
GET or SET (an implicit variable), 'call' runs its GET to show it; without the attribute a property has no path.

Expected behaviour from CODESYS's online help, "Attribute: monitoring": "An implicit variable is created for the
property, which is always assigned the current property value when the application calls the Set or Get method.
The last value stored in this variable is shown"; 'call': "the monitoring service of the runtime executes the Get
... method" (side effects possible); "only read access is possible for the value 'variable'"; 'call' serves only a
property of a simple data type or a pointer, on a structure it is ignored with warning C0344 ("The monitoring
attribute is not supported for property ... and will be ignored"). The values are worked out by hand from the
program texts."""

from __future__ import annotations

import pytest

from ladderlab.engine.inputs import InputRefused
from ladderlab.engine.paths import AccessorFault, NoTarget, UnknownPath
from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.simulation.build import build_project
from ladderlab.simulation.conditions import BadCondition, parse_condition
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.st_text import compose_pou_text

from .oo_support import run

TANK = """
FUNCTION_BLOCK Tank
VAR amount : INT; reads : INT; END_VAR
{attribute 'monitoring' := 'variable'}
PROPERTY Level : INT
GET
reads := reads + 1;
IF amount > 5 THEN
    Level := amount * 10;
    RETURN;
END_IF;
Level := amount;
END_GET
SET
amount := Level;
END_SET
END_PROPERTY
{attribute 'monitoring' := 'call'}
PROPERTY Share : INT
GET
reads := reads + 1;
Share := 100 / amount;
END_GET
END_PROPERTY
PROPERTY Hidden : INT
GET
Hidden := amount;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
FUNCTION_BLOCK Big EXTENDS Tank
{attribute 'monitoring' := 'call'}
PROPERTY Share : INT
GET
Share := amount + 1000;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : Tank; b : Big; x : INT; n : INT; END_VAR
n := n + 1;
IF n = 2 THEN t.Level := 4; b.Level := 2; END_IF;
IF n = 3 THEN x := t.Level; END_IF;
IF n = 4 THEN t.Level := 7; END_IF;
IF n = 5 THEN x := t.Level; END_IF;
END_PROGRAM
"""


def line(text: str) -> int:
    """The line of TANK that is exactly ``text`` (the lines faults and breakpoints name)."""
    return TANK.splitlines().index(text) + 1


def scans(sim, paths: list[str], count: int) -> list[list[object]]:
    """The values at ``paths`` after each of ``count`` scans."""
    found = []
    for _ in range(count):
        sim.cycle(1)
        found.append([sim.read(path) for path in paths])
    return found


def test_variable_shows_the_value_of_the_last_get_or_set_scan_by_scan():
    """Scan 2 writes 4 (SET), scan 3 reads 4 (GET), scan 4 writes 7, scan 5's GET returns 70 through its RETURN."""
    sim = run(TANK)
    assert scans(sim, ["Main.t.Level", "Main.t.reads", "Main.x"], 5) == [
        [0, 0, 0],
        [4, 0, 0],
        [4, 1, 4],
        [7, 1, 4],
        [70, 2, 70],
    ]


def test_variable_is_read_only():
    sim = run(TANK)
    with pytest.raises(ValueError) as refused:
        sim.write("Main.t.Level", 3)
    assert str(refused.value) == (
        "MAIN.T.LEVEL cannot be written: a property monitored as 'variable' shows the value of its last GET or SET, "
        "and is read only (CODESYS); assign the property in the program or write the variables its SET writes"
    )


def test_call_runs_the_get_at_each_read_between_scans():
    """Each read runs the GET (its side effect counts: reads); 100 / 4 = 25, 100 / 7 = 14 (INT division)."""
    sim = run(TANK)
    sim.cycle(2)
    assert [sim.read("Main.t.Share"), sim.read("Main.t.reads")] == [25, 1]
    assert [sim.read("Main.t.Share"), sim.read("Main.t.reads")] == [25, 2]
    sim.cycle(2)
    assert [sim.read("Main.t.Share"), sim.read("Main.t.reads")] == [14, 4]  # the program's GET at scan 3: one more


def test_a_fault_in_the_get_is_a_located_error_for_that_value_and_the_program_runs_on():
    sim = run(TANK)
    sim.cycle(1)
    with pytest.raises(AccessorFault) as fault:
        sim.read("Main.t.Share")
    message = str(fault.value)
    assert message.startswith(
        "MAIN.T.SHARE: its GET faulted: division by zero: 100 / 0 at POU TANK.SHARE.GET, "
        f"line {line('Share := 100 / amount;')} column 1"
    )
    assert sim.faults == []  # the tasks were not stopped
    sim.cycle(1)
    assert (sim.read("Main.n"), sim.read("Main.t.Share")) == (2, 25)


def test_a_derived_block_inherits_the_variable_and_its_override_of_call_runs():
    """b.Level := 2 at scan 2 (the base's SET, inherited); b.Share is Big's GET: amount + 1000."""
    sim = run(TANK)
    sim.cycle(2)
    assert (sim.read("Main.b.Level"), sim.read("Main.b.Share")) == (2, 1002)


def test_without_the_attribute_a_property_still_has_no_path():
    sim = run(TANK)
    with pytest.raises(UnknownPath) as refused:
        sim.read("Main.t.Hidden")
    assert str(refused.value).startswith("MAIN.T.Hidden is a PROPERTY of TANK: its value is what its GET returns")


def test_call_never_runs_in_a_halted_scan():
    project, diagnostics = source_to_project(TANK, "monitoring")
    assert project is not None and diagnostics == []
    sim = Simulation(lower_project(project).program, variant="debug")
    sim.cycle(2)
    assert sim.read("Main.t.Share") == 25  # the debug variant's GET, run through between scans
    sim.set_breakpoint("Main", line=line("IF n = 4 THEN t.Level := 7; END_IF;"))
    sim.cycle(1)  # halts in scan 3, before its IF n = 4 (the line runs every scan)
    assert sim.halted is not None
    with pytest.raises(NoTarget) as refused:
        sim.read("Main.t.Share")
    assert str(refused.value) == (
        "MAIN.T.SHARE: the scan is halted in the middle, and a property's GET runs only between scans"
    )
    assert sim.read("Main.t.Level") == 4  # 'variable' reads its implicit variable, halted too


PROGRAM_PROPERTY = """
PROGRAM Counter
VAR c : INT; END_VAR
{attribute 'monitoring' := 'variable'}
PROPERTY Count : INT
GET
Count := c * 2;
END_GET
SET
c := Count;
END_SET
END_PROPERTY
END_PROGRAM
PROGRAM Main
VAR n : INT; y : INT; END_VAR
n := n + 1;
Counter.Count := n;
y := Counter.Count;
END_PROGRAM
"""


def test_a_programs_property_is_shown_too():
    """Scan k: the SET stores k, then the GET returns 2k: the last value is the GET's."""
    sim = run(PROGRAM_PROPERTY)
    assert scans(sim, ["Counter.Count", "Main.y"], 3) == [[2, 2], [4, 4], [6, 6]]


def diagnostics(text: str) -> list[tuple[str, str, str | None, int | None, int | None, str]]:
    project, _ = source_to_project(text, "monitoring")
    assert project is not None
    return [
        (d.severity, d.code, d.file, d.line, d.column, d.message)
        for d in build_project(project).diagnostics
        if d.code == "ST-PRAGMA"
    ]


def test_an_unknown_mode_is_a_located_error():
    text = TANK.replace("'monitoring' := 'variable'", "'monitoring' := 'value'")
    assert diagnostics(text) == [
        (
            "error",
            "ST-PRAGMA",
            "Tank.Level.GET/declarations",
            1,
            1,
            "the attribute 'monitoring' on the property Tank.Level: 'value' is no mode of it: write 'variable' or "
            "'call'",
        )
    ]


def test_call_on_a_structure_is_ignored_with_a_warning_c0344():
    text = """
TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT END_TYPE
FUNCTION_BLOCK Holder
VAR p : Pair; END_VAR
{attribute 'monitoring' := 'call'}
PROPERTY Both : Pair
GET
Both := p;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR h : Holder; END_VAR
END_PROGRAM
"""
    assert diagnostics(text) == [
        (
            "warning",
            "ST-PRAGMA",
            "Holder.Both.GET/declarations",
            1,
            1,
            "the attribute 'monitoring' on the property Holder.Both: Both is of a structured type, and 'call' calls "
            "only a property of a simple type or a pointer (CODESYS C0344): the attribute is ignored",
        )
    ]
    with pytest.raises(UnknownPath) as refused:
        run(text).read("Main.h.Both")
    assert str(refused.value).startswith("MAIN.H.Both is a PROPERTY of HOLDER")


def test_the_st_text_writes_the_attribute_above_property_and_reads_it_back():
    project, _ = source_to_project(TANK, "monitoring")
    tank = project.pous[0]
    text = compose_pou_text(tank)
    assert "{attribute 'monitoring' := 'variable'}\nPROPERTY PUBLIC Level : INT\nGET\nreads" in text
    assert "{attribute 'monitoring' := 'call'}\nPROPERTY PUBLIC Share : INT\nGET\nreads" in text
    again, problems = source_to_project(text, "monitoring")
    assert problems == []
    heads = [(p.name, p.get.declarations, p.set.declarations if p.set else None) for p in again.pous[0].properties]
    assert heads == [
        ("Level", "{attribute 'monitoring' := 'variable'}", ""),
        ("Share", "{attribute 'monitoring' := 'call'}", None),
        ("Hidden", "", None),
    ]
    assert [p.get.body.strip() for p in again.pous[0].properties] == [p.get.body.strip() for p in tank.properties]


def test_a_run_until_condition_reads_variable_and_refuses_call():
    """'variable' is a value the scan left (the condition holds after scan 4: Level 7); 'call' would run its GET
    after every scan."""
    sim = run(TANK)
    until = parse_condition("Main.t.Level >= 7", sim)
    held = []
    for _ in range(5):
        sim.cycle(1)
        held.append(until.holds(sim))
    assert held == [False, False, False, True, True]
    with pytest.raises(BadCondition) as refused:
        parse_condition("Main.t.Share > 3", sim)
    assert str(refused.value) == (
        "'Main.t.Share > 3': MAIN.T.SHARE is a property monitored as 'call', read by running its GET: a condition is "
        "checked after every scan, and would run it each time; use 'variable' or the variables its GET reads"
    )


def test_the_attribute_anywhere_but_a_property_is_a_located_warning():
    """CODESYS also monitors function calls with it; LadderLab shows properties only, and says so where it stands:
    above METHOD in IEC text, heading a method's declarations, in a body."""
    text = """
FUNCTION_BLOCK Pump
VAR on : BOOL; END_VAR
{attribute 'monitoring' := 'call'}
METHOD Start : BOOL
Start := on;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR p : Pump; END_VAR
{attribute 'monitoring' := 'variable'}
p.Start();
END_PROGRAM
"""
    project, problems = source_to_project(text, "monitoring")
    assert project is not None and [(d.code, d.severity, d.line) for d in problems] == [
        ("ST-PRAGMA", "warning", 4),  # above METHOD
        ("ST-PRAGMA", "warning", 11),  # in Main's body
    ]
    pump = project.pous[0]
    method = pump.methods[0].model_copy(update={"declarations": "{attribute 'monitoring' := 'call'}"})
    project.pous[0] = pump.model_copy(update={"methods": [method]})
    found = [
        (d.severity, d.file, d.line, d.column, d.message)
        for d in build_project(project).diagnostics
        if d.code == "ST-PRAGMA"
    ]
    tail = (
        ": it shows a property's value online when it heads the declarations of the property's GET (or SET), written "
        "above PROPERTY in IEC text; move it there or remove it"
    )
    assert found == [
        ("warning", "Main/body", 11, 1, "the attribute 'monitoring' has no effect here" + tail),
        ("warning", "Pump.Start/declarations", 1, 1, "the attribute 'monitoring' has no effect on a method" + tail),
    ]


def test_the_attribute_on_an_interfaces_property_is_a_located_warning():
    """An INTERFACE's property is a prototype: no instance of it holds a value to show."""
    text = """
INTERFACE ILevel
{attribute 'monitoring' := 'call'}
PROPERTY Level : INT
GET
END_GET
END_PROPERTY
END_INTERFACE
PROGRAM Main
END_PROGRAM
"""
    project, problems = source_to_project(text, "monitoring")
    assert project is not None
    assert [(d.code, d.severity, d.line, d.column, d.message.split(":")[0]) for d in problems] == [
        ("ST-PRAGMA", "warning", 3, 1, "the attribute 'monitoring' has no effect on a property of an INTERFACE")
    ]


VALVE = """
FUNCTION_BLOCK Valve
VAR pos : INT; sets : INT; END_VAR
{attribute 'monitoring' := 'call'}
PROPERTY Opening : INT
GET
Opening := pos;
END_GET
SET
sets := sets + 1;
pos := 1000 / Opening;
END_SET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR v : Valve; n : INT; END_VAR
n := n + 1;
END_PROGRAM
"""


def test_writing_call_runs_its_set_once_between_scans_and_a_fault_in_it_is_located():
    """CODESYS: 'call' is "read or written by calling the property": the write runs the SET before the next scan
    (1000 / 4 = 250); a SET dividing by the 0 written faults where it divides, the tasks go on."""
    sim = run(VALVE)
    sim.write("Main.v.Opening", 4)
    assert sim.read("Main.v.sets") == 0  # not yet: at the next scan's start
    sim.cycle(1)
    assert [sim.read(p) for p in ("Main.v.Opening", "Main.v.pos", "Main.v.sets", "Main.n")] == [250, 250, 1, 1]
    sim.write("Main.v.Opening", 0)
    sim.cycle(1)
    assert [sim.read(p) for p in ("Main.v.pos", "Main.v.sets", "Main.n")] == [250, 2, 2]
    assert sim.faults == []
    [fault] = sim.accessor_faults
    assert fault.text().startswith(
        f"division by zero: 1000 / 0 at POU VALVE.OPENING.SET, line {VALVE.splitlines().index('pos := 1000 / Opening;') + 1} "
        "column 1"
    )


def test_a_call_property_is_not_forced_nor_faulted():
    sim = run(VALVE)
    with pytest.raises(InputRefused) as refused:
        sim.force("Main.v.Opening", 4)
    assert str(refused.value) == (
        "MAIN.V.OPENING is a property monitored as 'call': a write runs its SET once, and no variable holds its value "
        "to force"
    )


def test_a_write_of_a_call_property_is_refused_while_a_scan_is_halted():
    project, diagnostics = source_to_project(VALVE, "monitoring")
    assert project is not None and diagnostics == []
    sim = Simulation(lower_project(project).program, variant="debug")
    sim.set_breakpoint("Main", line=VALVE.splitlines().index("n := n + 1;") + 1)
    sim.cycle(1)
    assert sim.halted is not None
    with pytest.raises(InputRefused) as refused:
        sim.write("Main.v.Opening", 4)
    assert str(refused.value) == "MAIN.V.OPENING: its SET runs only between scans; the scan is halted in the middle"
