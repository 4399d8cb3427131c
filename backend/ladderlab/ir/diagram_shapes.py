"""Box calls of one shape checked and lowered once per POU, then bound for every alike box.

A large diagram has thousands of boxes that differ only in the variables wired to
them: ``TON`` with instance ``T17``, input ``C17`` and ``PT := T#5s``. The ST checker's
verdict on such a call and the IR the ST lowering builds depend on those variables
only through their types. So ``diagram_calls`` checks and lowers the first box of a
*shape* - the callee, each pin's kind of value and its type, the exact text of every
other operand (literals, expressions) - a second time with placeholder variables in
place of the box's own, keeps that IR as the shape's template, and binds every later
alike box's variables into a copy of it. The rules stay the ST checker's and the ST
lowering's; this module only decides when two calls are alike and substitutes.

A *leaf* (a value the template generalises): a wire or power-flow slot; a declared
variable, not CONSTANT, of an elementary type other than STRING, or an elementary output
of an FB instance (``T17.Q``: the key names the FB type and the pin), optionally under
``NOT`` (a negated FBD input pin); the FB instance, named by a plain name. A call gets
no template when the box writes variables through its pins (``Q => y``: the checker's
verdict on a written variable depends on more than its type), when any other value is
neither a text nor a constant, or when checking and lowering its placeholder version
reported anything.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, NamedTuple

from ..st import ast
from ..st import types as t
from .nodes import Binary, Call, Convert, Expr, FbCall, FnCall, Index, Origin, Stmt, Unary, Var, node_copy, node_fields
from .types import BOOL, Elementary, IrType

if TYPE_CHECKING:
    from .diagram_operands import Operands

PLACEHOLDER = "__#"  # hidden slots are "__" and letters, digits, "_": a placeholder's name is never one's
_COMPOSITE = (Unary, Binary, Call, Convert, Index)  # IR expressions with expressions inside
RESULT = "=>"  # the function result's entry among the pins of a template's placeholders (never a pin name)


class Leaf(NamedTuple):
    """One generalised value of a call: its part of the shape key, the box's own IR value, its ST type."""

    key: tuple
    value: Expr
    ty: t.Type


class Shape(NamedTuple):
    """A call's shape key and the box's own values of its leaves, by pin (``""``: the FB instance)."""

    key: tuple
    leaves: dict[str, Leaf]


class Placeholders(NamedTuple):
    """What the template's call is checked and lowered with: the box's values with placeholders for its leaves."""

    names: dict[str, str]  # pin ("" the instance, RESULT the function result) -> placeholder name
    inputs: dict[str, Any]
    instance: ast.Expr | None
    en: Any
    eno: Var | None
    result: Var


class Template:
    """A shape's call as checked (its type, the FB type it calls) and lowered with placeholders: one ``FnCall``
    or ``FbCall`` (the calls templates cover need no statements around them)."""

    def __init__(self, ty: t.Type, fb: t.FbType | None, statements: list[Stmt], names: dict[str, str]):
        self.ty, self.fb, self._names = ty, fb, names
        placeholders = frozenset(names.values())
        self._statements = [_statement_binder(statement, placeholders) for statement in statements]

    @staticmethod
    def covers(statements: list[Stmt]) -> bool:
        return all(type(statement) in (FnCall, FbCall) for statement in statements)

    def bind(self, leaves: dict[str, Leaf], result: Var | None, origin: Origin) -> list[Stmt]:
        """The template's statements with one box's values, result and origin."""
        bindings: dict[str, Expr] = {self._names[pin]: leaf.value for pin, leaf in leaves.items()}
        if result is not None:
            bindings[self._names[RESULT]] = result
        return [bind(bindings, origin) for bind in self._statements]


