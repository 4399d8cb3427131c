"""FBD network structure: which output feeds each input, and the order the nodes run in.

IEC 61131-3 8.1.5 (GR-05, GR-06) and 8.3 (GR-30) as LadderLab applies them:

* Wires are resolved through connector/continuation pairs, so a continuation is
  just another name for whatever feeds its connector.
* Each input has at most one wire: FBD has no wired OR (GR-30); two wires into one
  input are an error that names both.
* Blocks run in data-flow order (a node after everything feeding it). Among
  nodes the wiring leaves independent, the network's ``order`` list decides,
  then position (top to bottom, then left to right), then id.
* A wire cycle is broken where that order says: the first node of the cycle
  reads the wires coming back from later nodes as *feedback* (the previous
  scan's value, GR-06 d).
* Output nodes run after their source; input nodes are read just before their
  first consumer; jumps and returns run last, once every other node of the
  network is evaluated (GR-05 c).
* A CFC chart (``explicit=True``, CFC-02) runs its blocks, outputs, jumps,
  labels and returns in the ``order`` list's order whatever the wiring (elements it leaves
  out follow in the FBD order above); every wire into an element that runs
  before the wire's producer is feedback.

The result is data only (``NetworkGraph``); lower_fbd turns it into IR and the
editor shows ``order`` as execution-order badges.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field
from typing import NamedTuple, Protocol

from ..model import fbd
from ..model.places import NetworkNames
from .diagram_checks import Report

# Node kinds by their ``type`` tag: comparing tags is several times cheaper than isinstance on the pydantic
# (ABC) node classes, and the structure of a large diagram asks it some 100 times per network.
PRODUCERS = frozenset({"block", "input", "continuation"})  # nodes with an output pin
CONSUMERS = frozenset({"block", "output", "jump", "return", "connector"})  # nodes with an input pin
CONTROL = frozenset({"jump", "return", "label"})  # labels: CFC charts only (an FBD network reports one)
# The one pin of the simple nodes, as the editor draws them.
SIMPLE_OUT = "OUT"
SIMPLE_IN = "IN"

_KIND = {
    "block": "a block",
    "input": "an input",
    "output": "an output",
    "jump": "a jump",
    "return": "a return",
    "label": "a label",
    "connector": "a connector",
    "continuation": "a continuation",
    "comment": "a comment",
}


class Source(NamedTuple):
    """The output pin feeding an input, after following connectors; ``via`` the wire that reaches the input."""

    node: str
    pin: str
    via: fbd.Wire


@dataclass
class NetworkGraph:
    nodes: dict[str, fbd.FbdNode]
    #: consumer node id -> {upper-case input pin: its source}
    inputs: dict[str, dict[str, Source]] = field(default_factory=dict)
    #: ids of blocks, input, output, jump and return nodes in evaluation order
    order: list[str] = field(default_factory=list)
    #: (consumer id, pin) pairs whose wire carries the previous scan's value
    feedback: set[tuple[str, str]] = field(default_factory=set)
    #: (consumer id, pin) pairs wired to a continuation that leads nowhere (already reported)
    broken: set[tuple[str, str]] = field(default_factory=set)

    def visit(self, visitor: NodeVisitor) -> None:
        """Hand every node to the visitor in evaluation order (the lowering and the ST export walk it alike)."""
        for node_id in self.order:
            node = self.nodes[node_id]
            kind = node.type
            if kind == "input":
                visitor.input_node(node)
            elif kind == "block":
                visitor.block(node)
            elif kind == "output":
                visitor.output_node(node)
            elif kind == "label":
                visitor.label(node)
            else:
                visitor.control(node)


class NodeVisitor(Protocol):
    def input_node(self, node: fbd.InputNode) -> None: ...
    def block(self, node: fbd.Block) -> None: ...
    def output_node(self, node: fbd.OutputNode) -> None: ...
    def control(self, node: fbd.FbdJump | fbd.FbdReturn) -> None: ...
    def label(self, node: fbd.FbdLabel) -> None: ...


def wire_text(wire: fbd.Wire, names: NetworkNames) -> str:
    """The wire as messages name it: ``from ADD.OUT to output Level``."""
    return f"from {names(wire.from_.node, wire.from_.pin.upper())} to {names(wire.to.node, wire.to.pin.upper())}"


def analyse(network: fbd.FbdNetwork, report: Report, explicit: bool = False) -> NetworkGraph:
    """Resolve the wires of ``network`` and fix its evaluation order, reporting structural errors;
    ``explicit``: a CFC chart, whose ``order`` list is the order (CFC-02)."""
    nodes: dict[str, fbd.FbdNode] = {}
    named = False  # any connector or continuation? (most networks have none)
    for node in network.nodes:
        nodes.setdefault(node.id, node)  # a repeated id is reported for the whole POU (check_unique_ids)
        named = named or node.type in ("connector", "continuation")
    graph = NetworkGraph(nodes)
    names = NetworkNames(network)
    wires = _wires_by_input(network, nodes, report, names)
    connectors = _connectors(network, nodes, report) if named else {}
    _resolve(graph, network, wires, connectors, report)
    graph.order = _order(graph, network, report)
    if explicit:
        graph.order = _explicit_order(graph, network)
    return graph


def _wires_by_input(
    network: fbd.FbdNetwork, nodes: dict[str, fbd.FbdNode], report: Report, names: NetworkNames
) -> dict[tuple[str, str], fbd.Wire]:
    """Valid wires by their (consumer, PIN) end; a second wire into one input is a wired OR (GR-30)."""
    result: dict[tuple[str, str], fbd.Wire] = {}  # the first wire into each input
    more: dict[tuple[str, str], list[fbd.Wire]] = {}  # the further ones (wired ORs, rare)
    for wire in network.wires:
        source, target = wire.from_, wire.to
        pin = target.pin.upper()
        if (
            _plain_end(nodes.get(source.node), source.pin, PRODUCERS, SIMPLE_OUT)
            and _plain_end(nodes.get(target.node), pin, CONSUMERS, SIMPLE_IN)
        ) or (
            _valid_end(wire, source, nodes, PRODUCERS, SIMPLE_OUT, "output", network.id, report, names)
            and _valid_end(wire, target, nodes, CONSUMERS, SIMPLE_IN, "input", network.id, report, names)
        ):
            key = (target.node, pin)
            if key not in result:
                result[key] = wire
            else:
                more.setdefault(key, []).append(wire)
    for node, pin in [key for key in result if key in more] if more else []:  # in the order of their first wires
        group = [result[(node, pin)], *more[(node, pin)]]
        sources = " and ".join(f"from {names(w.from_.node, w.from_.pin.upper())}" for w in group)
        into = f"input {pin}" if nodes[node].type == "block" else "it"
        report(
            "FBD-WIRED-OR",
            f"{len(group)} wires lead into {into} ({sources}): FBD has no wired OR, use an OR block",
            network=network.id,
            element=node,
            pin=pin,
        )
    return result


def _plain_end(node: fbd.FbdNode | None, pin: str, kinds: frozenset, simple_pin: str) -> bool:
    """``_valid_end`` without its reports, for the common case of a valid end (checked for every wire)."""
    kind = node.type if node is not None else None
    return kind == "block" or (kind in kinds and (pin == simple_pin or pin.upper() == simple_pin))


def _valid_end(
    wire: fbd.Wire,
    end: fbd.PinRef,
    nodes: dict[str, fbd.FbdNode],
    kinds: frozenset,
    simple_pin: str,
    side: str,
    network: str,
    report: Report,
    names: NetworkNames,
) -> bool:
    node = nodes.get(end.node)
    if node is None:
        report(
            "FBD-BAD-WIRE",
            f"the wire {wire_text(wire, names)} ends at a node this network does not have",
            network=network,
            element=end.node,
            pin=end.pin.upper(),
        )
        return False
    if node.type not in kinds:
        report(
            "FBD-BAD-WIRE",
            f"the wire {wire_text(wire, names)}: {_KIND[node.type]} has no {side} pin",
            network=network,
            element=node.id,
            pin=end.pin.upper(),
        )
        return False
    if node.type != "block" and end.pin.upper() != simple_pin:
        report(
            "FBD-BAD-WIRE",
            f"the wire {wire_text(wire, names)}: {_KIND[node.type]} has no {side} pin {end.pin.upper()}",
            network=network,
            element=node.id,
            pin=end.pin.upper(),
        )
        return False
    return True


def _connectors(network: fbd.FbdNetwork, nodes: dict[str, fbd.FbdNode], report: Report) -> dict[str, str]:
    """Connector name (upper case) -> connector node id; duplicates and orphan continuations are reported."""
    connectors: dict[str, str] = {}
    for node in nodes.values():
        if isinstance(node, fbd.Connector):
            key = node.name.upper()
            if key in connectors:
                report(
                    "FBD-CONNECTOR",
                    f"this network has another connector '{node.name}'",
                    network=network.id,
                    element=node.id,
                )
            else:
                connectors[key] = node.id
    for node in nodes.values():
        if isinstance(node, fbd.Continuation) and node.name.upper() not in connectors:
            report(
                "FBD-CONNECTOR",
                f"this network has no connector '{node.name}' for the continuation to continue",
                network=network.id,
                element=node.id,
            )
    return connectors


def _resolve(
    graph: NetworkGraph,
    network: fbd.FbdNetwork,
    wires: dict[tuple[str, str], fbd.Wire],
    connectors: dict[str, str],
    report: Report,
) -> None:
    """Fill ``graph.inputs`` with every consumer pin's real source; report outputs and connectors left unwired."""
    nodes, inputs = graph.nodes, graph.inputs
    for (node_id, pin), wire in wires.items():
        if nodes[node_id].type == "connector":
            continue
        producer = nodes[wire.from_.node]
        if producer.type == "continuation":
            source = _follow(wire, nodes, wires, connectors, set())
        else:  # the common case, as _follow would answer it
            source = Source(producer.id, wire.from_.pin.upper(), wire)
        if source is None:
            graph.broken.add((node_id, pin))
        elif node_id in inputs:
            inputs[node_id][pin] = source
        else:
            inputs[node_id] = {pin: source}
    for node in nodes.values():
        if node.type != "output" and node.type != "connector":
            continue
        if (node.id, SIMPLE_IN) not in wires:
            what = "the output" if isinstance(node, fbd.OutputNode) else "the connector"
            report("FBD-DANGLING", f"{what} has no input wire", network=network.id, element=node.id, pin=SIMPLE_IN)
        elif isinstance(node, fbd.Connector):
            _follow(wires[(node.id, SIMPLE_IN)], nodes, wires, connectors, set(), report, network.id)


