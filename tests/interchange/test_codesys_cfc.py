"""CODESYS CFC POUs in PLCopen XML (issue 25): the chart in the body's addData, read into LadderLab's CFC model.

What real exports look like was read in public files: MatGros/2026_Projet_YGO_ExcavatriceDragage
``TOOLS/ST_PLCOPENXML_GENERATOR/samples_reference_codesys/PRG_CFC_3FB.xml`` (an export of CODESYS V3.5 SP19 Patch 1:
an empty ``<ST>``, the chart in ``.../plcopenxml/cfc``, every wire through an unnamed ``<connector>`` at (0,0)
whose connection names the source pin, boxes with ``cfccalltype`` ``functionblock``, localId 0, grid positions,
unwired inputs listed without a connection, in-out pins); the CFC POU template of the TwinCAT Automation
Interface scripting samples (``Scripting.CSharp.PouTemplates.CFCPOU``: an ``operator`` box ADD with pins
``In1``/``In3``/``Out1``) and SeMdhl/KNX_autogen_9 and SeMdhl/MP-bus_Autogen_4, generators of e!COCKPIT (CODESYS V3)
CFC imports (``mdhl_Knx.h``, ``mdhl_Knx_Items*.h``: comments, ``functionblock`` and ``operator`` boxes, an
operator's result connected with an empty ``formalParameter``). The fixture
tests/interchange/data/codesys_cfc.xml has that structure with LadderLab's own names and logic; the expected values
are worked out by hand in each docstring. What CODESYS does without execution order numbers (its automatic data
flow mode: data flow, then top to bottom, left to right) is from the CODESYS online help, "Automatic Execution
Order by Data Flow" and "Dialog: Properties: CFC Execution Order".
"""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.interchange.plcopen.codesys_cfc import GRID_X, GRID_Y
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.model.cfc import CfcBody
from ladderlab.model.fbd import Block, FbdComment, OutputNode, PinFlags, Position
from ladderlab.simulation.build import build_project
from tests.interchange.plcopen_helpers import project_xml, xsd_errors
from tests.interchange.st_support import same_traces

FIXTURE = Path(__file__).parent / "data" / "codesys_cfc.xml"
EXPECTED_WARNINGS = [
    ("PLCOPEN-VERSION", "the document uses 'http://www.plcopen.org/xml/tc6_0200'; it is read as TC6 v2.01"),
    (
        "PLCOPEN-ADDDATA",
        "addData 'http://www.3s-software.com/plcopenxml/objectid' (3 places) is another tool's data that LadderLab "
        "cannot carry; it was dropped",
    ),
]


def imported(data: bytes | None = None):
    result = import_plcopen(data or FIXTURE.read_bytes())
    assert result.project is not None
    return result


def chart(result, name: str):
    pou = next(p for p in result.project.pous if p.name == name)
    assert pou.language == "cfc" and isinstance(pou.body, CfcBody)
    return pou.body.chart


def test_a_codesys_chart_is_a_cfc_pou_with_its_elements_CFC_01():
    """Every element but the wire points becomes a chart element: the unnamed connectors are gone, each wire runs
    from its source pin (the ADD's Out1 is OUT, its In1/In2 IN1/IN2), CallType and ElementType are understood
    (not reported as dropped), the comment keeps its text."""
    result = imported()
    assert [(d.code, d.message) for d in result.diagnostics] == EXPECTED_WARNINGS
    main = chart(result, "PLC_PRG")
    kinds = [n.type for n in main.nodes]
    assert kinds.count("connector") == 0 and kinds.count("continuation") == 0
    assert kinds == [
        *("comment", "input", "input", "block", "output", "input", "input", "block", "output", "output"),
        *("input", "jump", "input", "output", "label", "input", "input", "input", "block", "output"),
        *("input", "block", "output"),
    ]
    by_id = {n.id: n for n in main.nodes}
    wires = [(by_id[w.from_.node], w.from_.pin, by_id[w.to.node], w.to.pin) for w in main.wires]
    add = next(n for n in main.nodes if isinstance(n, Block) and n.call == "ADD")
    into_add = sorted((src.expr, pin) for src, _, dst, pin in wires if dst is add)
    assert into_add == [("inflow", "IN2"), ("level", "IN1")]
    assert [(pin, dst.var) for src, pin, dst, _ in wires if src is add] == [("OUT", "level")]
    [comment] = [n for n in main.nodes if isinstance(n, FbdComment)]
    assert comment.text == "Fill by inflow; empty once over the limit"


