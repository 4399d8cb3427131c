"""From one expression per specialisation to the fast callable, the checked callable and an inline template.

Each standard function, given concrete argument and result types, describes
itself as an ``Impl``: a Python expression over the positional parameters
``a0..a{n-1}`` computing the exact result, plus the type it is stored into.
From that one description this module derives

* the fast callable: ``lambda a0, a1: <store(exact)>`` compiled once, positional
  only, no allocation beyond what the operation itself needs;
* the checked callable, returning ``(value, None | PlcWarning)``: the same
  computation, comparing the exact and the stored value to detect overflow
  (FUN-90), non-finite REAL results (FUN-20, FUN-31) or string truncation
  (FUN-83);
* an inline template (``str.format`` placeholders ``{0}``..) when the
  expression evaluates every argument exactly once and unconditionally, so the
  code generator can paste it instead of a call.
"""

from __future__ import annotations

import ast
import builtins
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from ...iec.values import INLINE_NAMES, resolve, store_expr
from ..errors import DOMAIN, INVALID_ARGUMENT, OVERFLOW, TRUNCATED, PlcWarning

#: Globals available to every Impl expression and inline template (module helpers register here).
HELPERS: dict[str, object] = dict(INLINE_NAMES)

Precheck = Callable[..., "PlcWarning | None"]


@dataclass(frozen=True)
class Impl:
    """A standard function specialised for concrete types.

    ``exact``: expression over a0..; the value before storing (for integers the
    true mathematical result, so the checked form can tell it wrapped).
    ``result``: the type the value is stored into; None when no store is needed
    (comparisons, selection, bitwise logic: the value is already in range).
    ``store``: replaces ``values.store_expr`` for this result, with ``{x}``.
    ``names``: extra per-specialisation globals; their presence disables inlining.
    ``precheck``: run first by the checked form; a warning it returns wins.
    ``guard``: the plain call's check of the exact value, which raises (a fault) where the checked form (ENO) warns
    and returns it otherwise: a result no wrap may stand in for (a duration or a date outside its type).
    """

    exact: str
    result: str | None = None
    store: str | None = None
    names: Mapping[str, object] = field(default_factory=dict)
    precheck: Precheck | None = None
    guard: Callable[[Any], Any] | None = None

    def body(self) -> str:
        if self.result is None:
            return self.exact
        if self.store is not None:
            return self.store.format(x=self.exact)
        return store_expr(self.exact, self.result)


def params(arity: int) -> list[str]:
    return [f"a{i}" for i in range(arity)]


def compile_expr(expr: str, arity: int, names: Mapping[str, object] = {}) -> Callable:
    """``lambda a0, .., a{arity-1}: expr`` with the helpers as globals."""
    return eval(f"lambda {', '.join(params(arity))}: {expr}", {**HELPERS, **names})


@dataclass(frozen=True)
class Specialised:
    fast: Callable
    checked: Callable
    template: str | None
    #: The checked form inline, when its only warning is a wrap (an integer, bit string or time result): templates
    #: of the exact value over ``{0}``.. and of its store over ``{0}``; ENO is "the store kept the value".
    wrapped: tuple[str, str] | None = None


def specialise(name: str, impl: Impl, arity: int) -> Specialised:
    body = impl.body()
    fast = compile_expr(body, arity, impl.names)
    template = None if impl.names else inline_template(body, arity)
    checked = _checked(name, impl, arity, fast)
    if impl.guard is not None:
        fast, template = _guarded(impl, arity), None
    return Specialised(fast, checked, template, _wrapped_templates(impl, arity))


def _guarded(impl: Impl, arity: int) -> Callable:
    """The plain call of an Impl with a guard: the exact value checked by it, then stored."""
    exact, store, guard = compile_expr(impl.exact, arity, impl.names), compile_expr(_store_of(impl), 1), impl.guard
    return lambda *args: store(guard(exact(*args)))  # type: ignore[misc]  # guard is set (specialise)


def _wrapped_templates(impl: Impl, arity: int) -> tuple[str, str] | None:
    if impl.names or impl.precheck is not None or impl.result is None:
        return None
    if _PROBLEMS.get(resolve(impl.result).category) is not _wrapped:
        return None
    exact, store = inline_template(impl.exact, arity), inline_template(_store_of(impl), 1)
    return (exact, store) if exact is not None and store is not None else None