def _follow(
    wire: fbd.Wire,
    nodes: dict[str, fbd.FbdNode],
    wires: dict[tuple[str, str], fbd.Wire],
    connectors: dict[str, str],
    seen: set[str],
    report: Report | None = None,
    network: str = "",
) -> Source | None:
    """The block or input node output at the far end of ``wire``, through any connectors."""
    producer = nodes[wire.from_.node]
    if not isinstance(producer, fbd.Continuation):
        return Source(producer.id, wire.from_.pin.upper(), wire)
    connector = connectors.get(producer.name.upper())
    if connector is None or connector in seen or (connector, SIMPLE_IN) not in wires:
        if report is not None and connector in seen:
            report(
                "FBD-CONNECTOR",
                "the connector is fed only through its own continuations",
                network=network,
                element=connector,
            )
        return None
    return _follow(wires[(connector, SIMPLE_IN)], nodes, wires, connectors, seen | {connector}, report, network)


# --------------------------------------------------------------------------- evaluation order


def _order(graph: NetworkGraph, network: fbd.FbdNetwork, report: Report) -> list[str]:
    nodes, inputs = graph.nodes, graph.inputs
    key = _priorities(network, nodes, report).__getitem__  # a node's priority among those the wiring leaves independent

    predecessors: dict[str, set[str]] = {}  # blocks and output nodes (in node order) -> the blocks feeding them
    fed = {s.node for sources in inputs.values() for s in sources.values()}
    unused: list[str] = []  # input nodes that feed nothing
    control: list[str] = []
    for node in nodes.values():
        kind = node.type
        if kind == "block" or kind == "output":
            predecessors[node.id] = {
                s.node for s in inputs.get(node.id, _NONE).values() if nodes[s.node].type == "block"
            }
        elif kind == "input":
            if node.id not in fed:
                unused.append(node.id)
        elif kind in CONTROL:
            control.append(node.id)
    scheduled = _data_flow_order(list(predecessors), predecessors, key)
    done: set[str] = set()
    for node_id in scheduled:
        preds = predecessors[node_id]
        if preds:
            for pin, source in inputs[node_id].items():
                if source.node in preds and source.node not in done:
                    graph.feedback.add((node_id, pin))
        done.add(node_id)
    return _place_inputs(graph, scheduled + sorted(unused, key=key) + sorted(control, key=key), key)


