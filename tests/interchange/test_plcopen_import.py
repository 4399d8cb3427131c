"""PLCopen XML -> project, construct by construct (issue 8: import of LD graphs, FBD, ST, declarations, sections).

Documents are written here the way Beremiz, OpenPLC and RuSTy write them (no
LadderLab addData), so these tests cover what the importer derives from the
graph alone.
"""

from __future__ import annotations

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import (
    Block,
    Box,
    Compare,
    InputNode,
    OutputNode,
    Parallel,
    PinFlags,
    ProgramInstance,
    Task,
)
from tests.interchange.plcopen_helpers import fbd_project, ld_project, pou_xml, project_xml


def pos(x: float, y: float) -> str:
    return f'<position x="{x}" y="{y}"/>'


def cin(*refs: str) -> str:
    """A connectionPointIn with connections: "5" or "5.Q" (source localId and pin)."""
    parts = []
    for ref in refs:
        local_id, _, pin = ref.partition(".")
        param = f' formalParameter="{pin}"' if pin else ""
        parts.append(f'<connection refLocalId="{local_id}"{param}/>')
    return f"<connectionPointIn>{''.join(parts)}</connectionPointIn>"


def rail(local_id: int = 1) -> str:
    return f'<leftPowerRail localId="{local_id}">{pos(0, 0)}<connectionPointOut formalParameter=""/></leftPowerRail>'


def contact(local_id: int, var: str, *refs: str, x: float, y: float, attrs: str = "") -> str:
    return (
        f'<contact localId="{local_id}" {attrs}>{pos(x, y)}{cin(*refs)}<connectionPointOut/>'
        f"<variable>{var}</variable></contact>"
    )


def coil(local_id: int, var: str, *refs: str, x: float, y: float, attrs: str = "") -> str:
    return (
        f'<coil localId="{local_id}" {attrs}>{pos(x, y)}{cin(*refs)}<connectionPointOut/>'
        f"<variable>{var}</variable></coil>"
    )


def in_var(local_id: int, expr: str, x: float, y: float, attrs: str = "") -> str:
    return (
        f'<inVariable localId="{local_id}" {attrs}>{pos(x, y)}<connectionPointOut/>'
        f"<expression>{expr}</expression></inVariable>"
    )


def out_var(local_id: int, expr: str, *refs: str, x: float, y: float, attrs: str = "") -> str:
    return (
        f'<outVariable localId="{local_id}" {attrs}>{pos(x, y)}{cin(*refs)}'
        f"<expression>{expr}</expression></outVariable>"
    )


def block(
    local_id: int,
    type_name: str,
    inputs: dict[str, tuple[str, ...]],
    outputs: list[str],
    *,
    x: float,
    y: float,
    instance: str | None = None,
    order: int | None = None,
) -> str:
    head = f'<block localId="{local_id}" typeName="{type_name}"'
    head += f' instanceName="{instance}"' if instance else ""
    head += f' executionOrderId="{order}"' if order is not None else ""
    ins = "".join(f'<variable formalParameter="{pin}">{cin(*refs)}</variable>' for pin, refs in inputs.items())
    outs = "".join(f'<variable formalParameter="{pin}"><connectionPointOut/></variable>' for pin in outputs)
    return (
        f"{head}>{pos(x, y)}<inputVariables>{ins}</inputVariables><inOutVariables/>"
        f"<outputVariables>{outs}</outputVariables></block>"
    )


def imported(data: bytes):
    result = import_plcopen(data)
    assert result.project is not None
    return result


def elements(data: bytes) -> list:
    result = imported(data)
    assert [d.format() for d in result.diagnostics] == []
    (network,) = result.project.pous[0].body.networks
    return network.elements


def name(node) -> str:
    """An FBD node by what it is: ``SEL``, ``in:a``, ``out:Cnt``, ``jump:lbl``, ``return``."""
    if isinstance(node, Block):
        return node.call
    if isinstance(node, InputNode):
        return f"in:{node.expr}"
    if isinstance(node, OutputNode):
        return f"out:{node.var}"
    return f"jump:{node.target}" if hasattr(node, "target") else node.type


def wires(network) -> set[tuple[str, str, str, str]]:
    """The network's wires between named nodes (names must be unique in the network)."""
    names = {n.id: name(n) for n in network.nodes}
    assert len(set(names.values())) == len(names), names
    return {(names[w.from_.node], w.from_.pin, names[w.to.node], w.to.pin) for w in network.wires}


