"""The FB_init calls that initialise a program (CODESYS): each instance's FB_init runs once, after the initial values.

Which run, in which order (docs/st.md, "FB_init and FB_exit"): every instance of a function block whose lineage
declares an FB_init, in the program instances then the globals, each in declaration order (an array's elements in
row-major order, a STRUCT's members in their order); an instance's own instances first (they are initialised when
it is, so its FB_init finds them ready: Beckhoff's "the function block instance is already fully initialized via the
implicit initialization code" when the explicit FB_init code runs), then for the instance the FB_init of each FB of
its lineage, the base's first (CODESYS and Beckhoff, "FB_init with derived function blocks"). Each call passes
``bInitRetains`` (TRUE on a cold start, FALSE on a warm one: the RETAIN variables kept their values), ``bInCopyCode``
FALSE (no online change here) and the declaration's arguments (the input's initial value for one not given). The
statements are plain method calls that run the base's method itself (no dispatch), so the engine runs, pauses and
locates faults in them as in any call (engine/codegen/tasks.py ``ll_fb_init``).
"""

from __future__ import annotations

import itertools

from ..st.symbols import CheckResult
from .nodes import Call, Const, FnCall, Index, Member, Origin, Program, Slot, Stmt, Var
from .types import BOOL, Array, Elementary, FbInstance, IrType, Struct

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


def init_statements(program: Program, retains: bool) -> list[Stmt]:
    """The FB_init calls of every instance of ``program``, in order (``retains``: a cold start)."""
    return _Walk(program, program.fb_inits, retains, with_args=True).run()


def exit_statements(program: Program) -> list[Stmt]:
    """The FB_exit calls of every instance of ``program`` before a restart (CODESYS's "GlobalExit ... before a new
    download or a reset"): the reverse of the initialisation's order, so a derived FB's FB_exit runs before its
    base's (Beckhoff, "FB_exit with derived function blocks") and an instance's before those of its instances."""
    return _Walk(program, program.fb_exits, False, with_args=False).run()[::-1]


class _Walk:
    def __init__(self, program: Program, chains: dict[str, list[str]], retains: bool, with_args: bool) -> None:
        self.program, self.chains, self.retains, self.with_args = program, chains, retains, with_args
        self.out: list[Stmt] = []
        self._needs: dict[str, bool] = {}

    def run(self) -> list[Stmt]:
        for instance in self.program.program_instances():
            self.members(instance.pou.upper(), Var("global", instance.name.upper(), FbInstance(instance.pou.upper())))
        for slot in self.program.globals:
            self.slot(slot, Var("global", slot.name, slot.type))
        return self.out

    def needs(self, fb: str) -> bool:
        """Whether an instance of ``fb`` runs an FB_init, its own or one of an instance inside it."""
        if fb not in self._needs:
            self._needs[fb] = False  # (a cycle of instances is refused by the checker)
            pou = self.program.pous.get(fb)
            inside = pou is not None and any(self.holds(slot.type) for slot in pou.slots if _made(slot))
            self._needs[fb] = fb in self.chains or inside
        return self._needs[fb]

    def holds(self, ty: IrType) -> bool:
        """Whether a variable of ``ty`` holds an instance that runs an FB_init (in an array, a STRUCT, nested)."""
        while isinstance(ty, Array):
            ty = ty.element
        if isinstance(ty, Struct):
            return any(self.holds(f.type) for f in ty.fields)
        return isinstance(ty, FbInstance) and self.needs(ty.fb)

    def members(self, pou: str, owner: Var) -> None:
        found = self.program.pous.get(pou)
        for slot in found.slots if found is not None else []:
            if _made(slot):
                self.slot(slot, Var(owner.scope, owner.name, slot.type, (*owner.path, Member(slot.name))))

    def slot(self, slot: Slot, var: Var) -> None:
        self.place(var, slot.init_args or ())

    def place(self, var: Var, args: tuple[tuple[tuple[str, Const], ...], ...]) -> None:
        """The instances ``var`` holds, with each one's arguments (an array's elements in order; a STRUCT's members
        take none: st/fb_init.py refuses an FB_init there that needs any)."""
        if not self.holds(var.type):
            return
        for number, element in enumerate(_elements(var)):
            if isinstance(element.type, Struct):
                for f in element.type.fields:
                    self.place(Var(element.scope, element.name, f.type, (*element.path, Member(f.name))), ())
            else:
                self.instance(element, args[number] if number < len(args) else ())

    def instance(self, var: Var, args: tuple[tuple[str, Const], ...]) -> None:
        fb = var.type.fb  # type: ignore[union-attr]  # _elements gives instances
        self.members(fb, var)
        given = dict(args) if self.with_args else {}
        for method in self.chains.get(fb, []):
            inputs = [s for s in self.program.pous[method].slots if s.var_class == "VAR_INPUT"]
            values = [self.system(s) or given.get(s.name) or Const(s.initial, s.type) for s in inputs]
            call = Call(method, tuple(values), tuple(s.type for s in inputs), BOOL, True, (var,), False)
            self.out.append(FnCall(call, None, ORIGIN))

    def system(self, slot: Slot) -> Const | None:
        if slot.name == "BINITRETAINS":
            return Const(self.retains, BOOL)
        return Const(False, BOOL) if slot.name == "BINCOPYCODE" else None


def _made(slot: Slot) -> bool:
    """A slot that holds instances of its own (an in-out refers to another's)."""
    return slot.var_class not in ("VAR_IN_OUT", "VAR_EXTERNAL", "VAR_TEMP")


def _elements(var: Var) -> list[Var]:
    """The instance ``var``, or each instance of the array it is, in row-major order."""
    ty = var.type
    if not isinstance(ty, Array):
        return [var]
    out = []
    for indices in itertools.product(*(range(low, high + 1) for low, high in ty.dims)):
        index = Index(tuple(Const(i, _DINT) for i in indices))
        out += _elements(Var(var.scope, var.name, ty.element, (*var.path, index)))
    return out
