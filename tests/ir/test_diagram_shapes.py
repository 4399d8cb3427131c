"""Box call templates (ir/diagram_shapes.py, issue 5): a box whose shape was checked and lowered once gets exactly
the IR and the diagnostics the full ST check and lowering give it.

The property draws LD and FBD POUs of boxes over a small pool of callees (standard functions and FBs, a user
FB and a user function in ST), instances and operands - variables of several types, FB outputs, constants,
literals, expressions, unknown names, wrong instances, negated pins, EN - so that many boxes share a shape
and many are wrong, and lowers each project with and without templates.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.ir import diagram_shapes
from ladderlab.ir.context import PouContext
from ladderlab.ir.diagram_operands import At, Operands
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import fbd
from ladderlab.model.project import Pou
from ladderlab.st.checker import check_project
from tests.ir.diagram_support import blk, box, contact, fbd_pou, inp, ld_pou, net, out, project, rung

DECLARATIONS = """VAR
    b0, b1, b2 : BOOL; i0, i1 : INT; d0 : DINT; r0 : REAL; t0 : TIME; s0 : STRING;
    tn0, tn1 : TON; cu0 : CTU; u0, u1 : MyFb;
END_VAR
VAR CONSTANT kc : INT := 3; END_VAR"""
MY_FB = Pou(
    name="MyFb",
    kind="function_block",
    language="st",
    declarations="VAR_INPUT a : INT; b : BOOL; END_VAR VAR_OUTPUT q : INT; END_VAR",
    body="q := a;",
)
TWICE = Pou(
    name="Twice",
    kind="function",
    return_type="INT",
    language="st",
    declarations="VAR_INPUT x : INT; END_VAR",
    body="Twice := x * 2;",
)

# callee -> its pins and the operands that suit each (another operand is drawn now and then)
CALLEES = {
    "TON": ({"IN": ["b0", "b1", "tn1.Q"], "PT": ["t0", "T#1s", "tn1.ET"]}, ["tn0", "tn1"]),
    "CTU": ({"CU": ["b0", "b1"], "R": ["b2", "FALSE"], "PV": ["i0", "5", "cu0.CV"]}, ["cu0"]),
    "ADD": ({"IN1": ["i0", "i1", "u0.q"], "IN2": ["i1", "1", "cu0.CV"], "IN3": ["i0", "d0"]}, [None]),
    "GT": ({"IN1": ["i0", "r0", "d0"], "IN2": ["i1", "2.5", "5"]}, [None]),
    "SEL": ({"G": ["b0", "b1"], "IN0": ["i0", "5"], "IN1": ["i1", "i0 + 1"]}, [None]),
    "AND": ({"IN1": ["b0", "b1", "tn0.Q"], "IN2": ["b1", "b0", "TRUE"]}, [None]),
    "MyFb": ({"A": ["i0", "i1", "3"], "B": ["b0", "b1"]}, ["u0", "u1"]),
    "Twice": ({"X": ["i0", "i1", "kc"]}, [None]),
}
OTHER_OPERANDS = ["kc", "s0", "t0", "r0", "d0", "tn0", "nosuch", "i0 + 1", "T#1s", "2.5"]
OTHER_INSTANCES = [None, "tn0", "u1", "i0", "kc"]


@st.composite
def boxes(draw):
    """(callee, instance, en, EN operand, [(pin, operand, negated)]): mostly well-formed, sometimes not."""
    call = draw(st.sampled_from(sorted(CALLEES)))
    pins, instances = CALLEES[call]
    odd = st.integers(0, 19).map(lambda n: n == 0)  # something wrong, now and then
    instance = draw(st.sampled_from(OTHER_INSTANCES) if draw(odd) else st.sampled_from(instances))
    fb = instances != [None]
    wired = []
    for pin, suits in pins.items():
        if (fb and draw(st.integers(0, 4)) == 0) or draw(odd):
            continue  # left unconnected
        operand = draw(st.sampled_from(OTHER_OPERANDS) if draw(odd) else st.sampled_from(suits))
        wired.append((pin, operand, draw(st.integers(0, 3)) == 0))
    if draw(odd):
        wired.append(("IN9", "i0", False))
    en = draw(st.booleans()) if fb else not draw(odd)  # a function box in LD takes the power at EN
    return call, instance, en, draw(st.sampled_from(["b0", "b1", "TRUE", "i0"])), wired


def ld_program(drawn: list) -> Pou:
    networks = []
    for n, (call, instance, en, _, pins) in enumerate(drawn):
        networks.append(
            rung(
                f"n{n}",
                contact(f"c{n}", "b0"),
                box(f"x{n}", call, instance, en, **{pin: operand for pin, operand, _ in pins}),
            )
        )
    return ld_pou("Main", DECLARATIONS, *networks)


def fbd_program(drawn: list) -> Pou:
    networks = []
    for n, (call, instance, en, en_operand, pins) in enumerate(drawn):
        nodes: list = [blk(f"x{n}", call, instance, en)]
        wires = [(f"v{n}{pin}.OUT", f"x{n}.{pin}") for pin, _, _ in pins]
        nodes += [inp(f"v{n}{pin}", operand) for pin, operand, _ in pins]
        flags = {pin: fbd.PinFlags(negated=True) for pin, _, negated in pins if negated}
        nodes[0].pins = flags or None
        if en:
            nodes.append(inp(f"e{n}", en_operand))
            wires.append((f"e{n}.OUT", f"x{n}.EN"))
        if call not in ("TON", "CTU", "MyFb"):
            nodes.append(out(f"o{n}", "i1" if call in ("ADD", "SEL", "Twice") else "b2"))
            wires.append((f"x{n}.OUT", f"o{n}.IN"))
        networks.append(net(f"n{n}", nodes, wires))
    return fbd_pou("Main", DECLARATIONS, *networks)


def lowered(pou: Pou) -> tuple[str, list[str]]:
    result = lower_project(project(pou, MY_FB, TWICE))
    return repr(result.program), [repr(d) for d in result.diagnostics]


def without_templates(monkeypatch: pytest.MonkeyPatch, pou: Pou) -> tuple[str, list[str]]:
    with monkeypatch.context() as patch:
        patch.setattr(diagram_shapes.CallShapes, "shape", lambda *_args: None)
        return lowered(pou)


@given(st.lists(boxes(), min_size=2, max_size=12), st.sampled_from([ld_program, fbd_program]))
def test_property_templated_boxes_lower_as_the_full_check_does(drawn, language):
    pou = language(drawn)
    with pytest.MonkeyPatch.context() as monkeypatch:
        assert lowered(pou) == without_templates(monkeypatch, pou)


def test_alike_boxes_are_bound_from_one_template(monkeypatch):
    """Two TON boxes and two AND blocks with a negated pin, differing only in their variables: the second of each
    is bound from its shape's template, and its IR is what the full check gives."""
    bound: list[str] = []
    original = diagram_shapes.Template.bind

    def spy(self, leaves, result, origin):
        bound.append(origin.element)
        return original(self, leaves, result, origin)

    monkeypatch.setattr(diagram_shapes.Template, "bind", spy)
    ld_main = ld_program(
        [("TON", "tn0", False, "", [("PT", "T#1s", False)]), ("TON", "tn1", False, "", [("PT", "T#1s", False)])]
    )
    fbd_main = fbd_program(
        [
            ("AND", None, False, "", [("IN1", "b0", False), ("IN2", "b1", True)]),
            ("AND", None, False, "", [("IN1", "b1", False), ("IN2", "b0", True)]),
        ]
    )
    for pou in (ld_main, fbd_main):
        assert lowered(pou) == without_templates(monkeypatch, pou)
    assert bound == ["x1", "x1"]