def test_call_types_negations_and_places_are_kept():
    """The CTU is the instance pulses (functionblock) with R negated; F_DOUBLE (function) has no instance and its
    result, written without a pin name, is OUT; notFull is a negated output; places are grid units times GRID_X and GRID_Y
    (the ADD at 12, 2)."""
    main = chart(imported(), "PLC_PRG")
    blocks = {n.call: n for n in main.nodes if isinstance(n, Block)}
    assert (blocks["CTU"].instance, blocks["CTU"].pins) == ("pulses", {"R": PinFlags(negated=True)})
    assert (blocks["F_DOUBLE"].instance, blocks["F_DOUBLE"].pins) == (None, None)
    assert [w.from_.pin for w in main.wires if w.from_.node == blocks["F_DOUBLE"].id] == ["OUT"]
    outputs = {n.var: n.mode for n in main.nodes if isinstance(n, OutputNode) and n.var != "level"}
    assert outputs == {"full": "normal", "notFull": "negated", "count": "normal", "twice": "normal"}
    assert blocks["ADD"].pos == Position(x=12 * GRID_X, y=2 * GRID_Y)


def test_the_execution_order_is_the_executionorderids_CFC_02():
    """The chart's order lists the numbered elements by number: ADD, level, GT, full, notFull, the jump, level := 0,
    the label, CTU, count, F_DOUBLE, twice. AutoFlow has no numbers (CODESYS's automatic data flow mode): no
    order list, so the chart runs by data flow, then top to bottom."""
    result = imported()
    main = chart(result, "PLC_PRG")
    by_id = {n.id: n for n in main.nodes}
    named = [
        getattr(by_id[i], "call", None) or getattr(by_id[i], "var", None) or by_id[i].type for i in main.order or []
    ]
    assert named == [
        "ADD",
        "level",
        "GT",
        "full",
        "notFull",
        "jump",
        "level",
        "label",
        "CTU",
        "count",
        "F_DOUBLE",
        "twice",
    ]
    assert chart(result, "AutoFlow").order is None


def test_the_imported_charts_run_scan_by_scan():
    """PLC_PRG (inflow 3, limit 9): level := level + 3; full := level > 9; notFull := NOT (level > 9); when notFull
    the jump to Done skips level := 0; pulses counts rising edges of full (R is NOT start = FALSE); twice :=
    F_DOUBLE(level) after all that. Scans: level 3, 6, 9 (9 > 9 is FALSE), then 12 > 9: full, no jump, level 0,
    count 1, twice 0; then 3 again. AutoFlow (a = 4), no numbers: c := b + 1 is drawn above b := a * 2 and nothing
    wires them, so it runs first: c reads b's previous value: c 1 then 9, b 8."""
    built = build_project(imported().project)
    assert [d.format() for d in built.diagnostics if d.severity != "info"] == []
    sim = built.simulation()
    seen = []
    for _ in range(5):
        sim.cycle(1)
        main = tuple(sim.read(f"PLC_PRG.{v}") for v in ("level", "full", "notFull", "count", "twice"))
        seen.append((main, sim.read("AutoFlow.b"), sim.read("AutoFlow.c")))
    assert seen == [
        ((3, False, True, 0, 6), 8, 1),
        ((6, False, True, 0, 12), 8, 9),
        ((9, False, True, 0, 18), 8, 9),
        ((0, True, False, 1, 0), 8, 9),
        ((3, False, True, 1, 6), 8, 9),
    ]


def test_ladderlabs_export_of_the_imported_charts_is_valid_and_imports_back_the_same():
    """LadderLab writes the imported charts as it writes its own (an IEC 61131-10 style <FBD>, TC6-valid), and
    reads them back as the same CFC POUs."""
    project = imported().project
    data = export_plcopen(project)
    assert xsd_errors(data) == []
    again = import_plcopen(data)
    assert [d.format() for d in again.diagnostics] == []
    assert again.project.pous == project.pous


