"""LD, FBD and ST versions of one program give identical variable traces (issue 5; LAB-27's cross-editor check).

Hypothesis generates rungs: series/parallel trees of no/nc/p/n contacts over inputs and outputs (so rungs
also read what earlier rungs and scans wrote), one to three coils of any mode, and sometimes an ADD box
with EN counting while the rung conducts. Each program is drawn as LD (contacts, parallels, coils, box),
as FBD (AND/OR blocks, negated and edge pins, output nodes, an ADD block with EN) and written as ST
(R_TRIG/F_TRIG for the edges, IF for set/reset and EN), then run for 200 scans of random inputs.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model import fbd, ld
from ladderlab.model.project import Pou
from tests.ir.diagram_support import blk, coil, contact, fbd_pou, inp, ld_pou, out, parallel, simulate, trace

INPUTS = [f"i{n}" for n in range(4)]
OUTPUTS = [f"o{n}" for n in range(4)]
COUNTERS = ["c0", "c1"]
DECLARATIONS = f"VAR {', '.join(INPUTS + OUTPUTS)} : BOOL; {', '.join(COUNTERS)} : INT; END_VAR"
SCANS = 200


@dataclass(frozen=True)
class Leaf:
    var: str
    mode: str  # no, nc, p, n


@dataclass(frozen=True)
class Gate:
    kind: str  # series (AND), parallel (OR)
    children: tuple


@dataclass(frozen=True)
class Rung:
    condition: object
    coils: tuple[tuple[str, str], ...]  # (mode, variable)
    counter: str | None


def rung_strategy(
    contacts: tuple[str, ...] = ("no", "nc", "p", "n"),
    coils: tuple[str, ...] = ("normal", "negated", "set", "reset", "p", "n"),
    counters: tuple[str | None, ...] = (None, *COUNTERS),
):
    """Rungs with contacts and coils of the given modes (test_ld_il.py draws those IL can express)."""
    leaves = st.builds(Leaf, st.sampled_from(INPUTS + OUTPUTS), st.sampled_from(contacts))
    trees = st.recursive(
        leaves,
        lambda inner: st.builds(
            Gate, st.sampled_from(["series", "parallel"]), st.lists(inner, min_size=2, max_size=3).map(tuple)
        ),
        max_leaves=6,
    )
    outputs = st.tuples(st.sampled_from(coils), st.sampled_from(OUTPUTS))
    return st.builds(Rung, trees, st.lists(outputs, min_size=1, max_size=3).map(tuple), st.sampled_from(counters))


rungs = rung_strategy()


# ------------------------------------------------------------------ LD


@dataclass
class _Ids:
    count: int = 0

    def __call__(self, stem: str) -> str:
        self.count += 1
        return f"{stem}{self.count}"


def ld_series(node, ids: _Ids) -> list:
    if isinstance(node, Leaf):
        return [contact(ids("k"), node.var, node.mode)]
    if node.kind == "series":
        return [element for child in node.children for element in ld_series(child, ids)]
    return [parallel(ids("p"), *[ld_series(child, ids) for child in node.children])]


def ld_program(program: list[Rung]) -> Pou:
    ids = _Ids()
    networks = []
    for index, rung in enumerate(program):
        coils = [coil(ids("q"), var, mode) for mode, var in rung.coils]
        elements = ld_series(rung.condition, ids)
        elements += coils if len(coils) == 1 or index % 2 else [parallel(ids("p"), *[[c] for c in coils])]
        if rung.counter:
            elements.append(
                ld.Box(
                    id=ids("add"),
                    call="ADD",
                    en=True,
                    inputs={"IN1": rung.counter, "IN2": "1"},
                    outputs={"OUT": rung.counter},
                )
            )
        networks.append(ld.LdNetwork(id=f"n{index}", elements=elements))
    return ld_pou("Main", DECLARATIONS, *networks)


# ------------------------------------------------------------------ FBD


@dataclass
class _Net:
    ids: _Ids
    nodes: list = field(default_factory=list)
    wires: list = field(default_factory=list)

    def source(self, node) -> tuple[str, fbd.PinFlags | None]:
        """The output pin carrying ``node``'s value, and the flags its consumer's pin needs."""
        if isinstance(node, Leaf):
            name = self.ids("in")
            self.nodes.append(inp(name, node.var, *self.place()))
            flags = {
                "no": None,
                "nc": fbd.PinFlags(negated=True),
                "p": fbd.PinFlags(edge="rising"),
                "n": fbd.PinFlags(edge="falling"),
            }[node.mode]
            return f"{name}.OUT", flags
        name = self.ids("g")
        pins = {}
        for position, child in enumerate(node.children, 1):
            pin, flags = self.source(child)
            self.wires.append(fbd.Wire.model_validate({"from": _ref(pin), "to": _ref(f"{name}.IN{position}")}))
            if flags is not None:
                pins[f"IN{position}"] = flags
        self.nodes.append(blk(name, "AND" if node.kind == "series" else "OR", None, False, *self.place()))
        self.nodes[-1].pins = pins or None
        return f"{name}.OUT", None

    def plain(self, node) -> str:
        """A pin carrying the value without flags (a MOVE block takes the flags of a lone edge/nc contact)."""
        pin, flags = self.source(node)
        if flags is None:
            return pin
        name = self.ids("mv")
        self.nodes.append(blk(name, "MOVE", None, False, *self.place()))
        self.nodes[-1].pins = {"IN": flags}
        self.wires.append(fbd.Wire.model_validate({"from": _ref(pin), "to": _ref(f"{name}.IN")}))
        return f"{name}.OUT"

    def place(self) -> tuple[float, float]:
        """Nodes are drawn top to bottom in the order they are made, so independent ones run in that order."""
        return 0.0, float(self.ids.count)

    def connect(self, pin: str, target: str) -> None:
        self.wires.append(fbd.Wire.model_validate({"from": _ref(pin), "to": _ref(target)}))


def _ref(text: str) -> dict:
    node, pin = text.split(".")
    return {"node": node, "pin": pin}


def fbd_program(program: list[Rung]) -> Pou:
    ids = _Ids()
    networks = []
    for index, rung in enumerate(program):
        network = _Net(ids)
        root = network.plain(rung.condition)
        for mode, var in rung.coils:
            name = ids("out")
            network.nodes.append(out(name, var, mode, *network.place()))
            network.connect(root, f"{name}.IN")
        if rung.counter:
            add, value, one, result = ids("add"), ids("cnt"), ids("one"), ids("res")
            network.nodes += [
                blk(add, "ADD", None, True, *network.place()),
                inp(value, rung.counter),
                inp(one, "1"),
                out(result, rung.counter, "normal", *network.place()),
            ]
            for pin, target in (
                (root, f"{add}.EN"),
                (f"{value}.OUT", f"{add}.IN1"),
                (f"{one}.OUT", f"{add}.IN2"),
                (f"{add}.OUT", f"{result}.IN"),
            ):
                network.connect(pin, target)
        networks.append(fbd.FbdNetwork(id=f"n{index}", nodes=network.nodes, wires=network.wires))
    return fbd_pou("Main", DECLARATIONS, *networks)


# ------------------------------------------------------------------ ST


def st_program(program: list[Rung]) -> Pou:
    triggers: list[str] = []
    lines: list[str] = []

    def edge(kind: str, clock: str) -> str:
        name = f"e{len(triggers)}"
        triggers.append(f"{name} : {kind};")
        lines.append(f"{name}(CLK := {clock});")
        return f"{name}.Q"

    def expression(node) -> str:
        if isinstance(node, Leaf):
            return {"no": node.var, "nc": f"NOT {node.var}", "p": None, "n": None}[node.mode] or edge(
                "R_TRIG" if node.mode == "p" else "F_TRIG", node.var
            )
        joined = f" {'AND' if node.kind == 'series' else 'OR'} ".join(expression(c) for c in node.children)
        return f"({joined})"

    for index, rung in enumerate(program):
        lines.append(f"r{index} := {expression(rung.condition)};")
        for mode, var in rung.coils:
            lines.append(
                {
                    "normal": f"{var} := r{index};",
                    "negated": f"{var} := NOT r{index};",
                    "set": f"IF r{index} THEN {var} := TRUE; END_IF;",
                    "reset": f"IF r{index} THEN {var} := FALSE; END_IF;",
                }.get(mode)
                or f"{var} := {edge('R_TRIG' if mode == 'p' else 'F_TRIG', f'r{index}')};"
            )
        if rung.counter:
            lines.append(f"IF r{index} THEN {rung.counter} := {rung.counter} + 1; END_IF;")
    rungs_decl = f"VAR {', '.join(f'r{i}' for i in range(len(program)))} : BOOL; END_VAR"
    declarations = f"{DECLARATIONS} {rungs_decl}" + (f" VAR {' '.join(triggers)} END_VAR" if triggers else "")
    return Pou(name="Main", kind="program", language="st", declarations=declarations, body="\n".join(lines))


# ------------------------------------------------------------------ the property


@given(
    st.lists(rungs, min_size=1, max_size=4),
    st.lists(st.integers(0, 2 ** len(INPUTS) - 1), min_size=SCANS, max_size=SCANS),
)
def test_property_ld_fbd_and_st_traces_are_identical(program, masks):
    scans = [{name: bool(mask >> bit & 1) for bit, name in enumerate(INPUTS)} for mask in masks]
    traces = [
        trace(simulate(pou), "Main", scans, OUTPUTS + COUNTERS)
        for pou in (st_program(program), ld_program(program), fbd_program(program))
    ]
    assert traces[1] == traces[0], "LD differs from ST"
    assert traces[2] == traces[0], "FBD differs from ST"
