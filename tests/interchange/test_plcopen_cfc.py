"""PLCopen XML of CFC charts (issue 26 item 5): an IEC 61131-10 style ``<FBD>`` whose ``executionOrderId``s are
the chart's execution order numbers (CFC-02); LadderLab's addData marks it a chart, so it comes back a CFC POU."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model.cfc import CfcBody
from tests.interchange.plcopen_helpers import xsd_errors
from tests.ir.diagram_support import project
from tests.ir.test_lower_cfc import INTS, cfc_pou, copy_chart, counter_chart

NS = "{http://www.plcopen.org/xml/tc6_0201}"


def chart_project():
    return project(
        cfc_pou("Main", INTS, counter_chart(["mul", "or", "inc", "oc"])),
        cfc_pou("Copy", INTS, copy_chart(["oy", "ox"])),
    )


def test_a_chart_comes_back_a_chart_with_its_order_CFC_01_CFC_02():
    original = chart_project()
    result = import_plcopen(export_plcopen(original))
    assert [d.format() for d in result.diagnostics] == []
    assert result.project == original
    assert all(pou.language == "cfc" and isinstance(pou.body, CfcBody) for pou in result.project.pous)


def test_execution_order_ids_are_the_chart_order_CFC_02():
    """MUL is number 1 although it reads the ADD: the ids say MUL, r, ADD, count (input variables are not
    executed elements; they carry ids just before their first reader, as the FBD export writes them)."""
    data = export_plcopen(project(cfc_pou("Main", INTS, counter_chart(["mul", "or", "inc", "oc"]))))
    assert xsd_errors(data) == []
    fbd = ET.fromstring(data).find(f".//{NS}pou[@name='Main']/{NS}body/{NS}FBD")
    executed = sorted(
        (int(e.get("executionOrderId")), e)
        for e in fbd
        if e.tag in (f"{NS}block", f"{NS}outVariable") and e.get("executionOrderId") is not None
    )
    named = [e.get("typeName") or e.findtext(f"{NS}expression") for _, e in executed]
    assert named == ["MUL", "r", "ADD", "count"]
