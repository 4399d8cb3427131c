"""CFC (issue 26 item 5): one chart, execution order numbers that decide (CFC-01, CFC-02), run scan by scan.

Expected values are worked out by hand from CFC-02's rule: elements run in their order numbers' order; a wire
into an element that runs before its producer carries the producer's value of the previous scan.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import ValidationError

from ladderlab.ir.fbd_order import analyse
from ladderlab.ir.lower_fbd import evaluation_order
from ladderlab.model import fbd
from ladderlab.model.cfc import CfcBody
from ladderlab.model.project import Pou
from tests.ir.diagram_support import blk, fret, inp, net, out, simulate, trace


def cfc_pou(name: str, declarations: str, chart: fbd.FbdNetwork) -> Pou:
    return Pou(name=name, kind="program", language="cfc", declarations=declarations, body=CfcBody(networks=[chart]))


def copy_chart(order: list[str]) -> fbd.FbdNetwork:
    """x := a and y := x, unwired to each other: only the order numbers say which runs first (drawn y := x
    above x := a, which in FBD would run y := x first)."""
    return net(
        "chart",
        [inp("ia", "a", 0, 50), out("ox", "x", x=100, y=50), inp("ix", "x", 0, 0), out("oy", "y", x=100, y=0)],
        [("ia.OUT", "ox.IN"), ("ix.OUT", "oy.IN")],
        order=order,
    )


INTS = "VAR a, x, y, count, r : INT; cond : BOOL; END_VAR"


@pytest.mark.parametrize(
    ("order", "expected_y"),
    [(["ox", "oy"], [1, 2, 3]), (["oy", "ox"], [0, 1, 2])],
)
def test_order_numbers_decide_between_independent_elements_CFC_02(order, expected_y):
    """With y := x numbered before x := a, y sees the previous scan's x (positions would say otherwise)."""
    sim = simulate(cfc_pou("Main", INTS, copy_chart(order)))
    rows = trace(sim, "Main", [{"a": 1}, {"a": 2}, {"a": 3}], ["x", "y"])
    assert rows == [(a, y) for a, y in zip([1, 2, 3], expected_y)]


def counter_chart(order: list[str] | None) -> fbd.FbdNetwork:
    """inc := count + 1 -> count; r := inc * 2 (the MUL reads the ADD's result)."""
    return net(
        "chart",
        [
            inp("ic", "count", 0, 0),
            inp("one", "1", 0, 40),
            blk("inc", "ADD", x=100, y=0),
            out("oc", "count", x=250, y=0),
            inp("two", "2", 100, 100),
            blk("mul", "MUL", x=200, y=100),
            out("or", "r", x=350, y=100),
        ],
        [
            ("ic.OUT", "inc.IN1"),
            ("one.OUT", "inc.IN2"),
            ("inc.OUT", "oc.IN"),
            ("inc.OUT", "mul.IN1"),
            ("two.OUT", "mul.IN2"),
            ("mul.OUT", "or.IN"),
        ],
        order=order,
    )


def test_wire_against_the_order_carries_the_previous_scan_CFC_02():
    """MUL numbered before ADD reads ADD's result of the previous scan, kept in ``count`` (its output variable):
    scan k: r = 2 * (k - 1), count = k."""
    sim = simulate(cfc_pou("Main", INTS, counter_chart(["mul", "or", "inc", "oc"])))
    assert trace(sim, "Main", [{}] * 4, ["count", "r"]) == [(1, 0), (2, 2), (3, 4), (4, 6)]


def test_data_flow_order_reads_the_same_scan_CFC_02():
    sim = simulate(cfc_pou("Main", INTS, counter_chart(["inc", "oc", "mul", "or"])))
    assert trace(sim, "Main", [{}] * 3, ["count", "r"]) == [(1, 2), (2, 4), (3, 6)]


