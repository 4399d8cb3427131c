"""LD networks of one shape lowered once per POU, later ones filled in with their own variables (issue 27).

A large ladder repeats a few network shapes with other variables: ``--| A7 |--|/ B7 |--( C7 )--``. The IR of
such a network depends on its variables only through their types, classes and which of them are the same, and
on its ids only through the origins and probes it names. So the first network of a *shape* is lowered as usual
and kept as a template; a later one of the same shape gets a copy of the template's statements with its own
variables, origins and probe names. The shape is every field of every element except its id, with each operand
that names a plain variable replaced by the variable's kind (its ST and IR type, its class) and which of the
network's variables it is; any other operand is kept as its text (a template whose texts name one of its own
variables is none: the names in its texts' IR would be bound too).

What keeps a network plain (lowered as usual): a label, a jump or return, an element id with a ``.`` (probe
names join an id and a pin) or twice in the network, a variable that is CONSTANT, located, an edge input, global,
in-out, of a method's instance or of a type other than an elementary one or an FB (as an instance or under one of
its outputs, ``T1.Q``). A network becomes a template only when lowering it reported nothing, added no slot (a
pooled temporary, an edge memory, a located address) and made IR nodes this module knows how to copy; the
statements are made anew by one function compiled per template, the expressions shared unless they hold one of
the network's variables (tests/ir/test_ld_templates.py compares the IR with the plain lowering's). A filled
network's block says so (``Block.filled``: its template's, which finds its variables in it), unless one of its
variables is named like another variable of the template's statements: the code generator then knows its shape
without walking it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..model import ld
from ..st import types as t
from .diagram_shapes import fb_key, type_key
from .nodes import (
    Assign,
    Binary,
    Block,
    Call,
    Const,
    Convert,
    FbCall,
    Filled,
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
    from .lower_ld import _Rung

_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")  # a name in an operand text (or a piece of a literal: never less)
_CLASSES = ("VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_TEMP")  # variables var_for reads as a plain local slot
_STATEMENTS = (Assign, If, FbCall, FnCall, Probe)  # the statements a template may hold
_COMPOSITE = (Unary, Binary, Call, Convert)  # the expressions with expressions inside a template may hold
_TYPES = ("type", "arg_types", "source")  # the fields of IR types in the expressions


class _Plain(Exception):
    """The network has no shape (or its IR none this module copies): it is lowered plainly."""


class _Shape:
    """A network's shape key (``key``), its element ids in walk order and its variables in the order the key
    names them."""

    def __init__(
        self, ctx: PouContext, network: ld.LdNetwork, symbols: dict[str, Symbol], operands: Callable[[str], Any]
    ):
        """``symbols``: the POU's variables by upper-case name, looked up directly (none in a method's POU)."""
        self.ctx, self._symbols, self._named = ctx, symbols, operands
        self.ids: list[str] = []
        self.positions: dict[Symbol, int] = {}  # the network's variables -> their position in ``values``
        self.values: list[Var] = []
        self._kinds: list[tuple[Any, ...]] = []
        self.texts: list[str] = []  # the operands kept as their text
        elements = self.series(network.elements)
        if len(set(self.ids)) != len(self.ids) or "." in "".join(self.ids):  # (no element id with a dot)
            raise _Plain
        self.key = (tuple(self._kinds), elements)

    def series(self, elements: list[ld.LdElement]) -> tuple[Any, ...]:
        return tuple([self.element(element) for element in elements])

    def element(self, element: Any) -> tuple[Any, ...]:
        self.ids.append(element.id)
        kind = element.type  # (the tag, not isinstance: the pydantic classes check through ABCMeta)
        if kind == "contact" or kind == "coil":
            return kind, element.mode, self.operand(element.var)
        if kind == "compare":
            return kind, element.op, self.operand(element.left), self.operand(element.right)
        if kind == "parallel":
            return kind, tuple([self.series(branch) for branch in element.branches])
        if kind == "box":
            inputs = tuple(
                [
                    (pin, self.series(value) if type(value) is list else self.operand(value))
                    for pin, value in element.inputs.items()
                ]
            )
            outputs = tuple([(pin, self.operand(text)) for pin, text in element.outputs.items()])
            instance = self.operand(element.instance, True) if element.instance is not None else None
            return kind, element.call, instance, inputs, outputs, element.en
        raise _Plain  # a jump or return

    def operand(self, text: str, fb: bool = False) -> tuple[Any, ...]:
        """An operand's part of the key: which variable of the network and its member, or else its text. (A
        POU variable's plain name is looked up directly: it is what ``Operands.named_variable`` finds first.) A
        variable new to the network takes the next position and puts its kind into the key."""
        symbol = self._symbols.get(text.upper())
        member = None
        if symbol is None:
            named = self._named(text)
            if named is None:
                if fb:
                    raise _Plain
                self.texts.append(text)
                return ("text", text)
            symbol, member = named
        if (member is not None or fb) != isinstance(symbol.type, t.FbType) or (fb and member is not None):
            raise _Plain  # (a member of an FB instance only; an instance only where one is wanted)
        position = self.positions.get(symbol)
        if position is not None:
            return "var", position, member
        if (
            symbol.constant
            or symbol.address is not None
            or symbol.edge is not None
            or symbol.implicit is not None
            or symbol.pou is None
            or symbol.var_class not in _CLASSES
        ):
            raise _Plain
        ctx = self.ctx
        var = ctx.var_for(symbol)
        if var.scope != "local" or var.path or var.name != symbol.name.upper() or var.name in ctx.edges:
            raise _Plain
        if type(symbol.type) is t.Elementary:
            kind = type_key(symbol.type, var.type)
        elif isinstance(symbol.type, t.FbType):
            kind = fb_key(symbol.type)
        else:
            raise _Plain
        self._kinds.append((kind, symbol.var_class))
        position = self.positions[symbol] = len(self.values)
        self.values.append(var)
        return "var", position, member


class _Template:
    """A network's statements as the source of one function of the network's variables (``v``), its elements'
    origins (``o``, by walk position; the last: the network's own) and its element ids (``ids``), compiled once.
    Shared values (types, constants, expressions without a variable of the network) are its ``c``."""

    def __init__(self, statements: list[Stmt], shape: _Shape, origins: dict[int, int]):
        self._names = {var.name: i for i, var in enumerate(shape.values)}
        if any(word.upper() in self._names for text in shape.texts for word in _WORD.findall(text)):
            raise _Plain  # a text naming a variable of the network: its IR would be bound too (only the text is kept)
        self._ids, self._origins = shape.ids, origins  # origins: id() of a template origin -> its position
        self._shared: list[Any] = []
        self.others: set[str] = set()  # the names of the statements' variables that are not the network's
        source = f"lambda v, o, ids: [{', '.join(self._statement(s) for s in statements)}]"
        self.fill: Callable[[list[Var], list[Origin], list[str]], list[Stmt]] = eval(  # our own text
            source, {"c": self._shared, "_select": _select}
        )
        places = "".join(f"{place}, " for place in _places(statements, self._names))
        self.filled = Filled(eval(f"lambda s: ({places})", {}))  # (our own text)

    def _constant(self, value: Any) -> str:
        self._shared.append(value)
        return f"c[{len(self._shared) - 1}]"

    def _statement(self, statement: Any) -> str:
        kind = type(statement)
        position = self._origins.get(id(statement.origin))
        if kind not in _STATEMENTS or position is None:
            raise _Plain
        fields = []
        for name in kind.__slots__:  # (a dataclass's constructor takes its fields in this order)
            value = getattr(statement, name)
            if name == "origin":
                fields.append(f"o[{position}]")
            elif kind is Probe and name == "element":
                fields.append(self._probe_name(value))
            elif kind is If and name == "branches":
                fields.append(f"[{', '.join(f'({self._value(c)}, {self._statements(b)})' for c, b in value)}]")
            elif kind is If and name == "orelse":
                fields.append(self._statements(value))
            else:
                fields.append(self._value(value))
        return f"{self._constant(kind)}({', '.join(fields)})"

    def _statements(self, statements: list[Stmt]) -> str:
        return f"[{', '.join(self._statement(s) for s in statements)}]"

    def _probe_name(self, name: str) -> str:
        """A probe's name: an element's id, or a box's id and a pin (``t1.Q``)."""
        head, dot, pin = name.partition(".")
        if head not in self._ids:
            raise _Plain
        return f"ids[{self._ids.index(head)}]" + (f" + {self._constant(dot + pin)}" if dot else "")

    def _value(self, value: Any) -> str:
        """A field's value: shared when it holds no variable of the network (IR expressions are immutable)."""
        return self._constant(value) if not self._holds(value) else self._made(value)

    def _made(self, value: Any) -> str:
        kind = type(value)
        if kind is Var:
            position = self._names[value.name]
            return f"v[{position}]" if not value.path else f"_select(v[{position}], {self._constant(value)})"
        if kind is list or kind is tuple:
            items = ", ".join(self._value(item) for item in value)
            return f"[{items}]" if kind is list else f"({items},)"
        fields = ", ".join(
            self._constant(getattr(value, name)) if name in _TYPES else self._value(getattr(value, name))
            for name in kind.__slots__
        )
        return f"{self._constant(kind)}({fields})"

    def _holds(self, value: Any) -> bool:
        """Does ``value`` hold a variable of the network? Raises ``_Plain`` for what this module does not copy."""
        kind = type(value)
        if kind is Var:
            if value.name not in self._names:
                self.others.add(value.name)
                return False
            if value.scope != "local" or any(type(s) is not Member for s in value.path):
                raise _Plain
            return True
        if kind is list or kind is tuple:
            return any([self._holds(item) for item in value])
        if value is None or kind is str or kind is bool or kind is int or kind is Const:
            return False
        if kind not in _COMPOSITE:
            raise _Plain
        return any([self._holds(getattr(value, name)) for name in kind.__slots__ if name not in _TYPES])


def _places(statements: list[Stmt], names: dict[str, int]) -> list[str]:
    """Where each of the network's variables (``names``) that ``statements`` hold is found in them
    (``s[2].value.left``), in the order of ``names``: as itself where it appears so, else with its first member."""
    whole: dict[str, str] = {}
    member: dict[str, str] = {}
    _visit(statements, "s", names, whole, member)
    return [whole.get(name) or member[name] for name in names if name in whole or name in member]


def _visit(value: Any, place: str, names: dict[str, int], whole: dict[str, str], member: dict[str, str]) -> None:
    """``_places`` below ``value`` (found at ``place``). (Not a closure: a recursive one would be a reference cycle,
    tests/ir/test_build_memory.py.)"""
    kind = type(value)
    if kind is Var:
        if value.name in names:
            (member if value.path else whole).setdefault(value.name, place)
    elif kind is list or kind is tuple:
        for i, item in enumerate(value):
            _visit(item, f"{place}[{i}]", names, whole, member)
    elif kind in _STATEMENTS or kind in _COMPOSITE:
        for name in kind.__slots__:
            if name not in _TYPES and name != "origin":
                _visit(getattr(value, name), f"{place}.{name}", names, whole, member)


def _select(value: Var, member: Var) -> Var:
    """A member of the network's FB instance: the template's selectors below the instance's own path."""
    return Var(value.scope, value.name, member.type, (*value.path, *member.path))


class LdTemplates:
    """The templates of one LD POU's network shapes (None: a shape whose IR cannot be copied); lowers each network
    through them."""

    def __init__(self, rung: _Rung):
        self.rung, self.ctx = rung, rung.ctx
        self.templates: dict[tuple[Any, ...], _Template | None] = {}
        info = self.ctx.info
        self._symbols = info.symbols if info is not None and info.method is None else {}

    def lower(self, network: ld.LdNetwork) -> Block:
        try:
            shape = (
                _Shape(self.ctx, network, self._symbols, self.rung.ops.named_variable)
                if network.label is None
                else None
            )
        except _Plain:
            shape = None
        template = self.templates.get(shape.key, False) if shape is not None else None
        if shape is not None and isinstance(template, _Template):
            return self._filled(template, network, shape)
        ctx = self.ctx
        before = (len(ctx.diagnostics), len(ctx.slots), len(ctx.image))
        block = self.rung.lower(network)
        if shape is not None and template is False and (len(ctx.diagnostics), len(ctx.slots), len(ctx.image)) == before:
            self.templates[shape.key] = self._template(block, shape)
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
        except (_Plain, SyntaxError, RecursionError):  # (the latter two: a source nested beyond CPython's parser)
            return None

    def _filled(self, template: _Template, network: ld.LdNetwork, shape: _Shape) -> Block:
        pou, name, ids = self.ctx.name, network.id, shape.ids
        origins = [diagram_origin(pou, name, ident) for ident in ids]
        origins.append(diagram_origin(pou, name))
        values, others = shape.values, template.others
        filled = template.filled if not any([var.name in others for var in values]) else None
        return Block(template.fill(values, origins, ids), origins[-1], None, filled)
