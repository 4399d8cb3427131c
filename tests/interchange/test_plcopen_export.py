"""Project -> PLCopen XML, element by element (issue 8: exporter unit tests per element kind, XSD validation).

Each test exports a small project and reads the XML back with plain ElementTree,
so the assertions are about the document other tools see: elements, localIds,
connections (``refLocalId``/``formalParameter``), modifiers, sections.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from datetime import UTC, datetime

import pytest
from hypothesis import given

from ladderlab.interchange.plcopen.exporter import PlcopenExportError, export_plcopen
from ladderlab.model import (
    Block,
    Box,
    Coil,
    Compare,
    Contact,
    FbdBody,
    FbdNetwork,
    InputNode,
    Jump,
    LdBody,
    LdNetwork,
    OutputNode,
    Parallel,
    PinFlags,
    PinRef,
    Position,
    Pou,
    Project,
    Return,
    Task,
    Wire,
)
from ladderlab.storage import load_project_path
from tests.interchange.plcopen_helpers import NS, xsd_errors
from tests.interchange.plcopen_strategies import projects
from tests.support import EXAMPLES

XHTML = "{http://www.w3.org/1999/xhtml}"


def export(*pous: Pou, **project) -> ET.Element:
    data = export_plcopen(Project(name="t", pous=list(pous), **project))
    return ET.fromstring(data)


def ld(*networks: LdNetwork, declarations: str = "") -> Pou:
    return Pou(
        name="Main", kind="program", language="ld", declarations=declarations, body=LdBody(networks=list(networks))
    )


def body(root: ET.Element, language: str = "LD") -> ET.Element:
    return root.find(f"p:types/p:pous/p:pou/p:body/p:{language}", NS)


def by_id(root: ET.Element) -> dict[str, ET.Element]:
    return {e.get("localId"): e for e in body(root) if e.get("localId")}


def sources(root: ET.Element, element: ET.Element, pin: str | None = None) -> list[tuple[str, str | None]]:
    """(tag of the source element, formalParameter) of every connection into ``element`` (or its ``pin``)."""
    holder = element if pin is None else element.find(f".//p:variable[@formalParameter='{pin}']", NS)
    elements = by_id(root)
    return [
        (elements[c.get("refLocalId")].tag.split("}")[1], c.get("formalParameter"))
        for c in holder.find("p:connectionPointIn", NS).findall("p:connection", NS)
    ]


def only(root: ET.Element, tag: str) -> ET.Element:
    (found,) = body(root).findall(f"p:{tag}", NS)
    return found


def test_motor_example_validates_against_the_tc6_schema():
    assert xsd_errors(export_plcopen(load_project_path(EXAMPLES / "motor"))) == []


@given(projects())
def test_generated_projects_validate_against_the_tc6_schema(project):
    assert xsd_errors(export_plcopen(project)) == []


def test_document_header_names_the_project_and_the_time():
    data = export_plcopen(Project(name="plant 1"), now=datetime(2025, 3, 4, 5, 6, 7, 890, tzinfo=UTC))
    root = ET.fromstring(data)
    assert data.startswith(b"<?xml version='1.0' encoding='utf-8'?>\n<project ")
    assert root.tag == "{http://www.plcopen.org/xml/tc6_0201}project"
    header = root.find("p:fileHeader", NS)
    assert (header.get("companyName"), header.get("creationDateTime")) == ("LadderLab", "2025-03-04T05:06:07")
    assert root.find("p:contentHeader", NS).get("name") == "plant 1"


@pytest.mark.parametrize(
    "mode, negated, edge",
    [("no", "false", None), ("nc", "true", None), ("p", "false", "rising"), ("n", "false", "falling")],
)
def test_contact_modes(mode, negated, edge):
    """GR-15..18: normally open/closed and transition contacts are PLCopen's negated/edge attributes."""
    root = export(ld(LdNetwork(id="n", elements=[Contact(id="c", var="%IX0.1", mode=mode)])))
    contact = only(root, "contact")
    assert (contact.get("negated"), contact.get("edge"), contact.get("storage")) == (negated, edge, None)
    assert contact.find("p:variable", NS).text == "%IX0.1"
    assert sources(root, contact) == [("leftPowerRail", None)]
    assert sources(root, only(root, "rightPowerRail")) == [("contact", None)]


