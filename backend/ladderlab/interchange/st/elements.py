"""What a coil, an edge and a box are in ST - shared by the LD and FBD exporters.

Mirrors ir/power.py and ir/diagram_calls.py, so that the exported text lowers to
what the diagram lowers to: a coil writes a function of its power (set/reset
under IF), an edge is an R_TRIG/F_TRIG instance declared in the POU (a
FUNCTION has no instances: there it is a BOOL memory, as the IR keeps it), a box
is the formal call the diagram lowering checks (``inst(IN := ..., Q => y)``,
``y := ADD(IN1 := ..., IN2 := ...)``) with EN written as an IF.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ...iec import stdlib
from ...ir.diagram_calls import Callee
from ...st import ast
from ...st.parser import parse_expression
from ...st.symbols import CheckResult, PouInfo
from .network import TRUE, Declarations, NetworkCode, Value, root_name

FALSE = ast.BoolLit(False)


@lru_cache(maxsize=8192)
def _parsed(text: str) -> Any:
    parsed = parse_expression(text)
    return parsed.ast if parsed.ok else None


def operand(text: str) -> Any:
    """The AST of an operand text the diagram lowering accepted (so it parses)."""
    node = _parsed(text.strip())
    if node is None:  # the lowering accepted it, so the parser does too
        raise ValueError(f"operand '{text}' does not parse")
    return node


def callee_of(checked: CheckResult, call: str) -> Callee:
    """The user POU, standard function or standard FB a box calls (the lowering already resolved it)."""
    name = call.strip()
    pou = checked.pou(name)
    if pou is not None:
        return Callee(pou.name, pou=pou)
    if stdlib.function(name) is not None:
        return Callee(name.upper(), std_function=stdlib.function(name))
    return Callee(name.upper(), std_fb=stdlib.function_block(name))


def spelled(callee: Callee, pin: str) -> str:
    """A pin as its POU declares it (``Enable``), a standard pin as the catalogue has it (``IN``)."""
    symbol = callee.pou.symbols.get(pin) if callee.pou is not None else None
    return symbol.name if symbol is not None else pin


def formal_args(callee: Callee, inputs: dict[str, Any]) -> list[ast.Arg]:
    """``PIN := value`` for upper-case ``inputs``, in the order the box draws its pins (the lowering's order)."""
    return [ast.Arg(spelled(callee, pin), inputs[pin]) for pin in sorted(inputs, key=callee.rank)]


def function_call(callee: Callee, inputs: dict[str, Any]) -> Any:
    """A function box's call: the formal call, except NOT, which ST has only as the operator (``NOT(IN := x)``
    does not parse) and which never warns."""
    if callee.std_function is not None and callee.name == "NOT":
        return ast.Unary("NOT", next(iter(inputs.values())))
    return ast.Call(ast.Name(callee.name), formal_args(callee, inputs))


def output_pin(callee: Callee, instance: Any, pin: str) -> ast.Member:
    return ast.Member(instance, spelled(callee, pin))


@dataclass
class PouScope:
    """What the element exporters of one POU share: the checked project, the POU, and its new variables."""

    checked: CheckResult
    info: PouInfo
    declarations: Declarations

    @property
    def is_function(self) -> bool:
        return self.info.kind == "FUNCTION"

    # ------------------------------------------------------------ edges
    def edge(self, code: NetworkCode, rising: bool, clock: Any, element: str, hint: str) -> Value:
        """The rising/falling edge of ``clock`` at this position, with its memory updated (ir/power.py edge)."""
        if not self.is_function:
            trigger = self.declarations.declare(f"{hint}_trig", "R_TRIG" if rising else "F_TRIG", "VAR")
            call = ast.Call(ast.Name(trigger), [ast.Arg("CLK", clock)])
            code.step([ast.CallStmt(call)], element, frozenset({trigger.upper()}))
            return code.value(ast.Member(ast.Name(trigger), "Q"), element, hint)
        memory = self.declarations.declare(f"{hint}_mem", "BOOL", "VAR")
        value = code.value(_edge(rising, clock, ast.Name(memory)), element, hint, pinned=True)
        code.step([ast.Assign(ast.Name(memory), clock)], element, frozenset({memory.upper()}))
        return value

    # ------------------------------------------------------------ coils
    def coil(self, code: NetworkCode, mode: str, target: Any, power: Any, element: str, guard: Any = None) -> None:
        """An LD coil / FBD output node in ``mode`` writing ``target`` from ``power`` (ir/power.py coil); with
        ``guard`` (an FBD output fed by a block with EN) all of it, edge memory included, runs only when it holds."""
        writes = {root_name(target)}
        if mode == "normal":
            statements = [ast.Assign(target, power)]
        elif mode == "negated":
            statements = [ast.Assign(target, ast.Unary("NOT", power))]
        elif mode in ("set", "reset"):
            write = ast.Assign(target, TRUE if mode == "set" else FALSE)
            statements = [write] if power == TRUE else [ast.If([(power, [write])])]
        elif not self.is_function:
            trigger = self.declarations.declare(f"{element}_trig", "R_TRIG" if mode == "p" else "F_TRIG", "VAR")
            statements = [
                ast.CallStmt(ast.Call(ast.Name(trigger), [ast.Arg("CLK", power)])),
                ast.Assign(target, ast.Member(ast.Name(trigger), "Q")),
            ]
            writes.add(trigger.upper())
        else:
            memory = self.declarations.declare(f"{element}_mem", "BOOL", "VAR")
            statements = [
                ast.Assign(target, _edge(mode == "p", power, ast.Name(memory))),
                ast.Assign(ast.Name(memory), power),
            ]
            writes.add(memory.upper())
        if guard is not None and guard != TRUE:
            statements = [ast.If([(guard, statements)])]
        code.step(statements, element, frozenset(w for w in writes if w is not None))

    # ------------------------------------------------------------ calls
    def call_writes(self, callee: Callee, instance: Any, targets: list[Any]) -> frozenset[str] | None:
        """What a box call may write: a user POU anything (globals), else its instance and output variables."""
        if callee.pou is not None:
            return None
        names = [root_name(t) for t in targets] + ([root_name(instance)] if instance is not None else [])
        return frozenset(n for n in names if n is not None)

    def call(
        self,
        code: NetworkCode,
        callee: Callee,
        instance: Any,
        inputs: dict[str, Any],
        outputs: dict[str, Any],
        en: Any,
        element: str,
        target: Any = None,
        eno_hint: str | None = None,
    ) -> Value | None:
        """Emit a box: ``inputs``/``outputs`` by upper-case pin, ``en`` the EN value or None (no EN).

        A function's result goes to ``target`` (None: discarded). Returns the box's ENO as a value when it can
        differ from EN (a standard function's warning, ``eno_hint`` set), else None: then ENO is EN.
        """
        args = formal_args(callee, inputs)
        args += [ast.Arg(spelled(callee, pin), value, output=True) for pin, value in outputs.items()]
        name = instance if instance is not None else ast.Name(callee.name)
        writes = self.call_writes(callee, instance, [*outputs.values(), *([target] if target is not None else [])])
        if callee.is_fb:
            body = [ast.CallStmt(ast.Call(name, args))]
            code.step(_guard(en, body), element, writes)
            return None
        if en is None or callee.pou is not None or eno_hint is None or callee.name == "NOT":
            code.step(_guard(en, _result(target, function_call(callee, inputs))), element, writes)
            return None
        eno = self.declarations.names.fresh(f"{eno_hint}_ENO")
        flagged = _result(target, ast.Call(name, [*args, ast.Arg("ENO", ast.Name(eno), output=True)]))
        full = flagged if en == TRUE else [ast.If([(en, flagged)], [ast.Assign(ast.Name(eno), FALSE)])]
        eno_value = Value(ast.Name(eno), element, eno)
        code.step(
            full,
            element,
            writes | {eno.upper()} if writes is not None else None,
            optional=eno_value,
            without=_guard(en, _result(target, ast.Call(name, args))),
            declare=(eno, "BOOL", "VAR_TEMP"),
        )
        code.ops.append(eno_value)
        return eno_value


def _edge(rising: bool, clock: Any, memory: ast.Name) -> Any:
    """``clock AND NOT m`` (rising) / ``m AND NOT clock`` (falling): ir/power.py's edge on a BOOL memory."""
    return (
        ast.Binary("AND", clock, ast.Unary("NOT", memory))
        if rising
        else ast.Binary("AND", memory, ast.Unary("NOT", clock))
    )


def _guard(en: Any, body: list[Any]) -> list[Any]:
    return body if en is None or en == TRUE or not body else [ast.If([(en, body)])]


def _result(target: Any, call: Any) -> list[Any]:
    """``target := call``, or the call alone when its result is not used (nothing for NOT: no call to make)."""
    if target is not None:
        return [ast.Assign(target, call)]
    return [ast.CallStmt(call)] if isinstance(call, ast.Call) else []