def test_the_imported_charts_export_as_st_that_runs_the_same():
    """The ST export of the imported charts (jumps as IF around what they skip) gives the same 200-scan traces under
    the same random writes as the charts."""
    trace = same_traces(imported().project, scans=200)
    assert len(trace) == 200


# ---------------------------------------------------------------- what a LadderLab chart cannot hold


def _in(local_id: int, expr: str, x: int = 2, y: int = 2) -> str:
    return (
        f'<inVariable localId="{local_id}"><position x="{x}" y="{y}" /><connectionPointOut><expression />'
        f"</connectionPointOut><expression>{expr}</expression></inVariable>"
    )


def _point(local_id: int, ref: int, param: str) -> str:
    return (
        f'<connector localId="{local_id}" name=""><position x="0" y="0" /><connectionPointIn>'
        f'<connection refLocalId="{ref}" formalParameter="{param}" /></connectionPointIn></connector>'
    )


def _out(local_id: int, order: int, ref: int, expr: str) -> str:
    return (
        f'<outVariable localId="{local_id}" executionOrderId="{order}"><position x="20" y="{order * 3}" />'
        f'<connectionPointIn><relPosition x="0" y="0" /><connection refLocalId="{ref}" /></connectionPointIn>'
        f"<expression>{expr}</expression></outVariable>"
    )


def _call(call: str) -> str:
    return (
        '<addData><data name="http://www.3s-software.com/plcopenxml/cfccalltype" handleUnknown="implementation">'
        f'<CallType xmlns="">{call}</CallType></data></addData>'
    )


def _document(elements: str, variables: str = "", other_pous: str = "") -> str:
    body = (
        '<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml" /></ST><addData>'
        '<data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>\n'
        f"{elements}\n</CFC></data></addData></body>"
    )
    interface = f"<interface><localVars>{variables}</localVars></interface>"
    return project_xml(f'{other_pous}<pou name="Chart" pouType="program">{interface}{body}</pou>').decode()


def _line(text: str, part: str) -> int:
    return text[: text.index(part)].count("\n") + 1


INT = '<variable name="{}"><type><INT /></type></variable>'


def test_a_composer_is_a_located_error_and_left_out():
    """A composer (a vendorElement, cfcelementtype composer) has no place on a LadderLab chart: an error at the
    element, naming the POU and the localId; the rest of the chart is read (y := 5), and the output the composer fed
    is left unwired, which the build reports rather than running it."""
    composer = (
        '<vendorElement localId="3" executionOrderId="1"><position x="10" y="2" /><alternativeText>'
        '<xhtml xmlns="http://www.w3.org/1999/xhtml">Point</xhtml></alternativeText><inputVariables>'
        '<variable formalParameter="x"><connectionPointIn><connection refLocalId="2" /></connectionPointIn>'
        '</variable></inputVariables><outputVariables><variable formalParameter="Out1"><connectionPointOut>'
        '<expression /></connectionPointOut></variable></outputVariables><addData><data name="http://www.3s-'
        'software.com/plcopenxml/cfcelementtype" handleUnknown="implementation"><ElementType xmlns="">composer'
        "</ElementType></data></addData></vendorElement>"
    )
    text = _document(
        "\n".join(
            [
                _in(1, "a"),
                _point(2, 1, "a"),
                composer,
                _point(4, 3, "Out1"),
                _out(5, 2, 4, "x"),
                _in(8, "5", y=12),
                _point(9, 8, "5"),
                _out(10, 4, 9, "y"),
            ]
        ),
        INT.format("a") + INT.format("x") + INT.format("y"),
    )
    result = imported(text.encode())
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == [
        f"POU Chart line {_line(text, '<vendorElement')}, network chart, element localId 3: error PLCOPEN-FBD: the "
        "CFC composer has no LadderLab chart element; it was left out (wire the structure's members, or a connector "
        "and continuation, instead)"
    ]
    main = chart(result, "Chart")
    assert sorted(n.var for n in main.nodes if isinstance(n, OutputNode)) == ["x", "y"]
    assert not any(isinstance(n, Block) for n in main.nodes)
    assert [d.format() for d in build_project(result.project).diagnostics if d.severity == "error"] == [
        "POU Chart, chart, output x: error FBD-DANGLING: the output has no input wire"
    ]