@pytest.mark.parametrize(
    "mode, attrs",
    [
        ("normal", {}),
        ("negated", {"negated": "true"}),
        ("set", {"storage": "set"}),
        ("reset", {"storage": "reset"}),
        ("p", {"edge": "rising"}),
        ("n", {"edge": "falling"}),
    ],
)
def test_coil_modes(mode, attrs):
    """GR-20..25: negated, set, reset and transition coils."""
    root = export(ld(LdNetwork(id="n", elements=[Contact(id="c", var="a"), Coil(id="q", var="Out", mode=mode)])))
    coil = only(root, "coil")
    assert {k: v for k, v in coil.attrib.items() if k in ("negated", "storage", "edge") and v != "false"} == attrs
    assert sources(root, coil) == [("contact", None)]


def test_parallel_branches_are_several_connections_on_one_input():
    """The wired OR: Motor := (Start OR Motor) AND NOT Stop - the Stop contact lists both branch ends."""
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Parallel(id="p", branches=[[Contact(id="a", var="Start")], [Contact(id="b", var="Motor")]]),
                    Contact(id="s", var="Stop", mode="nc"),
                    Coil(id="m", var="Motor"),
                ],
            )
        )
    )
    contacts = body(root).findall("p:contact", NS)
    assert [c.find("p:variable", NS).text for c in contacts] == ["Start", "Motor", "Stop"]
    assert [sources(root, c) for c in contacts] == [[("leftPowerRail", None)]] * 2 + [[("contact", None)] * 2]
    refs = [c.get("refLocalId") for c in contacts[2].findall(".//p:connection", NS)]
    assert refs == [contacts[0].get("localId"), contacts[1].get("localId")]


def test_compare_contact_is_a_comparison_block_with_en_on_the_rung_and_out_continuing_it():
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Contact(id="c", var="run"),
                    Compare(id="k", op="GE", left="Level", right="100"),
                    Coil(id="q", var="Full"),
                ],
            )
        )
    )
    block = only(root, "block")
    assert block.get("typeName") == "GE" and block.get("instanceName") is None
    assert [v.get("formalParameter") for v in block.findall("p:inputVariables/p:variable", NS)] == ["EN", "IN1", "IN2"]
    assert sources(root, block, "EN") == [("contact", None)]
    elements = by_id(root)
    operands = [
        elements[c.get("refLocalId")].find("p:expression", NS).text
        for pin in ("IN1", "IN2")
        for c in block.findall(f".//p:variable[@formalParameter='{pin}']//p:connection", NS)
    ]
    assert operands == ["Level", "100"]
    assert sources(root, only(root, "coil")) == [("block", "OUT")]


def test_box_without_en_takes_power_on_its_first_bool_input_and_passes_it_from_its_first_bool_output():
    """TON: power enters IN and leaves from Q; PT is an inVariable; ET writes an outVariable."""
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Contact(id="c", var="go"),
                    Box(id="t", call="TON", instance="T1", inputs={"PT": "T#5s"}, outputs={"ET": "Elapsed"}),
                    Coil(id="q", var="Done"),
                ],
            )
        )
    )
    block = only(root, "block")
    assert (block.get("typeName"), block.get("instanceName")) == ("TON", "T1")
    assert [v.get("formalParameter") for v in block.findall("p:inputVariables/p:variable", NS)] == ["IN", "PT"]
    assert [v.get("formalParameter") for v in block.findall("p:outputVariables/p:variable", NS)] == ["Q", "ET"]
    assert sources(root, block, "IN") == [("contact", None)] and sources(root, block, "PT") == [("inVariable", None)]
    assert sources(root, only(root, "coil")) == [("block", "Q")]
    out = only(root, "outVariable")
    assert out.find("p:expression", NS).text == "Elapsed" and sources(root, out) == [("block", "ET")]


def test_box_with_en_uses_en_and_eno():
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Contact(id="c", var="go"),
                    Box(id="a", call="ADD", en=True, inputs={"IN1": "x", "IN2": "1"}, outputs={"OUT": "x"}),
                    Coil(id="q", var="ok"),
                ],
            )
        )
    )
    block = only(root, "block")
    assert [v.get("formalParameter") for v in block.findall("p:inputVariables/p:variable", NS)] == ["EN", "IN1", "IN2"]
    assert [v.get("formalParameter") for v in block.findall("p:outputVariables/p:variable", NS)] == ["ENO", "OUT"]
    assert sources(root, block, "EN") == [("contact", None)] and sources(root, only(root, "coil")) == [("block", "ENO")]


