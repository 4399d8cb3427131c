"""Checking an IL body and turning it into typed ST statements (docs/il.md).

Each IL instruction becomes one ST statement with the instruction's span, so
breakpoints, pause points and runtime errors stay per IL line. The current result
(CR, the accumulator) lives in hidden variables, one per type and nesting depth of
``(`` (``__CR_INT``, ``__CR1_BOOL``): its type follows the last load or operation
(IL-05, IL-25), checked here, so a type error names the accumulator's type. An
untyped literal (``LD 17``) stays a constant until an operation gives it a type, as
it would in the equivalent ST expression. Labels and jumps become ``ast.Label`` and
``ast.Goto``, which the IR lowering turns into labelled blocks and jumps.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field

from ..iec import stdlib
from ..iec.spelling import did_you_mean
from . import ast
from . import types as t
from .body import BodyChecker, Report
from .il_parser import IlBody, IlInstruction
from .il_words import FB_INPUT_OPERATORS, OPERATORS
from .methods import action_inputs
from .symbols import CheckResult, PouInfo, Symbol
from .types import ERROR, Type

ACCUMULATOR_PREFIX = "__CR"

_OPERAND_COUNT = {0: "no operand", 1: "one operand"}
_LOGIC = {"AND": "AND", "&": "AND", "OR": "OR", "XOR": "XOR"}
_ARITHMETIC = {"ADD": "+", "SUB": "-", "MUL": "*", "DIV": "/", "MOD": "MOD"}
_COMPARE = {"GT": ">", "GE": ">=", "EQ": "=", "NE": "<>", "LE": "<=", "LT": "<"}


@dataclass(eq=False)
class Cr:
    """The accumulator's state: a hidden variable (``name``) or a constant (``const``) of ``type``."""

    type: Type
    name: str | None = None
    const: ast.Expr | None = None
    read: bool = False


@dataclass(eq=False)
class Conflict:
    """The accumulator at a label that paths reach with different types (IL-25)."""

    types: list[Type]
    label: str


@dataclass
class _Frame:
    instruction: IlInstruction
    saved: Cr | None


@dataclass
class IlValue:
    """The accumulator after the instruction on ``line`` (body-relative): ``value`` (an accumulator variable or a
    constant, typed ``type``) as it stands before ``statements[index]`` - online mode shows it on the line."""

    line: int
    index: int
    value: ast.Expr
    type: Type


#: Where a single step stops in IL (ON-04): the next load, jump or call (an FB input operator calls too).
STEP_OPERATORS = frozenset({"LD", "LDN", "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN"}) | FB_INPUT_OPERATORS


@dataclass
class IlResult:
    statements: list[ast.Stmt]
    accumulators: list[Symbol] = field(default_factory=list)
    result_assigned: bool = False
    values: list[IlValue] = field(default_factory=list)
    step_lines: frozenset[int] = frozenset()
    #: the accumulator after the last instruction, when the end is reached with one typed value (an IL transition's
    #: value, as in CODESYS); None: no value (an empty body, a jump or RET last, a type error, types that differ)
    end: IlValue | None = None


class _AccumulatorChecker(BodyChecker):
    """A body checker that also knows the hidden accumulator variables."""

    def __init__(self, result: CheckResult, pou: PouInfo | None, report: Report, accumulators: dict[str, Symbol]):
        super().__init__(result, pou, report)
        self.accumulators = accumulators

    def lookup(self, name: str) -> Symbol | None:
        found = self.accumulators.get(name.upper())
        return found if found is not None else super().lookup(name)


def check_il_body(result: CheckResult, info: PouInfo, body: IlBody, report: Report) -> IlResult:
    return _Translator(result, info, report).run(body)


