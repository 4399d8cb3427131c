"""PLCopen XML the way a real CODESYS V3.5 whole-project export is built (issue 25 item 5: import of other tools'
files). tests/interchange/data/codesys_application.xml follows the structure of MichielVanwelsenaere/
HomeAutomation.CoDeSys3, src/Exports/PLCopen.xml (CODESYS V3.5 SP21 Patch 3) and, for ``<Implements>``, of
src/Exports/archive/FB_OUTPUT_DIMMER_DALI_MQTT.xml of the same repository (e!COCKPIT, built on CODESYS V3): library
POUs in ``types/pous``, the application's POUs in its resource's addData, tasks calling programs with an empty
typeName and an XML duration as interval, a GVL mixing CONSTANT and plain variables, EXTENDS and IMPLEMENTS in the
inheritance entry, a method's comment in its interface's ``<documentation>``; and of jarbesk109-jpg/plcdoc,
samples/05_drive_oop.xml (CODESYS V3.5 SP22 Patch 3): the application's data types in its resource's addData, its
libraries and device, a PROPERTY whose SetAccessor comes first and whose ``<AccessModifiers />`` says PUBLIC. Names
and logic are LadderLab's own; the expected values are worked out by hand in each docstring."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.plcopen.xml_io import LADDERLAB_DATA
from ladderlab.model.fbd import Position
from ladderlab.simulation.build import build_project
from tests.interchange.plcopen_helpers import xsd_errors

FIXTURE = Path(__file__).parent / "data" / "codesys_application.xml"
CODESYS = "http://www.3s-software.com/plcopenxml/"


def dropped(name: str, places: int) -> tuple[str, str]:
    plural = "s" if places > 1 else ""
    return (
        "PLCOPEN-ADDDATA",
        f"addData '{CODESYS}{name}' ({places} place{plural}) is another tool's data that LadderLab cannot carry; "
        "it was dropped",
    )


def imported(text: str | None = None):
    result = import_plcopen((text or FIXTURE.read_text()).encode())
    assert result.project is not None
    return result


def test_every_part_of_the_whole_project_export_is_read():
    """The application's program and data type (resource addData), the GVL's two blocks (mixedattrsvarlist, not the
    merged list written CONSTANT) as the list GVL, the task's program (typeName empty: the instance's name) and
    interval (PT0.01S is 10 ms), EXTENDS and IMPLEMENTS (<Inheritance>), PRIVATE and PROTECTED (AccessModifiers), the method's comment
    (<documentation>), the properties' accessors in either order; what LadderLab cannot carry is named in a
    warning. FB_init is an FB_init, which LadderLab runs by itself as CODESYS does (test_plcopen_fb_init.py)."""
    result = imported()
    assert [(d.code, d.message) for d in result.diagnostics] == [
        ("PLCOPEN-VERSION", "the document uses 'http://www.plcopen.org/xml/tc6_0200'; it is read as TC6 v2.01"),
        (
            "PLCOPEN-ADDDATA",
            "addData 'Device' (1 place) is another tool's data that LadderLab cannot carry; it was dropped",
        ),
        dropped("libraries", 1),
        dropped("objectid", 6),
        dropped("projectinformation", 1),
        dropped("projectstructure", 1),
        dropped("tasksettings", 1),
    ]
    project = result.project
    assert [(p.name, p.kind, p.extends, p.implements) for p in project.pous] == [
        ("FB_COUNTER", "function_block", None, []),
        ("FB_TANK", "function_block", "FB_COUNTER", ["I_LEVEL"]),
        ("PLC_PRG", "program", None, []),
    ]
    fill, get_level = project.pous[1].methods
    assert (fill.name, fill.access, fill.declarations) == (
        "Fill",
        "PRIVATE",
        "//Adds amount while the tank is below CAPACITY.\nVAR_INPUT\n    amount : INT;\nEND_VAR",
    )
    assert (get_level.name, get_level.access, get_level.return_type) == ("GetLevel", "PUBLIC", "INT")
    amount, room = project.pous[1].properties
    assert (amount.name, amount.type, amount.access) == ("Amount", "INT", "PUBLIC")
    assert (amount.get.declarations, amount.get.body, amount.set.body) == (
        "VAR\n    half : INT;\nEND_VAR",
        "half := n / 2;\nAmount := half + half + n MOD 2;",
        "n := Amount;",
    )
    assert (room.name, room.access, room.get.body, room.set) == ("Room", "PROTECTED", "Room := CAPACITY - n;", None)
    assert project.types.startswith("TYPE\n    E_STATE : (Idle := 0, Filling := 1, Full := 2);\nEND_TYPE")
    [resource] = project.configuration.resources
    assert resource.globals == ""  # the GVL is a named list (tests/interchange/test_plcopen_gvls.py)
    assert [(g.name, g.qualified_only, g.text) for g in project.gvls] == [
        (
            "GVL",
            False,
            "VAR_GLOBAL CONSTANT\n    CAPACITY : INT := 9;\nEND_VAR\n"
            "VAR_GLOBAL\n    tankLevel : INT; (* written by PLC_PRG every scan *)\nEND_VAR",
        )
    ]
    [task] = resource.tasks
    assert (task.name, task.interval, task.priority) == ("MainTask", "T#10ms", 1)
    assert [(p.name, p.type) for p in task.programs] == [("PLC_PRG", "PLC_PRG")]


def test_the_imported_application_runs_scan_by_scan():
    """Each scan PLC_PRG calls tank with inflow: Fill adds 3 while n < CAPACITY (9), through FB_COUNTER.Add. n is 3, 6,
    9, 9; shown is I_LEVEL.GetLevel() * 10 plus the GET of Amount (n / 2 twice plus n MOD 2: n again), 33, 66, 99,
    99; state is Filling (1) until n reaches 9, then Full (2)."""
    result = build_project(imported().project)
    assert [d.format() for d in result.diagnostics if d.severity != "info"] == []
    sim = result.simulation()
    seen = []
    for _ in range(4):
        sim.cycle(1)
        seen.append(
            (
                sim.read("PLC_PRG.shown"),
                sim.read("GVL.tankLevel"),
                sim.read("PLC_PRG.isFull"),
                sim.read("PLC_PRG.tank.state"),
            )
        )
    assert seen == [(33, 3, False, 1), (66, 6, False, 1), (99, 9, True, 2), (99, 9, True, 2)]


def test_the_imported_access_of_a_property_is_enforced():
    """Room came PROTECTED from its AccessModifiers: a program may not read it (it was PUBLIC before)."""
    project = imported().project
    main = project.pous[2]
    changed = project.model_copy(
        update={"pous": [*project.pous[:2], main.model_copy(update={"body": main.body + "\nshown := tank.Room;"})]}
    )
    assert [(d.code, d.file, d.message) for d in build_project(changed).diagnostics] == [
        (
            "ST-NOT-ACCESSIBLE",
            "PLC_PRG/body",
            "the property FB_TANK.Room is PROTECTED: only its function block and those derived from it may use it",
        )
    ]


@pytest.mark.parametrize(
    ("duration", "literal"),
    [
        ("PT0.01S", "T#10ms"),  # the intervals of the real export: 50 ms, 10 s, 200 ms
        ("PT0.05S", "T#50ms"),
        ("PT10S", "T#10s"),
        ("PT0.2S", "T#200ms"),
        ("PT1H30M", "T#1h30m"),
        ("P1DT0.0000015S", "T#1d1us500ns"),
        ("PT0S", "T#0s"),
        ("T#5ms", "T#5ms"),  # already a TIME literal (LadderLab's own export)
    ],
)
def test_a_task_interval_written_as_an_xml_duration_is_a_time_literal(duration, literal):
    """CODESYS writes the interval as an XML Schema duration (PnDTnHnMnS); TC6 v2.01 says a TIME or a variable."""
    text = FIXTURE.read_text().replace('interval="PT0.01S"', f'interval="{duration}"')
    [task] = imported(text).project.configuration.resources[0].tasks
    assert task.interval == literal


@pytest.mark.parametrize(
    "implements",
    ["<Implements>I_LEVEL</Implements><Implements>I_SHOW</Implements>", "<Implements>I_LEVEL, I_SHOW</Implements>"],
)
def test_several_interfaces_in_the_inheritance_entry(implements):
    """Only one <Implements> was seen in a real file: one element per INTERFACE and a comma list read alike."""
    text = FIXTURE.read_text().replace("<Implements>I_LEVEL</Implements>", implements)
    assert imported(text).project.pous[1].implements == ["I_LEVEL", "I_SHOW"]


def without_ladderlab_data(document: bytes) -> bytes:
    root = ET.fromstring(document)
    for parent in list(root.iter()):
        for child in list(parent):
            if child.get("name") == LADDERLAB_DATA:
                parent.remove(child)
    return ET.tostring(root)


def test_ladderlabs_export_of_the_imported_project_imports_back_the_same():
    """With LadderLab's own data and without it (IMPLEMENTS and the method's comment travel as CODESYS writes them).
    The document is valid TC6 v2.01: a resource's tasks come before its globalVars (written after them before)."""
    project = imported().project
    document = export_plcopen(project)
    assert xsd_errors(document) == []
    for data in (document, without_ladderlab_data(document)):
        again = import_plcopen(data)
        assert [d.message for d in again.diagnostics] == []
        assert again.project == project
    root = ET.fromstring(without_ladderlab_data(document))
    ns = {"p": "http://www.plcopen.org/xml/tc6_0201", "x": "http://www.w3.org/1999/xhtml"}
    tank = root.find("p:types/p:pous/p:pou[@name='FB_TANK']", ns)
    assert [e.text for e in tank.iterfind("p:interface/p:addData/p:data/p:Inheritance/*", ns)] == [
        "FB_COUNTER",
        "I_LEVEL",
    ]
    fill = tank.find("p:addData/p:data/p:Method[@name='Fill']", ns)
    assert fill.findtext("p:interface/p:documentation/x:p", namespaces=ns) == (
        "Adds amount while the tank is below CAPACITY."
    )


