"""PLCopen ``<LD>`` graph -> LD body (series/parallel model).

Each network (a connected drawing, or the network LadderLab wrote) becomes a
power-flow graph: contacts, coils, compare blocks, boxes, jumps and returns are
edges from their power input to their power output, the left rail is the source,
the right rail (and every output nobody reads) the sink. ``plcopen_sp`` reduces
it to series lists and parallels; a bridge is refused with a diagnostic naming
its elements.

Blocks are read the way the model draws them:

- a comparison block (GT, GE, EQ, LE, LT, NE) fed by two values, whose OUT
  carries on the power flow, is a compare contact;
- a function block without instance whose only output feeds other blocks'
  inputs (e.g. INT_TO_DINT in front of a vendor block) is written inline, as
  the call text of that input;
- any other block is a box. Power enters EN when EN is wired, else the first
  input that can be BOOL when power feeds it (``plcopen_blocks``); otherwise the
  box runs unconditionally (EN from the rail, as PLCopen's unwired EN means).
  Inputs fed by values become operand texts (``T1.Q`` for another block's
  output), inputs fed by contacts a series list from the left rail, outputs
  wired to variables its ``outputs``;
- a block output that is not the power output but feeds contacts or coils
  (``TOF0.Q`` to a coil while power leaves by ENO) is read by a contact on
  ``TOF0.Q`` placed after the block; a variable fed by power is a coil, one fed
  by a value a MOVE box.
"""

from __future__ import annotations

import re
from collections import defaultdict
from dataclasses import dataclass, field

from ...iec import stdlib
from ...iec.elementary import canonical_type_name
from ...model.ld import Box, Coil, Compare, Contact, Jump, LdBody, LdElement, LdNetwork, Parallel, Return
from .blocks import RESULT_PIN, Signatures
from .body import IdMaker, NetworkGroup
from .graph import Conn, Element, Graph, reaches
from .sp import Edge, NotSeriesParallel, Par, reduce_graph
from .xml_io import Reader

COMPARE_OPS = ("GT", "GE", "EQ", "LE", "LT", "NE")
S, T = 0, 1  # left rail, right rail (every jump and return gets a sink point of its own)
_SIMPLE = re.compile(r"^[A-Za-z_%][A-Za-z0-9_.%\[\]]*\Z")
_POWER_CONSUMERS = ("contact", "coil", "jump", "return", "rightPowerRail")
_CONTACT_MODE = {(False, None): "no", (True, None): "nc", (False, "rising"): "p", (False, "falling"): "n"}


def negate(text: str) -> str:
    """``NOT x`` / ``NOT (a > b)``: an inverted operand (negated variables and pins)."""
    return f"NOT {text}" if _SIMPLE.match(text) else f"NOT ({text})"


@dataclass
class _Plan:
    """How one block is read: its role and, for a box, its power pins."""

    role: str  # "compare", "inline" or "box"
    power_in: str | None = None
    power_out: str | None = None
    en: bool = False
    virtual_en: bool = False
    constant: bool = False  # an FB that always runs, read without its EN/ENO chain (always_enabled)


@dataclass
class _Net:
    """Working state of one network."""

    members: set[int]
    edges: list[Edge] = field(default_factory=list)
    next_node: int = 2
    ends: list[tuple[tuple, int]] = field(default_factory=list)  # (sort key, sink) of each jump/return
    out_nodes: dict[tuple[int, str | None], int] = field(default_factory=dict)
    junctions: dict[frozenset[int], int] = field(default_factory=dict)
    virtual: dict[tuple[int, str | None], int] = field(default_factory=dict)
    side_points: dict[tuple[int, str], int] = field(default_factory=dict)

    def node(self) -> int:
        self.next_node += 1
        return self.next_node - 1


