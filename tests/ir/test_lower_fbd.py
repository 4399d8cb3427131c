"""FBD lowering: the IR it produces (data-flow order, pin flags, EN/ENO, feedback, probes) - GR-05, GR-06, GR-29..31."""

from __future__ import annotations

from pathlib import Path

from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_fbd import evaluation_order
from ladderlab.ir.lower_project import lower_project
from ladderlab.ir.types import Elementary, FbInstance
from ladderlab.storage.load import read_project_folder
from tests.ir.diagram_support import (
    blk,
    check_diagram_program,
    connector,
    continuation,
    fbd_pou,
    fjump,
    fret,
    inp,
    lower_ok,
    net,
    out,
    probes,
    statements,
)
from tests.support import EXAMPLES

BOOL, INT, REAL, TIME = (Elementary(n) for n in ("BOOL", "INT", "REAL", "TIME"))
DECL = "VAR a, b, c, q : BOOL; n, m : INT; r : REAL; t1 : TON; run : BOOL := TRUE; END_VAR"


def var(name: str, ty=BOOL, *path) -> ir.Var:
    return ir.Var("local", name, ty, tuple(path))


def at(element: str, network: str = "n") -> ir.Origin:
    return ir.Origin("MAIN", network=network, element=element)


def test_scaling_example_runs_in_data_flow_order_with_a_probe_per_pin():
    project = read_project_folder(Path(EXAMPLES / "motor"))
    result = lower_project(project)
    check_diagram_program(result.program)
    assert probes(result.program, "Scaling") == [
        "count",
        "ten",
        "mul.OUT",
        "five",
        "add.OUT",
        "speed_out",
        "limit",
        "gt.OUT",
        "high",
    ]
    assert evaluation_order(project.pou("Scaling").body.networks[0]) == [
        "count",
        "ten",
        "mul",
        "five",
        "add",
        "speed_out",
        "limit",
        "gt",
        "high",
    ]


def test_function_result_goes_to_a_temporary_that_consumers_read():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("x", "n"), inp("y", "2"), blk("add", "ADD"), out("o", "m")],
                [("x.OUT", "add.IN1"), ("y.OUT", "add.IN2"), ("add.OUT", "o.IN")],
            ),
        )
    )
    result = var("__T", INT)
    assert statements(program, "Main", "n") == [
        ir.Probe("x", var("N", INT), at("x")),
        ir.Probe("y", ir.Const(2, INT), at("y")),
        ir.FnCall(ir.Call("ADD", (var("N", INT), ir.Const(2, INT)), (INT, INT), INT), result, at("add")),
        ir.Probe("add.OUT", result, at("add")),
        ir.Assign(var("M", INT), result, at("o")),
        ir.Probe("o", result, at("o")),
    ]
    assert next(s for s in program.pous["MAIN"].slots if s.name == "__T").var_class == "VAR_TEMP"


def test_one_input_node_is_typed_for_each_pin_it_feeds():
    """The literal 2 becomes an INT for ADD(n, 2) and a REAL for ADD(r, 2), as it would in ST."""
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [
                    inp("two", "2"),
                    inp("x", "n"),
                    inp("y", "r"),
                    blk("i", "ADD"),
                    blk("f", "ADD"),
                    out("oi", "m"),
                    out("of", "r"),
                ],
                [
                    ("x.OUT", "i.IN1"),
                    ("two.OUT", "i.IN2"),
                    ("y.OUT", "f.IN1"),
                    ("two.OUT", "f.IN2"),
                    ("i.OUT", "oi.IN"),
                    ("f.OUT", "of.IN"),
                ],
            ),
        )
    )
    calls = [s.call for s in statements(program, "Main", "n") if isinstance(s, ir.FnCall)]
    assert [c.args[1] for c in calls] == [ir.Const(2.0, REAL), ir.Const(2, INT)]  # f, i: unplaced, by id


def test_gr29_negated_input_and_output_pins():
    """FBD-02: a negation circle inverts the BOOL pin; consumers of a negated output read the inverted value."""
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [
                    inp("x", "a"),
                    inp("y", "b"),
                    blk("and", "AND", IN2={"negated": True}, OUT={"negated": True}),
                    out("o", "q"),
                ],
                [("x.OUT", "and.IN1"), ("y.OUT", "and.IN2"), ("and.OUT", "o.IN")],
            ),
        )
    )
    body = statements(program, "Main", "n")
    result, inverted = var("__P"), var("__P_1")
    assert body[2:] == [
        ir.FnCall(ir.Call("AND", (var("A"), ir.Unary("NOT", var("B"), BOOL)), (BOOL, BOOL), BOOL), result, at("and")),
        ir.Assign(inverted, ir.Unary("NOT", result, BOOL), at("and")),
        ir.Probe("and.OUT", inverted, at("and")),
        ir.Assign(var("Q"), inverted, at("o")),
        ir.Probe("o", inverted, at("o")),
    ]