def shape(items: list) -> list:
    """An LD series list without ids, for comparison."""
    out = []
    for item in items:
        if isinstance(item, Parallel):
            out.append(("OR", [shape(b) for b in item.branches]))
        elif isinstance(item, Box):
            inputs = {k: shape(v) if isinstance(v, list) else v for k, v in item.inputs.items()}
            out.append((item.call, item.instance, item.en, inputs, item.outputs))
        elif isinstance(item, Compare):
            out.append((item.op, item.left, item.right))
        else:
            out.append((item.type, getattr(item, "var", None), getattr(item, "mode", None)))
    return out


# ------------------------------------------------------------------ LD


def test_several_connections_on_one_input_are_a_parallel():
    """The wired OR of GR-14: (Start OR Motor) AND NOT Stop -> Motor."""
    data = ld_project(
        rail()
        + contact(2, "Start", "1", x=50, y=10)
        + contact(3, "Motor", "1", x=50, y=50)
        + contact(4, "Stop", "2", "3", x=120, y=10, attrs='negated="true"')
        + coil(5, "Motor", "4", x=200, y=10)
    )
    assert shape(elements(data)) == [
        ("OR", [[("contact", "Start", "no")], [("contact", "Motor", "no")]]),
        ("contact", "Stop", "nc"),
        ("coil", "Motor", "normal"),
    ]


def test_branches_are_ordered_top_to_bottom_whatever_the_document_order():
    data = ld_project(
        rail()
        + contact(3, "Lower", "1", x=50, y=90)
        + contact(2, "Upper", "1", x=50, y=10)
        + coil(4, "q", "2", "3", x=200, y=10)
    )
    assert shape(elements(data))[0] == ("OR", [[("contact", "Upper", "no")], [("contact", "Lower", "no")]])


def test_a_bridge_is_refused_with_a_diagnostic_naming_its_elements():
    """a feeds x and d, b feeds c, and x also feeds c: the rung is not series-parallel."""
    data = ld_project(
        rail()
        + contact(2, "a", "1", x=50, y=10)
        + contact(3, "b", "1", x=50, y=50)
        + contact(4, "x", "2", x=120, y=30)
        + coil(5, "c", "3", "4", x=200, y=50)
        + coil(6, "d", "2", x=200, y=10)
    )
    result = imported(data)
    (problem,) = result.diagnostics
    assert (problem.code, problem.severity, problem.pou) == ("PLCOPEN-LD-BRIDGE", "error", "Main")
    assert problem.message == (
        "the rung is not series-parallel (a bridge): coil c (localId 5), coil d (localId 6), contact a (localId 2), "
        "contact b (localId 3), contact x (localId 4) cannot be written as series and parallel branches; the network "
        "is left empty"
    )
    assert result.project.pous[0].body.networks[0].elements == []


def test_openplc_timer_chain_with_en_and_a_coil_on_an_output():
    """OpenPLC's Blink: TON/TOF with EN on the rung, IN fed by a contact and by TON0.Q, the coil on TOF0.Q.
    Issue 28: the EN/ENO chain starts at the left rail, so both FBs always run (an FB's ENO is its EN) and the
    rung reads left to right as drawn - contact, TON, TOF, coil - with the power through IN and Q."""
    data = ld_project(
        rail()
        + block(3, "TON", {"EN": ("1",), "IN": ("5",), "PT": ("7",)}, ["ENO", "Q", "ET"], x=350, y=130, instance="TON0")
        + block(
            4,
            "TOF",
            {"EN": ("3.ENO",), "IN": ("3.Q",), "PT": ("8",)},
            ["ENO", "Q", "ET"],
            x=640,
            y=130,
            instance="TOF0",
        )
        + contact(5, "blink_led", "1", x=180, y=200, attrs='negated="true"')
        + coil(6, "blink_led", "4.Q", x=820, y=200)
        + in_var(7, "T#500ms", 240, 230)
        + in_var(8, "T#500ms", 520, 230)
        + '<rightPowerRail localId="2">'
        + pos(990, 110)
        + cin("4.ENO")
        + cin("6")
        + "</rightPowerRail>"
    )
    assert shape(elements(data)) == [
        ("contact", "blink_led", "nc"),
        ("TON", "TON0", False, {"PT": "T#500ms"}, {}),
        ("TOF", "TOF0", False, {"PT": "T#500ms"}, {}),
        ("coil", "blink_led", "normal"),
    ]


