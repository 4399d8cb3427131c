"""Literal typing in LD boxes and FBD blocks (issue 16): the same rule as ST, and their ST export runs the same.

A function box whose result is written to one variable is the ST statement ``y := F(...)``: its literals and
its generic type take that variable's type (docs/st.md, "Literal typing"). Expected values come from the rule,
not from running the implementation.
"""

from __future__ import annotations

import struct

import pytest

from ladderlab.simulation.build import build_project
from tests.interchange.st_support import exported, same_traces
from tests.ir.diagram_support import blk, box, coil, contact, errors, fbd_pou, inp, ld_pou, net, out, project, rung

DECLS = "VAR m : DINT; l : LINT; s : SINT; r : REAL; run : BOOL := TRUE; END_VAR"


def f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


def ld_box(call: str, target: str, **inputs: str):
    return rung(
        "N1", contact("C1", "run"), box("B1", call, en=True, outputs={"OUT": target}, **inputs), coil("Q", "run")
    )


def fbd_block(call: str, target: str, **inputs: str):
    nodes = [inp(f"I{i}", text) for i, text in enumerate(inputs.values())]
    wires = [(f"I{i}.OUT", f"B1.{pin}") for i, pin in enumerate(inputs)] + [("B1.OUT", "Y.IN")]
    return net("N1", [*nodes, blk("B1", call), out("Y", target)], wires)


CASES = [
    ("MAX", "m", {"IN1": "1", "IN2": "100000"}, 100000),
    ("LIMIT", "l", {"MN": "1000000000", "IN": "4000000000", "MX": "3000000000"}, 3000000000),
    ("MAX", "s", {"IN1": "1", "IN2": "2"}, 2),
    ("SEL", "r", {"G": "FALSE", "IN0": "10.5", "IN1": "20.5"}, 10.5),
    ("SQRT", "r", {"IN": "2.0"}, f32(2.0**0.5)),
]


@pytest.mark.parametrize("call, target, inputs, expected", CASES)
@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_box_literals_take_the_type_of_the_variable_the_result_goes_to(language, call, target, inputs, expected):
    pou = (
        ld_pou("Main", DECLS, ld_box(call, target, **inputs))
        if language == "ld"
        else fbd_pou("Main", DECLS, fbd_block(call, target, **inputs))
    )
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sim = build.simulation()
    sim.cycle(1)
    value = sim.read(f"Main.{target}")
    assert value == expected and type(value) is type(expected)
    assert f"{target} :=" in exported(project(pou), "Main").text
    same_traces(project(pou), scans=3)  # the ST export computes the same


@pytest.mark.parametrize("language", ["ld", "fbd"])
def test_a_box_literal_that_does_not_fit_is_a_located_error(language):
    pou = (
        ld_pou("Main", DECLS, ld_box("MAX", "s", IN1="1", IN2="300"))
        if language == "ld"
        else fbd_pou("Main", DECLS, fbd_block("MAX", "s", IN1="1", IN2="300"))
    )
    assert errors(pou) == ["POU Main, network 1, MAX.IN2: error ST-RANGE: 300 is out of range for SINT (-128..127)"]


def fbd_chain(inner: str, inner_inputs: dict[str, str], outer: str, outer_inputs: dict[str, str], target: str):
    """``target := outer(inner(...), ...)`` drawn as two FBD blocks: the inner block's result feeds the outer
    block's first input named in ``outer_inputs`` with the value ``"inner"``."""
    nodes, wires = [blk("B1", inner), blk("B2", outer), out("Y", target)], [("B2.OUT", "Y.IN")]
    for number, (pin, text) in enumerate([*inner_inputs.items()]):
        nodes.append(inp(f"I{number}", text))
        wires.append((f"I{number}.OUT", f"B1.{pin}"))
    for number, (pin, text) in enumerate(outer_inputs.items()):
        if text == "inner":
            wires.append(("B1.OUT", f"B2.{pin}"))
        else:
            nodes.append(inp(f"J{number}", text))
            wires.append((f"J{number}.OUT", f"B2.{pin}"))
    return net("N1", nodes, wires)


CHAINS = [
    # The inner block computes in the type its result is used as, as the nested ST call does: LINT, not DINT
    # (100000 * 100000 in DINT would wrap to 1410065408).
    ("MUL", {"IN1": "100000", "IN2": "100000"}, "ADD", {"IN1": "inner", "IN2": "0"}, "l", 10_000_000_000),
    # SQRT(2.0) in REAL (binary32) because ADD's result goes to a REAL: accepted, no LREAL to narrow.
    ("SQRT", {"IN": "2.0"}, "ADD", {"IN1": "inner", "IN2": "1.0"}, "r", f32(f32(f32(2.0) ** 0.5) + 1.0)),
    # A comparison types its operands alike: MUL(200, 200) compares as a DINT with m (0), 40000 > 0; alone it
    # would compute in INT and wrap to -25536.
    ("MUL", {"IN1": "200", "IN2": "200"}, "GT", {"IN1": "inner", "IN2": "m"}, "run", True),
    # A fixed input type is the context: DINT_TO_LINT's IN makes MAX compute in DINT.
    ("MAX", {"IN1": "1", "IN2": "100000"}, "DINT_TO_LINT", {"IN": "inner"}, "l", 100000),
]


@pytest.mark.parametrize("inner, inner_inputs, outer, outer_inputs, target, expected", CHAINS)
def test_a_chained_block_computes_in_the_type_of_its_place_as_the_nested_st_call(
    inner, inner_inputs, outer, outer_inputs, target, expected
):
    pou = fbd_pou("Main", DECLS, fbd_chain(inner, inner_inputs, outer, outer_inputs, target))
    build = build_project(project(pou))
    assert [d.format() for d in build.diagnostics] == []
    sim = build.simulation()
    sim.cycle(1)
    value = sim.read(f"Main.{target}")
    assert value == expected and type(value) is type(expected)
    same_traces(project(pou), scans=3)  # the ST export (operators where ST has them) computes the same


def test_a_chained_literal_that_does_not_fit_its_place_is_a_located_error():
    """INT_TO_DINT takes an INT: ADD(1, 100000) there is refused as ``INT_TO_DINT(ADD(1, 100000))`` is in ST."""
    pou = fbd_pou("Main", DECLS, fbd_chain("ADD", {"IN1": "1", "IN2": "100000"}, "INT_TO_DINT", {"IN": "inner"}, "m"))
    assert errors(pou) == [
        "POU Main, network 1, ADD.IN2: error ST-RANGE: 100000 is out of range for INT (-32768..32767)"
    ]
