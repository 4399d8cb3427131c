"""LD boxes and FBD blocks: what they call, and the call checked and lowered like the ST call it stands for.

A box is the ST call ``inst(EN := power, IN := x, PT := T#5s, Q => y, ENO => eno)``
or ``result := ADD(EN := power, IN1 := a, IN2 := b, ENO => eno)``, where power
flow and wires are hidden slots (``Operands.wire_node``). The ST checker types it
(generic inputs, widening, in-outs, unknown pins, read-only outputs ...) and the
ST lowering builds the ``FnCall``/``FbCall``, so a box and its ST text behave the
same by construction. What the checker cannot see from one call - a function
box with an input left unconnected, an FB without an instance or with an
instance of another type - is checked here first.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import NamedTuple

from ..iec import stdlib
from ..iec.spelling import did_you_mean
from ..st import ast
from ..st import types as t
from ..st.body import BodyChecker
from ..st.symbols import PouInfo
from .diagram_operands import At, Operands
from .diagram_shapes import Leaf, Shape, Template
from .lower_expr import lower_en_eno, std_call, user_call
from .lower_st import gated, lower_fb_call  # a box is lowered exactly like the call of an ST statement
from .lower_types import LoweringError
from .nodes import Expr, FnCall, If, Origin, Stmt, Var

Wired = tuple[Expr, t.Type]  # a value from a wire or the power flow (hidden slot or constant) and its type
PinValue = str | Wired | ast.Expr  # operand text, a value from a wire or the power flow, or a ready AST


@dataclass(frozen=True)
class Callee:
    """The function or function block a box calls: a standard one or a user POU."""

    name: str
    std_function: stdlib.StdFunction | None = None
    std_fb: stdlib.StdFunctionBlock | None = None
    pou: PouInfo | None = None

    @functools.cached_property
    def is_fb(self) -> bool:  # asked several times for every box
        return self.std_fb is not None or (self.pou is not None and self.pou.kind in ("FUNCTION_BLOCK", "PROGRAM"))

    @property
    def is_program(self) -> bool:
        """A PROGRAM box (seed 003's FBD program call): called like an FB whose one instance is the program."""
        return self.pou is not None and self.pou.kind == "PROGRAM"

    def input_names(self) -> list[str]:
        """The declared inputs (VAR_IN_OUT included) in formal order; an extensible function's minimum."""
        return list(self._inputs)

    @functools.cached_property
    def _inputs(self) -> tuple[str, ...]:  # asked for every pin of every box
        if self.std_function is not None:
            return tuple(p.name for p in self.std_function.inputs)
        if self.std_fb is not None:
            return tuple(p.name for p in self.std_fb.inputs)
        return tuple(s.name.upper() for s in self.pou.parameters("VAR_INPUT", "VAR_IN_OUT"))

    def method_outputs(self) -> list[str]:
        """A method's VAR_OUTPUTs (``inst.M`` boxes: written to the variables at their pins, as ``q => x``)."""
        if self.pou is None or self.pou.method is None:
            return []
        return [s.name.upper() for s in self.pou.parameters("VAR_OUTPUT")]

    def output_names(self) -> list[str]:
        if self.std_fb is not None:
            return [p.name for p in self.std_fb.outputs]
        if self.pou is not None and self.is_fb:
            return [s.name.upper() for s in self.pou.parameters("VAR_OUTPUT")]
        return ["OUT"]

    def output_type(self, pin: str) -> t.Type:
        """The type of FB output ``pin`` (one of ``output_names``), as the checker types ``inst.PIN``."""
        if self.std_fb is not None:
            return t.elementary(next(p.type for p in self.std_fb.outputs if p.name == pin)) or t.ERROR
        return self.pou.symbols[pin].type

    def rank(self, pin: str) -> tuple[int, int]:
        """Position of an input pin as the box draws it (top to bottom): declared order, then IN3, IN4 ..."""
        names = self._inputs
        if pin in names:
            return 0, names.index(pin)
        digits = pin[len(pin.rstrip("0123456789")) :]
        return 1, int(digits) if digits else 0

    def is_input(self, pin: str) -> bool:
        if self.std_function is not None:
            return self.std_function.pin(pin) is not None
        return pin in self._inputs

    def bool_inputs(self) -> list[str]:
        """Inputs that can carry power flow: BOOL pins, and generic pins whose family admits BOOL (AND, OR ...)."""
        if self.std_function is not None:
            return [
                p.name
                for p in self.std_function.inputs
                if p.type == "BOOL" or (p.generic and t.in_family(t.BOOL, p.type))
            ]
        if self.std_fb is not None:
            return [p.name for p in self.std_fb.inputs if p.type == "BOOL"]
        return [s.name.upper() for s in self.pou.parameters("VAR_INPUT") if t.same(s.type, t.BOOL)]

    def bool_outputs(self) -> list[str]:
        """FB outputs that can carry power flow on (for a function, its result type decides)."""
        if self.std_fb is not None:
            return [p.name for p in self.std_fb.outputs if p.type == "BOOL"]
        return [s.name.upper() for s in self.pou.parameters("VAR_OUTPUT") if t.same(s.type, t.BOOL)]

    def in_outs(self) -> list[str]:
        if self.pou is None:
            return []
        return [s.name.upper() for s in self.pou.parameters("VAR_IN_OUT")]

    def missing(self, connected: set[str]) -> list[str]:
        """Inputs that must be connected but are not: every input of a standard function (extension pins
        without gaps: IN3 needs IN2 ...), and every VAR_IN_OUT. Answered once per set of connected pins
        (the boxes of one type are mostly wired alike)."""
        key = frozenset(connected)
        missing = self._memo.get(key)
        if missing is None:
            missing = self._memo[key] = self._missing(connected)
        return list(missing)

    @functools.cached_property
    def _memo(self) -> dict[frozenset[str], list[str]]:
        return {}

    def _missing(self, connected: set[str]) -> list[str]:
        if self.std_function is None:
            return [pin for pin in self.in_outs() if pin not in connected]
        needed = self.input_names()
        extra = [self.rank(pin)[1] for pin in connected if self.rank(pin)[0] == 1 and self.is_input(pin)]
        if extra and self.std_function.extensible:
            last = self.std_function.inputs[-1].name
            stem = last.rstrip("0123456789")
            needed += [f"{stem}{n}" for n in range(int(last[len(stem) :]) + 1, max(extra))]
        return [pin for pin in needed if pin not in connected]


def resolve_callee(ops: Operands, call: str, instance: str | None, at: At) -> tuple[Callee, str | None] | None:
    """The callee of a box and its instance operand (FBs), or None (reported): unknown name, FB without
    an instance or with an instance of another type, function with an instance."""
    name = call.strip()
    callee = ops.callees.get(name.upper())
    if callee is None:
        callee = _callee(ops, name, at)
        if callee is None:
            return None
        ops.callees[name.upper()] = callee
    if not callee.is_fb:
        if instance:
            ops.report(
                at, f"{ops.lang}-INSTANCE", f"{callee.name} is a function: it has no instance (remove '{instance}')"
            )
            return None
        return callee, None
    if callee.is_program:  # its one instance is the program itself (docs/st.md, "Program calls")
        caller = ops.ctx.info.kind if ops.ctx.info is not None else "PROGRAM"
        if caller != "PROGRAM":
            ops.report(
                at,
                f"{ops.lang}-NOT-CALLABLE",
                f"a {caller.lower().replace('_', ' ')} cannot call the program {callee.name}: only programs call "
                "programs",
            )
            return None
        if instance and instance.strip() and instance.strip().upper() != callee.name.upper():
            ops.report(
                at,
                f"{ops.lang}-INSTANCE",
                f"{callee.name} is a program: its one instance is the program itself (remove '{instance.strip()}')",
            )
            return None
        return callee, callee.name
    if not instance or not instance.strip():
        ops.report(
            at,
            f"{ops.lang}-NO-INSTANCE",
            f"the function block {callee.name} needs an instance: declare "
            f"one (e.g. inst : {callee.name};) and name it in the box",
        )
        return None
    value, ty = ops.read(instance, at, f"the instance of {callee.name}")
    if value is None:
        return None
    if not isinstance(ty, t.FbType) or ty.name.upper() != callee.name.upper():
        ops.report(at, f"{ops.lang}-INSTANCE-TYPE", f"'{instance.strip()}' is a {ty}, not a {callee.name} instance")
        return None
    return callee, instance.strip()


def _callee(ops: Operands, name: str, at: At) -> Callee | None:
    """What ``name`` calls, or None (reported): a program or an unknown name."""
    if "." in name:  # ``inst.Method`` (CODESYS): a method of an instance or an interface variable
        method = _method(ops, name, at)
        if method is not None:
            return Callee(name, pou=method)
    pou = ops.ctx.checked.pou(name)
    if pou is not None and pou.plant:
        ops.report(
            at,
            f"{ops.lang}-PLANT",
            f"{pou.name} is a plant: it models the process and runs in the plant task before every scan; "
            "control code cannot call it",
        )
        return None
    if pou is not None:
        return Callee(pou.name, pou=pou)
    if stdlib.function(name) is not None:
        return Callee(name.upper(), std_function=stdlib.function(name))
    if stdlib.function_block(name) is not None:
        return Callee(name.upper(), std_fb=stdlib.function_block(name))
    known = [*ops.ctx.checked.pous, *stdlib.FUNCTIONS, *stdlib.FUNCTION_BLOCKS]
    ops.report(
        at, f"{ops.lang}-UNKNOWN-CALL", f"unknown function or function block '{name}'" + did_you_mean(name, known)
    )
    return None


def _method(ops: Operands, name: str, at: At) -> PouInfo | None:
    """The METHOD a box ``inst.M`` calls (st/methods.py), or None when ``name`` names none."""
    with ops.muted():
        node = ops.parse(name, at, "the method")
    if not isinstance(node, ast.Member):
        return None
    base = BodyChecker(ops.ctx.checked, ops.ctx.info, lambda *args, **kwargs: None).expr(node.base)
    owner = base.pou if isinstance(base, t.FbType) else base.info if isinstance(base, t.InterfaceType) else None
    return owner.find_method(node.name) if owner is not None else None


def _target(ops: Operands, callee: Callee, instance: str | None, at: At) -> ast.Expr | None:
    """What the box's ST call calls: its instance (FBs), ``inst.M`` (a method), else the function's name."""
    if instance is not None:
        return ops.parse(instance, at, "the instance")
    if callee.pou is not None and callee.pou.method is not None:
        return ops.parse(callee.name, at, "the method")
    return ast.Name(callee.name)


class CheckedCall(NamedTuple):
    """A box call the checker accepted: its type (a function's result), the FB type it calls, and what
    ``lower_call`` lowers - the checked ST call, or the template of its shape and the box's own values."""

    ty: t.Type
    fb: t.FbType | None
    node: ast.Call | None
    template: Template | None = None
    leaves: dict[str, Leaf] | None = None


def check_call(
    ops: Operands,
    callee: Callee,
    instance: str | None,
    inputs: dict[str, PinValue],
    outputs: dict[str, str | Wired],
    at: At,
    en: PinValue | None = None,
    eno: Var | None = None,
    context: t.Type | None = None,
) -> CheckedCall | None:
    """The box as a checked ST call (None when reported). ``inputs``/``outputs`` map upper-case pin names
    to what feeds them / the variable they write (FB or method outputs: an operand, or an FBD block's slot);
    ``context`` is the type of the variable a function's result is written to, which its literals and generic
    type adapt to as in ``y := F(...)`` (st/context_typing.py). The first box of a shape that checks without a
    word also gives that shape its template (diagram_shapes); later boxes of the shape use it."""
    shape = ops.shapes.shape(ops, callee.name, instance, inputs, outputs, en, eno, context)
    if shape is not None:
        template = ops.shapes.templates.get(shape.key)
        if template is not None:
            return CheckedCall(template.ty, template.fb, None, template, shape.leaves)
    before = len(ops.ctx.diagnostics)
    target = _target(ops, callee, instance, at)
    node = _check(ops, callee, target, inputs, outputs, at, en, eno, context)
    if node is None:
        return None
    if shape is not None and shape.key not in ops.shapes.templates and len(ops.ctx.diagnostics) == before:
        _learn(ops, callee, shape, inputs, at, en, context)
    return CheckedCall(node.ty, _fb(callee, node), node)


def _fb(callee: Callee, node: ast.Call) -> t.FbType | None:
    if callee.is_program:  # the pins of the program's one instance, as an FB type's (lower_st.fb_pins)
        return t.FbType(callee.pou.name, pou=callee.pou)
    return node.callee.ty if callee.is_fb else None


def _learn(
    ops: Operands,
    callee: Callee,
    shape: Shape,
    inputs: dict[str, PinValue],
    at: At,
    en: PinValue | None,
    context: t.Type | None,
) -> None:
    """Check and lower the shape's call with placeholders; it becomes the template unless anything was reported."""
    holders = ops.shapes.placeholders(ops, shape, inputs, en)
    template = None
    with ops.muted() as reported:
        node = _check(
            ops,
            callee,
            holders.instance or ast.Name(callee.name),
            holders.inputs,
            {},
            at,
            holders.en,
            holders.eno,
            context,
        )
        statements = _lower(ops, callee, node, holders.result, at, Origin(ops.ctx.name)) if node else None
        if statements is not None and Template.covers(statements):
            template = Template(node.ty, _fb(callee, node), statements, holders.names)
    ops.shapes.templates[shape.key] = None if reported else template


def _check(
    ops: Operands,
    callee: Callee,
    target: ast.Expr | None,
    inputs: dict[str, PinValue],
    outputs: dict[str, str | Wired],
    at: At,
    en: PinValue | None,
    eno: Var | None,
    context: t.Type | None = None,
) -> ast.Call | None:
    """Check the box as the ST call of ``target`` (the instance or the function's name; None: reported)."""
    node = call_ast(ops, callee, target, inputs, outputs, at, en, eno)
    if node is None:
        return None
    before = len(ops.ctx.diagnostics)
    pins = node.args[:-1] if eno is not None else node.args  # the pins diagnostics are located on (not ENO)
    checker = ops.checker(at, {arg.name: arg for arg in pins if arg.name is not None})
    if callee.is_fb:
        checker.call(node, statement=True)
    else:
        checker.expr(node, context)  # types the call node (its result type, adapted to where it goes)
    if ops.errors_since(before) or node.ty is t.ERROR:
        return None
    return node


def type_call(
    ops: Operands,
    callee: Callee,
    instance: str | None,
    inputs: dict[str, PinValue],
    at: At,
    en: PinValue | None,
    context: t.Type | None,
) -> None:
    """Type the box's call as ST types it, reporting nothing: the calls nested in ``inputs`` (``call_ast``: the
    blocks chained into it) get the types their place in it gives them (st/context_typing.py)."""
    with ops.muted():
        target = _target(ops, callee, instance, at)
        _check(ops, callee, target, inputs, {}, at, en, None, context)


def call_ast(
    ops: Operands,
    callee: Callee,
    target: ast.Expr | None,
    inputs: dict[str, PinValue],
    outputs: dict[str, str | Wired],
    at: At,
    en: PinValue | None = None,
    eno: Var | None = None,
) -> ast.Call | None:
    """The box as an unchecked ST call of ``target`` (the instance or the function's name; None: reported, or
    ``target`` is None: an instance that does not parse)."""
    missing = callee.missing(set(inputs))
    for pin in missing:
        ops.report(at.on(pin), f"{ops.lang}-MISSING-PIN", f"input {pin} of {callee.name} is not connected")
    wired_in_outs = [pin for pin in callee.in_outs() if pin in inputs and not isinstance(inputs[pin], str)]
    for pin in wired_in_outs:  # VAR-51: an in-out is passed by reference, so it needs a variable
        ops.report(
            at.on(pin), f"{ops.lang}-IN-OUT", f"in-out {pin} of {callee.name} needs a variable, not a computed value"
        )
    args: list[ast.Arg] = []
    failed = bool(missing or wired_in_outs)
    if en is not None:
        node = _node(ops, en, at, "EN", callee)
        failed |= node is None
        if node is not None:
            args.append(ast.Arg("EN", node))
    for pin in sorted(inputs, key=callee.rank):
        node = _node(ops, inputs[pin], at, pin, callee)
        failed |= node is None
        if node is not None:
            args.append(ast.Arg(pin, node))
    for pin, written in outputs.items():
        if isinstance(written, str):
            node = ops.parse(written, at.on(pin), f"output {pin} of {callee.name}")
        else:
            node = ops.wire_node(*written)
        failed |= node is None
        if node is not None:
            args.append(ast.Arg(pin, node, output=True))
    if eno is not None:
        args.append(ast.Arg("ENO", ops.wire_node(eno, t.BOOL), output=True))
    if failed or target is None:
        return None
    return ast.Call(target, args)


def _node(ops: Operands, value: PinValue, at: At, pin: str, callee: Callee) -> ast.Expr | None:
    if isinstance(value, str):
        return ops.parse(value, at.on(pin), f"input {pin} of {callee.name}")
    return ops.wire_node(*value) if isinstance(value, tuple) else value


def lower_call(
    ops: Operands, callee: Callee, call: CheckedCall, result: Var | None, at: At, origin: Origin
) -> list[Stmt] | None:
    """The statements of a checked box call: one ``FnCall`` writing ``result``, or the ``FbCall`` (and the
    output copies an ST call would have); None when the engine cannot run it (reported)."""
    if call.template is not None:
        return call.template.bind(call.leaves, result, origin)
    return _lower(ops, callee, call.node, result, at, origin)


def _lower(
    ops: Operands, callee: Callee, node: ast.Call, result: Var | None, at: At, origin: Origin
) -> list[Stmt] | None:
    try:
        if callee.is_fb:
            return [_located(s, origin) for s in lower_fb_call(node, ops.ctx, origin)]
        copies: list[Stmt] = []  # a method's outputs that need a conversion
        call = std_call(node, ops.ctx) if callee.std_function is not None else user_call(node, ops.ctx, copies)
        en, eno, after = lower_en_eno(node, ops.ctx)
        en, eno, copies = gated(en, eno, copies, origin, ops.ctx)
    except LoweringError as error:
        if error.message is not None:
            ops.report(at, error.code, error.message)
        return None
    return [FnCall(call, result, origin, en, eno), *(_located(s, origin) for s in (*copies, *after))]


def _located(statement: Stmt, origin: Origin) -> Stmt:
    """Give the statements of a box (output copies placed by the ST lowering) the box's own origin."""
    statement.origin = origin
    if isinstance(statement, If):
        for _, body in statement.branches:
            for inner in body:
                _located(inner, origin)
    return statement
