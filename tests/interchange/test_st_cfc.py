"""ST export of CFC charts (issue 26 item 5): the statements in the chart's execution order (CFC-02), a wire
against the order read from where the previous scan left its value, a return where it stands; the exported ST
runs like the chart (same traces)."""

from __future__ import annotations

from tests.interchange.st_support import body, exported, same_traces
from tests.ir.diagram_support import fret, inp, net, out, project
from tests.ir.test_lower_cfc import INTS, cfc_pou, copy_chart, counter_chart

TITLE = "(* CFC chart: its elements in their execution order (CFC-02) *)\n"


def check(chart, expected: str) -> None:
    pou = cfc_pou("Main", INTS, chart)
    assert body(exported(project(pou), "Main").text) == TITLE + expected
    same_traces(project(pou))


def test_independent_outputs_in_order_number_order_CFC_02():
    check(copy_chart(["oy", "ox"]), "y := x;\nx := a;\n")
    check(copy_chart(["ox", "oy"]), "x := a;\ny := x;\n")


def test_a_wire_against_the_order_reads_the_output_variable_of_the_previous_scan_CFC_02():
    check(counter_chart(["mul", "or", "inc", "oc"]), "r := count * 2;\ncount := count + 1;\n")
    check(counter_chart(["inc", "oc", "mul", "or"]), "count := count + 1;\nr := count * 2;\n")


def test_a_return_acts_where_its_number_puts_it():
    chart = net(
        "chart",
        [inp("one", "1"), out("ox", "x"), inp("c", "cond"), fret("ret"), inp("one2", "1"), out("oy", "y")],
        [("one.OUT", "ox.IN"), ("c.OUT", "ret.IN"), ("one2.OUT", "oy.IN")],
        order=["ox", "ret", "oy"],
    )
    check(chart, "x := 1;\nIF cond THEN\n    RETURN;\nEND_IF;\ny := 1;\n")