def test_an_en_chain_that_does_not_start_at_the_rail_keeps_en():
    """The same drawing with a contact in front of TON's EN: EN decides whether the FBs run, so it stays."""
    data = ld_project(
        rail()
        + contact(9, "go", "1", x=100, y=130)
        + block(3, "TON", {"EN": ("9",), "IN": ("5",), "PT": ("7",)}, ["ENO", "Q", "ET"], x=350, y=130, instance="TON0")
        + contact(5, "blink_led", "1", x=180, y=200, attrs='negated="true"')
        + in_var(7, "T#500ms", 240, 230)
        + '<rightPowerRail localId="2">'
        + pos(990, 110)
        + cin("3.ENO")
        + "</rightPowerRail>"
    )
    assert shape(elements(data)) == [
        ("contact", "go", "no"),
        ("TON", "TON0", True, {"IN": [("contact", "blink_led", "nc")], "PT": "T#500ms"}, {}),
    ]


def test_a_comparison_block_whose_out_drives_the_rung_is_a_compare_contact():
    data = ld_project(
        rail()
        + in_var(2, "socket_id", 10, 60)
        + in_var(3, "0", 10, 90)
        + block(4, "LT", {"EN": ("1",), "IN1": ("2",), "IN2": ("3",)}, ["ENO", "OUT"], x=100, y=30)
        + coil(5, "connected", "4.OUT", x=200, y=30, attrs='storage="reset"')
    )
    assert shape(elements(data)) == [("LT", "socket_id", "0"), ("coil", "connected", "reset")]


def test_a_function_feeding_only_another_blocks_input_is_written_inline():
    data = ld_project(
        rail()
        + in_var(2, "minute_count", 10, 60)
        + block(3, "INT_TO_DINT", {"IN": ("2",)}, ["OUT"], x=60, y=60)
        + block(4, "ADD", {"EN": ("1",), "IN1": ("3.OUT",), "IN2": ("5",)}, ["ENO", "OUT"], x=150, y=30)
        + in_var(5, "1", 100, 100)
        + out_var(6, "total", "4.OUT", x=250, y=60)
    )
    assert shape(elements(data)) == [
        ("ADD", None, True, {"IN1": "INT_TO_DINT(IN := minute_count)", "IN2": "1"}, {"OUT": "total"})
    ]


def test_a_counter_takes_power_on_cu_and_its_reset_from_its_own_contacts():
    data = ld_project(
        rail()
        + contact(2, "pulse", "1", x=50, y=10, attrs='edge="rising"')
        + contact(3, "clear", "1", x=50, y=50)
        + block(4, "CTU", {"CU": ("2",), "R": ("3",), "PV": ("5",)}, ["Q", "CV"], x=150, y=10, instance="C1")
        + in_var(5, "10", 100, 90)
        + coil(6, "full", "4.Q", x=250, y=10)
        + out_var(7, "count", "4.CV", x=250, y=50)
    )
    assert shape(elements(data)) == [
        ("contact", "pulse", "p"),
        ("CTU", "C1", False, {"R": [("contact", "clear", "no")], "PV": "10"}, {"CV": "count"}),
        ("coil", "full", "normal"),
    ]


def test_a_vendor_block_runs_unconditionally_with_its_power_input_as_a_contact_chain():
    """MQTT_CONNECT is unknown: its CONNECT pin keeps the contacts feeding it, SUCCESS drives the coil."""
    data = ld_project(
        rail()
        + contact(2, "connected", "1", x=50, y=10, attrs='negated="true"')
        + block(3, "MQTT_CONNECT", {"CONNECT": ("2",), "PORT": ("4",)}, ["SUCCESS"], x=150, y=10, instance="M0")
        + in_var(4, "1883", 100, 50)
        + coil(5, "connected", "3.SUCCESS", x=250, y=10)
    )
    assert shape(elements(data)) == [
        (
            "OR",
            [
                [("MQTT_CONNECT", "M0", True, {"CONNECT": [("contact", "connected", "nc")], "PORT": "1883"}, {})],
                [("contact", "M0.SUCCESS", "no"), ("coil", "connected", "normal")],
            ],
        )
    ]


def test_variables_in_a_rung_become_contacts_coils_or_a_move():
    """A variable feeding the power flow is a contact; an outVariable fed by power a coil; value to variable a MOVE."""
    data = ld_project(
        in_var(2, "ready", 0, 10, attrs='negated="true"')
        + coil(3, "lamp", "2", x=100, y=10)
        + rail(6)
        + contact(7, "on", "6", x=50, y=40)
        + out_var(8, "busy", "7", x=100, y=40)
        + in_var(4, "Setpoint", 0, 80)
        + out_var(5, "Target", "4", x=100, y=80)
    )
    result = imported(data)
    assert [d.format() for d in result.diagnostics] == []
    networks = result.project.pous[0].body.networks
    assert [shape(n.elements) for n in networks] == [
        [("contact", "ready", "nc"), ("coil", "lamp", "normal")],
        [("contact", "on", "no"), ("coil", "busy", "normal")],
        [("MOVE", None, True, {"IN": "Setpoint"}, {"OUT": "Target"})],
    ]


