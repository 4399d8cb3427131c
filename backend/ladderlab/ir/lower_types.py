"""Checker types -> IR types, declared initial values -> engine values, symbols -> slots.

The checker resolves a subrange to its base type and keeps initial values as
AST, so both are recovered here from the type specifications: ``Symbol.type_spec``
and the TYPE declarations are walked alongside the resolved type. A variable of
``TYPE TPercent : INT (0..100)`` is a ``Subrange``, an array of ``THomeTemp``
elements starts with 20.0 in every element (TYP-11).

Initial values are engine values (docs/ir.md invariant 1, docs/runtime.md value
model) and always complete: an ARRAY's is a tuple of its elements' values (a
tuple of tuples for ``ARRAY [1..2, 1..3]``: one level per dimension, like the
engine's nested lists; IEC initialisers fill it in row-major order), a STRUCT's
a tuple of its field values in field order, an FB
instance's None or a tuple of ``(PIN, value)`` overrides (``t : TON := (PT := T#2s)``).
Tuples keep the frozen IR types (``StructField.initial``) hashable.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import Any

from .. import limits
from ..iec.addresses import incomplete
from ..iec.elementary import ELEMENTARY
from ..iec.values import default_value, f32, store_fn
from ..st import ast
from ..st import types as t
from ..st.body import BodyChecker
from ..st.printer import print_expression
from ..st.rules import EnumValue, constant_value
from ..st.symbols import CheckResult, PouInfo, Symbol, TypeDef
from .byte_layout import POINTER_BYTES, byte_layout, same_target, view_specs
from .nodes import Const, ReferenceInit, Slot, upper_name
from .types import (
    Array,
    Elementary,
    Enum,
    FbInstance,
    IrType,
    Reference,
    Struct,
    StructField,
    Subrange,
    fb_instance,
)

_ALIAS_DEPTH = 64  # longer TYPE alias chains than this are cycles the checker already reported


class LoweringError(Exception):
    """A construct the checker accepted that this lowering cannot express.

    ``message`` None means the cause was already reported by the checker (a type
    with errors), so nothing more is said. ``node`` locates the diagnostic.
    """

    def __init__(self, message: str | None, node: Any = None, code: str = "IR-UNSUPPORTED", file: str | None = None):
        super().__init__(message or "already reported")
        self.message, self.node, self.code, self.file = message, node, code, file


def _in_types_text(error: LoweringError) -> LoweringError:
    """An error in a TYPE declaration's initial value is located in the ``types`` text, wherever it is used."""
    if error.file is None:
        error.file = "types"
    return error


def _quiet(*_args: Any, **_kwargs: Any) -> None:
    """Constant folding during lowering re-reads checked expressions; the checker already reported on them."""


