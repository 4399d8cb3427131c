"""Plants in the scan (issue 21): the plant task runs before the control tasks of every scan on the same
virtual clock, in lockstep under breakpoints and single steps; plants cannot be called from control code."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.inputs import InputEvent
from ladderlab.model import Configuration, ProgramInstance, Project, Resource, Task
from ladderlab.simulation.build import build_project

from .plant_support import TANK_CONTROL, TANK_GLOBALS, TANK_PLANT, project, simulate, st_pou, tank_reference

ORDER_GLOBALS = "VAR_GLOBAL\n    Order : DINT;\nEND_VAR"


def _marker(name: str, kind: str, mark: int):
    """A POU that appends its mark to the global Order (Order := Order * 10 + mark)."""
    return st_pou(name, kind, "VAR_EXTERNAL\n    Order : DINT;\nEND_VAR", f"Order := Order * 10 + {mark};")


def _rows(sim, scans: int, paths: list[str]) -> list[tuple]:
    rows = []
    for _ in range(scans):
        sim.cycle()
        rows.append(tuple(sim.read(p) for p in paths))
    return rows


def test_the_plant_runs_first_in_every_scan_on_the_same_clock():
    """Two control tasks (10 ms, 25 ms): each scan runs the plant (mark 9) first, then the tasks due then."""
    tasks = [
        Task(name="Fast", interval="T#10ms", priority=5, programs=["FastP"]),
        Task(name="Slow", interval="T#25ms", priority=1, programs=["SlowP"]),
    ]
    sim = simulate(
        _marker("FastP", "program", 1),
        _marker("SlowP", "program", 2),
        _marker("Model", "plant", 9),
        globals=ORDER_GLOBALS,
        tasks=tasks,
    )
    rows = []
    for _ in range(7):
        sim.write("Order", 0)
        sim.cycle()
        rows.append((sim.time_ms, sim.read("Order")))
    # the due times of the control tasks make the scans; at 50 ms both are due: Slow (priority 1) first
    assert rows == [(10, 91), (20, 91), (25, 92), (30, 91), (40, 91), (50, 921), (60, 91)]


def test_a_project_of_plants_only_scans_every_10_ms():
    sim = simulate(_marker("Model", "plant", 9), globals=ORDER_GLOBALS)
    assert _rows(sim, 3, ["Order"]) == [(9,), (99,), (999,)] and sim.time_ms == 30


def test_plant_and_program_in_lockstep_scan_by_scan():
    """The tank fills while the pump runs and the program stops the pump at the high switch: every scan as the
    reference computes it (plant first, seeing the pump the program set in the previous scan)."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    assert _rows(sim, 30, ["Pump", "High", "Level"]) == tank_reference(30)


def test_a_force_holds_a_plant_signal_for_the_program():
    """The plant writes High every scan; forced FALSE, the program still sees FALSE and never stops the pump."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    sim.force("High", False)
    assert _rows(sim, 12, ["Pump", "High", "Level"]) == tank_reference(12, forced_high=False)


def test_plants_are_monitored_like_programs():
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS, variant="monitor")
    sim.cycle(2)
    assert sim.instances() == {"MAIN": ["MAIN"], "TANK": ["TANK"]}
    assert sim.probes("TANK").executed == frozenset()  # an ST plant: probed like an ST program (no elements)
    assert [t.name for t in sim.tasks] == ["DEFAULT", "PLANTS"] and sim.tasks[1].plant


def _debug_run(breakpoints: list[tuple[str, int]], steps: list[int], scans: int) -> list[dict]:
    """Snapshots after each scan of the tank, with breakpoints on the given lines and some statement steps."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS, variant="debug")
    for pou, line in breakpoints:
        sim.set_breakpoint(pou, line=line)
    snapshots = []
    for scan in range(scans):
        halted = sim.step("statement") if scan in steps else (None if sim.cycle() else sim.halted)
        while halted is not None:
            halted = sim.resume()
        snapshots.append(sim.snapshot())
    return snapshots