def test_connected_parts_are_networks_top_to_bottom_with_labels_and_comment_networks():
    """Issue 28: a free comment box is a comment network of its own where it stands, never merged into a rung."""
    data = ld_project(
        rail()
        + '<comment localId="9" height="20" width="100">'
        + pos(0, 90)
        + "<content><xhtml:p>second rung</xhtml:p></content></comment>"
        + '<label localId="8" label="Again">'
        + pos(0, 95)
        + "</label>"
        + contact(4, "b", "1", x=50, y=100)
        + coil(5, "q2", "4", x=150, y=100)
        + contact(2, "a", "1", x=50, y=10)
        + coil(3, "q1", "2", x=150, y=10)
    )
    result = imported(data)
    networks = result.project.pous[0].body.networks
    assert [(n.id, n.label, n.comment, shape(n.elements)) for n in networks] == [
        ("network1", None, None, [("contact", "a", "no"), ("coil", "q1", "normal")]),
        ("network2", None, "second rung", []),
        ("network3", "Again", None, [("contact", "b", "no"), ("coil", "q2", "normal")]),
    ]
    assert [[e.id for e in n.elements] for n in networks] == [["contact1", "coil1"], [], ["contact2", "coil2"]]


def test_connector_and_continuation_join_a_rung():
    data = ld_project(
        rail()
        + contact(2, "a", "1", x=50, y=10)
        + '<connector localId="3" name="c1">'
        + pos(100, 10)
        + cin("2")
        + "</connector>"
        + '<continuation localId="4" name="c1">'
        + pos(0, 60)
        + "<connectionPointOut/></continuation>"
        + coil(5, "q", "4", x=150, y=60)
    )
    assert shape(elements(data)) == [("contact", "a", "no"), ("coil", "q", "normal")]


def test_an_element_without_power_input_is_reported():
    result = imported(ld_project(coil(2, "q", x=10, y=10)))
    (problem,) = result.diagnostics
    assert (problem.code, problem.element, problem.message) == (
        "PLCOPEN-LD",
        "localId 2",
        "this element has no power input; it is read as fed from the left rail",
    )


# ------------------------------------------------------------------ FBD


COUNTER_FBD = (
    in_var(1, "Reset", 0, 0)
    + in_var(2, "ResetCounterValue", 0, 40)
    + in_var(3, "1", 0, 80)
    + block(4, "SEL", {"G": ("1",), "IN0": ("5.OUT",), "IN1": ("2",)}, ["OUT"], x=200, y=0)
    + block(5, "ADD", {"IN1": ("3",), "IN2": ("6",)}, ["OUT"], x=100, y=60)
    + '<inOutVariable localId="6">'
    + pos(150, 120)
    + cin("4.OUT")
    + "<connectionPointOut/>"
    "<expression>Cnt</expression></inOutVariable>" + out_var(7, "OUT", "6", x=300, y=120)
)


def test_in_out_variable_feedback_reads_the_variable_and_other_readers_the_new_value():
    """Beremiz CounterFBD: Cnt := SEL(Reset, ADD(1, Cnt), ResetCounterValue); OUT := Cnt.

    ADD feeds the writer of Cnt, so it reads the variable (last scan's value); OUT is wired to SEL's result."""
    result = imported(fbd_project(COUNTER_FBD))
    assert [d.format() for d in result.diagnostics] == []
    (network,) = result.project.pous[0].body.networks
    assert wires(network) == {
        ("in:Reset", "OUT", "SEL", "G"),
        ("ADD", "OUT", "SEL", "IN0"),
        ("in:ResetCounterValue", "OUT", "SEL", "IN1"),
        ("in:1", "OUT", "ADD", "IN1"),
        ("in:Cnt", "OUT", "ADD", "IN2"),
        ("SEL", "OUT", "out:Cnt", "IN"),
        ("SEL", "OUT", "out:OUT", "IN"),
    }


CFC_JUMP = (
    in_var(1, "TRUE", 0, 0)
    + out_var(2, "x", "1", x=100, y=0, attrs='executionOrderId="0"')
    + in_var(3, "x", 0, 40)
    + '<jump localId="4" label="lbl" executionOrderId="1">'
    + pos(100, 40)
    + cin("3")
    + "</jump>"
    + in_var(5, "2", 0, 80)
    + out_var(6, "a", "5", x=100, y=80, attrs='executionOrderId="2"')
    + '<label localId="7" label="lbl" executionOrderId="3">'
    + pos(300, 0)
    + "</label>"
    + in_var(8, "a + 3", 300, 40)
    + out_var(9, "a", "8", x=400, y=40, attrs='executionOrderId="4"')
)


