"""ST statements -> IR statements; an ST body is one unlabelled ``Block`` (docs/ir.md invariant 4).

Every statement gets the ``Origin`` of its span. A statement that cannot be
lowered is dropped with a located diagnostic and the rest of the body is still
lowered, so one pass reports every problem. Calls with EN/ENO nested in a
statement's expressions are lifted into ``FnCall``s placed before it (see
``lower_expr._lift``); where that would change when they run (ELSIF, WHILE and
UNTIL conditions) they are refused with ``IR-EN-CALL``.
"""

from __future__ import annotations

from ..iec import stdlib
from ..model.project import Pou as ModelPou
from ..st import ast
from ..st import types as t
from ..st.interfaces import attempted_fb
from ..st.methods import SUPER, is_self
from ..st.printer import print_expression
from ..st.symbols import PouInfo, PropertyRef, Symbol
from .byte_layout import has_checked_values
from .context import PouContext
from .lower_expr import (
    address_of,
    assign_part,
    convert,
    is_part,
    lower_access,
    lower_en_eno,
    lower_expr,
    lower_input,
    lower_to,
    program_instance,
    property_call,
    retarget,
    std_call,
    user_call,
    value_type,
)
from .lower_types import LoweringError
from .nodes import (
    Assign,
    Attempt,
    Block,
    Call,
    Case,
    CaseLabel,
    Const,
    Continue,
    Exit,
    Expr,
    FbCall,
    FnCall,
    For,
    If,
    Origin,
    Repeat,
    Return,
    Stmt,
    Unary,
    Var,
    While,
    member,
)
from .types import BOOL, IrType, Reference


def lower_st_body(pou: ModelPou, ctx: PouContext) -> list[Block]:
    """The checked body of an ST POU as one block (no block when it did not parse)."""
    body = ctx.info.body if ctx.info is not None else None
    if body is None:
        return []
    origin = Origin(ctx.name)
    if body:
        first, last = body[0].span, body[-1].span
        origin = Origin(
            ctx.name, first.line or None, first.column or None, last.end_line or None, last.end_column or None
        )
    return [Block(lower_statements(body, ctx), origin)]


def lower_statements(statements: list[ast.Stmt], ctx: PouContext) -> list[Stmt]:
    out: list[Stmt] = []
    for statement in statements:
        out += _statement(statement, ctx)
    return out


def _statement(statement: ast.Stmt, ctx: PouContext) -> list[Stmt]:
    """One statement, preceded by the FnCalls lifted out of its expressions; nothing if it cannot be lowered."""
    saved = ctx.lifts, ctx.reads, ctx.calls
    lifted: list[Stmt] = []
    ctx.lifts, ctx.reads, ctx.calls = lifted, 0, 0
    try:
        lower = ctx.extra_statements.get(type(statement)) if ctx.extra_statements else None
        lowered = (lower or _LOWER[type(statement)])(statement, ctx)
    except LoweringError as error:
        if not ctx.checker_error_in(statement.span):  # no second diagnostic for a statement the checker rejected
            ctx.report_error(error, statement)
        return []
    finally:
        ctx.lifts, ctx.reads, ctx.calls = saved
    return lifted + lowered


# ---------------------------------------------------------------- assignments and calls


def _assign(statement: ast.Assign, ctx: PouContext) -> list[Stmt]:
    origin = ctx.origin(statement)
    target, value = statement.target, statement.value
    if is_part(target):
        return [_assign_bit(target, value, ctx, origin)]
    if isinstance(getattr(target, "ref", None), PropertyRef):  # its SET
        return [FnCall(property_call(target, ctx, value), None, origin)]
    if isinstance(value, ast.Call) and _has_en_eno_or_outputs(value) and _is_function(value.ref):
        copies: list[Stmt] = []
        call = _function_call(value, ctx, copies)
        en, eno, after = lower_en_eno(value, ctx)
        en, eno, copies = gated(en, eno, copies, origin, ctx)
        return [FnCall(call, lower_access(target, ctx), origin, en, eno), *copies, *after]
    lowered = lower_to(value, ctx, ctx.ir_type(target.ty))  # the value is computed before the target is stored
    if statement.attempt:  # ?=: NULL unless the instance's FB implements the interface (extends the target's FB)
        blocks = [fb for fb in ctx.checked.pous.values() if fb.kind == "FUNCTION_BLOCK"]
        base = attempted_fb(target.ty)
        fits = [fb for fb in blocks if (fb.derives_from(base) if base is not None else fb.implements(target.ty.info))]
        lowered = Attempt(lowered, tuple(fb.name.upper() for fb in fits), lowered.type)
    place = lower_access(target, ctx)
    if isinstance(place.type, Reference) and has_checked_values(place.type.target):  # the checker's may lack the range
        lowered = retarget(lowered, place.type, value)
    return [Assign(place, lowered, origin)]


