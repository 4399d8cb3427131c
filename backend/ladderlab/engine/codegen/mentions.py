"""The variables a statement mentions (its own expressions, not nested statements) and their IEC text: shown in
fault reports."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any

from ...ir import nodes as ir
from ...ir import types as t


def expression_nodes(e: ir.Expr | None) -> Iterator[ir.Expr]:
    """Every node of an expression, outermost first, index expressions and call arguments included."""
    if e is None:
        return
    yield e
    if isinstance(e, ir.Var):
        for selector in e.path:
            if isinstance(selector, ir.Index):
                for index in selector.indices:
                    yield from expression_nodes(index)
    elif isinstance(e, ir.Binary):
        yield from expression_nodes(e.left)
        yield from expression_nodes(e.right)
    elif isinstance(e, ir.Call):
        for a in (*e.args, *e.in_outs):
            yield from expression_nodes(a)
    elif isinstance(e, (ir.Unary, ir.Convert, ir.Fit)):
        yield from expression_nodes(e.operand)
    elif isinstance(e, ir.AddressOf):
        yield from expression_nodes(e.var)
    elif isinstance(e, (ir.Attempt, ir.View)):
        yield from expression_nodes(e.value)


def expression_vars(e: ir.Expr | None) -> Iterator[ir.Var]:
    return (n for n in expression_nodes(e) if isinstance(n, ir.Var))


def calls_in(e: ir.Expr | None) -> list[ir.Call]:
    """Every function call in an expression, outermost first, index expressions and arguments included. (Walked by
    plain recursion, not ``expression_nodes``'s nested generators, at about half the cost: it runs for every
    expression of a POU, ~0.2 s of generating a 50,000-network program's code.)"""
    found: list[ir.Call] = []
    if e is not None:
        _calls(e, found)
    return found


def _calls(e: ir.Expr, found: list[ir.Call]) -> None:
    if type(e) is ir.Var:
        for selector in e.path:
            if type(selector) is ir.Index:
                for index in selector.indices:
                    _calls(index, found)
    elif type(e) is ir.Binary:
        _calls(e.left, found)
        _calls(e.right, found)
    elif type(e) is ir.Call:
        found.append(e)
        for a in (*e.args, *e.in_outs):
            _calls(a, found)
    elif type(e) is ir.Unary or type(e) is ir.Convert or type(e) is ir.Fit:
        _calls(e.operand, found)
    elif type(e) is ir.AddressOf:
        _calls(e.var, found)
    elif type(e) is ir.Attempt or type(e) is ir.View:
        _calls(e.value, found)


def own_expressions(s: ir.Stmt) -> Iterable[ir.Expr | None]:
    """The expressions of ``s`` itself, not of its nested statements. (By the statement's class, not a chain of
    isinstance checks: it runs for every statement of a large body, probes first of all, in ``mentions``.)"""
    own = _OWN_EXPRESSIONS.get(type(s))
    return () if own is None else own(s)


_OWN_EXPRESSIONS: dict[type, Callable[[Any], Iterable[ir.Expr | None]]] = {
    ir.Assign: lambda s: (s.target, s.value),
    ir.Probe: lambda s: (s.value,),
    ir.If: lambda s: [cond for cond, _ in s.branches],
    ir.Case: lambda s: (s.selector,),
    ir.For: lambda s: (s.var, s.start, s.end, s.step),
    ir.While: lambda s: (s.cond,),
    ir.Repeat: lambda s: (s.until,),
    ir.FbCall: lambda s: (s.en, *(e for _, e in s.inputs), *(v for _, v in s.outputs), s.eno),
    ir.FnCall: lambda s: (s.en, s.call, s.target, s.eno),
    ir.Jump: lambda s: (s.cond,),
}


def statement_vars(s: ir.Stmt) -> list[ir.Var]:
    """Distinct variables of the statement's own expressions, in order of appearance."""
    seen: dict[ir.Var, None] = {}
    for e in own_expressions(s):
        for v in expression_vars(e):
            seen.setdefault(v, None)
    return list(seen)


def nested(s: ir.Stmt) -> Iterator[list[ir.Stmt]]:
    """The statement lists directly inside ``s``."""
    if isinstance(s, (ir.If, ir.Case)):
        for _, body in s.branches:
            yield body
        yield s.orelse
    elif isinstance(s, (ir.For, ir.While, ir.Repeat)):
        yield s.body


_LEAVES = (ir.Assign, ir.Probe, ir.FbCall, ir.FnCall, ir.Exit, ir.Continue, ir.Return, ir.Jump)  # no nested statements


def walk(statements: list[ir.Stmt]) -> Iterator[ir.Stmt]:
    for s in statements:
        yield s
        if not isinstance(s, _LEAVES):
            for body in nested(s):
                yield from walk(body)


def walk_filled(statements: list[ir.Stmt], walked: list[ir.Stmt]) -> list[ir.Stmt]:
    """``walk`` of a network filled in from a template (``ir.Filled``: only IFs nest statements there) into the list
    ``walked``, without the generators (it runs for each of 50,000 networks, issue 27)."""
    for s in statements:
        walked.append(s)
        if type(s) is ir.If:
            for _, body in s.branches:
                walk_filled(body, walked)
            walk_filled(s.orelse, walked)
    return walked


def var_text(var: ir.Var) -> str:
    """IEC text of an access path, e.g. ``ARR[I]``, ``S.F``, ``T1.Q``."""
    text = var.name
    for selector in var.path:
        if isinstance(selector, ir.Member):
            text += f".{selector.name}"
        elif isinstance(selector, ir.Deref):
            text += "^"
        else:
            text += "[" + ", ".join(_index_text(i) for i in selector.indices) + "]"
    return text


def _index_text(e: ir.Expr) -> str:
    if isinstance(e, ir.Var):
        return var_text(e)
    if isinstance(e, ir.Const):
        return repr(e.value)
    return "..."


@dataclass(frozen=True, slots=True)
class Mentions:
    """What the questions below need of a POU's body, found in one walk (``mentions``): one walk per question
    took ~0.5 s each over a 50,000-network body."""

    pou: ir.Pou
    addressed: frozenset[str]  # upper-case names of the local variables it takes REF()/ADR() of (or of a part of)
    in_out_args: tuple[ir.Var, ...]  # what its function and method calls pass to a VAR_IN_OUT
    fb_calls: tuple[ir.FbCall, ...]
    jumps: bool
    returns: bool  # whether it has a RETURN (a statement after it may not run)
    nested_fb_calls: frozenset[int]  # the ids of its FB calls inside another statement (not run on every run)
    paths: tuple[ir.Var, ...]  # the variables it names with a path (``T1.PT``, ``A[i]``), FB calls' instances aside
    whole_fbs: frozenset[str]  # upper-case names of the FB instances it names whole (passed, ADR()), last member's


def mentions(pou: ir.Pou) -> Mentions:
    """One walk over the POU's statements and their expressions (plain recursion, as ``calls_in``)."""
    walked = Walk()
    for block in pou.blocks:
        walked.statements(block.statements)
    return Mentions(
        pou,
        frozenset(walked.addressed),
        tuple(walked.in_outs),
        tuple(walked.fb_calls),
        walked.jumps,
        walked.returns,
        frozenset(walked.nested_fb_calls),
        tuple(walked.paths),
        frozenset(walked.whole_fbs),
    )


class Walk:
    """What ``mentions`` collects, from any statements (a task's body too)."""

    def __init__(self) -> None:
        self.addressed: set[str] = set()
        self.in_outs: list[ir.Var] = []
        self.fb_calls: list[ir.FbCall] = []
        self.jumps = False
        self.returns = False
        self.paths: list[ir.Var] = []
        self.whole_fbs: set[str] = set()
        self.nested_fb_calls: set[int] = set()  # ids of the FB calls inside another statement (IF, loop...)
        self._depth = 0

    def statements(self, statements: list[ir.Stmt]) -> None:
        for s in statements:
            if type(s) is ir.Probe:  # (most statements of a diagram: a probe of a power flow's temporary)
                if type(s.value) is ir.Var and not s.value.path:
                    continue
            elif type(s) is ir.FbCall:
                self.fb_calls.append(s)
                if self._depth:
                    self.nested_fb_calls.add(id(s))
            elif type(s) is ir.Jump:
                self.jumps = True
            elif type(s) is ir.Return:
                self.returns = True
            for e in own_expressions(s):
                if e is not None:
                    self.expression(e)
            if not isinstance(s, _LEAVES):
                self._depth += 1
                for body in nested(s):
                    self.statements(body)
                self._depth -= 1

    def expression(self, e: ir.Expr) -> None:
        if type(e) is ir.Var:
            if type(e.type) is t.FbInstance:
                self.whole_fbs.add(
                    e.path[-1].name.upper() if e.path and type(e.path[-1]) is ir.Member else e.name.upper()
                )
            if e.path:
                self.paths.append(e)
            for selector in e.path:
                if type(selector) is ir.Index:
                    for index in selector.indices:
                        self.expression(index)
        elif type(e) is ir.Binary:
            self.expression(e.left)
            self.expression(e.right)
        elif type(e) is ir.Call:
            self.in_outs += e.in_outs
            for a in (*e.args, *e.in_outs):
                self.expression(a)
        elif type(e) is ir.Unary or type(e) is ir.Convert or type(e) is ir.Fit:
            self.expression(e.operand)
        elif type(e) is ir.AddressOf:
            if e.var.scope == "local":
                self.addressed.add(e.var.name.upper())
            self.expression(e.var)
        elif type(e) is ir.Attempt or type(e) is ir.View:
            self.expression(e.value)


def addressed_locals(found: Mentions) -> set[str]:
    """The POU's own variables (not its in-outs or externals) that its body takes REF()/ADR() of: a FUNCTION that
    has any gives each call a ``runtime.Frame`` so a reference into it dangles once the call returned (a PROGRAM /
    FUNCTION_BLOCK: when any is a VAR_TEMP, ``addressed_temps``)."""
    if not found.addressed:  # (most POUs: no set of all its slots' names to build)
        return set()
    return set(found.addressed & _own_names(found.pou))


def _own_names(pou: ir.Pou) -> set[str]:
    """The upper-case names of the POU's own variables: neither its in-outs nor its externals."""
    return {s.name.upper() for s in pou.slots if s.var_class not in ("VAR_IN_OUT", "VAR_EXTERNAL")}


def addresses_in_out(found: Mentions) -> bool:
    """Whether the POU's body takes REF()/ADR() of (a part of) its own VAR_IN_OUT: such a reference refers to the
    caller's variable, so a caller passing its own call's variable makes it carry the call's frame."""
    return bool(found.addressed) and any(
        s.var_class == "VAR_IN_OUT" and s.name.upper() in found.addressed for s in found.pou.slots
    )


def passed_in_out(found: Mentions, in_out_pin: Callable[[str, str], bool]) -> set[str]:
    """The POU's own variables (not its in-outs or externals) passed, whole or a part, to a VAR_IN_OUT: of a
    function or method called, or a pin of an FB called for which ``in_out_pin(fb type, pin)`` holds."""

    def root(v: object) -> str | None:
        if not isinstance(v, ir.Var) or v.scope != "local" or any(isinstance(p, ir.Deref) for p in v.path):
            return None
        return v.name.upper()

    passed = {name for v in found.in_out_args if (name := root(v)) is not None}
    for s in found.fb_calls:
        if isinstance(s.instance.type, t.FbInstance):
            fb = s.instance.type.fb
            passed.update(name for pin, v in s.inputs if in_out_pin(fb, pin) and (name := root(v)) is not None)
    return passed & _own_names(found.pou) if passed else passed


def addressed_temps(found: Mentions) -> set[str]:
    """The VAR_TEMP of a PROGRAM / FUNCTION_BLOCK that its body takes REF()/ADR() of: its calls then have a
    ``runtime.Frame``, as a FUNCTION's do, for the VAR_TEMP live only while the call runs."""
    addressed = addressed_locals(found)
    if not addressed:
        return addressed
    return addressed & {s.name.upper() for s in found.pou.slots if s.var_class == "VAR_TEMP"}


def referenced_locals(found: Mentions, by_value: Callable[[str], bool] = lambda fb: False) -> set[str]:
    """The POU's own slots passed whole by reference somewhere in its body (to a VAR_IN_OUT): a FUNCTION boxes
    them in a 1-element list, the fast variant keeps none of them in a local (scope.temp_locals). The inputs of
    an FB call count too, unless ``by_value(fb type)`` says the FB has no VAR_IN_OUT (a standard FB)."""

    def whole_local(v: object) -> bool:
        return isinstance(v, ir.Var) and v.scope == "local" and not v.path

    referenced = {v.name.upper() for v in found.in_out_args if whole_local(v)}
    for s in found.fb_calls:
        if not (
            isinstance(s.instance.type, t.FbInstance) and by_value(s.instance.type.fb)
        ):  # a global FB instance's VAR_IN_OUT pin (boxing an input is harmless)
            referenced.update(v.name.upper() for _, v in s.inputs if whole_local(v))
    return referenced & _own_names(found.pou) if referenced else referenced


def boxed_locals(found: Mentions) -> set[str]:
    """The variables a FUNCTION keeps in a 1-element list, so a reference can name them as ``(list, 0)``: those
    passed whole to a VAR_IN_OUT and those it takes REF()/ADR() of."""
    return referenced_locals(found) | addressed_locals(found)
