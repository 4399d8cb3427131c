"""ST export of jump patterns (GR-07..10): IF structure where the forward jumps nest, a network state machine
(CASE inside WHILE) otherwise; returns as RETURN. Every case also runs like the diagram (st_support)."""

from __future__ import annotations

from ladderlab.model import ld
from tests.interchange.st_support import body, exported, same_traces
from tests.ir.diagram_support import coil, contact, jump, ld_pou, parallel, project, ret, rung

DECL = "VAR a, b, c, x, y, z : BOOL; END_VAR"


def check(*networks, expected: str) -> None:
    pou = ld_pou("Main", DECL, *networks)
    assert body(exported(project(pou), "Main").text) == expected
    same_traces(project(pou))


def test_nested_forward_jumps_become_nested_ifs():
    check(
        rung("n1", contact("k1", "a"), jump("j1", "L4")),
        rung("n2", contact("k2", "b"), jump("j2", "L3")),
        rung("n3", contact("k3", "c"), coil("q1", "x")),
        rung("n4", contact("k4", "a"), coil("q2", "y"), label="L3"),
        rung("n5", contact("k5", "b"), coil("q3", "z"), label="L4"),
        expected="(* Network 1 *)\nIF NOT a THEN\n    (* Network 2 *)\n    IF NOT b THEN\n"
        '        (* Network 3 *)\n        x := c;\n    END_IF;\n    (* Network 4 "L3" *)\n'
        '    y := a;\nEND_IF;\n(* Network 5 "L4" *)\nz := b;\n',
    )


def test_a_jump_to_the_next_network_skips_nothing_and_an_unconditional_jump_skips_networks_that_never_run():
    check(
        rung("n1", contact("k1", "a"), jump("j1", "L2")),
        rung("n2", jump("j2", "L4"), label="L2"),
        rung("n3", contact("k3", "c"), coil("q1", "x")),
        rung("n4", contact("k4", "b"), coil("q2", "y"), label="L4"),
        expected='(* Network 1 *)\n(* Network 2 "L2" *)\n'
        "(* Network 3 never runs: the jump in network 2 always skips it *)\n"
        '(* Network 4 "L4" *)\ny := b;\n',
    )


def test_crossing_forward_jumps_need_the_state_machine():
    check(
        rung("n1", contact("k1", "a"), jump("j1", "L3")),
        rung("n2", contact("k2", "b"), jump("j2", "L4")),
        rung("n3", contact("k3", "c"), coil("q1", "x"), label="L3"),
        rung("n4", contact("k4", "a"), coil("q2", "y"), label="L4"),
        expected="next_network := 0;\nWHILE next_network < 4 DO\n    CASE next_network OF\n        0:\n"
        "            (* Network 1 *)\n            IF a THEN\n                next_network := 2;\n"
        "            ELSE\n                next_network := 1;\n            END_IF;\n        1:\n"
        "            (* Network 2 *)\n            IF b THEN\n                next_network := 3;\n"
        "            ELSE\n                next_network := 2;\n            END_IF;\n        2:\n"
        '            (* Network 3 "L3" *)\n            x := c;\n            next_network := 3;\n'
        '        3:\n            (* Network 4 "L4" *)\n            y := a;\n'
        "            next_network := 4;\n    END_CASE;\nEND_WHILE;\n",
    )


def test_gr05c_several_jumps_and_returns_of_one_network_act_in_element_order():
    """Branches end in a jump, a return and another jump: the first that conducts acts (ELSIF chain)."""
    check(
        ld.LdNetwork(
            id="n1",
            elements=[
                parallel(
                    "p",
                    [contact("k1", "a"), jump("j1", "L3")],
                    [contact("k2", "b"), ret("r1")],
                    [contact("k3", "c"), jump("j2", "L2")],
                )
            ],
        ),
        rung("n2", contact("k4", "c"), coil("q1", "x"), label="L2"),
        rung("n3", contact("k5", "a", "p"), coil("q2", "y", "set"), label="L3"),
        expected="next_network := 0;\nWHILE next_network < 3 DO\n    CASE next_network OF\n        0:\n"
        "            (* Network 1 *)\n            IF a THEN\n                next_network := 2;\n"
        "            ELSIF b THEN\n                RETURN;\n            ELSIF c THEN\n"
        "                next_network := 1;\n            ELSE\n                next_network := 1;\n"
        '            END_IF;\n        1:\n            (* Network 2 "L2" *)\n            x := c;\n'
        '            next_network := 2;\n        2:\n            (* Network 3 "L3" *)\n'
        "            a_rising(CLK := a);\n            IF a_rising.Q THEN\n                y := TRUE;\n"
        "            END_IF;\n            next_network := 3;\n    END_CASE;\nEND_WHILE;\n",
    )


def test_backward_jump_loops_like_the_diagram_and_an_endless_one_trips_the_watchdog_in_the_same_scan():
    """GR-09 allows backward jumps; while b holds, n2 jumps to itself: the diagram and its ST both loop until
    the watchdog stops the task (st_support compares the faults)."""
    check(
        rung("n1", contact("k1", "a"), coil("q", "x")),
        rung("n2", contact("k2", "b"), jump("j", "L"), label="L"),
        expected="next_network := 0;\nWHILE next_network < 2 DO\n    CASE next_network OF\n        0:\n"
        "            (* Network 1 *)\n            x := a;\n            next_network := 1;\n"
        '        1:\n            (* Network 2 "L" *)\n            IF b THEN\n'
        "                next_network := 1;\n            ELSE\n                next_network := 2;\n"
        "            END_IF;\n    END_CASE;\nEND_WHILE;\n",
    )


def test_gr10_unconditional_return_from_the_left_rail():
    check(
        rung("n1", contact("k1", "a"), coil("q", "x")),
        rung("n2", ret("r")),
        rung("n3", contact("k2", "b"), coil("q2", "y")),
        expected="(* Network 1 *)\nx := a;\n(* Network 2 *)\nRETURN;\n(* Network 3 *)\ny := b;\n",
    )