def _ref_assign(statement: ast.RefAssign, ctx: PouContext) -> list[Stmt]:
    """``r REF= x``: the reference itself (not read through) gets a reference to x, as ``r := REF(x)`` would."""
    target = lower_access(statement.target, ctx)
    value = address_of(statement.value, target.type, f"REF({print_expression(statement.value)})", ctx)
    return [Assign(target, value, ctx.origin(statement))]


def _assign_bit(target: ast.Member, value: ast.Expr, ctx: PouContext, origin: Origin) -> Assign:
    """``x.3 := b`` and ``x.%B1 := v``: the variable gets its new pattern (lower_expr.assign_part)."""
    var, updated = assign_part(target, lower_to(value, ctx, ctx.ir_type(target.ty)), ctx)
    return Assign(var, updated, origin)


def lower_call_statement(statement: ast.CallStmt, ctx: PouContext) -> list[Stmt]:
    call = statement.call
    if not isinstance(call, ast.Call):
        raise LoweringError(None)
    if isinstance(call.ref, Symbol):
        return lower_fb_call(call, ctx, ctx.origin(statement))
    if isinstance(call.ref, PouInfo) and call.ref.kind == "PROGRAM":
        return _program_call(call, call.ref, ctx, ctx.origin(statement))
    if is_self(call.callee):  # SUPER^(): the base's body on this instance; THIS^(): its own class's (st/calls.py)
        statements = lower_fb_call(call, ctx, ctx.origin(statement))
        if call.callee.base.name.upper() == SUPER:
            statements[0].body = call.callee.ty.name.upper()
        return statements
    if not _is_function(call.ref):
        raise LoweringError(None)
    copies: list[Stmt] = []
    lowered = _function_call(call, ctx, copies)
    en, eno, after = lower_en_eno(call, ctx)
    origin = ctx.origin(statement)
    en, eno, copies = gated(en, eno, copies, origin, ctx)
    return [FnCall(lowered, None, origin, en, eno), *copies, *after]


def _is_function(ref: object) -> bool:
    return isinstance(ref, stdlib.StdFunction) or (isinstance(ref, PouInfo) and ref.kind == "FUNCTION")


def _has_en_eno_or_outputs(call: ast.Call) -> bool:
    """EN, ENO or a method's ``=>`` outputs: the call is a statement of its own (``FnCall``) with copies after it."""
    return any(a.output or (a.name is not None and a.name.upper() == "EN") for a in call.args)


def _function_call(call: ast.Call, ctx: PouContext, after: list[Stmt]) -> Call:
    """The call; the copies a method's ``=>`` outputs need after it go to ``after`` (ir/method_outputs.py)."""
    return std_call(call, ctx) if isinstance(call.ref, stdlib.StdFunction) else user_call(call, ctx, after)


def gated(
    en: Expr | None, eno: Var | None, copies: list[Stmt], origin: Origin, ctx: PouContext
) -> tuple[Expr | None, Var | None, list[Stmt]]:
    """EN and ENO of a call and the ``copies`` after it, which run only when the call ran (ENO) if it has an EN."""
    if en is not None and copies:
        eno = eno or ctx.hidden("ENO", BOOL, var_class="VAR_TEMP")
        copies = [If([(eno, copies)], [], origin)]
    return en, eno, copies