def test_cfc_execution_order_cuts_networks_at_labels_and_after_jumps():
    """RuSTy's jump_true: x := TRUE; jump if x; a := 2 (skipped); lbl: a := a + 3 - a jump leaves at once."""
    result = imported(fbd_project(CFC_JUMP))
    networks = result.project.pous[0].body.networks
    names = [{n.id: name(n) for n in network.nodes} for network in networks]
    assert [(n.label, [names[i][node] for node in n.order]) for i, n in enumerate(networks)] == [
        (None, ["out:x", "jump:lbl"]),
        (None, ["out:a"]),
        ("lbl", ["out:a"]),
    ]
    assert [wires(n) for n in networks] == [
        {("in:TRUE", "OUT", "out:x", "IN"), ("in:x", "OUT", "jump:lbl", "IN")},
        {("in:2", "OUT", "out:a", "IN")},
        {("in:a + 3", "OUT", "out:a", "IN")},
    ]


def test_a_return_negated_in_bachmann_add_data_gets_a_not_block():
    data = fbd_project(
        in_var(1, "val = 5", 0, 0)
        + '<return localId="2" executionOrderId="0">'
        + pos(100, 0)
        + cin("1")
        + '<addData><data name="www.bachmann.at/plc/plcopenxml" '
        'handleUnknown="implementation"><negated value="true"/></data></addData></return>'
    )
    result = imported(data)
    assert [d.format() for d in result.diagnostics] == []
    (network,) = result.project.pous[0].body.networks
    assert wires(network) == {("in:val = 5", "OUT", "NOT", "IN"), ("NOT", "OUT", "return", "IN")}


def test_rusty_pin_names_become_the_projects():
    """A function's result pin named after the function is OUT; unnamed SEL pins take SEL's names."""
    data = fbd_project(
        in_var(1, "a > b", 0, 0)
        + in_var(2, "a", 0, 30)
        + in_var(3, "b", 0, 60)
        + block(4, "SEL", {"": ("1",)}, [""], x=100, y=0).replace(
            "</inputVariables>",
            f'<variable formalParameter="">{cin("2")}</variable>'
            f'<variable formalParameter="">{cin("3")}</variable></inputVariables>',
        )
        + block(5, "myAdd", {"a": ("4",), "b": ("3",)}, ["myAdd"], x=200, y=0)
        + out_var(6, "y", "5.myAdd", x=300, y=0)
    )
    (network,) = imported(data).project.pous[0].body.networks
    names = {n.id: name(n) for n in network.nodes}
    assert {(names[w.from_.node], w.from_.pin, names[w.to.node], w.to.pin) for w in network.wires} == {
        ("in:a > b", "OUT", "SEL", "G"),
        ("in:a", "OUT", "SEL", "IN0"),
        ("in:b", "OUT", "SEL", "IN1"),
        ("SEL", "OUT", "myAdd", "a"),
        ("in:b", "OUT", "myAdd", "b"),
        ("myAdd", "OUT", "out:y", "IN"),
    }


def test_a_wire_between_networks_is_reported():
    data = fbd_project(
        in_var(1, "x", 0, 0)
        + '<label localId="2" label="L">'
        + pos(0, 50)
        + "</label>"
        + out_var(3, "y", "4", x=100, y=100)
        + block(4, "NOT", {"IN": ("1",)}, ["OUT"], x=50, y=100)
        + out_var(5, "z", "4", x=100, y=10)
    )
    problems = [(d.code, d.message) for d in imported(data).diagnostics]
    assert problems == [
        ("PLCOPEN-FBD", "the connection from block 4 crosses into another network; use a connector and continuation")
    ]


# ------------------------------------------------------------------ POUs, declarations, sections