class TypeLowering:
    """Types, initial values and slots of one scope (a POU, or the globals when ``pou`` is None)."""

    def __init__(self, checked: CheckResult | None, pou: PouInfo | None = None):
        self.checked = checked if checked is not None else CheckResult()
        self.types: dict[str, TypeDef] = self.checked.types
        self.constants = BodyChecker(self.checked, pou, _quiet)  # scope for constant_value (CONSTANTs, enums)
        self._structs: dict[int, Struct] = {}

    # ------------------------------------------------------------ types
    def type_of(self, ty: t.Type | None, spec: ast.TypeSpec | None = None) -> IrType:
        """The IR type of a checker type; ``spec`` (the declaration's type specification) restores subranges."""
        if type(ty) is t.Elementary and (
            spec is None or (type(spec) is ast.NamedType and (not self.types or spec.name.upper() not in self.types))
        ):
            return _elementary(ty.name)  # most variables: no TYPE to follow (a shortcut of _type_of)
        if type(ty) is t.FbType:  # an instance, whatever its specification says (another shortcut of _type_of)
            return fb_instance(ty.name.upper())
        return self._type_of(ty, spec)

    def _type_of(self, ty: t.Type | None, spec: ast.TypeSpec | None) -> IrType:
        spec = self._spec_body(spec)
        if isinstance(ty, t.Elementary):
            if isinstance(spec, ast.SubrangeType):
                low, high = constant_value(self.constants, spec.low), constant_value(self.constants, spec.high)
                if isinstance(low, int) and isinstance(high, int) and low <= high:
                    return Subrange(Elementary(ty.name), low, high)
            return Elementary(ty.name)
        if isinstance(ty, t.StringType):
            if ty.length is not None and ty.length > limits.STRING_LENGTH.value:
                found = f"{'WSTRING' if ty.wide else 'STRING'}[{ty.length}] holds {ty.length:,} characters"
                raise LoweringError(limits.STRING_LENGTH.message(found), code="LIMIT-SIZE")
            return Elementary("STRING", ty.length, ty.wide)  # both are a Python str in the value model
        if isinstance(ty, (t.UntypedInt, t.UntypedReal)):
            return self.type_of(t.concrete(ty))
        if isinstance(ty, t.ArrayType):
            if any(dim is None for dim in ty.dims):
                raise LoweringError("open arrays (ARRAY [*]) are not supported by the engine yet")
            if any(low > high for low, high in ty.dims):  # type: ignore[misc]
                raise LoweringError(None)  # the checker reported the empty range
            element_spec = spec.element if isinstance(spec, ast.ArrayType) else None
            count = _size(Array(Elementary("BOOL"), tuple(ty.dims)))  # type: ignore[arg-type]  # no open dims here
            if count > limits.ARRAY_ELEMENTS.value:  # before anything is allocated for it
                raise LoweringError(
                    limits.ARRAY_ELEMENTS.message(f"the array has {count:,} elements"), code="LIMIT-SIZE"
                )
            array = Array(self.type_of(ty.element, element_spec), tuple(ty.dims))  # type: ignore[arg-type]  # as above
            count = scalar_count(array)
            if count > limits.ARRAY_ELEMENTS.value:  # an array of arrays or structures
                raise LoweringError(
                    limits.ARRAY_ELEMENTS.message(f"the array has {count:,} elements"), code="LIMIT-SIZE"
                )
            return array
        if isinstance(ty, t.EnumType):  # the values as declared: online views show them so (CODESYS does)
            return Enum(ty.name.upper(), tuple(ty.values.values()), ty.base)
        if isinstance(ty, t.StructType):
            return self._struct(ty, spec)
        if isinstance(ty, t.FbType):
            return fb_instance(ty.name.upper())
        if isinstance(ty, t.InterfaceType):  # a reference to the instance of an FB implementing it (or NULL)
            return Reference(FbInstance(ty.name.upper()))
        if isinstance(ty, t.PointerType):
            target_spec = spec.target if isinstance(spec, ast.PointerType) else None
            return Reference(self.type_of(ty.target, target_spec))
        if isinstance(ty, t.NullType):  # a bare NULL: it takes the type of the reference it is stored in
            return Reference(Elementary("BYTE"))
        raise LoweringError(None)  # ERROR / VOID / None: the checker reported why

    def _spec_body(self, spec: ast.TypeSpec | None) -> ast.TypeSpec | None:
        """Follow ``NamedType`` aliases of user TYPEs to the specification that defines them."""
        for _ in range(_ALIAS_DEPTH):
            typedef = self._typedef(spec)
            if typedef is None:
                return spec
            spec = typedef.decl.type
        return None

    def _typedef(self, spec: ast.TypeSpec | None) -> TypeDef | None:
        return self.types.get(spec.name.upper()) if isinstance(spec, ast.NamedType) else None

    def _struct(self, ty: t.StructType, spec: ast.TypeSpec | None) -> Struct:
        if id(ty) in self._structs:
            return self._structs[id(ty)]
        # registered before its fields are lowered: a field pointing to this STRUCT (a linked list's ``next``)
        # lowers to a Reference to this very object, whose fields are set once all are lowered
        lowered = self._structs[id(ty)] = Struct(ty.name.upper(), (), ty.pack_mode)
        fields = []
        try:
            for upper, (field_type, field_spec, init) in self._fields(ty, spec).items():
                try:
                    initial = self.initial(field_type, field_spec, init)
                except LoweringError as error:
                    raise _in_types_text(error) from None
                fields.append(StructField(upper, self.type_of(field_type, field_spec), initial))
        except LoweringError:
            del self._structs[id(ty)]
            raise
        object.__setattr__(lowered, "fields", tuple(fields))  # frozen: completed once, before anyone reads it
        return lowered

    def _fields(self, ty: t.StructType, spec: ast.TypeSpec | None) -> dict[str, tuple[t.Type, Any, Any]]:
        """Field name -> (resolved type, type specification, declared initial value), in declaration order."""
        if not isinstance(spec, ast.StructType):
            spec = next((self._spec_body(d.decl.type) for d in self.types.values() if d.type is ty), None)
        decls = {}
        if isinstance(spec, ast.StructType):
            decls = {n.name.upper(): decl for decl in spec.members for n in decl.names if n.name is not None}
        out = {}
        for upper, (_, field_type) in ty.fields.items():
            decl = decls.get(upper)
            out[upper] = (field_type, decl.type if decl else None, decl.init if decl else None)
        return out

    # ------------------------------------------------------------ values
    def default(self, ty: t.Type | None, spec: ast.TypeSpec | None = None) -> object:
        """The initial value of a variable declared without one: its TYPE's own (TYP-11), else the type default."""
        typedef = self._typedef(spec)
        if typedef is not None:
            if typedef.init is not None:
                try:
                    return self.initial(ty, typedef.decl.type, typedef.init)
                except LoweringError as error:
                    raise _in_types_text(error) from None
            return self.default(ty, typedef.decl.type)
        lowered = self.type_of(ty, spec)
        if isinstance(lowered, Array) and isinstance(ty, t.ArrayType):  # elements may have a TYPE's own initial
            element_spec = spec.element if isinstance(spec, ast.ArrayType) else None
            return _nest([self.default(ty.element, element_spec)] * _size(lowered), lowered.dims)
        return ir_default(lowered)

    def initial(self, ty: t.Type | None, spec: ast.TypeSpec | None, init: ast.Init | None) -> object:
        """The value a variable of ``ty`` (declared as ``spec``) starts with, given its initialiser ``init``."""
        if init is None:
            return self.default(ty, spec)
        body = self._spec_body(spec)
        if isinstance(init, ast.ArrayInit):
            return self._array_initial(ty, body, init)
        if isinstance(init, ast.StructInit):
            return self._struct_initial(ty, body, init)
        return self.constant(init, self.type_of(ty, spec))

    def _array_initial(self, ty: t.Type | None, spec: ast.TypeSpec | None, init: ast.ArrayInit) -> tuple:
        if not isinstance(ty, t.ArrayType):
            raise LoweringError(None)
        lowered = self.type_of(ty, spec)
        element_spec = spec.element if isinstance(spec, ast.ArrayType) else None
        values: list[object] = []
        for item in init.items:
            if isinstance(item, ast.RepeatInit):
                values += [self.initial(ty.element, element_spec, item.value)] * item.count
            else:
                values.append(self.initial(ty.element, element_spec, item))
        size = _size(lowered)  # type: ignore[arg-type]
        if len(values) < size:
            values += [self.default(ty.element, element_spec)] * (size - len(values))
        return _nest(values[:size], lowered.dims)  # type: ignore[union-attr]

    def _struct_initial(self, ty: t.Type | None, spec: ast.TypeSpec | None, init: ast.StructInit) -> object:
        if isinstance(ty, t.FbType):
            return tuple((name.upper(), self.initial(*self._pin(ty, name), value)) for name, value in init.fields)
        if not isinstance(ty, t.StructType):
            raise LoweringError(None)
        fields = self._fields(ty, spec)
        values = list(self.default(ty, spec))
        names = list(fields)
        for name, value in init.fields:
            upper = name.upper()
            if upper not in fields:
                raise LoweringError(None)
            field_type, field_spec, _ = fields[upper]
            values[names.index(upper)] = self.initial(field_type, field_spec, value)
        return tuple(values)

    @staticmethod
    def _pin(ty: t.FbType, name: str) -> tuple[t.Type | None, ast.TypeSpec | None]:
        if ty.pou is not None:
            symbol = ty.pou.symbols.get(name.upper())
            return (symbol.type, symbol.type_spec) if symbol else (None, None)
        pin = next((p for p in (*ty.std.inputs, *ty.std.outputs) if p.name == name.upper()), None)
        return (t.elementary(pin.type) if pin else None), None

    def constant(self, node: ast.Expr, target: IrType) -> object:
        """Engine value of a constant expression (literal, CONSTANT, enum value, arithmetic on them) in ``target``."""
        if getattr(node, "ty", None) is t.ERROR:
            raise LoweringError(None)
        if isinstance(target, Reference):
            return self._reference_start(node, target)
        raw = self.raw_constant(node)
        if raw is None:
            raise LoweringError(
                "an initial value must be a constant (a literal, a CONSTANT or an enumeration value)",
                node,
                code="IR-INIT",
            )
        return engine_value(raw, target)

    def _reference_start(self, node: ast.Expr, target: Reference) -> ReferenceInit | None:
        """``_reference_initial``, seeing its variable through a view (engine/codegen/views.py) when it is not of
        the reference's target type: ``p : POINTER TO BYTE := ADR(str)`` walks the STRING's bytes, ``p : POINTER TO
        INT := ADR(pct)`` keeps ``pct`` in its subrange (as the same assignment in the body does: lower_expr)."""
        start = _reference_initial(node)
        if start is None:
            return None
        assert isinstance(node, ast.Call)  # REF(x) / ADR(x) (_reference_initial)
        value = node.args[0].value
        name = value.base if isinstance(value, ast.Index) else value
        assert isinstance(name, ast.Name) and isinstance(name.ref, Symbol)
        symbol = name.ref
        referred = self.type_of(symbol.type, symbol.type_spec)
        if start.index and isinstance(referred, Array) and len(referred.dims) == len(start.index):
            referred = referred.element
        if same_target(referred, target.target) or isinstance(referred, FbInstance):  # (an FB: the checker's call)
            return start
        specs = view_specs(referred, target.target)
        if isinstance(specs, str):
            raise LoweringError(specs, node)
        return dataclasses.replace(start, view=specs)

    def raw_constant(self, node: Any, depth: int = 0) -> object:
        """The Python value of a constant expression before it is stored in a type; None when not constant."""
        if depth > _ALIAS_DEPTH:
            return None
        if isinstance(node, (ast.IntLit, ast.RealLit, ast.BoolLit, ast.StringLit, ast.TimeLit)):
            return node.value
        if isinstance(node, ast.TypedLit):
            if isinstance(node.ty, t.EnumType) and isinstance(node.value, ast.Name):
                return node.ty.values[node.value.name.upper()][1]
            return self.raw_constant(node.value, depth + 1)
        if isinstance(node, (ast.Name, ast.Member)) and isinstance(node.ref, EnumValue):  # Green, Color.Green
            return node.ref.value
        if isinstance(node, ast.Name):
            if isinstance(node.ref, Symbol) and node.ref.constant and node.ref.init is not None:
                symbol = node.ref
                return self.initial(symbol.type, symbol.type_spec, symbol.init)
            return None
        if isinstance(node, ast.Unary):
            value = self.raw_constant(node.operand, depth + 1)
            if isinstance(value, bool) and node.op == "NOT":
                return not value
            if isinstance(value, int) and not isinstance(value, bool):
                return -value if node.op == "-" else ~value
            return -value if isinstance(value, float) and node.op == "-" else None
        if isinstance(node, ast.Binary):
            return constant_value(self.constants, node)
        return None

    # ------------------------------------------------------------ slots
    def slot(self, symbol: Symbol) -> Slot:
        """The slot of a declared variable; VAR_IN_OUT slots are references and have no initial value, nor has a
        located variable without one (its memory keeps what the process image holds)."""
        ty, spec = symbol.type, symbol.type_spec
        if (  # most variables: an elementary type by its name, no initial value (what the steps below make of it)
            type(ty) is t.Elementary
            and type(spec) is ast.NamedType
            and symbol.init is None
            and symbol.address is None
            and symbol.init_args is None
            and symbol.var_class != "VAR_IN_OUT"
            and (not self.types or spec.name.upper() not in self.types)
        ):
            lowered, initial = _elementary_slot(ty.name)
            return Slot(upper_name(symbol.name), symbol.var_class, lowered, initial, symbol.retain, symbol.constant)
        located = symbol.address is not None and not incomplete(symbol.address)  # %I*: an ordinary variable
        if symbol.var_class == "VAR_IN_OUT" or (located and symbol.init is None):
            initial = None
        else:
            initial = self.initial(symbol.type, symbol.type_spec, symbol.init)
        return Slot(
            upper_name(symbol.name),
            symbol.var_class,
            self.type_of(symbol.type, symbol.type_spec),
            initial,
            symbol.retain,
            symbol.constant,
            symbol.address.upper() if located else None,
            init_args=self._init_args(symbol),
        )

    def _init_args(self, symbol: Symbol) -> tuple[tuple[tuple[str, Const], ...], ...] | None:
        """The FB_init arguments of each instance ``symbol`` holds, as values of their inputs' types (st/fb_init.py)."""
        if symbol.init_args is None:
            return None
        ty = symbol.type
        while isinstance(ty, t.ArrayType):
            ty = ty.element
        method = ty.pou.find_method("FB_INIT")  # type: ignore[union-attr]  # checked: an FB with an FB_init
        inputs = {p.name.upper(): p for p in method.parameters("VAR_INPUT")}
        return tuple(
            tuple(
                (name, Const(self.initial(p.type, p.type_spec, value), self.type_of(p.type, p.type_spec)))
                for name, value in args
                for p in (inputs[name],)
            )
            for args in symbol.init_args
        )


