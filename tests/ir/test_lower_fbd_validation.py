"""FBD validation (issue 5 "Validation"): every problem is a diagnostic with POU, network, element and pin."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir.lower_project import lower_project
from ladderlab.model import fbd
from tests.ir.diagram_support import (
    blk,
    connector,
    continuation,
    errors,
    fbd_pou,
    fjump,
    inp,
    net,
    out,
    project,
    wire,
)

DECL = (
    "VAR a, b : BOOL; n, m : INT; t1 : TON; c1 : CTU; END_VAR VAR CONSTANT kc : BOOL := TRUE; END_VAR "
    "VAR_INPUT inb : BOOL; END_VAR"
)
WHERE = "POU Main, network n1, element"

CASES = {
    "unknown variable": (
        net("n1", [inp("i", "Strat"), out("o", "a")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, input Strat: error ST-UNKNOWN-VAR: unknown variable 'Strat'",
    ),
    "write to a CONSTANT": (
        net("n1", [inp("i", "b"), out("o", "kc")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, output kc: error ST-CONST-WRITE: 'kc' is a CONSTANT and cannot be assigned",
    ),
    "write to an input": (
        net("n1", [inp("i", "b"), out("o", "inb", "set")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, set output inb: error FBD-INPUT-WRITE: 'inb' is an input of Main: assigning it overwrites the caller's value",
    ),
    "set output on a non-BOOL variable": (
        net("n1", [inp("i", "b"), out("o", "n", "set")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, set output n: error FBD-NOT-BOOL: the output needs a BOOL variable; 'n' is INT",
    ),
    "set output fed a non-BOOL value": (
        net("n1", [inp("i", "n"), out("o", "a", "set")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, set output a: error FBD-NOT-BOOL: the output needs a BOOL value, got INT",
    ),
    "type mismatch into an output node": (
        net(
            "n1",
            [inp("i", "n"), blk("g", "ADD"), out("o", "a")],
            [("i.OUT", "g.IN1"), ("i.OUT", "g.IN2"), ("g.OUT", "o.IN")],
        ),
        "POU Main, network 1, output a: error ST-TYPE-MISMATCH: the output: expected BOOL, got INT without a conversion such as INT_TO_BOOL",
    ),
    "unknown function": (
        net("n1", [blk("x", "ADDD")], []),
        "POU Main, network 1, ADDD: error FBD-UNKNOWN-CALL: unknown function or function block 'ADDD' - did you mean 'ADD'?",
    ),
    "FB without an instance": (
        net("n1", [blk("x", "TON")], []),
        "POU Main, network 1, TON: error FBD-NO-INSTANCE: the function block TON needs an instance: declare one (e.g. inst : TON;) and name it in the box",
    ),
    "instance of another FB type": (
        net("n1", [blk("x", "TON", "c1")], []),
        "POU Main, network 1, TON c1: error FBD-INSTANCE-TYPE: 'c1' is a CTU, not a TON instance",
    ),
    "dangling function input": (
        net("n1", [inp("i", "n"), blk("x", "ADD"), out("o", "m")], [("i.OUT", "x.IN1"), ("x.OUT", "o.IN")]),
        "POU Main, network 1, ADD.IN2: error FBD-MISSING-PIN: input IN2 of ADD is not connected",
    ),
    "input without operand": (
        net("n1", [inp("i", ""), out("o", "a")], [("i.OUT", "o.IN")]),
        "POU Main, network 1, input (no operand): error FBD-MISSING-OPERAND: the input has no operand",
    ),
    "dangling output node": (
        net("n1", [out("o", "a")], []),
        "POU Main, network 1, output a: error FBD-DANGLING: the output has no input wire",
    ),
    "dangling EN": (
        net("n1", [blk("x", "TON", "t1", en=True)], []),
        "POU Main, network 1, TON t1.EN: error FBD-MISSING-PIN: input EN is not connected",
    ),
    "unknown input pin": (
        net("n1", [inp("i", "n"), blk("x", "TON", "t1")], [("i.OUT", "x.XX")]),
        "POU Main, network 1, TON t1.XX: error ST-CALL-ARGS: TON has no parameter 'XX'",
    ),
    "unknown output pin": (
        net("n1", [blk("x", "TON", "t1"), out("o", "a")], [("x.QQ", "o.IN")]),
        "POU Main, network 1, TON t1.QQ: error FBD-UNKNOWN-PIN: TON has no output 'QQ' - did you mean 'Q'?",
    ),
    "EN without en": (
        net("n1", [inp("i", "a"), blk("x", "TON", "t1")], [("i.OUT", "x.EN")]),
        "POU Main, network 1, TON t1.EN: error FBD-UNKNOWN-PIN: the block has no EN: switch on EN/ENO to use it",
    ),
    "ENO without en": (
        net("n1", [blk("x", "TON", "t1"), out("o", "a")], [("x.ENO", "o.IN")]),
        "POU Main, network 1, TON t1.ENO: error FBD-UNKNOWN-PIN: the block has no ENO: switch on EN/ENO to use it",
    ),
    "a wire into ENO without en": (
        net("n1", [inp("i", "a"), blk("x", "TON", "t1")], [("i.OUT", "x.ENO")]),
        "POU Main, network 1, TON t1.ENO: error FBD-UNKNOWN-PIN: the block has no ENO: switch on EN/ENO to use it",
    ),
    "type mismatch on a pin": (
        net("n1", [inp("i", "n"), blk("x", "TON", "t1")], [("i.OUT", "x.PT")]),
        "POU Main, network 1, TON t1.PT: error ST-TYPE-MISMATCH: input PT of TON: expected TIME, got INT without a conversion such as INT_TO_TIME",
    ),
    "negated pin that is not BOOL": (
        net("n1", [inp("i", "n"), blk("x", "TON", "t1", PT={"negated": True})], [("i.OUT", "x.PT")]),
        "POU Main, network 1, TON t1.PT: error FBD-NOT-BOOL: the negated input PT needs a BOOL value, got INT",
    ),
    "edge flag on an output": (
        net("n1", [blk("x", "TON", "t1", Q={"edge": "rising"})], []),
        "POU Main, network 1, TON t1.Q: error FBD-PIN-FLAG: output Q cannot have an edge flag: edge detection is for inputs",
    ),
    "flags for a pin the block lacks": (
        net("n1", [blk("x", "TON", "t1", ZZ={"negated": True})], []),
        "POU Main, network 1, TON t1.ZZ: error FBD-UNKNOWN-PIN: TON has no pin 'ZZ' for the flags",
    ),
    "cycle without a feedback value": (
        net("n1", [blk("c", "ABS")], [("c.OUT", "c.IN")]),
        "POU Main, network 1, ABS.IN: error FBD-FEEDBACK: the wire from ABS.OUT to ABS.IN closes a loop, and nothing outside the loop gives ABS.OUT a type: connect a typed variable to one of its inputs, or its output to an output variable",
    ),
    "wired OR": (
        net("n1", [inp("i", "a"), inp("k", "b"), out("o", "a")], [("i.OUT", "o.IN"), ("k.OUT", "o.IN")]),
        "POU Main, network 1, output a: error FBD-WIRED-OR: 2 wires lead into it (from input a and from input b): FBD has no wired OR, use an OR block",
    ),
    "unknown jump target": (
        net("n1", [inp("i", "a"), fjump("j", "nowhere")], [("i.OUT", "j.IN")]),
        "POU Main, network 1, jump to nowhere: error FBD-UNKNOWN-LABEL: jump to 'nowhere', but no network of this POU has that label",
    ),
    "jump on a non-BOOL value": (
        net("n1", [inp("i", "n"), fjump("j", "L")], [("i.OUT", "j.IN")]),
        "POU Main, network 1, jump to L: error FBD-NOT-BOOL: the jump needs a BOOL value, got INT",
    ),
    "unknown order entry": (
        net("n1", [], [], order=["ghost"]),
        "POU Main, network 1: error FBD-ORDER: the network's execution order names a node it does not have ('ghost')",
    ),
    "connector named like a variable": (
        net(
            "n1",
            [inp("i", "a"), connector("k", "B"), continuation("c", "b"), out("o", "a")],
            [("i.OUT", "k.IN"), ("c.OUT", "o.IN")],
        ),
        "POU Main, network 1, connector B: error FBD-CONNECTOR: connector 'B' has the name of a variable of this POU",
    ),
    "duplicate node id": (
        net("n1", [inp("i", "a"), out("i", "b")], []),
        "POU Main, network 1, output b: error FBD-DUPLICATE-ID: an element of network 1 has the same id 'i': element ids must be unique in the POU (was the file edited by hand?)",
    ),
}


@pytest.mark.parametrize("name", list(CASES))
def test_validation_diagnostic(name):
    network, expected = CASES[name]
    assert errors(fbd_pou("Main", DECL, network, net("n2", [], [], label="L"))) == [expected]


def test_in_out_needs_a_variable():
    swap = fbd_pou("Bump", "VAR_IN_OUT x : INT; END_VAR", kind="function_block")
    main = fbd_pou(
        "Main",
        "VAR n : INT; u : Bump; END_VAR",
        net(
            "n1",
            [inp("i", "n"), blk("add", "ADD"), blk("b", "Bump", "u")],
            [("i.OUT", "add.IN1"), ("i.OUT", "add.IN2"), ("add.OUT", "b.X")],
        ),
    )
    assert errors(swap, main) == [
        "POU Main, network 1, Bump u.X: error FBD-IN-OUT: in-out X of Bump needs a variable, not a computed value"
    ]


# ------------------------------------------------------------------ never an exception

_exprs = st.sampled_from(["a", "b", "n", "kc", "inb", "t1.Q", "zz", "", "1", "T#1s", "a AND"])
_ids = st.sampled_from(["a", "b", "c", "d", "e", "f"])
_pins = st.sampled_from(["IN", "IN1", "IN2", "OUT", "Q", "PT", "EN", "ENO", "CU", "X"])


@st.composite
def _networks(draw, index: int):
    nodes = []
    for node_id in draw(st.lists(_ids, unique=True, max_size=6)):
        kind = draw(st.sampled_from(["input", "output", "block", "jump", "return", "connector", "continuation"]))
        if kind == "input":
            nodes.append(inp(node_id, draw(_exprs)))
        elif kind == "output":
            nodes.append(out(node_id, draw(_exprs), draw(st.sampled_from(["normal", "set", "n"]))))
        elif kind == "block":
            flags = draw(
                st.dictionaries(
                    _pins,
                    st.fixed_dictionaries({"negated": st.booleans(), "edge": st.sampled_from([None, "rising"])}),
                    max_size=2,
                )
            )
            nodes.append(
                blk(
                    node_id,
                    draw(st.sampled_from(["ADD", "AND", "TON", "CTU", "NOT", "Nope"])),
                    draw(st.sampled_from([None, "t1", "c1"])),
                    draw(st.booleans()),
                    **flags,
                )
            )
        elif kind in ("connector", "continuation"):
            node_type = fbd.Connector if kind == "connector" else fbd.Continuation
            nodes.append(node_type(id=node_id, name=draw(st.sampled_from(["k", "K", "j"]))))
        else:
            nodes.append(
                fjump(node_id, draw(st.sampled_from(["L", "x"]))) if kind == "jump" else fbd.FbdReturn(id=node_id)
            )
    wires = draw(st.lists(st.tuples(_ids, _pins, _ids, _pins), max_size=8))
    return fbd.FbdNetwork(
        id=f"n{index}",
        label=draw(st.sampled_from([None, "L"])),
        nodes=nodes,
        wires=[wire(f"{a}.{p}", f"{b}.{q}") for a, p, b, q in wires],
        order=draw(st.one_of(st.none(), st.lists(_ids, max_size=3))),
    )


@given(
    st.lists(st.integers(0, 0), min_size=1, max_size=3).flatmap(
        lambda items: st.tuples(*[_networks(i) for i in range(len(items))])
    )
)
def test_property_any_fbd_lowers_or_reports_located_diagnostics(networks):
    result = lower_project(project(fbd_pou("Main", DECL, *networks)))
    for diagnostic in result.diagnostics:
        assert diagnostic.pou == "Main" and diagnostic.network is not None, diagnostic
    assert (result.program is None) == any(d.severity == "error" for d in result.diagnostics)


def test_a_program_in_a_block_a_bit_as_output_and_a_malformed_label():
    """The diagram checks FBD shares with LD (docs/diagnostics.md): each reported at its block, output or network.
    An output node writing a bit (``w.3``) is accepted since issue 25 (tests/engine/test_partial_access.py)."""
    other = fbd_pou("Other", "")
    main = fbd_pou(
        "Main",
        "VAR a : BOOL; w : WORD; END_VAR",
        net("n1", [blk("x", "Other")], []),
        net("n2", [inp("i", "a"), out("o", "w.3")], [("i.OUT", "o.IN")]),
        net("n3", [], [], label="2go"),
        kind="function_block",
    )
    assert errors(main, other) == [
        "POU Main, network 3 \"2go\": error FBD-BAD-LABEL: network label '2go' must be an identifier or an unsigned "
        "integer",
        "POU Main, network 1, Other: error FBD-NOT-CALLABLE: a function block cannot call the program Other: only "
        "programs call programs",
    ]