DIVIDER = """<pou name="Divider" pouType="functionBlock"><interface><localVars>{calls}</localVars></interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml" /></ST></body><addData>
<data name="http://www.3s-software.com/plcopenxml/method" handleUnknown="implementation"><Method name="DivMod">
<interface><returnType><BOOL /></returnType><inputVars>{a}{b}</inputVars><outputVars>{q}{r}</outputVars></interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">calls := calls + 1;
q := a / b;
r := a MOD b;
DivMod := r = 0;</xhtml></ST></body><addData /></Method></data></addData></pou>
"""


def test_a_method_box_is_a_call_of_the_instances_method():
    """CODESYS's box calling the method DivMod of the instance d (CallType method, the instance apart, the result
    pin named after the method) is LadderLab's box d.DivMod: 12 / 4 gives q 3, r 0, and the result r = 0 TRUE;
    the method ran once."""
    box = (
        '<block localId="5" executionOrderId="1" typeName="DivMod" instanceName="d"><position x="10" y="2" />'
        '<inputVariables><variable formalParameter="a"><connectionPointIn><connection refLocalId="2" />'
        '</connectionPointIn></variable><variable formalParameter="b"><connectionPointIn><connection refLocalId="4" />'
        "</connectionPointIn></variable></inputVariables><inOutVariables /><outputVariables>"
        + "".join(
            f'<variable formalParameter="{pin}"><connectionPointOut><expression /></connectionPointOut></variable>'
            for pin in ("DivMod", "q", "r")
        )
        + f"</outputVariables>{_call('method')}</block>"
    )
    elements = [_in(1, "n"), _point(2, 1, "n"), _in(3, "4"), _point(4, 3, "4"), box]
    for order, (pin, var) in enumerate([("DivMod", "even"), ("q", "q"), ("r", "r")], start=2):
        elements += [_point(10 + order, 5, pin), _out(20 + order, order, 10 + order, var)]
    variables = (
        '<variable name="d"><type><derived name="Divider" /></type></variable>'
        '<variable name="n"><type><INT /></type><initialValue><simpleValue value="12" /></initialValue></variable>'
        + INT.format("q")
        + INT.format("r")
        + '<variable name="even"><type><BOOL /></type></variable>'
    )
    divider = DIVIDER.format(**{v: INT.format(v) for v in ("calls", "a", "b", "q", "r")})
    result = imported(_document("\n".join(elements), variables, divider).encode())
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    [block] = [n for n in chart(result, "Chart").nodes if isinstance(n, Block)]
    assert (block.call, block.instance) == ("d.DivMod", None)
    built = build_project(result.project)
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    sim = built.simulation()
    sim.cycle(1)
    assert [sim.read(f"Chart.{v}") for v in ("q", "r", "even", "d.calls")] == [3, 0, True, 1]


def test_a_function_block_box_without_an_instance_is_a_located_error():
    """CODESYS always writes the instance of a functionblock call; one without is reported, not run as a call of
    nothing."""
    box = (
        '<block localId="1" executionOrderId="1" typeName="TON"><position x="10" y="2" /><inputVariables />'
        f"<inOutVariables /><outputVariables />{_call('functionblock')}</block>"
    )
    text = _document(box)
    [error] = [d for d in imported(text.encode()).diagnostics if d.severity == "error"]
    assert (error.code, error.message, error.line, error.element) == (
        "PLCOPEN-FBD",
        "box TON names no instance; it was left out",
        _line(text, "<block"),
        "localId 1",
    )


def test_two_elements_with_one_number_are_a_located_warning_and_run_top_to_bottom():
    """x := 1 (drawn above) and x := 2 both numbered 1: a warning at the second; they run top to bottom, so x is 2
    after a scan."""
    text = _document(
        "\n".join([_in(1, "1"), _point(2, 1, "1"), _out(3, 1, 2, "x"), _in(4, "2"), _point(5, 4, "2")])
        + '<outVariable localId="6" executionOrderId="1"><position x="20" y="9" /><connectionPointIn>'
        '<connection refLocalId="5" /></connectionPointIn><expression>x</expression></outVariable>',
        INT.format("x"),
    )
    result = imported(text.encode())
    [warning] = [d for d in result.diagnostics if d.code == "PLCOPEN-FBD"]
    assert (warning.severity, warning.message, warning.line) == (
        "warning",
        "localIds 3 and 6 have the same executionOrderId 1; they run top to bottom, left to right",
        _line(text, '<outVariable localId="6"'),
    )
    sim = build_project(result.project).simulation()
    sim.cycle(1)
    assert sim.read("Chart.x") == 2


