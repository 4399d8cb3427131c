"""Named global variable lists in a whole-project ST file (``ladderlab export st``, st/gvl_text.py): each list under
its ``{attribute 'global_variable_list' := 'NAME'}`` pragma (and CODESYS's ``{attribute 'qualified_only'}``), read
back by ``source_to_project`` as the same lists; the exported file runs the same."""

from __future__ import annotations

from ladderlab.interchange.st.project import export_project_st
from ladderlab.model import GlobalVariableList, Pou, Project, Task
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.ir.diagram_support import coil, contact, ld_pou, rung

IO = GlobalVariableList(name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR")
PAR = GlobalVariableList(
    name="GVL_Par", text="VAR_GLOBAL CONSTANT\n    nMax : INT := 3;\nEND_VAR\nVAR_GLOBAL\n    nCount : INT;\nEND_VAR"
)
MAIN = Pou(
    name="Main",
    kind="program",
    language="st",
    body="IF GVL_IO.bStart AND nCount < GVL_Par.nMax THEN\n    nCount := nCount + 1;\nEND_IF;",
)
LAMP = ld_pou("Lamp", "VAR q : BOOL; END_VAR", rung("n1", contact("c1", "GVL_IO.bStart"), coil("q1", "q")))


def project() -> Project:
    return Project(
        name="p",
        globals="VAR_GLOBAL\n    g : INT;\nEND_VAR",
        gvls=[IO, PAR, GlobalVariableList(name="GVL_Empty")],
        pous=[MAIN, LAMP],
        tasks=[Task(name="T", programs=["Main", "Lamp"])],
    )


def test_the_lists_are_written_under_their_pragmas_after_the_unnamed_globals():
    text = export_project_st(project()).text
    assert text.startswith(
        "VAR_GLOBAL\n    g : INT;\nEND_VAR\n\n"
        "{attribute 'global_variable_list' := 'GVL_IO'}\n{attribute 'qualified_only'}\n"
        "VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR\n\n"
        "{attribute 'global_variable_list' := 'GVL_Par'}\n" + PAR.text + "\n\n"
        "{attribute 'global_variable_list' := 'GVL_Empty'}\nVAR_GLOBAL\nEND_VAR\n\nPROGRAM Main"
    )


def test_the_file_reads_back_with_the_same_lists_and_runs_the_same():
    again, diagnostics = source_to_project(export_project_st(project()).text, "p")
    assert diagnostics == []
    assert again.globals == "VAR_GLOBAL\n    g : INT;\nEND_VAR"
    assert again.gvls == [IO, PAR, GlobalVariableList(name="GVL_Empty", text="VAR_GLOBAL\nEND_VAR")]
    sim = build_project(again).simulation()
    sim.write("GVL_IO.bStart", True)
    seen = []
    for _ in range(4):
        sim.cycle(1)
        seen.append((sim.read("GVL_Par.nCount"), sim.read("LAMP.q")))
    assert seen == [(1, True), (2, True), (3, True), (3, True)]  # nCount stops at nMax (3)


def test_a_list_named_twice_in_a_file_is_one_list_and_a_located_error():
    text = (
        "{attribute 'global_variable_list' := 'G'}\nVAR_GLOBAL a : INT; END_VAR\n"
        "PROGRAM Main\nEND_PROGRAM\n"
        "{attribute 'global_variable_list' := 'g'}\nVAR_GLOBAL b : INT; END_VAR\n"
    )
    again, diagnostics = source_to_project(text, "p")
    assert [(d.code, d.line, d.message) for d in diagnostics] == [
        ("ST-DUPLICATE", 6, "a second global variable list called G: its blocks are added to the first")
    ]
    assert [(g.name, g.text) for g in again.gvls] == [("G", "VAR_GLOBAL a : INT; END_VAR\nVAR_GLOBAL b : INT; END_VAR")]


def test_two_lists_sharing_a_name_read_back_and_run_the_same_in_st_and_ld():
    """CODESYS: a name in two lists is two variables, each used qualified (test_gvl_shared_names.py)."""
    lists = [
        GlobalVariableList(name="GVL_A", text="VAR_GLOBAL\n    b : BOOL;\nEND_VAR"),
        GlobalVariableList(name="GVL_B", text="VAR_GLOBAL\n    b : BOOL;\nEND_VAR"),
    ]
    copy = ld_pou("Copy", "", rung("n1", contact("c1", "GVL_A.b"), coil("q1", "GVL_B.b")))
    toggle = Pou(name="Toggle", kind="program", language="st", body="GVL_A.b := NOT GVL_A.b;")
    project = Project(name="p", gvls=lists, pous=[toggle, copy], tasks=[Task(name="T", programs=["Toggle", "Copy"])])
    text = export_project_st(project).text
    again, diagnostics = source_to_project(text, "p")
    assert diagnostics == []
    assert again.gvls == lists
    sim = build_project(again).simulation()
    seen = []
    for _ in range(3):
        sim.cycle(1)
        seen.append((sim.read("GVL_A.b"), sim.read("GVL_B.b")))
    assert seen == [(True, True), (False, False), (True, True)]  # Copy runs after Toggle in the scan
