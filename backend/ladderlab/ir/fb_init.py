"""The FB_init calls that initialise a program (CODESYS): each instance's FB_init runs once, between its FB's
initial values and its declaration's.

Which run, in which order (docs/st.md, "FB_init and FB_exit"): every instance of a function block whose lineage
declares an FB_init, in the program instances then the globals, each in declaration order (an array's elements in
row-major order, a STRUCT's members in their order); an instance's own instances first (they are initialised when
it is, so its FB_init finds them ready: Beckhoff's "the function block instance is already fully initialized via the
implicit initialization code" when the explicit FB_init code runs), then for the instance the FB_init of each FB of
its lineage, the base's first (CODESYS and Beckhoff, "FB_init with derived function blocks"). Each call passes
``bInitRetains`` (TRUE on a cold start, FALSE on a warm one: the RETAIN variables kept their values), ``bInCopyCode``
FALSE (no online change here) and the declaration's arguments (the input's initial value for one not given).

An instance declaration's own initialisation (``fb : F := (x := 1)``, an array's ``[(x := 1), ...]``, a STRUCT's
value for a member that is an instance) is assigned after that instance's FB_init, as CODESYS processes it ("Attribute:
call_after_init": ``fbDoIt.FB_Init(); fbDoIt.in1 := 99;``; Beckhoff's FB_init page, "Observe the order of
initialization"): the instances are made with those values (engine/codegen/constructors.py), so before its FB_init
each such variable is set back to the FB's own declared value and after it to the declaration's. A warm restart does
the same except for the RETAIN variables, which keep their values. Then the
instance calls its call_after_init methods (CODESYS's "Attribute: call_after_init": ``fbDoIt.FB_AfterInit();`` after
the declaration's values; st/call_after_init.py), the base's first, each as the instance's FB runs it. The
statements are plain method calls that run the base's method itself (no dispatch), so the engine runs, pauses and
locates faults in them as in any call (engine/codegen/tasks.py ``ll_fb_init``).
"""

from __future__ import annotations

import itertools
from typing import Any

from ..iec import stdlib
from ..st.symbols import CheckResult
from .lower_types import ir_default, merged_initial
from .nodes import Assign, Call, Const, FnCall, Index, Member, Origin, Program, Slot, Stmt, Var
from .types import BOOL, Array, Elementary, FbInstance, IrType, Reference, Struct

#: The origin of the calls: named as the engine names what it runs when the program is initialised
ORIGIN = Origin("INITIALISATION")
_DINT = Elementary("DINT")


def method_chains(checked: CheckResult, key: str) -> dict[str, list[str]]:
    """For each FB with the method ``key`` (FB_INIT, FB_EXIT) in its lineage: those its instances run, the base's
    first."""
    chains = {}
    for info in checked.pous.values():
        if info.kind == "FUNCTION_BLOCK":
            chain = [fb.methods[key].name.upper() for fb in reversed(info.lineage()) if key in fb.methods]
            if chain:
                chains[info.name.upper()] = chain
    return chains


def after_init_chains(checked: CheckResult) -> dict[str, list[str]]:
    """For each FB whose instances call methods after their initialisation ({attribute 'call_after_init'},
    st/call_after_init.py): each such method of its lineage, the base's first, as the FB runs it (an override in its
    place)."""
    chains = {}
    for info in checked.pous.values():
        if info.kind == "FUNCTION_BLOCK" and info.after_init:
            keys = dict.fromkeys(
                key for fb in reversed(info.lineage()) for key, m in fb.methods.items() if m.after_init
            )
            chain = [found.name.upper() for found in map(info.find_method, keys) if found is not None]
            if chain:
                chains[info.name.upper()] = chain
    return chains


def init_statements(program: Program, retains: bool) -> list[Stmt]:
    """The FB_init calls of every instance of ``program``, each followed by its call_after_init calls, in order
    (``retains``: a cold start)."""
    return _Walk(program, program.fb_inits, retains, with_args=True, after=program.after_inits).run()


def exit_statements(program: Program) -> list[Stmt]:
    """The FB_exit calls of every instance of ``program`` before a restart (CODESYS's "GlobalExit ... before a new
    download or a reset"): the reverse of the initialisation's order, so a derived FB's FB_exit runs before its
    base's (Beckhoff, "FB_exit with derived function blocks") and an instance's before those of its instances."""
    return _Walk(program, program.fb_exits, False, with_args=False).run()[::-1]