@settings(max_examples=15, deadline=None)
@given(st.permutations(range(1, 5)))
def test_the_highest_number_writes_last_whatever_the_drawing_CFC_02(numbers):
    """Four outputs write v from the literals 10, 20, 30, 40 (drawn top to bottom), numbered by any permutation:
    after a scan v holds the literal of the highest number, as CODESYS runs the chart in its numbers' order."""
    parts = []
    for i, number in enumerate(numbers):
        base = 10 * i + 1
        parts += [_in(base, str(10 * (i + 1)), y=3 * i), _point(base + 1, base, "x")]
        parts.append(_out(base + 2, number, base + 1, "v").replace(f'y="{number * 3}"', f'y="{3 * i}"'))
    result = imported(_document("\n".join(parts), INT.format("v")).encode())
    sim = build_project(result.project).simulation()
    sim.cycle(1)
    assert sim.read("Chart.v") == 10 * (numbers.index(4) + 1)


def test_a_connector_and_its_continuation_and_a_return_are_kept():
    """A named connector C1 fed with 7 and its continuation feeding y stay a connector and a continuation (unlike
    the unnamed wire points); the return numbered 2, fed by stop (TRUE), ends the scan before z := 9 (number 3):
    after a scan y is 7 and z still 0."""
    elements = [
        _in(1, "7"),
        _point(2, 1, "7"),
        '<connector localId="3" name="C1"><position x="8" y="2" /><connectionPointIn><connection refLocalId="2" />'
        "</connectionPointIn></connector>",
        '<continuation localId="4" name="C1"><position x="12" y="6" /><connectionPointOut><expression />'
        "</connectionPointOut></continuation>",
        _point(5, 4, "C1"),
        _out(6, 1, 5, "y"),
        _in(7, "stop", y=9),
        _point(8, 7, "stop"),
        '<return localId="9" executionOrderId="2"><position x="12" y="9" /><connectionPointIn>'
        '<connection refLocalId="8" /></connectionPointIn></return>',
        _in(10, "9", y=12),
        _point(11, 10, "9"),
        _out(12, 3, 11, "z"),
    ]
    variables = (
        INT.format("y") + INT.format("z") + '<variable name="stop"><type><BOOL /></type><initialValue>'
        '<simpleValue value="TRUE" /></initialValue></variable>'
    )
    result = imported(_document("\n".join(elements), variables).encode())
    assert [d.format() for d in result.diagnostics if d.severity != "warning"] == []
    main = chart(result, "Chart")
    assert [(n.type, getattr(n, "name", None)) for n in main.nodes if n.type in ("connector", "continuation")] == [
        ("connector", "C1"),
        ("continuation", "C1"),
    ]
    built = build_project(result.project)
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    sim = built.simulation()
    sim.cycle(1)
    assert (sim.read("Chart.y"), sim.read("Chart.z")) == (7, 0)


SCALER = """<pou name="FB_SUM" pouType="functionBlock"><interface><inputVars>{raw}{gain}</inputVars>
<inOutVars>{mem}</inOutVars><outputVars>{out}</outputVars></interface>
<body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">mem := mem + raw;
out := mem * 2;</xhtml></ST></body></pou>
"""