_NONE: dict[str, Source] = {}  # no inputs (read only)

EXECUTED = frozenset(fbd.EXECUTED_ELEMENTS)


def _explicit_order(graph: NetworkGraph, network: fbd.FbdNetwork) -> list[str]:
    """CFC-02: the executed elements in ``order`` list order, then the unlisted ones in the data-flow order
    ``graph.order`` holds; a wire from an element that runs later (or from the element itself) is feedback.
    Unknown ids in the list were reported by ``_order``."""
    nodes = graph.nodes
    listed = [
        node_id
        for node_id in dict.fromkeys(network.order or [])
        if node_id in nodes and nodes[node_id].type in EXECUTED
    ]
    chosen = set(listed)
    executed = listed + [n for n in graph.order if nodes[n].type in EXECUTED and n not in chosen]
    graph.feedback = set()
    done: set[str] = set()
    for node_id in executed:
        for pin, source in graph.inputs.get(node_id, _NONE).items():
            if nodes[source.node].type == "block" and source.node not in done:
                graph.feedback.add((node_id, pin))
        done.add(node_id)
    fed = {source.node for sources in graph.inputs.values() for source in sources.values()}
    unused = [n for n in graph.order if nodes[n].type == "input" and n not in fed]
    position = {node_id: i for i, node_id in enumerate(graph.order)}
    return _place_inputs(graph, executed + unused, position.__getitem__)


