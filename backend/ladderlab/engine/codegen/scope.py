"""How the body of one POU reaches its variables: roots of access paths and references to them.

Inside a PROGRAM / FUNCTION_BLOCK method a slot is ``self.v_X`` (or
``ll_p2.v_X`` on a further page, loaded once at entry). Inside a FUNCTION,
whose variables live only for one call (VAR-43), slots are Python locals;
a local passed whole to a VAR_IN_OUT is boxed in a one-element list so it can
be referenced. Globals are ``G.v_X`` (``G1``, ``G2``.. for further pages).
A VAR_IN_OUT slot holds a reference ``(container, key)``: scalars are read and
written as ``ll_c_X[ll_k_X]``; an array or structure is fetched once at entry
into ``v_X`` (composite values never change identity).
"""

from __future__ import annotations

from ...ir import nodes as ir
from ...ir import types as t
from . import names
from .context import CodegenError, ModuleContext
from .layout import Layout
from .typeinfo import is_composite


def global_owner(page: int) -> str:
    return "G" if page == 0 else f"G{page}"


def _page_owner(page: int) -> str:
    """What a method's code reads a slot on ``page`` through: ``self``, or the page loaded at entry."""
    return f"ll_p{page}" if page else "self"


class Scope:
    def __init__(self, module: ModuleContext, pou: ir.Pou) -> None:
        self.module = module
        self.pou = pou
        self.function = pou.kind == "function"
        self.layout: Layout | None = None if self.function else module.layouts[pou.name.upper()]
        self.slots = {s.name.upper(): s for s in pou.slots if s.var_class != "VAR_EXTERNAL"}
        self.in_outs = [s for s in self.slots.values() if s.var_class == "VAR_IN_OUT"]
        self.boxed: set[str] = set()
        self.pages_used: set[int] = set()
        self._temps = 0
        self._roots: dict[tuple[str, str], tuple[str, t.IrType, int]] = {}

    def temp(self, prefix: str) -> str:
        self._temps += 1
        return f"ll_{prefix}{self._temps}"

    def slot(self, var: ir.Var) -> ir.Slot:
        if var.scope == "global":
            place = self.module.globals.get(var.name)
            if place is None:
                located = self.module.globals.located.get(var.name.upper())
                if located is not None:
                    return located
                raise CodegenError(f"unknown global variable {var.name}")
            return place.slot
        slot = self.slots.get(var.name.upper())
        if slot is None:
            raise CodegenError(f"unknown variable {var.name} in {self.pou.name}")
        return slot

    def _owner(self, var: ir.Var) -> str:
        """``self`` or the local holding the page of a method's slot (loaded at entry)."""
        place = self.layout.get(var.name)  # type: ignore[union-attr]
        if place.page:  # type: ignore[union-attr]
            self.pages_used.add(place.page)  # type: ignore[union-attr]
        return _page_owner(place.page)  # type: ignore[union-attr]

    def root(self, var: ir.Var) -> tuple[str, t.IrType]:
        """Source reading (and assignable as) the root slot of ``var``, and the slot's type."""
        key = (var.scope, var.name)
        found = self._roots.get(key)
        if found is None:
            found = self._roots[key] = self._root(var)
        code, ty, page = found
        if page:  # every chunk function loads the pages its own statements use
            self.pages_used.add(page)
        return code, ty

    def _root(self, var: ir.Var) -> tuple[str, t.IrType, int]:
        """``root``'s source and type, and the page its slot lives on (0: ``self``, a local or a global)."""
        if self._self(var):
            return "self", t.FbInstance(self.pou.name.upper()), 0
        slot = self.slot(var)
        if slot.address is not None:  # a located variable: its process image view (engine/process_image.py)
            view, key = self.module.image_view(slot, world=self.pou.live_clock)
            return f"{view}[{key}]", slot.type, 0
        attr = names.slot(slot.name)
        if var.scope == "global":
            place = self.module.globals.get(var.name)
            return f"{global_owner(place.page)}.{attr}", slot.type, 0  # type: ignore[union-attr]
        if slot.var_class == "VAR_IN_OUT":
            if is_composite(slot.type):
                return attr, slot.type, 0
            key = names.escape(slot.name)
            return f"ll_c_{key}[ll_k_{key}]", slot.type, 0
        if self.function:
            return (f"{attr}[0]" if slot.name.upper() in self.boxed else attr), slot.type, 0
        place = self.layout.get(var.name)  # type: ignore[union-attr]
        return f"{_page_owner(place.page)}.{place.attr}", slot.type, place.page  # type: ignore[union-attr]

    def root_ref(self, var: ir.Var) -> str:
        """Source of a ``(container, key)`` reference to the whole root slot of ``var``."""
        if self._self(var):
            return "((self,), 0)"
        slot = self.slot(var)
        if slot.address is not None:
            view, key = self.module.image_view(slot, world=self.pou.live_clock)
            return f"({view}, {key})"
        attr = names.slot(slot.name)
        if var.scope == "global":
            place = self.module.globals.get(var.name)
            return f"({global_owner(place.page)}, {attr!r})"  # type: ignore[union-attr]
        if slot.var_class == "VAR_IN_OUT":
            return f"r_{names.escape(slot.name)}"
        if self.function:
            if slot.name.upper() not in self.boxed:
                raise CodegenError(f"{slot.name} cannot be passed by reference")  # boxed() missed it: a bug
            return f"({attr}, 0)"
        return f"({self._owner(var)}, {attr!r})"

    def _self(self, var: ir.Var) -> bool:
        """``THIS^`` in a function block's body: the instance running it (ir.nodes.SELF)."""
        return var.scope == "local" and var.name == ir.SELF and not self.function

    def result_slot(self) -> ir.Slot:
        """A FUNCTION's result: the slot named like the function."""
        slot = self.slots.get(self.pou.name.upper())
        if slot is None:
            raise CodegenError(f"function {self.pou.name} has no result slot")
        return slot

    def return_statement(self) -> str:
        if not self.function:
            return "return"
        name = self.result_slot().name
        return f"return {names.slot(name)}{'[0]' if name.upper() in self.boxed else ''}"