def test_localid_0_unwired_inputs_and_an_in_out_pin_as_codesys_v35_sp19_writes_them():
    """PRG_CFC_3FB.xml (CODESYS V3.5 SP19 Patch 1) numbers a box localId 0, lists its unwired inputs without a
    connection and wires an in-out pin through a wire point. FB_SUM adds raw (5) to its in-out mem (total) and
    outputs mem * 2; gain stays unwired: total 5, y 10 after one scan, total 10, y 20 after two."""
    box = (
        '<block localId="0" executionOrderId="1" typeName="FB_SUM" instanceName="sum"><position x="16" y="9" />'
        '<inputVariables><variable formalParameter="raw"><connectionPointIn><relPosition x="0" y="0" />'
        '<connection refLocalId="2" /></connectionPointIn></variable><variable formalParameter="gain">'
        '<connectionPointIn><relPosition x="0" y="1" /></connectionPointIn></variable></inputVariables>'
        '<inOutVariables><variable formalParameter="mem"><connectionPointIn><relPosition x="0" y="2" />'
        '<connection refLocalId="4" /></connectionPointIn><connectionPointOut><expression /></connectionPointOut>'
        '</variable></inOutVariables><outputVariables><variable formalParameter="out"><connectionPointOut>'
        f'<relPosition x="0" y="0" /><expression /></connectionPointOut></variable></outputVariables>{_call("functionblock")}'
        "</block>"
    )
    elements = [_in(1, "5"), _point(2, 1, "5"), _in(3, "total"), _point(4, 3, "total"), box]
    elements += [_point(5, 0, "out"), _out(6, 2, 5, "y")]
    variables = '<variable name="sum"><type><derived name="FB_SUM" /></type></variable>' + "".join(
        INT.format(v) for v in ("total", "y")
    )
    scaler = SCALER.format(**{v: INT.format(v) for v in ("raw", "gain", "mem", "out")})
    result = imported(_document("\n".join(elements), variables, scaler).encode())
    assert [d.format() for d in result.diagnostics if d.severity != "warning"] == []
    built = build_project(result.project)
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    sim = built.simulation()
    seen = []
    for _ in range(2):
        sim.cycle(1)
        seen.append((sim.read("Chart.total"), sim.read("Chart.y")))
    assert seen == [(5, 10), (10, 20)]


def test_an_element_type_on_a_tc6_element_is_a_located_warning():
    """An ElementType LadderLab does not know on an <outVariable> is named in a warning at the element; the
    element is read as the output it is (x := 3 after a scan)."""
    marked = _out(3, 1, 2, "x").replace(
        "</outVariable>",
        '<addData><data name="http://www.3s-software.com/plcopenxml/cfcelementtype" handleUnknown="implementation">'
        '<ElementType xmlns="">fancyOutput</ElementType></data></addData></outVariable>',
    )
    text = _document("\n".join([_in(1, "3"), _point(2, 1, "3"), marked]), INT.format("x"))
    result = imported(text.encode())
    [warning] = [d for d in result.diagnostics if d.code == "PLCOPEN-FBD"]
    assert (warning.severity, warning.message, warning.line, warning.element) == (
        "warning",
        "the CFC element type 'fancyOutput' is not read; this <outVariable> is read as TC6 defines it",
        _line(text, "<outVariable"),
        "localId 3",
    )
    sim = build_project(result.project).simulation()
    sim.cycle(1)
    assert sim.read("Chart.x") == 3


_ELEMENT = st.sampled_from(["in", "point", "out", "add", "vendor"])


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(_ELEMENT, st.integers(0, 12), st.integers(0, 12)), min_size=1, max_size=12))
def test_any_wiring_of_wire_points_imports_without_a_traceback(shape):
    """Wire points naming each other in circles, missing localIds, boxes fed by what was left out: the import
    always gives a chart whose wires join its own elements, and every problem is a diagnostic at a line of the
    document."""
    parts = []
    for local_id, (kind, ref, other) in enumerate(shape):
        if kind == "in":
            parts.append(_in(local_id, "a"))
        elif kind == "point":
            parts.append(_point(local_id, ref, "OUT"))
        elif kind == "out":
            parts.append(_out(local_id, other + 1, ref, "x"))
        elif kind == "add":
            parts.append(
                f'<block localId="{local_id}" executionOrderId="{other + 1}" typeName="ADD"><position x="1" y="1" />'
                f'<inputVariables><variable formalParameter="In1"><connectionPointIn><connection refLocalId="{ref}" />'
                f'</connectionPointIn></variable><variable formalParameter="In2"><connectionPointIn><connection '
                f'refLocalId="{other}" /></connectionPointIn></variable></inputVariables><inOutVariables />'
                f'<outputVariables><variable formalParameter="Out1"><connectionPointOut><expression />'
                f"</connectionPointOut></variable></outputVariables>{_call('operator')}</block>"
            )
        else:
            parts.append(f'<vendorElement localId="{local_id}"><position x="1" y="1" /></vendorElement>')
    result = import_plcopen(_document("\n".join(parts), INT.format("a") + INT.format("x")).encode())
    assert result.project is not None
    main = chart(result, "Chart")
    ids = {n.id for n in main.nodes}
    assert all(w.from_.node in ids and w.to.node in ids for w in main.wires)  # no wire to what was left out
    assert not any(n.type == "connector" for n in main.nodes)  # the unnamed wire points are gone
    assert all(d.line is not None for d in result.diagnostics if d.code.startswith("PLCOPEN-") and d.pou == "Chart")