def _reference_initial(node: ast.Expr) -> ReferenceInit | None:
    """A reference starts as NULL (None; CODESYS's 0 too) or as ``REF(x)`` / ``ADR(x)`` of a whole variable or of an
    element of an array variable with literal indices (``ADR(arrayINT[0])``, seed 000 TYP-46)."""
    if node.ty is t.NULL or isinstance(node, ast.IntLit):  # an integer only as CODESYS's 0 (st/types.null_literal)
        return None
    if isinstance(node, ast.Call) and isinstance(node.callee, ast.Name) and len(node.args) == 1:
        value = node.args[0].value
        indices: tuple[int | None, ...] = ()
        if isinstance(value, ast.Index):
            indices = tuple(_literal_int(i) for i in value.indices)
            value = value.base if None not in indices else value
        if isinstance(value, ast.Name) and isinstance(value.ref, Symbol):
            symbol: Symbol = value.ref
            scope = "global" if symbol.pou is None or symbol.var_class == "VAR_EXTERNAL" else "local"
            text = f"{node.callee.name.upper()}({print_expression(node.args[0].value)})"
            return ReferenceInit(symbol.name.upper(), scope, text, indices)  # type: ignore[arg-type]  # no None
    raise LoweringError(
        "a reference starts as NULL or as REF(x) of a whole variable x or of an array element x[3] "
        "(assign REF(a[i]) or REF(s.f) in the body)",
        node,
        code="IR-INIT",
    )


