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


def test_a_codesys_method_marked_call_after_init_is_refused_at_the_import():
    """CODESYS keeps ``{attribute 'call_after_init'}`` in its attributes entry of the method's interface ("Attribute:
    call_after_init": the method is called after the instance's initialisation); LadderLab never calls it, so the
    import says so at the method instead of dropping the attribute."""
    tc6 = "http://www.plcopen.org/xml/tc6_0201"
    root = ET.fromstring(export_plcopen(project()))
    method = root.find(f".//{{{tc6}}}Method[@name='FB_reinit']")
    interface = method.find(f"{{{tc6}}}interface")
    if interface is None:
        interface = ET.SubElement(method, f"{{{tc6}}}interface")
    data = ET.SubElement(
        ET.SubElement(interface, f"{{{tc6}}}addData"),
        f"{{{tc6}}}data",
        {"name": "http://www.3s-software.com/plcopenxml/attributes", "handleUnknown": "implementation"},
    )
    ET.SubElement(ET.SubElement(data, f"{{{tc6}}}Attributes"), f"{{{tc6}}}Attribute", {"Name": "call_after_init"})
    imported = import_plcopen(without_ladderlab_data(ET.tostring(root)))
    found = [(d.severity, d.code, d.pou, d.message) for d in imported.diagnostics if d.code == "IR-UNSUPPORTED"]
    assert found == [
        (
            "error",
            "IR-UNSUPPORTED",
            "F",
            "LadderLab does not call a method marked {attribute 'call_after_init'} after the instance is initialised, "
            "as CODESYS does: call the method from the program (on its first scan) and remove the attribute",
        )
    ]
