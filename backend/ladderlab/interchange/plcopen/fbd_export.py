"""FBD body -> PLCopen ``<FBD>``: nodes map 1:1 to elements, wires to ``connection``s on their input.

Block pins come from the callee's interface (``plcopen_blocks``) plus any pin a
wire or a pin flag names; ``negated``/``edge`` pin flags become the PLCopen pin
attributes. Input/output nodes become ``inVariable``/``outVariable`` (set/reset
/edge/negated output modes become ``storage``/``edge``/``negated``), jumps,
returns, connectors and continuations their namesakes. Networks are drawn one
below the other; nodes without a position get one from a small column layout
(column = longest path from a source). ``executionOrderId`` is the order the FBD
lowering runs the nodes in (``ir/fbd_order.py``), so CFC-style readers such as
RuSTy execute the same order (for a CFC chart, the chart's execution order
numbers, CFC-02); the network's own ``order`` list travels in LadderLab's addData.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections import defaultdict
from decimal import Decimal

from ...ir.fbd_order import analyse
from ...model.diagnostics import Diagnostic
from ...model.fbd import (
    Block,
    Connector,
    FbdComment,
    FbdJump,
    FbdLabel,
    FbdNetwork,
    FbdNode,
    FbdReturn,
    InputNode,
    OutputNode,
    Position,
)
from .blocks import Signatures
from .body import Counter, write_header
from .xml_io import formatted_text, ladderlab_data, position, sub

PIN_STEP = 20
NODE_W = 80
_EDGE = {"p": "rising", "n": "falling"}
_STORAGE = {"set": "set", "reset": "reset"}


def _ignore(*_args: object, **_kwargs: object) -> None:
    """Structural problems of a network are the lowering's to report; the export writes what is there."""


def _auto_positions(network: FbdNetwork) -> dict[str, Position]:
    """Positions for nodes that have none: column = longest wire path from a source, rows in node order.

    Columns are relaxed once per node (a wire cycle, allowed in FBD, cannot push them further).
    """
    ids = [n.id for n in network.nodes]
    column = dict.fromkeys(ids, 0)
    for _ in ids:
        changed = False
        for wire in network.wires:
            if (
                wire.from_.node in column
                and wire.to.node in column
                and column[wire.to.node] < column[wire.from_.node] + 1 <= len(ids)
            ):
                column[wire.to.node] = column[wire.from_.node] + 1
                changed = True
        if not changed:
            break
    placed = [n.pos for n in network.nodes if n.pos is not None]
    base_y = max(p.y for p in placed) + 100.0 if placed else 0.0
    rows: dict[int, int] = defaultdict(int)
    out = {}
    for node in network.nodes:
        if node.pos is None:
            out[node.id] = Position(x=column[node.id] * 150.0, y=base_y + rows[column[node.id]] * 80.0)
            rows[column[node.id]] += 1
    return out