def _priorities(network: fbd.FbdNetwork, nodes: dict[str, fbd.FbdNode], report: Report) -> dict[str, tuple]:
    """Node id -> its priority key: rank in the ``order`` list, then position (top to bottom, left to right),
    then id."""
    rank = _explicit_ranks(network, nodes, report)
    return {
        node_id: (
            rank.get(node_id, len(rank)),
            node.pos.y if node.pos else math.inf,
            node.pos.x if node.pos else math.inf,
            node_id,
        )
        for node_id, node in nodes.items()
    }


def _explicit_ranks(network: fbd.FbdNetwork, nodes: dict[str, fbd.FbdNode], report: Report) -> dict[str, int]:
    ranks: dict[str, int] = {}
    for node_id in network.order or []:
        if node_id not in nodes:
            report(
                "FBD-ORDER",
                f"the network's execution order names a node it does not have ('{node_id}')",
                network=network.id,
                element=node_id,
            )
        else:
            ranks.setdefault(node_id, len(ranks))
    return ranks


def _data_flow_order(nodes: list[str], predecessors: dict[str, set[str]], key) -> list[str]:
    """Kahn's algorithm with a priority key; when only cycles remain, the best-keyed node of a source
    strongly connected component goes first (its incoming cycle wires become feedback)."""
    component: dict[str, int] | None = None  # computed only if a cycle is met
    waiting = {n: set(p) for n, p in predecessors.items()}
    successors: dict[str, list[str]] = {n: [] for n in nodes}
    for node, preds in predecessors.items():
        for pred in preds:
            successors[pred].append(node)
    ready = [(key(n), n) for n in nodes if not waiting[n]]
    heapq.heapify(ready)
    order: list[str] = []
    done: set[str] = set()
    while len(order) < len(nodes):
        if not ready:  # only cycles are left: start one that nothing outside it still feeds
            component = component or _components(nodes, predecessors)
            blocked = {component[n] for n in nodes if n not in done for p in waiting[n] if component[p] != component[n]}
            first = min((n for n in nodes if n not in done and component[n] not in blocked), key=key)
            heapq.heappush(ready, (key(first), first))
        _, node = heapq.heappop(ready)
        if node in done:
            continue
        done.add(node)
        order.append(node)
        for succ in successors[node]:
            waiting[succ].discard(node)
            if not waiting[succ] and succ not in done:
                heapq.heappush(ready, (key(succ), succ))
    return order