def test_series_list_on_a_box_input_is_a_contact_chain_from_the_left_rail():
    """CTU: power enters CU; R is fed by its own contacts from the rail (the model's series-list input)."""
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Contact(id="c", var="pulse", mode="p"),
                    Box(
                        id="k",
                        call="CTU",
                        instance="C1",
                        inputs={"R": [Contact(id="r1", var="reset"), Contact(id="r2", var="enable")], "PV": "10"},
                    ),
                    Coil(id="q", var="full"),
                ],
            )
        )
    )
    block = only(root, "block")
    contacts = {c.find("p:variable", NS).text: c for c in body(root).findall("p:contact", NS)}
    assert sources(root, block, "CU") == [("contact", None)]
    assert sources(root, contacts["reset"]) == [("leftPowerRail", None)]
    assert sources(root, contacts["enable"]) == [("contact", None)]
    r_ref = block.find(".//p:variable[@formalParameter='R']//p:connection", NS).get("refLocalId")
    assert r_ref == contacts["enable"].get("localId")


def test_jump_label_and_return():
    root = export(
        ld(
            LdNetwork(id="a", elements=[Contact(id="c", var="skip"), Jump(id="j", target="Done")]),
            LdNetwork(id="b", elements=[Contact(id="d", var="stop"), Return(id="r")]),
            LdNetwork(id="z", label="Done", comment="the end", elements=[Coil(id="q", var="x")]),
        )
    )
    assert only(root, "jump").get("label") == "Done"
    assert sources(root, only(root, "jump")) == [("contact", None)]
    assert sources(root, only(root, "return")) == [("contact", None)]
    label, comment = only(root, "label"), only(root, "comment")
    assert label.get("label") == "Done" and comment.find(f"p:content/{XHTML}p", NS).text == "the end"
    coil_y = float(only(root, "coil").find("p:position", NS).get("y"))
    assert float(comment.find("p:position", NS).get("y")) < float(label.find("p:position", NS).get("y")) < coil_y


def test_execution_order_follows_evaluation_order():
    """Left to right, branches top to bottom, a box's input chains before the box."""
    root = export(
        ld(
            LdNetwork(
                id="n",
                elements=[
                    Parallel(id="p", branches=[[Contact(id="a", var="a")], [Contact(id="b", var="b")]]),
                    Box(id="k", call="CTU", instance="C1", inputs={"R": [Contact(id="r", var="r")], "PV": "3"}),
                    Coil(id="q", var="q"),
                ],
            )
        )
    )
    executed = sorted(
        (
            int(e.get("executionOrderId")),
            e.find("p:variable", NS).text if e.find("p:variable", NS) is not None else e.get("typeName"),
        )
        for e in body(root)
        if e.get("executionOrderId")
    )
    assert [name for _, name in executed] == ["a", "b", "r", "CTU", "q"]


def test_elements_are_drawn_inside_their_networks_band():
    root = export(
        ld(
            LdNetwork(
                id="one",
                elements=[
                    Parallel(id="p", branches=[[Contact(id="a", var="a")], [Contact(id="b", var="b")]]),
                    Coil(id="q", var="q"),
                ],
            ),
            LdNetwork(id="two", elements=[Contact(id="c", var="c"), Coil(id="r", var="r")]),
        )
    )
    ys = {
        e.find("p:variable", NS).text: float(e.find("p:position", NS).get("y"))
        for e in body(root)
        if e.find("p:variable", NS) is not None
    }
    xs = {
        e.find("p:variable", NS).text: float(e.find("p:position", NS).get("x"))
        for e in body(root)
        if e.find("p:variable", NS) is not None
    }
    assert ys["a"] < ys["b"] < ys["c"] and ys["a"] == ys["q"] and xs["a"] == xs["b"] < xs["q"]


def test_fbd_nodes_and_wires_map_one_to_one():
    network = FbdNetwork(
        id="n",
        nodes=[
            InputNode(id="x", expr="Speed", pos=Position(x=10, y=20)),
            Block(id="g", call="GT", pos=Position(x=120.5, y=20), pins={"IN1": PinFlags(negated=True)}),
            InputNode(id="lim", expr="50", pos=Position(x=10, y=60)),
            OutputNode(id="o", var="Fast", mode="set", pos=Position(x=250, y=20)),
        ],
        wires=[
            Wire(from_=PinRef(node="x", pin="OUT"), to=PinRef(node="g", pin="IN1")),
            Wire(from_=PinRef(node="lim", pin="OUT"), to=PinRef(node="g", pin="IN2")),
            Wire(from_=PinRef(node="g", pin="OUT"), to=PinRef(node="o", pin="IN")),
        ],
    )
    root = export(Pou(name="Main", kind="program", language="fbd", body=FbdBody(networks=[network])))
    fbd = body(root, "FBD")
    assert [e.tag.split("}")[1] for e in fbd] == ["inVariable", "block", "inVariable", "outVariable"]
    block = fbd.find("p:block", NS)
    assert block.find("p:position", NS).attrib == {"x": "120.5", "y": "20"}
    assert block.find(".//p:variable[@formalParameter='IN1']", NS).get("negated") == "true"
    assert fbd.find("p:outVariable", NS).get("storage") == "set"
    elements = {e.get("localId"): e for e in fbd}
    conns = [
        (elements[c.get("refLocalId")].find("p:expression", NS).text, pin)
        for pin in ("IN1", "IN2")
        for c in block.findall(f".//p:variable[@formalParameter='{pin}']//p:connection", NS)
    ]
    assert conns == [("Speed", "IN1"), ("50", "IN2")]
    out_conn = fbd.find("p:outVariable/p:connectionPointIn/p:connection", NS)
    assert (out_conn.get("refLocalId"), out_conn.get("formalParameter")) == (block.get("localId"), "OUT")
    orders = {
        e.find("p:expression", NS).text if e.find("p:expression", NS) is not None else e.get("typeName"): int(
            e.get("executionOrderId")
        )
        for e in fbd
    }
    assert orders["GT"] < orders["Fast"]