class _Walk:
    def __init__(
        self,
        program: Program,
        chains: dict[str, list[str]],
        retains: bool,
        with_args: bool,
        after: dict[str, list[str]] | None = None,
    ) -> None:
        self.program, self.chains, self.retains, self.with_args = program, chains, retains, with_args
        self.after = after or {}  # FB -> the methods its instances call last (call_after_init)
        self.out: list[Stmt] = []
        self._needs: dict[str, bool] = {}

    def run(self) -> list[Stmt]:
        # no FB has the method: no instance runs it (a 200,000-slot program's walk: ~0.3 s)
        if not self.chains and not self.after:
            return self.out
        for instance in self.program.program_instances():
            var = Var("global", instance.name.upper(), FbInstance(instance.pou.upper()))
            self.members(instance.pou.upper(), var, instance.retain, {})
        for slot in self.program.globals:
            self.slot(slot, Var("global", slot.name, slot.type), slot.initial, slot.retain)
        return self.out

    def needs(self, fb: str) -> bool:
        """Whether an instance of ``fb`` runs an FB_init, its own or one of an instance inside it."""
        if fb not in self._needs:
            self._needs[fb] = False  # (a cycle of instances is refused by the checker)
            pou = self.program.pous.get(fb)
            inside = pou is not None and any(self.holds(slot.type) for slot in pou.slots if _made(slot))
            self._needs[fb] = fb in self.chains or fb in self.after or inside
        return self._needs[fb]

    def holds(self, ty: IrType) -> bool:
        """Whether a variable of ``ty`` holds an instance that runs an FB_init (in an array, a STRUCT, nested)."""
        while isinstance(ty, Array):
            ty = ty.element
        if isinstance(ty, Struct):
            return any(self.holds(f.type) for f in ty.fields)
        return isinstance(ty, FbInstance) and self.needs(ty.fb)

    def members(self, pou: str, owner: Var, kept: bool, given: dict[str, object]) -> None:
        """The instances inside ``owner``, an instance of ``pou``, each with its declared initial value (``given``:
        the owner's declaration's, which replace the FB's own as the instance is made)."""
        found = self.program.pous.get(pou)
        for slot in found.slots if found is not None else []:
            if _made(slot) and self.holds(slot.type):  # (``place`` asks it of the same type: asked first, cheaper)
                var = Var(owner.scope, owner.name, slot.type, (*owner.path, Member(slot.name)))
                initial = merged_initial(slot.type, slot.initial, given.get(slot.name))
                self.slot(slot, var, initial, kept or slot.retain)

    def slot(self, slot: Slot, var: Var, initial: object, kept: bool) -> None:
        self.place(var, slot.init_args or (), initial, kept)

    def place(self, var: Var, args: tuple[tuple[tuple[str, Const], ...], ...], initial: object, kept: bool) -> None:
        """The instances ``var`` holds (initial value ``initial``; ``kept``: a RETAIN variable), with each one's
        arguments (an array's elements in order; a STRUCT's members take none: st/fb_init.py refuses an FB_init
        there that needs any)."""
        if not self.holds(var.type):
            return
        for number, (element, value) in enumerate(_elements(var, initial)):
            if isinstance(element.type, Struct):
                values = value if isinstance(value, tuple) else ()
                for i, f in enumerate(element.type.fields):
                    member = Var(element.scope, element.name, f.type, (*element.path, Member(f.name)))
                    given = values[i] if i < len(values) else None
                    self.place(member, (), merged_initial(f.type, f.initial, given), kept)
            else:
                self.instance(element, args[number] if number < len(args) else (), value, kept)

    def instance(self, var: Var, args: tuple[tuple[str, Const], ...], initial: object, kept: bool) -> None:
        """``var``'s FB_init calls, after those of its own instances; with the arguments ``args`` and between the
        FB's own initial values and those of its declaration (``initial``: ``(NAME, value)`` pairs)."""
        fb = var.type.fb  # type: ignore[union-attr]  # _elements gives instances
        chain = self.chains.get(fb, [])
        warm = not self.retains
        declared = tuple(initial) if isinstance(initial, tuple) and self.with_args and not (kept and warm) else ()
        if chain and declared:
            self.out += _Values(self.program, warm).restore(var, fb, declared, {})
        self.members(fb, var, kept, {} if chain else dict(declared))
        given = dict(args) if self.with_args else {}
        for method in chain:
            inputs = [s for s in self.program.pous[method].slots if s.var_class == "VAR_INPUT"]
            values = [self.system(s) or given.get(s.name) or Const(s.initial, s.type) for s in inputs]
            call = Call(method, tuple(values), tuple(s.type for s in inputs), BOOL, True, (var,), False)
            self.out.append(FnCall(call, None, ORIGIN))
        if chain and declared:
            self.out += _Values(self.program, warm).assign(var, var.type, declared)
        for method in self.after.get(fb, []):  # (no inputs: st/call_after_init.py)
            call = Call(method, (), (), self.program.pous[method].return_type or BOOL, True, (var,), False)
            self.out.append(FnCall(call, None, ORIGIN))

    def system(self, slot: Slot) -> Const | None:
        if slot.name == "BINITRETAINS":
            return Const(self.retains, BOOL)
        return Const(False, BOOL) if slot.name == "BINCOPYCODE" else None