INTERFACE = """
<returnType><derived name="Mode"/></returnType>
<inputVars retain="true"><variable name="clk"><type><BOOL/></type>
  <addData><data name="urn:ladderlab:plcopen:1" handleUnknown="discard"><ll:info xmlns:ll="urn:ladderlab:plcopen:1"
  edge="R_EDGE"/></data></addData><documentation><xhtml:p>clock input</xhtml:p></documentation></variable></inputVars>
<localVars constant="true">
  <variable name="table"><type><array><dimension lower="1" upper="3"/><baseType><INT/></baseType></array></type>
    <initialValue><arrayValue><value repetitionValue="2"><simpleValue value="7"/></value><value><simpleValue value="9"/>
    </value></arrayValue></initialValue></variable>
  <variable name="p"><type><derived name="Point"/></type><initialValue><structValue><value member="x">
    <simpleValue value="1"/></value></structValue></initialValue></variable>
  <variable name="s"><type><string length="20"/></type><initialValue><simpleValue value="'hi'"/></initialValue>
  </variable>
  <variable name="r"><type><subrangeSigned><range lower="-5" upper="5"/><baseType><INT/></baseType></subrangeSigned>
  </type></variable>
  <variable name="c"><type><enum><values><value name="Red"/><value name="Green" value="5"/></values></enum></type>
  </variable>
  <variable name="out1" address="%QX0.1"><type><TOD/></type></variable>
  <variable name="ref"><type><pointer><baseType><REAL/></baseType></pointer></type></variable>
</localVars>
<externalVars><variable name="g"><type><LREAL/></type></variable></externalVars>
"""


def test_declarations_are_printed_as_st_from_the_typed_lists():
    result = imported(
        project_xml(
            pou_xml("F", "<xhtml:p>F := Mode#Off;</xhtml:p>", language="ST", interface=INTERFACE, pou_type="function")
        )
    )
    assert [d.format() for d in result.diagnostics] == []
    (pou,) = result.project.pous
    assert (pou.kind, pou.language, pou.return_type, pou.body) == ("function", "st", "Mode", "F := Mode#Off;")
    assert pou.declarations == (
        "VAR_INPUT RETAIN\n"
        "    clk : BOOL R_EDGE; (* clock input *)\n"
        "END_VAR\n"
        "VAR CONSTANT\n"
        "    table : ARRAY [1..3] OF INT := [2(7), 9];\n"
        "    p : Point := (x := 1);\n"
        "    s : STRING[20] := 'hi';\n"
        "    r : INT (-5..5);\n"
        "    c : (Red, Green := 5);\n"
        "    out1 AT %QX0.1 : TOD;\n"
        "    ref : REF_TO REAL;\n"
        "END_VAR\n"
        "VAR_EXTERNAL\n"
        "    g : LREAL;\n"
        "END_VAR"
    )


def test_types_globals_and_tasks_fill_the_project():
    types = (
        '<dataType name="Point"><baseType><struct><variable name="x"><type><INT/></type></variable>'
        '<variable name="y"><type><INT/></type><initialValue><simpleValue value="2"/></initialValue>'
        "</variable></struct></baseType></dataType>"
        '<dataType name="Level"><baseType><subrangeUnsigned><range lower="0" upper="9"/><baseType><USINT/>'
        '</baseType></subrangeUnsigned></baseType><initialValue><simpleValue value="3"/></initialValue>'
        "</dataType>"
    )
    instances = """<instances><configurations><configuration name="C">
      <resource name="R">
        <task name="Fast" priority="3" interval="T#5ms"><pouInstance name="i1" typeName="Main"/></task>
        <task name="OnEvent" priority="1" single="trigger"/>
        <globalVars><variable name="rg"><type><BOOL/></type></variable></globalVars>
        <pouInstance name="loose" typeName="Main"/>
      </resource>
      <globalVars constant="true"><variable name="Max"><type><INT/></type><initialValue><simpleValue value="5"/>
      </initialValue></variable></globalVars>
    </configuration></configurations></instances>"""
    result = imported(
        project_xml(pou_xml("Main", "<xhtml:p></xhtml:p>", language="ST"), instances=instances, data_types=types)
    )
    project = result.project
    assert project.types == (
        "TYPE\n    Point : STRUCT\n        x : INT;\n        y : INT := 2;\n    END_STRUCT;\n"
        "    Level : USINT (0..9) := 3;\nEND_TYPE"
    )
    assert project.globals == "VAR_GLOBAL CONSTANT\n    Max : INT := 5;\nEND_VAR"
    assert project.tasks == []
    config = project.configuration
    assert config.name == "C" and [r.name for r in config.resources] == ["R"]
    (resource,) = config.resources
    assert resource.globals == "VAR_GLOBAL\n    rg : BOOL;\nEND_VAR"
    assert resource.tasks == [
        Task(name="Fast", interval="T#5ms", priority=3, programs=[ProgramInstance(name="i1", type="Main")]),
        Task(name="OnEvent", interval=None, single="trigger", priority=1, programs=[]),
    ]
    assert resource.programs == [ProgramInstance(name="loose", type="Main")]  # runs in the default task
    assert [(d.code, d.severity, d.message) for d in result.diagnostics] == []