@settings(max_examples=25, deadline=None)
@given(
    breakpoints=st.lists(st.sampled_from([("Tank", 2), ("Tank", 5), ("Main", 2), ("Main", 4)]), unique=True),
    steps=st.lists(st.integers(0, 14), unique=True),
)
def test_breakpoints_and_steps_change_no_value(breakpoints, steps):
    """Lockstep: halting in the plant or in the program and stepping statement by statement gives every scan
    exactly the values of a fast run, because the plant runs inside the scan the debugger halts."""
    fast = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS)
    expected = []
    for _ in range(15):
        fast.cycle()
        expected.append(fast.snapshot())
    assert _debug_run(breakpoints, steps, 15) == expected


def test_a_breakpoint_in_the_program_halts_after_the_plant_ran():
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS, variant="debug")
    sim.cycle(3)
    level = sim.read("Level")
    sim.set_breakpoint("Main", line=4)  # Pump := NOT High
    assert not sim.cycle()
    assert sim.halted.origin.pou.upper() == "MAIN"
    _, _, expected_level = tank_reference(4)[3]
    assert sim.read("Level") == expected_level != level  # the plant already ran in this halted scan
    sim.resume()
    assert (sim.read("Pump"), sim.read("High"), sim.read("Level")) == tank_reference(4)[3]


def test_panel_presses_while_halted_wait_for_the_next_scan():
    """At a halt the panel shows the halt's values; a press queues and applies at the start of the next scan."""
    sim = simulate(TANK_CONTROL, TANK_PLANT, globals=TANK_GLOBALS, variant="debug")
    sim.set_breakpoint("Tank", line=1)
    assert not sim.cycle() and sim.halted.origin.pou.upper() == "TANK"
    sim.submit(InputEvent("panel", "Main.Starts", 40))
    assert sim.read("Main.Starts") == 0 and [e.kind for e in sim.pending] == ["panel"]
    sim.resume()
    assert sim.read("Main.Starts") == 1  # the first scan counted its start; the press waits
    sim.clear_breakpoints()
    sim.cycle()
    assert sim.read("Main.Starts") == 40 and sim.pending == []


def _diagnostics(*pous, tasks=None, globals=TANK_GLOBALS):
    build = build_project(project(*pous, globals=globals, tasks=tasks))
    return [(d.code, d.pou, d.line, d.column, d.message) for d in build.diagnostics if d.severity == "error"]


def test_control_code_cannot_call_a_plant():
    main = st_pou("Main", "program", "", "Tank();")
    assert _diagnostics(main, TANK_PLANT) == [
        (
            "ST-PLANT",
            "Main",
            1,
            1,
            "Tank is a plant: it models the process and runs in the plant task before every scan; control code "
            "cannot call it (read and write the signals it shares instead)",
        )
    ]


def test_control_code_cannot_declare_a_plant():
    main = st_pou("Main", "program", "VAR\n    t : Tank;\nEND_VAR", "")
    codes = _diagnostics(main, TANK_PLANT)
    assert [(c, p, line) for c, p, line, _, _ in codes] == [("ST-PLANT", "Main", 2)]
    assert "Tank is a plant" in codes[0][4] and "cannot be declared as a variable" in codes[0][4]


@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_a_diagram_box_cannot_call_a_plant(language):
    from ladderlab.model import Box, FbdBody, FbdNetwork, LdBody, LdNetwork, Pou
    from ladderlab.model.fbd import Block

    body = (
        LdBody(networks=[LdNetwork(id="n1", elements=[Box(id="b1", call="Tank")])])
        if language == "ld"
        else FbdBody(networks=[FbdNetwork(id="n1", nodes=[Block(id="b1", call="Tank")])])
    )
    main = Pou(name="Main", kind="program", language=language, body=body)
    found = _diagnostics(main, TANK_PLANT)
    assert [(c, p) for c, p, *_ in found] == [(f"{language.upper()}-PLANT", "Main")]
    assert "Tank is a plant" in found[0][4]


