"""IL bodies -> IR blocks (docs/il.md, IL-26): the checker turned each instruction into a typed ST statement
(``st/il_check.py``); here labels start labelled blocks and jumps become ``Jump``s, so the engine, monitoring,
breakpoints (one pause point per IL line) and tracing treat an IL POU like any other.

Online mode shows the accumulator after every line: each line's value (``IlValue``) is a probe
``L<line>:<type>`` where the checker says it stands, so the monitor variant records it like a diagram
element's value (the type tells the browser how to show it: a TIME, a REAL).
"""

from __future__ import annotations

from ..model.project import Pou as ModelPou
from ..st import ast
from ..st.il_check import IlValue
from .context import PouContext
from .lower_expr import lower_to
from .lower_st import lower_statements
from .lower_types import LoweringError, ir_default
from .nodes import Block, Jump, Origin, Probe, Slot, Stmt
from .types import BOOL


def lower_il_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """One block for the instructions before the first label, then one labelled block per label."""
    info = ctx.info
    if info is None or info.body is None:
        return []
    return lower_il(info.body, info.accumulators, info.il_values, ctx)


def lower_il(statements: list[ast.Stmt], accumulators: list, il_values: list[IlValue], ctx: PouContext) -> list[Block]:
    """Checked IL (an IL POU's body, or an IL action or transition of an SFC POU) as blocks: one for the
    instructions before the first label, then one labelled block per label."""
    for symbol in accumulators:  # the hidden current-result variables (one per type and '(' depth)
        if ctx.has_slot(symbol.name.upper()):  # another IL part of the POU made it: the CR is not kept between parts
            continue
        ir_type = ctx.types.type_of(symbol.type, symbol.type_spec)
        ctx.add_slot(Slot(symbol.name.upper(), "VAR", ir_type, ir_default(ir_type), hidden=True))
    blocks = [Block([], Origin(ctx.name))]
    values = list(reversed(il_values))  # by index, next one last
    for index, statement in enumerate(statements):
        while values and values[-1].index == index:
            blocks[-1].statements += _probe(values.pop(), ctx)
        if isinstance(statement, ast.Label):
            blocks.append(Block([], ctx.origin(statement), statement.name.upper()))
        elif isinstance(statement, ast.Goto):
            blocks[-1].statements += _jump(statement, ctx)
        else:
            blocks[-1].statements += lower_statements([statement], ctx)
    while values:
        blocks[-1].statements += _probe(values.pop(), ctx)
    return blocks if blocks[0].statements or len(blocks) == 1 else blocks[1:]


def probe_id(line: int, type_name: str) -> str:
    """The probe of the accumulator after body line ``line`` holding a ``type_name`` (``L12:INT``)."""
    return f"L{line}:{type_name}"


def _probe(value: IlValue, ctx: PouContext) -> list[Stmt]:
    try:
        expr = lower_to(value.value, ctx, ctx.ir_type(value.type))
    except LoweringError:
        return []  # a value the statements lower without trouble; nothing to show rather than a wrong one
    return [Probe(probe_id(value.line, str(value.type)), expr, Origin(ctx.name, value.line))]


def _jump(statement: ast.Goto, ctx: PouContext) -> list[Stmt]:
    try:
        cond = lower_to(statement.cond, ctx, BOOL) if statement.cond is not None else None
    except LoweringError as error:
        ctx.report_error(error, statement)
        return []
    return [Jump(statement.label.upper(), cond, ctx.origin(statement))]
