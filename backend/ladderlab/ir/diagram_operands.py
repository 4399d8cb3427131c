"""Operand texts of LD/FBD elements, checked by the ST checker and lowered by lower_expr.

The one place where diagram text meets the ST front end. A contact's ``T1.Q``,
a coil's ``Motor``, a pin's ``T#5s`` are ST operands: they are parsed and typed
by the ST checker (so names, types and messages are exactly ST's) and lowered
by ``lower_expr``. The checker's diagnostics are re-located from the operand
text to the POU, network, element and pin they belong to.

Values that come from a wire or the power flow rather than from text are
hidden slots; ``wire_node`` gives them an AST name the checker resolves
(``_WireChecker``), so a box call with wired inputs is checked like any ST call.
"""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import re
from collections.abc import Callable, Iterator, Sequence
from typing import Any, NamedTuple

from ..iec.addresses import partial_access
from ..model.diagnostics import Diagnostic
from ..st import ast
from ..st import types as t
from ..st.body import BodyChecker
from ..st.parser import parse_expression
from ..st.rules import assignable_or_report
from ..st.symbols import Symbol
from .context import HIDDEN_PREFIX, PouContext
from .diagram_shapes import CallShapes
from .lower_expr import assign_part, lower_access, lower_expr, lower_to
from .lower_types import LoweringError
from .nodes import Assign, Const, Expr, Origin, Var
from .types import BOOL, IrType

#: Writes a value into a written operand: the assignment a coil or output node makes.
Store = Callable[[Expr, Origin], Assign]

_QUICK = re.compile(r"([0-9]+)|([A-Za-z_][A-Za-z0-9_]*)(?:\.([A-Za-z_][A-Za-z0-9_]*))?")  # integer | name[.member]


class At(NamedTuple):
    """Where a diagnostic of a diagram goes: network, element and pin. (A tuple: made for every operand and
    pin of a large diagram, it must be cheap.)"""

    network: str | None
    element: str | None = None
    pin: str | None = None

    def on(self, pin: str | None) -> At:
        return At(self.network, self.element, pin)


class _WireChecker(BodyChecker):
    """The ST checker, plus names for values that come from wires and power flow instead of text."""

    def __init__(self, operands: Operands, report: Any):
        super().__init__(operands.ctx.checked, operands.ctx.info, report)
        self._wires = operands.wires

    def lookup(self, name: str) -> Symbol | None:
        return self._wires.get(name.upper()) or BodyChecker.lookup(self, name)


