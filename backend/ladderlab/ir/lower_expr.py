"""Typed ST expressions (checked AST, every node has ``.ty``) -> IR expressions.

Mirrors the checker's typing (st/body.py, st/calls.py): operands of one operator
are brought to the type the checker combined them in, inserting ``Convert`` for
the implicit widenings it accepted; untyped literals take that type directly.
Decisions (docs/ir.md, "Lowering of ST and whole projects"):

* every node's type is the one the checker settled (st/context_typing.py): a literal has the
  type its context gave it, a generic operation computes in ``node.ty``; literal expressions
  (``-5``, ``3 * 4``) are folded into one ``Const`` in that type;
* a STRING of any length and a Subrange count as one type with STRING / their base,
  so they never get a ``Convert``;
* explicit ``*_TO_*`` conversions and TRUNC stay standard ``Call``s, ``Convert`` is only
  an implicit widening (which never changes the Python value);
* operators on mixed time operands (TOD + TIME, DT - DT, TIME * INT ...) become calls of
  their FUN-85 functions (``ADD_TOD_TIME``, ``MUL_TIME`` ...) via the runtime's
  ``OPERATOR_OVERLOADS``; ``ANY_NUM * TIME`` is ``MUL_TIME(time, number)``;
  STRING ``+`` is ``CONCAT``; ``**`` on two types is ``EXPT``; ``MOVE(x)`` is ``x``;
* a call with EN/ENO is lifted into a ``FnCall`` statement writing a hidden temporary,
  where the statement lowering allows it (``ctx.lifts``) and evaluation order is kept.
"""

from __future__ import annotations

from typing import TypeGuard

from ..iec import stdlib
from ..iec.addresses import part_type, partial_access
from ..iec.elementary import DEFAULT_STRING_LENGTH, ELEMENTARY, GENERIC
from ..iec.stdlib import OPERATOR_OVERLOADS
from ..iec.values import article
from ..st import ast
from ..st import types as t
from ..st.context_typing import FoldError, fold, literal_only
from ..st.gvls import list_qualified
from ..st.methods import is_self, is_super
from ..st.printer import print_expression
from ..st.rules import EnumValue
from ..st.symbols import PouInfo, PropertyRef, Symbol
from .byte_layout import byte_layout, has_checked_values, same_target, view_specs
from .codesys_dates import in_seconds
from .context import PouContext
from .lower_types import LoweringError, byte_size, engine_value, ir_default
from .method_outputs import output_arguments
from .nodes import (
    AddressOf,
    Assign,
    Binary,
    Call,
    Const,
    Convert,
    Deref,
    Expr,
    Fit,
    FnCall,
    Index,
    Stmt,
    Unary,
    Var,
    View,
    member,
)
from .types import BOOL, Array, Elementary, FbInstance, IrType, Reference, Struct, Subrange, describe

POINTER_ARITHMETIC = "pointer arithmetic is not supported: a reference reaches its variable only"

_OPERATORS = {
    "+": "ADD",
    "-": "SUB",
    "*": "MUL",
    "/": "DIV",
    "MOD": "MOD",
    "**": "EXPT",
    "AND": "AND",
    "OR": "OR",
    "AND_THEN": "AND_THEN",
    "OR_ELSE": "OR_ELSE",
    "XOR": "XOR",
    "=": "EQ",
    "<>": "NE",
    "<": "LT",
    ">": "GT",
    "<=": "LE",
    ">=": "GE",
}
_TIME_CATEGORIES = {"time", "tod", "dt", "date"}
_COMPARISONS = frozenset({"EQ", "NE", "LT", "GT", "LE", "GE"})


def lower_expr(node: ast.Expr, ctx: PouContext, expected: IrType | None = None) -> Expr:
    """The IR of a checked expression; ``expected`` is the type an untyped literal should take.

    Raises ``LoweringError`` for what the engine cannot run yet (pointers, unnamed
    direct addresses ...) and for nodes the checker typed as errors; report it with
    ``ctx.report_error``.
    """
    try:
        return _lower(node, ctx, expected)
    except LoweringError as error:
        if error.node is None:  # located at the innermost expression it arose in
            error.node = node
        raise


def _lower(node: ast.Expr, ctx: PouContext, expected: IrType | None) -> Expr:
    ty = node.ty
    if ty is None or ty is t.ERROR or ty is t.VOID:
        raise LoweringError(None)
    if type(node) is ast.Name and type(node.ref) is Symbol:  # the commonest node by far: a declared variable
        return lower_access(node, ctx)
    if isinstance(ty, t.UNTYPED):  # not settled by the checker (a diagram's placeholder): the expected type decides
        return _untyped(node, ctx, expected)
    if type(node) in _NUMERIC_LITERALS or (type(node) in _OPERATIONS and literal_only(node)):
        return _folded(node, ctx.ir_type(ty))
    if isinstance(node, (ast.BoolLit, ast.StringLit, ast.TimeLit, ast.TypedLit)):
        return _literal(node, ctx)
    if isinstance(node, (ast.Name, ast.Member)) and isinstance(node.ref, EnumValue):  # Green, Color.Green
        return Const(node.ref.value, ctx.ir_type(ty))
    if ty is t.NULL:
        return Const(None, ctx.ir_type(ty))
    if is_part(node):
        return _bit(node, ctx)
    if isinstance(getattr(node, "ref", None), PropertyRef):
        return property_call(node, ctx, None)
    if isinstance(node, (ast.Name, ast.DirectAddr, ast.Member, ast.Index, ast.Deref)):
        return lower_access(node, ctx)
    if isinstance(node, ast.Unary):
        return _unary(node, ctx)
    if isinstance(node, ast.Binary):
        return _binary(node, ctx)
    if isinstance(node, ast.Fit):
        return Fit(lower_expr(node.operand, ctx), ctx.ir_type(ty), print_expression(node.operand))
    return _call(node, ctx)


