"""LD body -> IR: one labelled block per network, power flow computed once per element (docs/diagrams.md).

Evaluation order (GR-28, LD-10, GR-05): networks top to bottom unless a jump
changes it; inside a network every element exactly once, left to right,
parallel branches top to bottom, every branch (no short-circuit, so edge
contacts see every scan). Each element's right-side power goes into a hidden
BOOL that every consumer reads (docs/ir.md invariant 5), so coils fed by one rung
all see one value. Jumps and returns act after the whole network is evaluated
(GR-05 c). Every element records its power in a ``Probe`` named by its id.
"""

from __future__ import annotations

from ..model import ld
from ..model.places import Places
from ..model.project import Pou as ModelPou
from ..st import ast
from ..st import types as t
from .context import PouContext
from .diagram_calls import Callee, check_call, lower_call, resolve_callee
from .diagram_checks import canonical_label, check_jump_target, check_labels, check_unique_ids, check_unique_networks
from .diagram_operands import At, Operands
from .ld_templates import LdTemplates
from .lower_expr import convert
from .lower_st import fb_output, fb_pins
from .nodes import Assign, Block, Expr, If, Jump, Origin, Probe, Return, Stmt, Var, diagram_origin
from .power import FALSE, TRUE, and_, coil, edge, not_, or_
from .types import BOOL


def lower_ld_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """The networks of an LD POU as IR blocks; problems are reported on ``ctx`` with network and element."""
    body: ld.LdBody = pou.body  # type: ignore[assignment]
    ctx.places = Places(body)
    check_unique_networks(body.networks, ctx.report, "LD")
    ids = [e.id for n in body.networks for e in ld.walk(n.elements)]
    if len(set(ids)) < len(ids):  # a repeated id, reported with its networks (no tuple each when none: issue 27)
        check_unique_ids(
            ((i, n.id, e.id) for i, n in enumerate(body.networks, 1) for e in ld.walk(n.elements)), ctx.report, "LD"
        )
    labels = check_labels(body.networks, ctx.report, "LD")
    templates = LdTemplates(_Rung(ctx, Operands(ctx, "LD"), labels))  # networks of one shape lowered once
    return [templates.lower(network) for network in body.networks]