class Operands:
    """Reads, writes and checks the operand texts of one diagram POU; ``lang`` prefixes diagram codes (LD, FBD)."""

    def __init__(self, ctx: PouContext, lang: str):
        self.ctx = ctx
        self.lang = lang
        self.wires: dict[str, Symbol] = {}
        #: by the text, or the text and the expected type's name: (IR, type, diagnostics; none: a shared ``()``)
        self._reads: dict[str | tuple[str, str], tuple[Expr | None, t.Type, Sequence[Diagnostic]]] = {}
        self._parsed: dict[str, tuple[ast.Expr | None, list[Diagnostic]]] = {}  # by the parser, never annotated
        self._shapes: dict[str, tuple | None] = {}  # stripped operand text -> its quick shape (see _quick_parse)
        self.callees: dict[str, Any] = {}  # upper-case name -> diagram_calls.Callee, resolved once per POU
        self.shapes = CallShapes()  # box call templates (diagram_calls)
        self._temps: dict[IrType, list[Var]] = {}
        self._used: dict[IrType, int] = {}
        #: every temporary its own slot kept between scans (a CFC chart with jumps: a value whose producer a jump
        #: skipped is read as it was left, never as another value's leftover)
        self.kept_temps = False
        self._muted: list[str] | None = None
        self._clean_targets: set[tuple] = set()  # (type, class, constness) of variables written without a word

    # ------------------------------------------------------------ temporaries
    def new_network(self) -> None:
        self._used = {}

    def temp(self, ty: IrType = BOOL) -> Var:
        """A temporary for one value a network computes (power flow, a function's result, a held input).

        Each is written before it is read within its network, so all networks share the same few
        slots: a 10,000-network POU does not get 50,000 slots, and the scan touches few names.
        """
        if self.kept_temps:
            return self.ctx.hidden("P" if ty == BOOL else "T", ty)
        pool = self._temps.setdefault(ty, [])
        used = self._used.get(ty, 0)
        if used == len(pool):
            pool.append(self.ctx.hidden("P" if ty == BOOL else "T", ty, var_class="VAR_TEMP"))
        self._used[ty] = used + 1
        return pool[used]

    # ------------------------------------------------------------ diagnostics
    def report(self, at: At, code: str, message: str, severity: str = "error") -> None:
        if self._muted is not None:
            self._muted.append(code)
            return
        self.ctx.report(code, message, network=at.network, element=at.element, pin=at.pin, severity=severity)

    @contextlib.contextmanager
    def muted(self) -> Iterator[list[str]]:
        """Collect the codes of what is reported meanwhile instead of reporting it (a call template's placeholder
        check); what the ST lowering reports to the POU directly is taken back and counts too."""
        sink: list[str] = []
        before, self._muted = len(self.ctx.diagnostics), sink
        try:
            yield sink
        finally:
            self._muted = None
            if len(self.ctx.diagnostics) != before:
                sink += [d.code for d in self.ctx.diagnostics[before:]]
                self.ctx.retract(before)

    def errors_since(self, before: int) -> bool:
        """Was an error reported since the POU had ``before`` diagnostics? (Asked after every check: mostly
        nothing was reported, and then nothing is scanned.)"""
        diagnostics = self.ctx.diagnostics
        return len(diagnostics) > before and any(d.severity == "error" for d in diagnostics[before:])

    def _relocate(self, diagnostic: Diagnostic, at: At) -> None:
        """An operand's diagnostic, moved from the operand text to the element and pin."""
        code, severity = diagnostic.code, diagnostic.severity
        if code == "ST-INPUT-WRITE":  # harmless in ST, but a coil or output on an input is a design error here
            code, severity = f"{self.lang}-INPUT-WRITE", "error"
        self.report(at, code, diagnostic.message, severity)

    def checker(self, at: At, pins: dict[str, Any] | None = None) -> BodyChecker:
        """A checker reporting at ``at``; ``pins`` maps pin names to the AST (argument) each pin gets, so a
        problem found inside one is reported on that pin."""

        def report(code: str, message: str, node: Any, severity: str = "error") -> None:
            pin = next((pin for pin, root in (pins or {}).items() if any(n is node for n in subnodes(root))), at.pin)
            self._relocate(Diagnostic(code=code, message=message, severity=severity), at.on(pin))

        return _WireChecker(self, report)

    # ------------------------------------------------------------ parsing and lowering
    def parse(self, text: str, at: At, what: str) -> ast.Expr | None:
        """The AST of an operand text, or None (reported)."""
        sink: list[Diagnostic] = []
        node = self._parse(text, what, sink)
        for diagnostic in sink:
            self._relocate(diagnostic, at)
        return node

    def _parse(self, text: str, what: str, sink: list[Diagnostic]) -> ast.Expr | None:
        stripped = text.strip()
        if not stripped:
            sink.append(Diagnostic(code=f"{self.lang}-MISSING-OPERAND", message=f"{what} has no operand"))
            return None
        quick = self._quick_parse(stripped)
        if quick is not None:
            return quick
        if text not in self._parsed:
            parsed = parse_expression(text, pou=self.ctx.info.name)
            self._parsed[text] = (parsed.ast if parsed.ok else None, parsed.diagnostics)
        node, diagnostics = self._parsed[text]
        sink += diagnostics
        return fresh_copy(node)

    def _quick_parse(self, text: str) -> ast.Expr | None:
        """The AST of the common operand shapes without the LALR parser - a declared variable, a member of
        one (``T1.Q``), a decimal integer - exactly as the parser builds them; None for anything else.
        (A generated 10,000-network diagram has some 60,000 operands, most read twice: an FBD input node's
        text by the node and by its consumer's call; the shape is recognised once, the nodes are new.)"""
        shape = self._shape(text)
        if shape is None:
            return None
        digits, root, member = shape
        if digits is not None:
            return ast.IntLit(digits, span=_one_line(len(text)))
        name = ast.Name(root, span=_one_line(len(root)))
        return ast.Member(name, member, span=_one_line(len(text))) if member is not None else name

    def _shape(self, text: str) -> tuple[int | None, str | None, str | None] | None:
        """The quick shape of a stripped operand text, recognised once per text."""
        if text in self._shapes:
            return self._shapes[text]
        shape = self._shapes[text] = self._quick_shape(text)
        return shape

    def _quick_shape(self, text: str) -> tuple[int | None, str | None, str | None] | None:
        """(integer, root name, member) of a quick operand text; None when the parser must read it."""
        match = _QUICK.fullmatch(text)
        if match is None:
            return None
        digits, root, member = match.groups()
        if digits is not None:
            return int(digits), None, None
        if not self.declared(root):
            return None
        return None, text if member is None else root, member  # (the text itself: one string less per name kept)

    def named_variable(self, text: str) -> tuple[Symbol, str | None] | None:
        """The declared variable an operand text names (``x``) and the member it selects (``t1.Q``), or None for
        any other text (an index, an expression, a literal)."""
        shape = self._shape(text.strip())
        if shape is None or shape[1] is None:
            return None
        symbol = self._symbol(shape[1])
        return (symbol, shape[2]) if symbol is not None else None

    def declared(self, name: str) -> bool:
        """Is ``name`` a variable of this POU or a global? (A declared name is never a keyword, so the parser
        reads it as a name.)"""
        return self._symbol(name) is not None

    def _symbol(self, name: str) -> Symbol | None:
        """A POU variable or else a global by name, as the checker looks names up (not one of a qualified_only list:
        its bare name is an error the checker reports)."""
        upper = name.upper()
        found = self.ctx.info.symbols.get(upper)
        if found is not None:
            return found
        listed = self.ctx.checked.listed.get(upper)  # a qualified_only list's variable: the checker reports it
        return None if listed is not None and listed.qualified_only else self.ctx.checked.globals.get(upper)

    def lower(self, node: ast.Expr, at: At, expected: IrType | None = None) -> Expr | None:
        """``lower_expr`` with its errors reported at ``at`` (None then)."""
        try:
            return lower_to(node, self.ctx, expected) if expected is not None else lower_expr(node, self.ctx)
        except LoweringError as error:
            if error.message is not None:
                self.report(at, error.code, error.message)
            return None

    def access(self, node: ast.Expr, at: At) -> Var | None:
        try:
            return lower_access(node, self.ctx)
        except LoweringError as error:
            if error.message is not None:
                self.report(at, error.code, error.message)
            return None

    def wire_node(self, value: Expr, ty: t.Type) -> ast.Expr:
        """An AST standing for a computed value (a BOOL constant or a hidden slot) as a call argument."""
        if isinstance(value, Const) and isinstance(value.value, bool):
            node: ast.Expr = ast.BoolLit(value.value)
        else:
            assert isinstance(value, Var) and not value.path and value.name.startswith(HIDDEN_PREFIX)
            if value.name not in self.wires:
                self.wires[value.name] = Symbol(value.name, "VAR", ty, None, pou=self.ctx.info.name)
            node = ast.Name(value.name)
            node.ref = self.wires[value.name]  # also when the checker skips it (EN/ENO of standard functions)
        node.ty = ty
        return node

    # ------------------------------------------------------------ operands
    def read(self, text: str, at: At, what: str, expected: t.Type | None = None) -> tuple[Expr | None, t.Type]:
        """Check and lower a read operand (contact variable, pin value, input node); (None, type) when reported.

        Identical operand texts of one POU are checked once (the IR is immutable), so large
        generated diagrams lower fast; their diagnostics are reported at every use.
        """
        key = (text, expected.name) if expected is not None else text  # (a 50,000-network POU reads 150,000 texts)
        if key not in self._reads:
            self._reads[key] = self._read(text, what, expected)
        value, ty, diagnostics = self._reads[key]
        for diagnostic in diagnostics:
            self._relocate(diagnostic, at)
        return value, ty

    def clean_read(self, text: str) -> tuple[Expr, t.Type] | None:
        """A read operand's IR and type when reading it reports nothing (nothing is reported here), else None."""
        entry = self._reads.get(text) or self._read(text, "", None)
        value, ty, diagnostics = entry
        if diagnostics or value is None:
            return None  # (not kept when read here: its messages would name no element)
        self._reads.setdefault(text, entry)
        return value, ty

    def _read(self, text: str, what: str, expected: t.Type | None) -> tuple[Expr | None, t.Type, Sequence[Diagnostic]]:
        """``st.checker.check_operand``'s steps (type, then assignability to ``expected``) on the quick parse."""
        if expected is None:
            named = self._named_read(text)
            if named is not None:
                return named
        diagnostics: list[Diagnostic] = []
        node = self._parse(text, what, diagnostics)
        if node is None:
            return None, t.ERROR, diagnostics

        def report(code: str, message: str, _node: Any, severity: str = "error") -> None:
            diagnostics.append(Diagnostic(code=code, message=message, severity=severity))

        checker = _WireChecker(self, report)
        ty = checker.expr(node, expected)
        if expected is not None and ty is not t.ERROR:
            assignable_or_report(checker, expected, ty, node, f"operand '{text.strip()}'")
        if ty is t.ERROR or ty is t.VOID or (diagnostics and any(d.severity == "error" for d in diagnostics)):
            return None, t.ERROR, diagnostics
        lowered = self._lower_quietly(node, diagnostics, self.ctx.ir_type(expected) if expected is not None else None)
        return lowered, node.ty, diagnostics

    def _named_read(self, text: str) -> tuple[Expr, t.Type, Sequence[Diagnostic]] | None:
        """A plain declared variable's read without the checker and ``lower_expr``: the checker types a name it
        finds by its symbol's type, and ``lower_expr`` lowers it to ``var_for(symbol)``. (The commonest operand
        by far: some 30,000 of a 10,000-network diagram; tests/ir/test_diagram_operands.py checks it against
        the full read.) None where the full read must decide."""
        named = self.named_variable(text)
        if named is None or named[1] is not None or named[0].type is t.ERROR:
            return None
        try:
            return self.ctx.var_for(named[0]), named[0].type, ()
        except LoweringError:
            return None

    def _lower_quietly(self, node: ast.Expr, diagnostics: list[Diagnostic], expected: IrType | None) -> Expr | None:
        try:
            return lower_to(node, self.ctx, expected) if expected is not None else lower_expr(node, self.ctx)
        except LoweringError as error:
            if error.message is not None:
                diagnostics.append(Diagnostic(code=error.code, message=error.message))
            return None

    def read_bool(self, text: str, at: At, what: str) -> Expr | None:
        """A contact's variable: any BOOL operand; anything else is reported as not BOOL."""
        value, ty = self.read(text, at, what)
        if value is not None and not t.same(ty, t.BOOL):
            self.report(at, f"{self.lang}-NOT-BOOL", f"{what} needs a BOOL variable; '{text.strip()}' is {ty}")
            return None
        return value

    def target(self, text: str, at: At, what: str) -> tuple[Var | ast.Member | None, t.Type]:
        """A written operand (coil, output node, box output): a variable that may be assigned, or a bit or part of
        one (``w.3``, ``w.%X3``, ``w.%B1``), returned as its checked AST for ``store``.

        The checker's verdict on writing a plain variable name depends only on the variable's type, class and
        constness; once one such variable was written without a word, alike ones are not checked again (some
        15,000 coils or output nodes of a 10,000-network diagram write their own variables)."""
        named = self.named_variable(text)
        kind = None
        if named is not None and named[1] is None and type(named[0].type) is t.Elementary:
            symbol = named[0]
            kind = (symbol.type, symbol.var_class, symbol.constant)
            if kind in self._clean_targets:
                name = ast.Name(symbol.name)
                name.ref = symbol
                return self.access(name, at), symbol.type
        node = self.parse(text, at, what)
        if node is None:
            return None, t.ERROR
        before = len(self.ctx.diagnostics)
        ty = self.checker(at).target(node)
        if ty is t.ERROR or self.errors_since(before):
            return None, t.ERROR
        if isinstance(node, ast.Member) and partial_access(node.name) is not None:
            return node, ty
        if kind is not None and len(self.ctx.diagnostics) == before:
            self._clean_targets.add(kind)
        return self.access(node, at), ty

    def bool_target(self, text: str, at: At, what: str) -> Store | None:
        """A coil's or BOOL output node's operand: a BOOL variable or a bit of one (``w.3``, ``w.%X3``), as the
        store of a value."""
        var, ty = self.target(text, at, what)
        if var is not None and not t.same(ty, t.BOOL):
            self.report(at, f"{self.lang}-NOT-BOOL", f"{what} needs a BOOL variable; '{text.strip()}' is {ty}")
            return None
        return None if var is None else self.store(var)

    def store(self, target: Var | ast.Member) -> Store:
        """Writing a value into a variable, or into a bit of one: the variable gets its new bit pattern, as ST's
        ``w.3 := v`` (lower_expr.assign_part)."""
        if isinstance(target, Var):
            return lambda value, origin: Assign(target, value, origin)
        return lambda value, origin: Assign(*assign_part(target, value, self.ctx), origin)

    def value_target(self, text: str, at: At, what: str, value: t.Type) -> Var | ast.Member | None:
        """A written operand that receives a ``value``-typed result (a box output pin): a variable, or a bit or
        part of one as its checked AST for ``store``."""
        var, ty = self.target(text, at, what)
        return var if var is not None and self.assignable(ty, value, at, f"{what} ('{text.strip()}')") else None

    def assignable(self, target: t.Type, value: t.Type, at: At, what: str) -> bool:
        """Can a ``value`` be stored in ``target``? ST's rule and message (ST-23), reported at ``at``."""
        return assignable_or_report(self.checker(at), target, value, None, what)

    def compare(self, op: str, left: str, right: str, at: At) -> Expr | None:
        """A compare contact's condition, typed by the ST rules of ``left <op> right`` (GR-19)."""
        nodes = [
            self.parse(left, at.on("left"), "the compare contact"),
            self.parse(right, at.on("right"), "the compare contact"),
        ]
        if None in nodes:
            return None
        node = ast.Binary(_COMPARE[op], nodes[0], nodes[1])
        before = len(self.ctx.diagnostics)
        self.checker(at, {"left": nodes[0], "right": nodes[1]}).expr(node)
        if self.errors_since(before):
            return None
        return self.lower(node, at)


