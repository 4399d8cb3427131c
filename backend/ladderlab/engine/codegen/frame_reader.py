"""Reading IR variables out of a frame of generated code, the way that code reaches them.

A FUNCTION's (and a METHOD's) variables live only in the Python locals of its call (VAR-43, codegen/scope.py):
``v_X`` (boxed ``[value]`` when referenced), a VAR_IN_OUT as ``ll_c_X[ll_k_X]`` or, composite, fetched into
``v_X``; a PROGRAM's and FUNCTION_BLOCK's are slots of ``self``. Fault reports read the variables of the failing
statement through this (faults.py), the call stack of a halted scan the variables of each call (engine/call_stack.py),
so both read what the code generator wrote, by its names (names.py), and nothing is guessed.
"""

from __future__ import annotations

from types import FrameType

from ...ir import nodes as ir
from ...ir import types as t
from . import names
from .context import ModuleContext, std_pin_type
from .mentions import boxed_locals
from .scope import global_owner
from .typeinfo import is_composite


class FrameReader:
    """Reads IR variables in a frame of generated code, the way the generated code reaches them."""

    def __init__(self, context: ModuleContext, frame: FrameType, ns: dict, pou: str) -> None:
        self.context, self.locals, self.ns = context, frame.f_locals, ns
        self.pou = context.pous[pou.upper()]
        self.slots = {s.name.upper(): s for s in self.pou.slots}
        self.boxed = boxed_locals(context.mentions(self.pou)) if self.pou.kind == "function" else set()

    def read(self, var: ir.Var) -> object:
        value, ty = self.root(var)
        for selector in var.path:
            if isinstance(selector, ir.Index):
                assert isinstance(ty, t.Array)
                for index, (lo, hi) in zip(selector.indices, ty.dims):
                    i = self.scalar(index)
                    if not lo <= i <= hi:
                        raise IndexError(i)
                    value = value[i - lo]  # type: ignore[index]
                rest = ty.dims[len(selector.indices) :]
                ty = t.Array(ty.element, rest) if rest else ty.element
            elif isinstance(selector, ir.Deref):
                assert isinstance(ty, t.Reference) and value is not None  # (a NULL one raises: not shown)
                value, ty = value.v, ty.target  # type: ignore[attr-defined]  # a runtime.Ref
            else:
                value, ty = self.member(value, ty, selector.name)
        return value

    def scalar(self, e: ir.Expr) -> int:
        if isinstance(e, ir.Const):
            return e.value  # type: ignore[return-value]
        if isinstance(e, ir.Var):
            return self.read(e)  # type: ignore[return-value]
        raise ValueError("index is an expression")

    def root(self, var: ir.Var) -> tuple[object, t.IrType]:
        if var.scope == "global":
            place = self.context.globals.get(var.name)
            return getattr(self.ns[global_owner(place.page)], place.attr), place.slot.type  # type: ignore[union-attr]
        slot = self.slots[var.name.upper()]
        attr, key = names.slot(slot.name), names.escape(slot.name)
        if slot.var_class == "VAR_IN_OUT":
            if is_composite(slot.type):
                return self.locals[attr], slot.type
            return self.locals[f"ll_c_{key}"][self.locals[f"ll_k_{key}"]], slot.type
        if self.pou.kind == "function":
            value = self.locals[attr]
            return (value[0] if slot.name.upper() in self.boxed else value), slot.type
        if f"ll_t_{key}" in self.locals:  # a temporary the fast variant keeps in a local (scope.temp_locals)
            return self.locals[f"ll_t_{key}"], slot.type
        place = self.context.layouts[self.pou.name.upper()].get(slot.name)
        owner = self.locals["self"] if place.page == 0 else getattr(self.locals["self"], f"ll_p{place.page}")  # type: ignore[union-attr]
        return getattr(owner, place.attr), slot.type  # type: ignore[union-attr]

    def member(self, value: object, ty: t.IrType, name: str) -> tuple[object, t.IrType]:
        if isinstance(ty, t.Struct):
            field_type = next(f.type for f in ty.fields if f.name.upper() == name.upper())
            return getattr(value, names.slot(name)), field_type
        assert isinstance(ty, t.FbInstance)
        user = self.context.user_fb(ty.fb)
        if user is not None:
            place = self.context.layouts[user.name.upper()].get(name)
            owner = value if place.page == 0 else getattr(value, f"ll_p{place.page}")  # type: ignore[union-attr]
            return getattr(owner, place.attr), place.slot.type  # type: ignore[union-attr]
        return getattr(value, name.upper()), std_pin_type(ty.fb, name)  # type: ignore[return-value]