class FbdExporter:
    """Writes the networks of one FBD body into an ``<FBD>`` element; bad wires are collected as problems."""

    def __init__(self, parent: ET.Element, signatures: Signatures, counter: Counter, pou: str):
        self.parent = parent
        self.signatures = signatures
        self.counter = counter
        self.pou = pou
        self.problems: list[Diagnostic] = []

    def network(self, network: FbdNetwork, top: float, explicit: bool = False) -> tuple[Decimal, float]:
        """Write one network below ``top``; returns (the y offset its positions were drawn at, its bottom).
        ``explicit``: a CFC chart, whose execution order numbers are its order list's (CFC-02).

        Element y = position y + offset, added exactly (decimal) so the import subtracts it back exactly.
        """
        positions = {n.id: n.pos for n in network.nodes if n.pos is not None} | _auto_positions(network)
        xs = [p.x for p in positions.values()] or [0.0]
        top = write_header(
            self.parent, self.counter, network.id, network.label, network.comment, top, max(xs) - min(xs) + 2 * NODE_W
        )
        min_y = min([0.0, *(p.y for p in positions.values())])
        offset = Decimal(repr(float(top))) - Decimal(repr(min_y))
        nodes = {n.id: n for n in network.nodes}
        local_ids = {n.id: self.counter.next_local() for n in network.nodes}
        order = {node_id: self.counter.next_order() for node_id in analyse(network, _ignore, explicit).order}
        incoming: dict[tuple[str, str], list] = defaultdict(list)
        self.wire_index = {id(wire): i for i, wire in enumerate(network.wires)}
        for wire in network.wires:
            if wire.from_.node not in nodes or wire.to.node not in nodes:
                missing = wire.from_.node if wire.from_.node not in nodes else wire.to.node
                self.problems.append(
                    Diagnostic(
                        code="PLCOPEN-EXPORT",
                        pou=self.pou,
                        network=network.id,
                        message=f"a wire names the node '{missing}', which this network does not have",
                    )
                )
                continue
            incoming[(wire.to.node, wire.to.pin)].append(wire)
        bottom = top
        for node in network.nodes:
            pos = positions[node.id]
            y_exact = Decimal(repr(pos.y)) + offset
            height = self.node(node, local_ids, order.get(node.id), incoming, pos.x, y_exact, positions, nodes)
            y = float(y_exact)
            ladderlab_data(
                self.parent[-1],
                {
                    "id": node.id,
                    "network": network.id,
                    "pos": "auto" if node.pos is None else None,
                    "pins": " ".join(node.pins) if isinstance(node, Block) and node.pins is not None else None,
                    "size": "auto"
                    if isinstance(node, FbdComment) and (node.width is None or node.height is None)
                    else None,
                },
            )
            bottom = max(bottom, y + height)
        return offset, bottom

    # ------------------------------------------------------------ nodes

    def block_pins(self, block: Block, wired_in: list[str], wired_out: list[str]) -> tuple[list, list, list]:
        sig = self.signatures(block.call)
        flagged = list(block.pins or {})
        if sig is None:
            in_outs: list[str] = []
            inputs = _unique([*wired_in, *(p for p in flagged if p not in wired_out)])
            outputs = _unique(wired_out)
        else:
            in_outs = [name for name, _ in sig.in_outs]
            inputs = sig.input_names(p for p in [*wired_in, *flagged] if p not in in_outs)
            outputs = _unique([*(name for name, _ in sig.outputs), *(p for p in wired_out if p not in in_outs)])
        inputs = [p for p in inputs if p.upper() not in ("EN", "ENO")]
        outputs = [p for p in outputs if p.upper() not in ("EN", "ENO")]
        if block.en or any(p.upper() == "EN" for p in wired_in):  # a wire to EN is kept even without ``en``
            inputs = ["EN", *inputs]
        if block.en or any(p.upper() == "ENO" for p in wired_out):
            outputs = ["ENO", *outputs]
        return inputs, in_outs, outputs

    def node(
        self,
        node: FbdNode,
        local_ids: dict[str, int],
        order: int | None,
        incoming: dict[tuple[str, str], list],
        x: float,
        y_exact: Decimal,
        positions: dict[str, Position],
        nodes: dict[str, FbdNode],
    ) -> float:
        """Append the element for ``node`` at (x, y_exact); returns its height."""
        local_id = local_ids[node.id]
        y = float(y_exact)
        offset = float(y_exact) - positions[node.id].y

        def connect(holder: ET.Element, wires: list, end_x: float, end_y: float) -> None:
            for wire in wires:
                source = nodes[wire.from_.node]
                param = wire.from_.pin if isinstance(source, Block) else None
                connection = sub(holder, "connection", {"refLocalId": local_ids[source.id], "formalParameter": param})
                position(connection, "position", end_x, end_y)
                start = positions[source.id]
                position(connection, "position", start.x + NODE_W, start.y + offset + 10)
                ladderlab_data(connection, {"wire": self.wire_index[id(wire)]})  # the model's wire order

        def single_input(element: ET.Element) -> None:
            holder = sub(element, "connectionPointIn")
            position(holder, "relPosition", 0, 10)
            wires = [w for (target, _), ws in incoming.items() if target == node.id for w in ws]
            connect(holder, wires, x, y + 10)

        if isinstance(node, Block):
            wired_in = _unique(pin for (target, pin) in incoming if target == node.id)
            wired_out = _unique(w.from_.pin for ws in incoming.values() for w in ws if w.from_.node == node.id)
            inputs, in_outs, outputs = self.block_pins(node, wired_in, wired_out)
            rows = max(len(inputs), len(outputs)) + len(in_outs)
            height = PIN_STEP * rows + 30
            element = sub(
                self.parent,
                "block",
                {
                    "localId": local_id,
                    "width": NODE_W,
                    "height": height,
                    "typeName": node.call,
                    "instanceName": node.instance,
                    "executionOrderId": order,
                },
            )
            position(element, "position", x, y_exact)
            flags = node.pins or {}

            def pin(parent: ET.Element, name: str) -> ET.Element:
                flag = flags.get(name)
                return sub(
                    parent,
                    "variable",
                    {
                        "formalParameter": name,
                        "negated": True if flag and flag.negated else None,
                        "edge": flag.edge if flag else None,
                    },
                )

            holder_in = sub(element, "inputVariables")
            for row, name in enumerate(inputs):
                holder = sub(pin(holder_in, name), "connectionPointIn")
                position(holder, "relPosition", 0, 30 + PIN_STEP * row)
                connect(holder, incoming.get((node.id, name), []), x, y + 30 + PIN_STEP * row)
            holder_io = sub(element, "inOutVariables")
            for row, name in enumerate(in_outs, start=max(len(inputs), len(outputs))):
                variable = pin(holder_io, name)
                holder = sub(variable, "connectionPointIn")
                position(holder, "relPosition", 0, 30 + PIN_STEP * row)
                connect(holder, incoming.get((node.id, name), []), x, y + 30 + PIN_STEP * row)
                position(sub(variable, "connectionPointOut"), "relPosition", NODE_W, 30 + PIN_STEP * row)
            holder_out = sub(element, "outputVariables")
            for row, name in enumerate(outputs):
                position(sub(pin(holder_out, name), "connectionPointOut"), "relPosition", NODE_W, 30 + PIN_STEP * row)
            return height
        if isinstance(node, InputNode):
            element = sub(
                self.parent,
                "inVariable",
                {"localId": local_id, "height": 20, "width": NODE_W, "executionOrderId": order},
            )
            position(element, "position", x, y_exact)
            position(sub(element, "connectionPointOut"), "relPosition", NODE_W, 10)
            sub(element, "expression").text = node.expr
            return 20
        if isinstance(node, OutputNode):
            element = sub(
                self.parent,
                "outVariable",
                {
                    "localId": local_id,
                    "height": 20,
                    "width": NODE_W,
                    "executionOrderId": order,
                    "negated": True if node.mode == "negated" else None,
                    "edge": _EDGE.get(node.mode),
                    "storage": _STORAGE.get(node.mode),
                },
            )
            position(element, "position", x, y_exact)
            single_input(element)
            sub(element, "expression").text = node.var
            return 20
        if isinstance(node, (FbdJump, FbdReturn)):
            attrs: dict[str, object] = {"localId": local_id, "height": 20, "width": NODE_W}
            if isinstance(node, FbdJump):
                attrs["label"] = node.target
            attrs["executionOrderId"] = order
            element = sub(self.parent, "jump" if isinstance(node, FbdJump) else "return", attrs)
            position(element, "position", x, y_exact)
            single_input(element)
            return 20
        if isinstance(node, FbdLabel):  # a CFC chart's label (TC6 <label>, with its execution order number)
            attrs = {"localId": local_id, "height": 20, "width": NODE_W, "label": node.name, "executionOrderId": order}
            position(sub(self.parent, "label", attrs), "position", x, y_exact)
            return 20
        if isinstance(node, FbdComment):  # a free comment box: its size as drawn (issue 28)
            width, height = node.width or NODE_W, node.height or 40
            element = sub(self.parent, "comment", {"localId": local_id, "height": height, "width": width})
            position(element, "position", x, y_exact)
            formatted_text(element, "content", node.text)
            return height
        tag = "connector" if isinstance(node, Connector) else "continuation"
        element = sub(self.parent, tag, {"name": node.name, "localId": local_id, "height": 20, "width": NODE_W})
        position(element, "position", x, y_exact)
        if isinstance(node, Connector):
            single_input(element)
        else:
            position(sub(element, "connectionPointOut"), "relPosition", NODE_W, 10)
        return 20


def _unique(names) -> list[str]:
    out: list[str] = []
    for name in names:
        if name not in out:
            out.append(name)
    return out