def test_boxes_of_other_shapes_get_their_own_check():
    """An INT where the first box had a TIME variable, and a CONSTANT, are not the first box's shape: each is
    checked in full and reported at its own box."""
    pou = ld_program(
        [
            ("TON", "tn0", False, "", [("PT", "t0", False)]),
            ("TON", "tn1", False, "", [("PT", "i0", False)]),
            ("TON", "tn1", False, "", [("PT", "kc", False)]),
            ("TON", "tn1", False, "", [("PT", "t0", False)]),
        ]
    )
    diagnostics = [d.format() for d in lower_project(project(pou, MY_FB, TWICE)).diagnostics]
    assert diagnostics == [
        f"POU Main, network {n}, TON tn1.PT: error ST-TYPE-MISMATCH: input PT of TON: expected TIME, got "
        "INT without a conversion such as INT_TO_TIME"
        for n in (2, 3)
    ]


def test_what_a_muted_check_reports_is_taken_back():
    """A template's placeholder check reports nothing to the POU, even what the lowering reports directly."""
    checked_project = project(ld_pou("Main", DECLARATIONS, rung("n0", contact("c", "b0"))))
    checked = check_project(checked_project)
    ctx = PouContext(checked, checked.pou("Main"), [])
    ctx.report("LD-MISSING-PIN", "reported before", network="n0")
    ops = Operands(ctx, "LD")
    with ops.muted() as reported:
        ops.report(At("n0", "x"), "LD-NOT-BOOL", "muted")
        ctx.report("ST-TYPE-MISMATCH", "reported to the POU directly", network="n0")
    assert reported == ["LD-NOT-BOOL", "ST-TYPE-MISMATCH"]
    assert [d.code for d in ctx.diagnostics] == ["LD-MISSING-PIN"]
    ctx.report("ST-TYPE-MISMATCH", "reported to the POU directly", network="n0")  # not taken for a duplicate
    assert [d.code for d in ctx.diagnostics] == ["LD-MISSING-PIN", "ST-TYPE-MISMATCH"]
