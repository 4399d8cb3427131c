"""Standard FB calls inlined: the body of the FB's own ``execute`` pasted where the call is.

A method call costs as much as a timer's whole body, so the fast and monitor variants paste the body of a standard
FB's ``execute`` (engine/stdlib/fbs.py, the one definition of its behaviour) in place of the call. An input just
assigned a local or a constant is read from there (``known``), not back from the instance::

    ll_fb = self.v_T1
    ll_fb.IN = ll_t___P_2
    ll_fb.PT = 100
    if not ll_t___P_2:
        ...

In a unit test program (``ir.Program.mockable``) the body is guarded by the instance's class: a mocked instance,
docs/testing.md, has another class and is called as before (``else: ll_fb.execute(now)``).

The body is taken from the method's source with ``ast``, not copied: ``self`` becomes the instance's local,
the clock argument the scan's clock, the method's locals ``ll_s_<name>``, and an early ``return`` becomes the
``else`` of its ``if`` (the statements after it go into both branches). A body that needs anything else (a
``return`` in a loop, a global other than a builtin) is not inlined.
"""

from __future__ import annotations

import ast
import builtins
import copy
import functools
import inspect
import textwrap

from ..stdlib import STANDARD_FBS


class _NotInlinable(Exception):
    pass


@functools.lru_cache(maxsize=4096)
def inline_body(
    fb: str, instance: str, now: str, known: tuple[tuple[str, str], ...] = (), output: tuple[str, str] | None = None
) -> tuple[str, ...] | None:
    """The lines of standard FB ``fb``'s ``execute`` acting on the local ``instance`` at clock ``now`` (None: not
    inlinable), indented from column 0. ``known``: (input, code) pairs, the code of a local or a constant the input
    was just assigned, read in its place (an input the body assigns itself is read from the instance). ``output``:
    (output, local) to also hold the output in that local when the body ends (``_output_copied``; None when the
    body cannot)."""
    cls = STANDARD_FBS.get(fb.upper())
    if cls is None:
        return None
    function = ast.parse(textwrap.dedent(inspect.getsource(cls.execute))).body[0]
    assert isinstance(function, ast.FunctionDef)
    this, clock = (a.arg for a in function.args.args)
    assigned = {n.id for n in ast.walk(function) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    renames = {this: instance, clock: now} | {name: f"ll_s_{name}" for name in assigned}
    try:
        for node in ast.walk(function):
            if isinstance(node, ast.Name):
                if node.id in renames:
                    node.id = renames[node.id]
                elif not hasattr(builtins, node.id):
                    raise _NotInlinable(node.id)
        body = _without_returns([s for s in function.body if not _docstring(s)])
    except _NotInlinable:
        return None
    body = [_KnownInputs(instance, dict(known), _assigned_attributes(body, instance)).visit(s) for s in body]
    body = _propagated(body)
    if output is not None:
        copied = _output_copied(body, instance, *output)
        if copied is None:
            return None
        body = copied
    return tuple(ast.unparse(ast.Module(body=body or [ast.Pass()], type_ignores=[])).splitlines())


def _output_copied(body: list[ast.stmt], instance: str, pin: str, local: str) -> list[ast.stmt] | None:
    """``body`` storing the output ``pin`` into ``local`` too wherever it stores it (``ll_fb._running = ll_fb.Q =
    ll_t___P_3 = False``; ``ll_fb.Q, ll_fb.ET = (True, 100)`` becomes ``ll_t___P_3 = ll_fb.Q = True`` then
    ``ll_fb.ET = 100``), so the copy after the body (``ll_t___P_3 = ll_fb.Q``, a TON's Q into the next box) reads
    nothing again. None unless every path through the body stores the output (else the local would keep an older
    value) and the body never mentions ``local`` (it could read it as an input after the store)."""
    if any(isinstance(node, ast.Name) and node.id == local for s in body for node in ast.walk(s)):
        return None
    if not _always_stores(body, instance, pin):
        return None
    try:
        return _with_copies(body, instance, pin, local)
    except _NotInlinable:
        return None


def _is_pin(node: ast.expr, instance: str, pin: str) -> bool:
    return (
        isinstance(node, ast.Attribute)
        and node.attr == pin
        and isinstance(node.value, ast.Name)
        and node.value.id == instance
    )


def _place(node: ast.AST) -> str | None:
    """``ll_fb.Q`` or ``ll_s_x`` for an attribute of a name or a name, stored or read alike; else None."""
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
        return f"{node.value.id}.{node.attr}"
    return node.id if isinstance(node, ast.Name) else None


def _stores_pin(statement: ast.stmt, instance: str, pin: str) -> bool:
    """Whether ``statement`` itself (an assignment, not a branch inside it) stores the output."""
    if not isinstance(statement, ast.Assign):
        return False
    targets = [e for t in statement.targets for e in (t.elts if isinstance(t, ast.Tuple) else [t])]
    return any(_is_pin(target, instance, pin) for target in targets)


def _always_stores(body: list[ast.stmt], instance: str, pin: str) -> bool:
    return any(
        _stores_pin(s, instance, pin)
        or (isinstance(s, ast.If) and _always_stores(s.body, instance, pin) and _always_stores(s.orelse, instance, pin))
        for s in body
    )


def _with_copies(body: list[ast.stmt], instance: str, pin: str, local: str) -> list[ast.stmt]:
    """The statements of ``body`` with ``local`` stored next to every store of the output (``_output_copied``)."""
    done: list[ast.stmt] = []
    for statement in body:
        if isinstance(statement, ast.If):
            statement.body = _with_copies(statement.body, instance, pin, local)
            statement.orelse = _with_copies(statement.orelse, instance, pin, local)
        elif _stores_pin(statement, instance, pin):
            assert isinstance(statement, ast.Assign)
            if len(statement.targets) == 1 and isinstance(statement.targets[0], ast.Tuple):
                done.extend(_split(statement, instance, pin, local))
                continue
            statement.targets.append(ast.Name(id=local, ctx=ast.Store()))
        elif any(
            isinstance(node, ast.Attribute) and _is_pin(node, instance, pin) and not isinstance(node.ctx, ast.Load)
            for node in ast.walk(statement)
        ):
            raise _NotInlinable("the output stored in another way")  # (``+=``, in a loop)
        done.append(statement)
    return [ast.fix_missing_locations(s) for s in done]


def _split(statement: ast.Assign, instance: str, pin: str, local: str) -> list[ast.stmt]:
    """A tuple assignment storing the output as one assignment per target, the output's with ``local`` too: exact
    when no value reads an attribute the assignment stores (the body's values read locals, constants and the
    instance's attributes, and compute nothing that can fault)."""
    pairs = _pairs(statement.targets[0], statement.value)
    stored = {_place(target) for target, _ in pairs}
    if len(pairs) < 2 or any(_place(node) in stored for _, value in pairs for node in ast.walk(value)):
        raise _NotInlinable("a tuple assignment reading what it stores")
    split = []
    for target, value in pairs:
        targets = [target, ast.Name(id=local, ctx=ast.Store())] if _is_pin(target, instance, pin) else [target]
        split.append(ast.Assign(targets=targets, value=value))
    return split


class _KnownInputs(ast.NodeTransformer):
    """Reads of ``instance.<input>`` replaced by the code the input was just assigned (``inline_body``'s ``known``)."""

    def __init__(self, instance: str, known: dict[str, str], assigned: set[str]) -> None:
        self.instance = instance
        self.known = {pin: code for pin, code in known.items() if pin not in assigned}

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        if (
            isinstance(node.ctx, ast.Load)
            and isinstance(node.value, ast.Name)
            and node.value.id == self.instance
            and node.attr in self.known
        ):
            return ast.parse(self.known[node.attr], mode="eval").body
        return self.generic_visit(node)


def _propagated(body: list[ast.stmt]) -> list[ast.stmt]:
    """``body`` without the copies into a method local assigned nowhere else (``ll_s_cu = ll_t___P_3``,
    the ``pt`` of ``elapsed, pt = now - ll_fb._start, 100``): its reads use the copied local or constant instead,
    which nothing in the body assigns (the body assigns only its own locals and the instance's attributes), and a
    conditional on two constants that results (``pt if pt > 0 else 0``) is folded."""
    stores: dict[str, int] = {}
    for statement in body:
        for node in ast.walk(statement):
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                stores[node.id] = stores.get(node.id, 0) + 1
    copies: dict[str, ast.expr] = {}
    kept = _without_copies(body, stores, copies)
    if not copies:
        return body
    return [ast.fix_missing_locations(_Copies(copies).visit(statement)) for statement in kept]


def _without_copies(body: list[ast.stmt], stores: dict[str, int], copies: dict[str, ast.expr]) -> list[ast.stmt]:
    """``body`` (and the branches of its ``if`` statements) without the copies ``_propagated`` removes, which go
    into ``copies``."""
    kept: list[ast.stmt] = []
    for statement in body:
        if isinstance(statement, ast.If):
            statement.body = _without_copies(statement.body, stores, copies) or [ast.Pass()]
            statement.orelse = _without_copies(statement.orelse, stores, copies)
        elif isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            pairs = _pairs(statement.targets[0], statement.value)
            left = []
            for target, value in pairs:
                if (
                    isinstance(target, ast.Name)
                    and stores.get(target.id) == 1
                    and (isinstance(value, ast.Constant) or (isinstance(value, ast.Name) and value.id not in stores))
                ):
                    copies[target.id] = value
                else:
                    left.append((target, value))
            if len(left) < len(pairs):
                if not left:
                    continue
                statement = _assignment(left)
        kept.append(statement)
    return kept


def _pairs(target: ast.expr, value: ast.expr) -> list[tuple[ast.expr, ast.expr]]:
    if isinstance(target, ast.Tuple) and isinstance(value, ast.Tuple) and len(target.elts) == len(value.elts):
        return list(zip(target.elts, value.elts))
    return [(target, value)]


def _assignment(pairs: list[tuple[ast.expr, ast.expr]]) -> ast.Assign:
    if len(pairs) == 1:
        return ast.Assign(targets=[pairs[0][0]], value=pairs[0][1])
    targets = ast.Tuple(elts=[t for t, _ in pairs], ctx=ast.Store())
    return ast.Assign(targets=[targets], value=ast.Tuple(elts=[v for _, v in pairs], ctx=ast.Load()))


class _Copies(ast.NodeTransformer):
    """Reads of the propagated locals replaced by what they copied; conditionals on constants folded."""

    def __init__(self, copies: dict[str, ast.expr]) -> None:
        self.copies = copies

    def visit_Name(self, node: ast.Name) -> ast.AST:
        if isinstance(node.ctx, ast.Load) and node.id in self.copies:
            return copy.deepcopy(self.copies[node.id])
        return node

    def visit_IfExp(self, node: ast.IfExp) -> ast.AST:
        self.generic_visit(node)
        test = node.test
        if (
            isinstance(test, ast.Compare)
            and len(test.ops) == 1
            and type(test.ops[0]) in _FOLDED
            and isinstance(test.left, ast.Constant)
            and isinstance(test.comparators[0], ast.Constant)
        ):
            decided = _FOLDED[type(test.ops[0])](test.left.value, test.comparators[0].value)
            return node.body if decided else node.orelse
        return node


_FOLDED = {
    ast.Gt: lambda a, b: a > b,
    ast.GtE: lambda a, b: a >= b,
    ast.Lt: lambda a, b: a < b,
    ast.LtE: lambda a, b: a <= b,
}


def _assigned_attributes(body: list[ast.stmt], instance: str) -> set[str]:
    """The attributes of ``instance`` the statements assign."""
    return {
        node.attr
        for statement in body
        for node in ast.walk(statement)
        if isinstance(node, ast.Attribute)
        and isinstance(node.ctx, ast.Store)
        and isinstance(node.value, ast.Name)
        and node.value.id == instance
    }


def _docstring(statement: ast.stmt) -> bool:
    return isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant)


def _without_returns(statements: list[ast.stmt]) -> list[ast.stmt]:
    """The same statements with every ``return`` (of nothing) turned into control flow: the statements after an
    ``if`` that may return move into both of its branches, and a branch ends where it returned."""
    done: list[ast.stmt] = []
    for index, statement in enumerate(statements):
        if isinstance(statement, ast.Return):
            if statement.value is not None:
                raise _NotInlinable("return with a value")
            return done
        if not _returns(statement):
            done.append(statement)
            continue
        if not isinstance(statement, ast.If):
            raise _NotInlinable("return in a loop")
        rest = statements[index + 1 :]
        statement.body = _without_returns(statement.body + copy.deepcopy(rest)) or [ast.Pass()]
        statement.orelse = _without_returns(statement.orelse + rest)
        done.append(statement)
        return done
    return done


def _returns(statement: ast.stmt) -> bool:
    return any(isinstance(node, ast.Return) for node in ast.walk(statement))
