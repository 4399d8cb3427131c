"""ST export of FBD networks, one node kind at a time: the exact text, and the same traces as the diagram."""

from __future__ import annotations

from tests.interchange.st_support import body, exported, same_traces
from tests.ir.diagram_support import blk, connector, continuation, fbd_pou, fjump, fret, inp, net, out, project

DECL = "VAR a, b, c, x, y, z, go, ok : BOOL; n, m : INT; t1 : TON; e : TIME; END_VAR"


def check(*networks, expected: str, declarations: str = DECL) -> str:
    pou = fbd_pou("Main", declarations, *networks)
    text = exported(project(pou), "Main").text
    assert body(text) == expected
    same_traces(project(pou))
    return text


def test_gr29_bool_blocks_are_operators_and_a_result_with_two_consumers_is_read_back_from_the_first_output():
    check(
        net(
            "n1",
            [
                inp("ia", "a"),
                inp("ib", "b"),
                blk("and", "AND", IN2={"negated": True}),
                out("ox", "x"),
                out("oy", "y", "set"),
            ],
            [("ia.OUT", "and.IN1"), ("ib.OUT", "and.IN2"), ("and.OUT", "ox.IN"), ("and.OUT", "oy.IN")],
        ),
        expected="(* Network 1 *)\nx := a AND NOT b;\nIF x THEN\n    y := TRUE;\nEND_IF;\n",
    )


def test_fb_block_is_a_formal_call_its_outputs_are_read_from_the_instance_and_an_edge_pin_is_an_r_trig():
    check(
        net(
            "n1",
            [
                inp("ia", "a"),
                inp("pt", "T#50ms"),
                blk("t", "TON", "t1", IN={"edge": "rising"}),
                out("ox", "x"),
                out("oe", "e"),
            ],
            [("ia.OUT", "t.IN"), ("pt.OUT", "t.PT"), ("t.Q", "ox.IN"), ("t.ET", "oe.IN")],
        ),
        expected="(* Network 1 *)\na_rising(CLK := a);\nt1(IN := a_rising.Q, PT := T#50ms);\ne := t1.ET;\nx := t1.Q;\n",
    )


def test_lab01_block_with_en_runs_under_if_its_outputs_are_written_only_then_and_eno_is_tracked():
    """The input node reading n needs no temporary (n is written in the network, GR-05, but only after the call
    read it); ENO is the call's own (a standard function's warning clears it), so the call stays formal."""
    check(
        net(
            "n1",
            [
                inp("g", "go"),
                inp("ia", "n"),
                inp("one", "1"),
                blk("add", "ADD", en=True),
                out("on", "n"),
                out("ok", "ok"),
            ],
            [
                ("g.OUT", "add.EN"),
                ("ia.OUT", "add.IN1"),
                ("one.OUT", "add.IN2"),
                ("add.OUT", "on.IN"),
                ("add.ENO", "ok.IN"),
            ],
        ),
        expected="(* Network 1 *)\nIF go THEN\n"
        "    ADD_OUT := ADD(IN1 := n, IN2 := 1, ENO => ADD_ENO);\nELSE\n    ADD_ENO := FALSE;\nEND_IF;\n"
        "ok := ADD_ENO;\nIF go THEN\n    n := ADD_OUT;\nEND_IF;\n",
    )


def test_gr06_feedback_from_a_function_reads_the_variable_its_result_goes_to():
    check(
        net(
            "n1",
            [inp("one", "1"), blk("add", "ADD", x=0, y=0), out("on", "n")],
            [("add.OUT", "add.IN1"), ("one.OUT", "add.IN2"), ("add.OUT", "on.IN")],
        ),
        expected="(* Network 1 *)\nn := n + 1;\n",
    )


def test_gr06_feedback_from_a_function_without_variable_gets_a_declared_feedback_variable():
    """Issue 22 item 6: ADD's result in no variable - the export declares the lowering's feedback variable."""
    text = check(
        net(
            "n1",
            [inp("one", "1"), blk("add", "ADD", x=0, y=0), inp("three", "3"), blk("ge", "GE"), out("o", "ok")],
            [("add.OUT", "add.IN1"), ("one.OUT", "add.IN2"), ("add.OUT", "ge.IN1"), ("three.OUT", "ge.IN2")]
            + [("ge.OUT", "o.IN")],
        ),
        expected="(* Network 1 *)\nADD_OUT := ADD_OUT_prev + 1;\nADD_OUT_prev := ADD_OUT;\nok := ADD_OUT >= 3;\n",
    )
    assert "ADD_OUT_prev : INT;" in text