def lower_fb_call(call: ast.Call, ctx: PouContext, origin: Origin) -> list[Stmt]:
    """``inst(IN := x, PT := T#5s, Q => y)``: inputs by name, ``=>`` outputs copied out after the call.

    An output that needs a conversion or is negated (``NOT Q => y``) becomes an
    Assign after the call; with EN those run only when the call ran (ENO).
    """
    if isinstance(call.ref, PouInfo) and call.ref.kind == "PROGRAM":  # an LD/FBD program box: its one instance
        return _program_call(call, call.ref, ctx, origin)
    fb = call.callee.ty
    if not isinstance(fb, t.FbType):
        raise LoweringError(None)
    return _instance_call(call, lower_access(call.callee, ctx), fb_pins(fb, ctx), ctx, origin)


def _program_call(call: ast.Call, program: PouInfo, ctx: PouContext, origin: Origin) -> list[Stmt]:
    """``Prog(in := x, out => y)`` from another program (IL-08, seed 003 "PRGexample2"): the program's one
    instance runs now, like an FB instance; a task that runs it too runs it again (docs/st.md)."""
    instance = program_instance(call.callee, program, ctx, "call")
    return _instance_call(call, instance, _pou_pins(program, ctx), ctx, origin)


def _instance_call(
    call: ast.Call, instance: Var, pins: dict[str, tuple[IrType, str]], ctx: PouContext, origin: Origin
) -> list[Stmt]:
    """The call of an FB or program ``instance`` with ``pins`` (fb_pins): inputs, ``=>`` outputs, EN/ENO."""
    order = [name for name, (_, kind) in pins.items() if kind != "VAR_OUTPUT"]
    inputs: list[tuple[str, Expr]] = []
    outputs: list[tuple[str, Var]] = []
    copies: list[Stmt] = []
    arguments = [a for a in call.args if a.name is None or a.name.upper() not in ("EN", "ENO")]
    for position, arg in enumerate(arguments):
        name = arg.name.upper() if arg.name is not None else order[position] if position < len(order) else ""
        if name not in pins:
            raise LoweringError(None)
        pin_type, kind = pins[name]
        if kind == "VAR_IN_OUT":
            inputs.append((name, lower_access(arg.value, ctx)))
        elif not arg.output:
            inputs.append((name, lower_input(arg.value, ctx, pin_type)))
        else:
            target = lower_access(arg.value, ctx)
            if not arg.negated and value_type(target.type) == value_type(pin_type):
                outputs.append((name, target))
                continue
            pin: Expr = fb_output(instance, name, pin_type)
            if arg.negated:
                pin = Unary("NOT", pin, pin_type)
            copies.append(Assign(target, convert(pin, target.type), ctx.origin(arg)))
    en, eno, after = lower_en_eno(call, ctx)
    en, eno, copies = gated(en, eno, copies, origin, ctx)
    return [FbCall(instance, inputs, outputs, origin, en, eno), *copies, *after]


def fb_output(instance: Var, name: str, ty: IrType) -> Var:
    """Output pin ``name`` (upper case) of an FB instance, as read after its call."""
    return Var(instance.scope, instance.name, ty, (*instance.path, member(name)))


def fb_pins(fb: t.FbType, ctx: PouContext) -> dict[str, tuple[IrType, str]]:
    """Pin name -> (IR type, VAR_INPUT / VAR_IN_OUT / VAR_OUTPUT) of a standard or user FB, inputs first.
    Built once per FB type and POU (asked for at every call; callers only read it)."""
    key = (fb.name.upper(), fb.std is not None)
    pins = ctx.fb_pins.get(key)
    if pins is None:
        pins = ctx.fb_pins[key] = _fb_pins(fb, ctx)
    return pins


def _fb_pins(fb: t.FbType, ctx: PouContext) -> dict[str, tuple[IrType, str]]:
    if fb.std is not None:
        return {
            **{p.name: (ctx.ir_type(t.elementary(p.type)), "VAR_INPUT") for p in fb.std.inputs},
            **{p.name: (ctx.ir_type(t.elementary(p.type)), "VAR_OUTPUT") for p in fb.std.outputs},
        }
    return _pou_pins(fb.pou, ctx)


