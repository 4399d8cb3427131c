"""FBD body -> IR: one labelled block per network, nodes in the order fbd_order fixes (docs/diagrams.md).

Every block is the ST call it stands for (diagram_calls); its outputs stay where
the call leaves them - a function's result in a temporary (in a slot kept between
scans when the block has EN: EN FALSE keeps it), an FB's outputs in its instance -
and consumers read them there. A function block whose result feeds one plain input of
another block is typed as the call nested in that block's call (as the ST export
writes it; literal typing, docs/st.md): it waits, in its place, until that block is
lowered, then both are typed together and lowered where they stand. Pin flags add the inversion
or edge detection in front of an input or behind an output. Output nodes
write like LD coils (power.coil). Every block output pin is probed as
``<id>.<PIN>``; input, output, jump and return nodes as ``<id>``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..iec.spelling import did_you_mean
from ..model import fbd
from ..model.cfc import CfcBody
from ..model.places import NetworkNames, Places
from ..model.project import Pou as ModelPou
from ..st import ast
from ..st import types as t
from .context import PouContext
from .diagram_calls import Callee, PinValue, call_ast, check_call, lower_call, resolve_callee, type_call
from .diagram_checks import (
    canonical_label,
    check_chart_labels,
    check_jump_target,
    check_labels,
    check_unique_ids,
    check_unique_networks,
)
from .diagram_operands import At, Operands
from .fbd_order import Analyses, NetworkGraph, Source, analyse, wire_text
from .lower_expr import convert
from .lower_st import fb_output, fb_pins
from .nodes import (
    Assign,
    Binary,
    Block,
    Call,
    Convert,
    Expr,
    If,
    Jump,
    Origin,
    Probe,
    Return,
    Stmt,
    Unary,
    Var,
    diagram_origin,
)
from .power import TRUE, coil, edge, not_
from .types import BOOL

_ROOT = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)")


def lower_fbd_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """The networks of an FBD POU as IR blocks; problems are reported on ``ctx`` with network and element."""
    body: fbd.FbdBody = pou.body  # type: ignore[assignment]
    ctx.places = Places(body)
    check_unique_networks(body.networks, ctx.report, "FBD")
    check_unique_ids(
        ((i, n.id, node.id) for i, n in enumerate(body.networks, 1) for node in n.nodes), ctx.report, "FBD"
    )
    labels = check_labels(body.networks, ctx.report, "FBD")
    ops = Operands(ctx, "FBD")
    analyses = Analyses()
    return [_Network(ctx, ops, labels, network).lower(analyses) for network in body.networks]


def lower_cfc_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """A CFC chart: its elements in their execution order numbers' order (CFC-02, fbd_order), otherwise lowered
    exactly as an FBD network; each label element starts a labelled IR block its jumps go to (a jump skips the
    elements numbered between it and its label; backward, the engine's watchdog bounds the loop)."""
    body: CfcBody = pou.body  # type: ignore[assignment]  # language "cfc": the model made the body a CfcBody
    ctx.places = Places(body)
    chart = body.chart
    check_unique_ids(((1, chart.id, node.id) for node in chart.nodes), ctx.report, "FBD")
    labels = check_chart_labels(
        ((node.id, node.name) for node in chart.nodes if isinstance(node, fbd.FbdLabel)), ctx.report, network=chart.id
    )
    ops = Operands(ctx, "FBD")
    ops.kept_temps = any(isinstance(node, fbd.FbdJump) for node in chart.nodes)
    return _Network(ctx, ops, labels, chart, explicit=True).lower_chart()


def evaluation_order(network: fbd.FbdNetwork, explicit: bool = False) -> list[str]:
    """The node ids of ``network`` in the order they run, for the editor's execution-order badges;
    ``explicit``: a CFC chart (its ``order`` list decides, CFC-02)."""
    return analyse(network, lambda *_args, **_kwargs: None, explicit).order


@dataclass(frozen=True)
class _LabelMark:
    """Where a CFC chart's label stands among the chart's statements: a new IR block starts there."""

    label: str
    origin: Origin


@dataclass
class _Chained:
    """A block with its inputs gathered in its place; ``chained``: its inputs fed by chained blocks (pin -> block
    id), lowered before it; ``statements``: its place in the network's statements, filled when it is lowered."""

    node: fbd.Block
    callee: Callee
    instance: str | None
    inputs: dict[str, PinValue]
    chained: dict[str, str]
    en: PinValue | None
    statements: list[Stmt]


class _Network:
    def __init__(
        self, ctx: PouContext, ops: Operands, labels: dict[str, str], network: fbd.FbdNetwork, explicit: bool = False
    ):
        self.ctx, self.ops, self.labels, self.network = ctx, ops, labels, network
        self.explicit = explicit  # a CFC chart: its order list is the order (CFC-02)
        self.out: list[Stmt | _LabelMark | list[Stmt]] = []  # a block's statements are a list in its place (_Chained)
        self.chained: dict[str, _Chained] = {}  # chained blocks waiting for the block they feed
        #: (producer id, PIN) -> what its consumers read; missing when the producer could not be lowered
        self.values: dict[tuple[str, str], PinValue] = {}
        self.graph: NetworkGraph | None = None
        self.callees: dict[str, tuple[Callee, str | None] | None] = {}
        self.written: set[str] = set()  # root variables the output nodes of this network write
        self.enables: dict[str, Expr] = {}  # block id -> its EN condition (blocks with EN)
        self.origins: dict[str, Origin] = {}
        self.used_pins: dict[str, set[str]] = {}  # producer id -> its output pins that feed something
        self.names = NetworkNames(network)  # its elements as messages name them
        self.consumers: dict[tuple[str, str], list[str]] = {}  # (producer id, PIN) -> the nodes it feeds
        #: (producer id, PIN) -> the feedback variable a function's loop reads (GR-06), written after the producer
        self.loops: dict[tuple[str, str], tuple[Var, t.Type]] = {}

    def lower(self, analyses: Analyses) -> Block:
        """The network as one IR block, labelled when it is a jump target."""
        statements = self._statements(analyses)
        label = canonical_label(self.network.label) if self.network.label else None
        return Block(
            [s for s in statements if not isinstance(s, _LabelMark)],  # an FBD network's labels were reported
            diagram_origin(self.ctx.name, self.network.id),
            label if label is not None and self.labels.get(label) == self.network.id else None,
        )

    def lower_chart(self) -> list[Block]:
        """A CFC chart as IR blocks: the elements before the first label, then one labelled block per label (from
        its order number on); a first block with nothing in it is left out."""
        blocks = [Block([], diagram_origin(self.ctx.name, self.network.id))]
        for statement in self._statements(Analyses()):
            if isinstance(statement, _LabelMark):
                blocks.append(Block([], statement.origin, statement.label))
            else:
                blocks[-1].statements.append(statement)
        return blocks if blocks[0].statements or len(blocks) == 1 else blocks[1:]

    def _statements(self, analyses: Analyses) -> list[Stmt | _LabelMark]:
        """The statements of the nodes in their order (a CFC chart's labels marked where they stand)."""
        self.ops.new_network()
        if self.explicit:
            self.graph = graph = analyse(self.network, self.ctx.report, explicit=True)
        else:
            self.graph = graph = analyses.analyse(self.network, self.ctx.report)
        for consumer, sources in graph.inputs.items():  # once per network, not a scan of all wires per block
            for source in sources.values():
                self.used_pins.setdefault(source.node, set()).add(source.pin)
                self.consumers.setdefault((source.node, source.pin), []).append(consumer)
        self.written = {name for node in graph.nodes.values() if node.type == "output" for name in root_names(node.var)}
        for node in graph.nodes.values():
            if node.type == "block":
                self.callees[node.id] = resolve_callee(self.ops, node.call, node.instance, self.at(node.id))
            elif node.type == "connector":
                self.connector_name(node)
        graph.visit(self)
        for block in list(self.chained.values()):  # chained into a block that was not lowered: typed alone
            if self.chained.pop(block.node.id, None) is not None:
                self._lower_block(block, None)
        return [s for item in self.out for s in (item if isinstance(item, list) else (item,))]

    # ------------------------------------------------------------ helpers
    def at(self, node: str, pin: str | None = None) -> At:
        return At(self.network.id, node, pin)

    def origin(self, node: str) -> Origin:
        """One (immutable) origin per node: every statement and probe of the node carries it."""
        origin = self.origins.get(node)
        if origin is None:
            origin = self.origins[node] = diagram_origin(self.ctx.name, self.network.id, node)
        return origin

    def expr(self, value: PinValue, at: At, what: str, expected: t.Type | None = None) -> tuple[Expr | None, t.Type]:
        """A pin value as an IR expression and its type (operand texts are read and typed here)."""
        if isinstance(value, str):
            return self.ops.read(value, at, what, expected)
        if isinstance(value, tuple):
            return value
        return self.ops.lower(value, at), value.ty  # an AST the call check has typed (a negated operand)

    def source(self, node: str, pin: str) -> PinValue | None:
        """What feeds input ``pin`` of ``node`` (None: not wired, or its producer failed and was reported)."""
        source = self.graph.inputs.get(node, {}).get(pin)
        if source is None:
            return None
        if (node, pin) in self.graph.feedback:
            value = self.feedback(node, pin, source)
            if value is not None and isinstance(self.graph.nodes[node], fbd.Block):  # online: what the block read
                expr, _ = self.expr(value, self.at(node, pin), f"input {pin}")
                if expr is not None:
                    self.out.append(Probe(f"{node}.{pin}", expr, self.origin(node)))
            return value
        return self.values.get((source.node, source.pin))

    def feedback(self, node: str, pin: str, source: Source) -> PinValue | None:
        """GR-06 (IEC 61131-3 ed. 3 "feedback paths"): a wire that closes a loop carries the producer's value of
        the previous scan. An FB output keeps it in the instance; a function's result is kept in the variable it
        writes (an output node), else in a hidden feedback variable (``loops``) that starts with its type's
        default and takes the result after every call."""
        resolved = self.callees.get(source.node)
        if resolved is None:
            return None
        callee, instance = resolved
        flags = _flags(self.graph.nodes[source.node]).get(source.pin)
        if callee.is_fb and source.pin in callee.output_names():
            text = f"{instance}.{source.pin}"
            return f"NOT {text}" if flags is not None and flags.negated else text
        for consumer, sources in self.graph.inputs.items():
            target, fed = self.graph.nodes[consumer], sources.get("IN")
            if (
                isinstance(target, fbd.OutputNode)
                and target.mode == "normal"
                and fed is not None
                and (fed.node, fed.pin) == (source.node, source.pin)
            ):
                return target.var
        loop = self.loops.get((source.node, source.pin))
        if loop is not None:
            return loop
        ty = self._loop_type(source.node, source.pin, callee)
        if ty is None:
            how = "runs against the execution order" if self.explicit else "closes a loop"
            self.ops.report(
                self.at(node, pin),
                "FBD-FEEDBACK",
                f"the wire {wire_text(source.via, self.names)} {how}, and "
                f"nothing outside the loop gives {self.names(source.node, source.pin)} a type: connect a typed "
                "variable to one of its inputs, or its output to an output variable",
            )
            return None
        slot = self.ctx.hidden(f"{source.node}_{source.pin}_FEEDBACK", self.ctx.ir_type(ty))
        self.loops[(source.node, source.pin)] = (slot, ty)
        return slot, ty

    def _loop_type(self, producer: str, pin: str, callee: Callee) -> t.Type | None:
        """The type of a function's result read around a loop before the function runs: its declared result,
        else (a generic function) the type of its first input fed from outside the loop, a literal's default
        type (INT for ``1``) last."""
        if pin == "ENO":
            return t.BOOL
        if callee.pou is not None:
            return callee.pou.return_type
        declared = t.elementary(callee.std_function.result) if callee.std_function is not None else None
        if declared is not None:
            return declared
        found: list[t.Type] = []
        for into, source in self.graph.inputs.get(producer, {}).items():
            if into == "EN" or (producer, into) in self.graph.feedback:
                continue
            value = self.values.get((source.node, source.pin))
            node = self.graph.nodes[source.node]
            if value is None and isinstance(node, fbd.InputNode):
                value = node.expr
            if value is None:
                continue
            with self.ops.muted():
                expr, ty = self.expr(value, self.at(producer, into), f"input {into}")
            if expr is not None and ty is not t.ERROR:
                found.append(ty)
        typed = [ty for ty in found if t.concrete(ty) is ty]
        return typed[0] if typed else t.concrete(found[0]) if found else None

    def connector_name(self, node: fbd.Connector) -> None:
        """GR-02: a connector may not take the name of another named element of the POU."""
        upper = node.name.upper()
        clash = "a label" if upper in self.labels else "a variable" if self.ops.declared(node.name) else None
        if clash:
            self.ops.report(
                self.at(node.id), "FBD-CONNECTOR", f"connector '{node.name}' has the name of {clash} of this POU"
            )

    # ------------------------------------------------------------ nodes
    def input_node(self, node: fbd.InputNode) -> None:
        """An input node is evaluated once (GR-05): consumers read its operand text where they run, unless an
        output node of this network writes a variable it reads - then its value is kept in a temporary first."""
        value, ty = self.ops.read(node.expr, self.at(node.id), "the input")
        if value is None:
            return
        origin = self.origin(node.id)
        if not self.written.isdisjoint(variables(value)):
            slot = self.ops.temp(self.ctx.ir_type(t.concrete(ty)))
            self.out.append(Assign(slot, value, origin))
            self.values[(node.id, "OUT")], value = (slot, ty), slot
        else:
            self.values[(node.id, "OUT")] = node.expr
        self.out.append(Probe(node.id, value, origin))

    def output_node(self, node: fbd.OutputNode) -> None:
        """An output variable: ``normal`` stores any type; the other modes act like the LD coils on BOOL.

        Fed by a block with EN, it is written only when that block runs (EN TRUE), as the output variable
        of an LD box or an ST call with EN: with EN FALSE the variable keeps its value (LAB-01, LD-08).
        ENO itself is always written (FALSE when the block did not run).
        """
        at, origin = self.at(node.id, "IN"), self.origin(node.id)
        value = self.source(node.id, "IN")
        if value is None:
            return
        what = "the output"
        if node.mode == "normal":
            target, target_type = self.ops.target(node.var, at.on(None), what)
            if target is None:
                return
            expr, ty = self.expr(value, at, what, target_type)
            if expr is None or (not isinstance(value, str) and not self.ops.assignable(target_type, ty, at, what)):
                return
            expr = convert(expr, target.type if isinstance(target, Var) else self.ctx.ir_type(target_type))
            store = self.ops.store(target)
        else:
            bool_store = self.ops.bool_target(node.var, at.on(None), what)
            expr = self.bool_value(value, at, what)
            if bool_store is None or expr is None:
                return
            store = bool_store
        writes = coil(node.mode, store, expr, lambda: self.ctx.hidden(f"{node.id}_M", BOOL), origin)
        writes.append(Probe(node.id, expr, origin))
        source = self.graph.inputs[node.id]["IN"]
        enable = self.enables.get(source.node, TRUE) if source.pin != "ENO" else TRUE
        self.out += writes if enable == TRUE else [If([(enable, writes)], [], origin)]

    def control(self, node: fbd.FbdJump | fbd.FbdReturn) -> None:
        """GR-07..10: unwired, a jump or return always acts; wired, when its input is TRUE."""
        origin = self.origin(node.id)
        wired = "IN" in self.graph.inputs.get(node.id, {})
        if self.explicit and isinstance(node, fbd.FbdJump) and not wired:
            self.ops.report(
                self.at(node.id, "IN"),
                "CFC-JUMP-CONDITION",
                f"the jump to '{node.target}' has no condition: wire a BOOL value into its input (TRUE for a jump "
                "every scan)",
            )
            return
        value = self.source(node.id, "IN")
        if (node.id, "IN") in self.graph.broken or (wired and value is None):
            return  # reported where the wire breaks or the value fails
        condition = self.bool_value(value, self.at(node.id, "IN"), f"the {node.type}") if wired else TRUE
        if condition is None:
            return
        self.out.append(Probe(node.id, condition, origin))
        if isinstance(node, fbd.FbdJump):
            holder = "no label element of the chart has" if self.explicit else "no network of this POU has"
            label = check_jump_target(
                node.target,
                self.labels,
                self.ctx.report,
                "FBD",
                network=self.network.id,
                element=node.id,
                holder=holder,
            )
            if label is not None:
                self.out.append(Jump(label, None if condition == TRUE else condition, origin))
        else:
            self.out.append(Return(origin) if condition == TRUE else If([(condition, [Return(origin)])], [], origin))

    def label(self, node: fbd.FbdLabel) -> None:
        """A CFC chart's label: the chart's IR block for its jumps starts here (``lower_chart``). FBD labels
        networks, not elements."""
        if not self.explicit:
            self.ops.report(
                self.at(node.id),
                "FBD-BAD-LABEL",
                f"label '{node.name}' is an element: in FBD give the network the label (label elements are CFC's)",
            )
        elif self.labels.get(canonical_label(node.name)) == node.id:
            self.out.append(_LabelMark(canonical_label(node.name), self.origin(node.id)))

    def bool_value(self, value: PinValue, at: At, what: str) -> Expr | None:
        expr, ty = self.expr(value, at, what)
        if expr is not None and not t.same(ty, t.BOOL):
            self.ops.report(at, "FBD-NOT-BOOL", f"{what} needs a BOOL value, got {ty}")
            return None
        return expr

    # ------------------------------------------------------------ blocks
    def block(self, node: fbd.Block) -> None:
        """A block: its inputs gathered where it stands; a function block chained into another block (its
        result feeds one plain input of it) is lowered when that block is, in its own place (``_Chained``)."""
        resolved = self.callees[node.id]
        if resolved is None:
            return
        callee, instance = resolved
        at = self.at(node.id)
        flags = _flags(node)
        broken = self.graph.broken
        if not self._pins_known(node, callee, flags) or (broken and any(n == node.id for n, _ in broken)):
            return
        inputs: dict[str, PinValue] = {}
        chained: dict[str, str] = {}  # pin -> the chained block feeding it
        for pin in self.graph.inputs.get(node.id, {}):
            source = self.graph.inputs[node.id][pin]
            if source.node in self.chained:
                chained[pin] = source.node
                continue
            value = self.source(node.id, pin)
            if value is None:
                return  # its producer failed or the loop has no initial value: reported there
            flag = flags.get(pin)
            if flag is not None:
                value = self.flagged(value, flag, at.on(pin))
                if value is None:
                    return
            inputs[pin] = value
        en = inputs.pop("EN", None)
        if node.en and en is None:
            self.ops.report(at.on("EN"), "FBD-MISSING-PIN", "input EN is not connected")
            return
        block = _Chained(node, callee, instance, inputs, chained, en, [])
        self.out.append(block.statements)  # its place: the statements come when it is lowered
        if self._chains_into(node, callee):
            self.chained[node.id] = block
            return
        context = self._result_context(node) if not callee.is_fb else None
        contexts = self._chain_types(block, context) if chained else {}
        for member in self._members(block):
            self._lower_block(member, contexts.get(member.node.id))
        self._lower_block(block, context)

    def _chains_into(self, node: fbd.Block, callee: Callee) -> bool:
        """Whether a function block's result is typed where it is used (IEC 61131-3 6.4.2, as the ST export nests
        it): it feeds exactly one plain input (no flags, no loop, not EN) of another block, and nothing else."""
        if callee.is_fb or self.used_pins.get(node.id) != {"OUT"}:
            return False
        consumers = self.consumers.get((node.id, "OUT"), [])
        if len(consumers) != 1 or self.callees.get(consumers[0]) is None:
            return False
        consumer = self.graph.nodes[consumers[0]]
        pin = next(p for p, s in self.graph.inputs[consumer.id].items() if (s.node, s.pin) == (node.id, "OUT"))
        return (
            isinstance(consumer, fbd.Block)
            and pin != "EN"
            and pin not in _flags(consumer)
            and (consumer.id, pin) not in self.graph.feedback
        )

    def _members(self, block: _Chained) -> list[_Chained]:
        """The chained blocks under ``block``, producers first, taken from the waiting ones."""
        found: list[_Chained] = []
        for producer in block.chained.values():
            member = self.chained.pop(producer, None)
            if member is not None:
                found += [*self._members(member), member]
        return found

    def _chain_types(self, block: _Chained, context: t.Type | None) -> dict[str, t.Type]:
        """The type of each block chained into ``block``: the one ST gives the nested call in its place."""
        nested: dict[str, ast.Call] = {}
        with self.ops.muted():
            inputs = self._chained_inputs(block, nested)
        if inputs is None:
            return {}
        type_call(self.ops, block.callee, block.instance, inputs, self.at(block.node.id), block.en, context)
        return {name: call.ty for name, call in nested.items() if isinstance(call.ty, t.Elementary)}

    def _chained_inputs(self, member: _Chained, nested: dict[str, ast.Call]) -> dict[str, PinValue] | None:
        """``member``'s inputs with the blocks chained into it as nested calls (each also into ``nested`` by id);
        None when one cannot be. (A method, not a closure calling itself: that was a reference cycle holding the
        POU's check until a collection; issue 27.)"""
        found = dict(member.inputs)
        for pin, producer in member.chained.items():
            inner = self.chained.get(producer)
            values = self._chained_inputs(inner, nested) if inner is not None else None
            if inner is None or values is None:
                return None
            call = call_ast(self.ops, inner.callee, ast.Name(inner.callee.name), values, {}, self.at(producer))
            if call is None:
                return None
            found[pin] = nested[producer] = call
        return found

    def _lower_block(self, block: _Chained, context: t.Type | None) -> None:
        """Check and lower a block in its place with the type its result is used as (None: its own)."""
        node, callee, instance, en = block.node, block.callee, block.instance, block.en
        at, origin = self.at(node.id), self.origin(node.id)
        inputs = dict(block.inputs)
        for pin, producer in block.chained.items():
            value = self.values.get((producer, "OUT"))
            if value is None:
                return  # the chained block failed: reported there
            inputs[pin] = value
        saved, self.out = self.out, block.statements
        try:
            eno = self.ops.temp() if node.en else None
            outputs = self._method_outputs(node, callee)
            call = check_call(self.ops, callee, instance, inputs, dict(outputs), at, en, eno, context)
            if call is None:
                return
            result = None if callee.is_fb else self._result(node, call.ty)
            statements = lower_call(self.ops, callee, call, result, at, origin)
            if statements is None:
                return
            self.out += statements
            self._outputs(node, callee, instance, call, statements[0], result, eno, _flags(node), en, outputs)
        finally:
            self.out = saved

    def _method_outputs(self, node: fbd.Block, callee: Callee) -> dict[str, tuple[Var, t.Type]]:
        """The VAR_OUTPUTs of an ``inst.M`` block: the call writes each (``q => slot``, as LD's box and ST do) to a
        slot its consumers read and its probe shows (also unwired, as an FB's outputs: a value on every pin, ON-09),
        kept between scans when the block has EN (as its OUT)."""
        found = {}
        for pin in callee.method_outputs():
            ty = callee.output_type(pin)
            ir_type = self.ctx.ir_type(ty)
            found[pin] = (self.ctx.hidden(f"{node.id}_{pin}", ir_type) if node.en else self.ops.temp(ir_type), ty)
        return found

    def _result_context(self, node: fbd.Block) -> t.Type | None:
        """The type of the one variable a function block's result is written to (an output node, as in
        ``y := F(...)``), which its literals and generic type adapt to; None when it feeds anything else."""
        consumers = self.consumers.get((node.id, "OUT"), [])
        target = self.graph.nodes[consumers[0]] if len(consumers) == 1 else None
        if not isinstance(target, fbd.OutputNode) or target.mode != "normal":
            return None
        found = self.ops.clean_read(target.var)
        return found[1] if found is not None else None

    def _result(self, node: fbd.Block, ty: t.Type) -> Var:
        """Where a function block's result goes: a slot kept between scans when the block has EN (with EN
        FALSE it keeps its value), else a temporary (a loop reads it through an output variable)."""
        if node.en:
            return self.ctx.hidden(f"{node.id}_OUT", self.ctx.ir_type(ty))
        return self.ops.temp(self.ctx.ir_type(ty))

    def _pins_known(self, node: fbd.Block, callee: Callee, flags: dict[str, fbd.PinFlags]) -> bool:
        """Wires from the block and pin flags name pins it has; EN/ENO need ``en``; edges are for inputs.
        (Wires into unknown inputs are reported by the call check, with ST's messages.)"""
        outputs = callee.output_names() + callee.method_outputs() + (["ENO"] if node.en else [])
        used = self.used_pins.get(node.id, set())
        into = self.graph.inputs.get(node.id, {})
        if (
            (node.en or ("EN" not in into and "ENO" not in into))
            and used.issubset(outputs)
            and all(pin not in outputs and callee.is_input(pin) for pin in flags)
        ):
            return True  # the common case: every wire from a real output, flags on inputs only (nothing below applies)
        wired = set(self.graph.inputs.get(node.id, {}))
        problems: list[tuple[str, str, str]] = []
        method = callee.method_outputs()
        for pin in sorted(used - set(outputs) - {"ENO"}):
            hint = f": its outputs are {', '.join(['OUT', *method])}" if method else did_you_mean(pin, outputs)
            problems.append((pin, "FBD-UNKNOWN-PIN", f"{callee.name} has no output '{pin}'" + hint))
        for pin in ("EN", "ENO"):
            if not node.en and pin in wired | used | set(flags):
                problems.append((pin, "FBD-UNKNOWN-PIN", f"the block has no {pin}: switch on EN/ENO to use it"))
        for pin, flag in sorted(flags.items()):
            if pin in outputs and flag.edge is not None:
                problems.append(
                    (
                        pin,
                        "FBD-PIN-FLAG",
                        f"output {pin} cannot have an edge flag: edge detection is for inputs",
                    )
                )
            elif pin not in outputs and not callee.is_input(pin) and pin not in ("EN", "ENO"):
                problems.append((pin, "FBD-UNKNOWN-PIN", f"{callee.name} has no pin '{pin}' for the flags"))
        for pin, code, message in problems:
            self.ops.report(self.at(node.id, pin), code, message)
        return not problems

    def flagged(self, value: PinValue, flags: fbd.PinFlags, at: At) -> PinValue | None:
        """An input with its pin flags applied: inversion first, then edge detection (an R_TRIG/F_TRIG in
        front of the pin)."""
        if not flags.negated and flags.edge is None:
            return value
        flag = "negated" if flags.edge is None else f"{flags.edge} edge"
        what = f"the {flag} input {at.pin}"
        expr = self.bool_value(value, at, what)
        if expr is None:
            return None
        if flags.edge is None and isinstance(value, str):  # the call reads NOT <operand>
            node = self.ops.parse(value, at, what)
            return ast.Unary("NOT", node) if node is not None else None
        if flags.negated:
            expr = not_(expr)
        if flags.edge is not None:
            memory = self.ctx.hidden(f"{at.element}_{at.pin}_M", BOOL)
            expr, remember = edge(flags.edge == "rising", expr, memory, self.origin(at.element))
            slot = self.ops.temp()
            self.out += [Assign(slot, expr, self.origin(at.element)), remember]
            return slot, t.BOOL
        slot = self.ops.temp()
        self.out.append(Assign(slot, expr, self.origin(at.element)))
        return slot, t.BOOL

    def _outputs(
        self,
        node: fbd.Block,
        callee: Callee,
        instance: str | None,
        call,
        first: Stmt,
        result: Var | None,
        eno: Var | None,
        flags: dict,
        en: PinValue | None,
        method_outputs: dict[str, tuple[Var, t.Type]],
    ) -> None:
        """Record what each output pin carries (after its negation flag) and probe it. An FB's outputs are
        carried as their operand text (``inst.Q``: each consumer reads it in its own context); the probes read
        them from the instance the FbCall (``first``) called. A method's outputs are the slots its call wrote."""
        at, origin = self.at(node.id), self.origin(node.id)
        pins: dict[str, PinValue] = {}  # what the consumers read
        probed: dict[str, tuple[Expr, t.Type]] = {}  # what the probes read
        if callee.is_fb:
            types = fb_pins(call.fb, self.ctx)
            for pin in callee.output_names():
                pins[pin] = f"{instance}.{pin}"
                probed[pin] = fb_output(first.instance, pin, types[pin][0]), callee.output_type(pin)
        else:
            pins["OUT"] = probed["OUT"] = (result, call.ty)
            for pin, wired in method_outputs.items():
                pins[pin] = probed[pin] = wired
        if eno is not None:
            pins["ENO"] = probed["ENO"] = (eno, t.BOOL)
        probes: list[Stmt] = []
        for pin, value in pins.items():
            flag = flags.get(pin)
            expr, ty = probed[pin]
            if flag is not None and flag.negated:
                if not t.same(ty, t.BOOL):
                    self.ops.report(at.on(pin), "FBD-NOT-BOOL", f"output {pin} is negated, but it is {ty}, not BOOL")
                    continue
                negated = self.ops.temp()
                self.out.append(Assign(negated, not_(expr), origin))
                value, expr = (negated, t.BOOL), negated
            self.values[(node.id, pin)] = value
            probes.append(Probe(f"{node.id}.{pin}", expr, origin))
            loop = self.loops.get((node.id, pin))
            if loop is not None:  # the feedback variable a consumer before it read: this scan's value, for the next
                self.out.append(Assign(loop[0], convert(expr, loop[0].type), origin))
        if en is None:
            self.out += probes
            return
        condition, _ = self.expr(en, at.on("EN"), "input EN")
        self.enables[node.id] = condition
        self.out += [If([(condition, probes)], [], origin)] if condition != TRUE else probes


def root_names(text: str) -> set[str]:
    """The variable an output node's operand writes: the name it starts with (``x``, ``x.f``, ``a[i]``)."""
    match = _ROOT.match(text)
    return {match.group(1).upper()} if match else set()


def variables(expr: Expr):
    """Upper-case names of the variables an IR expression reads."""
    if isinstance(expr, Var):
        yield expr.name
    elif isinstance(expr, Unary):
        yield from variables(expr.operand)
    elif isinstance(expr, Binary):
        yield from variables(expr.left)
        yield from variables(expr.right)
    elif isinstance(expr, Call):
        for arg in (*expr.args, *expr.in_outs):
            yield from variables(arg)
    elif isinstance(expr, Convert):
        yield from variables(expr.operand)


def _flags(node: fbd.FbdNode) -> dict[str, fbd.PinFlags]:
    return {pin.upper(): flag for pin, flag in (getattr(node, "pins", None) or {}).items()}
