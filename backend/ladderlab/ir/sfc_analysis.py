"""SFCErrorAnalyzationTable and SFCErrorAnalyzation: why a timed-out step's transitions do not fire (docs/sfc.md).

When a step's time limit sets SFCError, the conditions of the transitions leaving the step are taken apart into
the parts that hold them FALSE, as CODESYS's Analyzation library does: a FALSE ``a AND b`` is held by its FALSE
operands, a FALSE ``a OR b`` by all of them, ``NOT x`` by ``x`` being TRUE (and the same rules mirrored for a TRUE
operand under NOT). Anything else (a variable, a comparison, a call, XOR) is one part. Which parts hold a
condition depends on the values in that scan, so the lowering writes one guarded entry per part: the table gets
``name`` (the part as ST), ``address`` (the variable's AT address), ``comment`` (its declaration comment),
``value`` and ``failed`` (TRUE: the entry is a part that holds the transition); the string gets the names joined
by `` | ``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from ..st import ast
from ..st import types as st_types
from ..st.parser import parse_expression
from ..st.printer import print_expression
from ..st.symbols import PouInfo, Symbol
from .context import PouContext
from .diagram_operands import At, Operands
from .nodes import Assign, Binary, Call, Const, Expr, If, Index, Member, Origin, Stmt, Unary, Var
from .types import BOOL, Array, Elementary, IrType, Struct, StructField

INT = Elementary("INT")
TRUE = Const(True, BOOL)
FALSE = Const(False, BOOL)
#: The fields of ExpressionResult (st/types.py) the analysis writes, and the type each must have.
STRING_FIELDS = ("NAME", "ADDRESS", "COMMENT")
BOOL_FIELDS = ("VALUE", "FAILED")


@dataclasses.dataclass
class Part:
    """One part of a condition that may hold it: its ST text and when it does: the whole condition FALSE and each
    of ``terms`` (an enclosing operand's text and the value it must have) as given."""

    text: str
    terms: list[tuple[str, bool]]
    address: str = ""
    comment: str = ""


def condition_parts(condition: str, symbol: Callable[[str], Symbol | None]) -> list[Part]:
    """The parts of an ST condition, left to right; ``symbol`` finds a variable by name (address, comment)."""
    parsed = parse_expression(condition).ast
    return [] if parsed is None else _parts(parsed, False, [], symbol)


def _parts(
    node: ast.Expr, holding: bool, terms: list[tuple[str, bool]], symbol: Callable[[str], Symbol | None]
) -> list[Part]:
    """The parts of ``node`` that give it the value ``holding`` (the value that holds the transition)."""
    if isinstance(node, ast.Unary) and node.op == "NOT":
        return _parts(node.operand, not holding, terms, symbol)
    if isinstance(node, ast.Binary) and node.op in ("AND", "OR"):
        # FALSE AND: its FALSE operands; TRUE OR: its TRUE operands; otherwise every operand has that value
        each = (node.op == "AND") != holding
        out: list[Part] = []
        for operand in _chain(node, node.op):
            more = [(print_expression(operand), holding)] if each else []
            out += _parts(operand, holding, terms + more, symbol)
        return out
    found = symbol(node.name) if isinstance(node, ast.Name) else None
    address = found.address if found is not None else node.address if isinstance(node, ast.DirectAddr) else None
    comment = found.comment if found is not None else None
    return [Part(print_expression(node), terms, address or "", (comment or "").strip())]


def table_problem(symbol: Symbol) -> str | None:
    """Why a declared SFCErrorAnalyzationTable cannot take the analysis (None: it can)."""
    ty = symbol.type
    wanted = "an ARRAY [0..n] OF ExpressionResult"
    if not isinstance(ty, st_types.ArrayType) or len(ty.dims) != 1 or ty.dims[0] is None:
        return f"the SFC flag {symbol.name} must be {wanted}, not {ty}"
    element = ty.element
    if not isinstance(element, st_types.StructType):
        return f"the SFC flag {symbol.name} must be {wanted}, not an array of {element}"
    fields = element.fields
    if "NAME" not in fields or "VALUE" not in fields:
        return f"the elements of {symbol.name} need the fields name : STRING and value : BOOL (as ExpressionResult)"
    for upper, (name, field_type) in fields.items():
        if upper in STRING_FIELDS and not isinstance(field_type, st_types.StringType):
            return f"the field {name} of {element.name} must be a STRING, not {field_type}"
        if upper in BOOL_FIELDS and not st_types.same(field_type, st_types.BOOL):
            return f"the field {name} of {element.name} must be a BOOL, not {field_type}"
    return None


def _chain(node: ast.Expr, op: str) -> list[ast.Expr]:
    """The operands of ``a op b op c`` (one level of a chain of the same operator), left to right."""
    if isinstance(node, ast.Binary) and node.op == op:
        return [*_chain(node.left, op), *_chain(node.right, op)]
    return [node]


class Analysis:
    """The statements that fill the table and the string for the transitions leaving one step."""

    def __init__(self, ctx: PouContext, info: PouInfo, ops: Operands, table: Var | None, text: Var | None):
        self.ctx = ctx
        self.info = info
        self.ops = ops
        self.table = table
        self.text = text

    def clear(self, origin: Origin) -> list[Stmt]:
        """Every entry back to its empty value and the string to ''."""
        out: list[Stmt] = []
        if self.text is not None:
            out.append(Assign(self.text, Const("", self.text.type), origin))
        if self.table is not None:
            low, high = self._bounds()
            for index in range(low, high + 1):
                for field in self._struct().fields:
                    if field.name in STRING_FIELDS:
                        out.append(Assign(self._field(Const(index, INT), field), Const("", field.type), origin))
                    elif field.name in BOOL_FIELDS:
                        out.append(Assign(self._field(Const(index, INT), field), FALSE, origin))
        return out

    def record(self, conditions: list[tuple[str, str]], origin: Origin) -> list[Stmt]:
        """Clear, then write the parts holding each condition (text, element id), in the order given."""
        out = self.clear(origin)
        count = self.ctx.hidden("SFC_ANALYSIS_N", INT, var_class="VAR_TEMP")
        out.append(Assign(count, Const(0, INT), origin))
        for text, element in conditions:
            whole = self._read(text, element)
            if whole is None:
                continue
            for part in condition_parts(text, self.symbol):
                guard: list[Expr] = [Unary("NOT", whole, BOOL)]
                for term, value in part.terms:
                    read = self._read(term, element)
                    if read is not None:
                        guard.append(read if value else Unary("NOT", read, BOOL))
                part_value = self._read(part.text, element)
                if part_value is not None:
                    out.append(If([(_and(guard), self._entry(part, part_value, count, origin))], [], origin))
        return out

    def symbol(self, name: str) -> Symbol | None:
        """A declared variable (of the POU, else global) by name, for a part's address and comment."""
        upper = name.upper()
        found = self.info.symbols.get(upper) or self.ctx.checked.globals.get(upper)
        return found if isinstance(found, Symbol) and found.implicit is None else None

    def _read(self, text: str, element: str) -> Expr | None:
        value, _ = self.ops.read(text, At(None, element), "the condition", st_types.BOOL)
        return value

    # ------------------------------------------------------------ writing an entry
    def _entry(self, part: Part, value: Expr, count: Var, origin: Origin) -> list[Stmt]:
        out: list[Stmt] = []
        if self.table is not None:
            low, high = self._bounds()
            index = Binary("ADD", count, Const(low, INT), INT)
            writes: list[Stmt] = []
            texts = {"NAME": part.text, "ADDRESS": part.address, "COMMENT": part.comment}
            for field in self._struct().fields:
                target = self._field(index, field)
                if field.name in texts:
                    writes.append(Assign(target, Const(_fit(texts[field.name], field.type), field.type), origin))
                elif field.name == "VALUE":
                    writes.append(Assign(target, value, origin))
                elif field.name == "FAILED":
                    writes.append(Assign(target, TRUE, origin))
            fits = Binary("LE", count, Const(high - low, INT), BOOL)
            out.append(If([(fits, writes)], [], origin))
        if self.text is not None:
            ty = self.text.type
            first = Assign(self.text, Const(_fit(part.text, ty), ty), origin)
            joined = Call("CONCAT", (self.text, Const(" | " + part.text, ty)), (ty, ty), ty)
            more = Assign(self.text, joined, origin)
            out.append(If([(Binary("EQ", count, Const(0, INT), BOOL), [first])], [more], origin))
        out.append(Assign(count, Binary("ADD", count, Const(1, INT), INT), origin))
        return out

    def _bounds(self) -> tuple[int, int]:
        assert self.table is not None and isinstance(self.table.type, Array)
        return self.table.type.dims[0]

    def _struct(self) -> Struct:
        assert self.table is not None and isinstance(self.table.type, Array)
        element = self.table.type.element
        assert isinstance(element, Struct)
        return element

    def _field(self, index: Expr, field: StructField) -> Var:
        assert self.table is not None
        path = (*self.table.path, Index((index,)), Member(field.name))
        return Var(self.table.scope, self.table.name, field.type, path)


def _and(terms: list[Expr]) -> Expr:
    out = terms[0]
    for term in terms[1:]:
        out = Binary("AND", out, term, BOOL)
    return out


def _fit(text: str, ty: IrType) -> str:
    """A name longer than the STRING it goes into is cut, as an assignment to that STRING would cut it."""
    length = ty.length if isinstance(ty, Elementary) else None
    return text if length is None else text[:length]