def test_configurations_a_project_cannot_hold_are_imported_with_warnings_saying_what_was_made_of_them():
    """A project runs one configuration; a task needs an interval or a single trigger and a numeric priority."""
    instances = """<instances><configurations><configuration name="C">
      <resource name="R">
        <task name="Bare" priority="high"><pouInstance name="i1" typeName="Main"/></task>
      </resource>
    </configuration><configuration name="D"/></configurations></instances>"""
    result = imported(project_xml(pou_xml("Main", "<xhtml:p></xhtml:p>", language="ST"), instances=instances))
    assert [(d.code, d.severity, d.message) for d in result.diagnostics] == [
        (
            "PLCOPEN-CONFIG",
            "warning",
            "2 configurations: a project runs one, so only the first was imported (the globals of all of them were)",
        ),
        (
            "PLCOPEN-CONFIG",
            "warning",
            "task Bare has neither interval nor single; it is imported as a cyclic task of T#10ms",
        ),
        ("PLCOPEN-CONFIG", "warning", "task Bare: priority 'high' is not a number; 0 is used"),
    ]
    (resource,) = result.project.configuration.resources
    assert resource.tasks == [
        Task(name="Bare", interval="T#10ms", priority=0, programs=[ProgramInstance(name="i1", type="Main")])
    ]


def test_sfc_and_il_pous_import_actions_outside_sfc_and_foreign_add_data_are_reported_not_dropped_silently():
    """SFC imports as a chart (issue 24), IL as IL text kept as written (issue 26)."""
    pous = (
        pou_xml(
            "Seq",
            "<step localId='1' name='Init' initialStep='true'>" + pos(0, 0) + "</step>"
            "<step localId='2' name='Run'>" + pos(0, 40) + "</step>",
            language="SFC",
            pou_type="functionBlock",
        )
        + pou_xml("Asm", "<xhtml:p>LD TRUE\n(* keep *)\nST x</xhtml:p>", language="IL")
        + '<pou name="Main" pouType="program"><actions><action name="Blink"><body><ST><xhtml:p>;</xhtml:p></ST>'
        "</body></action></actions><body><ST><xhtml:p>x := 1;</xhtml:p></ST></body>"
        '<addData><data name="http://vendor.example/pou" handleUnknown="preserve"><v/></data></addData></pou>'
    )
    result = imported(project_xml(pous))
    assert [(d.code, d.pou, d.message) for d in result.diagnostics] == [
        ("PLCOPEN-SFC", "Seq", "step Run is reached from no initial step: it was left out"),
        (
            "PLCOPEN-UNSUPPORTED",
            "Main",
            "action 'Blink' of POU Main was not imported: LadderLab imports an SFC POU's or a function block's "
            "actions with ST bodies",
        ),
        (
            "PLCOPEN-ADDDATA",
            None,
            "addData 'http://vendor.example/pou' (1 place) is another tool's data that "
            "LadderLab cannot carry; it was dropped",
        ),
    ]
    assert all(d.severity == "warning" for d in result.diagnostics)
    seq, asm, main = result.project.pous
    assert (seq.name, seq.kind, seq.language, asm.name, asm.language, main.name) == (
        "Seq",
        "function_block",
        "sfc",
        "Asm",
        "il",
        "Main",
    )
    assert [e.name for e in seq.body.chart.elements] == ["Init"]
    assert asm.body == "LD TRUE\n(* keep *)\nST x"


