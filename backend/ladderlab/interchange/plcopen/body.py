"""What LD and FBD bodies share in PLCopen: local ids, network headers, and LadderLab's network list.

PLCopen graphical bodies are one drawing without networks. A network of the
project model becomes a horizontal band: an optional ``<comment>`` (the network
comment) and ``<label>`` (the network label, the jump target) at its top, then
its elements. The body's addData lists the network ids in order and every
element names its network, so LadderLab reads its own files back network for
network; other files are split by the rules in the LD and FBD importers.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation

from .graph import COMMENT_TAGS, Graph
from .xml_io import (
    LADDERLAB_NS,
    Reader,
    decimal_text,
    formatted_text,
    info,
    ladderlab_data,
    position,
    sub,
    text_content,
)

#: Height of the comment box above a network and the gap between networks (pixels).
COMMENT_H = 40
NETWORK_GAP = 40


@dataclass
class Counter:
    """Body-wide ``localId`` numbers and ``executionOrderId`` numbers (both start at 1)."""

    local: int = 0
    order: int = 0

    def next_local(self) -> int:
        self.local += 1
        return self.local

    def next_order(self) -> int:
        self.order += 1
        return self.order


def write_header(
    parent: ET.Element,
    counter: Counter,
    network_id: str,
    label: str | None,
    comment: str | None,
    top: float,
    width: float,
) -> float:
    """Comment and label elements of a network; returns the y where its elements start."""
    if comment is not None:
        node = sub(parent, "comment", {"localId": counter.next_local(), "height": COMMENT_H - 10, "width": width})
        position(node, "position", 20, top)
        formatted_text(node, "content", comment)
        ladderlab_data(node, {"network": network_id})
        top += COMMENT_H
    if label is not None:
        node = sub(parent, "label", {"localId": counter.next_local(), "height": 20, "width": 80, "label": label})
        position(node, "position", 20, top)
        ladderlab_data(node, {"network": network_id})
        top += 30
    return top


def write_network_list(
    body: ET.Element, networks: list[tuple[str, float | Decimal, list[str] | None]], chart: bool = False
) -> None:
    """The body's addData: network ids in order, the y offset each was drawn at, an FBD network's ``order``;
    ``chart``: the body is a CFC chart (its one network), not FBD networks."""
    add = ladderlab_data(body, {"language": "cfc"} if chart else None)
    listing = add[0][0]
    for network_id, top, order in networks:
        attrs = {"id": network_id, "top": decimal_text(top)}
        if order is not None:
            attrs["order"] = " ".join(order)
        ET.SubElement(listing, f"{{{LADDERLAB_NS}}}network", attrs)


@dataclass
class NetworkList:
    """LadderLab's network list read back: ids in order and the y offset of each."""

    ids: list[str] = field(default_factory=list)
    tops: dict[str, Decimal] = field(default_factory=dict)
    orders: dict[str, list[str] | None] = field(default_factory=dict)
    chart: bool = False  # a CFC chart (issue 26)


def read_network_list(body: ET.Element, reader: Reader) -> NetworkList | None:
    node = info(body, reader)
    if node is None:
        return None
    listing = NetworkList(chart=node.get("language") == "cfc")
    for entry in node.findall(f"{{{LADDERLAB_NS}}}network"):
        network_id = entry.get("id")
        if network_id and network_id not in listing.tops:
            listing.ids.append(network_id)
            listing.tops[network_id] = _decimal(entry.get("top"))
            order = entry.get("order")
            listing.orders[network_id] = order.split() if order is not None else None
    return listing


def _decimal(text: str | None) -> Decimal:
    try:
        return Decimal(text or "0")
    except InvalidOperation:
        return Decimal(0)


# ---------------------------------------------------------------- import: which elements form which network


