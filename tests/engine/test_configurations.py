"""Configurations as IEC 61131-3 writes them (issue 16; IEC 2.7, CFG-01..08), scan by scan on the virtual clock.

CONFIGURATION with VAR_GLOBAL (CONSTANT, RETAIN), RESOURCE ... ON ... with its own globals and tasks, TASK with
INTERVAL and/or SINGLE and PRIORITY, named program instances with parameter bindings, VAR_ACCESS and VAR_CONFIG;
they survive the ST export, a project folder and PLCopen XML.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace
from ladderlab.storage.project_folder import project_files, read_project_folder

COUNTER = """
PROGRAM Counter
VAR_INPUT step : INT := 1; END_VAR
VAR_OUTPUT total : INT; END_VAR
VAR n : INT; END_VAR
n := n + step; total := n; log := log * 10 + step;
END_PROGRAM
"""

PLANT = (
    COUNTER
    + """
CONFIGURATION Plant
    VAR_GLOBAL CONSTANT big : INT := 5; END_VAR
    VAR_GLOBAL RETAIN kept : INT; END_VAR
    VAR_GLOBAL log : DINT; END_VAR
    RESOURCE Cpu ON PLC
        VAR_GLOBAL go : BOOL; sum_a : INT; END_VAR
        TASK fast (INTERVAL := T#10ms, PRIORITY := 2);
        TASK slow (INTERVAL := T#20ms, PRIORITY := 1);
        TASK event (SINGLE := go, PRIORITY := 0);
        PROGRAM a WITH fast : Counter (step := 1, total => sum_a);
        PROGRAM RETAIN b WITH slow : Counter (step := big);
        PROGRAM c WITH event : Counter (step := 2);
    END_RESOURCE
    VAR_ACCESS
        a_total : a.total : INT READ_ONLY;
        b_count : Cpu.b.n : INT READ_WRITE;
    END_VAR
    VAR_CONFIG
        a.n : INT := 100;
        b.n : INT := 7;
    END_VAR
END_CONFIGURATION
"""
)


def build(text: str):
    project, diagnostics = source_to_project(text, "plant")
    assert project is not None and diagnostics == [], diagnostics
    return project, build_project(project)


def simulation(text: str):
    project, result = build(text)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    return result.simulation()


def errors(text: str) -> list[str]:
    return [d.format() for d in build(text)[1].diagnostics if d.severity == "error"]


def test_two_instances_of_one_program_are_two_states_named_by_their_instances():
    sim = simulation(PLANT)
    sim.cycle(2)  # 10 ms: fast; 20 ms: slow (priority 1) then fast (priority 2)
    assert (sim.read("a.n"), sim.read("b.n"), sim.read("c.n")) == (102, 12, 0)  # VAR_CONFIG starts a at 100, b at 7
    assert sim.read("sum_a") == 102  # total => sum_a after each run of a
    assert sim.read("log") == 1 * 100 + 5 * 10 + 1  # 10 ms: a; 20 ms: b before a (priority 1 runs first)
    with pytest.raises(KeyError, match=r"PROGRAM Counter has 3 instances \(A, B, C\): name one"):
        sim.read("Counter.n")  # the program type is not an instance


def test_the_one_instance_of_a_program_is_also_reached_by_the_program_name():
    sim = simulation(
        COUNTER + "CONFIGURATION C\nVAR_GLOBAL log : DINT; END_VAR\nTASK t (INTERVAL := T#10ms);\n"
        "PROGRAM inst WITH t : Counter;\nEND_CONFIGURATION\n"
    )
    sim.cycle(3)
    assert (sim.read("inst.n"), sim.read("Counter.n")) == (3, 3)
    sim.write("counter.n", 10)  # as an online view of the program writes it (PLCopen's pouInstance names, Beremiz)
    sim.cycle(1)
    assert sim.read("INST.N") == 11
    assert sim.location("Counter.n").path == "COUNTER.N"  # the path as asked: a watch list finds its value


def test_a_single_task_runs_once_on_each_rising_edge():
    sim = simulation(PLANT)
    runs = []
    for scan, go in enumerate([False, True, True, False, True, False, False]):
        sim.write("go", go)
        sim.cycle(1)
        runs.append(sim.read("c.n"))
    assert runs == [0, 2, 2, 2, 4, 4, 4]


def test_interval_with_single_is_cyclic_while_single_is_false():
    text = COUNTER.replace("log := log * 10 + step;", "") + (
        "VAR_GLOBAL hold : BOOL; END_VAR\nCONFIGURATION C\n TASK t (INTERVAL := T#10ms, SINGLE := hold);\n"
        " PROGRAM p WITH t : Counter;\nEND_CONFIGURATION\n"
    )
    sim = simulation(text)
    counts = []
    for hold in [False, False, True, True, True, False, False]:
        sim.write("hold", hold)
        sim.cycle(1)
        counts.append(sim.read("p.n"))
    assert counts == [1, 2, 3, 3, 3, 4, 5]  # TRUE: one run on the rising edge, then none until it is FALSE (CFG-05)


def test_access_paths_read_and_write_as_declared():
    sim = simulation(PLANT)
    sim.cycle(2)
    assert (sim.read("a_total"), sim.read("b_count")) == (102, 12)
    sim.write("b_count", 40)
    sim.cycle(2)  # 30 ms: fast; 40 ms: slow, fast
    assert sim.read("b.n") == 45
    with pytest.raises(ValueError, match="READ_ONLY access path"):
        sim.write("a_total", 1)


def test_retain_instances_and_globals_survive_a_warm_restart_and_var_config_reapplies():
    sim = simulation(PLANT.replace("n := n + step;", "n := n + step; kept := kept + 1;"))
    sim.cycle(4)
    before = (sim.read("a.n"), sim.read("b.n"), sim.read("kept"))
    assert before == (104, 17, 6)
    sim.reset()  # warm: b is RETAIN, kept is RETAIN; a restarts at its VAR_CONFIG value
    assert (sim.read("a.n"), sim.read("b.n"), sim.read("kept")) == (100, 17, 6)
    sim.reset(cold=True)
    assert (sim.read("a.n"), sim.read("b.n"), sim.read("kept")) == (100, 7, 0)


def test_an_empty_configuration_runs_nothing():
    sim = simulation(COUNTER.replace("log := log * 10 + step;", "") + "CONFIGURATION Empty\nEND_CONFIGURATION\n")
    assert sim.cycle(3) == 3 and sim.time_ms == 30
    assert sim.snapshot() == {}  # no instance: the program never runs and has no state


def test_an_instance_without_a_task_runs_in_the_default_task_after_the_others():
    text = COUNTER + (
        "CONFIGURATION C\n VAR_GLOBAL log : DINT; END_VAR\n TASK t (INTERVAL := T#10ms, PRIORITY := 3);\n"
        " PROGRAM first : Counter (step := 1);\n PROGRAM second WITH t : Counter (step := 2);\nEND_CONFIGURATION\n"
    )
    sim = simulation(text)
    sim.cycle(1)
    assert sim.read("log") == 21  # the task (priority 3) before the default task (the lowest priority)


@pytest.mark.parametrize(
    "configuration, expected",
    [
        (
            "VAR_GLOBAL a : INT; END_VAR TASK t (INTERVAL := T#10ms); PROGRAM a WITH t : Counter;",
            "configuration, $.configuration.resources[0].tasks[0].programs[0]: error ST-DUPLICATE: 'a' names a "
            "program instance and a global variable: instances and globals share one namespace (ST-08)",
        ),
        (
            "TASK t (INTERVAL := T#10ms); PROGRAM p WITH t : Counter (stpe := 1);",
            "configuration, $.configuration.resources[0].tasks[0].programs[0].inputs.stpe: error ST-CALL-ARGS: "
            "the program Counter has no VAR_INPUT 'stpe' - did you mean 'step'?",
        ),
        (
            "VAR_GLOBAL x : INT; END_VAR TASK t (SINGLE := x); PROGRAM p WITH t : Counter;",
            "configuration, $.configuration.resources[0].tasks[0].single: error ST-TYPE-MISMATCH: SINGLE needs a "
            "BOOL variable, not 'x' (INT)",
        ),
        (
            "TASK t (INTERVAL := T#10ms); PROGRAM p WITH t : Nope;",
            "$.configuration.resources[0].tasks[0].programs[0].type: error UNKNOWN-PROGRAM: task t runs 'Nope', "
            "which is not a POU of this project",
        ),
        (
            "TASK t (INTERVAL := T#10ms); PROGRAM p WITH t : Counter; VAR_ACCESS v : p.x : INT; END_VAR",
            "configuration/access:9:73: error ST-UNKNOWN-MEMBER: Counter has no variable 'x'",
        ),
    ],
)
def test_configuration_errors_are_located(configuration, expected):
    text = COUNTER.replace("log := log * 10 + step;", "") + f"CONFIGURATION C\n{configuration}\nEND_CONFIGURATION\n"
    assert expected in errors(text)


def test_the_configuration_survives_st_export_a_project_folder_and_plcopen(tmp_path):
    project, _ = build(PLANT)
    text = export_project_st(project).text
    assert "PROGRAM RETAIN b WITH slow : Counter(step := big);" in text and "SINGLE := go" in text
    from_st, diagnostics = source_to_project(text, "plant")
    assert diagnostics == []
    workspace = Workspace(tmp_path)
    workspace.create(project)
    from_folder = workspace.load("plant").project
    assert from_folder.configuration == project.configuration
    from_xml = import_plcopen(export_plcopen(project), name="plant").project
    assert from_xml.configuration.resources == project.configuration.resources
    for other in (from_st, from_folder, from_xml):
        assert _trace(other) == _trace(project)


def _trace(project) -> list[tuple]:
    sim = build_project(project).simulation()
    out = []
    for go in [False, True, False, True, True, False]:
        sim.write("go", go)
        sim.cycle(1)
        out.append((sim.read("a.n"), sim.read("b.n"), sim.read("c.n"), sim.read("log"), sim.read("b_count")))
    return out


def test_projects_with_the_simple_task_list_load_and_save_unchanged():
    """project.json files written before configurations (tasks with program names) read as before and are written
    back byte for byte; no configuration key appears."""
    folder = Path(__file__).resolve().parents[2] / "examples" / "motor"
    project = read_project_folder(folder)
    assert project.configuration is None and all(isinstance(p, str) for t in project.tasks for p in t.programs)
    for rel, text in project_files(project).items():
        assert (folder / rel).read_text(encoding="utf-8") == text, rel
    assert "configuration" not in project_files(project)["project.json"]