INTERFACES = Path(__file__).parent / "data" / "codesys_interfaces.xml"


def test_interface_members_listed_as_codesys_v35_sp21_and_twincat_write_them_are_read():
    """codesys_interfaces.xml follows he-man86/volt, packages/volt-cli/test/Volt.Engine.Tests/fixtures/codesys-itf/
    IModuleManager.plcopen.xml and ITF_FolderedMember.plcopen.xml (CODESYS V3.5 SP21 Patch 4: <Methods> and
    <Properties> in the Interface, a property typed only in its header text) and fixtures/tc-pou/
    FB_TcMembers.plcopen.xml (TwinCAT 3.5.13: members' declaration text as a direct child, PRIVATE only there). The
    header of a declaration text is read after the comment or pragma opening it (IMPLEMENTS, PRIVATE)."""
    result = import_plcopen(INTERFACES.read_bytes())
    assert [d.code for d in result.diagnostics] == ["PLCOPEN-VERSION", "PLCOPEN-ADDDATA"]  # tc6_0200; objectid
    project = result.project
    assert project.types == (
        "INTERFACE I_SWITCH\nMETHOD Toggle : BOOL\n// Switches over; the new state\nEND_METHOD\n"
        "PROPERTY IsOn : BOOL\nGET END_GET\nSET END_SET\nEND_PROPERTY\n"
        "PROPERTY Toggles : INT\nGET END_GET\nEND_PROPERTY\nEND_INTERFACE"
    )
    lamp = project.pous[0]
    assert lamp.implements == ["I_SWITCH"]
    assert [(m.name, m.access) for m in lamp.methods] == [("Toggle", "PUBLIC"), ("Bump", "PRIVATE")]
    assert [(p.name, p.type, p.access, p.get is not None, p.set is not None) for p in lamp.properties] == [
        ("IsOn", "BOOL", "PUBLIC", True, True),
        ("Toggles", "INT", "PUBLIC", True, False),
    ]