def _pou_pins(pou: PouInfo, ctx: PouContext) -> dict[str, tuple[IrType, str]]:
    callee = ctx.types_for(pou.name)
    return {
        s.name.upper(): (callee.type_of(s.type, s.type_spec), s.var_class)
        for s in pou.parameters("VAR_INPUT", "VAR_IN_OUT", "VAR_OUTPUT")
    }


# ---------------------------------------------------------------- control flow


def _if(statement: ast.If, ctx: PouContext) -> list[Stmt]:
    branches = []
    for index, (condition, body) in enumerate(statement.branches):
        if index:
            ctx.lifts = None  # an ELSIF condition runs only when the ones before it were FALSE
        branches.append((lower_to(condition, ctx, BOOL), lower_statements(body, ctx)))
    return [If(branches, lower_statements(statement.else_body or [], ctx), ctx.origin(statement))]


def _case(statement: ast.Case, ctx: PouContext) -> list[Stmt]:
    selector = lower_expr(statement.selector, ctx)
    branches = []
    for branch in statement.branches:
        labels: list[CaseLabel] = []
        for label in branch.labels:
            if isinstance(label, ast.CaseRange):
                labels.append((_label(label.low, ctx), _label(label.high, ctx)))
            else:
                labels.append(_label(label, ctx))
        branches.append((labels, lower_statements(branch.body, ctx)))
    return [Case(selector, branches, lower_statements(statement.else_body or [], ctx), ctx.origin(statement))]


def _label(label: ast.Expr, ctx: PouContext) -> int:
    """A CASE label's integer: a literal, a CONSTANT, an enumeration value (its int), constant arithmetic."""
    value = ctx.types.raw_constant(label)
    if isinstance(value, bool) or not isinstance(value, int):
        raise LoweringError(None)
    return value


def _for(statement: ast.For, ctx: PouContext) -> list[Stmt]:
    """FOR: start, end and step are evaluated once, on entry (ST-31, ST-73); the step defaults to 1."""
    var = lower_access(statement.var, ctx)
    ty = value_type(var.type)
    start, end = lower_to(statement.start, ctx, ty), lower_to(statement.end, ctx, ty)
    step = lower_to(statement.step, ctx, ty) if statement.step is not None else Const(1, ty)
    return [For(var, start, end, step, lower_statements(statement.body, ctx), ctx.origin(statement))]


def _while(statement: ast.While, ctx: PouContext) -> list[Stmt]:
    ctx.lifts = None  # the condition is evaluated before every iteration
    return [While(lower_to(statement.cond, ctx, BOOL), lower_statements(statement.body, ctx), ctx.origin(statement))]


def _repeat(statement: ast.Repeat, ctx: PouContext) -> list[Stmt]:
    ctx.lifts = None
    body = lower_statements(statement.body, ctx)
    return [Repeat(body, lower_to(statement.until, ctx, BOOL), ctx.origin(statement))]


def _exit(statement: ast.Exit, ctx: PouContext) -> list[Stmt]:
    return [Exit(ctx.origin(statement))]


def _continue(statement: ast.Continue, ctx: PouContext) -> list[Stmt]:
    return [Continue(ctx.origin(statement))]


def _return(statement: ast.Return, ctx: PouContext) -> list[Stmt]:
    """RETURN; a method first hands its outputs to its caller (ir/method_outputs.py)."""
    return [*ctx.before_return, Return(ctx.origin(statement))]


def _empty(statement: ast.Empty, ctx: PouContext) -> list[Stmt]:
    return []


_LOWER = {
    ast.Assign: _assign,
    ast.RefAssign: _ref_assign,
    ast.CallStmt: lower_call_statement,
    ast.If: _if,
    ast.Case: _case,
    ast.For: _for,
    ast.While: _while,
    ast.Repeat: _repeat,
    ast.Exit: _exit,
    ast.Continue: _continue,
    ast.Return: _return,
    ast.Empty: _empty,
}