def test_edge_flag_is_an_r_trig_in_front_of_the_pin():
    program = lower_ok(
        fbd_pou(
            "Main",
            "VAR x : BOOL; c : CTU; END_VAR",
            net("n", [inp("i", "x"), blk("ctu", "CTU", "c", R={"edge": "falling"})], [("i.OUT", "ctu.R")]),
        )
    )
    body = statements(program, "Main", "n")
    memory, edge = var("__CTU_R_M"), var("__P")
    assert body[1:4] == [
        ir.Assign(edge, ir.Binary("AND", memory, ir.Unary("NOT", var("X"), BOOL), BOOL), at("ctu")),
        ir.Assign(memory, var("X"), at("ctu")),
        ir.FbCall(var("C", FbInstance("CTU")), [("R", edge)], [], at("ctu")),
    ]


def test_en_eno_block_and_probes_recorded_only_when_it_runs():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("go", "a"), inp("x", "n"), blk("mul", "MUL", en=True), out("o", "m"), out("ok", "q")],
                [
                    ("go.OUT", "mul.EN"),
                    ("x.OUT", "mul.IN1"),
                    ("x.OUT", "mul.IN2"),
                    ("mul.OUT", "o.IN"),
                    ("mul.ENO", "ok.IN"),
                ],
            ),
        )
    )
    body = statements(program, "Main", "n")
    result, eno = var("__MUL_OUT", INT), var("__P")  # kept between scans (EN), ENO a temporary
    assert body[2:4] == [
        ir.FnCall(ir.Call("MUL", (var("N", INT), var("N", INT)), (INT, INT), INT), result, at("mul"), var("A"), eno),
        ir.If(
            [(var("A"), [ir.Probe("mul.OUT", result, at("mul")), ir.Probe("mul.ENO", eno, at("mul"))])], [], at("mul")
        ),
    ]


def test_gr06_feedback_from_an_fb_output_reads_the_instance_before_it_runs():
    """A TON restarted by its own Q: the NOT block reads t1.Q of the previous scan (it runs first)."""
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [blk("not", "NOT", x=0, y=0), blk("ton", "TON", "t1", x=100, y=0), inp("pt", "T#1s"), out("o", "q")],
                [("ton.Q", "not.IN"), ("not.OUT", "ton.IN"), ("pt.OUT", "ton.PT"), ("ton.Q", "o.IN")],
            ),
        )
    )
    body = statements(program, "Main", "n")
    q = var("T1", BOOL, ir.Member("Q"))
    assert body[0] == ir.Probe("not.IN", q, at("not"))  # online: the value NOT read (issue 22 item 6)
    assert body[1] == ir.FnCall(ir.Call("NOT", (q,), (BOOL,), BOOL), var("__P"), at("not"))
    assert isinstance(body[4], ir.FbCall) and body[4].inputs[0] == ("IN", var("__P"))


def test_gr06_feedback_from_a_function_reads_the_output_variable_it_writes():
    """count := count + 1 drawn as a loop: the wire back into ADD is the variable's previous value."""
    program = lower_ok(
        fbd_pou(
            "Main",
            "VAR count : INT := 5; END_VAR",
            net(
                "n",
                [inp("one", "1"), blk("add", "ADD"), out("o", "count")],
                [("add.OUT", "add.IN1"), ("one.OUT", "add.IN2"), ("add.OUT", "o.IN")],
            ),
        )
    )
    body = statements(program, "Main", "n")
    assert body[1] == ir.Probe("add.IN1", var("COUNT", INT), at("add"))  # online: the value ADD read
    assert body[2].call.args == (var("COUNT", INT), ir.Const(1, INT))


def test_output_node_modes_write_like_coils():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("x", "a"), out("s", "b", "set"), out("r", "c", "reset"), out("neg", "q", "negated")],
                [("x.OUT", "s.IN"), ("x.OUT", "r.IN"), ("x.OUT", "neg.IN")],
            ),
        )
    )
    body = statements(program, "Main", "n")
    assert body[1:] == [  # unplaced nodes run by id: neg, r, s
        ir.Assign(var("Q"), ir.Unary("NOT", var("A"), BOOL), at("neg")),
        ir.Probe("neg", var("A"), at("neg")),
        ir.If([(var("A"), [ir.Assign(var("C"), ir.Const(False, BOOL), at("r"))])], [], at("r")),
        ir.Probe("r", var("A"), at("r")),
        ir.If([(var("A"), [ir.Assign(var("B"), ir.Const(True, BOOL), at("s"))])], [], at("s")),
        ir.Probe("s", var("A"), at("s")),
    ]


