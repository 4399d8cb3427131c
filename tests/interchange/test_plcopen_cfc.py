"""PLCopen XML of CFC charts (issue 26 item 5): an IEC 61131-10 style ``<FBD>`` whose ``executionOrderId``s are
the chart's execution order numbers (CFC-02); LadderLab's addData marks it a chart, so it comes back a CFC POU."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model.cfc import CfcBody
from tests.interchange.plcopen_helpers import xsd_errors
from tests.interchange.st_support import same_traces
from tests.interchange.test_st_cfc import JUMP_DECLS
from tests.ir.diagram_support import project
from tests.ir.test_cfc_jumps import counting_chart, skipping_chart
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


# ---------------------------------------------------------------- jumps, labels, returns (issue 26 item 5)


def jump_project():
    return project(
        cfc_pou("Skip", JUMP_DECLS, skipping_chart()),
        cfc_pou("Count", JUMP_DECLS, counting_chart()),
    )


def test_a_chart_with_jumps_and_labels_comes_back_the_same_chart():
    original = jump_project()
    data = export_plcopen(original)
    assert xsd_errors(data) == []
    result = import_plcopen(data)
    assert [d.format() for d in result.diagnostics] == []
    assert result.project == original


def test_jumps_and_labels_are_tc6_elements_with_the_chart_order():
    """IEC 61131-10 / TC6: ``<jump label>`` with its input wired, ``<label label>``, each with its execution order
    id: the order skipping_chart numbers them (x, jump, y, label, z)."""
    fbd = ET.fromstring(export_plcopen(jump_project())).find(f".//{NS}pou[@name='Skip']/{NS}body/{NS}FBD")
    executed = sorted(
        (int(e.get("executionOrderId")), e)
        for e in fbd
        if e.tag in (f"{NS}jump", f"{NS}label", f"{NS}outVariable") and e.get("executionOrderId") is not None
    )
    named = [(e.tag.removeprefix(NS), e.get("label") or e.findtext(f"{NS}expression")) for _, e in executed]
    assert named == [
        ("outVariable", "x"),
        ("jump", "Over"),
        ("outVariable", "y"),
        ("label", "Over"),
        ("outVariable", "z"),
    ]
    jump = fbd.find(f"{NS}jump")
    assert jump.find(f"{NS}connectionPointIn/{NS}connection") is not None


def test_a_foreign_cfc_file_with_labels_runs_like_the_chart():
    """Without LadderLab's addData (another tool's CFC, RuSTy style) the labels cut FBD networks and each jump ends
    one; the imported FBD computes what the chart does, scan by scan."""
    original = jump_project()
    root = ET.fromstring(export_plcopen(original))
    for parent in root.iter():
        for child in list(parent):
            if child.tag == f"{NS}addData":
                parent.remove(child)
    result = import_plcopen(ET.tostring(root, encoding="utf-8"))
    assert [pou.language for pou in result.project.pous] == ["fbd", "fbd"]
    assert [n.label for n in result.project.pou("Skip").body.networks] == [None, None, "Over"]
    same_traces(original, other=result.project)