def lower_to(node: ast.Expr, ctx: PouContext, target: IrType) -> Expr:
    """``node`` as a value of ``target``: untyped literals take it, accepted widenings get a ``Convert``."""
    if isinstance(target, Reference) and isinstance(node.ty, (t.FbType, t.InterfaceType)):
        return interface_value(node, ctx, target)
    expr = lower_expr(node, ctx, target)
    if isinstance(target, Reference):
        return _reference_to(expr, target, node)
    return convert(expr, target)


def interface_value(node: ast.Expr, ctx: PouContext, target: Reference) -> Expr:
    """An instance (a reference to it) or an interface variable's reference, stored in an interface variable (the
    checker accepted it: st/interfaces.py)."""
    if isinstance(node.ty, t.InterfaceType):
        return lower_expr(node, ctx, target)
    return AddressOf(lower_access(node, ctx), target, print_expression(node))


def _reference_to(expr: Expr, target: Reference, node: ast.Expr | None) -> Expr:
    """A reference stored as a reference to ``target.target``: NULL, one to a variable of that very type, or a
    ``View`` of the variable's bytes as that type (a ``POINTER TO BYTE`` over a STRING: ir/byte_layout.py) when
    both types have a byte layout."""
    if isinstance(expr, Const) and (expr.value is None or (expr.value == 0 and isinstance(expr.type, Elementary))):
        return Const(None, target)  # NULL, or CODESYS's 0 (the checker let it through: st/types.null_literal)
    if isinstance(expr.type, Elementary) and t.address_number(expr.type.name):  # ``pt := dw`` (CODESYS typing)
        return Convert(expr, expr.type, addressed(target, node))
    if not isinstance(expr.type, Reference):
        raise LoweringError(f"a {_reference_text(target)} cannot refer to {_referred_text(expr.type)}", node)
    instances = isinstance(expr.type.target, FbInstance) and isinstance(target.target, FbInstance)
    if instances or same_target(expr.type.target, target.target):
        return expr  # (FBs: a derived FB's instance the checker accepted, whose methods are dispatched by its class)
    specs = view_specs(expr.type.target, target.target)
    if isinstance(specs, str):
        raise LoweringError(specs, node)
    return View(expr, target, *specs)


def _reference_text(ty: Reference) -> str:
    return f"REF_TO {describe(ty.target)}"


def _referred_text(ty: IrType) -> str:
    return article(describe(ty.target)) if isinstance(ty, Reference) else describe(ty)


def convert(expr: Expr, target: IrType) -> Expr:
    """``expr`` stored in ``target``: a ``Convert`` for an accepted widening; a reference copied into a reference
    whose target differs from its own by a subrange or an enumeration (an output ``q => p``) sees its variable
    through a view."""
    source = expr.type
    if source is target:  # the common case: lowered types are mostly shared instances
        return expr
    if isinstance(source, Reference) and isinstance(target, Elementary):  # ``dw := pt`` (CODESYS typing, checked)
        return Convert(expr, addressed(source, None), target)
    if (
        isinstance(source, Elementary | Subrange)
        and isinstance(target, Elementary | Subrange)
        and value_type(source) != value_type(target)
    ):
        return Convert(expr, value_type(source), value_type(target))
    if (
        isinstance(source, Reference)
        and isinstance(target, Reference)
        and (has_checked_values(source.target) or has_checked_values(target.target))
    ):
        return _reference_to(expr, target, None)
    return expr


def addressed(pointer: Reference, node: ast.Expr | None) -> Reference:
    """``pointer``, whose address is taken as a number or resolved from one: its target needs a byte layout, as the
    engine sees the variable an address lies in through its bytes (engine/codegen/addresses.py)."""
    reason = byte_layout(pointer.target)
    if isinstance(reason, str):
        raise LoweringError(f"a pointer as a number needs the bytes of what it points to: {reason}", node)
    return pointer


def value_type(ty: IrType) -> IrType:
    """The type a value computes in: a Subrange's base, STRING whatever its length (a WSTRING's too: one Python str)."""
    if isinstance(ty, Subrange):
        return ty.base
    if isinstance(ty, Elementary) and (ty.length is not None or ty.wide):
        return Elementary(ty.name)
    return ty


# ---------------------------------------------------------------- literals and constants


_NUMERIC_LITERALS = (ast.IntLit, ast.RealLit)
_OPERATIONS = (ast.Unary, ast.Binary)


def _folded(node: ast.Expr, target: IrType) -> Const:
    """A literal expression as one constant of its settled type (the checker reported values that do not fit)."""
    base = value_type(target)
    try:
        value = fold(node, _checker_type(base))
    except FoldError:
        raise LoweringError(None) from None
    return Const(engine_value(value, target), target)


def _checker_type(ty: IrType) -> t.Type:
    return t.Elementary(ty.name) if isinstance(ty, Elementary) and ty.name in ELEMENTARY else t.ERROR


def _untyped(node: ast.Expr, ctx: PouContext, expected: IrType | None) -> Expr:
    """An untyped literal expression the checker did not settle: it takes ``expected`` when it may (as the checker's
    settle would), else its default type."""
    target = _literal_target(node, ctx, expected)
    if literal_only(node):
        return _folded(node, target)
    if isinstance(node, ast.Call):
        return _sizeof(node, ctx, target)
    raise LoweringError(None)


