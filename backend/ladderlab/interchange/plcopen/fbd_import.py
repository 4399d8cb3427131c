"""PLCopen ``<FBD>`` graph -> FBD body: elements map 1:1 to nodes, connections to wires.

Networks: a PLCopen FBD body has none, so they are cut where control can enter
or leave. When every executable element carries a distinct ``executionOrderId``
(CFC style, e.g. RuSTy) the elements run in that order, a ``label`` starts a new
network and a jump or return ends one (a CFC jump leaves at once, so what
follows it must be a network of its own); the ids become the network's
``order``. Otherwise ``label``s cut the drawing top to bottom. Values
(``inVariable``s, continuations) join the network of their first reader.

Two PLCopen elements have no FBD node of their own: an ``inOutVariable`` (a
variable written and read in one place) becomes an output node for the write,
its readers take the written value straight from the writer, except readers
that feed the writer (a feedback loop), which read the variable (last scan's
value) through an input node; a jump or return negated in Bachmann/RuSTy addData
gets a NOT block in front.
"""

from __future__ import annotations

from decimal import Decimal, InvalidOperation

from ...ir.fbd_order import SIMPLE_IN, SIMPLE_OUT
from ...model.fbd import (
    Block,
    Connector,
    Continuation,
    FbdBody,
    FbdComment,
    FbdJump,
    FbdLabel,
    FbdNetwork,
    FbdNode,
    FbdReturn,
    InputNode,
    OutputNode,
    PinFlags,
    PinRef,
    Position,
    Wire,
)
from .body import IdMaker, NetworkGroup
from .graph import Conn, Element, Graph, reaches
from .ld_import import negate
from .xml_io import Reader, data_entries, local, text_content

EXECUTABLE = ("block", "outVariable", "inOutVariable", "jump", "return", "label")
_PREFIX = {
    "block": "block",
    "inVariable": "input",
    "outVariable": "output",
    "jump": "jump",
    "return": "ret",
    "label": "label",
    "connector": "connector",
    "continuation": "continuation",
    "inOutVariable": "output",
    "comment": "comment",
}
_BACHMANN = "www.bachmann.at/plc/plcopenxml"


def fbd_groups(graph: Graph, reader: Reader) -> tuple[list[NetworkGroup], dict[int, list[int]]]:
    """Networks of a foreign FBD drawing and, in CFC style, each network's execution order (localIds)."""
    executable = [graph.elements[m] for m in graph.order if graph.elements[m].tag in EXECUTABLE]
    consumers = graph.consumers()
    connected = [
        e for e in executable if e.tag == "label" or consumers.get(e.local_id) or any(e.inputs.values())
    ]  # RuSTy leaves stray unordered elements that it ignores
    orders = [e.order for e in connected]
    cfc = bool(connected) and None not in orders and len(set(orders)) == len(orders)
    groups: list[NetworkGroup] = [NetworkGroup()]
    if cfc:
        for element in sorted(connected, key=lambda e: e.order):
            if element.tag == "label":
                if groups[-1].members or groups[-1].label is not None:
                    groups.append(NetworkGroup())
                groups[-1].label = element.node.get("label", "")
                continue
            groups[-1].members.append(element.local_id)
            if element.tag in ("jump", "return"):
                groups.append(NetworkGroup())
    else:
        labels = sorted((e for e in executable if e.tag == "label"), key=lambda e: e.key)
        groups += [NetworkGroup(label=label.node.get("label", ""), top=label.y) for label in labels]
        for element in sorted((e for e in executable if e.tag != "label"), key=lambda e: e.key):
            target = max((i for i, label in enumerate(labels) if label.y <= element.y), default=-1)
            groups[target + 1].members.append(element.local_id)
    _attach_values(graph, groups)
    groups = [g for g in groups if g.members or g.label is not None] or [NetworkGroup()]
    order = {id(g): [m for m in g.members if graph.elements[m].tag in EXECUTABLE] for g in groups} if cfc else {}
    return groups, order


def place_comments(groups: list[NetworkGroup], graph: Graph) -> None:
    """Free comment boxes of a foreign drawing become comment nodes of the network drawn at their height, where
    they were and as large as they were (issue 28): the first network whose elements reach below the box's top,
    else the last."""
    bottoms = [max((graph.elements[m].y for m in g.members), default=float(g.top)) for g in groups]
    for element in sorted((e for e in graph.elements.values() if e.tag == "comment"), key=lambda e: e.key):
        target = next((i for i, bottom in enumerate(bottoms) if bottom >= element.y), len(groups) - 1)
        groups[target].members.append(element.local_id)


