"""An FBD network as ST: nodes in the order ir/fbd_order.py fixes, each block the call it stands for.

Follows ir/lower_fbd.py: what a consumer reads from a wire is either an operand
text read where the consumer runs (``Text``: an input node, an FB output
``inst.Q``, the variable holding a function's result under EN) or a value
computed at the producer (a function's result, a negated output, an edge, an
input node whose variable an output node of the same network writes). Pin flags
put ``NOT`` or an R_TRIG/F_TRIG in front of an input; output nodes write like LD
coils, under ``IF`` when fed by a block with EN; a feedback wire reads what the
previous scan left (the FB's output, the variable a function's result goes to, or else a feedback variable
declared for it, ``ADD_OUT_prev``, assigned after the function's call).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ...ir import nodes as ir
from ...ir import types as irt
from ...ir.diagram_checks import canonical_label
from ...ir.fbd_order import analyse
from ...ir.lower_fbd import root_names  # the variable an output node writes, exactly as the lowering sees it
from ...model import fbd
from ...st import ast
from ...st.checker import check_operand
from .elements import PouScope, box_instance, callee_of, function_call, operand, output_pin, owner, text_of
from .network import ChartJump, ChartLabel, Control, NetworkCode, Use, Value


@dataclass(frozen=True)
class Text:
    """An operand read where its consumer runs."""

    expr: Any


PinValue = Text | Value


def fbd_network(scope: PouScope, network: fbd.FbdNetwork, lowered: ir.Pou, explicit: bool = False) -> NetworkCode:
    """``explicit``: a CFC chart - its elements in its execution order (CFC-02), a return where it stands."""
    return _Network(scope, network, lowered, explicit).code


class _Network:
    def __init__(self, scope: PouScope, network: fbd.FbdNetwork, lowered: ir.Pou, explicit: bool = False):
        self.scope, self.network, self.explicit = scope, network, explicit
        self.code = NetworkCode()
        self.graph = graph = analyse(network, lambda *args, **kwargs: None, explicit)
        self.values: dict[tuple[str, str], PinValue] = {}
        self.enables: dict[str, PinValue] = {}
        self.result_types = _result_types(lowered, network.id)
        self.written = {
            name for node in graph.nodes.values() if isinstance(node, fbd.OutputNode) for name in root_names(node.var)
        }
        self.consumed = {(s.node, s.pin) for sources in graph.inputs.values() for s in sources.values()}
        self.loops: dict[tuple[str, str], str] = {}  # (producer, PIN) -> its feedback variable (lower_fbd.loops)
        graph.visit(self)

    # ------------------------------------------------------------ wires
    def read(self, value: PinValue) -> Any:
        return value.expr if isinstance(value, Text) else Use(value)

    def source(self, node: str, pin: str) -> PinValue:
        source = self.graph.inputs[node][pin]
        if (node, pin) in self.graph.feedback:
            return self.feedback(source)
        return self.values[(source.node, source.pin)]

    def feedback(self, source) -> PinValue:
        """GR-06: the previous scan's value - the FB's output pin, the variable the function's result is written
        to, or a feedback variable that ``block`` assigns after the call."""
        producer = self.graph.nodes[source.node]
        callee = callee_of(self.scope.checked, producer.call)
        if callee.is_fb and source.pin in callee.output_names():
            flags = _flags(producer).get(source.pin)
            pin = output_pin(callee, box_instance(callee, producer.instance), source.pin)
            return Text(ast.Unary("NOT", pin) if flags is not None and flags.negated else pin)
        for consumer, sources in self.graph.inputs.items():
            target, fed = self.graph.nodes[consumer], sources.get("IN")
            if (
                isinstance(target, fbd.OutputNode)
                and target.mode == "normal"
                and fed is not None
                and (fed.node, fed.pin) == (source.node, source.pin)
            ):
                return Text(operand(target.var))
        name = self.loops.get((source.node, source.pin))
        if name is None:  # the lowering's hidden feedback variable, declared: it keeps the previous scan's result
            type_text = "BOOL" if source.pin == "ENO" else self.result_type(producer, callee)
            hint = f"{owner(callee, None)}_{source.pin}_prev"
            name = self.loops[(source.node, source.pin)] = self.scope.declarations.declare(hint, type_text, "VAR")
        return Text(ast.Name(name))

    def as_value(self, value: PinValue, element: str, hint: str) -> Value:
        """``value`` as read at this position (the planner moves it to its users when nothing in between
        writes what it reads)."""
        if isinstance(value, Value):
            return value
        return self.code.value(value.expr, element, hint)

    # ------------------------------------------------------------ nodes
    def input_node(self, node: fbd.InputNode) -> None:
        """Read where its consumers run; one whose variable an output of this network writes is read where it
        stands (the lowering's temporary), kept as ``<var>_prev`` only when a write comes before its use."""
        expr = operand(node.expr)
        if self.written & set(_variables(expr)):
            hint = f"{text_of(expr)}_prev"
            self.values[(node.id, "OUT")] = self.code.value(expr, node.id, hint, type=self.type_of(node.expr))
        else:
            self.values[(node.id, "OUT")] = Text(expr)

    def type_of(self, text: str) -> str:
        checked, _ = check_operand(self.scope.checked, self.scope.info.name, text)
        return str(checked.ty)

    def output_node(self, node: fbd.OutputNode) -> None:
        value = self.source(node.id, "IN")
        source = self.graph.inputs[node.id]["IN"]
        enable = self.enables.get(source.node) if source.pin != "ENO" else None
        guard = self.read(enable) if enable is not None else None
        target_type = self.type_of(node.var) if isinstance(value, Value) and node.mode == "normal" else None
        self.scope.coil(self.code, node.mode, operand(node.var), self.read(value), node.id, guard, target_type)

    def label(self, node: fbd.FbdLabel) -> None:
        """A CFC label: the chart's ST is cut here (a step that may write anything: no value moves across it)."""
        self.code.step([ChartLabel(canonical_label(node.name))], node.id, None)

    def control(self, node: fbd.FbdJump | fbd.FbdReturn) -> None:
        if self.explicit and isinstance(node, fbd.FbdJump):  # a CFC jump acts where its number puts it
            condition = self.read(self.source(node.id, "IN"))  # wired: CFC-JUMP-CONDITION refused the others
            self.code.step([ChartJump(canonical_label(node.target), condition)], node.id, None)
            return
        if self.explicit:  # a CFC return acts at its place in the order
            statement = ast.Return()
            if "IN" in self.graph.inputs.get(node.id, {}):
                statement = ast.If([(self.read(self.source(node.id, "IN")), [statement])])
            self.code.step([statement], node.id, None)
            return
        condition = None
        hint = f"jump_{node.target}" if isinstance(node, fbd.FbdJump) else "return_now"
        if "IN" in self.graph.inputs.get(node.id, {}):
            condition = self.code.value(self.read(self.source(node.id, "IN")), node.id, hint)
        label = canonical_label(node.target) if isinstance(node, fbd.FbdJump) else None
        self.code.controls.append(Control(label, condition, node.id))

    def flagged(self, value: PinValue, flags: fbd.PinFlags | None, node: str, pin: str, name: str) -> PinValue:
        """An input with its pin flags: inversion first, then edge detection. ``name`` is the block's (its
        instance or function): an edge of a variable is named after the variable, else after the pin."""
        if flags is None or (not flags.negated and flags.edge is None):
            return value
        expr = self.read(value)
        if flags.negated:
            expr = ast.Unary("NOT", expr)
        if flags.edge is not None:
            watched = text_of(value.expr) if isinstance(value, Text) and not flags.negated else f"{name}_{pin}"
            return self.scope.edge(self.code, flags.edge == "rising", expr, node, watched)
        return Text(expr) if isinstance(value, Text) else self.code.value(expr, node, f"{name}_{pin}")

    def block(self, node: fbd.Block) -> None:
        scope, code = self.scope, self.code
        callee = callee_of(scope.checked, node.call)
        instance = box_instance(callee, node.instance)
        name = owner(callee, instance)
        flags = _flags(node)
        inputs: dict[str, PinValue] = {}
        for pin in self.graph.inputs.get(node.id, {}):
            inputs[pin] = self.flagged(self.source(node.id, pin), flags.get(pin), node.id, pin, name)
        en = inputs.pop("EN", None)
        if en is not None and (node.id, "ENO") in self.consumed:
            en = self.as_value(en, node.id, f"{name}_EN")
        args = {pin: self.read(value) for pin, value in inputs.items()}
        guard = self.read(en) if en is not None else None
        pins: dict[str, PinValue] = {}
        if callee.is_fb:
            scope.call(code, callee, instance, args, {}, guard, node.id)
            pins = {pin: Text(output_pin(callee, instance, pin)) for pin in callee.output_names()}
            if en is not None:
                pins["ENO"] = en
        elif en is None:
            result_type = self.result_type(node, callee)
            call = function_call(callee, args)
            pins["OUT"] = code.value(call, node.id, f"{name}_OUT", type=result_type, effect=callee.pou is not None)
        else:
            target = None
            if (node.id, "OUT") in self.consumed:
                target = ast.Name(scope.declarations.declare(f"{name}_OUT", self.result_type(node, callee), "VAR"))
                pins["OUT"] = Text(target)
            eno = scope.call(
                code,
                callee,
                None,
                args,
                {},
                guard,
                node.id,
                target,
                eno_hint=name if (node.id, "ENO") in self.consumed else None,
            )
            pins["ENO"] = eno if eno is not None else en
        if en is not None:
            self.enables[node.id] = en
        for pin, value in pins.items():
            flag = flags.get(pin)
            if flag is not None and flag.negated:
                value = code.value(ast.Unary("NOT", self.read(value)), node.id, f"{name}_not_{pin}")
            self.values[(node.id, pin)] = value
            loop = self.loops.get((node.id, pin))
            if loop is not None:
                code.step([ast.Assign(ast.Name(loop), self.read(value))], node.id, frozenset({loop.upper()}))

    def result_type(self, node: fbd.Block, callee) -> str:
        """A function block's result type: a user function's declared type, else what the lowering typed."""
        if callee.pou is not None:
            model = self.scope.checked.pou(callee.name)
            return str(model.return_type)
        return _type_text(self.result_types[node.id])


def _flags(node: fbd.FbdNode) -> dict[str, fbd.PinFlags]:
    return {pin.upper(): flag for pin, flag in (getattr(node, "pins", None) or {}).items()}


def _variables(expr: Any):
    """The names ``lower_fbd.variables`` finds in the lowered expression: roots of accesses (not the index
    expressions), through operators and call arguments."""
    if isinstance(expr, ast.Name):
        yield expr.name.upper()
    elif isinstance(expr, (ast.Member, ast.Index)):
        yield from _variables(expr.base)
    elif isinstance(expr, ast.Unary):
        yield from _variables(expr.operand)
    elif isinstance(expr, ast.Binary):
        yield from _variables(expr.left)
        yield from _variables(expr.right)
    elif isinstance(expr, ast.Call):
        for arg in expr.args:
            yield from _variables(arg.value)


def _result_types(lowered: ir.Pou, network: str) -> dict[str, irt.IrType]:
    """Element id -> result type of the function call the lowering made for it, in ``network``."""
    found: dict[str, irt.IrType] = {}

    def visit(statements: list[ir.Stmt]) -> None:
        for s in statements:
            if isinstance(s, ir.FnCall) and s.origin.network == network and s.origin.element is not None:
                found[s.origin.element] = s.call.type
            elif isinstance(s, ir.If):
                for _, body in s.branches:
                    visit(body)

    for block in lowered.blocks:
        if block.origin.network == network:
            visit(block.statements)
    return found


def _type_text(ty: irt.IrType) -> str:
    if isinstance(ty, irt.Elementary):
        return ty.name if ty.length is None else f"{ty.name}[{ty.length}]"
    if isinstance(ty, irt.Subrange):
        return f"{_type_text(ty.base)} ({ty.low}..{ty.high})"
    if isinstance(ty, irt.Array):
        return f"ARRAY [{', '.join(f'{lo}..{hi}' for lo, hi in ty.dims)}] OF {_type_text(ty.element)}"
    return ty.name if hasattr(ty, "name") else ty.fb
