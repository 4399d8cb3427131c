"""What a coil, an edge and a box are in ST - shared by the LD and FBD exporters.

Mirrors ir/power.py and ir/diagram_calls.py, so that the exported text lowers to
what the diagram lowers to: a coil writes a function of its power (set/reset
under IF), an edge is an R_TRIG/F_TRIG instance declared in the POU (a
FUNCTION has no instances: there it is a BOOL memory, as the IR keeps it), a box
is the call the diagram lowering checks with EN written as an IF: a standard
function that has an operator (ST-04: ADD ``+`` ... NE ``<>``, NOT, MOVE) is that
operator, anything else the formal call (``inst(IN := ..., Q => y)``,
``y := LIMIT(MN := 0, IN := x, MX := 9)``), and a call whose ENO is read keeps
the formal call (``ENO => flag``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ...iec import stdlib
from ...ir.diagram_calls import Callee
from ...st import ast
from ...st.parser import parse_expression
from ...st.printer import print_expression
from ...st.symbols import CheckResult, PouInfo
from .network import TRUE, Declarations, NetworkCode, Use, Value, root_name

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


def box_instance(callee: Callee, written: str | None) -> Any:
    """The instance a box's call runs (None for a function): an FB's as written; a program's is the program itself
    (its one instance, ``PRGexample2(in_var := a)``)."""
    if not callee.is_fb:
        return None
    return ast.Name(callee.name) if callee.is_program else operand(written)


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


#: Standard functions written as ST operators (ST-04), with the extensible ones applied left to right
#: (``ADD(a, b, c)`` = ``a + b + c``). A comparison of more than two inputs stays a call (``GT(a, b, c)`` would be
#: ``a > b AND b > c``, reading ``b`` twice).
OPERATORS = {
    "ADD": "+",
    "SUB": "-",
    "MUL": "*",
    "DIV": "/",
    "MOD": "MOD",
    "EXPT": "**",
    "AND": "AND",
    "OR": "OR",
    "XOR": "XOR",
    "GT": ">",
    "GE": ">=",
    "EQ": "=",
    "LE": "<=",
    "LT": "<",
    "NE": "<>",
}
_EXTENSIBLE = {"ADD", "MUL", "AND", "OR", "XOR"}


def operator_form(name: str, operands: list[Any]) -> Any:
    """The operator expression of standard function ``name`` on ``operands`` (in pin order), or None when it has
    none: NOT is its operator (``NOT(IN := x)`` does not even parse: the keyword), MOVE is its input."""
    if name == "NOT" and len(operands) == 1:
        return ast.Unary("NOT", operands[0])
    if name == "MOVE" and len(operands) == 1:
        return operands[0]
    if name not in OPERATORS or len(operands) < 2 or (len(operands) > 2 and name not in _EXTENSIBLE):
        return None
    result = operands[0]
    for operand_ in operands[1:]:
        result = ast.Binary(OPERATORS[name], result, operand_)
    return result


def function_call(callee: Callee, inputs: dict[str, Any]) -> Any:
    """A function box's call without ENO: the operator where ST has one (``n + 1``), else the formal call."""
    if callee.std_function is not None:
        found = operator_form(callee.name, [inputs[pin] for pin in sorted(inputs, key=callee.rank)])
        if found is not None:
            return found
    return ast.Call(ast.Name(callee.name), formal_args(callee, inputs))


def owner(callee: Callee, instance: Any) -> str:
    """What a box is called in names made from it: its instance (``TON1``), else its function (``ADD``)."""
    return text_of(instance) if instance is not None else callee.name