def test_the_interface_project_runs_scan_by_scan_through_interface_properties():
    """Each scan: wasOn reads IsOn through I_SWITCH before Toggle flips it, state is Toggle's result, toggled reads
    Toggles (Bump counts the calls): (FALSE, TRUE, 1), (TRUE, FALSE, 2), (FALSE, TRUE, 3)."""
    result = build_project(import_plcopen(INTERFACES.read_bytes()).project)
    assert [d.format() for d in result.diagnostics if d.severity != "info"] == []
    sim = result.simulation()
    seen = []
    for _ in range(3):
        sim.cycle(1)
        seen.append((sim.read("PLC_PRG.wasOn"), sim.read("PLC_PRG.state"), sim.read("PLC_PRG.toggled")))
    assert seen == [(False, True, 1), (True, False, 2), (False, True, 3)]


def test_private_from_twincats_header_text_is_enforced():
    """TwinCAT writes no AccessModifiers: METHOD PRIVATE Bump in the declaration text makes it PRIVATE."""
    project = import_plcopen(INTERFACES.read_bytes()).project
    main = project.pous[1]
    changed = project.model_copy(
        update={"pous": [project.pous[0], main.model_copy(update={"body": main.body + "\ntoggled := lamp.Bump();"})]}
    )
    assert [(d.code, d.file, d.message) for d in build_project(changed).diagnostics] == [
        (
            "ST-NOT-ACCESSIBLE",
            "PLC_PRG/body",
            "the method FB_LAMP.Bump is PRIVATE: only its own function block may call it",
        )
    ]