def _literal_target(node: ast.Expr, ctx: PouContext, expected: IrType | None) -> IrType:
    """The expected type when the untyped literal may take it (a subrange's base: the store checks the range)."""
    base = value_type(expected) if expected is not None else None
    if isinstance(base, Elementary) and base.name in ELEMENTARY and t.takes_literal(_checker_type(base), node.ty):
        return base
    return ctx.ir_type(t.concrete(node.ty))


def _literal(node: ast.Expr, ctx: PouContext) -> Const:
    if isinstance(node, ast.StringLit):
        length = len(node.value) if len(node.value) > DEFAULT_STRING_LENGTH else None
        return Const(node.value, Elementary("STRING", length))
    ty = ctx.ir_type(node.ty)
    raw = ctx.types.raw_constant(node)
    if raw is None:
        raise LoweringError(None)
    return Const(engine_value(raw, ty), ty)


# ---------------------------------------------------------------- variables


def program_instance(node: ast.Expr, program: PouInfo, ctx: PouContext, use: str = "read") -> Var:
    """``Prog.x`` read or ``Prog(...)`` called from another POU: the instance named after the program (the engine
    keeps program instances among the globals, CODESYS's one instance of a program); a configuration that names
    its instances otherwise is read through those names."""
    configuration = ctx.checked.configuration
    name = program.name.upper()
    if configuration is not None and name not in configuration.instances:
        names = [i.name for i in configuration.instances.values() if i.pou is program]
        where = f"its instance{'s' if len(names) > 1 else ''} {', '.join(names)}" if names else "no instance"
        raise LoweringError(
            f"the program {program.name} runs as {where}: other POUs {use} the instance named like the program "
            f"(PROGRAM {program.name} : {program.name} in the configuration)",
            node,
        )
    return Var("global", name, FbInstance(name))


def lower_access(node: ast.Expr, ctx: PouContext) -> Var:
    """A variable access path: a declared variable, then ``[i]`` and ``.field`` / ``.PIN`` selectors; a CODESYS
    REFERENCE TO read through (the checker marked it ``deref``) gets the ``^`` it stands for."""
    var = _access(node, ctx)
    if getattr(node, "deref", None):
        if not isinstance(var.type, Reference):
            raise LoweringError(None)
        return Var(var.scope, var.name, var.type.target, (*var.path, Deref()))
    return var


def _access(node: ast.Expr, ctx: PouContext) -> Var:
    if isinstance(node, (ast.Name, ast.DirectAddr)):
        ref = node.ref
        if isinstance(ref, Symbol):
            ctx.reads += 1
            return ctx.var_for(ref)
        if isinstance(ref, PouInfo) and ref.kind == "PROGRAM":  # another program's outputs or SFC steps (ST-60)
            return program_instance(node, ref, ctx)
        if isinstance(ref, PouInfo):
            return ctx.result_var()
        if isinstance(node, ast.DirectAddr):  # used without a declaration: its size's default type (ST-13)
            return ctx.direct(node.address, ctx.ir_type(node.ty))
        raise LoweringError(None)
    if isinstance(getattr(node, "ref", None), PropertyRef):  # read with lower_expr, assigned by lower_st._assign
        raise LoweringError(
            f"the property {node.ref.name} is not a variable: read it or assign it with ':=' in ST (its GET and SET "
            "run then), it cannot be passed or written by reference here",
            node,
        )
    if list_qualified(node):  # GVL.x: the global x (st/gvls.py)
        return _access(node.base, ctx)
    if isinstance(node, ast.Member) and not is_part(node):
        base = lower_access(node.base, ctx)
        return Var(base.scope, base.name, _member_type(node, base.type, ctx), (*base.path, member(node.name.upper())))
    if isinstance(node, ast.Index):
        return _index(node, ctx)
    if is_self(node):  # THIS^ / SUPER^ (st/methods.py)
        return ctx.this_var()
    if isinstance(node, ast.Deref):
        base = lower_access(node.base, ctx)
        if not isinstance(base.type, Reference):
            raise LoweringError(None)
        return Var(base.scope, base.name, base.type.target, (*base.path, Deref()))
    if isinstance(node, ast.Member):
        raise LoweringError(
            "a bit or part of a variable (x.3, x.%B1) can be read or assigned, but not passed by reference", node
        )
    raise LoweringError(
        "only a variable, array element or field can be used here: assign this value to a variable first", node
    )


def _member_type(node: ast.Member, base: IrType, ctx: PouContext) -> IrType:
    upper = node.name.upper()
    if isinstance(base, Struct):
        for field in base.fields:
            if field.name == upper:
                return field.type
        raise LoweringError(None)
    if isinstance(base, FbInstance) and isinstance(node.ref, Symbol):  # a user FB's input or output
        return ctx.types_for(node.ref.pou).type_of(node.ref.type, node.ref.type_spec)
    if isinstance(base, FbInstance):  # a standard FB's pin, or EN / ENO
        return ctx.ir_type(node.ty)
    raise LoweringError(None)


def _index(node: ast.Index, ctx: PouContext) -> Var:
    if isinstance(node.base.ty, t.StringType):
        raise LoweringError("indexing a STRING is not supported: use MID(s, 1, i) to get one character", node)
    if isinstance(node.base.ty, t.PointerType):
        return _pointer_index(node, ctx)
    base = lower_access(node.base, ctx)
    if not isinstance(base.type, Array):
        raise LoweringError(None)
    indices = tuple(lower_expr(index, ctx) for index in node.indices)
    return Var(base.scope, base.name, base.type.element, (*base.path, Index(indices)))