def _checked(name: str, impl: Impl, arity: int, fast: Callable) -> Callable:
    precheck = impl.precheck
    problem = _PROBLEMS.get(resolve(impl.result).category) if impl.result else None
    if problem is not None:
        exact = compile_expr(impl.exact, arity, impl.names)
        store = compile_expr(_store_of(impl), 1)

    def checked(*args):
        if precheck is not None:
            warning = precheck(*args)
            if warning is not None:
                return fast(*args), warning
        if problem is None:
            return fast(*args), None
        value = exact(*args)
        stored = store(value)
        return stored, problem(name, args, value, stored, impl.result)

    return checked


def _store_of(impl: Impl) -> str:
    """The store step alone, as an expression over ``a0``."""
    return Impl("a0", impl.result, impl.store).body()


def _wrapped(name, args, value, stored, result):
    if value == stored:
        return None
    return PlcWarning(OVERFLOW, f"{call_text(name, args)} = {value} does not fit {result}; result {stored}")


def _non_finite(name, args, value, stored, result):
    if stored - stored == 0 or not all(_finite(a) for a in args):
        return None
    code = DOMAIN if stored != stored else OVERFLOW  # NaN: no result exists; ±inf: beyond any finite value
    return PlcWarning(code, f"{call_text(name, args)} gives {stored} ({result})")


def _truncated(name, args, value, stored, result):
    if len(value) == len(stored):
        return None
    return PlcWarning(TRUNCATED, f"{call_text(name, args)} has {len(value)} characters; cut to {len(stored)}")


_PROBLEMS = {
    "int": _wrapped,
    "bits": _wrapped,
    "time": _wrapped,
    "date": _wrapped,
    "dt": _wrapped,
    "real": _non_finite,
    "string": _truncated,
}


def _finite(value: object) -> bool:
    return not isinstance(value, float) or math.isfinite(value)


def finite_args(name: str) -> Precheck:
    """Precheck for functions that turn REAL arguments into integers: NaN and ±inf are invalid."""

    def precheck(*args):
        if all(_finite(a) for a in args):
            return None
        return PlcWarning(INVALID_ARGUMENT, f"{call_text(name, args)}: argument is not a finite number")

    return precheck


def call_text(name: str, args: tuple) -> str:
    return f"{name}({', '.join(map(repr, args))})"


_UNSAFE = (ast.IfExp, ast.BoolOp, ast.Lambda, ast.NamedExpr, ast.comprehension)


#: Globals of each generated module a template may name besides the helpers: ``ll_now``, the clock at the start of
#: the running scan (CODESYS ``TIME()``). A standalone callable has none of them: such a function is always inlined.
MODULE_NAMES = frozenset({"ll_now"})


@cache
def inline_template(body: str, arity: int) -> str | None:
    """``body`` with parameter i replaced by ``({i})``, or None when inlining could change what is evaluated."""
    tree = ast.parse(body, mode="eval")
    found: list[tuple[int, int]] = []  # (column, parameter index)
    for node in ast.walk(tree):
        if isinstance(node, _UNSAFE) or (isinstance(node, ast.Compare) and len(node.ops) > 1):
            return None
        if isinstance(node, ast.Name):
            if _is_param(node.id):
                found.append((node.col_offset, int(node.id[1:])))
            elif node.id not in HELPERS and node.id not in MODULE_NAMES and not hasattr(builtins, node.id):
                return None
    # each input exactly once, and in the IEC left-to-right order
    if [index for _, index in sorted(found)] != list(range(arity)):
        return None

    class Placeholders(ast.NodeTransformer):
        def visit_Name(self, node: ast.Name) -> ast.AST:
            if _is_param(node.id):
                return ast.Name(id=f"__ARG{node.id[1:]}__", ctx=node.ctx)
            return node

    text = ast.unparse(Placeholders().visit(tree)).replace("{", "{{").replace("}", "}}")
    for i in range(arity):
        text = text.replace(f"__ARG{i}__", f"({{{i}}})")
    return text


def _is_param(name: str) -> bool:
    return name[0] == "a" and name[1:].isdigit()
