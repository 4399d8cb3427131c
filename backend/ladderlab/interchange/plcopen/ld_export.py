"""LD body (series/parallel model) -> PLCopen ``<LD>`` graph.

Each element becomes its PLCopen element with a ``localId``; its input lists the
elements feeding it (``connectionPointIn/connection@refLocalId``, with
``@formalParameter`` when the source is a block pin). The branches of a parallel
all start from the parallel's input and the next element lists every branch end:
several connections on one input are the wired OR. A compare contact becomes a
comparison block (GT, EQ, ...) with EN on the power flow and OUT continuing it; a
box becomes a block whose power pins (``plcopen_blocks``) sit on the rung, whose
text inputs are ``inVariable``s, whose series-list inputs are contact chains from
the left rail and whose outputs write ``outVariable``s. Positions come from
``plcopen_layout``; ``executionOrderId`` numbers the elements in evaluation order.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass

from ...model.ld import Box, Coil, Compare, Contact, Jump, LdElement, LdNetwork, Parallel, Return
from .blocks import Signatures
from .body import Counter, write_header
from .layout import CELL_H, RAIL_X, layout_rung, x_of, y_of
from .xml_io import ladderlab_data, position, sub

_CONTACT_EDGE = {"p": "rising", "n": "falling"}
_COIL_STORAGE = {"set": "set", "reset": "reset"}


@dataclass(frozen=True)
class Src:
    """An output point feeding an input: the element's localId, its pin (blocks only) and where it is drawn."""

    local_id: int
    param: str | None
    x: float
    y: float


#: The left power rail as a source (its connection points are made per consumer).
RAIL = Src(0, None, 0, 0)


@dataclass
class BoxPins:
    """A box's block pins in drawing order and the two that carry power flow."""

    inputs: list[str]
    in_outs: list[str]
    outputs: list[str]
    power_in: str
    power_out: str | None
    en: bool

    @property
    def rows(self) -> int:
        return max(len(self.inputs), len(self.outputs)) + len(self.in_outs)


def box_pins(box: Box, signatures: Signatures) -> BoxPins:
    """Pins from the callee's interface; power enters EN when the callee has no input that can be BOOL."""
    sig = signatures(box.call)
    power_in = sig.power_in(box.en, box.inputs) if sig is not None else None
    en = box.en or power_in is None
    power_in = power_in or "EN"
    if sig is None:
        inputs = [p for p in box.inputs if p.upper() != "EN"]
        in_outs: list[str] = []
        outputs = [p for p in box.outputs if p.upper() != "ENO"]
    else:
        in_outs = [name for name, _ in sig.in_outs]
        inputs = sig.input_names(p for p in box.inputs if p not in in_outs)
        outputs = [name for name, _ in sig.outputs]
        outputs += [p for p in box.outputs if p not in outputs and p.upper() != "ENO"]
    power_out = sig.power_out(en) if sig is not None else "ENO"
    if en:
        inputs, outputs = ["EN", *inputs], ["ENO", *outputs]
    return BoxPins(inputs, in_outs, outputs, power_in, power_out, en)


