"""A PLCopen LD/FBD body read into a plain graph: elements by localId, their pins and connections.

Both importers work on this: an ``Element`` per graphical object with its
position, its input connections per pin (``""`` for single-input objects), its
output pins, pin modifiers and LadderLab's addData. Connections are normalised
once here: a connection without ``formalParameter`` to a block means the block's
first output that is not ENO (the XSD's rule), one to a missing element is
reported and dropped.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections import defaultdict
from dataclasses import dataclass, field

from .blocks import RESULT_PIN, Signatures
from .xml_io import Reader, info, local

#: Elements that take part in the flow (everything but drawing-only objects).
COMMENT_TAGS = ("comment", "error")
SINGLE_IN = ("contact", "coil", "outVariable", "inOutVariable", "jump", "return", "connector")
SINGLE_OUT = ("contact", "coil", "inVariable", "inOutVariable", "continuation")


@dataclass(frozen=True)
class Conn:
    """A connection into an input: the source element and, for a block, its output pin.

    ``index`` is the position of the wire in LadderLab's FBD wire list, when LadderLab wrote the file.
    """

    ref: int
    param: str | None = None
    index: int | None = field(default=None, compare=False)


@dataclass
class PinMods:
    negated: bool = False
    edge: str | None = None  # "rising" / "falling"
    storage: str | None = None  # "set" / "reset"


@dataclass
class Element:
    local_id: int
    tag: str
    node: ET.Element
    x: float
    y: float
    order: int | None
    y_text: str = "0"
    inputs: dict[str, list[Conn]] = field(default_factory=dict)
    in_pins: list[str] = field(default_factory=list)
    in_out_pins: list[str] = field(default_factory=list)
    out_pins: list[str] = field(default_factory=list)
    mods: dict[str, PinMods] = field(default_factory=dict)
    info: ET.Element | None = None

    @property
    def key(self) -> tuple[float, float, int]:
        """Drawing order: top to bottom, then left to right, then localId."""
        return (self.y, self.x, self.local_id)

    @property
    def network(self) -> str | None:
        return self.info.get("network") if self.info is not None else None

    @property
    def model_id(self) -> str | None:
        return self.info.get("id") if self.info is not None else None

    def text(self, reader: Reader, tag: str) -> str:
        child = reader.child(self.node, tag)
        return (child.text or "").strip() if child is not None else ""


@dataclass
class Graph:
    elements: dict[int, Element] = field(default_factory=dict)
    order: list[int] = field(default_factory=list)  # document order

    def consumers(self) -> dict[int, list[tuple[int, str, Conn]]]:
        """localId of a source -> (consumer localId, consumer pin, connection) for every connection."""
        out: dict[int, list[tuple[int, str, Conn]]] = defaultdict(list)
        for element in self.elements.values():
            for pin, conns in element.inputs.items():
                for conn in conns:
                    out[conn.ref].append((element.local_id, pin, conn))
        return out


def reaches(consumers: dict[int, list[tuple[int, str, Conn]]], start: int, goal: int) -> bool:
    """Does ``start``'s output flow (through any elements) into ``goal``?"""
    seen, todo = {start}, [start]
    while todo:
        for consumer, _, _ in consumers.get(todo.pop(), []):
            if consumer == goal:
                return True
            if consumer not in seen:
                seen.add(consumer)
                todo.append(consumer)
    return False


def _coordinate(pos: ET.Element | None, axis: str, reader: Reader, pou: str) -> str:
    """The text of a position coordinate, "0" when it is missing or no finite number (reported: a NaN or an
    infinity cannot be stored, drawn or saved)."""
    text = pos.get(axis) if pos is not None else None
    if text is None:
        return "0"
    try:
        if math.isfinite(float(text)):
            return text.strip()
    except ValueError:
        pass
    reader.report(
        "PLCOPEN-GRAPH", f"position {axis}={text!r} is not a finite number; 0 is used", pos, pou=pou, severity="warning"
    )
    return "0"


def _mods(node: ET.Element, prefix: str = "") -> PinMods:
    edge = node.get(f"edge{prefix}")
    storage = node.get(f"storage{prefix}")
    return PinMods(
        node.get(f"negated{prefix}") in ("true", "1"),
        edge if edge in ("rising", "falling") else None,
        storage if storage in ("set", "reset") else None,
    )


def read_graph(container: ET.Element, reader: Reader, pou: str, signatures: Signatures) -> Graph:
    """Every element of an ``<LD>``/``<FBD>`` body; unusable ids and connections are reported.

    Block pins drawn without a name (RuSTy's SEL) get the callee's pin name at that position.
    """
    graph = Graph()
    for node in reader.elements(container):
        tag = local(node)
        try:
            local_id = int(node.get("localId", ""))
        except ValueError:
            reader.report("PLCOPEN-GRAPH", f"<{tag}> has no usable localId; it is ignored", node, pou=pou)
            continue
        if local_id in graph.elements:
            reader.report(
                "PLCOPEN-GRAPH", f"localId {local_id} is used twice; the second <{tag}> is ignored", node, pou=pou
            )
            continue
        pos = reader.child(node, "position")
        order = node.get("executionOrderId")
        x_text = _coordinate(pos, "x", reader, pou)
        y_text = _coordinate(pos, "y", reader, pou)
        extra = info(node, reader)
        element = Element(
            local_id,
            tag,
            node,
            float(x_text),
            float(y_text),
            int(order) if order is not None and order.strip().isdigit() else None,
            y_text=y_text,
            info=extra,
        )
        _read_pins(element, reader, signatures)
        graph.elements[local_id] = element
        graph.order.append(local_id)
    _resolve(graph, reader, pou)
    return graph


