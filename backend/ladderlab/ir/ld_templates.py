"""LD networks of one shape lowered once per POU, later ones filled in with their own variables (issue 27).

A large ladder repeats a few network shapes with other variables: ``--| A7 |--|/ B7 |--( C7 )--``. The IR of
such a network depends on its variables only through their types, classes and which of them are the same, and
on its ids only through the origins and probes it names. So the first network of a *shape* is lowered as usual
and kept as a template; a later one of the same shape gets a copy of the template's statements with its own
variables, origins and probe names. The shape is every field of every element except its id, with each operand
that names a plain variable replaced by the variable's kind (its ST and IR type, its class) and which of the
network's variables it is; any other operand is kept as its text.

What keeps a network plain (lowered as usual): a label, a jump or return, an element id with a ``.`` (probe
names join an id and a pin) or twice in the network, a variable that is CONSTANT, located, an edge input, global,
in-out, of a method's instance or of a type other than an elementary one or an FB (as an instance or under one of
its outputs, ``T1.Q``). A network becomes a template only when lowering it reported nothing, added no slot (a
pooled temporary, an edge memory, a located address) and made IR nodes this module knows how to copy; the
statements are copied, the expressions shared unless they hold one of the network's variables
(tests/ir/test_ld_templates.py compares the IR with the plain lowering's).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..model import ld
from ..st import types as t
from .diagram_shapes import binder, fb_key, type_key
from .nodes import (
    Assign,
    Binary,
    Block,
    Call,
    Const,
    Convert,
    FbCall,
    FnCall,
    If,
    Member,
    Origin,
    Probe,
    Stmt,
    Unary,
    Var,
    diagram_origin,
)

if TYPE_CHECKING:
    from ..st.symbols import Symbol
    from .context import PouContext
    from .diagram_operands import Operands
    from .lower_ld import _Rung

_CLASSES = ("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_TEMP")  # variables var_for reads as a plain local slot
_EXPRESSIONS = (Var, Const, Unary, Binary, Call, Convert)  # the expressions a template may hold
_TYPES = ("type", "arg_types", "source")  # the fields of IR types in the expressions


class _Plain(Exception):
    """The network has no shape: lower it plainly."""


class _Shape:
    """A network's shape key, and its own element ids and variables in the order the key names them."""

    def __init__(self, ctx: PouContext, ops: Operands, network: ld.LdNetwork):
        self.ctx, self.ops = ctx, ops
        self.ids: list[str] = []
        self.variables: dict[str, int] = {}  # upper-case name -> position in ``values``
        self.values: list[Var] = []
        kinds: list[tuple] = []
        self._kinds = kinds
        elements = self.series(network.elements)
        if len(set(self.ids)) != len(self.ids) or any("." in ident for ident in self.ids):
            raise _Plain
        self.key = (tuple(kinds), elements)

    def series(self, elements: list[ld.LdElement]) -> tuple:
        return tuple(self.element(element) for element in elements)

    def element(self, element: Any) -> tuple:
        self.ids.append(element.id)
        kind = element.type  # (the tag, not isinstance: the pydantic classes check through ABCMeta)
        if kind == "contact" or kind == "coil":
            return kind, element.mode, self.operand(element.var)
        if kind == "compare":
            return kind, element.op, self.operand(element.left), self.operand(element.right)
        if kind == "parallel":
            return kind, tuple(self.series(branch) for branch in element.branches)
        if kind == "box":
            inputs = tuple(
                (pin, self.series(value) if isinstance(value, list) else self.operand(value))
                for pin, value in element.inputs.items()
            )
            outputs = tuple((pin, self.operand(text)) for pin, text in element.outputs.items())
            instance = self.operand(element.instance, fb=True) if element.instance is not None else None
            return kind, element.call, instance, inputs, outputs, element.en
        raise _Plain  # a jump or return

    def operand(self, text: str, fb: bool = False) -> tuple:
        """An operand's part of the key: which variable of the network and its member, or else its text."""
        named = self.ops.named_variable(text)
        if named is None:
            if fb:
                raise _Plain
            return ("text", text)
        symbol, member = named
        instance = isinstance(symbol.type, t.FbType)
        if (member is not None or fb) != instance or (fb and member is not None):
            raise _Plain  # (a member of an FB instance only; an instance only where one is wanted)
        return "var", self.variable(symbol), member

    def variable(self, symbol: Symbol) -> int:
        """The position of a variable among the network's; its kind goes into the key at its first use."""
        name = symbol.name.upper()
        found = self.variables.get(name)
        if found is not None:
            return found
        ctx = self.ctx
        if (
            symbol.constant
            or symbol.address is not None
            or symbol.edge is not None
            or symbol.implicit is not None
            or symbol.pou is None
            or symbol.var_class not in _CLASSES
            or name in ctx.edges
            or (ctx.info is not None and ctx.info.method is not None)
        ):
            raise _Plain
        var = ctx.var_for(symbol)
        if var.scope != "local" or var.path or var.name != name:
            raise _Plain
        if type(symbol.type) is t.Elementary:
            kind = type_key(symbol.type, var.type)
        elif isinstance(symbol.type, t.FbType):
            kind = fb_key(symbol.type)
        else:
            raise _Plain
        self._kinds.append((kind, symbol.var_class))
        self.variables[name] = len(self.values)
        self.values.append(var)
        return self.variables[name]


