"""LD networks as IL ("View as IL", issue 26 item 4): the exact text of each construct, the reason when a
network has none, and - the contract of a teaching aid - the IL runs like the LD network, scan by scan over
hypothesis-generated rungs (contacts NO/NC, series and parallel, coils normal/negated/set/reset, jumps)."""

from __future__ import annotations

import random

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.interchange.ld_il import body_il, network_il
from ladderlab.model.project import Pou
from tests.ir.diagram_support import coil, compare, contact, jump, ld_pou, parallel, ret, rung, simulate
from tests.ir.test_diagram_equivalence import DECLARATIONS, INPUTS, OUTPUTS, ld_program, rung_strategy


def text(network) -> str:
    made = network_il(network)
    assert made.reason is None, made.reason
    return made.text


def test_series_parallel_and_coils_IL_10_IL_13():
    network = rung(
        "n1",
        contact("a", "i0"),
        parallel("p", [contact("b", "i1", "nc"), contact("c", "i2")], [contact("d", "i3")], []),
        compare("cmp", "GT", "n", "5"),
        parallel("q", [coil("c1", "o0")], [coil("c2", "o1", "set")], [coil("c3", "o2", "negated")]),
        label="Start",
    )
    assert text(network) == (
        "Start:\nLD i0\nAND(\n    LDN i1\n    AND i2\n    OR i3\n    OR TRUE\n)\nAND( n\n    GT 5\n)\n"
        "ST o0\nS o1\nSTN o2"
    )


def test_jumps_and_returns_come_last_conditional_or_straight_on_the_rail():
    assert text(rung("n1", contact("a", "i0", "nc"), parallel("p", [coil("q", "o0", "reset")], [jump("j", "L")]))) == (
        "LDN i0\nR o0\nJMPC L"
    )
    assert text(rung("n2", ret("r"))) == "LD TRUE\nRET"


def test_a_network_without_il_equivalent_says_why():
    assert network_il(rung("n1", contact("a", "i0", "p"), coil("q", "o0"))).reason == (
        "the P contact i0 detects an edge: IL needs an R_TRIG"
    )
    assert network_il(rung("n2", coil("q", "o0"), contact("a", "i0"), coil("r", "o1"))).reason == (
        "the coil o0 stands where the rung's power is still being formed"
    )
    assert network_il(rung("n3", contact("a", "i0"))).reason == "the rung ends in no coil, jump or return"


rungs = rung_strategy(("no", "nc"), ("normal", "negated", "set", "reset"), (None,))


def run(pou: Pou, seed: int) -> list[tuple]:
    sim = simulate(pou)
    rng = random.Random(seed)
    rows = []
    for _ in range(60):
        for name in INPUTS:
            sim.write(f"Main.{name}", rng.random() < 0.5)
        sim.cycle(1)
        rows.append(tuple(sim.read(f"Main.{name}") for name in OUTPUTS))
    return rows


@settings(max_examples=40, deadline=None)
@given(st.lists(rungs, min_size=1, max_size=4), st.integers(0, 1000))
def test_the_il_runs_like_the_ld_network_scan_by_scan(program, seed):
    ld = ld_program(program)
    il = body_il(ld.body)
    assert il.reason is None, il.reason
    as_il = Pou(name="Main", kind="program", language="il", declarations=DECLARATIONS, body=il.text)
    assert run(as_il, seed) == run(ld, seed)


def test_a_jump_over_a_network_and_a_conditional_return_run_like_ld():
    """GR-07..10 in both: i0 skips network 2, i3 returns before network 4."""
    ld = ld_pou(
        "Main",
        DECLARATIONS,
        rung("n1", contact("a", "i0"), jump("j", "Skip")),
        rung("n2", contact("b", "i1"), coil("q", "o0")),
        rung("n3", contact("c", "i2"), parallel("p", [coil("r", "o1")], [ret("x")]), label="Skip"),
        rung("n4", contact("d", "i3", "nc"), coil("s", "o2", "set")),
    )
    il = body_il(ld.body)
    assert il.text == "LD i0\nJMPC Skip\nLD i1\nST o0\nSkip:\nLD i2\nST o1\nRETC\nLDN i3\nS o2"
    as_il = Pou(name="Main", kind="program", language="il", declarations=DECLARATIONS, body=il.text)
    assert run(as_il, 7) == run(ld, 7)
