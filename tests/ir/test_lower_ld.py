"""LD lowering: the IR it produces (evaluation order, power-flow slots, probes, jumps) - GR-11..28, LD-01..10."""

from __future__ import annotations

from pathlib import Path

from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_project import lower_project
from ladderlab.ir.types import Elementary, FbInstance
from ladderlab.storage.load import read_project_folder
from tests.ir.diagram_support import (
    box,
    check_diagram_program,
    coil,
    contact,
    jump,
    ld_pou,
    lower_ok,
    parallel,
    probes,
    ret,
    rung,
    statements,
)
from tests.support import EXAMPLES

BOOL, INT = Elementary("BOOL"), Elementary("INT")
DECL = "VAR in1, in2, in3, in4, C, D, E : BOOL; n : INT; t1 : TON; END_VAR"


def var(name: str, ty=BOOL, *path) -> ir.Var:
    return ir.Var("local", name, ty, tuple(path))


def at(network: str, element: str) -> ir.Origin:
    return ir.Origin("MAIN", network=network, element=element)


P, P1, P2, P3 = (var(n) for n in ("__P", "__P_1", "__P_2", "__P_3"))


def test_motor_example_lowers_with_a_probe_per_element():
    project = read_project_folder(Path(EXAMPLES / "motor"))
    result = lower_project(project)
    assert [d.format() for d in result.diagnostics] == []
    check_diagram_program(result.program)
    assert probes(result.program, "Main") == [
        "start",
        "seal",
        "start_or_motor",
        "stop",
        "motor",
        "motor_on",
        "ton",
        "ton.Q",
        "ton.ET",
        "running",
        "start_edge",
        "reset_count",
        "ctu",
        "ctu.Q",
        "ctu.CV",
        "running_on",
        "blink",
        "blink.OUT",
        "lamp_coil",
    ]


def test_gr15_gr16_series_is_an_and_chain_with_one_slot_per_element():
    """C := in1 AND NOT in2: each contact's right-side power is stored once, the coil writes it (GR-20)."""
    program = lower_ok(ld_pou("Main", DECL, rung("n", contact("a", "in1"), contact("b", "in2", "nc"), coil("c", "C"))))
    assert statements(program, "Main", "n") == [
        ir.Assign(P, var("IN1"), at("n", "a")),
        ir.Probe("a", P, at("n", "a")),
        ir.Assign(P1, ir.Binary("AND", P, ir.Unary("NOT", var("IN2"), BOOL), BOOL), at("n", "b")),
        ir.Probe("b", P1, at("n", "b")),
        ir.Assign(var("C"), P1, at("n", "c")),
        ir.Probe("c", P1, at("n", "c")),
    ]


def test_gr14_parallel_evaluates_every_branch_from_the_same_power_and_ors_them():
    """C := in1 AND (in2 OR in3), with an edge contact in a branch: no short-circuit, its memory always follows."""
    program = lower_ok(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n",
                contact("a", "in1"),
                parallel("p", [contact("b", "in2")], [contact("e", "in3", "p")]),
                coil("c", "C"),
            ),
        )
    )
    memory = var("__E_M")
    assert statements(program, "Main", "n")[2:] == [
        ir.Assign(P1, ir.Binary("AND", P, var("IN2"), BOOL), at("n", "b")),
        ir.Probe("b", P1, at("n", "b")),
        ir.Assign(
            P2,
            ir.Binary("AND", P, ir.Binary("AND", var("IN3"), ir.Unary("NOT", memory, BOOL), BOOL), BOOL),
            at("n", "e"),
        ),
        ir.Assign(memory, var("IN3"), at("n", "e")),
        ir.Probe("e", P2, at("n", "e")),
        ir.Assign(P3, ir.Binary("OR", P1, P2, BOOL), at("n", "p")),
        ir.Probe("p", P3, at("n", "p")),
        ir.Assign(var("C"), P3, at("n", "c")),
        ir.Probe("c", P3, at("n", "c")),
    ]


