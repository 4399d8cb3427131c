"""The resolved program the checker hands to the IR lowering: symbols, user types, POUs."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..model.diagnostics import Diagnostic
from . import ast
from .types import Type

PARAMETER_CLASSES = ("VAR_INPUT", "VAR_IN_OUT", "VAR_OUTPUT")


@dataclass(eq=False, slots=True)
class Symbol:
    """One declared variable (or directly represented variable when ``name`` is its address)."""

    name: str
    var_class: str  # VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_GLOBAL, VAR_EXTERNAL, VAR_TEMP
    type: Type
    type_spec: ast.TypeSpec
    init: ast.Init | None = None  # declared initial value, else the type's (TYP-11), else None (type default)
    address: str | None = None
    constant: bool = False
    retain: bool = False
    edge: str | None = None
    comment: str | None = None
    span: ast.Span = ast.NO_SPAN
    pou: str | None = None  # owning POU, None for globals
    implicit: str | None = None  # an SFC POU's step, action or named transition (st/sfc.py), None if declared
    #: CODESYS: each instance's FB_init arguments, (INPUT, value) checked (st/fb_init.py); None: none written
    init_args: list[list[tuple[str, ast.Expr]]] | None = None


@dataclass(eq=False)
class TypeDef:
    """A user TYPE: its resolved type and its own initial value (TYP-11)."""

    name: str
    type: Type
    init: ast.Init | None
    decl: ast.TypeDecl


@dataclass(eq=False)
class PouInfo:
    """A POU's interface and, for ST and IL POUs, its checked body (IL: as ST statements, st/il_check.py).

    ``symbols`` maps upper-case names to symbols in declaration order; ``body`` is
    the typed AST (every expression has ``.ty``, names have ``.ref``, calls have
    ``.ref``) or None for LD/FBD POUs. ``calls`` lists the upper-case names of the
    POUs this one calls or instantiates.
    """

    name: str
    kind: str  # PROGRAM, FUNCTION_BLOCK, FUNCTION (also a METHOD), INTERFACE (in CheckResult.interfaces only)
    language: str
    return_type: Type | None
    symbols: dict[str, Symbol] = field(default_factory=dict)
    return_spec: ast.TypeSpec | None = None  # the result type as written (subranges, a TYPE's own initial value)
    body: list[ast.Stmt] | None = None
    calls: set[str] = field(default_factory=set)
    plant: bool = False  # a PROGRAM that models the process: run by the plant task, never called
    actions: dict[str, list[ast.Stmt] | None] = field(default_factory=dict)
    accumulators: list[Symbol] = field(default_factory=list)  # IL POUs: the hidden current-result variables
    il_values: list = field(default_factory=list)  # IL POUs: the accumulator after each line (il_check.IlValue)
    il_step_lines: frozenset[int] = frozenset()  # IL POUs: the lines a single step stops at (ON-04)
    il_parts: dict = field(default_factory=dict)  # SFC POUs: IL actions and transitions, checked (st.sfc.il_key)
    methods: dict[str, PouInfo] = field(default_factory=dict)  # a function block's METHODs by upper-case name
    method: MethodInfo | None = None  # set on a METHOD: its FB, name as written and modifiers
    base: PouInfo | None = None  # the function block this one EXTENDS (st/inheritance.py)
    abstract: bool = False  # an ABSTRACT function block: no instances, only FBs derived from it
    final: bool = False  # a FINAL function block: nothing EXTENDS it
    interfaces: list[PouInfo] = field(default_factory=list)  # an FB: those it IMPLEMENTS; an INTERFACE: it EXTENDS
    methods_called: list[tuple[PouInfo, bool]] = field(default_factory=list)  # METHODs it calls, dispatched or not
    runs_base_body: bool = False  # a function block whose body or a method calls SUPER^(): runs its base's body
    #: CODESYS's {attribute 'call_after_init'} on a function block or on its method (st/call_after_init.py)
    after_init: bool = False
    #: a PROPERTY accessor's: its property's {attribute 'monitoring'} mode, "variable" or "call" (st/monitoring.py)
    monitoring: str | None = None
    #: the FB bodies its code runs (``SUPER^()``: the base's; ``THIS^()`` in a method: dispatched, the instance's own
    #: class's) with the call, for POU-02 (methods.check_method_recursion)
    bodies_called: list[tuple[PouInfo, bool, Any]] = field(default_factory=list)

    def lineage(self) -> list[PouInfo]:
        """This function block, then the one it extends, and so on."""
        chain, seen = [], set()
        pou: PouInfo | None = self
        while pou is not None and id(pou) not in seen:
            seen.add(id(pou))
            chain.append(pou)
            pou = pou.base
        return chain

    def derives_from(self, other: PouInfo) -> bool:
        return any(pou is other for pou in self.lineage())

    def find_method(self, name: str) -> PouInfo | None:
        """The method ``name`` of this FB, its own or the nearest inherited one; of an INTERFACE, its own or one
        of an interface it extends."""
        upper = name.upper()
        if self.kind == "INTERFACE":
            return next((i.methods[upper] for i in self.all_interfaces() if upper in i.methods), None)
        return next((pou.methods[upper] for pou in self.lineage() if upper in pou.methods), None)

    def all_interfaces(self) -> list[PouInfo]:
        """An INTERFACE and every one it extends; of an FB, every interface it or a base of it IMPLEMENTS."""
        found: list[PouInfo] = [self] if self.kind == "INTERFACE" else []
        pending = [i for pou in self.lineage() for i in pou.interfaces]
        while pending:
            interface = pending.pop(0)
            if all(interface is not known for known in found):
                found.append(interface)
                pending += interface.interfaces
        return found

    def implements(self, interface: PouInfo) -> bool:
        return any(known is interface for known in self.all_interfaces())

    def parameters(self, *classes: str) -> list[Symbol]:
        """The parameters of ``classes`` (default: all) in declaration order; a METHOD's ``THIS`` is none."""
        wanted, this = classes or PARAMETER_CLASSES, self.this()
        return [s for s in self.symbols.values() if s.var_class in wanted and s is not this]

    def this(self) -> Symbol | None:
        """A METHOD's hidden first in-out ``THIS``: the instance it is called on (st/methods.py)."""
        return self.symbols.get(THIS) if self.method is not None else None