class _Values:
    """Assignments that give a variable an initial value (docs/ir.md, "Initial values": scalars, one tuple level
    per array dimension, a STRUCT's field values, an instance's ``(NAME, value)`` pairs; None: the type's own).
    ``warm``: a warm restart, which leaves an instance's RETAIN variables as they are."""

    def __init__(self, program: Program, warm: bool) -> None:
        self.program, self.warm = program, warm

    def assign(self, var: Var, ty: IrType, value: object) -> list[Stmt]:
        if isinstance(ty, Array):
            return [s for element, item in _elements(var, value) for s in self.assign(element, ty.element, item)]
        if isinstance(ty, Struct):
            values = value if isinstance(value, tuple) else ()
            out: list[Stmt] = []
            for i, f in enumerate(ty.fields):
                item = values[i] if i < len(values) and values[i] is not None else f.initial
                out += self.assign(Var(var.scope, var.name, f.type, (*var.path, Member(f.name))), f.type, item)
            return out
        if isinstance(ty, FbInstance):
            pairs = value if isinstance(value, tuple) else ()
            return [s for name, item in pairs for s in self.member(var, ty.fb, name, item, {}, restore=False)]
        if isinstance(ty, Reference) and value is not None:
            return []  # (REF(x): made after every slot, never changed by an FB_init's order)
        return [Assign(var, Const(ir_default(ty) if value is None else value, ty), ORIGIN)]

    def restore(self, var: Var, fb: str, pairs: tuple[Any, ...], declared: dict[str, object]) -> list[Stmt]:
        """The variables the declaration's ``pairs`` set in the instance ``var`` of ``fb``, set back to the FB's own
        initial values (``declared``: an enclosing declaration's for this instance, which replace the FB's)."""
        return [s for name, item in pairs for s in self.member(var, fb, name, item, declared, restore=True)]

    def member(
        self, var: Var, fb: str, name: str, item: object, declared: dict[str, object], restore: bool
    ) -> list[Stmt]:
        """The variable ``name`` of the instance ``var`` of ``fb`` (a standard FB's input or output) set to ``item``,
        or (``restore``) back to its initial value where ``item`` would set it."""
        pou = self.program.pous.get(fb)
        if pou is not None:
            slot = next((s for s in pou.slots if s.name == name), None)
            if slot is None or (self.warm and slot.retain):
                return []  # (one the FB lacks: making the instance reports it, engine/codegen/constructors.py)
            ty, initial = slot.type, slot.initial
        else:
            block = stdlib.function_block(fb)
            pin = next(p for p in (*block.inputs, *block.outputs) if p.name.upper() == name.upper()) if block else None
            if pin is None or pin.generic:
                return []
            ty, initial = Elementary(pin.type), None
        member = Var(var.scope, var.name, ty, (*var.path, Member(name)))
        if not restore:
            return self.assign(member, ty, item)
        own = declared.get(name, initial)
        if isinstance(ty, FbInstance) and isinstance(item, tuple):
            return self.restore(member, ty.fb, item, dict(own) if isinstance(own, tuple) else {})
        return self.assign(member, ty, own)


def _made(slot: Slot) -> bool:
    """A slot that holds instances of its own (an in-out refers to another's)."""
    return slot.var_class not in ("VAR_IN_OUT", "VAR_EXTERNAL", "VAR_TEMP")


def _elements(var: Var, initial: object = None) -> list[tuple[Var, object]]:
    """The instance ``var`` with its initial value, or each element of the array it is with its own, in row-major
    order (one tuple level per dimension; missing ones are None)."""
    ty = var.type
    if not isinstance(ty, Array):
        return [(var, initial)]
    out = []
    for indices in itertools.product(*(range(low, high + 1) for low, high in ty.dims)):
        index = Index(tuple(Const(i, _DINT) for i in indices))
        value = initial
        for i, (low, _) in zip(indices, ty.dims):
            value = value[i - low] if isinstance(value, tuple) and i - low < len(value) else None
        out += _elements(Var(var.scope, var.name, ty.element, (*var.path, index)), value)
    return out
