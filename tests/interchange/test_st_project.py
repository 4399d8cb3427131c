"""Whole-project ST export: TYPEs, VAR_GLOBAL, every POU, and the CONFIGURATION from the tasks; the file reads
back (st.project_text) into a project that runs like the original."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

import tests.ir.test_diagram_equivalence as generated
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model.project import Pou, Project, Task
from ladderlab.st.checker import check_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.load import load_project_path
from tests.interchange.st_support import same_traces
from tests.ir.diagram_support import coil, contact, ld_pou, rung


def read_back(project: Project) -> Project:
    result = export_project_st(project)
    assert [d.format() for d in result.diagnostics] == []
    read, diagnostics = source_to_project(result.text, project.name)
    assert diagnostics == [] and check_project(read).diagnostics == []
    return read


def test_motor_project_file_has_every_part_and_runs_like_the_project():
    project = load_project_path("examples/motor")
    text = export_project_st(project).text
    assert text.startswith("VAR_GLOBAL\n    Start AT %IX0.0 : BOOL;")
    units = ("VAR_GLOBAL", "PROGRAM ", "FUNCTION_BLOCK ", "END_PROGRAM", "END_FUNCTION_BLOCK", "CONFIGURATION")
    assert [line for line in text.splitlines() if line.startswith(units)] == [
        "VAR_GLOBAL",
        "PROGRAM Main",
        "END_PROGRAM",
        "FUNCTION_BLOCK Blinker",
        "END_FUNCTION_BLOCK",
        "PROGRAM Scaling",
        "END_PROGRAM",
        "CONFIGURATION motor_config",
    ]
    assert text.endswith(
        "CONFIGURATION motor_config\n    RESOURCE main_resource ON PLC\n"
        "        TASK MainTask(INTERVAL := T#10ms, PRIORITY := 1);\n"
        "        PROGRAM Main WITH MainTask : Main;\n        PROGRAM Scaling WITH MainTask : Scaling;\n"
        "    END_RESOURCE\nEND_CONFIGURATION\n"
    )
    read = read_back(project)
    assert runs(read) == runs(project)
    same_traces(project, other=read)


def runs(project: Project) -> list[tuple]:
    """What each task runs: (task, interval, priority, [(instance, program)]), whichever form holds it."""
    return [
        (t.name, t.interval, t.priority, [(p, p) if isinstance(p, str) else (p.name, p.type) for p in t.programs])
        for t in project.all_tasks()
    ]


def test_project_source_map_names_pou_and_network():
    project = load_project_path("examples/motor")
    result = export_project_st(project)
    lines = result.text.splitlines()
    assert [
        (lines[line - 1], network, element) for line, network, element in result.source_map if element == "motor"
    ] == [("Motor := (Start OR Motor) AND NOT Stop;", "Main/seal_in", "motor")]


def test_types_are_kept_and_a_project_without_tasks_gets_the_default_task_explicitly():
    """ir/lower_project.py: without tasks every PROGRAM runs in one 10 ms task; the file says so, and names
    that a user already took are not reused for the configuration."""
    main = ld_pou("Main", "VAR a : BOOL; c : TColor; END_VAR", rung("n", contact("k", "a"), coil("q", "t_config")))
    project = Project(
        name="t",
        types="TYPE TColor : (red, green); END_TYPE",
        globals="VAR_GLOBAL t_config : BOOL; END_VAR",
        pous=[main],
    )
    text = export_project_st(project).text
    assert text.startswith("TYPE TColor : (red, green); END_TYPE\n\nVAR_GLOBAL t_config : BOOL; END_VAR\n\n")
    assert text.endswith(
        "CONFIGURATION t_config_2\n    RESOURCE main_resource ON PLC\n"
        "        TASK DEFAULT(INTERVAL := T#10ms, PRIORITY := 0);\n"
        "        PROGRAM Main WITH DEFAULT : Main;\n    END_RESOURCE\nEND_CONFIGURATION\n"
    )
    same_traces(project, other=read_back(project))


def test_a_pou_with_errors_is_refused_with_its_diagnostics():
    broken = ld_pou("Main", "VAR a : BOOL; END_VAR", rung("n", contact("k", "nope"), coil("q", "a")))
    result = export_project_st(Project(name="t", pous=[broken]))
    assert result.text == ""
    assert [d.code for d in result.diagnostics] == ["ST-UNKNOWN-VAR", "EXPORT-INVALID"]
    assert (result.diagnostics[0].pou, result.diagnostics[0].network, result.diagnostics[0].element) == (
        "Main",
        "n",
        "k",
    )


@given(
    st.lists(generated.rungs, min_size=1, max_size=3),
    st.lists(generated.rungs, min_size=1, max_size=3),
    st.integers(0, 2**16),
)
def test_property_a_two_program_project_reads_back_and_runs_identically(ld_rungs, fbd_rungs, seed):
    fbd_main = generated.fbd_program(fbd_rungs)
    fbd_main = Pou(**{**fbd_main.model_dump(), "name": "Second"})
    project = Project(
        name="p",
        pous=[generated.ld_program(ld_rungs), fbd_main],
        tasks=[Task(name="fast", interval="T#10ms", priority=1, programs=["Main", "Second"])],
    )
    same_traces(project, scans=100, seed=seed, other=read_back(project))


def test_an_export_that_would_not_check_is_refused_never_handed_out():
    """EXPORT-INTERNAL: the exported text is checked before it is given out; were it wrong (a defect of the
    export), the user gets this error instead of a file that does not build."""
    from ladderlab.interchange.st.export import verify
    from ladderlab.interchange.st.project import verify_text

    project = Project(
        name="p", pous=[Pou(name="Main", kind="program", language="ld", declarations="VAR a : BOOL; END_VAR")]
    )
    broken = Pou(name="Main", kind="program", language="st", declarations="VAR a : BOOL; END_VAR", body="a := b;")
    assert [d.format() for d in verify(project, broken)] == [
        "POU Main: error EXPORT-INTERNAL: the exported ST of Main does not check: Main/body:1:6, POU Main: error "
        "ST-UNKNOWN-VAR: unknown variable 'b'"
    ]
    text = "PROGRAM Main\nVAR a : BOOL; END_VAR\na := 1.5;\nEND_PROGRAM\n"
    assert [d.format() for d in verify_text(text, project)] == [
        "POU Main: error EXPORT-INTERNAL: the exported ST does not check: Main/body:3:6, POU Main: error "
        "ST-TYPE-MISMATCH: cannot assign ANY_REAL literal to BOOL"
    ]


def test_a_configuration_naming_a_missing_task_is_located():
    """ST-CONFIG (docs/diagnostics.md): the program instance names a task its resource does not have."""
    text = (
        "PROGRAM MainProgram\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n"
        "CONFIGURATION Plant\n  RESOURCE Cpu ON PLC\n    TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n"
        "    PROGRAM Main WITH Slow : MainProgram;\n  END_RESOURCE\nEND_CONFIGURATION\n"
    )
    project, diagnostics = source_to_project(text)
    assert project is not None and project.configuration is not None
    assert [(d.code, d.line, d.column, d.message) for d in diagnostics] == [
        ("ST-CONFIG", 8, 5, "program Main: there is no task Slow in this resource")
    ]
