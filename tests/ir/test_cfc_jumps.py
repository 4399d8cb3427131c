"""CFC jumps, labels and returns (issue 26 item 5, CFC-02): a jump whose input is TRUE goes on at its label's
execution order number, skipping the elements numbered between; backward, it runs them again in the same scan.

Expected values are worked out by hand from that rule (CODESYS's CFC jump/label): an element a jump skips does
not run in that scan, so the variables it writes and the results it gives keep their values.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import fbd
from ladderlab.model.cfc import CfcBody
from ladderlab.model.project import Pou
from tests.ir.diagram_support import blk, errors, fjump, flabel, fret, inp, net, out, project, simulate, trace

DECLS = "VAR a, x, y, z, n : INT; skip, back, stop : BOOL; END_VAR"


def cfc_pou(chart: fbd.FbdNetwork, declarations: str = DECLS) -> Pou:
    return Pou(name="Main", kind="program", language="cfc", declarations=declarations, body=CfcBody(networks=[chart]))


def skipping_chart() -> fbd.FbdNetwork:
    """1 x := a; 2 jump to Over if skip; 3 y := a; 4 label Over; 5 z := a."""
    return net(
        "chart",
        [
            inp("ia", "a"),
            out("ox", "x"),
            inp("is", "skip"),
            fjump("j", "Over"),
            inp("ia2", "a"),
            out("oy", "y"),
            flabel("l", "Over"),
            inp("ia3", "a"),
            out("oz", "z"),
        ],
        [("ia.OUT", "ox.IN"), ("is.OUT", "j.IN"), ("ia2.OUT", "oy.IN"), ("ia3.OUT", "oz.IN")],
        order=["ox", "j", "oy", "l", "oz"],
    )


def test_a_forward_jump_skips_the_elements_numbered_between_it_and_its_label_CFC_02():
    """y keeps its value in the scans the jump is taken; x and z are written every scan."""
    sim = simulate(cfc_pou(skipping_chart()))
    scans = [{"a": 1, "skip": False}, {"a": 2, "skip": True}, {"a": 3, "skip": True}, {"a": 4, "skip": False}]
    assert trace(sim, "Main", scans, ["x", "y", "z"]) == [(1, 1, 1), (2, 1, 2), (3, 1, 3), (4, 4, 4)]


def test_the_order_numbers_not_the_positions_decide_what_a_jump_skips_CFC_02():
    """The same chart numbered y := a after the label: the jump skips nothing."""
    chart = skipping_chart()
    chart.order = ["ox", "j", "l", "oy", "oz"]
    sim = simulate(cfc_pou(chart))
    assert trace(sim, "Main", [{"a": 5, "skip": True}], ["x", "y", "z"]) == [(5, 5, 5)]


def test_a_skipped_function_keeps_its_result_for_the_elements_after_the_label():
    """1 jump to L if skip; 2 ADD(a, 10); 3 label L; 4 y := the ADD's result. With the ADD skipped, y reads the
    result it gave when it last ran (0 before it ever ran), never another value's leftover."""
    chart = net(
        "chart",
        [
            inp("is", "skip"),
            fjump("j", "L"),
            inp("ia", "a"),
            inp("ten", "10"),
            blk("add", "ADD"),
            flabel("l", "L"),
            out("oy", "y"),
            inp("ia2", "a"),
            out("ox", "x"),
        ],
        [("is.OUT", "j.IN"), ("ia.OUT", "add.IN1"), ("ten.OUT", "add.IN2"), ("add.OUT", "oy.IN"), ("ia2.OUT", "ox.IN")],
        order=["j", "add", "l", "oy", "ox"],
    )
    sim = simulate(cfc_pou(chart))
    scans = [{"a": 1, "skip": True}, {"a": 2, "skip": False}, {"a": 3, "skip": True}, {"a": 4, "skip": False}]
    assert trace(sim, "Main", scans, ["y", "x"]) == [(0, 1), (12, 2), (12, 3), (14, 4)]


def counting_chart() -> fbd.FbdNetwork:
    """1 label Again; 2 n := n + 1; 3 jump to Again if n < 5 AND back; ... a backward jump: a loop in one scan."""
    return net(
        "chart",
        [
            flabel("l", "Again"),
            inp("in", "n"),
            inp("one", "1"),
            blk("inc", "ADD"),
            out("on", "n"),
            inp("in2", "n"),
            inp("five", "5"),
            blk("lt", "LT"),
            inp("ib", "back"),
            blk("and", "AND"),
            fjump("j", "Again"),
        ],
        [
            ("in.OUT", "inc.IN1"),
            ("one.OUT", "inc.IN2"),
            ("inc.OUT", "on.IN"),
            ("in2.OUT", "lt.IN1"),
            ("five.OUT", "lt.IN2"),
            ("lt.OUT", "and.IN1"),
            ("ib.OUT", "and.IN2"),
            ("and.OUT", "j.IN"),
        ],
        order=["l", "inc", "on", "lt", "and", "j"],
    )


def test_a_backward_jump_runs_the_elements_again_in_the_same_scan_CFC_02():
    """With back TRUE n counts up to 5 within one scan; without, by one per scan."""
    sim = simulate(cfc_pou(counting_chart()))
    scans = [{"n": 0, "back": True}, {"back": False}, {"n": 2, "back": True}, {"n": 7}]
    assert trace(sim, "Main", scans, ["n"]) == [(5,), (6,), (5,), (8,)]