def _attach_values(graph: Graph, groups: list[NetworkGroup]) -> None:
    """inVariables and continuations join their first reader's network; connectors their writer's."""
    where = {m: i for i, g in enumerate(groups) for m in g.members}
    consumers = graph.consumers()
    pending = [
        graph.elements[m]
        for m in graph.order
        if m not in where and graph.elements[m].tag not in EXECUTABLE + ("comment", "error")
    ]
    for _ in range(len(pending) + 1):
        left = []
        for element in pending:
            linked = [c for c, _, _ in consumers.get(element.local_id, []) if c in where]
            linked += [c.ref for conns in element.inputs.values() for c in conns if c.ref in where]
            if linked:
                target = min(where[c] for c in linked)
                groups[target].members.append(element.local_id)
                where[element.local_id] = target
            else:
                left.append(element)
        if len(left) == len(pending):
            break
        pending = left
    for element in pending:
        groups[0].members.append(element.local_id)
        where[element.local_id] = 0


class FbdImporter:
    """Reads the networks of one FBD body; problems go to ``reader`` located at the POU and element."""

    def __init__(self, graph: Graph, reader: Reader, pou: str, ids: IdMaker):
        self.graph = graph
        self.reader = reader
        self.pou = pou
        self.ids = ids
        self.consumers = graph.consumers()

    def error(self, message: str, element: Element, network: str, severity: str = "error") -> None:
        self.reader.report(
            "PLCOPEN-FBD",
            message,
            element.node,
            severity=severity,
            pou=self.pou,
            network=network,
            item=f"localId {element.local_id}",
        )

    def body(self, groups: list[NetworkGroup], orders: dict[int, list[int]], *, relative: bool) -> FbdBody:
        return FbdBody(networks=[self.network(g, orders.get(id(g)), relative) for g in groups])

    def network(self, group: NetworkGroup, order: list[int] | None, relative: bool) -> FbdNetwork:
        network_id = self.ids.take(group.id, "network")
        self.network_id = network_id
        self.offset = group.top if relative else 0
        members = set(group.members)
        self.nodes: dict[int, FbdNode] = {}
        self.node_list: list[FbdNode] = []
        self.wires: list[Wire] = []
        self.wire_order: list[int] = []  # LadderLab's wire positions, when every connection has one
        for m in group.members:
            self.node(self.graph.elements[m])
        self.feedback_inputs: dict[int, InputNode] = {}
        for m in group.members:
            self.connect(self.graph.elements[m], members)
        if self.wire_order and len(self.wire_order) == len(self.wires):
            self.wires = [w for _, w in sorted(zip(self.wire_order, self.wires), key=lambda p: p[0])]
        if relative:  # LadderLab's own file: the network's order list as it was
            order_ids = group.order
        else:
            order_ids = [self.nodes[m].id for m in order or [] if m in self.nodes] or None
        return FbdNetwork(
            id=network_id,
            label=group.label,
            comment=group.comment,
            nodes=self.node_list,
            wires=self.wires,
            order=order_ids,
        )

    # ------------------------------------------------------------ nodes

    def position(self, element: Element) -> Position | None:
        if element.info is not None and element.info.get("pos") == "auto":
            return None
        if not self.offset:
            return Position(x=element.x, y=element.y)
        try:  # exact decimal subtraction undoes the exporter's exact addition
            return Position(x=element.x, y=float(Decimal(element.y_text) - Decimal(self.offset)))
        except InvalidOperation:
            return Position(x=element.x, y=element.y - float(self.offset))

    def add(self, element: Element | None, node: FbdNode) -> FbdNode:
        if element is not None:
            self.nodes[element.local_id] = node
        self.node_list.append(node)
        return node

    def node(self, element: Element) -> None:
        tag = element.tag
        node_id = self.ids.take(element.model_id, _PREFIX.get(tag, "node"))
        pos = self.position(element)
        mods = element.mods.get("")
        if tag == "block":
            self.add(
                element,
                Block(
                    id=node_id,
                    pos=pos,
                    call=element.node.get("typeName", ""),
                    instance=element.node.get("instanceName") or None,
                    en=any(p.upper() == "EN" for p in element.in_pins),
                    pins=self.pin_flags(element),
                ),
            )
        elif tag == "inVariable":
            expr = element.text(self.reader, "expression")
            if mods.edge or mods.storage:
                self.error(
                    "edge/storage modifiers on an input variable have no FBD equivalent; ignored",
                    element,
                    self.network_id,
                    "warning",
                )
            self.add(element, InputNode(id=node_id, pos=pos, expr=negate(expr) if mods.negated else expr))
        elif tag in ("outVariable", "inOutVariable"):
            if tag == "inOutVariable" and not element.inputs.get(""):
                if not self.consumers.get(element.local_id):
                    self.error(
                        f"inOutVariable '{element.text(self.reader, 'expression')}' is connected to nothing; ignored",
                        element,
                        self.network_id,
                        "warning",
                    )
                    return
                self.add(element, InputNode(id=node_id, pos=pos, expr=element.text(self.reader, "expression")))
                return
            mode = (
                mods.storage
                or ({"rising": "p", "falling": "n"}.get(mods.edge or ""))
                or ("negated" if mods.negated else "normal")
            )
            self.add(element, OutputNode(id=node_id, pos=pos, var=element.text(self.reader, "expression"), mode=mode))
        elif tag == "jump":
            self.add(element, FbdJump(id=node_id, pos=pos, target=element.node.get("label", "")))
        elif tag == "return":
            self.add(element, FbdReturn(id=node_id, pos=pos))
        elif tag == "label":  # a CFC chart's label element (a network's label is its header, not a member)
            self.add(element, FbdLabel(id=node_id, pos=pos, name=element.node.get("label", "")))
        elif tag == "connector":
            self.add(element, Connector(id=node_id, pos=pos, name=element.node.get("name", "")))
        elif tag == "continuation":
            self.add(element, Continuation(id=node_id, pos=pos, name=element.node.get("name", "")))
        elif tag == "comment":
            auto = element.info is not None and element.info.get("size") == "auto"
            self.add(
                element,
                FbdComment(
                    id=node_id,
                    pos=pos,
                    text=text_content(self.reader.child(element.node, "content")).strip(),
                    width=None if auto else _size(element.node.get("width")),
                    height=None if auto else _size(element.node.get("height")),
                ),
            )
        else:
            self.error(f"<{tag}> is not an FBD element this project can hold", element, self.network_id)

    def pin_flags(self, element: Element) -> dict[str, PinFlags] | None:
        listed = element.info.get("pins") if element.info is not None else None
        flags = {}
        for pin, mods in element.mods.items():
            if mods.storage:
                self.error(
                    f"pin {pin} has a set/reset modifier, which a block pin cannot hold; ignored",
                    element,
                    self.network_id,
                    "warning",
                )
            if listed is not None or mods.negated or mods.edge:
                flags[pin] = PinFlags(negated=mods.negated, edge=mods.edge)
        if listed is not None:
            return {pin: flags.get(pin, PinFlags()) for pin in listed.split()}
        return flags or None

    # ------------------------------------------------------------ wires

    def connect(self, element: Element, members: set[int]) -> None:
        if element.local_id not in self.nodes:
            return
        target = self.nodes[element.local_id]
        for pin, conns in element.inputs.items():
            to_pin = pin if element.tag == "block" else SIMPLE_IN
            if element.tag in ("jump", "return") and self.negated_by_vendor(element):
                target, to_pin = self.not_block(element, target), "IN"
            for conn in conns:
                source = self.source(conn, element, members)
                if source is not None:
                    self.wires.append(Wire(from_=source, to=PinRef(node=target.id, pin=to_pin)))
                    if conn.index is not None:
                        self.wire_order.append(conn.index)

    def source(self, conn: Conn, consumer: Element, members: set[int]) -> PinRef | None:
        element = self.graph.elements[conn.ref]
        if conn.ref not in members:
            self.error(
                f"the connection from {element.tag} {element.local_id} crosses into another network; "
                "use a connector and continuation",
                consumer,
                self.network_id,
            )
            return None
        if element.tag == "inOutVariable" and element.inputs.get(""):
            return self.in_out_source(element, consumer, members)
        node = self.nodes.get(conn.ref)
        if node is None:
            return None
        return PinRef(node=node.id, pin=conn.param if element.tag == "block" else SIMPLE_OUT)

    def in_out_source(self, element: Element, consumer: Element, members: set[int]) -> PinRef | None:
        """A reader of an inOutVariable: the writer's value, or the variable itself when the reader feeds the writer."""
        writer = element.inputs[""][0]
        if not reaches(self.consumers, consumer.local_id, writer.ref):
            return self.source(writer, consumer, members)
        if element.local_id not in self.feedback_inputs:
            node = InputNode(
                id=self.ids.fresh("input"), pos=self.position(element), expr=element.text(self.reader, "expression")
            )
            self.feedback_inputs[element.local_id] = node
            self.add(None, node)
        return PinRef(node=self.feedback_inputs[element.local_id].id, pin=SIMPLE_OUT)

    def negated_by_vendor(self, element: Element) -> bool:
        for data in data_entries(element.node, self.reader, _BACHMANN):
            flag = next((c for c in data if local(c) == "negated"), None)
            return flag is not None and flag.get("value") == "true"
        return False

    def not_block(self, element: Element, target: FbdNode) -> FbdNode:
        block = Block(id=self.ids.fresh("block"), pos=self.position(element), call="NOT")
        self.add(None, block)
        self.wires.append(Wire(from_=PinRef(node=block.id, pin="OUT"), to=PinRef(node=target.id, pin=SIMPLE_IN)))
        return block


def _size(text: str | None) -> float | None:
    """A comment box's width or height: a positive finite number, else None (drawn as the text needs)."""
    try:
        value = float(text or "")
    except ValueError:
        return None
    return value if 0 < value < float("inf") else None
