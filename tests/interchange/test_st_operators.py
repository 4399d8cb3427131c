"""Standard functions as ST operators (issue 28, ST-02, ST-03, ST-04): the exact text of FBD networks covering every
operator and every pair of precedence levels, with only the parentheses the precedence table needs, and the same
traces as the diagrams.

The expected texts come from the seed's precedence table (ST-02, Table 4.5) and left-to-right grouping (ST-03),
written out below independently of the ST printer: ``expected`` puts a child in parentheses when it binds more
loosely than its parent, or as tightly on the right of a left-associative operator.
"""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from tests.interchange.st_support import body, exported, same_traces
from tests.ir.diagram_support import blk, fbd_pou, inp, net, out, project

DECLARATIONS = (
    "VAR i1, i2, i3, ri : INT; b1, b2, b3, rb : BOOL; r1 : REAL := 1.5; r2 : REAL := 2.0; r3 : REAL := 0.5; "
    "rr : REAL; END_VAR"
)

#: ST-02 (seed 000, Table 4.5), loosest first; higher binds tighter.
LEVEL = {"OR": 1, "XOR": 2, "AND": 3, "=": 4, "<>": 4, "<": 5, ">": 5, "<=": 5, ">=": 5}
LEVEL |= {"+": 6, "-": 6, "*": 7, "/": 7, "MOD": 7, "NOT": 8, "**": 9}
SYMBOL = {"ADD": "+", "SUB": "-", "MUL": "*", "DIV": "/", "MOD": "MOD", "EXPT": "**", "AND": "AND", "OR": "OR"}
SYMBOL |= {"XOR": "XOR", "GT": ">", "GE": ">=", "EQ": "=", "LE": "<=", "LT": "<", "NE": "<>", "NOT": "NOT"}
ARITHMETIC = ["ADD", "SUB", "MUL", "DIV", "MOD"]
BOOLEAN = ["AND", "OR", "XOR"]
COMPARISONS = ["GT", "GE", "EQ", "LE", "LT", "NE"]


@dataclass
class Op:
    """A block (``call``) of operands: variable names or nested blocks."""

    call: str
    operands: list


def expected(node, parent: str | None = None, right: bool = False) -> str:
    """``node`` as ST with the parentheses ST-02/ST-03 need under ``parent`` (operators group left to right)."""
    if isinstance(node, str):
        return node
    symbol = SYMBOL[node.call]
    if symbol == "NOT":
        text = f"NOT {expected(node.operands[0], 'NOT')}"
    else:
        parts = [expected(node.operands[0], symbol)]
        parts += [expected(operand, symbol, right=True) for operand in node.operands[1:]]
        text = f" {symbol} ".join(parts)
    if parent is not None and (LEVEL[symbol] < LEVEL[parent] or (right and LEVEL[symbol] == LEVEL[parent])):
        return f"({text})"
    return text


def network(tree: Op, target: str, index: int):
    """The FBD network of ``tree``: an input node per variable, a block per operator, one output node."""
    nodes, wires = [], []

    def build(node) -> str:
        if isinstance(node, str):
            name = f"n{index}in{len(nodes)}"
            nodes.append(inp(name, node))
            return f"{name}.OUT"
        name = f"n{index}b{len(nodes)}"
        nodes.append(blk(name, node.call))
        pins = ["IN"] if node.call in ("NOT", "MOVE") else [f"IN{n + 1}" for n in range(len(node.operands))]
        for pin, operand in zip(pins, node.operands):
            wires.append((build(operand), f"{name}.{pin}"))
        return f"{name}.OUT"

    nodes.append(out(f"n{index}out", target))
    wires.append((build(tree), f"n{index}out.IN"))
    return net(f"net{index}", nodes, wires)


def cases() -> list[tuple[Op, str]]:
    """Every operator inside every other of its kind, on either side; comparisons and NOT across levels."""
    found: list[tuple[Op, str]] = []
    for outer in ARITHMETIC:
        for inner in ARITHMETIC:
            found.append((Op(outer, [Op(inner, ["i1", "i2"]), "i3"]), "ri"))
            found.append((Op(outer, ["i3", Op(inner, ["i1", "i2"])]), "ri"))
    for outer in BOOLEAN:
        for inner in BOOLEAN:
            found.append((Op(outer, [Op(inner, ["b1", "b2"]), "b3"]), "rb"))
            found.append((Op(outer, ["b3", Op(inner, ["b1", "b2"])]), "rb"))
    for compare in COMPARISONS:
        found.append((Op(compare, [Op("ADD", ["i1", "i2"]), Op("MUL", ["i3", "i1"])]), "rb"))
        found.append((Op("AND", [Op(compare, ["i1", "i2"]), "b1"]), "rb"))
        found.append((Op("NOT", [Op(compare, ["i1", "i2"])]), "rb"))
    for outer in ("EQ", "NE"):
        for inner in ("EQ", "LT", "AND"):
            found.append((Op(outer, [Op(inner, ["b1", "b2"]), "b3"]), "rb"))
            found.append((Op(outer, ["b3", Op(inner, ["b1", "b2"])]), "rb"))
    for outer, inner in (("EXPT", "EXPT"), ("EXPT", "MUL"), ("MUL", "EXPT"), ("ADD", "EXPT")):
        found.append((Op(outer, [Op(inner, ["r1", "r2"]), "r3"]), "rr"))
        found.append((Op(outer, ["r3", Op(inner, ["r1", "r2"])]), "rr"))
    found.append((Op("NOT", [Op("AND", ["b1", "b2"])]), "rb"))
    found.append((Op("AND", [Op("NOT", ["b1"]), Op("NOT", [Op("OR", ["b2", "b3"])])]), "rb"))
    found.append((Op("XOR", [Op("NOT", [Op("NOT", ["b1"])]), "b2"]), "rb"))  # NOT NOT x is x
    found.append((Op("ADD", ["i1", "i2", "i3"]), "ri"))
    found.append((Op("AND", ["b1", Op("OR", ["b2", "b3"]), "b1"]), "rb"))
    found.append((Op("MOVE", [Op("SUB", ["i1", Op("SUB", ["i2", "i3"])])]), "ri"))
    return found