def _pointer_index(node: ast.Index, ctx: PouContext) -> Var:
    """CODESYS ``p[i]``: ``(p + i * SIZEOF(p^))^``, the i-th element on from the one p points to (the engine faults
    when it leaves the array p points into, as for ``p + n``). The moved pointer is computed before the statement,
    into a hidden temporary, like a lifted call: so only where such a call could be (ctx.lifts)."""
    if len(node.indices) != 1:
        raise LoweringError("a pointer takes one index: p[i] is (p + i * SIZEOF(p^))^", node)
    if ctx.lifts is None or ctx.calls:
        raise LoweringError(
            "p[i] cannot be evaluated here in the right order: assign p[i] to a variable in a statement of its own "
            "first",
            node,
        )
    pointer = _sized(lower_expr(node.base, ctx))
    reference = pointer.type
    if not isinstance(reference, Reference):
        raise LoweringError(None)
    dint = Elementary("DINT")
    offset = Binary("MUL", lower_to(node.indices[0], ctx, dint), Const(byte_size(reference.target), dint), dint)
    moved = ctx.hidden("POINTER_INDEX", reference, var_class="VAR_TEMP")
    ctx.lifts.append(Assign(moved, Binary("ADD", pointer, offset, reference), ctx.origin(node)))
    return Var(moved.scope, moved.name, reference.target, (*moved.path, Deref()))


_BITS_OF_WIDTH = {8: "BYTE", 16: "WORD", 32: "DWORD", 64: "LWORD"}
_SHIFT_COUNT = Elementary("INT")


def is_part(node: ast.Expr) -> TypeGuard[ast.Member]:
    """Bit access ``x.3`` / ``x.%X3`` or partial access ``x.%B1`` (a member that is no field or pin)."""
    return isinstance(node, ast.Member) and partial_access(node.name) is not None


def bit_access(node: ast.Member, ctx: PouContext) -> tuple[Var, Elementary, Expr, Elementary, int, int]:
    """``x.%B1`` -> (x, its type, x as a bit string, that bit string's type, the part's width in bits, its
    shift); integers go through their same-width bit string (``INT_TO_WORD``), the two's complement pattern."""
    var = lower_access(node.base, ctx)
    ty = value_type(var.type)
    width, index = partial_access(node.name) or (0, 0)
    if not isinstance(ty, Elementary) or not ty.info.bits or width == 0 or (index + 1) * width > ty.info.bits:
        raise LoweringError(None)
    if ty.info.category == "bits":
        return var, ty, var, ty, width, index * width
    bits_type = Elementary(_BITS_OF_WIDTH[ty.info.bits])  # AND/OR work on ANY_BIT
    return var, ty, Call(f"{ty.name}_TO_{bits_type.name}", (var,), (ty,), bits_type), bits_type, width, index * width


def _shifted(name: str, value: Expr, ty: Elementary, shift: int) -> Expr:
    return Call(name, (value, Const(shift, _SHIFT_COUNT)), (ty, _SHIFT_COUNT), ty) if shift else value


def _resized(value: Expr, source: Elementary, target: Elementary) -> Expr:
    return value if source == target else Call(f"{source.name}_TO_{target.name}", (value,), (source,), target)


def _bit(node: ast.Member, ctx: PouContext) -> Expr:
    """Bit access ``x.3`` reads as ``(x AND 2#1000) <> 0``; a part ``x.%B1`` as ``DWORD_TO_BYTE(SHR(x, 8))``."""
    _, _, bits, ty, width, shift = bit_access(node, ctx)
    if width == 1:
        mask = Const(engine_value(1 << shift, ty), ty)
        return Binary("NE", Binary("AND", bits, mask, ty), Const(0, ty), BOOL)
    return _resized(_shifted("SHR", bits, ty, shift), ty, Elementary(part_type(width)))


def assign_part(target: ast.Member, value: Expr, ctx: PouContext) -> tuple[Var, Expr]:
    """``x.3 := b`` stores ``SEL(b, x AND NOT 2#1000, x OR 2#1000)``; ``x.%B1 := v`` stores
    ``(x AND NOT 16#FF00) OR SHL(BYTE_TO_DWORD(v), 8)`` (integers through their bit string)."""
    var, var_type, bits, ty, width, shift = bit_access(target, ctx)
    mask = ((1 << width) - 1) << shift
    cleared = Binary("AND", bits, Const(engine_value(~mask, ty), ty), ty)
    if width == 1:
        updated: Expr = Call(
            "SEL", (value, cleared, Binary("OR", bits, Const(engine_value(mask, ty), ty), ty)), (BOOL, ty, ty), ty
        )
    else:
        part = Elementary(part_type(width))
        updated = Binary("OR", cleared, _shifted("SHL", _resized(value, part, ty), ty, shift), ty)
    return var, _resized(updated, ty, var_type)


# ---------------------------------------------------------------- operators


def _unary(node: ast.Unary, ctx: PouContext) -> Expr:
    ty = ctx.ir_type(node.ty)
    return Unary("NOT" if node.op == "NOT" else "NEG", lower_to(node.operand, ctx, ty), ty)


