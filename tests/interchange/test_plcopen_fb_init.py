"""FB_init, FB_exit and an instance's FB_init arguments through PLCopen XML and the ST export (issue 25).

CODESYS keeps an instance's FB_init arguments outside TC6's ``<variable>``: in its addData entry
``http://www.3s-software.com/plcopenxml/inputassignments`` (``<InputAssignments><InputAssignment><Value>``, by
position). LadderLab writes that entry with each input's ``<Name>`` and the declaration's exact type in its own data;
expected values are those the declarations give (docs/st.md, "FB_init and FB_exit")."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model import Task
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.interchange.plcopen_helpers import xsd_errors
from tests.interchange.test_codesys_real_exports import without_ladderlab_data

SOURCE = """FUNCTION_BLOCK F
VAR_OUTPUT x : INT; s : STRING; END_VAR
METHOD FB_init : BOOL
VAR_INPUT bInitRetains : BOOL; bInCopyCode : BOOL; n : INT; t : STRING := 'd'; END_VAR
x := n; s := t;
END_METHOD
METHOD FB_reinit : BOOL
x := 0;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    a : F(n := 3, t := 'q');
    b : F(4);
    c : F(5, 'w');
    arr : ARRAY [0..1] OF F[(n := 1), (n := 2, t := 'z')];