def test_gr26_coils_fed_by_one_rung_all_read_the_one_stored_value():
    """docs/ir.md invariant 5: a coil that writes the contact's own variable does not change what later coils see."""
    program = lower_ok(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n",
                contact("a", "in1"),
                coil("c1", "in1", "negated"),
                parallel("p", [coil("c2", "C")], [coil("c3", "D", "set")]),
                coil("c4", "E", "reset"),
            ),
        )
    )
    body = statements(program, "Main", "n")
    writes = [s for s in body if isinstance(s, (ir.Assign, ir.If)) and s.origin.element != "a"]
    assert writes[:2] == [
        ir.Assign(var("IN1"), ir.Unary("NOT", P, BOOL), at("n", "c1")),
        ir.Assign(var("C"), P, at("n", "c2")),
    ]
    assert writes[2] == ir.If([(P, [ir.Assign(var("D"), ir.Const(True, BOOL), at("n", "c3"))])], [], at("n", "c3"))
    assert writes[3] == ir.Assign(P1, ir.Binary("OR", P, P, BOOL), at("n", "p"))
    assert writes[4] == ir.If([(P1, [ir.Assign(var("E"), ir.Const(False, BOOL), at("n", "c4"))])], [], at("n", "c4"))


def test_gr24_gr25_edge_coils_keep_a_memory_of_the_power():
    program = lower_ok(ld_pou("Main", DECL, rung("n", contact("a", "in1"), coil("p", "C", "p"), coil("m", "D", "n"))))
    mp, mn = var("__P_M"), var("__M_M")
    assert statements(program, "Main", "n")[2:] == [
        ir.Assign(var("C"), ir.Binary("AND", P, ir.Unary("NOT", mp, BOOL), BOOL), at("n", "p")),
        ir.Assign(mp, P, at("n", "p")),
        ir.Probe("p", P, at("n", "p")),
        ir.Assign(var("D"), ir.Binary("AND", mn, ir.Unary("NOT", P, BOOL), BOOL), at("n", "m")),
        ir.Assign(mn, P, at("n", "m")),
        ir.Probe("m", P, at("n", "m")),
    ]


def test_power_temporaries_are_shared_by_networks_but_edge_memories_are_per_element():
    networks = [
        rung(f"n{i}", contact(f"a{i}", "in1", "p"), contact(f"b{i}", "in2"), coil(f"c{i}", "C")) for i in range(50)
    ]
    program = lower_ok(ld_pou("Main", DECL, *networks))
    hidden = [s for s in program.pous["MAIN"].slots if s.hidden]
    assert [s.name for s in hidden if s.var_class == "VAR_TEMP"] == ["__P", "__P_1"]
    assert len([s for s in hidden if s.var_class == "VAR"]) == 50


def test_invariant7_edge_memory_lives_in_the_fb_instance():
    """Two instances of an LD FB with a P contact each get their own memory: it is a slot of the FB POU."""
    fb = ld_pou(
        "Pulse",
        "VAR_INPUT x : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR",
        rung("n", contact("edge", "x", "p"), coil("out", "q")),
        kind="function_block",
    )
    main = ld_pou(
        "Main",
        "VAR u1, u2 : Pulse; a : BOOL; END_VAR",
        rung("n1", contact("a1", "a"), box("b1", "Pulse", "u1")),
        rung("n2", contact("a2", "a"), box("b2", "Pulse", "u2")),
    )
    program = lower_ok(fb, main)
    assert [s.name for s in program.pous["PULSE"].slots if s.hidden and s.var_class == "VAR"] == ["__EDGE_M"]
    assert [s.type for s in program.pous["MAIN"].slots if s.name in ("U1", "U2")] == [FbInstance("PULSE")] * 2