def test_an_endless_backward_jump_trips_the_watchdog_at_the_jump():
    """A jump back whose condition stays TRUE is a watchdog fault of the scan, located at the chart, not a hang."""
    chart = net(
        "chart",
        [flabel("l", "Top"), inp("in", "n"), inp("one", "1"), blk("inc", "ADD"), out("on", "n"), inp("t", "TRUE")]
        + [fjump("j", "Top")],
        [("in.OUT", "inc.IN1"), ("one.OUT", "inc.IN2"), ("inc.OUT", "on.IN"), ("t.OUT", "j.IN")],
        order=["l", "inc", "on", "j"],
    )
    sim = Simulation(lower_project(project(cfc_pou(chart))).program, watchdog_s=0.05)
    sim.cycle(1)
    assert sim.fault is not None and sim.fault.kind == "watchdog"
    assert (sim.fault.origin.network, sim.fault.origin.element) == ("chart", "j")


def test_a_return_after_a_label_ends_the_pou_only_when_reached():
    """1 jump to End if skip; 2 RETURN if stop; 3 label End; 4 y := a: a taken jump passes over the return."""
    chart = net(
        "chart",
        [inp("is", "skip"), fjump("j", "End"), inp("ist", "stop"), fret("r"), flabel("l", "End"), inp("ia", "a")]
        + [out("oy", "y")],
        [("is.OUT", "j.IN"), ("ist.OUT", "r.IN"), ("ia.OUT", "oy.IN")],
        order=["j", "r", "l", "oy"],
    )
    sim = simulate(cfc_pou(chart))
    scans = [
        {"a": 1, "skip": False, "stop": True},
        {"a": 2, "skip": True, "stop": True},
        {"a": 3, "skip": False, "stop": False},
    ]
    assert trace(sim, "Main", scans, ["y"]) == [(0,), (2,), (3,)]


def test_unknown_label_is_a_located_error():
    chart = net(
        "chart",
        [inp("t", "TRUE"), fjump("j", "Ovr"), flabel("l", "Over")],
        [("t.OUT", "j.IN")],
        order=["j", "l"],
    )
    assert errors(cfc_pou(chart)) == [
        "POU Main, chart, jump to Ovr: error FBD-UNKNOWN-LABEL: jump to 'Ovr', but no label element of the chart has "
        "that label - did you mean 'OVER'?"
    ]


def test_duplicate_and_malformed_labels_are_located_errors():
    chart = net("chart", [flabel("l1", "Over"), flabel("l2", "over"), flabel("l3", "no good")], [])
    assert errors(cfc_pou(chart)) == [
        "POU Main, chart, label over: error FBD-DUPLICATE-LABEL: label 'over' is on the chart twice",
        "POU Main, chart, label no good: error FBD-BAD-LABEL: label 'no good' must be an identifier or an unsigned "
        "integer",
    ]


def test_a_jump_without_condition_is_a_located_error():
    """CODESYS's CFC jump acts on its input; an unwired one is refused (wire TRUE for an every-scan jump)."""
    chart = net("chart", [fjump("j", "Over"), flabel("l", "Over")], [], order=["j", "l"])
    assert errors(cfc_pou(chart)) == [
        "POU Main, chart, jump to Over: error CFC-JUMP-CONDITION: the jump to 'Over' has no condition: wire a BOOL "
        "value into its input (TRUE for a jump every scan)"
    ]


def test_a_label_element_in_an_fbd_network_is_a_located_error():
    pou = Pou(
        name="Main",
        kind="program",
        language="fbd",
        declarations=DECLS,
        body=fbd.FbdBody(networks=[net("n1", [flabel("l", "Over")], [])]),
    )
    assert errors(pou) == [
        "POU Main, network 1, label Over: error FBD-BAD-LABEL: label 'Over' is an element: in FBD give the network "
        "the label (label elements are CFC's)"
    ]


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.integers(0, 3), min_size=4, max_size=4),
    st.integers(0, 3),
    st.integers(0, 3),
    st.lists(st.booleans(), min_size=1, max_size=4),
)
def test_a_forward_jump_skips_exactly_the_writes_numbered_between_CFC_02(values, jump_at, label_at, conditions):
    """Four writes w0..w3 (wi := i + 1 + scan * 10); a jump stands before write ``jump_at`` and a label before
    write ``label_at`` (after the jump). Reference: in a scan whose condition is TRUE the writes numbered between
    the jump and the label keep their previous value, all others take this scan's."""
    label_at = max(label_at, jump_at)
    nodes: list = [inp("c", "skip"), fjump("j", "L"), flabel("l", "L")]
    wires = [("c.OUT", "j.IN")]
    elements: list[str] = []
    for i in range(4):
        if i == jump_at:
            elements.append("j")
        if i == label_at:
            elements.append("l")
        nodes += [inp(f"i{i}", f"a + {i + 1}"), out(f"o{i}", f"w{i}")]
        wires.append((f"i{i}.OUT", f"o{i}.IN"))
        elements.append(f"o{i}")
    declarations = "VAR a, w0, w1, w2, w3 : INT; skip : BOOL; END_VAR"
    sim = simulate(cfc_pou(net("chart", nodes, wires, order=elements), declarations))
    expected = [0, 0, 0, 0]
    rows = []
    for scan, condition in enumerate(conditions):
        expected = [expected[i] if condition and jump_at <= i < label_at else scan * 10 + i + 1 for i in range(4)]
        rows.append(tuple(expected))
    scans = [{"a": scan * 10, "skip": condition} for scan, condition in enumerate(conditions)]
    assert trace(sim, "Main", scans, ["w0", "w1", "w2", "w3"]) == rows
