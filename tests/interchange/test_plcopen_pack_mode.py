"""A STRUCT's CODESYS ``pack_mode`` through PLCopen XML (issue 25 item 1): CODESYS writes a declaration's attribute
pragmas in its dataType's addData (``<data name="http://www.3s-software.com/plcopenxml/attributes"><Attributes>
<Attribute Name="pack_mode" Value="1"/>``); LadderLab writes it there and reads it back, so another tool's file
(without LadderLab's carried types text) keeps the STRUCT packed."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model import Pou, Project
from ladderlab.simulation.build import build_project
from tests.interchange.plcopen_helpers import NS, strip_ladderlab, xsd_errors

TYPES = "{attribute 'pack_mode' := '1'}\nTYPE P : STRUCT a : BYTE; b : DINT; END_STRUCT; END_TYPE"
MAIN = Pou(
    name="Main",
    kind="program",
    language="st",
    declarations="VAR\n  p : P;\n  n : DINT;\nEND_VAR",
    body="n := SIZEOF(p);",
)


def sizeof_p(project: Project) -> int:
    """SIZEOF(p) after one scan: 5 packed (a at 0, b at 1..4), 8 laid out naturally."""
    built = build_project(project)
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    sim = built.simulation()
    sim.cycle(1)
    return sim.read("Main.n")


def test_pack_mode_is_codesys_s_attribute_of_the_data_type():
    data = export_plcopen(Project(name="packed", types=TYPES, pous=[MAIN]))
    assert xsd_errors(data) == []
    data_type = ET.fromstring(data).find("p:types/p:dataTypes/p:dataType[@name='P']", NS)
    assert data_type is not None
    attributes = data_type.findall(
        "p:addData/p:data[@name='http://www.3s-software.com/plcopenxml/attributes']/p:Attributes/p:Attribute", NS
    )
    assert [(a.get("Name"), a.get("Value")) for a in attributes] == [("pack_mode", "1")]


def test_ladderlab_s_file_and_another_tool_s_both_come_back_packed():
    project = Project(name="packed", types=TYPES, pous=[MAIN])
    assert sizeof_p(project) == 5
    data = export_plcopen(project)
    ours = import_plcopen(data).project
    assert ours is not None and ours.types == TYPES
    foreign = import_plcopen(strip_ladderlab(data))
    assert foreign.diagnostics == []  # CODESYS's attributes entry read, so nothing reported dropped
    assert foreign.project is not None and "{attribute 'pack_mode' := '1'}\n    P : STRUCT" in foreign.project.types
    assert sizeof_p(foreign.project) == 5


def test_a_value_no_pragma_can_hold_is_a_located_import_error():
    """Another tool's ``Value="1'"`` would end the pragma early and vanish when the text is read: an error at the
    data type instead, the STRUCT imported without it."""
    data = export_plcopen(Project(name="packed", types=TYPES, pous=[MAIN]))
    result = import_plcopen(strip_ladderlab(data).replace(b'Value="1"', b'Value="1\'"'), file="plc.xml")
    errors = [(d.code, d.message, d.file) for d in result.diagnostics if d.severity == "error"]
    assert errors == [("PLCOPEN-DECL", 'the pack_mode "1\'" cannot be written as a pragma; it is left out', "plc.xml")]
    assert result.project is not None and "pack_mode" not in result.project.types
