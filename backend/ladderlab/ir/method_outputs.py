"""VAR_OUTPUT of a METHOD (CODESYS; IEC 61131-3 ed. 3, 6.6.5): the method's output is a variable of its own call,
fresh in every call like its VAR; when the method returns (at its end or a RETURN) the output's value is copied
to the call's ``=>`` target.

Both sides are lowered onto what the engine already has, the in-outs of a function: the method gets one hidden
in-out per output after its declared ones, and copies each output into it before it returns; the caller passes
the ``=>`` target itself for it when the target has exactly the output's type, else a hidden temporary it copies from
after the call (a conversion, ``NOT b => x``, a bit of a variable), and a temporary for an output it leaves out.
"""

from __future__ import annotations

from ..st import ast
from ..st.printer import print_expression
from ..st.symbols import PouInfo
from .context import PouContext
from .lower_types import LoweringError
from .nodes import Assign, Origin, Stmt, Unary, Var


def declare_output_references(ctx: PouContext) -> list[Stmt]:
    """In a method being lowered: a hidden in-out per VAR_OUTPUT (after every declared slot, the order in which
    callers pass them), and the copies of the outputs into them that run before the method returns."""
    info = ctx.info
    if info is None or info.method is None:
        return []
    copies: list[Stmt] = []
    for symbol in info.parameters("VAR_OUTPUT"):
        local = ctx.var_for(symbol)
        reference = ctx.hidden(f"{symbol.name}_OUT", local.type, var_class="VAR_IN_OUT")
        copies.append(Assign(reference, local, Origin(ctx.name)))
    return copies


def output_arguments(node: ast.Call, method: PouInfo, ctx: PouContext, after: list[Stmt] | None) -> list[Var]:
    """The in-outs a call of ``method`` passes for its outputs, in declaration order. The copies a target needs
    after the call go to ``after``; None: the call is in an expression, where nothing can run after it, so such a
    target is a located error (call the method as a statement)."""
    from .lower_expr import assign_part, convert, is_part, lower_access  # (lower_expr calls this)

    targets = {a.name.upper(): a for a in node.args if a.output and a.name is not None and a.name.upper() != "ENO"}
    callee = ctx.types_for(method.name)
    passed: list[Var] = []
    for symbol in method.parameters("VAR_OUTPUT"):
        ty = callee.type_of(symbol.type, symbol.type_spec)
        arg = targets.get(symbol.name.upper())
        if arg is not None and not arg.negated and not is_part(arg.value):
            target = lower_access(arg.value, ctx)
            if target.type == ty:  # (a STRING of another length is copied: its own length cuts it)
                passed.append(target)
                continue
        temporary = ctx.hidden(f"{method.method.name}_{symbol.name}", ty, var_class="VAR_TEMP")
        passed.append(temporary)
        if arg is None:
            continue
        if after is None:
            raise LoweringError(
                f"the output {symbol.name} => {print_expression(arg.value)} is converted after the call, which "
                "cannot happen inside an expression: call the method as a statement, or assign its result "
                "directly (x := inst.M(...))",
                arg,
            )
        value = Unary("NOT", temporary, ty) if arg.negated else temporary
        if is_part(arg.value):
            part, updated = assign_part(arg.value, convert(value, ctx.ir_type(arg.value.ty)), ctx)
            after.append(Assign(part, updated, ctx.origin(arg)))
        else:
            target = lower_access(arg.value, ctx)
            after.append(Assign(target, convert(value, target.type), ctx.origin(arg)))
    return passed