def test_an_il_function_block_is_imported_as_il_and_runs_for_its_st_caller():
    """Issue 26: the IL body runs (``SEL`` with the accumulator as its selector, IL-04): Out is 1 while Go."""
    interface = (
        "<interface><inputVars><variable name='Go'><type><BOOL/></type></variable></inputVars>"
        "<outputVars><variable name='Out'><type><INT/></type></variable></outputVars></interface>"
    )
    counter = (
        f'<pou name="CounterIL" pouType="functionBlock">{interface}<body><IL><xhtml:p>LD Go\nSEL 0, 1\nST Out'
        "</xhtml:p></IL></body></pou>"
    )
    main = (
        '<pou name="Main" pouType="program"><interface><localVars><variable name="c"><type><derived name="CounterIL"/>'
        '</type></variable><variable name="n"><type><INT/></type></variable></localVars></interface>'
        "<body><ST><xhtml:p>c(Go := TRUE); n := n + 1 + c.Out;</xhtml:p></ST></body></pou>"
    )
    project = imported(project_xml(counter + main)).project
    result = lower_project(project)
    assert [d for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    sim.cycle(3)
    assert (sim.read("Main.n"), sim.read("Main.c.Out")) == (6, 1)


def test_a_single_pou_document_with_a_textual_declaration():
    """RuSTy/Bachmann CFC files: one <pou> root, the interface as ST text in addData."""
    data = b"""<pou xmlns="http://www.plcopen.org/xml/tc6_0201" name="main" pouType="function">
      <interface><localVars/><addData><data name="www.bachmann.at/plc/plcopenxml" handleUnknown="implementation">
      <textDeclaration><content>
FUNCTION main : DINT
VAR
    x: BOOL := FALSE;
END_VAR
      </content></textDeclaration></data></addData></interface>
      <body><FBD/></body></pou>"""
    result = import_plcopen(data, name="cfc")
    assert result.diagnostics == []
    (pou,) = result.project.pous
    assert (result.project.name, pou.name, pou.return_type, pou.declarations) == (
        "cfc",
        "main",
        "DINT",
        "VAR\nx: BOOL := FALSE;\nEND_VAR",
    )


def test_tc6_2_00_documents_are_read_as_2_01():
    data = b"""<project xmlns="http://www.plcopen.org/xml/tc6_0200"><types><pous>
      <pou name="P" pouType="program"><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">y := 1;</xhtml></ST>
      </body></pou></pous></types></project>"""
    result = import_plcopen(data)
    assert [(d.code, d.severity) for d in result.diagnostics] == [("PLCOPEN-VERSION", "warning")]
    assert result.project.pous[0].body == "y := 1;"


@pytest.mark.parametrize("name, expected", [(None, "sample"), ("renamed", "renamed")])
def test_the_project_is_named_after_the_content_header_unless_told(name, expected):
    assert import_plcopen(project_xml(""), name=name).project.name == expected


def test_fbd_pin_modifiers_and_output_modes():
    data = fbd_project(
        in_var(1, "a", 0, 0, attrs='negated="true"')
        + block(2, "AND", {"IN1": ("1",), "IN2": ("1",)}, ["OUT"], x=100, y=0).replace(
            '<variable formalParameter="IN2">', '<variable formalParameter="IN2" edge="rising">'
        )
        + out_var(3, "q", "2.OUT", x=200, y=0, attrs='storage="reset"')
    )
    (network,) = imported(data).project.pous[0].body.networks
    nodes = {name(n): n for n in network.nodes}
    assert list(nodes) == ["AND", "out:q", "in:NOT a"] and nodes["out:q"].mode == "reset"
    assert nodes["AND"].pins == {"IN2": PinFlags(negated=False, edge="rising")}
    assert wires(network) == {
        ("in:NOT a", "OUT", "AND", "IN1"),
        ("in:NOT a", "OUT", "AND", "IN2"),
        ("AND", "OUT", "out:q", "IN"),
    }


def test_a_declaration_the_importer_cannot_read_is_reported_with_its_pou():
    """PLCOPEN-DECL (docs/diagnostics.md): an empty type element is read as BOOL and reported as an error."""
    interface = '<localVars><variable name="x"><type/></variable></localVars>'
    result = import_plcopen(
        project_xml(pou_xml("Main", "<xhtml:p>x := TRUE;</xhtml:p>", language="ST", interface=interface))
    )
    assert [(d.code, d.severity, d.pou, d.message) for d in result.diagnostics] == [
        ("PLCOPEN-DECL", "error", "Main", "a type element is empty; assumed BOOL")
    ]


def test_a_pou_the_importer_cannot_take_as_it_is_is_reported_with_its_pou():
    """PLCOPEN-POU (docs/diagnostics.md), with no external file needed: a FUNCTION without a return type (the
    error of ironplc's plcopen-cdata.xml sample: kept, so its text is not lost, for the user to give it one) and an
    unknown pouType (left out) are errors; the other POUs of the document are imported."""
    result = import_plcopen(
        project_xml(
            pou_xml("Twice", "<xhtml:p>Twice := 2;</xhtml:p>", language="ST", pou_type="function")
            + pou_xml("Thing", "<xhtml:p>x := TRUE;</xhtml:p>", language="ST", pou_type="class")
            + pou_xml("Main", "<xhtml:p></xhtml:p>", language="ST")
        )
    )
    assert [(d.code, d.severity, d.pou, d.message) for d in result.diagnostics] == [
        ("PLCOPEN-POU", "error", "Twice", "function 'Twice' has no return type"),
        (
            "PLCOPEN-POU",
            "error",
            "Thing",
            "POU 'Thing' has pouType 'class'; expected program, functionBlock or function",
        ),
    ]
    assert [(p.name, p.return_type) for p in result.project.pous] == [("Twice", None), ("Main", None)]
