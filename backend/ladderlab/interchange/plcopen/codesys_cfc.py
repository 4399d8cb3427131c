"""CODESYS's CFC chart -> a LadderLab CFC body (issue 25).

CODESYS writes a CFC POU as an empty ``<ST>`` whose body's addData holds the chart:
``<data name="http://www.3s-software.com/plcopenxml/cfc"><CFC>`` with TC6 FBD elements (``inVariable``,
``outVariable``, ``block``, ``jump``, ``label``, ``return``, ``comment``, ``connector`` ...). Its own conventions
are undone here before the FBD importer makes nodes and wires of the elements:

- every wire runs through an unnamed ``<connector>`` whose input names the source (``formalParameter`` = the
  source's pin); the consumer's connection names the connector's localId. Such references are followed back to
  the source and the unnamed connectors dropped;
- a box's ``cfccalltype`` addData says how it is called: an ``operator`` (ADD, GT, SEL ...) names its pins
  ``In1``..``Inn`` and ``Out1``, read by position as the callee's inputs and its result ``OUT``; a
  ``functionblock`` needs its instance; a ``method`` is LadderLab's box ``inst.M``. ``vendorElement``s
  (composer, selector, connection marks: ``cfcelementtype``) have no place on a LadderLab chart: located errors;
- ``executionOrderId`` is the chart's execution order (CFC-02); elements without one (CODESYS's automatic data
  flow mode) run after the numbered ones in data flow order, then top to bottom, left to right, as CODESYS orders
  them in that mode;
- positions are CODESYS grid units (one unit between two pins of a box, the height of an input or output element):
  scaled by ``GRID_X`` and ``GRID_Y`` to LadderLab's pixels, so inputs CODESYS stacks on adjacent rows do not overlap.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from itertools import pairwise

from ...model.cfc import CHART_ID, CfcBody
from ...model.fbd import FbdComment, FbdNetwork, Position
from .blocks import RESULT_PIN, Signatures
from .body import IdMaker, NetworkGroup
from .fbd_import import EXECUTABLE, FbdImporter
from .graph import Conn, Element, Graph, read_graph
from .xml_io import Reader, data_entries, local

CALLTYPE_DATA = "http://www.3s-software.com/plcopenxml/cfccalltype"
ELEMENTTYPE_DATA = "http://www.3s-software.com/plcopenxml/cfcelementtype"
#: Pixels per CODESYS CFC grid unit: across, the pin pitch of LadderLab's boxes (frontend FbdNodeView PIN_ROW);
#: down, the height of its input and output elements (fbd.css, 34 px) and a gap.
GRID_X = 22
GRID_Y = 36
#: CODESYS's call types (``operator`` for ADD, GT, SEL ...; a program box is called like a function block).
_CALLS = ("operator", "function", "functionblock", "program", "method")


def chart_element(data: ET.Element) -> ET.Element | None:
    """The ``<CFC>`` inside CODESYS's ``.../plcopenxml/cfc`` addData entry."""
    return next((c for c in data if isinstance(c.tag, str) and local(c) == "CFC"), None)


def _vendor_text(element: ET.Element, reader: Reader, data: str, tag: str) -> str | None:
    """The text of CODESYS's ``<CallType>`` / ``<ElementType>`` (written with ``xmlns=""``: matched by local name)."""
    for entry in data_entries(element, reader, data):
        for child in entry:
            if isinstance(child.tag, str) and local(child) == tag:
                return (child.text or "").strip()
    return None