def test_wire_points_feeding_each_other_are_a_located_error():
    """Two wire points naming each other (no source) feed x: one error at the wire point where the circle closes;
    x is unwired, which the build reports."""
    text = _document("\n".join([_point(1, 2, "OUT"), _point(2, 1, "OUT"), _out(3, 1, 1, "x")]), INT.format("x"))
    result = imported(text.encode())
    assert [(d.severity, d.message, d.line) for d in result.diagnostics if d.code == "PLCOPEN-FBD"] == [
        ("error", "the wire points [1, 2] feed each other; they carry no value", _line(text, '<connector localId="2"'))
    ]
    assert [d.code for d in build_project(result.project).diagnostics if d.severity == "error"] == ["FBD-DANGLING"]


def test_a_negated_input_variable_and_a_negated_box_output_run_negated():
    """A negated <inVariable> a (FALSE) is NOT a; the AND's inputs NOT a and b (TRUE) give TRUE, its negated
    output gives FALSE to x; y reads NOT a directly: TRUE."""
    negated_in = _in(1, "a").replace('<inVariable localId="1">', '<inVariable localId="1" negated="true">')
    box = (
        '<block localId="5" executionOrderId="1" typeName="AND"><position x="10" y="2" /><inputVariables>'
        '<variable formalParameter="In1"><connectionPointIn><connection refLocalId="2" /></connectionPointIn>'
        '</variable><variable formalParameter="In2"><connectionPointIn><connection refLocalId="4" />'
        "</connectionPointIn></variable></inputVariables><inOutVariables /><outputVariables>"
        '<variable formalParameter="Out1" negated="true"><connectionPointOut><expression /></connectionPointOut>'
        f"</variable></outputVariables>{_call('operator')}</block>"
    )
    elements = [negated_in, _point(2, 1, "a"), _in(3, "b"), _point(4, 3, "b"), box, _point(6, 5, "Out1")]
    elements += [_out(7, 2, 6, "x"), _point(8, 1, "a"), _out(9, 3, 8, "y")]
    booleans = "".join(f'<variable name="{v}"><type><BOOL /></type></variable>' for v in ("a", "x", "y"))
    b_true = (
        '<variable name="b"><type><BOOL /></type><initialValue><simpleValue value="TRUE" /></initialValue></variable>'
    )
    result = imported(_document("\n".join(elements), booleans + b_true).encode())
    main = chart(result, "Chart")
    assert [n.expr for n in main.nodes if n.type == "input"] == ["NOT a", "b"]
    [block] = [n for n in main.nodes if isinstance(n, Block)]
    assert block.pins == {"OUT": PinFlags(negated=True)}
    built = build_project(result.project)
    assert [d.format() for d in built.diagnostics if d.severity == "error"] == []
    sim = built.simulation()
    sim.cycle(1)
    assert (sim.read("Chart.x"), sim.read("Chart.y")) == (False, True)


def test_a_chart_entry_without_a_cfc_element_is_a_located_error():
    """CODESYS's chart entry with something else than <CFC> in it (not seen in any export) is not read as an
    empty chart silently: an error at the entry, the POU an empty chart."""
    text = _document("").replace("<CFC>\n\n</CFC>", "<CFCPages />")
    result = imported(text.encode())
    [error] = [d for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED"]
    assert (error.severity, error.message, error.line) == (
        "error",
        "POU Chart's CODESYS chart entry holds no <CFC>; the POU was imported as an empty chart",
        _line(text, '<data name="http://www.3s-software.com/plcopenxml/cfc"'),
    )
    assert chart(result, "Chart").nodes == []