class LdImporter:
    """Reads the networks of one LD body; problems go to ``reader`` located at the POU and element."""

    def __init__(
        self, graph: Graph, reader: Reader, pou: str, signatures: Signatures, ids: IdMaker, *, foreign: bool = True
    ):
        self.graph = graph
        #: Drawn by another tool: read an FB on an EN/ENO chain as its author drew it (LadderLab's own files say
        #: what each box is, and read back exactly).
        self.foreign = foreign
        self.reader = reader
        self.pou = pou
        self.signatures = signatures
        self.ids = ids
        self.consumers = graph.consumers()
        self.plans: dict[int, _Plan] = {}
        self.inline: dict[int, tuple[str, set[int]]] = {}
        self.models: dict[int, LdElement] = {}  # localId -> model element
        self.reads: dict[int, set[int]] = defaultdict(set)  # id(model element) -> localIds of boxes it reads
        self.box_of: dict[int, int] = {}  # id(model element) -> localId of the block it stands for
        self.paths: dict[int, list[str]] = {}  # id(model element) -> LadderLab's enclosing parallel ids
        self.keys: dict[int, tuple] = {}  # id(model element) -> drawing position, orders parallel branches
        self.right_rail: dict[int, list[tuple[Element, Conn]]] = defaultdict(list)  # localId -> its rail connections
        for rail in (e for e in graph.elements.values() if e.tag == "rightPowerRail"):
            for conn in rail.inputs.get("", []):
                self.right_rail[conn.ref].append((rail, conn))

    def body(self, groups: list[NetworkGroup]) -> LdBody:
        return LdBody(networks=[self.network(group) for group in groups])

    # ------------------------------------------------------------ reporting

    def error(
        self,
        message: str,
        element: Element | None,
        *,
        network: str | None,
        severity: str = "error",
        code: str = "PLCOPEN-LD",
    ) -> None:
        self.reader.report(
            code,
            message,
            element.node if element else None,
            severity=severity,
            pou=self.pou,
            network=network,
            item=f"localId {element.local_id}" if element else None,
        )

    # ------------------------------------------------------------ network

    def network(self, group: NetworkGroup) -> LdNetwork:
        network_id = self.ids.take(group.id, "network")
        self.network_id = network_id
        net = _Net(set(group.members))
        flow = [
            m
            for m in self.topological(group.members)
            if self.graph.elements[m].tag not in ("leftPowerRail", "rightPowerRail")
        ]
        for local_id in flow:
            self.plan(self.graph.elements[local_id])
        for local_id in flow:
            self.place(self.graph.elements[local_id], net)
        for member in group.members:
            for rail, conn in self.right_rail.get(member, []):
                if self.is_power(conn):
                    self.wire(self.source_node(conn, net, rail), T, net)
        self.dangling(net)
        elements = self.reduce(net)
        return LdNetwork(id=network_id, label=group.label, comment=group.comment, elements=elements)

    def topological(self, members: list[int]) -> list[int]:
        """Members in data-flow order (a variable read through an inOutVariable does not wait for its write)."""
        inside = set(members)
        after: dict[int, set[int]] = defaultdict(set)
        waiting: dict[int, int] = {m: 0 for m in members}
        for m in members:
            for conns in self.graph.elements[m].inputs.values():
                for conn in conns:
                    source = self.graph.elements[conn.ref]
                    if conn.ref in inside and source.tag != "inOutVariable" and m not in after[conn.ref]:
                        after[conn.ref].add(m)
                        waiting[m] += 1
        ready = sorted((m for m, n in waiting.items() if n == 0), key=lambda m: self.graph.elements[m].key)
        out = []
        while ready:
            m = ready.pop(0)
            out.append(m)
            for n in sorted(after[m], key=lambda m: self.graph.elements[m].key):
                waiting[n] -= 1
                if waiting[n] == 0:
                    ready.append(n)
            ready.sort(key=lambda m: self.graph.elements[m].key)
        if len(out) < len(members):
            stuck = sorted(set(members) - set(out))
            self.error(
                f"the elements with localIds {stuck} form a loop; LD networks cannot have feedback",
                self.graph.elements[stuck[0]],
                network=self.network_id,
            )
            out += stuck
        return out

    # ------------------------------------------------------------ what each element is

    def is_power(self, conn: Conn) -> bool:
        source = self.graph.elements[conn.ref]
        if source.tag in ("leftPowerRail", "contact", "coil"):
            return True
        plan = self.plans.get(conn.ref)
        if plan is None or source.tag != "block":
            return False
        return (plan.role == "compare" and conn.param == RESULT_PIN) or (
            plan.role == "box" and plan.power_out is not None and conn.param == plan.power_out
        )

    def text(self, conn: Conn, reader: int | None = None) -> tuple[str, set[int]] | None:
        """The operand text of a value source and the blocks it reads, or None for a power source.

        Reading an inOutVariable waits for the block writing it, unless ``reader`` feeds that block (feedback).
        """
        source = self.graph.elements[conn.ref]
        if source.tag in ("inVariable", "inOutVariable"):
            text = source.text(self.reader, "expression")
            mods = source.mods.get("")
            negated = mods is not None and mods.negated and source.tag == "inVariable"
            writers = {c.ref for c in source.inputs.get("", []) if self.graph.elements[c.ref].tag == "block"}
            if reader is not None:
                writers = {w for w in writers if not reaches(self.consumers, reader, w)}
            return (negate(text) if negated else text), writers
        if source.tag != "block" or (self.is_power(conn) and not source.node.get("instanceName")):
            return None
        if conn.ref in self.inline:
            return self.inline[conn.ref]
        instance = source.node.get("instanceName")
        if instance:
            return f"{instance}.{conn.param}", {conn.ref}
        for consumer, _, c in self.consumers.get(conn.ref, []):
            target = self.graph.elements[consumer]
            if c.param == conn.param and target.tag in ("outVariable", "inOutVariable"):
                return target.text(self.reader, "expression"), {conn.ref}
        return None

    def plan(self, element: Element) -> None:
        if element.tag != "block":
            return
        type_name = element.node.get("typeName", "")
        instance = element.node.get("instanceName")
        sig = self.signatures(type_name)
        inputs = element.inputs
        en_pin = next((p for p in element.in_pins if p.upper() == "EN"), None)
        wired_en = bool(en_pin and inputs.get(en_pin))
        values = [p for p in element.in_pins if p.upper() != "EN"]
        eno_pin = next((p for p in element.out_pins if p.upper() == "ENO"), None)
        eno_free = all(
            self.graph.elements[c].tag == "rightPowerRail"
            for c, _, conn in self.consumers.get(element.local_id, [])
            if conn.param == eno_pin
        )
        if (
            type_name.upper() in COMPARE_OPS
            and not instance
            and [p.upper() for p in values] == ["IN1", "IN2"]
            and all(len(inputs[p]) == 1 and self.text(inputs[p][0]) is not None for p in values)
            and all(self.is_power(c) for c in inputs.get(en_pin or "", []))
            and eno_free
            and self.used_outputs(element) == {RESULT_PIN}
        ):
            self.plans[element.local_id] = _Plan("compare", "EN", RESULT_PIN)
            return
        if (
            not instance
            and (sig is None or sig.kind == "function")
            and eno_free
            and all(self.graph.elements[c.ref].tag == "leftPowerRail" for c in inputs.get(en_pin or "", []))
            and self.feeds_only_blocks(element)
            and all(self.text(c) is not None for p in values for c in inputs[p])
            and all(len(inputs[p]) <= 1 for p in values)
        ):
            self.inline_call(element, type_name, values)
            self.plans[element.local_id] = _Plan("inline")
            return
        plan = _Plan("box", en=True, power_in=en_pin, power_out=eno_pin or "ENO")
        if self.foreign and wired_en and self.always_enabled(element, sig, instance, en_pin, eno_pin):
            # Issue 28: an FB on an EN/ENO chain from the left rail always runs (an FB's ENO is its EN), so the
            # power flow can pass from its BOOL input to its BOOL output as drawn, left to right (OpenPLC's
            # contact -> TON -> TOF -> coil), instead of a box on the rail and its output read by a contact.
            power_in = self.power_input(values, inputs, sig.bool_inputs() if sig is not None else [])
            power_out = self.power_output(element, sig)
            if power_in is not None and power_out is not None:
                self.plans[element.local_id] = _Plan("box", power_in=power_in, power_out=power_out, constant=True)
                return
        if not wired_en:
            # Without EN the power flow passes through the box only from a BOOL input to a BOOL output. An
            # unknown FB (a vendor block) has neither as far as the export could name them again: it runs
            # unconditionally (EN from the rail, as an unwired EN means) with every input as drawn.
            power_in = self.power_input(
                values, inputs, sig.bool_inputs() if sig is not None else values[:1] if not instance else []
            )
            power_out = self.power_output(element, sig)
            if power_in is not None and power_out is not None:
                plan = _Plan("box", power_in=power_in, power_out=power_out)
            else:
                plan.virtual_en, plan.power_in = True, "EN"
        self.plans[element.local_id] = plan

    def always_enabled(self, element: Element, sig, instance: str | None, en_pin: str, eno_pin: str | None) -> bool:
        """An FB whose EN comes only from the left rail or the ENO of an FB that always runs, and whose ENO goes
        only to the right rail or other blocks' EN: it runs in every scan, whatever its EN says."""
        if not instance or (sig is not None and sig.kind != "function_block"):
            return False
        for conn in element.inputs.get(en_pin, []):
            source = self.graph.elements[conn.ref]
            plan = self.plans.get(conn.ref)
            from_chain = plan is not None and plan.constant and (conn.param or "").upper() == "ENO"
            if source.tag != "leftPowerRail" and not from_chain:
                return False
        return all(
            self.graph.elements[c].tag == "rightPowerRail" or target_pin.upper() == "EN"
            for c, target_pin, conn in self.consumers.get(element.local_id, [])
            if eno_pin is not None and conn.param == eno_pin
        )

    def power_output(self, element: Element, sig) -> str | None:
        """The output the power flow leaves by: the first that is BOOL, or of a generic type and driving contacts
        or coils (the lowering accepts a function's generic result when its operands make it BOOL)."""
        wanted = (
            sig.power_out(False) if sig is not None else next((p for p in element.out_pins if p.upper() != "ENO"), None)
        )
        pin = next((p for p in element.out_pins if wanted and p.upper() == wanted.upper()), wanted)
        declared = dict(sig.outputs).get(wanted) if sig is not None else None
        if pin is not None and (canonical_type_name(declared or "") == "BOOL" or self.feeds_power(element, pin)):
            return pin
        return None

    def feeds_power(self, element: Element, pin: str) -> bool:
        """Does a pin of uncertain type (generic OUT of SEL, a vendor block's output) drive contacts or coils?"""
        return any(
            conn.param == pin and (self.graph.elements[c].tag in _POWER_CONSUMERS or target_pin.upper() == "EN")
            for c, target_pin, conn in self.consumers.get(element.local_id, [])
        )

    def power_input(self, values: list[str], inputs: dict[str, list[Conn]], bool_inputs: list[str]) -> str | None:
        """The input the power flow enters, read the way the lowering picks it: the first BOOL input that gets
        no operand. So earlier BOOL inputs must be wired to values; an unwired one would take the power."""
        for wanted in bool_inputs:
            pin = next((p for p in values if p.upper() == wanted.upper()), None)
            conns = inputs.get(pin, []) if pin else []
            if not conns:
                return None
            if all(self.is_power(c) for c in conns):
                return pin
        return None

    def used_outputs(self, element: Element) -> set[str | None]:
        return {
            conn.param
            for _, _, conn in self.consumers.get(element.local_id, [])
            if conn.param is None or conn.param.upper() != "ENO"
        }

    def feeds_only_blocks(self, element: Element) -> bool:
        used = [
            (self.graph.elements[c], pin)
            for c, pin, conn in self.consumers.get(element.local_id, [])
            if conn.param is None or conn.param.upper() != "ENO"
        ]
        return (
            bool(used)
            and len(self.used_outputs(element)) == 1
            and all(target.tag == "block" and pin.upper() != "EN" for target, pin in used)
        )

    def inline_call(self, element: Element, type_name: str, values: list[str]) -> None:
        args, reads = [], set()
        for pin in values:
            if element.inputs[pin]:
                text, more = self.text(element.inputs[pin][0], element.local_id)
                mods = element.mods.get(pin)
                args.append(f"{pin} := {negate(text) if mods and mods.negated else text}")
                reads |= more
        self.inline[element.local_id] = (f"{type_name}({', '.join(args)})", reads)

    # ------------------------------------------------------------ graph building

    def model(self, element: Element, item: LdElement, reads: set[int] = frozenset()) -> LdElement:
        self.models[element.local_id] = item
        self.paths[id(item)] = (element.info.get("parallels") or "").split() if element.info is not None else []
        self.reads[id(item)] |= set(reads)
        return item

    def take_id(self, element: Element, prefix: str) -> str:
        return self.ids.take(element.model_id, prefix)

    def place(self, element: Element, net: _Net) -> None:
        tag = element.tag
        if tag in ("contact", "coil"):
            mods = element.mods.get("")
            var = element.text(self.reader, "variable")
            if tag == "contact":
                mode = _CONTACT_MODE.get((mods.negated, mods.edge))
                if mode is None:
                    self.error(
                        "a negated edge contact has no LD equivalent; read as a plain edge contact",
                        element,
                        network=self.network_id,
                        severity="warning",
                    )
                    mode = "p" if mods.edge == "rising" else "n"
                item = Contact(id=self.take_id(element, "contact"), var=var, mode=mode)
            else:
                item = Coil(id=self.take_id(element, "coil"), var=var, mode=self.coil_mode(element))
            self.power_edge(
                element, net, element.inputs.get("", []), self.model(element, item), (element.local_id, None)
            )
        elif tag in ("jump", "return"):
            if tag == "jump":
                item = Jump(id=self.take_id(element, "jump"), target=element.node.get("label", ""))
            else:
                item = Return(id=self.take_id(element, "ret"))
            self.power_edge(element, net, element.inputs.get("", []), self.model(element, item), None)
        elif tag in ("outVariable", "inOutVariable"):
            self.variable_sink(element, net)
        elif tag == "block":
            self.block(element, net)
        elif tag == "inVariable":
            if not self.consumers.get(element.local_id):
                self.error(
                    f"inVariable '{element.text(self.reader, 'expression')}' is connected to nothing; ignored",
                    element,
                    network=self.network_id,
                    severity="warning",
                )
        else:
            self.error(f"<{tag}> is not an LD element this project can hold", element, network=self.network_id)

    def coil_mode(self, element: Element) -> str:
        mods = element.mods.get("")
        if mods.storage:
            return mods.storage
        if mods.edge:
            return "p" if mods.edge == "rising" else "n"
        return "negated" if mods.negated else "normal"

    def variable_sink(self, element: Element, net: _Net) -> None:
        """An outVariable (or the input side of an inOutVariable): a coil when power feeds it, else an assignment."""
        conns = element.inputs.get("", [])
        var = element.text(self.reader, "expression")
        if not conns:
            if element.tag == "outVariable":
                self.error(
                    f"outVariable '{var}' is connected to nothing; ignored",
                    element,
                    network=self.network_id,
                    severity="warning",
                )
            return
        plan = self.plans.get(conns[0].ref)
        if len(conns) == 1 and plan is not None and plan.role == "box":
            box = self.models.get(conns[0].ref)
            if isinstance(box, Box) and conns[0].param not in box.outputs:
                box.outputs[conns[0].param] = var
                return
        if len(conns) == 1 and not self.is_power(conns[0]):
            found = self.text(conns[0], element.local_id)
            if found is None:
                self.error(f"the value written to '{var}' cannot be read here", element, network=self.network_id)
                return
            text, reads = found
            item = Box(id=self.ids.fresh("box"), call="MOVE", en=True, inputs={"IN": text}, outputs={"OUT": var})
            self.reads[id(item)] |= reads
            self.models.setdefault(element.local_id, item)
            self.paths[id(item)] = []
            self.add_edge(net, S, T, item, element)
            return
        item = Coil(id=self.take_id(element, "coil"), var=var, mode=self.coil_mode(element))
        self.power_edge(element, net, conns, self.model(element, item), None, sink=T)

    def block(self, element: Element, net: _Net) -> None:
        plan = self.plans[element.local_id]
        if plan.role == "inline":
            return
        inputs = element.inputs
        if plan.role == "compare":
            (left, reads_l), (right, reads_r) = (self.text(inputs[pin][0], element.local_id) for pin in ("IN1", "IN2"))
            item = Compare(
                id=self.take_id(element, "compare"), op=element.node.get("typeName").upper(), left=left, right=right
            )
            en = inputs.get(next((p for p in element.in_pins if p.upper() == "EN"), ""), [])
            self.power_edge(
                element,
                net,
                en,
                self.model(element, item, reads_l | reads_r),
                (element.local_id, RESULT_PIN),
                from_rail=not en,
            )
            return
        values: dict[str, str | list] = {}
        reads: set[int] = set()
        for pin in [*element.in_pins, *element.in_out_pins]:
            conns = inputs.get(pin, [])
            if pin == plan.power_in or not conns or pin.upper() == "EN":
                continue
            mods = element.mods.get(pin)
            if mods and mods.edge and not self.edge_pin(element, pin, mods.edge):
                self.error(
                    f"pin {pin} has an edge modifier, which an LD box cannot hold; it is ignored",
                    element,
                    network=self.network_id,
                    severity="warning",
                )
            if all(self.is_power(c) for c in conns):
                net.side_points[(element.local_id, pin)] = self.point(conns, net, element)
                values[pin] = []
                continue
            found = self.text(conns[0], element.local_id) if len(conns) == 1 else None
            if found is None:
                self.error(
                    f"input {pin} is fed by something that is neither a value nor the power flow",
                    element,
                    network=self.network_id,
                )
                continue
            text, more = found
            values[pin] = negate(text) if mods and mods.negated else text
            reads |= more
        item = Box(
            id=self.take_id(element, "box"),
            call=element.node.get("typeName", ""),
            instance=element.node.get("instanceName") or None,
            inputs=values,
            outputs={},
            en=plan.en,
        )
        self.box_of[id(item)] = element.local_id
        conns = [] if plan.virtual_en else inputs.get(plan.power_in, [])
        self.power_edge(
            element,
            net,
            conns,
            self.model(element, item, reads),
            (element.local_id, plan.power_out),
            from_rail=plan.virtual_en,
        )

    def edge_pin(self, element: Element, pin: str, edge: str) -> bool:
        """A rising modifier on a pin that is R_EDGE already (CTU.CU) changes nothing."""
        block = stdlib.function_block(element.node.get("typeName", ""))
        declared = next((p.edge for p in block.inputs if p.name == pin.upper()), None) if block else None
        return edge == "rising" and declared == "R_EDGE"

    def power_edge(
        self,
        element: Element,
        net: _Net,
        conns: list[Conn],
        item: LdElement,
        out: tuple[int, str | None] | None,
        *,
        sink: int | None = None,
        from_rail: bool = False,
    ) -> None:
        """The element as an edge from the point feeding it to its output point (or to ``sink``)."""
        if from_rail:
            start = S
        elif not conns:
            self.error(
                "this element has no power input; it is read as fed from the left rail",
                element,
                network=self.network_id,
            )
            start = S
        else:
            start = self.point(conns, net, element)
        if out is not None:
            end = self.out_node(out, net)
        elif sink is not None:
            end = sink
        else:  # a jump or return: the top row's last one first, the likely end of the rung
            end = net.node()
            net.ends.append(((element.y, -element.x, element.local_id), end))
        self.add_edge(net, start, end, item, element)

    def add_edge(self, net: _Net, u: int, v: int, item: LdElement, element: Element) -> None:
        self.keys[id(item)] = element.key
        net.edges.append(Edge(u, v, [item]))

    def out_node(self, out: tuple[int, str | None], net: _Net) -> int:
        if out not in net.out_nodes:
            net.out_nodes[out] = net.node()
        return net.out_nodes[out]

    def source_node(self, conn: Conn, net: _Net, consumer: Element) -> int:
        source = self.graph.elements[conn.ref]
        if source.tag == "leftPowerRail":
            return S
        if self.is_power(conn):
            return self.out_node((conn.ref, conn.param), net)
        key = (conn.ref, conn.param)
        if key not in net.virtual:
            found = self.text(conn, consumer.local_id)
            if found is None:
                self.error(
                    f"{source.tag} {source.local_id} cannot feed the power flow", consumer, network=self.network_id
                )
                found = ("FALSE", set())
            text, reads = found
            mods = source.mods.get("")
            if source.tag == "inVariable" and mods is not None and mods.negated:
                text, mode = source.text(self.reader, "expression"), "nc"
            else:
                mode = "no"
            item = Contact(id=self.ids.fresh("contact"), var=text, mode=mode)
            self.reads[id(item)] |= reads
            self.paths[id(item)] = []
            net.virtual[key] = net.node()
            self.add_edge(net, S, net.virtual[key], item, consumer)
        return net.virtual[key]

    def point(self, conns: list[Conn], net: _Net, consumer: Element) -> int:
        """The graph point an input is fed from: one source's point, or a junction (wired OR) of several."""
        nodes = list(dict.fromkeys(self.source_node(c, net, consumer) for c in conns))
        if len(nodes) == 1:
            return nodes[0]
        key = frozenset(nodes)
        if key not in net.junctions:
            net.junctions[key] = net.node()
            for n in nodes:
                self.wire(n, net.junctions[key], net)
        return net.junctions[key]

    @staticmethod
    def wire(u: int, v: int, net: _Net) -> None:
        net.edges.append(Edge(u, v, []))

    def dangling(self, net: _Net) -> None:
        """Outputs nobody reads end at the (implied) right rail."""
        starts = {e.u for e in net.edges}
        sides = set(net.side_points.values())
        for node in net.out_nodes.values():
            if node not in starts and node not in sides:
                self.wire(node, T, net)

    # ------------------------------------------------------------ reduction

    def reduce(self, net: _Net) -> list[LdElement]:
        edges = net.edges
        for (local_id, pin), point in net.side_points.items():
            box = self.models[local_id]
            side, edges = self.side_region(edges, point)
            if side is None:
                self.error(
                    f"input {pin} is fed by contacts that also feed other elements; LD boxes take a "
                    "series list of their own",
                    self.graph.elements[local_id],
                    network=self.network_id,
                )
                box.inputs.pop(pin, None)
                continue
            box.inputs[pin] = self.tree(self.sp(side, S, point, local_id, f"input {pin} is left unconnected"))
        if not edges:
            return []
        return self.tree(
            self.sp(edges, S, T, None, "the network is left empty", ends=[end for _, end in sorted(net.ends)])
        )

    def side_region(self, edges: list[Edge], point: int) -> tuple[list[Edge] | None, list[Edge]]:
        """The edges feeding only ``point`` (a box input's own contact chain) and the rest."""
        if point == S:
            return [], edges
        feeding = {point}
        changed = True
        while changed:
            changed = False
            for e in edges:
                if e.v in feeding and e.u not in feeding:
                    feeding.add(e.u)
                    changed = True
        side = [e for e in edges if e.v in feeding]
        exclusive = all(e.v in feeding for e in edges if e.u in feeding - {S})
        if not exclusive or any(e.u == point for e in edges):
            return None, edges
        return side, [e for e in edges if e.v not in feeding]

    def sp(
        self, edges: list[Edge], source: int, sink: int, owner: int | None, outcome: str, ends: list[int] = ()
    ) -> list:
        """The series list of a rung (or of a box input's chain); a bridge is reported and gives nothing."""
        try:
            return reduce_graph(edges, source, sink, lambda item: self.keys[id(item)], ends)
        except NotSeriesParallel as err:
            names = ", ".join(sorted({self.name_of(item) for item in err.items}))
            where = self.graph.elements[owner] if owner is not None else None
            self.error(
                f"the rung is not series-parallel (a bridge): {names} cannot be written as series and "
                f"parallel branches; {outcome}",
                where,
                network=self.network_id,
                code="PLCOPEN-LD-BRIDGE",
            )
            return []

    def name_of(self, item: LdElement) -> str:
        label = {Contact: "contact", Coil: "coil", Compare: "compare", Box: "box", Jump: "jump", Return: "return"}
        text = getattr(item, "var", None) or getattr(item, "call", None) or getattr(item, "target", None) or ""
        local_id = next((k for k, v in self.models.items() if v is item), None)
        where = f" (localId {local_id})" if local_id is not None else ""
        return f"{label[type(item)]} {text}{where}".replace("  ", " ")

    def tree(self, items: list, depth: int = 0) -> list[LdElement]:
        """``Par`` nodes -> ``Parallel`` elements with ids; branches ordered so a reader runs after its writer."""
        out: list[LdElement] = []
        for item in items:
            if isinstance(item, Par):
                branches = self.order_branches([self.tree(b, depth + 1) for b in item.branches])
                out.append(Parallel(id=self.parallel_id(branches, depth), branches=branches))
            else:
                out.append(item)
        return out

    def parallel_id(self, branches: list[list[LdElement]], depth: int) -> str:
        """The id LadderLab wrote for this parallel when all its elements agree on it (``parallels`` paths)."""
        wanted = {
            path[depth] if len(path) > depth else None
            for item in _leaves(branches, sides=False)
            for path in [self.paths.get(id(item), [])]
        }
        return self.ids.take(wanted.pop() if len(wanted) == 1 else None, "par")

    def order_branches(self, branches: list[list[LdElement]]) -> list[list[LdElement]]:
        writes = [{self.box_of[id(i)] for i in _leaves([b]) if id(i) in self.box_of} for b in branches]
        reads = [set().union(*(self.reads.get(id(i), set()) for i in _leaves([b]))) for b in branches]
        order, left = [], list(range(len(branches)))
        while left:
            pick = next((i for i in left if not reads[i] & set().union(*(writes[j] for j in left if j != i))), left[0])
            order.append(pick)
            left.remove(pick)
        return [branches[i] for i in order]