THIS = "THIS"


@dataclass(eq=False)
class MethodInfo:
    """What makes a FUNCTION-like PouInfo a METHOD (``<FB>.<name>``): the function block it belongs to, its name
    as written, who may call it (PUBLIC, PRIVATE, PROTECTED, INTERNAL), FINAL and ABSTRACT."""

    owner: PouInfo
    name: str
    access: str = "PUBLIC"
    final: bool = False
    abstract: bool = False
    key: str = ""  # its key in ``owner.methods``: the upper-case name; a PROPERTY's accessors ``<P>.GET`` / ``.SET``
    action: bool = False  # an ACTION of the FB (CODESYS, IL-08): no variables of its own

    def __post_init__(self) -> None:
        self.key = self.key or self.name.upper()


@dataclass(eq=False)
class PropertyRef:
    """A PROPERTY of a function block as ``Member.ref`` / ``Name.ref``: read through ``getter``, written through
    ``setter`` (methods ``<FB>.<P>.GET`` / ``.SET``, st/properties.py; None: it has no such accessor)."""

    name: str
    type: Any
    getter: PouInfo | None
    setter: PouInfo | None


@dataclass(eq=False)
class GvlInfo:
    """A named global variable list (``Project.gvls``): its variables by their own (upper-case) names, which are also
    in ``CheckResult.globals``: under the same name, or as ``LIST.X`` when another list declares the name too."""

    name: str
    qualified_only: bool
    members: dict[str, Symbol] = field(default_factory=dict)


@dataclass
class CheckResult:
    diagnostics: list[Diagnostic] = field(default_factory=list)
    types: dict[str, TypeDef] = field(default_factory=dict)
    globals: dict[str, Symbol] = field(default_factory=dict)
    pous: dict[str, PouInfo] = field(default_factory=dict)
    interfaces: dict[str, PouInfo] = field(default_factory=dict)  # INTERFACEs (kind INTERFACE) by upper-case name
    gvls: dict[str, GvlInfo] = field(default_factory=dict)  # named global variable lists by upper-case name
    listed: dict[str, GvlInfo] = field(default_factory=dict)  # a GVL's variable (its globals key) -> its list
    #: a name declared in several lists (upper case) -> those lists: each keeps its variable as ``LIST.X``
    shared: dict[str, list[GvlInfo]] = field(default_factory=dict)
    configuration: Any = None  # configuration.ConfigurationInfo: the instances and tasks the project runs

    @property
    def ok(self) -> bool:
        return not any(d.severity == "error" for d in self.diagnostics)

    def pou(self, name: str) -> PouInfo | None:
        """A POU by name, or a METHOD by ``<FB>.<method>``."""
        upper = name.upper()
        found = self.pous.get(upper)
        if found is None and "." in upper:
            owner, _, method = upper.partition(".")
            fb = self.pous.get(owner) or self.interfaces.get(owner)
            found = fb.methods.get(method) if fb is not None else None
        return found
