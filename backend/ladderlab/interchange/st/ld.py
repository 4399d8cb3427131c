"""An LD network as ST: the rung's power flow as expressions, coils as assignments, boxes as formal calls.

Follows ir/lower_ld.py element by element (left to right, parallel branches top
to bottom, every branch, jumps and returns after the network). The power at a
point is kept as a conjunction - a base value and the contact terms after it -
so a rung reads like ``Motor := (Start OR Motor) AND NOT Stop;``: a parallel
whose branches only add contacts to the same power becomes one OR term
(``p AND a OR p AND b`` = ``p AND (a OR b)``, no element is evaluated twice).
Each contact term is a value placed where the contact is evaluated, so the
planner (st_network) keeps it there whenever a write in between could change it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ...ir.diagram_checks import canonical_label
from ...model import ld
from ...st import ast
from .elements import PouScope, box_instance, callee_of, function_call, operand, output_pin, owner, text_of
from .network import TRUE, Control, NetworkCode, Use, Value, conjunction, disjunction

_COMPARE = {"GT": ">", "GE": ">=", "EQ": "=", "LE": "<=", "LT": "<", "NE": "<>"}


@dataclass(eq=False)
class Power:
    """``base AND term1 AND term2 ...`` (no base: the left rail). ``value`` makes it one value, once."""

    base: Value | None = None
    terms: tuple[Value, ...] = ()
    _value: Value | None = None

    def value(self, code: NetworkCode, element: str, hint: str) -> Value | None:
        """The power as one value (None: the left rail, TRUE), created at the first consumer."""
        parts = ([self.base] if self.base is not None else []) + list(self.terms)
        if len(parts) <= 1:
            return parts[0] if parts else None
        if self._value is None:
            self._value = code.value(conjunction([Use(p) for p in parts]), element, hint)
        return self._value

    def expr(self, code: NetworkCode, element: str, hint: str) -> Any:
        value = self.value(code, element, hint)
        return Use(value) if value is not None else TRUE


def ld_network(scope: PouScope, network: ld.LdNetwork, number: int) -> NetworkCode:
    """Network ``network``, the ``number``-th of its POU (1-based: what the editor shows)."""
    return _Rung(scope, network, number).code


class _Rung:
    def __init__(self, scope: PouScope, network: ld.LdNetwork, number: int):
        self.scope, self.network = scope, network
        self.code = NetworkCode()
        self.hint = f"rung{number}"  # the power of this rung, where several elements need it
        self.series(network.elements, Power())

    def expr(self, power: Power, element: str) -> Any:
        return power.expr(self.code, element, self.hint)

    def series(self, elements: list[ld.LdElement], power: Power) -> Power | None:
        """The power at the right end of a series list; None when it ends in a jump or return."""
        for element in elements:
            if isinstance(element, (ld.Jump, ld.Return)):
                label = canonical_label(element.target) if isinstance(element, ld.Jump) else None
                self.code.controls.append(Control(label, power.value(self.code, element.id, self.hint), element.id))
                return None  # the lowering accepts a jump or return only as the last element
            power = self.element(element, power)
        return power

    def element(self, element: ld.LdElement, power: Power) -> Power:
        if isinstance(element, ld.Contact):
            return Power(power.base, power.terms + (self.contact(element),))
        if isinstance(element, ld.Compare):
            condition = ast.Binary(_COMPARE[element.op], operand(element.left), operand(element.right))
            hint = f"{element.left}_{element.op}_{element.right}"
            return Power(power.base, power.terms + (self.code.value(condition, element.id, hint),))
        if isinstance(element, ld.Coil):
            target = operand(element.var)
            self.scope.coil(self.code, element.mode, target, self.expr(power, element.id), element.id, None, "BOOL")
            return power
        if isinstance(element, ld.Parallel):
            return self.parallel(element, power)
        return self.box(element, power)

    def contact(self, contact: ld.Contact) -> Value:
        """The contact's term: its variable as read here (kept as ``<var>_prev`` when a coil before its use
        writes it), negated for nc, or the edge of it."""
        variable = operand(contact.var)
        if contact.mode in ("p", "n"):
            return self.scope.edge(self.code, contact.mode == "p", variable, contact.id, text_of(variable))
        read = self.code.value(variable, contact.id, f"{text_of(variable)}_prev")
        if contact.mode == "no":
            return read
        return self.code.value(ast.Unary("NOT", Use(read)), contact.id, f"not_{text_of(variable)}")

    def parallel(self, element: ld.Parallel, power: Power) -> Power:
        """OR of the branches that reach the right side; factored when they only add terms to ``power``."""
        reaching = [out for branch in element.branches if (out := self.series(branch, power)) is not None]
        if not reaching:
            return Power(self.code.value(ast.BoolLit(False), element.id, self.hint))
        if all(out.base is power.base and out.terms[: len(power.terms)] == power.terms for out in reaching):
            extras = [out.terms[len(power.terms) :] for out in reaching]
            if any(not extra for extra in extras):  # power OR (power AND x) = power
                return power
            branches = disjunction([conjunction([Use(term) for term in extra]) for extra in extras])
            return Power(power.base, power.terms + (self.code.value(branches, element.id, self.hint),))
        branches = disjunction([self.expr(out, element.id) for out in reaching])
        return Power(self.code.value(branches, element.id, self.hint))

    def box(self, box: ld.Box, power: Power) -> Power:
        """A box as the call the lowering checks: power into EN or the first free BOOL input, out of ENO or the
        first BOOL output (GR-27); series lists feeding inputs are evaluated first, in pin order."""
        scope, code = self.scope, self.code
        callee = callee_of(scope.checked, box.call)
        inputs: dict[str, Any] = {}
        for pin in sorted(box.inputs, key=lambda p: callee.rank(p.upper())):
            value = box.inputs[pin]
            inputs[pin.upper()] = (
                self.expr(self.series(value, Power()), box.id) if isinstance(value, list) else operand(value)
            )
        outputs = {pin.upper(): operand(text) for pin, text in box.outputs.items()}
        target = outputs.pop("OUT", None) if not callee.is_fb else None
        instance = box_instance(callee, box.instance)
        enable = power.value(code, box.id, self.hint) if box.en else None
        if box.en:
            en = Use(enable) if enable is not None else TRUE
        else:
            en = None
            free = next(pin for pin in callee.bool_inputs() if pin not in inputs)
            inputs[free] = self.expr(power, box.id)
        name = owner(callee, instance)
        if not callee.is_fb and target is None and not box.en and callee.pou is None:
            return Power(code.value(function_call(callee, inputs), box.id, f"{name}_OUT"))
        if not callee.is_fb and target is None and not box.en:  # a user function: run where the box is
            return Power(code.value(function_call(callee, inputs), box.id, f"{name}_OUT", effect=True))
        eno = scope.call(code, callee, instance, inputs, outputs, en, box.id, target, eno_hint=name)
        if box.en:
            return Power(eno) if eno is not None else Power(enable)
        if callee.is_fb:
            pin = callee.bool_outputs()[0]
            return Power(code.value(output_pin(callee, instance, pin), box.id, f"{name}_{pin}"))
        return Power(code.value(target, box.id, text_of(target)))