def _components(nodes: list[str], predecessors: dict[str, set[str]]) -> dict[str, int]:
    """Strongly connected components (iterative Tarjan over predecessor edges): node -> component number."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    component: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    count = 0
    for root in nodes:
        if root in index:
            continue
        work = [(root, iter(sorted(predecessors[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, edges = work[-1]
            advanced = False
            for nxt in edges:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(predecessors[nxt]))))
                    advanced = True
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component[member] = count
                    if member == node:
                        break
                count += 1
    return component


def _place_inputs(graph: NetworkGraph, order: list[str], key) -> list[str]:
    """Put each input node just before its first consumer (unused ones stay where ``order`` has them)."""
    nodes = graph.nodes
    placed = set(order)
    result: list[str] = []
    for node_id in order:
        sources = [
            s.node
            for s in graph.inputs.get(node_id, _NONE).values()
            if s.node not in placed and nodes[s.node].type == "input"
        ]
        if len(sources) > 1:
            sources.sort(key=key)
        for source in sources:
            if source not in placed:  # one input node may feed several pins of this node
                placed.add(source)
                result.append(source)
        result.append(node_id)
    return result


# --------------------------------------------------------------------------- networks drawn alike


class Analyses:
    """``analyse`` for the networks of one POU, once per structure. Networks drawn alike - the same kinds of
    nodes (connectors with the same names) in the same order, wired alike, ranked alike by order list and
    position - have the same graph but for node ids and wire objects, which are put in (a hand-drawn program
    repeats its rungs; a generated 10,000-network one has two structures). A structure whose analysis
    reported anything is analysed again for every network, so each gets its own diagnostics."""

    def __init__(self) -> None:
        self._known: dict[tuple, _Pattern | None] = {}

    def analyse(self, network: fbd.FbdNetwork, report: Report) -> NetworkGraph:
        structure = _structure(network)
        if structure is None:
            return analyse(network, report)
        key, ids = structure
        pattern = self._known.get(key, _UNKNOWN)
        if isinstance(pattern, _Pattern):
            return pattern.graph(network, ids)
        reported: list[bool] = []

        def counting(*args, **kwargs) -> None:
            reported.append(True)
            report(*args, **kwargs)

        graph = analyse(network, counting)
        if pattern is _UNKNOWN:
            self._known[key] = None if reported else _Pattern.of(graph, network, ids)
        return graph


_UNKNOWN = object()


def _structure(network: fbd.FbdNetwork) -> tuple[tuple, list[str]] | None:
    """A network's structure key and its node ids in node order; None when the ids repeat or the ``order``
    list names an unknown node (the key would miss what that reports)."""
    nodes = network.nodes
    ids = [node.id for node in nodes]
    index = {node_id: i for i, node_id in enumerate(ids)}
    if len(index) != len(ids) or (network.order and any(node_id not in index for node_id in network.order)):
        return None
    kinds = tuple(
        node.type if node.type not in ("connector", "continuation") else (node.type, node.name.upper())
        for node in nodes
    )
    wires = tuple(
        (index.get(wire.from_.node, -1), wire.from_.pin.upper(), index.get(wire.to.node, -1), wire.to.pin.upper())
        for wire in network.wires
    )
    priority = _priorities(network, dict(zip(ids, nodes)), _unreported)
    ranking = tuple(sorted(range(len(ids)), key=lambda i: priority[ids[i]]))
    return (kinds, wires, ranking), ids


def _unreported(*_args, **_kwargs) -> None:
    """For a structure key: what the analysis reports, it reports itself."""


class _Pattern(NamedTuple):
    """A network's graph with node positions (in node order) for its ids and wire positions for its wires."""

    inputs: tuple[tuple[int, tuple[tuple[str, int, str, int], ...]], ...]
    order: tuple[int, ...]
    feedback: tuple[tuple[int, str], ...]
    broken: tuple[tuple[int, str], ...]

    @staticmethod
    def of(graph: NetworkGraph, network: fbd.FbdNetwork, ids: list[str]) -> _Pattern:
        index = {node_id: i for i, node_id in enumerate(ids)}
        wire_at = {id(wire): k for k, wire in enumerate(network.wires)}
        return _Pattern(
            tuple(
                (index[node], tuple((pin, index[s.node], s.pin, wire_at[id(s.via)]) for pin, s in pins.items()))
                for node, pins in graph.inputs.items()
            ),
            tuple(index[node] for node in graph.order),
            tuple((index[node], pin) for node, pin in graph.feedback),
            tuple((index[node], pin) for node, pin in graph.broken),
        )

    def graph(self, network: fbd.FbdNetwork, ids: list[str]) -> NetworkGraph:
        wires = network.wires
        return NetworkGraph(
            dict(zip(ids, network.nodes)),
            {
                ids[i]: {pin: Source(ids[j], source_pin, wires[k]) for pin, j, source_pin, k in pins}
                for i, pins in self.inputs
            },
            [ids[i] for i in self.order],
            {(ids[i], pin) for i, pin in self.feedback},
            {(ids[i], pin) for i, pin in self.broken},
        )
