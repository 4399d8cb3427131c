"""Helpers for the PLCopen tests: XSD validation, stripping LadderLab's addData, building small XML bodies."""

from __future__ import annotations

import functools
import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.xml_io import LADDERLAB_DATA, PLCOPEN_NS
from tests.support import external

NS = {"p": PLCOPEN_NS}
#: The external fixture folders with PLCopen files (../shared/external).
FOLDERS = ("beremiz-examples", "openplc-examples", "rusty-cfc", "ironplc")
#: The only import errors among them, the source's own fault (a FUNCTION without a return type).
IMPORT_ERRORS = {
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-cdata.xml": ["PLCOPEN-POU"],
    # a syntax-highlighting sample: SFC elements without localId
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-sfc.xml": ["PLCOPEN-SFC"] * 3,
    # a transition condition drawn with TON and SR instances in the chart, which SFC-03 forbids
    "beremiz-examples/exemples/svghmi_traffic_light/plc.xml": ["PLCOPEN-SFC"],
}


@functools.cache
def _schema():
    import xmlschema

    return xmlschema.XMLSchema(str(external("plcopen", "tc6_xml_v201.xsd")))


def xsd_errors(data: bytes) -> list[str]:
    """Reasons the document breaks tc6_xml_v201.xsd (skips the test when the schema is not present)."""
    return [f"{e.path}: {e.reason}" for e in _schema().iter_errors(data.decode("utf-8"))]


def strip_ladderlab(data: bytes) -> bytes:
    """The document as another tool would leave it after dropping LadderLab's addData."""
    root = ET.fromstring(data)
    for holder in list(root.iter(f"{{{PLCOPEN_NS}}}addData")):
        for entry in list(holder):
            if entry.get("name") == LADDERLAB_DATA:
                holder.remove(entry)
    for parent in list(root.iter()):
        for child in list(parent):
            if child.tag == f"{{{PLCOPEN_NS}}}addData" and not len(child):
                parent.remove(child)
    return ET.tostring(root)


def project_xml(
    pous: str, *, instances: str = "<instances><configurations/></instances>", data_types: str = ""
) -> bytes:
    """A minimal TC6 2.01 project around ``<pou>`` elements."""
    return f"""<?xml version="1.0" encoding="utf-8"?>
<project xmlns="{PLCOPEN_NS}" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="sample"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld>
  <sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes>{data_types}</dataTypes><pous>{pous}</pous></types>
  {instances}
</project>""".encode()


def pou_xml(name: str, body: str, *, language: str, interface: str = "", pou_type: str = "program") -> str:
    return (
        f'<pou name="{name}" pouType="{pou_type}"><interface>{interface}</interface>'
        f"<body><{language}>{body}</{language}></body></pou>"
    )


def ld_project(body: str, declarations: str = "") -> bytes:
    return project_xml(pou_xml("Main", body, language="LD", interface=declarations))


def fbd_project(body: str, declarations: str = "") -> bytes:
    return project_xml(pou_xml("Main", body, language="FBD", interface=declarations))