def test_gr06_feedback_from_an_fb_output_reads_the_instance_before_the_call():
    check(
        net(
            "n1",
            [inp("pt", "T#30ms"), blk("t", "TON", "t1", IN={"negated": True}), out("ox", "x")],
            [("t.Q", "t.IN"), ("pt.OUT", "t.PT"), ("t.Q", "ox.IN")],
        ),
        expected="(* Network 1 *)\nt1(IN := NOT t1.Q, PT := T#30ms);\nx := t1.Q;\n",
    )


def test_fbd_jump_and_return():
    check(
        net("n1", [inp("ia", "a"), fjump("j", "L")], [("ia.OUT", "j.IN")]),
        net("n2", [inp("ib", "b"), out("ox", "x")], [("ib.OUT", "ox.IN")]),
        net("n3", [inp("ic", "c"), fret("r")], [("ic.OUT", "r.IN")], label="L"),
        net("n4", [inp("ib4", "b"), out("oy", "y")], [("ib4.OUT", "oy.IN")]),
        expected="(* Network 1 *)\nIF NOT a THEN\n    (* Network 2 *)\n    x := b;\nEND_IF;\n"
        '(* Network 3 "L" *)\nIF c THEN\n    RETURN;\nEND_IF;\n(* Network 4 *)\ny := b;\n',
    )


def test_gr02_connector_and_continuation_carry_the_value_and_an_edge_output_is_an_r_trig():
    check(
        net(
            "n1",
            [inp("ia", "a"), connector("k", "w"), continuation("cc", "w"), out("ox", "x", "p")],
            [("ia.OUT", "k.IN"), ("cc.OUT", "ox.IN")],
        ),
        expected="(* Network 1 *)\nx_trig(CLK := a);\nx := x_trig.Q;\n",
    )


def test_gr05_an_input_node_whose_variable_the_network_writes_is_read_where_it_stands():
    """Read before the write, so the operator reads n itself; the unused read (the lowering's temporary) changes
    nothing and is left out."""
    check(
        net(
            "n1",
            [inp("ia", "n"), inp("unused", "n"), blk("add", "ADD"), inp("one", "1"), out("o", "n")],
            [("ia.OUT", "add.IN1"), ("one.OUT", "add.IN2"), ("add.OUT", "o.IN")],
        ),
        expected="(* Network 1 *)\nn := n + 1;\n",
    )


def test_issue28_the_light_control_exercise_reads_as_written_without_a_temporary():
    """Issue 28's light-control exercise (a push button toggles the lamp, a master switch turns it off) was
    ``Lamp := (R_TRIG_1.Q XOR in3) AND NOT MasterOff;`` with a ``VAR_TEMP in3`` named after a node id: the lamp's
    own value is read where the XOR stands, before the network writes it (GR-05), so no temporary is needed."""
    text = check(
        net(
            "n1",
            [
                inp("button", "Button"),
                blk("edge", "R_TRIG", "R_TRIG_1"),
                inp("lamp", "Lamp"),
                blk("xor", "XOR"),
                inp("master", "MasterOff"),
                blk("and", "AND", IN2={"negated": True}),
                out("o", "Lamp"),
            ],
            [
                ("button.OUT", "edge.CLK"),
                ("edge.Q", "xor.IN1"),
                ("lamp.OUT", "xor.IN2"),
                ("xor.OUT", "and.IN1"),
                ("master.OUT", "and.IN2"),
                ("and.OUT", "o.IN"),
            ],
        ),
        declarations="VAR Button, Lamp, MasterOff : BOOL; R_TRIG_1 : R_TRIG; END_VAR",
        expected="(* Network 1 *)\nR_TRIG_1(CLK := Button);\nLamp := (R_TRIG_1.Q XOR Lamp) AND NOT MasterOff;\n",
    )
    assert "VAR_TEMP" not in text and "in3" not in text