def _leaves(branches: list[list[LdElement]], *, sides: bool = True):
    """Every non-parallel element of the branches (and of box input lists, with ``sides``)."""
    for branch in branches:
        for item in branch:
            if isinstance(item, Parallel):
                yield from _leaves(item.branches, sides=sides)
            else:
                yield item
                if sides and isinstance(item, Box):
                    yield from _leaves([v for v in item.inputs.values() if isinstance(v, list)])


def ld_groups(graph: Graph) -> list[NetworkGroup]:
    """Networks of a foreign LD drawing: its connected parts (rails do not connect them), top to bottom."""
    flow = [
        m
        for m in graph.order
        if graph.elements[m].tag not in ("leftPowerRail", "rightPowerRail", "label", "comment", "error")
    ]
    parent = {m: m for m in flow}

    def find(m: int) -> int:
        while parent[m] != m:
            parent[m] = parent[parent[m]]
            m = parent[m]
        return m

    for m in flow:
        for conns in graph.elements[m].inputs.values():
            for conn in conns:
                if conn.ref in parent:
                    parent[find(conn.ref)] = find(m)
    parts: dict[int, list[int]] = defaultdict(list)
    for m in flow:
        parts[find(m)].append(m)
    ordered = sorted(parts.values(), key=lambda ms: min(graph.elements[m].key for m in ms))
    return [NetworkGroup(members=members) for members in ordered]
