"""Equivalence property for richer FBD networks (issues 8, 28): generated networks of BOOL, INT (every arithmetic
operator, MOVE, extensible ADD/MUL), compare and select blocks, TON/CTU instances, EN/ENO, negated and edge pin flags, negated outputs, output nodes of every mode,
feedback loops (through an FB output and through a function's output variable), and forward jumps - the
exported ST runs like the diagram (st_support.same_traces, 200 scans of random writes)."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model import fbd
from ladderlab.model.project import Pou
from tests.interchange.st_support import same_traces
from tests.ir.diagram_support import fjump, inp, out, project, wire

DECLARATIONS = "VAR i0, i1, i2, o0, o1, o2 : BOOL; c0, c1 : INT; t0, t1 : TON; k0, k1 : CTU; END_VAR"
BOOL_VARS, INT_VARS = ["i0", "i1", "i2", "o0", "o1", "o2"], ["c0", "c1"]
FLAGS = [None, None, {"negated": True}, {"edge": "rising"}, {"edge": "falling"}]
KINDS = ["bool", "bool", "int", "compare", "select", "timer", "counter", "accumulate", "oscillate"]


class _Builder:
    def __init__(self, draw, prefix: str):
        self.draw, self.prefix = draw, prefix
        self.nodes: list = []
        self.wires: list = []
        self.pool: dict[str, list[str]] = {"BOOL": [], "INT": []}

    def id(self, stem: str) -> str:
        return f"{self.prefix}{stem}{len(self.nodes)}"

    def add(self, node) -> None:
        node.pos = fbd.Position(x=0.0, y=float(len(self.nodes)))
        self.nodes.append(node)

    def source(self, ty: str) -> str:
        """An existing output pin of ``ty``, or a new input node (a variable or, for INT, a literal)."""
        if self.pool[ty] and self.draw(st.booleans()):
            return self.draw(st.sampled_from(self.pool[ty]))
        name = self.id("in")
        text = self.draw(st.sampled_from(BOOL_VARS if ty == "BOOL" else INT_VARS + ["1", "3"]))
        self.add(inp(name, text))
        return f"{name}.OUT"

    def connect(self, source: str, target: str) -> None:
        self.wires.append(wire(source, target))

    def block(
        self, call: str, instance: str | None, inputs: dict[str, str], outputs: dict[str, str], flags: bool = True
    ) -> str:
        name = self.id(call.lower())
        en = self.draw(st.booleans()) and self.draw(st.booleans())
        pins = {}
        for pin, ty in inputs.items():
            self.connect(self.source(ty), f"{name}.{pin}")
            flag = self.draw(st.sampled_from(FLAGS)) if ty == "BOOL" and flags else None
            if flag is not None:
                pins[pin] = fbd.PinFlags(**flag)
        if en:
            self.connect(self.source("BOOL"), f"{name}.EN")
        for pin, ty in outputs.items():
            if ty == "BOOL" and self.draw(st.integers(0, 4)) == 0:
                pins[pin] = fbd.PinFlags(negated=True)
            self.pool[ty].append(f"{name}.{pin}")
        if en:
            self.pool["BOOL"].append(f"{name}.ENO")
        self.add(fbd.Block(id=name, call=call, instance=instance, en=en, pins=pins or None))
        return name

    def kind(self, kind: str) -> None:
        draw = self.draw
        if kind == "bool":
            call = draw(st.sampled_from(["AND", "OR", "XOR", "NOT"]))
            count = 1 if call == "NOT" else draw(st.integers(2, 3))
            self.block(
                call, None, {f"IN{n + 1}" if call != "NOT" else "IN": "BOOL" for n in range(count)}, {"OUT": "BOOL"}
            )
        elif kind == "int":  # issue 28: the operators (a zero divisor stops both runs in the same scan)
            call = draw(st.sampled_from(["ADD", "SUB", "MUL", "MAX", "DIV", "MOD", "MOVE"]))
            inputs = {"IN": "INT"} if call == "MOVE" else {f"IN{n + 1}": "INT" for n in range(2)}
            if call in ("ADD", "MUL") and draw(st.booleans()):
                inputs["IN3"] = "INT"
            self.block(call, None, inputs, {"OUT": "INT"})
        elif kind == "compare":
            call = draw(st.sampled_from(["GT", "GE", "EQ", "LE", "LT", "NE"]))
            self.block(call, None, {"IN1": "INT", "IN2": "INT"}, {"OUT": "BOOL"})
        elif kind == "select":
            self.block("SEL", None, {"G": "BOOL", "IN0": "INT", "IN1": "INT"}, {"OUT": "INT"})
        elif kind == "timer":
            name = self.block("TON", draw(st.sampled_from(["t0", "t1"])), {"IN": "BOOL"}, {"Q": "BOOL"})
            self.add(inp(f"{name}pt", "T#20ms"))
            self.connect(f"{name}pt.OUT", f"{name}.PT")
        elif kind == "counter":
            self.block(
                "CTU",
                draw(st.sampled_from(["k0", "k1"])),
                {"CU": "BOOL", "R": "BOOL", "PV": "INT"},
                {"Q": "BOOL", "CV": "INT"},
            )
        elif kind == "accumulate":  # GR-06: c := c + x through the feedback wire and the output variable
            name, target = self.id("acc"), draw(st.sampled_from(INT_VARS))
            self.add(fbd.Block(id=name, call="ADD"))
            self.connect(f"{name}.OUT", f"{name}.IN1")
            self.connect(self.source("INT"), f"{name}.IN2")
            self.add(out(f"{name}o", target))
            self.connect(f"{name}.OUT", f"{name}o.IN")
        else:  # a TON that restarts itself: IN is its own Q, negated, from the previous scan
            name = self.id("osc")
            self.add(
                fbd.Block(
                    id=name,
                    call="TON",
                    instance=draw(st.sampled_from(["t0", "t1"])),
                    pins={"IN": fbd.PinFlags(negated=True)},
                )
            )
            self.add(inp(f"{name}pt", "T#30ms"))
            self.connect(f"{name}.Q", f"{name}.IN")
            self.connect(f"{name}pt.OUT", f"{name}.PT")
            self.pool["BOOL"].append(f"{name}.Q")


@st.composite
def networks(draw, index: int, count: int) -> fbd.FbdNetwork:
    builder = _Builder(draw, f"n{index}")
    for kind in draw(st.lists(st.sampled_from(KINDS), min_size=1, max_size=5)):
        builder.kind(kind)
    for number in range(draw(st.integers(1, 3))):
        name = builder.id("out")
        if builder.pool["INT"] and draw(st.booleans()):
            builder.add(out(name, draw(st.sampled_from(INT_VARS))))
            builder.connect(draw(st.sampled_from(builder.pool["INT"])), f"{name}.IN")
        else:
            mode = draw(st.sampled_from(["normal", "negated", "set", "reset", "p", "n"]))
            builder.add(out(name, draw(st.sampled_from(BOOL_VARS[3:])), mode))
            builder.connect(builder.source("BOOL"), f"{name}.IN")
    if index < count - 1 and draw(st.booleans()):
        name = builder.id("jmp")
        builder.add(fjump(name, f"L{draw(st.integers(index + 1, count - 1))}"))
        builder.connect(builder.source("BOOL"), f"{name}.IN")
    return fbd.FbdNetwork(id=f"n{index}", label=f"L{index}", nodes=builder.nodes, wires=builder.wires)


@st.composite
def programs(draw) -> Pou:
    count = draw(st.integers(1, 3))
    body = fbd.FbdBody(networks=[draw(networks(index, count)) for index in range(count)])
    return Pou(name="Main", kind="program", language="fbd", declarations=DECLARATIONS, body=body)


@given(programs(), st.integers(0, 2**16))
def test_property_generated_fbd_networks_export_to_st_that_runs_identically(pou, seed):
    same_traces(project(pou), seed=seed)
