"""How the body of one POU reaches its variables: roots of access paths and references to them.

Inside a PROGRAM / FUNCTION_BLOCK method a slot is ``self.v_X`` (or
``ll_p2.v_X`` on a further page, loaded once at entry). Inside a FUNCTION,
whose variables live only for one call (VAR-43), slots are Python locals;
a local passed whole to a VAR_IN_OUT is boxed in a one-element list so it can
be referenced. Globals are ``G.v_X`` (``G1``, ``G2``.. for further pages).
A VAR_IN_OUT slot holds a reference ``(container, key)``: scalars are read and
written as ``ll_c_X[ll_k_X]``; an array or structure is fetched once at entry
into ``v_X`` (composite values never change identity).

In the fast and monitor variants a hidden elementary VAR_TEMP of a PROGRAM / FUNCTION_BLOCK (a power-flow or ENO
temporary of the LD/FBD lowering) is a Python local ``ll_t_X`` of each chunk function that uses it: loaded
from its slot at the chunk's start, stored back at its end (``temp_locals``; docs/runtime.md, "Temporaries
as locals"). Nothing outside the POU's own code reads such a slot (hidden slots have no path) and its value
is dead when ``execute`` ends, so only the hand-over between chunks goes through the slot.
"""

from __future__ import annotations

from ...ir import nodes as ir
from ...ir import types as t
from . import names
from .context import CodegenError, ModuleContext, std_fb_class
from .layout import Layout, Place
from .mentions import addressed_locals, addressed_temps, passed_in_out, referenced_locals
from .templates import BlockTemplates
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
        self.slots = {ir.upper_name(s.name): s for s in pou.slots if s.var_class != "VAR_EXTERNAL"}
        self.in_outs = [s for s in self.slots.values() if s.var_class == "VAR_IN_OUT"]
        self.boxed: set[str] = set()
        #: the variables whose references die with the call (framed_variables): its calls have a Frame
        self.framed: set[str] = set()
        self.pages_used: set[int] = set()
        #: the prefix of each numbered temporary made (``temp``), the first's first
        self.temp_prefixes: list[str] = []
        #: ``placed`` by the name of a local variable and of a global one
        self._locals: dict[str, tuple[str, t.IrType, int]] = {}
        self._globals: dict[str, tuple[str, t.IrType, int]] = {}
        #: upper-case slot name -> the local it lives in (fast variant; ``temp_locals``)
        self.temp_locals: dict[str, str] = {} if self.function else temp_locals(module, pou)
        self.temps_used: set[str] = set()  # of ``temp_locals``, by the chunk being generated
        #: the network shapes of the code that records no probe (templates.py): the fast variant's, the monitor
        #: variant's unviewed twins
        self.templates = BlockTemplates() if not (module.debug or self.function) else None

    def temp(self, prefix: str) -> str:
        self.temp_prefixes.append(prefix)
        return f"ll_{prefix}{len(self.temp_prefixes)}"

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
        place = self._place(var.name)
        if place.page:
            self.pages_used.add(place.page)
        return _page_owner(place.page)

    def root(self, var: ir.Var) -> tuple[str, t.IrType]:
        """Source reading (and assignable as) the root slot of ``var``, and the slot's type."""
        code, ty, page = self.placed(var)
        if page:  # every chunk function loads the pages its own statements use
            self.pages_used.add(page)
        elif code.startswith("ll_t_"):  # ... and the temporaries they use (only temp_locals' are named so)
            self.temps_used.add(var.name.upper())
        return code, ty

    def placed(self, var: ir.Var) -> tuple[str, t.IrType, int]:
        """``root``'s source and type, and the page its slot lives on, without noting the page or temporary as
        used by the chunk being generated."""
        roots = self._locals if var.scope == "local" else self._globals
        found = roots.get(var.name)
        if found is None:
            found = roots[var.name] = self._root(var)
        return found

    def _root(self, var: ir.Var) -> tuple[str, t.IrType, int]:
        """``root``'s source and type, and the page its slot lives on (0: ``self``, a local or a global). (Asked once
        for each of a 50,000-network POU's 200,000 variables: a slot of the POU's own, the most, is found first.)"""
        upper = var.name.upper()
        slot = self.slots.get(upper) if var.scope == "local" else None
        if (
            slot is not None
            and slot.address is None
            and slot.var_class != "VAR_IN_OUT"
            and not self.function
            and var.name != ir.SELF
        ):
            local = self.temp_locals.get(upper)
            if local is not None:
                return local, slot.type, 0
            place = self.layout.places[upper]  # type: ignore[union-attr]  # a PROGRAM / FB has a layout
            return f"{_page_owner(place.page)}.{place.attr}", slot.type, place.page
        if self._self(var):
            return "self", t.FbInstance(self.pou.name.upper()), 0
        slot = self.slot(var)
        if slot.address is not None:  # a located variable: its process image view (engine/process_image.py)
            view, key = self.module.image_view(slot, world=self.pou.live_clock)
            return f"{view}[{key}]", slot.type, 0
        if var.scope == "global":
            place = self.module.globals.get(var.name)
            return f"{global_owner(place.page)}.{place.attr}", slot.type, 0  # type: ignore[union-attr]
        if slot.var_class == "VAR_IN_OUT":
            if is_composite(slot.type):
                return names.slot(slot.name), slot.type, 0
            key = names.escape(slot.name)
            return f"ll_c_{key}[ll_k_{key}]", slot.type, 0
        attr = names.slot(slot.name)  # (what is left: a FUNCTION's own variable, a local)
        return (f"{attr}[0]" if slot.name.upper() in self.boxed else attr), slot.type, 0

    def slot_source(self, name: str) -> str:
        """Where the slot ``name`` of this PROGRAM / FUNCTION_BLOCK lives (its page noted as used)."""
        place = self._place(name)
        if place.page:
            self.pages_used.add(place.page)
        return f"{_page_owner(place.page)}.{place.attr}"

    def _place(self, name: str) -> Place:
        """Where slot ``name`` lives in this PROGRAM's / FUNCTION_BLOCK's layout (a FUNCTION has none)."""
        assert self.layout is not None, "a function's slots are locals"
        place = self.layout.get(name)
        assert place is not None, f"{name} is a slot of this POU"
        return place

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
        result = f"{names.slot(name)}{'[0]' if name.upper() in self.boxed else ''}"
        return f"return ll_fr.end({result})" if self.framed else f"return {result}"