def _binary(node: ast.Binary, ctx: PouContext) -> Expr:
    op = _OPERATORS[node.op]
    left_ty, right_ty = node.left.ty, node.right.ty
    if op == "EXPT":
        return _power(node, ctx)
    if op in ("AND_THEN", "OR_ELSE"):
        return _short_circuit(node, op, ctx)
    if t.category(left_ty) == "string" and op == "ADD":  # FUN-82: '+' concatenates
        return _function("CONCAT", [node.left, node.right], ctx, ctx.ir_type(node.ty))
    if op in ("ADD", "SUB", "MUL", "DIV") and {t.category(left_ty), t.category(right_ty)} & _TIME_CATEGORIES:
        mixed = _time_operator(node, op, ctx)
        if mixed is not None:
            return mixed
    references = (t.PointerType, t.NullType, t.InterfaceType)
    if isinstance(left_ty, references) or isinstance(right_ty, references):
        return _reference_operation(node, op, ctx)
    if op in _COMPARISONS:  # the checker settled both operands to types whose lub is the one compared in
        operand = ctx.ir_type(t.lub(left_ty, right_ty) or t.concrete(t.common(left_ty, right_ty)[0]))
        result = BOOL
    else:
        operand = result = ctx.ir_type(node.ty)
    return Binary(op, lower_to(node.left, ctx, operand), lower_to(node.right, ctx, operand), result)  # type: ignore[arg-type]


def _short_circuit(node: ast.Binary, op: str, ctx: PouContext) -> Expr:
    """AND_THEN / OR_ELSE: the right operand may not run, so nothing of it is evaluated ahead of the statement
    (a call with EN/ENO there is IR-EN-CALL, as in a WHILE condition)."""
    left = lower_to(node.left, ctx, BOOL)
    saved, ctx.lifts = ctx.lifts, None
    try:
        right = lower_to(node.right, ctx, BOOL)
    finally:
        ctx.lifts = saved
    return Binary(op, left, right, BOOL)  # type: ignore[arg-type]  # op is AND_THEN or OR_ELSE


#: The unsigned integer a bit string of each width holds, as CODESYS adds it to an address.
_UNSIGNED = {8: "USINT", 16: "UINT", 32: "UDINT", 64: "ULINT"}


def _sized(pointer: Expr) -> Expr:
    """``pointer``, once what it points to has a size: the engine moves and orders pointers by it, so a target
    without one (a STRUCT CODESYS lays out differently on different targets, an FB instance) is refused here."""
    try:
        byte_size(pointer.type.target)  # type: ignore[union-attr]  # a pointer (the checker)
    except LoweringError as error:
        raise LoweringError(
            f"moving or ordering pointers needs the size of what they point to: {error.message}"
        ) from None
    return pointer


def _reference_operation(node: ast.Binary, op: str, ctx: PouContext) -> Expr:
    """``r1 = r2``, ``r <> NULL``: whether two references refer to one variable. ``p + n`` / ``p - n`` (bytes,
    CODESYS): the pointer moved along the array it points into (the engine checks it stays there). ``p < q`` ...
    order two pointers into one variable by the byte they point to (the engine faults on different variables)."""
    if op in ("ADD", "SUB") and isinstance(node.left.ty, t.PointerType) and t.moves_a_pointer(node.right.ty):
        pointer = _sized(lower_expr(node.left, ctx))
        offset = lower_expr(node.right, ctx, Elementary("DINT"))
        if isinstance(offset.type, Elementary) and offset.type.info.category == "bits":  # the number it holds
            offset = convert(offset, Elementary(_UNSIGNED[offset.type.info.bits]))
        return Binary(op, pointer, offset, pointer.type)  # type: ignore[arg-type]  # a Reference is a value type here
    if op in ("ADD", "SUB"):
        raise LoweringError(POINTER_ARITHMETIC, node)
    if t.holds_address(node.left.ty, node.right.ty) or t.holds_address(node.right.ty, node.left.ty):
        number = node.left.ty if isinstance(node.right.ty, t.PointerType) else node.right.ty
        operand = ctx.ir_type(number)  # CODESYS typing: the pointer's address compared with the number
        return Binary(op, lower_to(node.left, ctx, operand), lower_to(node.right, ctx, operand), BOOL)  # type: ignore[arg-type]
    if op not in ("EQ", "NE"):
        if not (isinstance(node.left.ty, t.PointerType) and isinstance(node.right.ty, t.PointerType)):
            raise LoweringError(f"'{node.op}' orders two pointers, not a pointer and a number", node)
        left, right = _sized(lower_expr(node.left, ctx)), _sized(lower_expr(node.right, ctx))
        return Binary(op, left, right, BOOL)  # type: ignore[arg-type]  # LT..GE
    left, right = lower_expr(node.left, ctx), lower_expr(node.right, ctx)
    if isinstance(left, Const) and left.value in (None, 0):  # NULL (an interface's 0) takes the other's type
        left = Const(None, right.type)
    if isinstance(right, Const) and right.value in (None, 0):
        right = Const(None, left.type)
    return Binary(op, left, right, BOOL)  # type: ignore[arg-type]  # EQ/NE


def _time_operator(node: ast.Binary, op: str, ctx: PouContext) -> Expr | None:
    """TOD + TIME, DT - DT, TIME * ANY_NUM ...: the FUN-85 function behind the operator (None: TIME +/- TIME)."""
    left, right = (ctx.ir_type(t.concrete(x)) for x in (node.left.ty, node.right.ty))
    result = ctx.ir_type(node.ty)
    if value_type(left) == value_type(right) == value_type(result):
        return None
    operands = [node.left, node.right]
    if op == "MUL" and t.category(node.right.ty) == "time":  # ANY_NUM * TIME = MUL_TIME(TIME, ANY_NUM)
        operands.reverse()
        left, right = right, left
    name = OPERATOR_OVERLOADS.get((op, (_category(left), _category(right))))
    if name is None:
        raise LoweringError(None)
    return _function(name, operands, ctx, result, (left, right))