class _Rung:
    """Lowers one network at a time; power-flow temporaries are reused from network to network."""

    def __init__(self, ctx: PouContext, ops: Operands, labels: dict[str, str]):
        self.ctx, self.ops, self.labels = ctx, ops, labels
        self.network = ""
        self.out: list[Stmt] = []
        self.control: list[Stmt] = []
        self.origins: dict[str, Origin] = {}

    def lower(self, network: ld.LdNetwork) -> Block:
        self.network, self.out, self.control, self.origins = network.id, [], [], {}
        self.ops.new_network()
        self.series(network.elements, TRUE, open_end=True)
        label = canonical_label(network.label) if network.label else None
        return Block(
            self.out + self.control,
            diagram_origin(self.ctx.name, network.id),
            label if label is not None and self.labels.get(label) == network.id else None,
        )

    # ------------------------------------------------------------ helpers
    def origin(self, element: str) -> Origin:
        """One (immutable) origin per element: every statement and probe of the element carries it."""
        origin = self.origins.get(element)
        if origin is None:
            origin = self.origins[element] = diagram_origin(self.ctx.name, self.network, element)
        return origin

    def at(self, element: str, pin: str | None = None) -> At:
        return At(self.network, element, pin)

    def power(self, element: str, value: Expr, *after: Stmt) -> Var:
        """Store an element's right-side power once, run ``after`` (edge memories), and probe it."""
        origin = self.origin(element)
        slot = self.ops.temp()
        self.out += [Assign(slot, value, origin), *after, Probe(element, slot, origin)]
        return slot

    def memory(self, element: str) -> Var:
        """Per-instance edge memory of an element (docs/ir.md invariant 7)."""
        return self.ctx.hidden(f"{element}_M", BOOL)

    # ------------------------------------------------------------ series lists
    def series(self, elements: list[ld.LdElement], power: Expr, open_end: bool) -> Expr | None:
        """Evaluate a series list from ``power``; its right-side power, None when it ends in a jump/return.

        ``open_end``: the list's right end is the rung's right end, where jumps and returns may stand.
        """
        for index, element in enumerate(elements):
            last = index == len(elements) - 1
            if element.type == "jump" or element.type == "return":
                self.control_element(element, power, last and open_end)
                if last:
                    return None
                continue
            power = self.element(element, power, open_end and last)
        return power

    def element(self, element: ld.LdElement, power: Expr, open_end: bool) -> Expr:
        kind = element.type  # (the tag, not isinstance: the pydantic classes check through ABCMeta)
        if kind == "contact":
            return self.contact(element, power)
        if kind == "compare":
            at = self.at(element.id)
            condition = self.ops.compare(element.op, element.left, element.right, at)
            return self.power(element.id, and_(power, condition if condition is not None else FALSE))
        if kind == "coil":
            return self.coil(element, power)
        if kind == "parallel":
            return self.parallel(element, power, open_end)
        return self.box(element, power)

    def contact(self, contact: ld.Contact, power: Expr) -> Var:
        """GR-15..18: no / nc / p / n contacts; an edge contact's memory follows its variable every scan."""
        value = self.ops.read_bool(contact.var, self.at(contact.id), "the contact")
        value = value if value is not None else FALSE
        if contact.mode == "no":
            return self.power(contact.id, and_(power, value))
        if contact.mode == "nc":
            return self.power(contact.id, and_(power, not_(value)))
        detected, remember = edge(contact.mode == "p", value, self.memory(contact.id), self.origin(contact.id))
        return self.power(contact.id, and_(power, detected), remember)

    def coil(self, element: ld.Coil, power: Expr) -> Expr:
        """GR-20..25: the coil writes a function of its left power and passes that power on unchanged."""
        origin = self.origin(element.id)
        target = self.ops.bool_target(element.var, self.at(element.id), "the coil")
        if target is not None:
            self.out += coil(element.mode, target, power, lambda: self.memory(element.id), origin)
        self.out.append(Probe(element.id, power, origin))
        return power

    def parallel(self, element: ld.Parallel, power: Expr, open_end: bool) -> Var:
        """GR-14: every branch from the same left power, top to bottom; the right side ORs the branches
        that reach it (a branch ending in a jump or return does not)."""
        if len(element.branches) < 2:
            self.ops.report(
                self.at(element.id),
                "LD-PARALLEL",
                f"the parallel branch has {len(element.branches)} branch(es); it needs at least two",
            )
        reaching = [out for branch in element.branches if (out := self.series(branch, power, open_end)) is not None]
        return self.power(element.id, or_(reaching))

    def control_element(self, element: ld.Jump | ld.Return, power: Expr, at_end: bool) -> None:
        """GR-07..10: a jump or return acts when its power is ON, after the whole network (GR-05 c)."""
        origin = self.origin(element.id)
        self.out.append(Probe(element.id, power, origin))
        kind = "jump" if isinstance(element, ld.Jump) else "return"
        if not at_end:
            self.ops.report(
                self.at(element.id),
                "LD-CONTROL-POSITION",
                f"a {kind} must be the last element of a branch that ends the rung",
            )
            return
        if isinstance(element, ld.Jump):
            label = check_jump_target(
                element.target, self.labels, self.ctx.report, "LD", network=self.network, element=element.id
            )
            if label is not None:
                self.control.append(Jump(label, None if power == TRUE else power, origin))
        elif power == TRUE:
            self.control.append(Return(origin))
        else:
            self.control.append(If([(power, [Return(origin)])], [], origin))

    # ------------------------------------------------------------ boxes
    def box(self, box: ld.Box, power: Expr) -> Expr:
        """A function or FB box: power enters EN (``en``) or the first free BOOL input, and leaves from ENO or
        the first BOOL output (GR-27). Series lists feeding inputs are evaluated first, in pin order."""
        at = self.at(box.id)
        resolved = resolve_callee(self.ops, box.call, box.instance, at)
        callee = resolved[0] if resolved is not None else None
        pins = sorted(box.inputs, key=lambda p: callee.rank(p.upper()) if callee else (0, 0))
        inputs = {}
        for pin in pins:
            value = box.inputs[pin]
            if isinstance(value, list):
                fed = self.series(value, TRUE, open_end=False)
                if fed is None:  # the list ends in a jump or return: reported
                    resolved = None
                inputs[pin.upper()] = (fed, t.BOOL)
            else:
                inputs[pin.upper()] = value
        if resolved is None:
            return self.power(box.id, FALSE)
        right = self._box(box, callee, resolved[1], inputs, power)
        return right if right is not None else self.power(box.id, FALSE)

    def _box(self, box: ld.Box, callee: Callee, instance: str | None, inputs: dict, power: Expr) -> Expr | None:
        """The call, its output copies and probes; the box's right-side power (None: reported)."""
        at, origin = self.at(box.id), self.origin(box.id)
        outputs = {pin.upper(): text for pin, text in box.outputs.items()}
        if not self._pins_allowed(callee, inputs, outputs, at):
            return None
        en, eno = ((power, t.BOOL), self.ops.temp()) if box.en else (None, None)
        if not box.en and not self._feed_power(callee, inputs, power, at):
            return None
        result_text = outputs.pop("OUT", None) if not callee.is_fb else None
        written = self.ops.clean_read(result_text) if result_text is not None else None  # as in y := F(...)
        unwired = self._unwired_method_outputs(callee, outputs)
        wired = dict(outputs)
        call = check_call(
            self.ops, callee, instance, inputs, {**outputs, **unwired}, at, en, eno, written[1] if written else None
        )
        if call is None:
            return None
        result, copies = (None, []) if callee.is_fb else self._result(callee, call.ty, result_text, at, en, origin)
        statements = (
            lower_call(self.ops, callee, call, result, at, origin) if result is not None or callee.is_fb else None
        )
        if statements is None:
            return None
        self.out += statements + copies
        if callee.is_fb:  # the outputs, read from the instance the FbCall (first statement) called
            types = fb_pins(call.fb, self.ctx)
            pins = {pin: fb_output(statements[0].instance, pin, types[pin][0]) for pin in callee.output_names()}
        else:  # a method's outputs too: the variables at their pins after the call, else the slots it wrote
            pins = {"OUT": result, **self._read_back(wired), **{pin: slot for pin, (slot, _) in unwired.items()}}
        right = eno if eno is not None else self._bool_output(callee, call.ty, pins, at)
        if right is None:
            return None
        probes: list[Stmt] = [Probe(box.id, eno, origin)] if eno is not None else []
        if eno is None:
            right = self.power(box.id, right)
        probes += [Probe(f"{box.id}.{pin}", value, origin) for pin, value in pins.items() if value is not None]
        self.out += probes if en is None or power == TRUE else [If([(power, probes)], [], origin)]
        return right

    def _unwired_method_outputs(self, callee: Callee, outputs: dict[str, str]) -> dict[str, tuple[Var, t.Type]]:
        """A method box's VAR_OUTPUTs with no variable at their pin: the call writes each to a temporary its probe
        reads, so the pin shows a value online as an FB's unwired outputs do (ON-09)."""
        found = {}
        for pin in callee.method_outputs():
            if pin not in outputs:
                ty = callee.output_type(pin)
                found[pin] = (self.ops.temp(self.ctx.ir_type(ty)), ty)
        return found

    def _read_back(self, outputs: dict[str, str]) -> dict[str, Expr | None]:
        """The variables a method box wrote at its output pins, read after the call for their probes."""
        return {
            pin: (read[0] if (read := self.ops.clean_read(text)) is not None else None) for pin, text in outputs.items()
        }

    def _pins_allowed(self, callee: Callee, inputs: dict, outputs: dict, at: At) -> bool:
        """EN and ENO are the power flow, not operands; a function's only output is OUT."""
        problems = [
            (pin, f"{pin} is the box's power flow: switch on EN/ENO instead of connecting it")
            for pin in ("EN", "ENO")
            if pin in inputs or pin in outputs
        ]
        if not callee.is_fb:
            known = ("OUT", *callee.method_outputs())
            what = f"its outputs are {', '.join(known)}" if len(known) > 1 else "its only output is OUT"
            kind = "method" if callee.pou is not None and callee.pou.method is not None else "function"
            problems += [
                (pin, f"{callee.name} is a {kind}: {what}") for pin in outputs if pin not in (*known, "EN", "ENO")
            ]
        for pin, message in problems:
            self.ops.report(at.on(pin), "LD-UNKNOWN-PIN", message)
        return not problems

    def _feed_power(self, callee: Callee, inputs: dict, power: Expr, at: At) -> bool:
        """Without ``en`` the power enters the first BOOL input that has no operand (GR-27 b)."""
        free = [pin for pin in callee.bool_inputs() if pin not in inputs]
        if not free:
            self.ops.report(
                at, "LD-BOX-POWER", f"{callee.name} has no free BOOL input for the power flow: switch on EN/ENO"
            )
            return False
        inputs[free[0]] = (power, t.BOOL)
        return True

    def _result(
        self, callee: Callee, ty: t.Type, text: str | None, at: At, en: tuple[Expr, t.Type] | None, origin: Origin
    ) -> tuple[Var | None, list[Stmt]]:
        """Where a function box's result (of type ``ty``) goes, and the statements that copy it on: its OUT
        variable; a bit or part of one (``w.%B1``): a temporary, copied into the part after the call (with EN,
        only when the box ran: the variable keeps its value with EN FALSE), as ST's ``w.%B1 := F(...)`` stores
        it; else a slot kept between scans when the box has EN (with EN FALSE it keeps its value), else a
        temporary. (None: the OUT variable was reported.)"""
        if text is None:
            ir_type = self.ctx.ir_type(ty)
            return (self.ctx.hidden(f"{at.element}_OUT", ir_type) if en else self.ops.temp(ir_type)), []
        target = self.ops.value_target(text, at.on("OUT"), f"output OUT of {callee.name}", ty)
        if not isinstance(target, ast.Member):
            return target, []
        slot = self.ops.temp(self.ctx.ir_type(ty))
        copy = self.ops.store(target)(convert(slot, self.ctx.ir_type(target.ty)), origin)
        return slot, [copy] if en is None else [If([(en[0], [copy])], [], origin)]

    def _bool_output(self, callee: Callee, ty: t.Type, pins: dict[str, Expr | None], at: At) -> Expr | None:
        if callee.is_fb:
            names = callee.bool_outputs()
            if names and pins.get(names[0]) is not None:
                return pins[names[0]]
        elif t.same(ty, t.BOOL):
            return pins["OUT"]
        if not callee.is_fb or not callee.bool_outputs():
            self.ops.report(
                at, "LD-BOX-POWER", f"{callee.name} has no BOOL output to pass the power flow on: switch on EN/ENO"
            )
        return None