class CodesysChart:
    """Reads one CODESYS ``<CFC>``; problems go to ``reader`` located at the POU and element."""

    def __init__(self, reader: Reader, pou: str, signatures: Signatures):
        self.reader = reader
        self.pou = pou
        self.signatures = signatures

    def error(self, message: str, element: Element, severity: str = "error") -> None:
        self.reader.report(
            "PLCOPEN-FBD",
            message,
            element.node,
            severity=severity,
            pou=self.pou,
            network=CHART_ID,
            item=f"localId {element.local_id}",
        )

    def body(self, cfc: ET.Element) -> CfcBody:
        graph = read_graph(cfc, self.reader, self.pou, self.signatures)
        self.refuse_vendor_elements(graph)
        self.follow_wire_points(graph)
        self.read_calls(graph)
        order = self.order(graph)
        importer = FbdImporter(graph, self.reader, self.pou, IdMaker(set()))
        group = NetworkGroup(id=CHART_ID, members=list(graph.order))
        network = importer.network(group, order, relative=False)
        return CfcBody(networks=[_scaled(network)])

    # ------------------------------------------------------------ elements LadderLab has no node for

    def refuse_vendor_elements(self, graph: Graph) -> None:
        """A ``vendorElement`` is left out with an error; an element type on a TC6 element is not read (a
        warning: the element is read as its tag says)."""
        for element in list(graph.elements.values()):
            kind = _vendor_text(element.node, self.reader, ELEMENTTYPE_DATA, "ElementType")
            if element.tag == "vendorElement":
                self.error(
                    f"the CFC {kind or 'vendor element'} has no LadderLab chart element; it was left out "
                    "(wire the structure's members, or a connector and continuation, instead)",
                    element,
                )
                _remove(graph, element.local_id)
            elif kind is not None:
                self.error(
                    f"the CFC element type '{kind}' is not read; this <{element.tag}> is read as TC6 defines it",
                    element,
                    "warning",
                )

    def follow_wire_points(self, graph: Graph) -> None:
        """Connections naming a ``<connector>`` by localId (CODESYS's wire points) name the connector's source;
        the unnamed connectors go (a named one stays: its continuations read it)."""
        connectors = {e.local_id: e for e in graph.elements.values() if e.tag == "connector"}
        circles: set[frozenset[int]] = set()

        def sources(conn: Conn, seen: frozenset[int]) -> list[Conn]:
            connector = connectors.get(conn.ref)
            if connector is None:
                return [conn]
            if conn.ref in seen:
                if seen not in circles:
                    circles.add(seen)
                    self.error(f"the wire points {sorted(seen)} feed each other; they carry no value", connector)
                return []
            return [c for inner in connector.inputs.get("", []) for c in sources(inner, seen | {conn.ref})]

        for element in graph.elements.values():
            for pin, conns in element.inputs.items():
                element.inputs[pin] = [c for conn in conns for c in sources(conn, frozenset())]
        for connector in connectors.values():
            if not connector.node.get("name", "").strip():
                _remove(graph, connector.local_id)

    # ------------------------------------------------------------ boxes

    def read_calls(self, graph: Graph) -> None:
        renamed: dict[tuple[int, str], str] = {}
        for element in [e for e in graph.elements.values() if e.tag == "block"]:
            call = _vendor_text(element.node, self.reader, CALLTYPE_DATA, "CallType")
            type_name = element.node.get("typeName", "")
            if call == "functionblock" and not element.node.get("instanceName"):
                self.error(f"box {type_name} names no instance; it was left out", element)
                _remove(graph, element.local_id)
                continue
            if call == "operator":
                renamed |= self.operator_pins(element)
            elif call == "method" or (call is None and "." in type_name):
                renamed |= self.method_box(element)
            elif call not in (None, *_CALLS):
                self.error(
                    f"box {type_name} has the call type '{call}', which LadderLab does not know; it is read as a "
                    f"call of {type_name}",
                    element,
                    "warning",
                )
        for element in graph.elements.values():
            for pin, conns in element.inputs.items():
                element.inputs[pin] = [
                    Conn(c.ref, renamed.get((c.ref, c.param or ""), c.param), c.index) for c in conns
                ]

    def operator_pins(self, element: Element) -> dict[tuple[int, str], str]:
        """An operator's ``In1``..``Inn`` become the callee's inputs by position, its ``Out1`` the result ``OUT``
        (EN and ENO stay). Returns the renamed outputs, for the connections that name them."""
        sig = self.signatures(element.node.get("typeName", ""))
        names = sig.input_names() if sig is not None else []
        inputs = [p for p in element.in_pins if p.upper() != "EN"]
        outputs = [p for p in element.out_pins if p.upper() != "ENO"]
        return _rename_pins(
            element,
            {p: names[i] if i < len(names) else f"IN{i + 1}" for i, p in enumerate(inputs)},
            {p: RESULT_PIN for p in outputs[:1]},
        )

    def method_box(self, element: Element) -> dict[tuple[int, str], str]:
        """A method call is LadderLab's box ``inst.M`` (docs/diagrams.md): the instance joins the call when CODESYS
        writes it apart, and a result pin named after the method is ``OUT``."""
        node = element.node
        call = node.get("typeName", "")
        if "." not in call and node.get("instanceName"):
            call = f"{node.attrib.pop('instanceName')}.{call}"
        node.set("typeName", call)
        method = call.rsplit(".", 1)[-1].upper()
        return _rename_pins(element, {}, {p: RESULT_PIN for p in element.out_pins if p.upper() == method})

    # ------------------------------------------------------------ execution order

    def order(self, graph: Graph) -> list[int]:
        """The numbered executed elements by number; two with one number are reported and run by position."""
        numbered = [e for e in graph.elements.values() if e.tag in EXECUTABLE and e.order is not None]
        numbered.sort(key=lambda e: (e.order, e.key))
        for before, after in pairwise(numbered):
            if before.order == after.order:
                self.error(
                    f"localIds {before.local_id} and {after.local_id} have the same executionOrderId {after.order}; "
                    "they run top to bottom, left to right",
                    after,
                    "warning",
                )
        return [e.local_id for e in numbered]


def _rename_pins(element: Element, inputs: dict[str, str], outputs: dict[str, str]) -> dict[tuple[int, str], str]:
    """Rename a box's pins; returns the renamed outputs by (localId, old name), for the connections naming them."""
    element.in_pins = [inputs.get(p, p) for p in element.in_pins]
    element.inputs = {inputs.get(p, p): conns for p, conns in element.inputs.items()}
    element.out_pins = [outputs.get(p, p) for p in element.out_pins]
    element.mods = {inputs.get(p, outputs.get(p, p)): m for p, m in element.mods.items()}
    return {(element.local_id, p): name for p, name in outputs.items()}


def _remove(graph: Graph, local_id: int) -> None:
    """Drop an element and every connection from it (its consumers are then unwired, as the chart reports)."""
    del graph.elements[local_id]
    graph.order.remove(local_id)
    for element in graph.elements.values():
        for pin, conns in element.inputs.items():
            element.inputs[pin] = [c for c in conns if c.ref != local_id]


def _scaled(network: FbdNetwork) -> FbdNetwork:
    """Grid units to pixels: places, and comment boxes' sizes."""
    nodes = []
    for node in network.nodes:
        update: dict[str, object] = {}
        if node.pos is not None:
            update["pos"] = Position(x=node.pos.x * GRID_X, y=node.pos.y * GRID_Y)
        if isinstance(node, FbdComment):
            if node.width is not None:
                update["width"] = node.width * GRID_X
            if node.height is not None:
                update["height"] = node.height * GRID_Y
        nodes.append(node.model_copy(update=update))
    return network.model_copy(update={"nodes": nodes})