def _category(ty: IrType) -> str:
    base = value_type(ty)
    return base.info.category if isinstance(base, Elementary) else ""


def _power(node: ast.Binary, ctx: PouContext) -> Expr:
    """``a ** b``: one Binary when both are the same type (a literal exponent takes the base's), else EXPT."""
    result = ctx.ir_type(node.ty)
    if isinstance(node.right.ty, t.UNTYPED) or t.same(node.ty, node.right.ty):
        return Binary("EXPT", lower_to(node.left, ctx, result), lower_to(node.right, ctx, result), result)
    exponent = ctx.ir_type(node.right.ty)
    return _function("EXPT", [node.left, node.right], ctx, result, (result, exponent))


def _function(
    name: str, operands: list[ast.Expr], ctx: PouContext, result: IrType, arg_types: tuple[IrType, ...] | None = None
) -> Call:
    types = arg_types or (result,) * len(operands)
    args = tuple(lower_to(operand, ctx, ty) for operand, ty in zip(operands, types))
    return Call(name, args, tuple(types), result)


# ---------------------------------------------------------------- calls


def _call(node: ast.Call, ctx: PouContext) -> Expr:
    if node.ref is None and isinstance(node.callee, ast.Name) and node.callee.name.upper() == "SIZEOF":
        return _sizeof(node, ctx, ctx.ir_type(node.ty))
    if node.ref is None and isinstance(node.callee, ast.Name) and node.callee.name.upper() in ("ADR", "REF"):
        return _address_of(node, ctx)
    if node.ref is None and isinstance(node.callee, ast.Name) and node.callee.name.upper() == "__ISVALIDREF":
        reference = lower_access(node.args[0].value, ctx)
        return Binary("NE", reference, Const(None, reference.type), BOOL)
    ref = node.ref
    en, eno = _en_eno(node)
    before = (ctx.reads, ctx.calls)
    if isinstance(ref, stdlib.StdFunction):
        if ref.name == "MOVE" and en is None and eno is None:  # FUN-32: MOVE is an assignment
            return lower_expr(_arguments(node)[0].value, ctx, ctx.ir_type(node.ty))
        call = std_call(node, ctx)
    elif isinstance(ref, PouInfo) and ref.kind == "FUNCTION":
        call = user_call(node, ctx)
    else:
        raise LoweringError(None)
    if en is None and eno is None:
        return call
    return _lift(node, call, before, ctx)


def lower_input(value: ast.Expr, ctx: PouContext, ty: IrType) -> Expr:
    """An input's value; a REFERENCE TO input given a variable (the checker bound it, CODESYS) gets a reference; a
    pointer input given CODESYS's 0 gets NULL (st/types.null_literal)."""
    references = (t.PointerType, t.NullType, t.InterfaceType, t.FbType)  # an interface input: lower_to (interfaces)
    if isinstance(ty, Reference) and not isinstance(value.ty, references) and not isinstance(value, ast.IntLit):
        return address_of(value, ty, f"REF({print_expression(value)})", ctx)
    return lower_to(value, ctx, ty)


def address_of(value: ast.Expr, ty: Reference, text: str, ctx: PouContext) -> Expr:
    """A reference of type ``ty`` to the variable ``value`` (``r REF= x``, a REFERENCE TO input given ``x``): seen
    through a view when ``x`` is of another type as far as subranges go (``_reference_to``)."""
    return _reference_to(_reference_of(value, ty, text, ctx), ty, value)


def _reference_of(value: ast.Expr, ty: IrType, text: str, ctx: PouContext) -> AddressOf:
    """A reference to the variable ``value`` (the checker refused temporaries) typed ``ty``, the checker's type, but
    for a variable with a subrange (or an array of one), whose own type it is: the checker's loses the range, which a
    reference to the base type must then keep (``_reference_to``); ``text`` shows it."""
    var = lower_access(value, ctx)
    return AddressOf(var, Reference(var.type) if has_checked_values(var.type) else ty, text)


def retarget(expr: Expr, target: Reference, node: ast.Expr) -> Expr:
    """``expr``, lowered as a reference of the checker's type (a subrange's base), as one of the declared ``target``
    (the subrange), which may need a view the checker's type did not."""
    return _reference_to(expr.value if isinstance(expr, View) else expr, target, node)


def _address_of(node: ast.Call, ctx: PouContext) -> AddressOf:
    """``REF(x)`` / ``ADR(x)``: a reference to the variable ``x``."""
    if len(node.args) != 1:
        raise LoweringError(None)
    text = f"{node.callee.name.upper()}({print_expression(node.args[0].value)})"  # type: ignore[union-attr]  # a Name
    return _reference_of(node.args[0].value, ctx.ir_type(node.ty), text, ctx)


def _sizeof(node: ast.Call, ctx: PouContext, target: IrType) -> Const:
    """``SIZEOF(x)`` / ``SIZEOF(TypeName)``: the size in bytes (``lower_types.byte_size``) as a constant."""
    if not isinstance(node.callee, ast.Name) or node.callee.name.upper() != "SIZEOF" or len(node.args) != 1:
        raise LoweringError(None)
    argument = node.args[0].value
    if argument.ty is None and isinstance(argument, ast.Name):  # a type name (the checker does not type it)
        named = t.elementary(argument.name)
        typedef = ctx.checked.types.get(argument.name.upper())
        ty = ctx.types.type_of(
            named if named is not None else typedef.type if typedef else None, ast.NamedType(argument.name)
        )
    elif isinstance(argument.ty, t.InterfaceType):
        raise LoweringError("SIZEOF of an interface variable is refused: LadderLab does not lay out what it holds")
    else:
        ty = lower_expr(argument, ctx).type
    return Const(engine_value(byte_size(ty), target), target)


