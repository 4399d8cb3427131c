"""One network as ST: values and statements in evaluation order, then inlined where that changes nothing.

The LD and FBD exporters describe a network the way the engine runs it
(docs/ir.md invariant 5, ir/lower_ld.py, ir/lower_fbd.py): every value an
element computes is a ``Value`` placed at the element's position, every side
effect (coil write, box call, edge trigger) a ``Step``. ``Use(value)`` stands for
a value inside later expressions and statements.

``plan`` then decides, from the last value to the first, what becomes an
expression and what a named temporary. A value is written inline into its one
user when no step between its position and the place where the user is finally
evaluated writes a variable the value reads (a step calling a user POU may write
anything). A trivial value (a variable, ``NOT`` variable, a literal) may be
inlined into several users under the same rule. A value used several times whose
first user writes it to a variable of its own type (``Speed := a * 10 + 5``) is
read back from that variable by the others (``HighSpeed := Speed > 50``) while
nothing writes it in between. Only what is left - "a rung value used by several
set coils", a variable read before the network writes it - gets a temporary,
named after what it holds (``rung2``, ``Lamp_prev``, ``TON1_Q``). A value that
may fault (non-constant index, integer division, MUX) or calls a user function
moves to its user only past nothing that could act first (no step, no other such
value), so it is evaluated exactly where the diagram evaluates it.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

from ...st import ast
from .names import Names

#: Standard functions whose call may stop the task with a fault (docs/runtime.md).
_FALLIBLE_CALLS = {"DIV", "DIV_TIME", "DIVTIME", "MUX"}

TRUE = ast.BoolLit(True)


@dataclass(eq=False)
class Value:
    """An expression evaluated at its position in the network (``expr`` may hold ``Use`` nodes)."""

    expr: Any
    element: str | None
    hint: str
    type: str = "BOOL"
    pinned: bool = False  # stored where it is computed even when used once
    effect: bool = False  # calls a user function: may write anything
    reads: frozenset[str] = frozenset()
    fallible: bool = False

    def __post_init__(self) -> None:
        self.reads = frozenset(read_names(self.expr))
        self.fallible = may_fault(self.expr)


@dataclass(eq=False)
class Use:
    """An AST placeholder for ``value``; replaced by its expression or its temporary before printing."""

    value: Value


@dataclass(eq=False)
class Step:
    """Statements run at this position; ``writes`` are the upper-case root names written (None: anything).

    ``optional`` is a value the statements write (an ENO flag): when nothing uses it, ``without`` is printed
    instead.
    """

    statements: list[Any]
    element: str | None
    writes: frozenset[str] | None
    optional: Value | None = None
    without: list[Any] | None = None
    declare: tuple[str, str, str] | None = None  # the optional value's variable, declared only when used
    carries: tuple[Value, Any, str | None] | None = None  # statements are ``target := Use(value)``; target's type


@dataclass(eq=False)
class Control:
    """A jump (``label``) or a return (``label`` None) acting when ``cond`` holds, after the network."""

    label: str | None
    cond: Value | None  # None: always
    element: str


@dataclass(frozen=True)
class ChartJump:
    """A CFC chart's jump, as a statement of its step: the chart's ST is cut after it (``chart_segments``)."""

    label: str  # canonical
    cond: Any


@dataclass(frozen=True)
class ChartLabel:
    """A CFC chart's label, as a statement of its step: the chart's ST is cut before it."""

    label: str  # canonical


@dataclass
class Declarations:
    """Variables the export adds to a POU: (name, type text, VAR or VAR_TEMP) in the order they were made;
    ``temp_class``: the class of the temporaries (VAR where a jump may skip the statement that writes one, so
    it keeps its value as the diagram's does)."""

    names: Names
    items: list[tuple[str, str, str]] = field(default_factory=list)
    temp_class: str = "VAR_TEMP"

    def declare(self, hint: str, type_text: str, var_class: str | None = None) -> str:
        var_class = var_class or self.temp_class
        name = self.names.fresh(hint)
        self.add(name, type_text, var_class)
        return name

    def add(self, name: str, type_text: str, var_class: str = "VAR_TEMP") -> None:
        """A variable whose name ``names`` already reserved."""
        self.items.append((name, type_text, var_class))


class NetworkCode:
    """The values, steps and controls of one network in evaluation order."""

    def __init__(self) -> None:
        self.ops: list[Value | Step] = []
        self.controls: list[Control] = []

    def value(self, expr: Any, element: str | None, hint: str, **flags: Any) -> Value:
        value = Value(expr, element, hint, **flags)
        self.ops.append(value)
        return value

    def step(self, statements: list[Any], element: str | None, writes: frozenset[str] | None, **optional: Any) -> Step:
        step = Step(statements, element, writes, **optional)
        self.ops.append(step)
        return step


@dataclass
class Planned:
    """A planned network: ``(element, statement)`` pairs to print, and each control's final condition."""

    statements: list[tuple[str | None, ast.Stmt]]
    conditions: list[ast.Expr | None]


def plan(code: NetworkCode, declarations: Declarations) -> Planned:
    """Decide inline, carried or temporary for every value (module docstring) and build the final statements."""
    position = {id(op): index for index, op in enumerate(code.ops)}
    end = len(code.ops)
    users: dict[int, list[Any]] = {id(op): [] for op in code.ops if isinstance(op, Value)}
    for op in code.ops:
        for value in uses_in(op.expr if isinstance(op, Value) else op.statements):
            users[id(value)].append(op)
    for control in code.controls:
        if control.cond is not None:
            users[id(control.cond)].append(control)
    effects = [
        (position[id(op)], op.writes if isinstance(op, Step) else None)
        for op in code.ops
        if isinstance(op, Step) or op.effect
    ]
    barriers = [op for op in code.ops if isinstance(op, Step) or op.effect or op.fallible]
    final: dict[int, int] = {}  # value -> where its expression is finally evaluated
    inline: set[int] = set()
    carried: dict[int, Value] = {}  # id of the step that writes the value first -> the value
    moved: set[int] = set()  # carried values

    def evaluated_at(user: Any) -> int:
        if isinstance(user, Control):
            return end
        if isinstance(user, Step) or (id(user) not in inline and id(user) not in moved):
            return position[id(user)]
        return final[id(user)]

    def undisturbed(reads: frozenset[str], start: int, stop: int) -> bool:
        return not any(start < at < stop and (writes is None or writes & reads) for at, writes in effects)

    def movable(value: Value, stop: int) -> bool:
        """Can ``value`` be evaluated at ``stop`` instead of where it stands?"""
        start = position[id(value)]
        if value.fallible:  # nothing that acts or may fault may come first, except what is computed from it
            return not any(
                start < position[id(op)] < stop and not (isinstance(op, Value) and _computed_from(op, value))
                for op in barriers
            )
        return undisturbed(value.reads, start, stop)

    def carrier(value: Value, found: list[Any]) -> Step | None:
        """The step that writes ``value`` to a variable of its type before every other user reads it."""
        steps = [u for u in found if isinstance(u, Step) and u.carries is not None and u.carries[0] is value]
        if not steps:
            return None
        step = min(steps, key=lambda u: position[id(u)])
        _, target, target_type = step.carries
        at = position[id(step)]
        root = frozenset({root_name(target)})
        others = [evaluated_at(u) for u in found if u is not step]
        if target_type != value.type or not movable(value, at) or any(stop <= at for stop in others):
            return None
        if not all(undisturbed(root | read_names(target), at, stop) for stop in others):
            return None
        return step

    for op in reversed(code.ops):
        if not isinstance(op, Value):
            continue
        found = users[id(op)]
        if not found and not op.pinned and not op.effect and not op.fallible:  # unread: so are its parts, here
            for part in uses_in(op.expr):
                users[id(part)].remove(op)
            continue
        if op.pinned or op.effect or (not found and op.fallible):
            final[id(op)] = position[id(op)]
            continue
        if len(found) == 1 or (trivial(op.expr) and not op.fallible):
            stops = [evaluated_at(user) for user in found]
            if all(movable(op, stop) for stop in stops):
                inline.add(id(op))
                final[id(op)] = stops[0]
                continue
        step = carrier(op, found)
        if step is not None:
            carried[id(step)] = op
            moved.add(id(op))
            final[id(op)] = position[id(step)]
            continue
        final[id(op)] = position[id(op)]

    temps: dict[int, ast.Expr] = {}

    def resolve(node: Any) -> Any:
        return without_double_not(
            substitute(node, lambda value: temps[id(value)] if id(value) in temps else resolve(value.expr))
        )

    statements: list[tuple[str | None, ast.Stmt]] = []
    for op in code.ops:
        if isinstance(op, Step):
            full = op.optional is None or bool(users[id(op.optional)])
            chosen = op.statements if full else op.without
            if full and op.declare is not None:
                declarations.items.append(op.declare)
            statements += [(op.element, resolve(s)) for s in chosen]
            if id(op) in carried:  # later users read the variable it wrote
                temps[id(carried[id(op)])] = op.carries[1]
        elif id(op) not in inline and _stored(op, users, moved):
            expr = resolve(op.expr)
            if op.effect and not users[id(op)]:  # a user function box whose result nothing reads
                statements.append((op.element, ast.CallStmt(expr)))
            else:  # read later, or evaluated here whether read or not (it may fault, as in the diagram)
                name = declarations.declare(op.hint, op.type)
                temps[id(op)] = ast.Name(name)
                statements.append((op.element, ast.Assign(ast.Name(name), expr)))
    conditions = [resolve(Use(c.cond)) if c.cond is not None else None for c in code.controls]
    return Planned(statements, conditions)


def chart_segments(planned: Planned) -> list[tuple[list[tuple[str | None, ast.Stmt]], ChartLabel | None, tuple]]:
    """A planned CFC chart cut at its labels and after its jumps: per segment its statements, the label it starts
    with (None: the first) and its jump at the end (``(label, cond, element)``, or ``()``)."""
    segments: list[tuple[list[tuple[str | None, ast.Stmt]], ChartLabel | None, tuple]] = [([], None, ())]
    for element, statement in planned.statements:
        if isinstance(statement, ChartLabel):
            segments.append(([], statement, ()))
        elif isinstance(statement, ChartJump):
            statements, label, _ = segments[-1]
            segments[-1] = (statements, label, (statement.label, statement.cond, element))
            segments.append(([], None, ()))
        else:
            segments[-1][0].append((element, statement))
    return [segment for segment in segments if segment[0] or segment[1] is not None or segment[2]] or segments[:1]


def _computed_from(op: Value, value: Value) -> bool:
    """Does ``op``'s expression use ``value``, directly or through other values?"""
    todo, seen = list(uses_in(op.expr)), set()
    while todo:
        part = todo.pop()
        if part is value:
            return True
        if id(part) not in seen:
            seen.add(id(part))
            todo += uses_in(part.expr)
    return False


def _stored(op: Value, users: dict[int, list[Any]], moved: set[int]) -> bool:
    """Does ``op`` (not inline) get its own statement here?"""
    return id(op) not in moved and (bool(users[id(op)]) or op.pinned or op.effect or op.fallible)


# ------------------------------------------------------------------ AST helpers


def substitute(node: Any, replace: Any) -> Any:
    """A copy of ``node`` with every ``Use`` replaced by ``replace(value)``."""
    if isinstance(node, Use):
        return replace(node.value)
    if isinstance(node, list):
        return [substitute(item, replace) for item in node]
    if isinstance(node, tuple):
        return tuple(substitute(item, replace) for item in node)
    if dataclasses.is_dataclass(node) and not isinstance(node, (ast.Span, Value)):
        changes = {
            f.name: substitute(getattr(node, f.name), replace)
            for f in dataclasses.fields(node)
            if f.name not in ("span", "ty", "ref")
        }
        return dataclasses.replace(node, **changes)
    return node


def without_double_not(node: Any) -> Any:
    """``NOT NOT x`` -> ``x`` (a negated pin fed by a negated value; NOT is its own inverse on BOOL and bits),
    ``NOT TRUE`` -> ``FALSE`` (a negated coil on the left rail)."""
    if (
        isinstance(node, ast.Unary)
        and node.op == "NOT"
        and isinstance(node.operand, ast.Unary)
        and node.operand.op == "NOT"
    ):
        return without_double_not(node.operand.operand)
    if isinstance(node, ast.Unary) and node.op == "NOT" and isinstance(node.operand, ast.BoolLit):
        return ast.BoolLit(not node.operand.value)
    if isinstance(node, list):
        return [without_double_not(item) for item in node]
    if isinstance(node, tuple):
        return tuple(without_double_not(item) for item in node)
    if dataclasses.is_dataclass(node) and not isinstance(node, (ast.Span, Value, Use)):
        changes = {
            f.name: without_double_not(getattr(node, f.name))
            for f in dataclasses.fields(node)
            if f.name not in ("span", "ty", "ref")
        }
        return dataclasses.replace(node, **changes)
    return node


def _nodes(node: Any):
    """Every AST node below ``node`` (not through ``Use``)."""
    if isinstance(node, (list, tuple)):
        for item in node:
            yield from _nodes(item)
    elif isinstance(node, Use):
        yield node
    elif dataclasses.is_dataclass(node) and not isinstance(node, (ast.Span, Value)):
        yield node
        for f in dataclasses.fields(node):
            if f.name not in ("span", "ty", "ref"):
                yield from _nodes(getattr(node, f.name))


def uses_in(node: Any) -> list[Value]:
    return [n.value for n in _nodes(node) if isinstance(n, Use)]


def read_names(node: Any) -> set[str]:
    """Upper-case names of every variable an expression mentions (index expressions included)."""
    return {n.name.upper() for n in _nodes(node) if isinstance(n, ast.Name)}


def may_fault(node: Any) -> bool:
    """Can evaluating ``node`` stop the task (a non-constant index, integer ``/``, DIV, MUX)?"""
    for n in _nodes(node):
        if isinstance(n, ast.Index) and not all(isinstance(i, ast.IntLit) for i in n.indices):
            return True
        if isinstance(n, ast.Binary) and n.op == "/":
            return True
        if isinstance(n, ast.Call) and isinstance(n.callee, ast.Name) and n.callee.name.upper() in _FALLIBLE_CALLS:
            return True
        if isinstance(n, ast.Deref):
            return True
    return False


def trivial(expr: Any) -> bool:
    """A literal, a variable or member access, or NOT of one: cheap to repeat, reads nothing twice that matters."""
    if isinstance(expr, ast.Unary) and expr.op == "NOT":
        expr = expr.operand
    if isinstance(expr, ast.Member):
        expr = expr.base
    return isinstance(expr, (ast.Name, ast.BoolLit, ast.IntLit))


def root_name(expr: Any) -> str | None:
    """The variable a target expression writes: ``x`` of ``x``, ``x.f``, ``x[i]``, ``x.3``."""
    while isinstance(expr, (ast.Member, ast.Index)):
        expr = expr.base
    return expr.name.upper() if isinstance(expr, ast.Name) else None


def conjunction(values: list[Any]) -> Any:
    """``a AND b AND c`` of AST operands, TRUE when empty."""
    if not values:
        return TRUE
    result = values[0]
    for value in values[1:]:
        result = ast.Binary("AND", result, value)
    return result


def disjunction(values: list[Any]) -> Any:
    if not values:
        return ast.BoolLit(False)
    result = values[0]
    for value in values[1:]:
        result = ast.Binary("OR", result, value)
    return result