def test_the_interface_project_exported_by_ladderlab_imports_back_the_same():
    """LadderLab writes the INTERFACE in the <Methods> / <Properties> form above; with and without its own data the
    project comes back the same."""
    project = import_plcopen(INTERFACES.read_bytes()).project
    document = export_plcopen(project)
    assert xsd_errors(document) == []
    for data in (document, without_ladderlab_data(document)):
        again = import_plcopen(data)
        assert again.diagnostics == []
        assert again.project == project
    ns = {"p": "http://www.plcopen.org/xml/tc6_0201"}
    interface = ET.fromstring(document).find("p:addData/p:data/p:Interface", ns)
    assert [e.get("name") for e in interface.iterfind("p:Methods/p:Method", ns)] == ["Toggle"]
    assert [
        (e.get("name"), [a.tag.split("}")[1] for a in e if a.tag.endswith("Accessor")])
        for e in interface.iterfind("p:Properties/p:Property", ns)
    ] == [("IsOn", ["GetAccessor", "SetAccessor"]), ("Toggles", ["GetAccessor"])]


def test_an_interface_property_without_a_type_is_a_located_warning():
    """Neither a returnType nor a header text with a type: the property is left out, the warning at its element."""
    text = INTERFACES.read_text().replace("PROPERTY PUBLIC Toggles : INT", "PROPERTY PUBLIC Toggles")
    result = import_plcopen(text.encode())
    [warning] = [d for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED"]
    assert (warning.severity, warning.message) == (
        "warning",
        "the PROPERTY Toggles of INTERFACE I_SWITCH has no type; it was left out",
    )
    assert warning.line == text[: text.index('<Property name="Toggles">\n            <GetAccessor>')].count("\n") + 1
    assert "Toggles" not in result.project.types


FBD_METHOD = """<data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation">
            <Method name="Drawn">
              <interface>
                <returnType>
                  <BOOL />
                </returnType>
              </interface>
              <body>
                <FBD>
                  <vendorElement localId="10000000000">
                    <position x="0" y="0" />
                    <alternativeText>
                      <xhtml xmlns="http://www.w3.org/1999/xhtml">FBD Implementation Attributes</xhtml>
                    </alternativeText>
                  </vendorElement>
                </FBD>
              </body>
              <InterfaceAsPlainText>
                <xhtml xmlns="http://www.w3.org/1999/xhtml">METHOD Drawn : BOOL</xhtml>
              </InterfaceAsPlainText>
              <addData />
            </Method>
          </data>
          """


def test_a_method_drawn_in_fbd_is_left_out_with_a_located_warning():
    """CODESYS V3.5 SP21 writes a method drawn in FBD with an <FBD> body (he-man86/volt, packages/volt-cli/test/
    Volt.Engine.Tests/fixtures/codesys-pou/POU_SfcRoot_StFbdMethods.plcopen.xml). LadderLab's methods are ST: the
    method is left out (it was imported with an empty body, whose calls returned FALSE), so calling it is a located
    build error."""
    marker = '<data name="http://www.3s-software.com/plcopenxml/property"'
    text = INTERFACES.read_text().replace(marker, FBD_METHOD + marker, 1)
    result = import_plcopen(text.encode())
    [warning] = [d for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED"]
    assert (warning.severity, warning.message) == (
        "warning",
        "the method FB_LAMP.Drawn is written in FBD; LadderLab's methods and properties are ST, so it was left out",
    )
    assert warning.line == text[: text.index('<Method name="Drawn">')].count("\n") + 1
    project = result.project
    assert [m.name for m in project.pous[0].methods] == ["Toggle", "Bump"]
    main = project.pous[1]
    changed = project.model_copy(
        update={"pous": [project.pous[0], main.model_copy(update={"body": main.body + "\nstate := lamp.Drawn();"})]}
    )
    assert [(d.severity, d.code, d.file) for d in build_project(changed).diagnostics] == [
        ("error", "ST-UNKNOWN-MEMBER", "PLC_PRG/body")
    ]


CFC_BODY = """<body>
                <ST>
                  <xhtml xmlns="http://www.w3.org/1999/xhtml" />
                </ST>
                <addData>
                  <data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation">
                    <CFC>
                      <inVariable localId="1">
                        <position x="20" y="2" />
                        <connectionPointOut>
                          <expression />
                        </connectionPointOut>
                        <expression>TRUE</expression>
                      </inVariable>
                    </CFC>
                  </data>
                </addData>
              </body>"""


def test_a_cfc_method_and_a_cfc_pou_are_reported_where_they_are():
    """CODESYS V3.5 SP21 writes a CFC chart as an empty <ST> with the chart in the body's addData (he-man86/volt,
    packages/volt-cli/test/Volt.Engine.Tests/fixtures/codesys-pou/FB_ChildFolderStructure.plcopen.xml): the method
    is left out with a warning (LadderLab's methods are ST); the POU becomes a CFC POU with the chart's input
    variable (tests/interchange/test_codesys_cfc.py reads whole charts)."""
    method = FBD_METHOD.replace('name="Drawn"', 'name="Charted"').replace(
        FBD_METHOD[FBD_METHOD.index("<body>") : FBD_METHOD.index("</body>") + len("</body>")], CFC_BODY
    )
    pou = f"""<pou name="FB_CHART" pouType="functionBlock">
        <interface />
        {CFC_BODY}
      </pou>
      """
    marker = '<data name="http://www.3s-software.com/plcopenxml/property"'
    text = INTERFACES.read_text().replace(marker, method + marker, 1)
    text = text.replace('<pou name="PLC_PRG"', pou + '<pou name="PLC_PRG"')
    result = import_plcopen(text.encode())
    reported = [(d.severity, d.message, d.line) for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED"]
    assert reported == [
        (
            "warning",
            "the method FB_LAMP.Charted is written in CFC; LadderLab's methods and properties are ST, so it was left out",
            text[: text.index('<Method name="Charted">')].count("\n") + 1,
        ),
    ]
    charted = next(p for p in result.project.pous if p.name == "FB_CHART")
    assert charted.language == "cfc"
    assert [(n.type, n.expr, n.pos) for n in charted.body.chart.nodes] == [("input", "TRUE", Position(x=440, y=72))]
    assert [m.name for m in result.project.pous[0].methods] == ["Toggle", "Bump"]
    assert [d.code for d in result.diagnostics if d.code == "PLCOPEN-ADDDATA"] == ["PLCOPEN-ADDDATA"]  # objectid only


def test_an_action_drawn_in_cfc_is_reported_not_imported_empty():
    """A function block's action in CODESYS's CFC form (an empty <ST>, the chart in the body's addData) is reported
    and left out like any action not in ST (it was imported as an empty ST action)."""
    action = (
        f'<actions>\n          <action name="Reset">\n            {CFC_BODY}\n          </action>\n        </actions>\n'
    )
    marker = '</interface>\n        <body>\n          <ST>\n            <xhtml xmlns="http://www.w3.org/1999/xhtml" />'
    text = INTERFACES.read_text()
    assert text.count(marker) == 1
    text = text.replace(marker, marker.replace("<body>", action + "        <body>"))
    result = import_plcopen(text.encode())
    [warning] = [d for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED"]
    assert (warning.message, warning.line) == (
        "action 'Reset' of POU FB_LAMP was not imported: LadderLab imports a function block's actions with ST bodies",
        text[: text.index('<action name="Reset">')].count("\n") + 1,
    )
    assert result.project.pous[0].actions == []


def test_an_sfc_action_drawn_in_cfc_is_a_located_error_not_an_empty_action():
    """An SFC program's action in CODESYS's CFC form (the chart in the body's addData) is reported where it is (it was
    imported as an empty ST action, which ran and did nothing)."""
    pou = f"""<pou name="Seq" pouType="program">
        <interface><localVars><variable name="n"><type><INT /></type></variable></localVars></interface>
        <actions>
          <action name="Fill">
            {CFC_BODY}
          </action>
        </actions>
        <body>
          <SFC>
            <step localId="1" name="Init" initialStep="true"><position x="0" y="0" />
              <connectionPointOut formalParameter="sfc" /><connectionPointOutAction formalParameter="" /></step>
            <actionBlock localId="2"><position x="0" y="0" />
              <connectionPointIn><connection refLocalId="1" /></connectionPointIn>
              <action localId="3" qualifier="N"><relPosition x="0" y="0" /><reference name="Fill" /></action>
            </actionBlock>
          </SFC>
        </body>
      </pou>
      """
    text = INTERFACES.read_text().replace('<pou name="PLC_PRG"', pou + '<pou name="PLC_PRG"')
    result = import_plcopen(text.encode())
    reported = [(d.severity, d.code, d.message, d.line) for d in result.diagnostics if d.code == "PLCOPEN-SFC"]
    cfc = '<data name="http://www.3s-software.com/plcopenxml/cfc"'
    assert text.count(cfc) == 1
    assert reported == [
        (
            "error",
            "PLCOPEN-SFC",
            "action Fill is written in CFC, which LadderLab cannot import here",
            text[: text.index(cfc)].count("\n") + 1,
        ),
    ]


def test_a_pous_own_documentation_opens_its_declarations():
    """TC6's <pou><documentation> (after its addData, tc6_xml_v201.xsd) is the POU's comment when its interface has
    none: the declarations start with it as // lines (it was dropped)."""
    marker = """                </addData>
              </pou>
            </data>
            <data name="http://www.3s-software.com/plcopenxml/libraries\""""
    text = FIXTURE.read_text()
    assert text.count(marker) == 1
    documented = marker.replace(
        "</addData>\n",
        '</addData>\n<documentation><xhtml xmlns="http://www.w3.org/1999/xhtml"> Fills the tank.\n'
        " Every scan.</xhtml></documentation>\n",
    )
    main = imported(text.replace(marker, documented)).project.pous[2]
    assert main.declarations.startswith("// Fills the tank.\n// Every scan.\nVAR\n    tank : FB_TANK;")
