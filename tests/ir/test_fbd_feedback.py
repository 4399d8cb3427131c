"""FBD feedback loops (issue 22 item 6; IEC 61131-3 ed. 3 "feedback paths", GR-06): a wire from a block's output
back into its own or an earlier block's input carries the value of the previous scan. A function's result that
no output variable keeps gets a hidden feedback variable, which starts with its type's default (0, 0.0) and takes
the result after every call. Expected values come from the recurrences written in each test (x_k = f(x_{k-1})).
Online, the block's input pin shows the value it read (probe ``<block>.<PIN>``), not the producer's new one.
"""

from __future__ import annotations

import struct

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.engine.simulation import Simulation
from tests.ir.diagram_support import blk, errors, fbd_pou, inp, lower_ok, net, out


def f32(x: float) -> float:
    """``x`` rounded to a REAL (IEEE single), as the PLC stores it."""
    return struct.unpack("f", struct.pack("f", x))[0]


def counter(declarations: str = "VAR done : BOOL; END_VAR") -> Simulation:
    """ADD(its own OUT, 1) -> GE(., 3) -> done: no variable holds the count, only the loop."""
    network = net(
        "n",
        [inp("one", "1"), blk("add", "ADD"), inp("three", "3"), blk("ge", "GE"), out("o", "done")],
        [
            ("add.OUT", "add.IN1"),
            ("one.OUT", "add.IN2"),
            ("add.OUT", "ge.IN1"),
            ("three.OUT", "ge.IN2"),
            ("ge.OUT", "o.IN"),
        ],
    )
    return Simulation(lower_ok(fbd_pou("Main", declarations, network)), variant="monitor")


def test_a_counter_loop_counts_once_per_scan_from_the_types_default():
    """count_k = count_{k-1} + 1, count_0 = 0 (INT's default): done = count_k >= 3 from scan 3 on; ADD.IN1 read
    count_{k-1} (the previous scan's), ADD.OUT shows count_k."""
    sim = counter()
    for k in range(1, 7):
        sim.cycle()
        assert sim.fault is None
        probes = sim.probes("Main").values
        assert (probes["add.IN1"], probes["add.OUT"], sim.read("Main.done")) == (k - 1, k, k >= 3)


@settings(max_examples=25, deadline=None)
@given(rates=st.lists(st.floats(min_value=-100, max_value=100, width=32), min_size=1, max_size=12))
def test_an_integrator_loop_sums_its_input_scan_by_scan(rates):
    """acc_k = acc_{k-1} + rate_k (REAL: the loop takes the type of ``rate``); y = acc_k * 2.0."""
    network = net(
        "n",
        [inp("r", "rate"), blk("add", "ADD"), inp("two", "2.0"), blk("mul", "MUL"), out("o", "y")],
        [
            ("add.OUT", "add.IN1"),
            ("r.OUT", "add.IN2"),
            ("add.OUT", "mul.IN1"),
            ("two.OUT", "mul.IN2"),
            ("mul.OUT", "o.IN"),
        ],
    )
    sim = Simulation(lower_ok(fbd_pou("Main", "VAR rate, y : REAL; END_VAR", network)))
    acc = 0.0
    for rate in rates:
        sim.write("Main.rate", rate)
        sim.cycle()
        acc = f32(acc + rate)
        assert sim.read("Main.y") == pytest.approx(f32(acc * 2.0), rel=1e-6, abs=1e-6)


def test_a_loop_through_two_blocks_reads_the_later_blocks_previous_result():
    """a_k = b_{k-1} + 1, b_k = 2 * a_k, b_0 = 0: a = 1, 3, 7, 15 (only ``a`` is a variable; MUL's result is the
    hidden feedback variable)."""
    network = net(
        "n",
        [inp("one", "1"), blk("add", "ADD"), inp("two", "2"), blk("mul", "MUL"), out("o", "a")],
        [
            ("mul.OUT", "add.IN1"),
            ("one.OUT", "add.IN2"),
            ("add.OUT", "mul.IN1"),
            ("two.OUT", "mul.IN2"),
            ("add.OUT", "o.IN"),
        ],
    )
    sim = Simulation(lower_ok(fbd_pou("Main", "VAR a : INT; END_VAR", network)), variant="monitor")
    b = 0
    for _ in range(4):
        sim.cycle()
        a, b_before = b + 1, b
        b = 2 * a
        probes = sim.probes("Main").values
        assert (sim.read("Main.a"), probes["add.IN1"], probes["mul.OUT"]) == (a, b_before, b)


def test_a_loop_whose_type_nothing_gives_is_a_located_error():
    """ABS fed only by itself: no input from outside the loop, no output variable - no type for its variable."""
    network = net("n", [blk("abs", "ABS")], [("abs.OUT", "abs.IN")])
    assert errors(fbd_pou("Main", "", network)) == [
        "POU Main, network 1, ABS.IN: error FBD-FEEDBACK: the wire from ABS.OUT to ABS.IN closes a loop, and "
        "nothing outside the loop gives ABS.OUT a type: connect a typed variable to one of its inputs, or its "
        "output to an output variable"
    ]
