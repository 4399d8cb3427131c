"""Named global variable lists through PLCopen XML, the way CODESYS V3 writes a GVL (its structure as in
tests/interchange/data/codesys_application.xml and CODESYS's ``{attribute 'qualified_only'}`` as the ``Attribute``
of a ``.../plcopenxml/attributes`` entry in the list's addData, as CODESYS projects exported to PLCopen carry it):
one ``<globalVars name>`` per list in the application's resource, its blocks in a ``mixedattrsvarlist`` entry when
they mix qualifiers. Export is TC6 v2.01 valid and imports back the same, with and without LadderLab's data."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model import GlobalVariableList, Pou, Project, Task
from ladderlab.simulation.build import build_project
from tests.interchange.plcopen_helpers import strip_ladderlab, xsd_errors

FIXTURE = Path(__file__).parent / "data" / "codesys_application.xml"
ATTRIBUTES = "http://www.3s-software.com/plcopenxml/attributes"
NS = {"p": "http://www.plcopen.org/xml/tc6_0201"}
QUALIFIED = """<data name="http://www.3s-software.com/plcopenxml/attributes" handleUnknown="implementation">
                <Attributes>
                  <Attribute Name="qualified_only" Value="" />
                </Attributes>
              </data>
              <data name="http://www.3s-software.com/plcopenxml/mixedattrsvarlist\""""

IO = GlobalVariableList(
    name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL; (* the start button *)\nEND_VAR"
)
MIXED = GlobalVariableList(
    name="GVL_Par",
    text="VAR_GLOBAL CONSTANT\n    nMax : INT := 5;\nEND_VAR\nVAR_GLOBAL RETAIN\n    nCount : INT;\nEND_VAR",
)
MAIN = Pou(
    name="Main",
    kind="program",
    language="st",
    body="IF GVL_IO.bStart AND nCount < GVL_Par.nMax THEN\n    nCount := nCount + 1;\nEND_IF;",
)


def codesys_with_qualified_only() -> bytes:
    """The CODESYS export with its GVL made qualified_only, as CODESYS writes the attribute."""
    text = FIXTURE.read_text()
    marker = '<data name="http://www.3s-software.com/plcopenxml/mixedattrsvarlist"'
    assert text.count(marker) == 1
    return text.replace(marker, QUALIFIED).encode()


def test_a_codesys_gvl_with_qualified_only_comes_as_such_and_its_bare_use_is_reported():
    result = import_plcopen(codesys_with_qualified_only())
    assert not any(ATTRIBUTES in d.message for d in result.diagnostics)  # understood, not dropped
    [gvl] = result.project.gvls
    assert (gvl.name, gvl.qualified_only) == ("GVL", True)
    found = [d.format() for d in build_project(result.project).diagnostics if d.severity == "error"]
    places = [d.split(": error ST-QUALIFIED-ONLY: ")[0] for d in found]
    assert places == [  # the bare uses of the fixture's sources (lines 1 and 4 of Fill, Room's GET, PLC_PRG line 2)
        "FB_TANK.Fill/body:1:8, POU FB_TANK.Fill",
        "FB_TANK.Fill/body:4:9, POU FB_TANK.Fill",
        "FB_TANK.Room.GET/body:1:9, POU FB_TANK.Room.GET",
        "PLC_PRG/body:2:1, POU PLC_PRG",
    ]
    assert found[-1].endswith(
        "'tankLevel' belongs to the global variable list GVL, which is qualified_only: write GVL.tankLevel"
    )


def test_lists_are_written_as_codesys_writes_a_gvl_and_read_back_the_same():
    project = Project(name="p", gvls=[IO, MIXED], pous=[MAIN], tasks=[Task(name="T", programs=["Main"])])
    document = export_plcopen(project)
    assert xsd_errors(document) == []
    assert import_plcopen(document).project == project
    assert import_plcopen(strip_ladderlab(document)).project.gvls == project.gvls  # (tasks: a configuration then)
    root = ET.fromstring(strip_ladderlab(document))
    resource = root.find("p:instances/p:configurations/p:configuration/p:resource", NS)
    io, par = resource.findall("p:globalVars", NS)
    assert (io.get("name"), [v.get("name") for v in io.findall("p:variable", NS)]) == ("GVL_IO", ["bStart"])
    assert [(a.get("Name"), a.get("Value")) for a in io.iterfind("p:addData/p:data/p:Attributes/p:Attribute", NS)] == [
        ("qualified_only", "")
    ]
    assert (par.get("name"), par.get("constant"), [v.get("name") for v in par.findall("p:variable", NS)]) == (
        "GVL_Par",
        "true",
        ["nMax", "nCount"],
    )
    blocks = par.findall("p:addData/p:data/p:MixedAttrsVarList/p:globalVars", NS)
    assert [(b.get("name"), b.get("constant"), b.get("retain")) for b in blocks] == [
        ("GVL_Par", "true", None),
        ("GVL_Par", None, "true"),
    ]


def test_the_lists_of_a_project_without_tasks_read_back_without_a_configuration():
    project = Project(name="p", globals="VAR_GLOBAL\n    g : INT;\nEND_VAR", gvls=[IO])
    document = export_plcopen(project)
    assert xsd_errors(document) == []
    again = import_plcopen(document).project
    assert (again.gvls, again.globals, again.configuration, again.tasks) == ([IO], project.globals, None, [])


def test_an_imported_and_exported_project_runs_the_same():
    """Main counts nCount up while GVL_IO.bStart is TRUE and nCount < GVL_Par.nMax (5): 1, 2, 3, 4, 5, 5."""
    project = Project(name="p", gvls=[IO, MIXED], pous=[MAIN], tasks=[Task(name="T", programs=["Main"])])
    sim = build_project(import_plcopen(strip_ladderlab(export_plcopen(project))).project).simulation()
    sim.write("GVL_IO.bStart", True)
    seen = []
    for _ in range(6):
        sim.cycle(1)
        seen.append(sim.read("GVL_Par.nCount"))
    assert seen == [1, 2, 3, 4, 5, 5]


def test_two_lists_sharing_a_name_go_out_and_come_back_and_run_the_same():
    """CODESYS: a name in two lists is two variables, ``GVL_A.x`` and ``GVL_B.x`` (test_gvl_shared_names.py)."""
    lists = [
        GlobalVariableList(name="GVL_A", text="VAR_GLOBAL\n    x : INT := 5;\nEND_VAR"),
        GlobalVariableList(name="GVL_B", text="VAR_GLOBAL\n    x : INT;\nEND_VAR"),
    ]
    main = Pou(name="Main", kind="program", language="st", body="GVL_B.x := GVL_B.x + GVL_A.x;")
    project = Project(name="p", gvls=lists, pous=[main], tasks=[Task(name="T", programs=["Main"])])
    document = export_plcopen(project)
    assert xsd_errors(document) == []
    assert import_plcopen(document).project == project
    again = import_plcopen(strip_ladderlab(document)).project
    assert again.gvls == lists
    sim = build_project(again).simulation()
    sim.cycle(3)
    assert (sim.read("GVL_A.x"), sim.read("GVL_B.x")) == (5, 15)