END_VAR
END_PROGRAM
"""

EXPECTED = {"a": (3, "q"), "b": (4, "d"), "c": (5, "w"), "arr[0]": (1, "d"), "arr[1]": (2, "z")}


def values(project) -> dict[str, tuple[int, str]]:
    sim = build_project(project).simulation()
    return {name: (sim.read(f"Main.{name}.x"), sim.read(f"Main.{name}.s")) for name in EXPECTED}


def project():
    found, diagnostics = source_to_project(SOURCE, "fbinit")
    assert diagnostics == []
    return found


def test_the_arguments_travel_in_codesys_entry_and_ladderlabs_and_run_the_same_after_the_import():
    original = project()
    assert values(original) == EXPECTED
    document = export_plcopen(original)
    assert xsd_errors(document) == []
    root = ET.fromstring(document)
    ns = {"p": "http://www.plcopen.org/xml/tc6_0201"}
    a = root.find(".//p:pou[@name='Main']//p:variable[@name='a']", ns)
    assert a.find("p:type/p:derived", ns).get("name") == "F"
    assignments = a.findall("p:addData/p:data/p:InputAssignments/p:InputAssignment", ns)
    assert [(e.findtext("p:Name", namespaces=ns), e.findtext("p:Value", namespaces=ns)) for e in assignments] == [
        ("n", "3"),
        ("t", "'q'"),
    ]
    again = import_plcopen(document)
    assert [d.message for d in again.diagnostics] == []
    assert values(again.project) == EXPECTED


def test_a_codesys_file_without_ladderlabs_data_gives_single_instances_their_arguments():
    """An array's per-element arguments travel only in LadderLab's data: without it the elements get none, and the
    build names the input they lack."""
    plain = import_plcopen(without_ladderlab_data(export_plcopen(project())))
    assert [(d.code, d.message) for d in plain.diagnostics] == [  # a CODESYS file: FB_reinit is not run by itself
        (
            "PLCOPEN-UNSUPPORTED",
            "method F.FB_reinit was imported as an ordinary method: CODESYS calls it by itself after an instance was "
            "copied in an online change, which LadderLab has not, so its statements run only where the program "
            "calls it",
        )
    ]
    main = next(p for p in plain.project.pous if p.name == "Main")
    assert main.declarations.splitlines()[1:5] == [
        "    a : F (n := 3, t := 'q');",
        "    b : F(4);",
        "    c : F(5, 'w');",
        "    arr : ARRAY [0..1] OF F;",
    ]
    errors = [(d.code, d.message) for d in build_project(plain.project).diagnostics if d.severity == "error"]
    assert errors == [
        (
            "ST-CALL-ARGS",
            "the FB_init of F needs n: declare it as ARRAY [...] OF F[(n := ...), ...]",
        )
    ]


def test_codesys_positional_values_are_read_by_position():
    document = export_plcopen(project()).decode()
    # CODESYS's own entry names no input: drop the names LadderLab writes, and LadderLab's data
    document = document.replace("<Name>n</Name>", "").replace("<Name>t</Name>", "")
    plain = import_plcopen(without_ladderlab_data(document.encode()))
    main = next(p for p in plain.project.pous if p.name == "Main")
    assert main.declarations.splitlines()[1] == "    a : F(3, 'q');"


def test_the_st_export_prints_the_arguments_and_runs_the_same():
    exported = export_project_st(project()).text
    assert "    arr : ARRAY [0..1] OF F[(n := 1), (n := 2, t := 'z')];" in exported
    again, diagnostics = source_to_project(exported, "again")
    assert diagnostics == []
    assert values(again) == EXPECTED


AFTER_INIT = """{attribute 'call_after_init'}
FUNCTION_BLOCK FB_DoIt
VAR_INPUT in1 : INT; END_VAR
VAR_OUTPUT seen : INT; END_VAR
{attribute 'call_after_init'}
METHOD FB_AfterInit
seen := in1 * 2;
END_METHOD
END_FUNCTION_BLOCK
PROGRAM Main
VAR fbDoIt : FB_DoIt := (in1 := 99); END_VAR
END_PROGRAM
"""


def _after_init_project():
    project, diagnostics = source_to_project(AFTER_INIT, "after")
    assert diagnostics == []
    return project.model_copy(update={"tasks": [Task(name="T", programs=["Main"])]})


def test_call_after_init_is_written_as_codesys_writes_it_and_read_back_from_it_alone():
    """CODESYS keeps ``{attribute 'call_after_init'}`` in its attributes entry of the POU's and the method's
    interface; without LadderLab's own data the import puts it back on the first line of their declarations and
    the method runs after the declaration's values (CODESYS's example: seen 198)."""
    tc6 = "http://www.plcopen.org/xml/tc6_0201"
    document = export_plcopen(_after_init_project())
    assert xsd_errors(document) == []
    root = ET.fromstring(without_ladderlab_data(document))
    attribute = "tc6:addData/tc6:data/tc6:Attributes/tc6:Attribute"
    ns = {"tc6": tc6}
    pou = root.find(".//tc6:pou[@name='FB_DoIt']/tc6:interface", ns)
    method = root.find(".//tc6:Method[@name='FB_AfterInit']/tc6:interface", ns)
    assert [a.get("Name") for a in pou.findall(attribute, ns)] == ["call_after_init"]
    assert [a.get("Name") for a in method.findall(attribute, ns)] == ["call_after_init"]
    imported = import_plcopen(without_ladderlab_data(document))
    assert [d.format() for d in imported.diagnostics if d.severity != "info"] == []
    [fb] = [p for p in imported.project.pous if p.name == "FB_DoIt"]
    assert fb.declarations.startswith("{attribute 'call_after_init'}\n")
    assert fb.methods[0].declarations.startswith("{attribute 'call_after_init'}")
    sim = build_project(imported.project).simulation()
    assert sim.read("Main.fbDoIt.seen") == 198


def test_call_after_init_comes_back_with_ladderlab_data_and_through_the_st_export():
    project = _after_init_project()
    assert import_plcopen(export_plcopen(project)).project == project
    exported = export_project_st(project).text
    assert exported.startswith("{attribute 'call_after_init'}\nFUNCTION_BLOCK FB_DoIt\n")
    assert "{attribute 'call_after_init'}\nMETHOD PUBLIC FB_AfterInit\n" in exported
    again, diagnostics = source_to_project(exported, "again")
    assert diagnostics == []
    assert build_project(again).simulation().read("Main.fbDoIt.seen") == 198