def test_unlisted_elements_follow_the_listed_ones_in_data_flow_order():
    """Only ``mul`` has a number: it runs first (so it reads the previous scan), the rest in data-flow order."""
    chart = counter_chart(["mul"])
    assert evaluation_order(chart, explicit=True) == ["two", "mul", "ic", "one", "inc", "oc", "or"]
    # the same network as FBD: ``order`` only breaks ties (MUL before the output of the ADD), MUL waits for ADD
    assert evaluation_order(chart) == ["ic", "one", "inc", "two", "mul", "oc", "or"]


def test_wire_against_the_order_from_a_function_without_output_variable_reads_its_feedback_variable():
    """ADD numbered after MUL, its result in no variable: MUL reads the hidden feedback variable, the previous
    scan's a + 1 (0, INT's default, in the first scan): r = 2 * (a_{k-1} + 1)."""
    chart = net(
        "chart",
        [inp("i", "a"), inp("one", "1"), blk("add", "ADD"), inp("two", "2"), blk("mul", "MUL"), out("o", "r")],
        [
            ("i.OUT", "add.IN1"),
            ("one.OUT", "add.IN2"),
            ("add.OUT", "mul.IN1"),
            ("two.OUT", "mul.IN2"),
            ("mul.OUT", "o.IN"),
        ],
        order=["mul", "o", "add"],
    )
    sim = simulate(cfc_pou("Main", INTS, chart))
    assert trace(sim, "Main", [{"a": 5}, {"a": 7}, {"a": 1}], ["r"]) == [(0,), (12,), (16,)]


def test_return_acts_at_its_order_number_CFC_02():
    """x := 1 (number 1), RETURN if cond (2), y := 1 (3): with cond TRUE the third element does not run."""
    chart = net(
        "chart",
        [inp("one", "1"), out("ox", "x"), inp("c", "cond"), fret("ret"), inp("one2", "1"), out("oy", "y")],
        [("one.OUT", "ox.IN"), ("c.OUT", "ret.IN"), ("one2.OUT", "oy.IN")],
        order=["ox", "ret", "oy"],
    )
    sim = simulate(cfc_pou("Main", INTS, chart))
    assert trace(sim, "Main", [{"cond": True}, {"cond": False}], ["x", "y"]) == [(1, 0), (1, 1)]


def test_a_chart_is_one_network_CFC_01():
    assert Pou(name="P", kind="program", language="cfc").body.chart.id == "chart"
    with pytest.raises(ValidationError, match=r"a CFC body is one chart without networks \(CFC-01\); this one has 2"):
        Pou(name="P", kind="program", language="cfc", body={"networks": [{"id": "a"}, {"id": "b"}]})


@st.composite
def charts(draw):
    """A chart of ADD blocks: each may read earlier blocks' results (a DAG in id order), in a random order."""
    count = draw(st.integers(1, 6))
    nodes: list = [inp("k", "1")]
    wires: list[tuple[str, str]] = []
    for i in range(count):
        nodes.append(blk(f"b{i}", "ADD"))
        for pin in ("IN1", "IN2"):
            source = draw(st.sampled_from(["k"] + [f"b{j}" for j in range(i)]))
            wires.append((f"{source}.OUT", f"b{i}.{pin}"))
    order = draw(st.permutations([f"b{i}" for i in range(count)]))
    return net("chart", nodes, wires, order=list(order)), list(order)


@settings(max_examples=60, deadline=None)
@given(charts())
def test_order_is_the_list_and_feedback_is_every_backward_wire_CFC_02(drawn):
    chart, order = drawn
    graph = analyse(chart, lambda *a, **k: None, explicit=True)
    assert [n for n in graph.order if n != "k"] == order
    rank = {node: i for i, node in enumerate(order)}
    backward = {
        (w.to.node, w.to.pin) for w in chart.wires if w.from_.node != "k" and rank[w.from_.node] >= rank[w.to.node]
    }
    assert graph.feedback == backward