def text_of(expr: Any) -> str:
    """An operand as the user wrote it, for names made from it (``Motor``, ``T1.Q``, ``a[1]``)."""
    return print_expression(expr)


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
        """The rising/falling edge of ``clock`` at this position, with its memory updated (ir/power.py edge).

        ``hint`` names what is watched (``Start``: the trigger is ``Start_rising``, a FUNCTION's memory
        ``Start_mem``)."""
        if not self.is_function:
            trigger = self.declarations.declare(
                f"{hint}_{'rising' if rising else 'falling'}", "R_TRIG" if rising else "F_TRIG", "VAR"
            )
            call = ast.Call(ast.Name(trigger), [ast.Arg("CLK", clock)])
            code.step([ast.CallStmt(call)], element, frozenset({trigger.upper()}))
            return code.value(ast.Member(ast.Name(trigger), "Q"), element, f"{trigger}_Q")
        memory = self.declarations.declare(f"{hint}_mem", "BOOL", "VAR")
        value = code.value(_edge(rising, clock, ast.Name(memory)), element, f"{hint}_edge", pinned=True)
        code.step([ast.Assign(ast.Name(memory), clock)], element, frozenset({memory.upper()}))
        return value

    # ------------------------------------------------------------ coils
    def coil(
        self,
        code: NetworkCode,
        mode: str,
        target: Any,
        power: Any,
        element: str,
        guard: Any = None,
        target_type: str | None = None,
    ) -> None:
        """An LD coil / FBD output node in ``mode`` writing ``target`` from ``power`` (ir/power.py coil); with
        ``guard`` (an FBD output fed by a block with EN) all of it, edge memory included, runs only when it holds.
        A plain write of a variable of ``target_type`` may carry its value to later readers (network.Step)."""
        writes = {root_name(target)}
        carries = None
        if mode == "normal" and (guard is None or guard == TRUE) and isinstance(power, Use) and readable(target):
            carries = (power.value, target, target_type)
        if mode == "normal":
            statements = [ast.Assign(target, power)]
        elif mode == "negated":
            statements = [ast.Assign(target, ast.Unary("NOT", power))]
        elif mode in ("set", "reset"):
            write = ast.Assign(target, TRUE if mode == "set" else FALSE)
            statements = [write] if power == TRUE else [ast.If([(power, [write])])]
        elif not self.is_function:
            trigger = self.declarations.declare(f"{text_of(target)}_trig", "R_TRIG" if mode == "p" else "F_TRIG", "VAR")
            statements = [
                ast.CallStmt(ast.Call(ast.Name(trigger), [ast.Arg("CLK", power)])),
                ast.Assign(target, ast.Member(ast.Name(trigger), "Q")),
            ]
            writes.add(trigger.upper())
        else:
            memory = self.declarations.declare(f"{text_of(target)}_mem", "BOOL", "VAR")
            statements = [
                ast.Assign(target, _edge(mode == "p", power, ast.Name(memory))),
                ast.Assign(ast.Name(memory), power),
            ]
            writes.add(memory.upper())
        if guard is not None and guard != TRUE:
            statements = [ast.If([(guard, statements)])]
        code.step(statements, element, frozenset(w for w in writes if w is not None), carries=carries)

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
        differ from EN (a standard function's warning, ``eno_hint`` set), else None: then ENO is EN. Only that
        call, whose ENO is read, is the formal call with ``ENO =>``; otherwise an operator where ST has one.
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
            code.step(_guard(en, _result(target, _called(callee, inputs, args, target))), element, writes)
            return None
        eno = self.declarations.names.fresh(f"{eno_hint}_ENO")  # declared only when something reads it
        flagged = _result(target, ast.Call(name, [*args, ast.Arg("ENO", ast.Name(eno), output=True)]))
        full = flagged if en == TRUE else [ast.If([(en, flagged)], [ast.Assign(ast.Name(eno), FALSE)])]
        eno_value = Value(ast.Name(eno), element, eno)
        code.step(
            full,
            element,
            writes | {eno.upper()} if writes is not None else None,
            optional=eno_value,
            without=_guard(en, _result(target, _called(callee, inputs, args, target))),
            declare=(eno, "BOOL", "VAR_TEMP"),
        )
        code.ops.append(eno_value)
        return eno_value


def readable(target: Any) -> bool:
    """A target that reads back exactly what was written to it: a variable or a field of one."""
    while isinstance(target, ast.Member):
        target = target.base
    return isinstance(target, ast.Name)


def _edge(rising: bool, clock: Any, memory: ast.Name) -> Any:
    """``clock AND NOT m`` (rising) / ``m AND NOT clock`` (falling): ir/power.py's edge on a BOOL memory."""
    return (
        ast.Binary("AND", clock, ast.Unary("NOT", memory))
        if rising
        else ast.Binary("AND", memory, ast.Unary("NOT", clock))
    )


def _guard(en: Any, body: list[Any]) -> list[Any]:
    return body if en is None or en == TRUE or not body else [ast.If([(en, body)])]


def _called(callee: Callee, inputs: dict[str, Any], args: list[ast.Arg], target: Any) -> Any:
    """A function's result as an operator where it is assigned; a result nobody takes stays a call statement (an
    expression is no statement, and a discarded ``a / b`` must still fault where the diagram faults)."""
    if target is not None or callee.name == "NOT":
        return function_call(callee, inputs)
    return ast.Call(ast.Name(callee.name), args)


def _result(target: Any, call: Any) -> list[Any]:
    """``target := call``, or the call alone when its result is not used (nothing for NOT: no call to make)."""
    if target is not None:
        return [ast.Assign(target, call)]
    return [ast.CallStmt(call)] if isinstance(call, ast.Call) else []