def test_st_body_types_globals_and_tasks_go_in_their_sections():
    project = dict(
        types="TYPE\n    Mode : (Off, Auto := 5);\nEND_TYPE",
        globals="VAR_GLOBAL CONSTANT\n    Limit : INT := 10;\nEND_VAR",
        tasks=[Task(name="Fast", interval="T#5ms", priority=2, programs=["Main"])],
    )
    root = export(
        Pou(
            name="Main",
            kind="program",
            language="st",
            declarations="VAR_INPUT\n    a : BOOL;\nEND_VAR",
            body="x := a < b;\r\ny := 1;",
        ),
        **project,
    )
    st = root.find("p:types/p:pous/p:pou/p:body/p:ST", NS)
    assert st.find(f"{XHTML}p").text == "x := a < b;\r\ny := 1;"
    (data_type,) = root.findall("p:types/p:dataTypes/p:dataType", NS)
    assert data_type.get("name") == "Mode"
    assert [(v.get("name"), v.get("value")) for v in data_type.findall(".//p:value", NS)] == [
        ("Off", None),
        ("Auto", "5"),
    ]
    config = root.find("p:instances/p:configurations/p:configuration", NS)
    (globals_,) = config.findall("p:globalVars", NS)
    assert globals_.get("constant") == "true"
    assert globals_.find("p:variable/p:initialValue/p:simpleValue", NS).get("value") == "10"
    task = config.find("p:resource/p:task", NS)
    assert (task.get("name"), task.get("interval"), task.get("priority")) == ("Fast", "T#5ms", "2")
    assert task.find("p:pouInstance", NS).attrib == {"name": "Main", "typeName": "Main"}
    (inputs,) = root.findall("p:types/p:pous/p:pou/p:interface/p:inputVars", NS)
    assert inputs.find("p:variable", NS).get("name") == "a"


def test_a_carriage_return_survives_the_xml_parser():
    data = export_plcopen(Project(name="t", pous=[Pou(name="M", kind="program", language="st", body="a;\r\nb;")]))
    assert b"a;&#13;\nb;" in data


def test_declarations_that_do_not_parse_stop_the_export_with_a_located_error():
    pou = Pou(name="Main", kind="program", language="st", declarations="VAR\n    x : INT\n    y : INT;\nEND_VAR")
    with pytest.raises(PlcopenExportError) as caught:
        export_plcopen(Project(name="t", pous=[pou]))
    (problem,) = caught.value.diagnostics
    assert (problem.code, problem.pou, problem.line) == ("ST-PARSE", "Main", 2)


def test_a_priority_plcopen_cannot_hold_is_an_export_error():
    with pytest.raises(PlcopenExportError) as caught:
        export_plcopen(Project(name="t", tasks=[Task(name="T", priority=70000)]))
    assert [(d.code, d.json_path, d.message) for d in caught.value.diagnostics] == [
        ("PLCOPEN-EXPORT", "$.tasks[0].priority", "task T: PLCopen priorities are 0..65535, not 70000")
    ]


def test_a_wire_to_a_missing_node_is_an_export_error_not_dropped():
    network = FbdNetwork(
        id="n",
        nodes=[OutputNode(id="o", var="q")],
        wires=[Wire(from_=PinRef(node="ghost", pin="OUT"), to=PinRef(node="o", pin="IN"))],
    )
    with pytest.raises(PlcopenExportError) as caught:
        export_plcopen(
            Project(name="t", pous=[Pou(name="M", kind="program", language="fbd", body=FbdBody(networks=[network]))])
        )
    assert caught.value.diagnostics[0].message == "a wire names the node 'ghost', which this network does not have"