def _en_eno(node: ast.Call) -> tuple[ast.Arg | None, ast.Arg | None]:
    en = next((a for a in node.args if a.name is not None and a.name.upper() == "EN" and not a.output), None)
    eno = next((a for a in node.args if a.name is not None and a.name.upper() == "ENO" and a.output), None)
    return en, eno


def _arguments(node: ast.Call) -> list[ast.Arg]:
    """The call's arguments without EN and ENO."""
    return [a for a in node.args if a.name is None or a.name.upper() not in ("EN", "ENO")]


def lower_en_eno(node: ast.Call, ctx: PouContext) -> tuple[Expr | None, Var | None, list[Assign]]:
    """EN as a BOOL expression, ENO as a variable; ``NOT ENO => x`` needs an Assign after the call."""
    en, eno = _en_eno(node)
    name = node.callee.name.upper() if isinstance(node.callee, ast.Name) else ""
    for arg in (en, eno):
        if arg is not None and arg.value.ty is None:
            ctx.check_en_eno(arg.value, name, arg.output)
    en_expr = lower_to(en.value, ctx, BOOL) if en is not None else None
    if eno is None:
        return en_expr, None, []
    target = lower_access(eno.value, ctx)
    if not eno.negated:
        return en_expr, target, []
    flag = ctx.hidden("ENO", BOOL, var_class="VAR_TEMP")
    return en_expr, flag, [Assign(target, Unary("NOT", flag, BOOL), ctx.origin(eno))]


def _lift(node: ast.Call, call: Call, before: tuple[int, int], ctx: PouContext) -> Var:
    """Evaluate a call with EN/ENO as a ``FnCall`` before the statement, into a hidden temporary.

    ``before`` counts the variable reads and user function calls the statement evaluated before
    this call: a user function could change those variables, and any user function could change
    what this call reads, so then the call cannot move ahead of them.
    """
    reads, calls = before
    where = (
        "here"
        if ctx.lifts is None
        else "after the values this statement computes before it"
        if calls or (call.user and reads)
        else None
    )
    if where is not None:
        raise LoweringError(
            f"a call with EN or ENO cannot be evaluated {where} in the right order: assign its "
            "result to a variable in a statement of its own first",
            node,
            code="IR-EN-CALL",
        )
    en_expr, eno_var, after = lower_en_eno(node, ctx)
    result = ctx.hidden(f"{call.function}_RESULT", call.type)
    ctx.lifts.append(FnCall(call, result, ctx.origin(node), en_expr, eno_var))
    ctx.lifts.extend(after)
    return result


def std_call(node: ast.Call, ctx: PouContext) -> Call:
    """A standard function call, arguments in IEC formal order (docs/runtime.md), missing ones as defaults."""
    function: stdlib.StdFunction = node.ref
    bound: dict[int, ast.Arg] = {}
    for position, arg in enumerate(_arguments(node)):
        index = position if arg.name is None else _position(function, arg.name)
        if index is None:
            raise LoweringError(None)
        bound[index] = arg
    types, result = _signature(function, node, bound, ctx)
    args = tuple(
        lower_to(bound[index].value, ctx, target) if index in bound else Const(ir_default(target), target)
        for index, target in enumerate(types)
    )
    return in_seconds(_narrowed_text(Call(function.name, args, types, result)))  # (a call statement's node has no .ty)


def _narrowed_text(call: Call) -> Call:
    """An overloaded ``TO_STRING`` of a WSTRING as ``WSTRING_TO_STRING``, which checks its characters are ones a
    STRING holds (engine/stdlib/conversions.py): the value model keeps both strings alike, the call's name tells."""
    source = call.arg_types[0] if len(call.arg_types) == 1 else None
    wide = isinstance(source, Elementary) and source.wide
    if wide and call.function.upper() == "TO_STRING":
        return Call("WSTRING_TO_STRING", call.args, call.arg_types, call.type)
    return call


def _signature(
    function: stdlib.StdFunction, node: ast.Call, bound: dict[int, ast.Arg], ctx: PouContext
) -> tuple[tuple[IrType, ...], IrType]:
    """The IR types of a standard function call's inputs (by position, omitted ones included) and of its
    result. They follow from the function, the bound positions, the argument types and the call's type
    alone, so they are worked out once per POU for each such combination (a large diagram has thousands
    of alike boxes)."""
    key = (function.name, node.ty, *((index, bound[index].value.ty) for index in sorted(bound)))
    try:
        signature = ctx.signatures.get(key)
    except TypeError:  # a type that cannot be a key: work it out every time
        return _work_out_signature(function, node, bound, ctx)
    if signature is None:
        signature = ctx.signatures[key] = _work_out_signature(function, node, bound, ctx)
    return signature


def _work_out_signature(
    function: stdlib.StdFunction, node: ast.Call, bound: dict[int, ast.Arg], ctx: PouContext
) -> tuple[tuple[IrType, ...], IrType]:
    count = max(len(function.inputs), max(bound, default=-1) + 1)
    generic = _generic_type(function, node, bound, ctx)
    types = []
    for index in range(count):
        pin = function.pin(function.input_name(index))  # type: ignore[arg-type]
        arg = bound.get(index)
        if pin.generic:
            target = generic
        elif pin.type in GENERIC:  # ANY_INT positions and counts, ANY_NUM factors: the argument's own type
            target = ctx.ir_type(t.concrete(arg.value.ty)) if arg is not None else Elementary("INT")
        else:
            target = ctx.ir_type(t.elementary(pin.type))
        types.append(target)
    result = generic if function.result == stdlib.T else ctx.ir_type(t.elementary(function.result))
    return tuple(types), result


