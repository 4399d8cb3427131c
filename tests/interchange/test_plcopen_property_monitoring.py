"""{attribute 'monitoring'} on a PROPERTY through PLCopen XML and the ST export (issue 25): CODESYS keeps a property's
attributes in the attributes entry of its interface (``<Attribute Name="monitoring" Value="variable"/>``, as it keeps
call_after_init's); IEC text writes the pragma above ``PROPERTY``; the model keeps it heading the GET's declarations
(st/monitoring.py). Each round trip shows the same values online, worked out by hand from the text."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.project import export_project_st
from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project
from tests.interchange.plcopen_helpers import xsd_errors
from tests.interchange.test_codesys_real_exports import without_ladderlab_data

SOURCE = """FUNCTION_BLOCK Tank
VAR amount : INT; END_VAR
{attribute 'monitoring' := 'variable'}
PROPERTY Level : INT
GET
Level := amount * 2;
END_GET
SET
amount := Level;
END_SET
END_PROPERTY
{attribute 'monitoring' := 'call'}
PROPERTY Half : INT
GET
Half := amount / 2;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : Tank; n : INT; END_VAR
n := n + 1;
t.Level := n * 3;
END_PROGRAM
"""

HEADS = {"Level": "{attribute 'monitoring' := 'variable'}", "Half": "{attribute 'monitoring' := 'call'}"}


def project():
    found, diagnostics = source_to_project(SOURCE, "monitoring")
    assert diagnostics == []
    return found


def shown(found) -> tuple[object, object]:
    """After 2 scans: the SET stored 6 (Level's last access), Half runs its GET: 6 / 2."""
    sim = build_project(found).simulation()
    sim.cycle(2)
    return sim.read("Main.t.Level"), sim.read("Main.t.Half")


def heads(found) -> dict[str, str]:
    tank = next(p for p in found.pous if p.name == "Tank")
    return {p.name: p.get.declarations for p in tank.properties}


def test_the_attribute_travels_in_codesys_attributes_entry_and_both_imports_keep_it():
    original = project()
    assert (heads(original), shown(original)) == (HEADS, (6, 3))
    document = export_plcopen(original)
    assert xsd_errors(document) == []
    ns = {"p": "http://www.plcopen.org/xml/tc6_0201"}
    root = ET.fromstring(document)
    found = {
        prop.get("name"): [(a.get("Name"), a.get("Value")) for a in prop.findall("p:interface//p:Attribute", ns)]
        for prop in root.findall(".//p:pou[@name='Tank']//p:Property", ns)
    }
    assert found == {"Level": [("monitoring", "variable")], "Half": [("monitoring", "call")]}
    for document_read in (document, without_ladderlab_data(document)):
        again = import_plcopen(document_read)
        assert [d.message for d in again.diagnostics] == []
        assert (heads(again.project), shown(again.project)) == (HEADS, (6, 3))


def test_the_st_export_writes_it_above_property_and_imports_back():
    exported = export_project_st(project())
    assert "{attribute 'monitoring' := 'call'}\nPROPERTY PUBLIC Half : INT\n" in exported.text
    again, diagnostics = source_to_project(exported.text, "monitoring")
    assert diagnostics == []
    assert (heads(again), shown(again)) == (HEADS, (6, 3))