def test_box_power_enters_the_first_free_bool_input_and_leaves_from_the_first_bool_output():
    """GR-27: TON's IN gets the rung's power, Q carries it on; the instance's outputs are probed per pin."""
    program = lower_ok(
        ld_pou("Main", DECL, rung("n", contact("a", "in1"), box("t", "TON", "t1", PT="T#10s"), coil("c", "C")))
    )
    body = statements(program, "Main", "n")
    q = var("T1", BOOL, ir.Member("Q"))
    assert body[2:8] == [
        ir.FbCall(
            var("T1", FbInstance("TON")), [("IN", P), ("PT", ir.Const(10000, Elementary("TIME")))], [], at("n", "t")
        ),
        ir.Assign(P1, q, at("n", "t")),
        ir.Probe("t", P1, at("n", "t")),
        ir.Probe("t.Q", q, at("n", "t")),
        ir.Probe("t.ET", var("T1", Elementary("TIME"), ir.Member("ET")), at("n", "t")),
        ir.Assign(var("C"), P1, at("n", "c")),
    ]


def test_box_with_en_calls_only_when_powered_and_probes_only_then():
    """LD-08: ADD with EN; ENO is the right-side power; with EN FALSE nothing of the box is recorded."""
    program = lower_ok(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n",
                contact("a", "in1"),
                box("add", "ADD", en=True, IN1="n", IN2="1", outputs={"OUT": "n"}),
                coil("c", "C"),
            ),
        )
    )
    body = statements(program, "Main", "n")
    call = ir.Call("ADD", (var("N", INT), ir.Const(1, INT)), (INT, INT), INT)
    assert body[2:5] == [
        ir.FnCall(call, var("N", INT), at("n", "add"), P, P1),
        ir.If(
            [(P, [ir.Probe("add", P1, at("n", "add")), ir.Probe("add.OUT", var("N", INT), at("n", "add"))])],
            [],
            at("n", "add"),
        ),
        ir.Assign(var("C"), P1, at("n", "c")),
    ]


def test_series_lists_feeding_box_inputs_run_first_in_pin_order():
    program = lower_ok(
        ld_pou(
            "Main",
            "VAR c : CTUD; up, down, r, q : BOOL; END_VAR",
            rung(
                "n",
                box("ctud", "CTUD", "c", CD=[contact("d", "down", "nc")], R=[contact("rr", "r")], PV="5"),
                coil("q", "q"),
            ),
        )
    )
    body = statements(program, "Main", "n")
    assert [s.element if isinstance(s, ir.Probe) else type(s).__name__ for s in body[:5]] == [
        "Assign",
        "d",
        "Assign",
        "rr",
        "FbCall",
    ]
    assert body[4].inputs[:3] == [("CU", ir.Const(True, BOOL)), ("CD", P), ("R", P1)]


def test_gr05c_jumps_and_returns_act_after_the_whole_network():
    program = lower_ok(
        ld_pou(
            "Main",
            DECL,
            rung(
                "n1",
                parallel(
                    "p", [contact("a", "in1"), jump("j", "Skip")], [contact("b", "in2"), ret("r")], [coil("c", "C")]
                ),
            ),
            rung("n2", coil("d", "D")),
            rung("n3", coil("e", "E"), label="skip"),
        )
    )
    body = statements(program, "Main", "n1")
    assert body[-2:] == [
        ir.Jump("SKIP", P, at("n1", "j")),
        ir.If([(P1, [ir.Return(at("n1", "r"))])], [], at("n1", "r")),
    ]
    assert [s.element for s in body if isinstance(s, ir.Probe)] == ["a", "j", "b", "r", "c", "p"]
    assert body[-3] == ir.Probe("p", P2, at("n1", "p"))
    assert [b.label for b in program.pous["MAIN"].blocks] == [None, None, "SKIP"]


def test_unconditional_jump_and_return_from_the_left_rail():
    program = lower_ok(ld_pou("Main", DECL, rung("n1", jump("j", "end")), rung("n2", ret("r"), label="END")))
    assert statements(program, "Main", "n1")[-1] == ir.Jump("END", None, at("n1", "j"))
    assert statements(program, "Main", "n2")[-1] == ir.Return(at("n2", "r"))