class CallShapes:
    """The call templates of one diagram POU by shape key (None: that shape has none). The POU's ``Operands``, which
    own this object, come with each call: kept here they were a reference cycle holding the POU's check until a
    collection (issue 27)."""

    def __init__(self) -> None:
        self.templates: dict[tuple, Template | None] = {}
        self._count = 0

    def shape(
        self,
        ops: Operands,
        callee: str,
        instance: str | None,
        inputs: dict[str, Any],
        outputs: dict[str, Any],
        en: Any,
        eno: Var | None,
        context: t.Type | None = None,
    ) -> Shape | None:
        """The shape of a box call, or None when templates do not cover it (``context``: the type its result is
        written to, which the call's type may adapt to)."""
        if outputs:
            return None
        leaves: dict[str, Leaf] = {}
        parts: list[Any] = [callee, eno is not None, context]
        if instance is not None:
            leaf = self._variable(ops, instance, fb=True)
            if leaf is None:
                return None
            leaves[""] = leaf
            parts.append(leaf.key)
        if eno is not None:
            leaves["ENO"] = Leaf(("eno",), eno, t.BOOL)
        pins = sorted(inputs.items()) if en is None else [("EN", en), *sorted(inputs.items())]
        for pin, value in pins:
            part = self._part(ops, pin, value, leaves)
            if part is None:
                return None
            parts.append((pin, part))
        key = tuple(parts)
        try:
            hash(key)
        except TypeError:  # a type that cannot be a key
            return None
        return Shape(key, leaves)

    def placeholders(self, ops: Operands, shape: Shape, inputs: dict[str, Any], en: Any) -> Placeholders:
        """The call of ``shape`` with fresh placeholder variables for its leaves (``inputs``/``en``: a box's own)."""
        names = {pin: self._name() for pin in (*shape.leaves, RESULT)}
        values = {pin: self._placeholder(ops, names[pin], leaf) for pin, leaf in shape.leaves.items()}
        instance, eno_wire = values.pop("", None), values.pop("ENO", None)
        return Placeholders(
            names,
            {pin: values.get(pin, value) for pin, value in inputs.items()},
            ops.wire_node(*instance) if instance is not None else None,
            values.get("EN", en),
            eno_wire[0] if eno_wire is not None else None,
            Var("local", names[RESULT], BOOL),
        )  # the result is only ever a target: its type is never read

    # ------------------------------------------------------------ leaves
    def _part(self, ops: Operands, pin: str, value: Any, leaves: dict[str, Leaf]) -> tuple | None:
        """The shape key of one input; a leaf's value goes to ``leaves``."""
        if isinstance(value, str):
            leaf = self._variable(ops, value, fb=False)
            if leaf is None:
                return ("text", value)
        elif isinstance(value, tuple):
            expr, ty = value
            if not isinstance(expr, Var):
                return ("const", expr.value, ty)
            leaf = Leaf(("wire", *type_key(ty, expr.type)), expr, ty)
        elif isinstance(value, ast.Unary) and value.op == "NOT" and type(value.operand) is ast.Name:
            inner = self._variable(ops, value.operand.name, fb=False)
            if inner is None:
                return None
            leaf = Leaf(("NOT", *inner.key), inner.value, inner.ty)
        else:
            return None
        leaves[pin] = leaf
        return leaf.key

    def _variable(self, ops: Operands, text: str, fb: bool) -> Leaf | None:
        """A named variable as a leaf, or None: an FB instance when ``fb``, else an elementary variable or an
        elementary output of an FB instance (``t1.Q``: the key names the FB type and the pin)."""
        named = ops.named_variable(text)
        if named is None or named[0].constant:
            return None
        symbol, member = named
        instance = isinstance(symbol.type, t.FbType)
        if fb:
            wanted = member is None and instance
        else:
            wanted = instance if member is not None else type(symbol.type) is t.Elementary
        if not wanted:
            return None
        read = ops.clean_read(text)
        if read is None:
            return None
        value, ty = read
        if fb:
            return Leaf(fb_key(ty), value, ty)
        if type(ty) is not t.Elementary:
            return None
        if member is None:
            return Leaf(("var", *type_key(ty, value.type)), value, ty)
        return Leaf(("pin", *fb_key(symbol.type), member.upper(), *type_key(ty, value.type)), value, ty)

    def _name(self) -> str:
        self._count += 1
        return f"{PLACEHOLDER}{self._count}"

    def _placeholder(self, ops: Operands, name: str, leaf: Leaf) -> Any:
        """A leaf's value in the template's call: a wire (for the checker, a name of the leaf's type), under NOT
        when the leaf is negated (typed as the checker types it, for EN, which standard calls leave untyped)."""
        wire = (Var("local", name, leaf.value.type), leaf.ty)
        if leaf.key[0] != "NOT":
            return wire
        negated = ast.Unary("NOT", ops.wire_node(*wire))
        negated.ty = leaf.ty
        return negated


def fb_key(ty: t.FbType) -> tuple:
    """An FB type as part of a shape key: a standard and a user FB may share a name."""
    return "fb", ty.name.upper(), ty.std is not None


def type_key(st_type: t.Type, ir_type: IrType) -> tuple:
    """A value's ST and IR type as part of a shape key: elementary ones by name (strings hash once; the type
    dataclasses hash field by field, and shape keys are hashed for every box)."""
    if type(st_type) is t.Elementary and type(ir_type) is Elementary:
        return st_type.name, ir_type.name, ir_type.length
    return st_type, ir_type


def binder(node: Any, names: frozenset[str]) -> Callable[[dict[str, Expr]], Any] | None:
    """How to copy template IR ``node`` with its placeholders (``names``) bound; None when it holds none and is
    shared as it is (IR expressions are immutable). Only the nodes on a path to a placeholder are copied."""
    if type(node) is Var:
        if node.name not in names:
            return None
        if not node.path:
            return lambda bindings: bindings[node.name]
        return lambda bindings: _select(bindings[node.name], node)
    if type(node) in (list, tuple):
        items = [binder(item, names) for item in node]
        if not any(items):
            return None
        kind = type(node)
        return lambda bindings: kind(item if bind is None else bind(bindings) for item, bind in zip(node, items))
    if not isinstance(node, _COMPOSITE):
        return None
    kind = type(node)  # (its constructor takes its fields in order: quick_init's, ~2x faster than node_copy)
    parts = [(value, binder(value, names)) for value in (getattr(node, name) for name in kind.__slots__)]
    if not any(bind for _, bind in parts):
        return None
    return lambda bindings: kind(*[value if bind is None else bind(bindings) for value, bind in parts])


def _statement_binder(statement: Stmt, names: frozenset[str]) -> Callable[[dict[str, Expr], Origin], Stmt]:
    """How to copy a (flat) template statement with its placeholders bound, at a box's origin."""
    fields = {
        name: bind
        for name, value in node_fields(statement).items()
        if name != "origin" and (bind := binder(value, names)) is not None
    }
    return lambda bindings, origin: node_copy(
        statement, {"origin": origin, **{name: bind(bindings) for name, bind in fields.items()}}
    )


def _select(value: Expr, placeholder: Var) -> Var:
    """A member of a bound FB instance: the placeholder's selectors below the instance's own path."""
    assert isinstance(value, Var)
    return Var(value.scope, value.name, placeholder.type, (*value.path, *placeholder.path))