def _literal_int(node: ast.Expr) -> int | None:
    """An index written as an integer literal (``3``, ``-1``), else None."""
    if isinstance(node, ast.Unary) and node.op == "-" and isinstance(node.operand, ast.IntLit):
        return -node.operand.value
    return node.value if isinstance(node, ast.IntLit) else None


@functools.cache
def _elementary(name: str) -> Elementary:
    return Elementary(name)


@functools.cache
def _elementary_slot(name: str) -> tuple[Elementary, object]:
    """An elementary type by its name and its default value: most slots' (a 50,000-network program's 200,000)."""
    lowered = _elementary(name)
    return lowered, ir_default(lowered)


def engine_value(raw: object, target: IrType) -> object:
    """A literal's Python value stored in ``target`` (wrapped, float32-rounded, cut) as the engine holds it."""
    if isinstance(target, (Enum, Subrange)):
        return int(raw)  # type: ignore[call-overload]
    if not isinstance(target, Elementary):
        return raw  # composite values are built complete by TypeLowering
    category = target.info.category
    if category == "bool":
        return bool(raw)
    if category == "string":
        return str(raw)[: target.max_length]
    if category == "real":
        return f32(float(raw)) if target.name == "REAL" else float(raw)  # type: ignore[arg-type]
    if isinstance(raw, float):  # fractional milliseconds (T#1.5ms) or a REAL constant folded for an integer
        raw = round(raw) if math.isfinite(raw) else 0
    return store_fn(target.name)(int(raw))  # type: ignore[call-overload]