def framed_variables(module: ModuleContext, pou: ir.Pou) -> set[str]:
    """The variables (upper case) whose references die with the POU's call, so that its calls have a
    ``runtime.Frame``: a FUNCTION's own variables, a PROGRAM's / FB's VAR_TEMP, that the body takes REF()/ADR() of,
    and, when some POU takes REF()/ADR() of its VAR_IN_OUT, those passed to an in-out (the reference the callee
    takes refers to them). Empty for the many POUs that do neither: their code has no frame."""
    found = module.mentions(pou)
    function = pou.kind == "function"
    own = addressed_locals(found) if function else addressed_temps(found)
    if not module.in_outs_addressed:
        return own
    passed = passed_in_out(found, lambda fb, pin: _in_out_pin(module, fb, pin))
    if not function:  # (the set of a large POU's VAR_TEMP names made only here)
        passed &= {s.name.upper() for s in pou.slots if s.var_class == "VAR_TEMP"}
    return own | passed


def _in_out_pin(module: ModuleContext, fb: str, pin: str) -> bool:
    layout = module.layouts.get(fb.upper())
    place = layout.get(pin) if layout is not None else None
    return place is not None and place.slot.var_class == "VAR_IN_OUT"


def temp_locals(module: ModuleContext, pou: ir.Pou) -> dict[str, str]:
    """The hidden elementary VAR_TEMP slots of a PROGRAM / FUNCTION_BLOCK that the fast and monitor variants keep
    in locals
    (upper-case name -> local), none when the body jumps (a chunk is then re-entered mid-way) or a slot is passed
    by reference (a VAR_IN_OUT needs a container)."""
    if module.debug or pou.kind == "function":  # (no probe is deferred to after the scan: not VAR_TEMP ones)
        return {}
    candidates = {
        s.name.upper(): f"ll_t_{names.escape(s.name)}"
        for s in pou.slots
        if s.hidden and s.var_class == "VAR_TEMP" and s.address is None and isinstance(s.type, t.Elementary)
    }
    found = module.mentions(pou)
    if not candidates or found.jumps:
        return {}
    referenced = referenced_locals(found, by_value=lambda fb: std_fb_class(fb) is not None)
    return {name: local for name, local in candidates.items() if name not in referenced}