class _Fill:
    """What a template's copy is bound to: the network's variables by the template's names, its origins by
    element position (the last: the network's own), its element ids."""

    __slots__ = ("ids", "names", "origins")

    def __init__(self, names: dict[str, Var], origins: list[Origin], ids: list[str]):
        self.names, self.origins, self.ids = names, origins, ids


class _Template:
    """A network's statements as copiers taking a ``_Fill``; raises ``_Plain`` for IR it cannot copy."""

    def __init__(self, statements: list[Stmt], shape: _Shape, origins: dict[int, int]):
        self.names = [var.name for var in shape.values]
        self._ids = shape.ids
        self._origins = origins  # id() of a template origin -> its element's position
        self._known = frozenset(self.names)
        self._statements = [self._statement(statement) for statement in statements]

    def fill(self, fill: _Fill) -> list[Stmt]:
        return [copy(fill) for copy in self._statements]

    def _statement(self, statement: Stmt) -> Callable[[_Fill], Stmt]:
        kind = type(statement)
        position = self._origins.get(id(statement.origin))
        if kind not in (Assign, If, FbCall, FnCall, Probe) or position is None:
            raise _Plain
        parts: list[tuple[Any, Callable[[_Fill], Any] | None]] = []  # (the fields in the constructor's order)
        for name in kind.__slots__:
            value = getattr(statement, name)
            if name == "origin":
                copier = None
            elif kind is Probe and name == "element":
                copier = self._probe_name(value)
            elif kind is If and name in ("branches", "orelse"):
                copier = self._nested(value)
            else:
                copier = self._value(value)
            parts.append((value, copier))
        at = kind.__slots__.index("origin")

        def copy(fill: _Fill) -> Stmt:
            values = [value if copier is None else copier(fill) for value, copier in parts]
            values[at] = fill.origins[position]
            return kind(*values)

        return copy

    def _nested(self, value: list) -> Callable[[_Fill], list]:
        """An If's branches (condition, statements) or its else statements."""
        if all(type(item) is tuple for item in value):
            branches = [
                (condition, self._value(condition), [self._statement(s) for s in body]) for condition, body in value
            ]
            return lambda fill: [
                (condition if bind is None else bind(fill), [copy(fill) for copy in body])
                for condition, bind, body in branches
            ]
        body = [self._statement(statement) for statement in value]
        return lambda fill: [copy(fill) for copy in body]

    def _probe_name(self, name: str) -> Callable[[_Fill], str]:
        """A probe's name: an element's id, or a box's id and a pin (``t1.Q``)."""
        head, dot, pin = name.partition(".")
        if head not in self._ids:
            raise _Plain
        position = self._ids.index(head)
        return lambda fill: fill.ids[position] + dot + pin

    def _value(self, value: Any) -> Callable[[_Fill], Any] | None:
        """A field's copier binding the network's variables (None: shared as it is, IR expressions are immutable)."""
        self._check(value)
        bind = binder(value, self._known)
        return None if bind is None else lambda fill: bind(fill.names)

    def _check(self, value: Any) -> None:
        """Every expression in ``value`` one ``binder`` copies, every variable of the network in it a member path."""
        if type(value) in (list, tuple):
            for item in value:
                self._check(item)
        elif value is None or type(value) in (str, bool, int):
            return
        elif type(value) not in _EXPRESSIONS:
            raise _Plain
        elif type(value) is Var:
            if value.name in self._known and (value.scope != "local" or any(type(s) is not Member for s in value.path)):
                raise _Plain
        elif type(value) is not Const:
            for name in value.__slots__:
                if name not in _TYPES:
                    self._check(getattr(value, name))


class LdTemplates:
    """The templates of one LD POU's network shapes (None: a shape whose IR cannot be copied); lowers each network
    through them."""

    def __init__(self, rung: _Rung):
        self.rung, self.ctx = rung, rung.ctx
        self.templates: dict[tuple, _Template | None] = {}

    def lower(self, network: ld.LdNetwork) -> Block:
        try:
            shape = _Shape(self.ctx, self.rung.ops, network) if network.label is None else None
        except _Plain:
            shape = None
        template = self.templates.get(shape.key, False) if shape is not None else None
        if template:
            return self._filled(template, network, shape)  # type: ignore[arg-type]
        ctx = self.ctx
        before = (len(ctx.diagnostics), len(ctx.slots), len(ctx.image))
        block = self.rung.lower(network)
        if template is False and (len(ctx.diagnostics), len(ctx.slots), len(ctx.image)) == before:
            self.templates[shape.key] = self._template(block, shape)  # type: ignore[union-attr]
        return block

    def _template(self, block: Block, shape: _Shape) -> _Template | None:
        """The template of a network just lowered, or None when its IR holds what this module cannot copy."""
        origins = {id(block.origin): len(shape.ids)}
        for position, ident in enumerate(shape.ids):
            origin = self.rung.origins.get(ident)
            if origin is not None:
                origins[id(origin)] = position
        try:
            return _Template(block.statements, shape, origins)
        except _Plain:
            return None

    def _filled(self, template: _Template, network: ld.LdNetwork, shape: _Shape) -> Block:
        pou, name = self.ctx.name, network.id
        origins = [diagram_origin(pou, name, ident) for ident in shape.ids]
        origins.append(diagram_origin(pou, name))
        fill = _Fill(dict(zip(template.names, shape.values)), origins, shape.ids)
        return Block(template.fill(fill), origins[-1], None)