def merged_initial(ty: IrType, own: object, given: object) -> object:
    """The initial value of a variable of ``ty`` whose own declaration gives it ``own`` and a declaration around it
    ``given`` (None: nothing). An instance's are ``(NAME, value)`` pairs (in F, ``inner : G := (a := 7)``, around it
    ``fb : F := (inner := (b := 2))``): the variables ``given`` names take its values, the others keep ``own``'s, as
    CODESYS assigns only the variables an initialisation names."""
    if given is None:
        return own
    if not isinstance(ty, FbInstance) or not isinstance(own, tuple) or not isinstance(given, tuple):
        return given
    pairs = dict(own)
    pairs.update(given)
    return tuple(pairs.items())


def ir_default(type: IrType) -> object:
    """The default value of an IR type (TYP-05): 0, FALSE, '', a subrange's lower limit, the first enum value."""
    if isinstance(type, Elementary):
        return default_value(type.name)
    if isinstance(type, Subrange):
        return type.low if not type.low <= 0 <= type.high else 0
    if isinstance(type, Enum):
        return type.values[0][1] if type.values else 0
    if isinstance(type, Array):
        return _nest([ir_default(type.element)] * _size(type), type.dims)
    if isinstance(type, Struct):
        return tuple(f.initial for f in type.fields)
    return None  # FB instance: its own slots hold its initial values