def _position(function: stdlib.StdFunction, name: str) -> int | None:
    upper = name.upper()
    for index, pin in enumerate(function.inputs):
        if pin.name == upper:
            return index
    if function.pin(upper) is None:
        return None
    last = function.inputs[-1].name
    stem = last.rstrip("0123456789")
    return len(function.inputs) - 1 + int(upper[len(stem) :]) - int(last[len(stem) :])


def _generic_type(function: stdlib.StdFunction, node: ast.Call, bound: dict[int, ast.Arg], ctx: PouContext) -> IrType:
    """The type T the generic inputs share: the call's own type when its result is T (settled by the checker,
    st/context_typing.py), else the lub of its settled generic arguments (a comparison)."""
    if function.result == stdlib.T and node.ty is not None and not isinstance(node.ty, t.UNTYPED):
        return ctx.ir_type(node.ty)
    shared: t.Type | None = None
    for index in sorted(bound):
        pin = function.pin(function.input_name(index))  # type: ignore[arg-type]
        if pin is not None and pin.generic:
            ty = bound[index].value.ty
            shared = ty if shared is None else (t.lub(shared, ty) or t.common(shared, ty)[0])
    if shared is None:
        return ctx.ir_type(node.ty) if function.result == stdlib.T else Elementary("INT")
    return ctx.ir_type(t.concrete(shared))


def property_call(node: ast.Name | ast.Member, ctx: PouContext, value: ast.Expr | None) -> Call:
    """Reading a PROPERTY (``value`` None: its GET) or writing it (its SET with ``value``): a call of the accessor
    on the instance (``inst.P``; ``P`` in its FB's own code: THIS), chosen by the instance's FB."""
    prop: PropertyRef = node.ref
    accessor = prop.setter if value is not None else prop.getter
    if accessor is None:
        raise LoweringError(
            f"the property {prop.name} has no GET: it can be assigned, not read", node, code="ST-READONLY"
        )
    this = lower_access(node.base, ctx) if isinstance(node, ast.Member) else ctx.this_var()
    if isinstance(this.type, Reference):
        this = Var(this.scope, this.name, this.type.target, (*this.path, Deref()))
    ty = ctx.types_for(accessor.name).type_of(prop.type)
    args = (lower_to(value, ctx, ty),) if value is not None else ()
    ctx.calls += 1
    result = ty if value is None else BOOL
    virtual = not (isinstance(node, ast.Member) and is_super(node.base))  # SUPER^.P: the base's accessor
    return Call(accessor.name.upper(), args, (ty,) if value is not None else (), result, True, (this,), virtual)


def user_call(node: ast.Call, ctx: PouContext, after: list[Stmt] | None = None) -> Call:
    """A user function: inputs in VAR_INPUT order (omitted ones as their initial values), then the in-outs; a
    method's outputs follow as in-outs (ir/method_outputs.py), the copies they need after the call go to ``after``."""
    pou: PouInfo = node.ref
    callee = ctx.types_for(pou.name)
    parameters = pou.parameters("VAR_INPUT", "VAR_IN_OUT")
    given: dict[str, ast.Expr] = {}
    in_outs: list[Var] = []
    if pou.method is not None:  # the instance it is called on; a bare ``M()``: the caller's own
        instance = node.callee.base if isinstance(node.callee, ast.Member) else None
        if isinstance(instance, ast.Name) and isinstance(instance.ref, PouInfo):  # ``Prog.M()``: its one instance
            this = program_instance(instance, instance.ref, ctx, "call")
        else:
            this = lower_access(instance, ctx) if instance is not None else ctx.this_var()
        if isinstance(this.type, Reference):  # an interface variable: the instance it refers to
            this = Var(this.scope, this.name, this.type.target, (*this.path, Deref()))
        in_outs.append(this)
    for position, arg in enumerate(_arguments(node)):
        if arg.name is None and position >= len(parameters):
            raise LoweringError(None)
        given[(arg.name or parameters[position].name).upper()] = arg.value
    args, types = [], []
    for symbol in parameters:
        ty = callee.type_of(symbol.type, symbol.type_spec)
        value = given.get(symbol.name.upper())
        if symbol.var_class == "VAR_IN_OUT":
            if value is None:
                raise LoweringError(None)
            in_outs.append(lower_access(value, ctx))
            continue
        initial = callee.initial(symbol.type, symbol.type_spec, symbol.init)
        args.append(lower_input(value, ctx, ty) if value is not None else Const(initial, ty))
        types.append(ty)
    ctx.calls += 1
    if pou.method is None:
        result = callee.type_of(pou.return_type, pou.return_spec)
        return Call(pou.name.upper(), tuple(args), tuple(types), result, True, tuple(in_outs))
    in_outs += output_arguments(node, pou, ctx, after)
    # a method without a value returns an unused BOOL (lower_project.lower_pou); SUPER^.M() runs the base's M
    result = callee.type_of(pou.return_type, pou.return_spec) if pou.return_type is not None else BOOL
    virtual = not is_super(node.callee.base) if isinstance(node.callee, ast.Member) else True
    return Call(pou.name.upper(), tuple(args), tuple(types), result, True, tuple(in_outs), virtual)