def text_of(tree: Op) -> str:
    """The exported statement: ``NOT NOT x`` cancels (a double inversion is the variable), else ``expected``."""
    if tree.call == "XOR" and isinstance(tree.operands[0], Op) and tree.operands[0].call == "NOT":
        return f"b1 XOR {tree.operands[1]}"
    if tree.call == "MOVE":
        return expected(tree.operands[0])
    return expected(tree)


CASES = cases()


@pytest.mark.parametrize("tree, target", CASES, ids=[text_of(tree) for tree, _ in CASES])
def test_st02_every_operator_pair_has_only_the_parentheses_precedence_needs(tree, target):
    pou = fbd_pou("Main", DECLARATIONS, network(tree, target, 1))
    assert body(exported(project(pou), "Main").text) == f"(* Network 1 *)\n{target} := {text_of(tree)};\n"


def test_hand_written_forms_of_the_issue():
    """Issue 28: ``result := (var1 + var2) - var3`` is ``result := var1 + var2 - var3``; ``a - (b - c)`` keeps its
    parentheses; ``NOT (a AND b)`` keeps them; ``a > b AND c < d`` needs none (ST-03's example)."""
    trees = [
        (Op("SUB", [Op("ADD", ["i1", "i2"]), "i3"]), "ri", "ri := i1 + i2 - i3;"),
        (Op("SUB", ["i1", Op("SUB", ["i2", "i3"])]), "ri", "ri := i1 - (i2 - i3);"),
        (Op("NOT", [Op("AND", ["b1", "b2"])]), "rb", "rb := NOT (b1 AND b2);"),
        (Op("AND", [Op("GT", ["i1", "i2"]), Op("LT", ["i3", "i1"])]), "rb", "rb := i1 > i2 AND i3 < i1;"),
        (Op("MUL", [Op("ADD", ["i1", "i2"]), Op("MOD", ["i3", "i1"])]), "ri", "ri := (i1 + i2) * (i3 MOD i1);"),
        (Op("EXPT", [Op("EXPT", ["r1", "r2"]), "r3"]), "rr", "rr := r1 ** r2 ** r3;"),
        (Op("OR", [Op("AND", ["b1", "b2"]), Op("XOR", ["b3", "b1"])]), "rb", "rb := b1 AND b2 OR b3 XOR b1;"),
    ]
    for index, (tree, target, text) in enumerate(trees):
        pou = fbd_pou("Main", DECLARATIONS, network(tree, target, index))
        assert body(exported(project(pou), "Main").text) == f"(* Network 1 *)\n{text}\n"


def test_functions_without_an_operator_stay_formal_calls_and_take_operator_arguments():
    pou = fbd_pou(
        "Main",
        DECLARATIONS,
        net(
            "n1",
            [inp("lo", "0"), inp("a", "i1"), inp("b", "i2"), blk("add", "ADD"), inp("hi", "100"), blk("lim", "LIMIT")]
            + [out("o", "ri"), inp("c", "i1"), inp("d", "i2"), inp("e", "i3"), blk("gt", "GT"), out("o2", "rb")],
            [
                ("lo.OUT", "lim.MN"),
                ("a.OUT", "add.IN1"),
                ("b.OUT", "add.IN2"),
                ("add.OUT", "lim.IN"),
                ("hi.OUT", "lim.MX"),
                ("lim.OUT", "o.IN"),
                ("c.OUT", "gt.IN1"),
                ("d.OUT", "gt.IN2"),
                ("e.OUT", "gt.IN3"),
                ("gt.OUT", "o2.IN"),
            ],
        ),
    )
    assert body(exported(project(pou), "Main").text) == (
        "(* Network 1 *)\nri := LIMIT(MN := 0, IN := i1 + i2, MX := 100);\nrb := GT(IN1 := i1, IN2 := i2, IN3 := i3);\n"
    )
    same_traces(project(pou))


def test_every_operator_case_runs_like_the_diagram():
    """All cases as one program, scan by scan (the divisions apart: a zero divisor stops both in the same scan)."""
    dividing = [case for case in CASES if "DIV" in repr(case[0]) or "MOD" in repr(case[0])]
    others = [case for case in CASES if case not in dividing]
    for group in (others, dividing):
        networks = [network(tree, target, index) for index, (tree, target) in enumerate(group)]
        same_traces(project(fbd_pou("Main", DECLARATIONS, *networks)), scans=60)