class _Translator:
    def __init__(self, result: CheckResult, info: PouInfo, report: Report):
        self.info = info
        self.report = report
        self.accumulators: dict[str, Symbol] = {}
        self.checker = _AccumulatorChecker(result, info, report, self.accumulators)
        self.silent = _AccumulatorChecker(result, info, lambda *args, **kwargs: None, self.accumulators)
        self.out: list[ast.Stmt] = []
        self.cr: Cr | Conflict | None = None
        self.reachable = True
        self.stack: list[_Frame] = []
        self.labels: dict[str, tuple[Cr | Conflict | None, ast.Span]] = {}
        self.forward: dict[str, list[Cr | None]] = {}
        self.jumps: list[tuple[str, Cr | None, IlInstruction]] = []
        self.values: list[IlValue] = []
        self.step_lines: set[int] = set()

    # ------------------------------------------------------------ driver
    def run(self, body: IlBody) -> IlResult:
        for instruction in body.instructions:
            for label, span in instruction.labels:
                self._label(label, span)
            start = len(self.out)
            self.instruction(instruction)
            self._record(instruction, start)
        for label, span in body.trailing_labels:
            self._label(label, span)
        if self.stack:
            opened = self.stack[-1].instruction
            self.report("IL-PAREN", f"'{opened.written}(' is never closed with ')'", opened)
        for label, state, instruction in self.jumps:
            if label.upper() not in self.labels:
                known = [name for name, _ in self.labels.items()]
                self.report(
                    "IL-LABEL",
                    f"there is no label '{label}' in {self.info.name}" + did_you_mean(label, known),
                    instruction,
                )
            else:
                self._check_back_edge(label, state, instruction)
        symbols = list(self.accumulators.values())
        result = IlResult(self.out, symbols, self.checker.result_assigned, self.values, frozenset(self.step_lines))
        cr = self.cr
        if self.reachable and isinstance(cr, Cr) and cr.type is not ERROR and body.instructions:
            span = body.instructions[-1].span
            value = self._value(cr, span)
            ty = self.silent.expr(value)  # typed like every statement the lowering reads
            if ty is not ERROR:
                result.end = IlValue(span.line, len(self.out), value, t.concrete(ty))
        return result

    def _record(self, instruction: IlInstruction, start: int) -> None:
        """The accumulator after ``instruction`` for online mode, and whether a single step stops at its line.
        A jump's or return's value stands before the jump (the CR is what it was; after it nothing runs)."""
        line = instruction.span.line
        word = instruction.operator
        if word in STEP_OPERATORS or (word == "R" and self._is_instance(instruction)):
            self.step_lines.add(line)
        cr = self.cr
        if not isinstance(cr, Cr) or cr.type is ERROR or instruction.broken:
            return
        index = len(self.out)
        if index > start and isinstance(self.out[-1], (ast.Goto, ast.Return)):
            index -= 1
        value = self._value(cr, instruction.span)
        ty = self.silent.expr(value)  # typed like every statement the lowering reads
        if ty is not ERROR:
            self.values.append(IlValue(line, index, value, t.concrete(ty)))

    def instruction(self, instruction: IlInstruction) -> None:
        word = instruction.operator
        handler = _HANDLERS.get(word)
        if instruction.broken:  # reported by the parser: the CR is unknown until the next load
            self.cr = Cr(ERROR, const=ast.BoolLit(False))
            if instruction.deferred:
                self.stack.append(_Frame(instruction, self.cr))
        elif instruction.deferred:
            self._open(instruction)
        elif word == ")":
            self._close(instruction)
        elif word in FB_INPUT_OPERATORS or (word == "R" and self._is_instance(instruction)):
            self._fb_input(instruction)
        elif handler is not None:
            handler(self, instruction)
        elif word in _LOGIC or (word.rstrip("N") in _LOGIC and word.endswith("N")):
            self._logic(instruction)
        elif word in _ARITHMETIC or word in _COMPARE:
            self._operate(instruction, self._operand(instruction))
        else:
            self._function(instruction)

    # ------------------------------------------------------------ the accumulator
    def _read(self, instruction: IlInstruction) -> Cr | None:
        cr = self.cr
        if isinstance(cr, Conflict):
            types = " and ".join(str(ty) for ty in cr.types)
            self.report(
                "IL-CR-TYPE",
                f"{instruction.written} reads the accumulator, but at label {cr.label} it is {types} on different "
                "paths: load a value (LD) after the label",
                instruction,
            )
            self.cr = Cr(ERROR, const=ast.BoolLit(False))
            return None
        if cr is None:
            where = " inside '('" if self.stack else ""
            self.report(
                "IL-NO-CR",
                f"{instruction.written} needs a value in the accumulator{where}: load one first (LD)",
                instruction,
            )
            return None
        cr.read = True
        return None if cr.type is ERROR else cr  # after an error (already reported) the CR is unknown

    def _value(self, cr: Cr, span: ast.Span) -> ast.Expr:
        if cr.const is not None:
            return copy.deepcopy(cr.const)
        return ast.Name(cr.name or "", span)

    def _set(self, value: ast.Expr, ty: Type, instruction: IlInstruction | _At) -> None:
        """``CR := value``: a constant stays one; anything else is stored in the accumulator of its type."""
        if ty is ERROR:
            self.cr = Cr(ERROR, const=value)
            return
        if isinstance(ty, (t.UntypedInt, t.UntypedReal)) and _constant(value):
            self.cr = Cr(ty, const=value)
            return
        concrete = t.concrete(ty)
        target = self._accumulator(concrete, instruction)
        if target is None:
            self.cr = Cr(ERROR, const=value)
            return
        self._emit(ast.Assign(ast.Name(target.name, instruction.span), value, instruction.span))
        self.cr = Cr(concrete, name=target.name)

    def _materialise(self, instruction: IlInstruction | _At) -> None:
        """Before a jump or label: a constant CR goes into its accumulator, so every path agrees on where it is."""
        cr = self.cr
        if isinstance(cr, Cr) and cr.const is not None and cr.type is not ERROR:
            self._set(cr.const, t.concrete(cr.type), instruction)

    def _accumulator(self, ty: Type, instruction: IlInstruction | _At) -> Symbol | None:
        if isinstance(ty, (t.FbType, t.ArrayType)):
            self.report(
                "IL-CR-TYPE", f"the accumulator cannot hold {ty}: load an elementary or user-typed value", instruction
            )
            return None
        depth = str(len(self.stack)) if self.stack else ""
        name = f"{ACCUMULATOR_PREFIX}{depth}_" + "".join(c if c.isalnum() else "_" for c in str(ty).upper())
        symbol = self.accumulators.get(name)
        if symbol is None:
            spec = ast.NamedType(str(ty))
            if isinstance(ty, t.StringType) and ty.length is not None:
                spec = ast.SizedType(ty.name, ast.IntLit(ty.length))
            symbol = Symbol(name, "VAR", ty, spec, pou=self.info.name)
            self.accumulators[name] = symbol
        return symbol

    def _emit(self, statement: ast.Stmt) -> None:
        self.checker.statement(statement)
        self.out.append(statement)

    # ------------------------------------------------------------ operands
    def _operand(self, instruction: IlInstruction, count: int = 1) -> ast.Expr | None:
        if len(instruction.operands) != count or instruction.call is not None:
            self.report(
                "IL-OPERAND",
                f"{instruction.written} takes {_OPERAND_COUNT[count]}"
                + (f", not {len(instruction.operands)}" if instruction.operands else ""),
                instruction,
            )
            return None
        return instruction.operands[0]

    def _type(self, node: ast.Expr) -> Type:
        """The operand's type, reporting its problems (unknown variable ...) once."""
        return self.checker.expr(node)

    def _label_operand(self, instruction: IlInstruction) -> str | None:
        operand = self._operand(instruction)
        if operand is None:
            return None
        if not isinstance(operand, ast.Name):
            self.report("IL-LABEL", f"{instruction.written} needs a label name", instruction)
            return None
        return operand.name

    def _is_instance(self, instruction: IlInstruction) -> bool:
        if len(instruction.operands) != 1 or not isinstance(instruction.operands[0], ast.Name):
            return False
        return isinstance(self.silent.expr(copy.deepcopy(instruction.operands[0])), t.FbType)

    # ------------------------------------------------------------ loads and stores (IL-20, IL-22)
    def _load(self, instruction: IlInstruction) -> None:
        operand = self._operand(instruction)
        if operand is None:
            self.cr = Cr(ERROR, const=ast.BoolLit(False))
            return
        ty = self._type(operand)
        if instruction.operator == "LDN":
            if not self._bits(ty, instruction, operand):
                self.cr = Cr(ERROR, const=operand)
                return
            operand = ast.Unary("NOT", operand, instruction.span)
        self._set(operand, ty, instruction)

    def _store(self, instruction: IlInstruction) -> None:
        operand = self._operand(instruction)
        cr = self._read(instruction)
        if operand is None or cr is None:
            return
        target = self.silent.target(copy.deepcopy(operand))
        value = self._value(cr, instruction.span)
        if instruction.operator == "STN":
            if not self._bits(cr.type, instruction, None):
                return
            value = ast.Unary("NOT", value, instruction.span)
        if cr.type is not ERROR and target is not ERROR and t.assignable(target, cr.type) == "error":
            self.report(
                "IL-TYPE",
                f"{instruction.written} {_text(operand)}: the accumulator holds {_describe(cr.type)}, "
                f"{_text(operand)} is {target}",
                instruction,
            )
            return
        self._emit(ast.Assign(operand, value, instruction.span))

    def _set_reset(self, instruction: IlInstruction) -> None:
        operand = self._operand(instruction)
        cr = self._read(instruction)
        if operand is None or cr is None or not self._condition(cr, instruction):
            return
        value = ast.BoolLit(instruction.operator == "S", instruction.span)
        assign = ast.Assign(operand, value, instruction.span)
        self._emit(ast.If([(self._value(cr, instruction.span), [assign])], None, instruction.span))

    # ------------------------------------------------------------ operators (IL-10..IL-13, IL-20..IL-24)
    def _logic(self, instruction: IlInstruction) -> None:
        operand = self._operand(instruction)
        if operand is None:
            return
        if instruction.operator.endswith("N"):
            operand = ast.Unary("NOT", operand, operand.span)
        self._operate(instruction, operand)

    def _operate(self, instruction: IlInstruction, operand: ast.Expr | None, word: str | None = None) -> None:
        """``CR := CR OP operand`` (IL-10); comparisons give a BOOL CR (IL-11)."""
        cr = self._read(instruction)
        if operand is None or cr is None:
            return
        word = word or instruction.operator
        op = _LOGIC.get(word.rstrip("N") if word not in _LOGIC else word) or _ARITHMETIC.get(word) or _COMPARE[word]
        probe = ast.Binary(op, self._value(cr, instruction.span), copy.deepcopy(operand), instruction.span)
        ty = self.silent.expr(probe)
        if ty is ERROR and cr.type is not ERROR:
            operand_type = self.silent.expr(copy.deepcopy(operand))
            if operand_type is not ERROR:
                self.report(
                    "IL-TYPE",
                    f"{instruction.written} {_text(operand)}: the accumulator holds {_describe(cr.type)}, "
                    f"the operand is {_describe(operand_type)}",
                    instruction,
                )
            else:
                self.checker.expr(operand)  # its own problem (unknown variable ...), reported once
            self.cr = Cr(ERROR, const=probe)
            return
        value = ast.Binary(op, self._value(cr, instruction.span), operand, instruction.span)
        self.checker.expr(value)
        self._set(value, ty, instruction)

    def _not(self, instruction: IlInstruction) -> None:
        cr = self._read(instruction)
        if cr is None or (instruction.operands and self._operand(instruction, 0) is None):
            return
        if self._bits(cr.type, instruction, None):
            value = ast.Unary("NOT", self._value(cr, instruction.span), instruction.span)
            self._set(value, self.checker.expr(value), instruction)

    def _open(self, instruction: IlInstruction) -> None:
        """``OP(``: keep (OP, CR) and start a new CR, from the operand when one is given (IL-13, IL-06)."""
        saved = self._read(instruction)
        self.stack.append(_Frame(instruction, saved))
        self.cr = None
        if instruction.operands:
            self._load(IlInstruction("LD", [], instruction.span, operands=instruction.operands, written="LD"))

    def _close(self, instruction: IlInstruction) -> None:
        """``)``: ``CR := saved OP CR`` (ANDN( negates the bracket's value, IL-21)."""
        if not self.stack:
            self.report("IL-PAREN", "')' without an operator with '(' before it", instruction)
            return
        inner = self._read(instruction)
        frame = self.stack.pop()
        self.cr = frame.saved
        if inner is None or frame.saved is None:
            self.cr = None if frame.saved is None else Cr(ERROR, const=ast.BoolLit(False))
            return
        opened = frame.instruction
        operand = self._value(inner, instruction.span)
        word = opened.operator
        if word in ("ANDN", "ORN", "XORN", "&N"):
            operand = ast.Unary("NOT", operand, instruction.span)
        self._operate(IlInstruction(")", [], instruction.span, written=f"{opened.written}( ... )"), operand, word)

    # ------------------------------------------------------------ jumps, calls, returns (IL-23, IL-14, IL-33)
    def _jump(self, instruction: IlInstruction) -> None:
        label = self._label_operand(instruction)
        if label is None:
            return
        if self.stack:
            self.report("IL-PAREN", f"{instruction.written} cannot jump out of '(' ... ')'", instruction)
            return
        cond = self._guard(instruction)
        if instruction.operator != "JMP" and cond is None:
            return
        self._materialise(instruction)
        state = self.cr if isinstance(self.cr, Cr) else None
        goto = ast.Goto(label, cond, instruction.span)
        if cond is not None:
            self.checker.expr(cond)
        self.out.append(goto)
        self.jumps.append((label, state, instruction))
        if label.upper() not in self.labels:
            self.forward.setdefault(label.upper(), []).append(state)
        if instruction.operator == "JMP":
            self.reachable = False

    def _guard(self, instruction: IlInstruction) -> ast.Expr | None:
        """The condition of a C-modified instruction (IL-14): the CR, negated for ``CN``; None when unconditional."""
        if not instruction.operator.endswith(("C", "CN")):
            return None
        cr = self._read(instruction)
        if cr is None or not self._condition(cr, instruction):
            return None
        value = self._value(cr, instruction.span)
        return ast.Unary("NOT", value, instruction.span) if instruction.operator.endswith("CN") else value

    def _call(self, instruction: IlInstruction) -> None:
        call = instruction.call
        if call is None:
            operand = self._operand(instruction)
            if operand is None:
                return
            call = ast.Call(operand, [], operand.span)
        self._guarded(instruction, *action_inputs(self.silent, call), ast.CallStmt(call, instruction.span))

    def _return(self, instruction: IlInstruction) -> None:
        if instruction.operands:
            self._operand(instruction, 0)
            return
        self._guarded(instruction, ast.Return(instruction.span))
        if instruction.operator == "RET":
            self.reachable = False

    def _guarded(self, instruction: IlInstruction, *statements: ast.Stmt) -> None:
        if instruction.operator.endswith(("C", "CN")):
            cond = self._guard(instruction)
            if cond is not None:
                self._emit(ast.If([(cond, list(statements))], None, instruction.span))
        else:
            for statement in statements:
                self._emit(statement)

    def _fb_input(self, instruction: IlInstruction) -> None:
        """``PV C10`` = ``CAL C10(PV := CR)`` (IL-24, IEC 61131-3 ed. 2 Table 52)."""
        operand = self._operand(instruction)
        cr = self._read(instruction)
        if operand is None or cr is None:
            return
        if not isinstance(self.silent.expr(copy.deepcopy(operand)), t.FbType):
            self.report(
                "IL-OPERAND",
                f"{instruction.written} needs a function block instance with an input {instruction.operator}",
                instruction,
            )
            return
        arg = ast.Arg(instruction.operator, self._value(cr, instruction.span), span=instruction.span)
        self._emit(ast.CallStmt(ast.Call(operand, [arg], instruction.span), instruction.span))

    def _function(self, instruction: IlInstruction) -> None:
        """A function as operator: the CR is its first input (IL-30, IL-04); ``F(args)`` ignores the CR (IL-31)."""
        word = instruction.operator
        if self.checker.result.pou(word) is None and stdlib.function(word) is None:
            self.report(
                "IL-UNKNOWN-OPERATOR",
                f"'{instruction.written}' is not an IL operator or a function"
                + did_you_mean(instruction.written, sorted(OPERATORS | FB_INPUT_OPERATORS)),
                instruction,
            )
            self.cr = Cr(ERROR, const=ast.BoolLit(False))
            return
        call = instruction.call
        if call is None:
            cr = self._read(instruction)
            if cr is None:
                return
            args = [ast.Arg(None, self._value(cr, instruction.span), span=instruction.span)]
            args += [ast.Arg(None, operand, span=operand.span) for operand in instruction.operands]
            call = ast.Call(ast.Name(instruction.written, instruction.span), args, instruction.span)
        ty = self.checker.expr(call)
        if ty is t.VOID:
            self.report("IL-TYPE", f"{instruction.written} returns no value for the accumulator", instruction)
            return
        self._set(call, ty, instruction)

    # ------------------------------------------------------------ labels (IL-02, IL-25)
    def _label(self, name: str, span: ast.Span) -> None:
        upper = name.upper()
        if upper in self.labels:
            self.report(
                "IL-LABEL", f"the label '{name}' is already defined on line {self.labels[upper][1].line}", _At(span)
            )
            return
        if self.reachable:
            self._materialise(_At(span))
        states = ([self.cr] if self.reachable else []) + self.forward.pop(upper, [])
        self.cr = _merge(states, name)
        self.reachable = True
        self.labels[upper] = (self.cr, span)
        self.out.append(ast.Label(name, span))

    def _check_back_edge(self, label: str, state: Cr | None, instruction: IlInstruction) -> None:
        entry, _ = self.labels[label.upper()]
        if not isinstance(entry, Cr) or state is None or not entry.read:
            return
        if state.type is not ERROR and entry.type is not ERROR and not t.same(state.type, entry.type):
            self.report(
                "IL-CR-TYPE",
                f"{instruction.written} {label}: the accumulator is {state.type} here but {entry.type} where "
                f"label {label} reads it: load a value (LD) after the label",
                instruction,
            )

    # ------------------------------------------------------------ type rules
    def _condition(self, cr: Cr, instruction: IlInstruction) -> bool:
        if cr.type is ERROR or t.same(cr.type, t.BOOL):
            return True
        self.report(
            "IL-TYPE", f"{instruction.written} needs a BOOL accumulator, but it holds {_describe(cr.type)}", instruction
        )
        return False

    def _bits(self, ty: Type, instruction: IlInstruction, operand: ast.Expr | None) -> bool:
        if ty is ERROR or t.in_family(ty, "ANY_BIT"):
            return True
        what = _text(operand) if operand is not None else "the accumulator"
        self.report(
            "IL-TYPE", f"{instruction.written} negates {what}, which is {_describe(ty)}, not a bit string", instruction
        )
        return False