@functools.cache
def _one_line(length: int) -> ast.Span:
    """The span of an operand text of ``length`` characters on its one line (spans are immutable: shared)."""
    return ast.Span(1, 1, 1, length + 1)


_COMPARE = {"GT": ">", "GE": ">=", "EQ": "=", "LE": "<=", "LT": "<", "NE": "<>"}


def fresh_copy(node: Any) -> Any:
    """A copy of a parsed expression tree: new nodes (the checker annotates them, and a box tells its pins apart
    by node identity), the immutable leaves (spans, names, values) shared."""
    if isinstance(node, list):
        return [fresh_copy(item) for item in node]
    if not dataclasses.is_dataclass(node) or isinstance(node, ast.Span):
        return node
    return type(node)(*(fresh_copy(getattr(node, field.name)) for field in dataclasses.fields(node)))


def subnodes(node: Any):
    """``node`` and every AST node below it (to map checker reports back to the pin an argument feeds)."""
    yield node
    if not dataclasses.is_dataclass(node):
        return
    for field in dataclasses.fields(node):
        if field.name in ("ty", "ref", "span"):
            continue
        value = getattr(node, field.name)
        for item in value if isinstance(value, list) else [value]:
            if dataclasses.is_dataclass(item) and not isinstance(item, ast.Span):
                yield from subnodes(item)