class LdExporter:
    """Writes the networks of one LD body into an ``<LD>`` element."""

    def __init__(self, parent: ET.Element, signatures: Signatures, counter: Counter):
        self.parent = parent
        self.signatures = signatures
        self.counter = counter
        self._pins: dict[int, BoxPins] = {}

    def pins(self, box: Box) -> BoxPins:
        if id(box) not in self._pins:
            self._pins[id(box)] = box_pins(box, self.signatures)
        return self._pins[id(box)]

    def network(self, network: LdNetwork, top: float) -> float:
        """Write one network from y = ``top``; returns its bottom."""
        self.network_id = network.id
        layout = layout_rung(network.elements, lambda box: self.pins(box).rows)
        width = x_of(layout.width) + 2 * RAIL_X
        top = write_header(self.parent, self.counter, network.id, network.label, network.comment, top, width)
        if not network.elements:
            return top
        self.layout, self.top = layout, top
        height = max(layout.height, 1) * CELL_H
        self.left = sub(
            self.parent, "leftPowerRail", {"localId": self.counter.next_local(), "height": height, "width": 10}
        )
        position(self.left, "position", RAIL_X, top)
        self.left_points: set[float] = set()
        end = self.series(network.elements, [RAIL], [])
        right = sub(
            self.parent, "rightPowerRail", {"localId": self.counter.next_local(), "height": height, "width": 10}
        )
        right_x = x_of(layout.width) + RAIL_X
        position(right, "position", right_x, top)
        for src in end:
            y = src.y if src is not RAIL else top + CELL_H / 2
            self.connect(self.connection_in(right, 0, y - top), [src], right_x, y)
        ladderlab_data(right, {"network": network.id})
        ladderlab_data(self.left, {"network": network.id})
        return top + height

    # ------------------------------------------------------------ structure

    def series(self, items: list[LdElement], point: list[Src], path: list[str]) -> list[Src]:
        for item in items:
            point = self.element(item, point, path)
        return point

    def element(self, item: LdElement, point: list[Src], path: list[str]) -> list[Src]:
        if isinstance(item, Parallel):
            outs: list[Src] = []
            for branch in item.branches:
                for src in self.series(branch, point, [*path, item.id]):
                    if src not in outs:
                        outs.append(src)
            return outs
        cell = self.layout.cells[id(item)]
        x, y = x_of(cell.col), y_of(self.top, cell.row)
        if isinstance(item, (Contact, Coil)):
            return [self.contact_or_coil(item, point, path, x + 35, y + 10)]
        if isinstance(item, Compare):
            return [self.compare(item, point, path, cell.col, cell.row)]
        if isinstance(item, Box):
            return self.box(item, point, path, cell.row)
        self.jump_or_return(item, point, path, x + 20, y + 10)
        return []

    # ------------------------------------------------------------ elements

    def ids(self, item: LdElement, path: list[str]) -> dict[str, object]:
        return {"id": item.id, "network": self.network_id, "parallels": " ".join(path) or None}

    def contact_or_coil(self, item: Contact | Coil, point: list[Src], path: list[str], x: float, y: float) -> Src:
        local_id = self.counter.next_local()
        attrs: dict[str, object] = {
            "localId": local_id,
            "height": 20,
            "width": 30,
            "executionOrderId": self.counter.next_order(),
        }
        if isinstance(item, Contact):
            tag, attrs["negated"], attrs["edge"] = "contact", item.mode == "nc", _CONTACT_EDGE.get(item.mode)
        else:
            tag, attrs["negated"] = "coil", item.mode == "negated"
            attrs["edge"], attrs["storage"] = _CONTACT_EDGE.get(item.mode), _COIL_STORAGE.get(item.mode)
        node = sub(self.parent, tag, attrs)
        position(node, "position", x, y)
        self.connect(self.connection_in(node, 0, 10), point, x, y + 10)
        position(sub(node, "connectionPointOut"), "relPosition", 30, 10)
        sub(node, "variable").text = item.var
        ladderlab_data(node, self.ids(item, path))
        return Src(local_id, None, x + 30, y + 10)

    def jump_or_return(self, item: Jump | Return, point: list[Src], path: list[str], x: float, y: float) -> None:
        attrs: dict[str, object] = {"localId": self.counter.next_local(), "height": 20, "width": 60}
        if isinstance(item, Jump):
            attrs["label"] = item.target
        attrs["executionOrderId"] = self.counter.next_order()
        node = sub(self.parent, "jump" if isinstance(item, Jump) else "return", attrs)
        position(node, "position", x, y)
        self.connect(self.connection_in(node, 0, 10), point, x, y + 10)
        ladderlab_data(node, self.ids(item, path))

    def compare(self, item: Compare, point: list[Src], path: list[str], col: int, row: int) -> Src:
        x, y = x_of(col + 1) + 20, y_of(self.top, row)
        operands = [
            self.in_variable(text, x_of(col) + 10, y_of(self.top, row + 1 + i) + 10)
            for i, text in enumerate((item.left, item.right))
        ]
        local_id = self.counter.next_local()
        node = sub(
            self.parent,
            "block",
            {
                "localId": local_id,
                "width": 60,
                "height": 3 * CELL_H,
                "typeName": item.op,
                "executionOrderId": self.counter.next_order(),
            },
        )
        position(node, "position", x, y)
        inputs = sub(node, "inputVariables")
        for i, (pin, source) in enumerate((("EN", point), ("IN1", [operands[0]]), ("IN2", [operands[1]]))):
            holder = self.connection_in(sub(inputs, "variable", {"formalParameter": pin}), 0, 20 + CELL_H * i)
            self.connect(holder, source, x, y + 20 + CELL_H * i)
        sub(node, "inOutVariables")
        outputs = sub(node, "outputVariables")
        for i, pin in enumerate(("ENO", "OUT")):
            position(
                sub(sub(outputs, "variable", {"formalParameter": pin}), "connectionPointOut"),
                "relPosition",
                60,
                20 + CELL_H * i,
            )
        ladderlab_data(node, self.ids(item, path))
        return Src(local_id, "OUT", x + 60, y + 20 + CELL_H)

    def box(self, item: Box, point: list[Src], path: list[str], row: int) -> list[Src]:
        pins = self.pins(item)
        col = self.layout.block_cols[id(item)]
        x, y = x_of(col) + 20, y_of(self.top, row)
        sources: dict[str, list[Src]] = {pins.power_in: point}
        for pin in sorted(item.inputs, key=lambda p: self.pin_row(pins, p, inputs=True)):  # the lowering's order
            value = item.inputs[pin]
            if pin == pins.power_in:
                continue
            if isinstance(value, list):
                sources[pin] = self.series(value, [RAIL], [])
            else:
                at = self.pin_row(pins, pin, inputs=True)
                sources[pin] = [self.in_variable(value, x_of(col - 1) + 10, y + at * CELL_H + 10)]
        local_id = self.counter.next_local()
        attrs = {
            "localId": local_id,
            "width": 60,
            "height": pins.rows * CELL_H,
            "typeName": item.call,
            "instanceName": item.instance,
            "executionOrderId": self.counter.next_order(),
        }
        node = sub(self.parent, "block", attrs)
        position(node, "position", x, y)
        inputs = sub(node, "inputVariables")
        for pin in pins.inputs:
            at = self.pin_row(pins, pin, inputs=True)
            holder = self.connection_in(sub(inputs, "variable", {"formalParameter": pin}), 0, 20 + at * CELL_H)
            self.connect(holder, sources.get(pin, []), x, y + 20 + at * CELL_H)
        in_outs = sub(node, "inOutVariables")
        for pin in pins.in_outs:
            at = self.pin_row(pins, pin, inputs=True)
            variable = sub(in_outs, "variable", {"formalParameter": pin})
            self.connect(
                self.connection_in(variable, 0, 20 + at * CELL_H), sources.get(pin, []), x, y + 20 + at * CELL_H
            )
            position(sub(variable, "connectionPointOut"), "relPosition", 60, 20 + at * CELL_H)
        outputs = sub(node, "outputVariables")
        for pin in pins.outputs:
            at = self.pin_row(pins, pin, inputs=False)
            position(
                sub(sub(outputs, "variable", {"formalParameter": pin}), "connectionPointOut"),
                "relPosition",
                60,
                20 + at * CELL_H,
            )
        ladderlab_data(node, self.ids(item, path))
        for pin, var in item.outputs.items():
            at = self.pin_row(pins, pin, inputs=False)
            self.out_variable(
                var, Src(local_id, pin, x + 60, y + 20 + at * CELL_H), x_of(col + 1) + 20, y + at * CELL_H + 10
            )
        if pins.power_out is None:
            return []
        at = self.pin_row(pins, pins.power_out, inputs=False)
        return [Src(local_id, pins.power_out, x + 60, y + 20 + at * CELL_H)]

    @staticmethod
    def pin_row(pins: BoxPins, pin: str, *, inputs: bool) -> int:
        names = pins.inputs if inputs else pins.outputs
        if pin in names:
            return names.index(pin)
        return max(len(pins.inputs), len(pins.outputs)) + pins.in_outs.index(pin) if pin in pins.in_outs else 0

    def in_variable(self, text: str, x: float, y: float) -> Src:
        local_id = self.counter.next_local()
        node = sub(self.parent, "inVariable", {"localId": local_id, "height": 20, "width": 80})
        position(node, "position", x, y)
        position(sub(node, "connectionPointOut"), "relPosition", 80, 10)
        sub(node, "expression").text = text
        ladderlab_data(node, {"network": self.network_id})
        return Src(local_id, None, x + 80, y + 10)

    def out_variable(self, text: str, source: Src, x: float, y: float) -> None:
        node = sub(
            self.parent,
            "outVariable",
            {
                "localId": self.counter.next_local(),
                "height": 20,
                "width": 80,
                "executionOrderId": self.counter.next_order(),
            },
        )
        position(node, "position", x, y)
        self.connect(self.connection_in(node, 0, 10), [source], x, y + 10)
        sub(node, "expression").text = text
        ladderlab_data(node, {"network": self.network_id})

    # ------------------------------------------------------------ wires

    @staticmethod
    def connection_in(parent: ET.Element, rel_x: float, rel_y: float) -> ET.Element:
        holder = sub(parent, "connectionPointIn")
        position(holder, "relPosition", rel_x, rel_y)
        return holder

    def connect(self, holder: ET.Element, point: list[Src], x: float, y: float) -> None:
        """Connections from every source of ``point`` into the input at (x, y), with the wire's end points."""
        for src in point:
            if src is RAIL:
                if y not in self.left_points:
                    self.left_points.add(y)
                    out = sub(self.left, "connectionPointOut", {"formalParameter": ""})
                    position(out, "relPosition", 10, y - self.top)
                connection = sub(holder, "connection", {"refLocalId": self.left.get("localId")})
                start = (RAIL_X + 10, y)
            else:
                connection = sub(holder, "connection", {"refLocalId": src.local_id, "formalParameter": src.param})
                start = (src.x, src.y)
            position(connection, "position", x, y)
            position(connection, "position", *start)