@dataclass
class NetworkGroup:
    """The elements (localIds) of one network to be, with its header; ``top`` is the y its positions start at."""

    id: str | None = None
    members: list[int] = field(default_factory=list)
    label: str | None = None
    comment: str | None = None
    top: float | Decimal = 0.0
    order: list[str] | None = None  # an FBD network's ``order`` as LadderLab wrote it


def header_text(graph: Graph, reader: Reader, element_id: int) -> str:
    element = graph.elements[element_id]
    if element.tag == "label":
        return element.node.get("label", "")
    return text_content(reader.child(element.node, "content"))


def group_by_ladderlab(graph: Graph, reader: Reader, listing: NetworkList | None) -> list[NetworkGroup] | None:
    """Networks as LadderLab wrote them, when every element still names a listed network; else None."""
    if listing is None:
        return None
    groups = {
        network_id: NetworkGroup(network_id, top=listing.tops[network_id], order=listing.orders[network_id])
        for network_id in listing.ids
    }
    for local_id in graph.order:
        element = graph.elements[local_id]
        group = groups.get(element.network or "")
        if group is None:
            return None
        if element.tag == "label" and element.model_id is None:  # the network's label (with an id: a CFC label)
            group.label = header_text(graph, reader, local_id)
        elif element.tag == "comment" and element.model_id is None:  # the network's comment
            group.comment = header_text(graph, reader, local_id)
        elif element.tag not in COMMENT_TAGS or element.tag == "comment":  # a comment with an id: an FBD node
            group.members.append(local_id)
    return list(groups.values())


def attach_headers(groups: list[NetworkGroup], graph: Graph, reader: Reader) -> list[NetworkGroup]:
    """Labels of a foreign LD drawing go to the first network at or below them; each free comment box becomes a
    comment network of its own where it stands among the networks (issue 28: nothing merged, nothing moved)."""

    def top(group: NetworkGroup) -> float:
        return min((graph.elements[m].y for m in group.members), default=group.top)

    for group in groups:
        group.top = top(group)
    labels = sorted((e for e in graph.elements.values() if e.tag == "label"), key=lambda e: e.key)
    for header in labels:
        text = header_text(graph, reader, header.local_id)
        below = [g for g in groups if g.top >= header.y and g.label is None]
        if below:
            below[0].label = text
        else:
            groups.append(NetworkGroup(label=text, top=header.y))
    comments = sorted((e for e in graph.elements.values() if e.tag == "comment"), key=lambda e: e.key)
    for header in comments:
        text = header_text(graph, reader, header.local_id).strip()
        at = next((i for i, g in enumerate(groups) if g.top > header.y), len(groups))
        groups.insert(at, NetworkGroup(comment=text, top=header.y))
    return groups


class IdMaker:
    """Element and network ids of one imported POU: the ids LadderLab wrote when still unique, else fresh ones.

    Fresh ids are ``<prefix><n>`` with the smallest free n (the editor's scheme) and
    never take an id that some element's addData still claims.
    """

    def __init__(self, reserved: set[str]):
        self.reserved = set(reserved)
        self.used: set[str] = set()
        self._next: dict[str, int] = {}  # per prefix: no smaller number is free any more (ids are never released)

    def take(self, wanted: str | None, prefix: str) -> str:
        if wanted and wanted not in self.used:
            self.used.add(wanted)
            return wanted
        return self.fresh(prefix)

    def fresh(self, prefix: str) -> str:
        n = self._next.get(prefix, 1)
        while f"{prefix}{n}" in self.used or f"{prefix}{n}" in self.reserved:
            n += 1
        self._next[prefix] = n + 1
        self.used.add(f"{prefix}{n}")
        return f"{prefix}{n}"


def claimed_ids(graph: Graph, listing: NetworkList | None) -> set[str]:
    """Every id LadderLab's addData claims in a body (elements, parallels, networks)."""
    ids = set(listing.ids if listing else ())
    for element in graph.elements.values():
        if element.info is not None:
            ids.update(filter(None, [element.info.get("id"), *(element.info.get("parallels") or "").split()]))
    return ids