def byte_size(type: IrType) -> int:
    """SIZEOF (TYP-45) as CODESYS counts: the type's width, BOOL 1, STRING[n] n + 1, WSTRING[n] 2 * (n + 1) (a WORD
    a character and the terminator: CODESYS's "WSTRING" page), an enumeration its base
    type's (INT unless it names another: CODESYS's "Enumeration" page), a pointer 4 (an address of the 32-bit
    x86/ARM target LadderLab computes as, docs/st.md), arrays the sum of their elements, a STRUCT its byte
    layout's size (padding included: ir/byte_layout.py)."""
    if isinstance(type, Subrange):
        return byte_size(type.base)
    if isinstance(type, Elementary):
        if type.info.category == "string":
            return (type.max_length + 1) * (2 if type.wide else 1)
        return max(1, type.info.bits // 8)
    if isinstance(type, Enum):
        return ELEMENTARY[type.base].bits // 8
    if isinstance(type, Array):
        return _size(type) * byte_size(type.element)
    if isinstance(type, Struct):
        spec = byte_layout(type, addresses=True)
        if isinstance(spec, str):
            raise LoweringError(f"SIZEOF is refused for {spec}")
        return spec[2]
    if isinstance(type, Reference):
        return POINTER_BYTES
    raise LoweringError(
        "SIZEOF of a function block instance is refused: CODESYS counts the instance's hidden data too (its method "
        "table pointer, the alignment of its members), which LadderLab does not lay out"
    )


def scalar_count(type: IrType) -> int:
    """How many scalar values a variable of ``type`` holds (an FB instance's are counted with its POU)."""
    if isinstance(type, Array):
        return _size(type) * scalar_count(type.element)
    if isinstance(type, Struct):
        return sum(scalar_count(f.type) for f in type.fields)
    return 0 if isinstance(type, FbInstance) else 1


def _nest(values: list[object], dims: tuple[tuple[int, int], ...]) -> tuple:
    """Row-major element values -> one tuple level per dimension."""
    if len(dims) == 1:
        return tuple(values)
    low, high = dims[0]
    step = len(values) // (high - low + 1)
    return tuple(_nest(values[i : i + step], dims[1:]) for i in range(0, len(values), step))


def _size(array: Array) -> int:
    size = 1
    for low, high in array.dims:
        size *= high - low + 1
    return size


def ir_type(ty: t.Type, checked: CheckResult | None = None) -> IrType:
    """The IR type of a checker type (raises ``LoweringError`` for pointers, open arrays and types with errors).

    Pass ``checked`` to get STRUCT field initial values and subranges of fields
    exactly as in slots; ``PouContext.ir_type`` does that for you.
    """
    return TypeLowering(checked).type_of(ty)