def test_jumps_and_returns_come_last_and_connectors_pass_values_through():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [
                    fjump("j", "done"),
                    fret("r"),
                    inp("x", "a"),
                    connector("k", "cond"),
                    continuation("c", "cond"),
                    out("o", "q"),
                    inp("y", "b"),
                ],
                [("x.OUT", "k.IN"), ("c.OUT", "j.IN"), ("c.OUT", "o.IN"), ("y.OUT", "r.IN")],
            ),
            net("n2", [fjump("always", "done")], []),
            net("n3", [], [], label="Done"),
        )
    )
    assert statements(program, "Main", "n") == [
        ir.Probe("x", var("A"), at("x")),
        ir.Assign(var("Q"), var("A"), at("o")),
        ir.Probe("o", var("A"), at("o")),
        ir.Probe("j", var("A"), at("j")),
        ir.Jump("DONE", var("A"), at("j")),
        ir.Probe("y", var("B"), at("y")),
        ir.Probe("r", var("B"), at("r")),
        ir.If([(var("B"), [ir.Return(at("r"))])], [], at("r")),
    ]
    assert statements(program, "Main", "n2")[-1] == ir.Jump("DONE", None, at("always", "n2"))


def test_extensible_inputs_and_user_functions():
    """FBD-02: AND with four inputs; a user function written in ST called from FBD."""
    scale = fbd_pou(
        "Twice",
        "VAR_INPUT x : INT; END_VAR",
        net(
            "n",
            [inp("i", "x"), blk("m", "MUL"), inp("k", "2"), out("o", "Twice")],
            [("i.OUT", "m.IN1"), ("k.OUT", "m.IN2"), ("m.OUT", "o.IN")],
        ),
        kind="function",
    )
    scale.return_type = "INT"
    main = fbd_pou(
        "Main",
        DECL,
        net(
            "n",
            [inp("x", "a"), blk("and", "AND"), blk("tw", "Twice"), inp("v", "n"), out("o", "q"), out("p", "m")],
            [
                *[("x.OUT", f"and.IN{i}") for i in range(1, 5)],
                ("and.OUT", "o.IN"),
                ("v.OUT", "tw.X"),
                ("tw.OUT", "p.IN"),
            ],
        ),
    )
    program = lower_ok(scale, main)
    calls = [s.call for s in statements(program, "Main", "n") if isinstance(s, ir.FnCall)]
    assert calls[0] == ir.Call("AND", (var("A"),) * 4, (BOOL,) * 4, BOOL)
    assert calls[1] == ir.Call("TWICE", (var("N", INT),), (INT,), INT, True)
    assert statements(program, "Twice", "n")[-2] == ir.Assign(
        ir.Var("local", "TWICE", INT), var("__T", INT), ir.Origin("TWICE", network="n", element="o")
    )


def test_gr05_an_input_node_is_evaluated_once_even_when_its_variable_is_written_in_the_network():
    """``a`` feeds two output nodes, one of which writes ``a``: both see the value read by the input node."""
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("x", "a", 0, 0), out("flip", "a", "negated", 10, 0), out("copy", "b", "normal", 10, 10)],
                [("x.OUT", "flip.IN"), ("x.OUT", "copy.IN")],
            ),
        )
    )
    held = var("__P")
    assert statements(program, "Main", "n") == [
        ir.Assign(held, var("A"), at("x")),
        ir.Probe("x", held, at("x")),
        ir.Assign(var("A"), ir.Unary("NOT", held, BOOL), at("flip")),
        ir.Probe("flip", held, at("flip")),
        ir.Assign(var("B"), held, at("copy")),
        ir.Probe("copy", held, at("copy")),
    ]


def test_lab01_an_output_node_fed_by_a_block_with_en_is_written_only_when_the_block_runs():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("go", "a"), inp("x", "n"), blk("add", "ADD", en=True), out("o", "m"), out("ok", "q")],
                [
                    ("go.OUT", "add.EN"),
                    ("x.OUT", "add.IN1"),
                    ("x.OUT", "add.IN2"),
                    ("add.OUT", "o.IN"),
                    ("add.ENO", "ok.IN"),
                ],
            ),
        )
    )
    body = statements(program, "Main", "n")
    result, eno = var("__ADD_OUT", INT), var("__P")
    assert body[-3:] == [
        ir.If([(var("A"), [ir.Assign(var("M", INT), result, at("o")), ir.Probe("o", result, at("o"))])], [], at("o")),
        ir.Assign(var("Q"), eno, at("ok")),
        ir.Probe("ok", eno, at("ok")),
    ]


def test_negated_en_pin_from_an_operand():
    program = lower_ok(
        fbd_pou(
            "Main",
            DECL,
            net(
                "n",
                [inp("stop", "a"), inp("x", "n"), blk("add", "ADD", en=True, EN={"negated": True}), out("o", "m")],
                [("stop.OUT", "add.EN"), ("x.OUT", "add.IN1"), ("x.OUT", "add.IN2"), ("add.OUT", "o.IN")],
            ),
        )
    )
    body = statements(program, "Main", "n")
    not_a = ir.Unary("NOT", var("A"), BOOL)
    assert body[2].en == not_a and body[3] == ir.If(
        [(not_a, [ir.Probe("add.OUT", var("__ADD_OUT", INT), at("add")), ir.Probe("add.ENO", var("__P"), at("add"))])],
        [],
        at("add"),
    )