@dataclass
class _At:
    """A place to report at when there is no instruction (a label on its own line)."""

    span: ast.Span
    written: str = ""


def _merge(states: list[Cr | Conflict | None], label: str) -> Cr | Conflict | None:
    crs = [state for state in states if isinstance(state, Cr)]
    if any(isinstance(state, Conflict) for state in states) or not crs:
        return None if not crs else Conflict([c.type for c in crs], label)
    first = crs[0]
    if all(t.same(c.type, first.type) or c.type is ERROR for c in crs) and len(crs) == len(states):
        return Cr(first.type, name=first.name, const=first.const)
    if len(crs) < len(states):  # a path without a value: reading the CR there is an error
        return None
    return Conflict(_distinct([c.type for c in crs]), label)


def _distinct(types: list[Type]) -> list[Type]:
    out: list[Type] = []
    for ty in types:
        if not any(t.same(ty, seen) for seen in out):
            out.append(ty)
    return out


def _constant(node: ast.Expr) -> bool:
    if isinstance(node, ast.LITERALS):
        return True
    if isinstance(node, ast.Binary):
        return _constant(node.left) and _constant(node.right)
    if isinstance(node, ast.Unary):
        return _constant(node.operand)
    return False


def _describe(ty: Type) -> str:
    return (
        "an integer literal"
        if isinstance(ty, t.UntypedInt)
        else "a real literal"
        if isinstance(ty, t.UntypedReal)
        else str(ty)
    )


def _text(node: ast.Expr) -> str:
    from .printer import print_expression

    return print_expression(node)


_HANDLERS = {
    "LD": _Translator._load,
    "LDN": _Translator._load,
    "ST": _Translator._store,
    "STN": _Translator._store,
    "S": _Translator._set_reset,
    "R": _Translator._set_reset,
    "NOT": _Translator._not,
    "JMP": _Translator._jump,
    "JMPC": _Translator._jump,
    "JMPCN": _Translator._jump,
    "CAL": _Translator._call,
    "CALC": _Translator._call,
    "CALCN": _Translator._call,
    "RET": _Translator._return,
    "RETC": _Translator._return,
    "RETCN": _Translator._return,
}