def test_a_control_task_cannot_run_a_plant_and_the_plant_task_name_is_reserved():
    tasks = [Task(name="Plants", programs=["Main"]), Task(name="T1", programs=["Tank"])]
    codes = {(c, m) for c, _, _, _, m in _diagnostics(TANK_CONTROL, TANK_PLANT, tasks=tasks)}
    assert codes == {
        ("RESERVED-TASK", "the task name PLANTS is reserved for the plant task; choose another name"),
        (
            "NOT-A-PROGRAM",
            "task T1 can only run programs; Tank is a plant: plants run in the plant task, before the control "
            "tasks of every scan",
        ),
    }


@pytest.mark.parametrize("variant", ["fast", "monitor", "debug"])
def test_a_plant_fault_stops_the_plant_task_with_its_location(variant):
    plant = st_pou("Model", "plant", "VAR\n    d : INT;\nEND_VAR", "d := 10 / d;")
    sim = simulate(TANK_CONTROL, plant, globals=TANK_GLOBALS, variant=variant)
    sim.cycle()
    assert sim.fault is not None and sim.fault.task == "PLANTS" and sim.fault.pou.upper() == "MODEL"


def test_the_plant_runs_every_scan_beside_a_single_task():
    """A SINGLE task (CFG-05) runs once per rising edge of its variable; the resource then scans every 10 ms
    and the plant (mark 9) runs in each of those scans, the triggered task (mark 1) after it."""
    globals_ = "VAR_GLOBAL\n    Order : DINT;\n    Go : BOOL;\nEND_VAR"
    task = Task(name="OnGo", interval=None, single="Go", programs=["Ctl"])
    sim = simulate(_marker("Ctl", "program", 1), _marker("Model", "plant", 9), globals=globals_, tasks=[task])
    rows = []
    for go in (False, True, True, False, True):
        sim.write("Order", 0)
        sim.write("Go", go)
        sim.cycle()
        rows.append((sim.time_ms, sim.read("Order")))
    assert rows == [(10, 9), (20, 91), (30, 9), (40, 9), (50, 91)]


def _configured(*instances: ProgramInstance, task: Task | None = None) -> Project:
    resource = Resource(name="Cpu", tasks=[task] if task else [], programs=list(instances))
    bench = project(TANK_PLANT, TANK_CONTROL, globals=TANK_GLOBALS)
    return bench.model_copy(update={"configuration": Configuration(name="Cell", resources=[resource])})


def test_a_configuration_runs_the_plants_first_in_every_scan():
    """With an IEC configuration (instance Ctl of Main in a 10 ms task), the plant still has its own instance
    (Tank, named after it) run by the plant task before the configuration's task: the tank's lockstep."""
    task = Task(name="Cyclic", interval="T#10ms", programs=[ProgramInstance(name="Ctl", type="Main")])
    build = build_project(_configured(task=task))
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    sim = build.simulation()
    assert [(t.name, t.programs, t.plant) for t in sim.tasks] == [
        ("CYCLIC", ["CTL"], False),
        ("PLANTS", ["TANK"], True),
    ]
    rows = [(sim.read("Pump"), sim.read("High"), sim.read("Level")) for _ in range(12) if sim.cycle()]
    reference = tank_reference(12)
    assert rows == reference
    # the program's own state is the instance Ctl's: it counts the scans that found the pump off below HIGH
    before = [False] + [pump for pump, _, _ in reference[:-1]]
    assert sim.read("Ctl.Starts") == sum(not pump and not high for pump, (_, high, _) in zip(before, reference))


def test_a_configuration_instance_cannot_take_a_plants_name():
    """The plant's instance is named after it, among the globals: a configuration's instance of that name
    would be a second one."""
    build = build_project(_configured(ProgramInstance(name="Tank", type="Main")))
    assert [(d.code, d.json_path) for d in build.diagnostics] == [
        ("DUPLICATE-INSTANCE", "$.configuration.resources[0].programs[0]")
    ]