def _connections(holder: ET.Element | None, reader: Reader) -> list[Conn]:
    out = []
    for conn in reader.children(holder, "connection"):
        try:
            ref = int(conn.get("refLocalId", ""))
        except ValueError:
            continue
        extra = info(conn, reader)
        index = extra.get("wire") if extra is not None else None
        out.append(Conn(ref, conn.get("formalParameter") or None, int(index) if index and index.isdigit() else None))
    return out


def _read_pins(element: Element, reader: Reader, signatures: Signatures) -> None:
    node = element.node
    if element.tag == "block":
        sig = signatures(node.get("typeName", ""))
        for position, variable in enumerate(reader.children(reader.child(node, "inputVariables"), "variable")):
            pin = variable.get("formalParameter") or _positional(sig.input_names() if sig else [], position, "IN")
            element.in_pins.append(pin)
            element.inputs[pin] = _connections(reader.child(variable, "connectionPointIn"), reader)
            element.mods[pin] = _mods(variable)
        for variable in reader.children(reader.child(node, "inOutVariables"), "variable"):
            pin = variable.get("formalParameter", "")
            element.in_out_pins.append(pin)
            element.inputs[pin] = _connections(reader.child(variable, "connectionPointIn"), reader)
            element.mods[pin] = _mods(variable)
        for position, variable in enumerate(reader.children(reader.child(node, "outputVariables"), "variable")):
            pin = variable.get("formalParameter") or _positional(
                [n for n, _ in sig.outputs] if sig else [], position, "OUT"
            )
            pin = _result_pin(node, pin)
            element.out_pins.append(pin)
            element.mods.setdefault(pin, _mods(variable))
    elif element.tag == "rightPowerRail":
        element.inputs[""] = [
            c for holder in reader.children(node, "connectionPointIn") for c in _connections(holder, reader)
        ]
    elif element.tag in SINGLE_IN:
        element.inputs[""] = _connections(reader.child(node, "connectionPointIn"), reader)
        element.mods[""] = _mods(node, "In" if element.tag == "inOutVariable" else "")
    if element.tag in SINGLE_OUT and element.tag not in SINGLE_IN:
        element.mods[""] = _mods(node)


def _result_pin(block: ET.Element, pin: str) -> str:
    """RuSTy names a function's result pin after the function; the project calls it OUT."""
    return RESULT_PIN if pin.upper() == block.get("typeName", "").upper() else pin


def _positional(names: list[str], position: int, stem: str) -> str:
    if position < len(names):
        return names[position]
    return f"{stem}{position + 1}" if position or stem == "IN" else stem


def _resolve(graph: Graph, reader: Reader, pou: str) -> None:
    """Default block output pins, and connections to missing elements reported and dropped."""
    for element in graph.elements.values():
        for pin, conns in element.inputs.items():
            kept = []
            for conn in conns:
                source = graph.elements.get(conn.ref)
                if source is None:
                    reader.report(
                        "PLCOPEN-GRAPH",
                        f"<{element.tag}> localId {element.local_id} is connected to "
                        f"localId {conn.ref}, which does not exist; the connection is ignored",
                        element.node,
                        pou=pou,
                    )
                    continue
                if source.tag == "block":
                    param = (
                        _result_pin(source.node, conn.param)
                        if conn.param
                        else next((p for p in source.out_pins if p.upper() != "ENO"), None)
                    )
                    conn = Conn(conn.ref, param, conn.index)
                else:
                    conn = Conn(conn.ref, None, conn.index)
                kept.append(conn)
            element.inputs[pin] = kept


def resolve_continuations(graph: Graph, reader: Reader, pou: str) -> None:
    """Replace connections from a ``continuation`` by the sources of the ``connector`` of the same name (LD)."""
    connectors = {e.node.get("name", "").upper(): e for e in graph.elements.values() if e.tag == "connector"}

    def sources(conn: Conn, seen: frozenset[int]) -> list[Conn]:
        source = graph.elements[conn.ref]
        if source.tag != "continuation":
            return [conn]
        connector = connectors.get(source.node.get("name", "").upper())
        if connector is None or source.local_id in seen:
            reader.report(
                "PLCOPEN-GRAPH",
                f"continuation '{source.node.get('name', '')}' has no connector of that name",
                source.node,
                pou=pou,
            )
            return []
        return [c for inner in connector.inputs.get("", []) for c in sources(inner, seen | {source.local_id})]

    for element in graph.elements.values():
        for pin, conns in element.inputs.items():
            element.inputs[pin] = [c for conn in conns for c in sources(conn, frozenset())]
    for element in [e for e in graph.elements.values() if e.tag in ("connector", "continuation")]:
        del graph.elements[element.local_id]
        graph.order.remove(element.local_id)
