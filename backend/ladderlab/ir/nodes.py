"""The common intermediate representation every POU is lowered to (ST, LD and FBD alike).

Structured like ST (so ST maps 1:1 and the generated Python stays readable),
plus what the diagrams need: labelled network blocks with jumps between them,
and probes that record per-element power flow. Every node keeps its ``origin``
so monitoring, breakpoints and runtime errors point at the user's source.
See docs/ir.md for the invariants.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import MISSING, dataclass, field, fields
from typing import Any, Literal, TypeVar

from ..model.places import ProjectPlaces
from ..model.validate import PLANT_TASK
from .types import IrType

T = TypeVar("T")


def quick_init(cls: type[T]) -> type[T]:
    """Give a frozen dataclass with slots an ``__init__`` that sets each field through its slot's descriptor
    instead of ``object.__setattr__`` (the frozen class's own way, ~40 % slower): a 50,000-network diagram makes
    ~1 million expression nodes (issue 27). Same parameters, defaults and fields; for classes without
    ``__post_init__`` or default factories (tests/ir/test_nodes.py compares it with the dataclass's own)."""
    own = fields(cls)  # type: ignore[arg-type]  # a dataclass (the decorator goes above @dataclass)
    assert not hasattr(cls, "__post_init__") and all(f.default_factory is MISSING for f in own), cls
    scope: dict[str, Any] = {f"set_{f.name}": getattr(cls, f.name).__set__ for f in own}
    scope.update({f"default_{f.name}": f.default for f in own if f.default is not MISSING})
    parameters = ", ".join(f.name if f.default is MISSING else f"{f.name}=default_{f.name}" for f in own)
    body = "".join(f"    set_{f.name}(self, {f.name})\n" for f in own) or "    pass\n"
    exec(f"def __init__(self, {parameters}):\n{body}", scope)
    init = scope["__init__"]
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    cls.__init__ = init  # type: ignore[misc]  # the dataclass's own, replaced
    return cls


# --------------------------------------------------------------------------- origin


@quick_init
@dataclass(frozen=True, slots=True)
class Origin:
    """Where a node came from: an ST span, or a network and element of a diagram. ``body`` names the part of an SFC
    POU the span or network lies in (an action or a named transition); None: the POU's own body, or its chart."""

    pou: str
    line: int | None = None
    column: int | None = None
    end_line: int | None = None
    end_column: int | None = None
    network: str | None = None
    element: str | None = None
    body: str | None = None


def diagram_origin(pou: str, network: str, element: str | None = None) -> Origin:
    """``Origin(pou, network=network, element=element)``, made without the frozen dataclass's eight
    ``object.__setattr__`` calls: a 10,000-network diagram makes one per element.
    (tests/ir/test_nodes.py checks it equals the constructor's object.)"""
    origin = object.__new__(Origin)
    _SET_POU(origin, pou)
    _SET_LINE(origin, None)
    _SET_COLUMN(origin, None)
    _SET_END_LINE(origin, None)
    _SET_END_COLUMN(origin, None)
    _SET_NETWORK(origin, network)
    _SET_ELEMENT(origin, element)
    _SET_BODY(origin, None)
    return origin


#: The slot setters of Origin's fields, in order (a slot's descriptor sets it past the frozen ``__setattr__``;
#: called one by one, not in a loop over them: a 50,000-network diagram makes 275,000; tests/ir/test_nodes.py
#: checks the order against the constructor's)
_SET_POU, _SET_LINE, _SET_COLUMN, _SET_END_LINE, _SET_END_COLUMN, _SET_NETWORK, _SET_ELEMENT, _SET_BODY = (
    getattr(Origin, name).__set__ for name in Origin.__slots__
)


def upper_name(name: str) -> str:
    """``name.upper()``, but the name's own string when it is upper case already: a large POU's slots, accesses and
    the code generator's tables share one string per name instead of a copy each (a 50,000-network POU has
    200,000 variables: ~10 MB a copy; issue 27)."""
    upper = name.upper()
    return name if upper == name else upper


def node_fields(node: Any) -> dict[str, Any]:
    """An IR node's fields by name (the nodes have slots, no ``__dict__``: memory and collections of a large
    build, issue 27)."""
    return {name: getattr(node, name) for name in node.__slots__}


def node_copy(node: T, changes: dict[str, Any]) -> T:
    """A copy of an IR node with ``changes``, without the frozen dataclasses' checks or ``__post_init__``."""
    copy = object.__new__(type(node))
    for name in node.__slots__:  # type: ignore[attr-defined]  # every IR node class has slots
        object.__setattr__(copy, name, changes[name] if name in changes else getattr(node, name))
    return copy


# --------------------------------------------------------------------------- expressions


@quick_init
@dataclass(frozen=True, slots=True)
class Const:
    value: object
    type: IrType


@quick_init
@dataclass(frozen=True, slots=True)
class Index:
    indices: tuple[Expr, ...]


@quick_init
@dataclass(frozen=True, slots=True)
class Member:
    name: str


@functools.lru_cache(maxsize=4096)
def member(name: str) -> Member:
    """``Member(name)``, one object per name (immutable): every FB output a diagram reads (``T1.Q``) has one, and
    each object is one more for a large build's memory and collections (issue 27)."""
    return Member(name)


@dataclass(frozen=True, slots=True)
class Deref:
    """``^``: the variable a reference (REF_TO / POINTER TO) refers to; a NULL reference is a runtime error."""


Selector = Index | Member | Deref
Scope = Literal["local", "global"]
#: The root of ``THIS^`` in a function block's body: the instance itself (no slot; a name no identifier can be)
SELF = "__SELF"


@quick_init
@dataclass(frozen=True, slots=True)
class Var:
    """A variable access path: a root slot then array indices (Index), struct/FB member selections (Member) and
    dereferences of references (Deref).

    ``scope`` says where the root lives: ``local`` in the POU instance (any declared
    class, VAR_IN_OUT included: the engine resolves the reference), ``global`` in the
    resource's globals (VAR_EXTERNAL names lower to global accesses), ``program``: the
    root is the instance of the PROGRAM ``name`` (its type ``FbInstance(name)``), read
    from another POU (``sfc1.step1.X``, ST-60). ``type`` is the type of the whole path.
    """

    scope: Scope
    name: str
    type: IrType
    path: tuple[Selector, ...] = ()


@quick_init
@dataclass(frozen=True, slots=True)
class Unary:
    op: Literal["NEG", "NOT"]
    operand: Expr
    type: IrType


@quick_init
@dataclass(frozen=True, slots=True)
class Binary:
    """Arithmetic, comparison or boolean operator on operands of one type (after conversions)."""

    op: Literal[
        "ADD",
        "SUB",
        "MUL",
        "DIV",
        "MOD",
        "EXPT",
        "AND",
        "OR",
        "XOR",
        "AND_THEN",
        "OR_ELSE",
        "EQ",
        "NE",
        "LT",
        "LE",
        "GT",
        "GE",
    ]
    left: Expr
    right: Expr
    type: IrType


@quick_init
@dataclass(frozen=True, slots=True)
class Call:
    """A function call: a standard function (by name, specialised to ``arg_types``) or a user function.

    ``virtual``: a METHOD ``<FB>.<M>`` whose implementation is chosen when it runs, by the FB of the instance it is
    called on (its first in-out, ``THIS``): ``Program.dispatch[function]`` maps each FB to the function it runs."""

    function: str
    args: tuple[Expr, ...]
    arg_types: tuple[IrType, ...]
    type: IrType
    user: bool = False
    in_outs: tuple[Var, ...] = ()
    virtual: bool = False


@quick_init
@dataclass(frozen=True, slots=True)
class Convert:
    operand: Expr
    source: IrType
    type: IrType


@quick_init
@dataclass(frozen=True, slots=True)
class Fit:
    """CODESYS typing: ``operand``, a narrow operation computed as CODESYS's register computes it (a DINT), which must
    lie in ``type``'s range (st/registers.py; ``text`` is the operation as written, for the fault's message)."""

    operand: Expr
    type: IrType
    text: str


@quick_init
@dataclass(frozen=True, slots=True)
class AddressOf:
    """``REF(x)`` / ``ADR(x)``: a reference (``type``, a ``Reference``) to the variable ``var``; ``text`` is the
    call as written, which the online views show as the reference's value."""

    var: Var
    type: IrType
    text: str


@quick_init
@dataclass(frozen=True, slots=True)
class View:
    """The reference ``value`` seen as a pointer to another type (``type``, a ``Reference``): CODESYS's
    ``pt := ADR(str)`` with ``pt : POINTER TO BYTE``. ``whole`` and ``seen`` are the byte layouts
    (ir/byte_layout.py) of what ``value`` points to and of what the view reads and writes."""

    value: Expr
    type: IrType
    whole: tuple
    seen: tuple


@quick_init
@dataclass(frozen=True, slots=True)
class Attempt:
    """``?=``'s value: the reference ``value`` (to an FB instance) when the instance's FB is one of ``blocks`` (those
    implementing the target's interface), else NULL (IEC 61131-3 ed. 3, 6.6.6.7)."""

    value: Expr
    blocks: tuple[str, ...]
    type: IrType


Expr = Const | Var | Unary | Binary | Call | Convert | Fit | AddressOf | View | Attempt

# --------------------------------------------------------------------------- statements


@dataclass(slots=True)
class Assign:
    target: Var
    value: Expr
    origin: Origin


@dataclass(slots=True)
class If:
    branches: list[tuple[Expr, list[Stmt]]]
    orelse: list[Stmt]
    origin: Origin


CaseLabel = int | tuple[int, int]


@dataclass(slots=True)
class Case:
    selector: Expr
    branches: list[tuple[list[CaseLabel], list[Stmt]]]
    orelse: list[Stmt]
    origin: Origin


@dataclass(slots=True)
class For:
    var: Var
    start: Expr
    end: Expr
    step: Expr
    body: list[Stmt]
    origin: Origin


@dataclass(slots=True)
class While:
    cond: Expr
    body: list[Stmt]
    origin: Origin


@dataclass(slots=True)
class Repeat:
    body: list[Stmt]
    until: Expr
    origin: Origin


@dataclass(slots=True)
class Exit:
    origin: Origin


@dataclass(slots=True)
class Continue:
    """CONTINUE: on to the next iteration of the innermost loop (a REPEAT's UNTIL is tested first)."""

    origin: Origin


@dataclass(slots=True)
class Return:
    origin: Origin


@dataclass(slots=True)
class FbCall:
    """Call an FB instance: set inputs, run one call with the scan's clock, copy outputs out.

    ``en`` (when not None) guards the call; ``eno`` receives whether it ran. ``body`` names the function block
    whose body runs (``SUPER^()``: the base's, on the derived instance running it); None: the instance's own.
    """

    instance: Var
    inputs: list[tuple[str, Expr]]
    outputs: list[tuple[str, Var]]
    origin: Origin
    en: Expr | None = None
    eno: Var | None = None
    body: str | None = None


@dataclass(slots=True)
class FnCall:
    """A function call as a statement, with EN/ENO: LD/FBD boxes and ST calls that use EN or ENO.

    With ``en`` FALSE the function is not called, ``target`` keeps its value and ``eno``
    is set FALSE. Otherwise the result goes to ``target`` (None: discarded) and ``eno``
    gets TRUE unless the call reported a warning (standard functions' checked form).
    """

    call: Call
    target: Var | None
    origin: Origin
    en: Expr | None = None
    eno: Var | None = None


@dataclass(slots=True)
class Jump:
    """Go to the network block ``label`` of the same POU when ``cond`` holds (None: always)."""

    label: str
    cond: Expr | None
    origin: Origin


@dataclass(slots=True)
class Probe:
    """Record ``value`` as element ``element``'s power flow / pin value in this scan (monitoring only).

    ``kind`` is the kind of its pause point in the debug variant: ``element``, or ``transition`` for an SFC
    transition that fires (what "step to the next transition" halts at)."""

    element: str
    value: Expr
    origin: Origin
    kind: Literal["element", "transition"] = "element"


@dataclass(frozen=True, slots=True, eq=False)
class Filled:
    """The template of a network shape (ir/ld_templates.py) that networks were filled in from, for the code
    generator to reuse that knowledge (engine/codegen/templates.py). The blocks of one ``Filled`` hold the same
    statements but for their networks' variables (each a local slot of the POU, none named like another variable
    of the statements), which appear in the same places (as themselves or with members: ``T1.Q``), and for the
    origins and probe names: every other value is the same object in all of them. ``variables(statements)``: a
    block's variables as it holds them, each at its first place as itself (else with its first member), in an
    order that is the same for every block."""

    variables: Callable[[list[Stmt]], tuple[Var, ...]]


@dataclass(slots=True)
class Block:
    """One network (LD/FBD) or the whole body (ST); ``label`` is its jump target, if any; ``filled``: the template
    it was filled in from, if it was (its statements left as filled)."""

    statements: list[Stmt]
    origin: Origin
    label: str | None = None
    filled: Filled | None = field(default=None, repr=False, compare=False)


Stmt = Assign | If | Case | For | While | Repeat | Exit | Continue | Return | FbCall | FnCall | Jump | Probe

# --------------------------------------------------------------------------- POUs


VarClass = Literal["VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL", "VAR_TEMP", "VAR_GLOBAL"]


@dataclass(frozen=True, slots=True)
class ReferenceInit:
    """The initial value ``REF(x)`` of a reference slot: the whole variable ``name`` of this POU (``local``) or a
    global, or its array element ``x[index]`` (constant indices, as declared), made after every other slot is
    initialised (``text`` as written, shown online); ``view``: the ``(whole, seen)`` byte layouts (ir/byte_layout.py)
    through which it sees a variable of another type, None for one of its own."""

    name: str
    scope: Scope
    text: str
    index: tuple[int, ...] = ()
    view: tuple[tuple, tuple] | None = None


@dataclass(slots=True)
class Slot:
    """A declared variable of a POU (or a global): its storage, type and initial value."""

    name: str
    var_class: VarClass
    type: IrType
    initial: object | None = None
    retain: bool = False
    constant: bool = False
    address: str | None = None
    hidden: bool = False
    #: CODESYS: the FB_init inputs of each instance it holds (one tuple; an array's, one per element in row-major
    #: order) as (INPUT, value) pairs; None: none declared (ir/fb_init.py)
    init_args: tuple[tuple[tuple[str, Const], ...], ...] | None = None


@dataclass(frozen=True, slots=True)
class MonitoredProperty:
    """A property shown online (CODESYS {attribute 'monitoring'}): ``mode`` "variable" reads the implicit slot named
    like the property that its accessors store (``name``); "call" runs ``getter`` (its GET, dispatched by the
    instance's FB when overridden) between scans, and ``setter`` (its SET) for a write."""

    name: str
    mode: str
    type: IrType
    getter: str | None = None
    setter: str | None = None


@dataclass(slots=True)
class Pou:
    name: str
    kind: Literal["program", "function_block", "function"]
    slots: list[Slot]
    blocks: list[Block]
    return_type: IrType | None = None
    language: Literal["st", "ld", "fbd", "cfc", "il", "sfc"] = "st"
    plant: bool = False  # a program that models the process: run by the plant task, never called
    #: IL: the body lines a single step stops at - loads, jumps, calls (ON-04); None: every statement's line.
    step_lines: frozenset[int] | None = None
    #: False: FB calls in the body see the time the POU was called with (a scan's clock, frozen in the scan).
    #: True: each FB call reads the engine's clock as it is then - a test's body, whose ADVANCE_TIME and
    #: RUN_SCANS move the clock between its statements (docs/testing.md).
    live_clock: bool = False


@dataclass(slots=True)
class ProgramInstance:
    """A program instance: an object of its PROGRAM's class that the engine keeps among the globals, so
    paths start with its name (``INST.X``) and RETAIN / warm restarts treat it like a global FB instance.

    ``init`` holds VAR_CONFIG initial values: (instance variable, constant, whether it is RETAIN, so that a
    warm restart keeps its value instead)."""

    name: str
    pou: str
    retain: bool = False
    init: list[tuple[Var, Const, bool]] = field(default_factory=list)


@dataclass(slots=True)
class TaskSpec:
    """A task: cyclic every ``interval_ms`` (None: only on SINGLE), once on each rising edge of ``single``
    (a BOOL variable's path; with an interval, the task is cyclic while it is FALSE, CFG-05), in ``priority``
    order (0 first). ``programs`` are the instances it runs, in order; ``body`` runs them with their parameter
    bindings and VAR_CONFIG addresses (None: just the FB calls of ``programs``). The plant task (``plant``)
    runs the plants' instances first in every scan, whichever control tasks are due."""

    name: str
    interval_ms: float | None
    priority: int
    programs: list[str]
    single: str | None = None
    body: list[Stmt] | None = None
    plant: bool = False  # the plant task: runs the plants first in every scan (engine/tasks.py)


@dataclass(slots=True)
class Program:
    """Everything the engine needs: all POUs, the globals, the program instances and the task configuration.

    ``instances`` None means one instance of every PROGRAM, named after it (IR built without a project);
    ``access`` maps VAR_ACCESS names to (path, read only)."""

    pous: dict[str, Pou]
    globals: list[Slot]
    tasks: list[TaskSpec] = field(default_factory=list)
    instances: list[ProgramInstance] | None = None
    access: dict[str, tuple[str, bool]] = field(default_factory=dict)
    #: the LD/FBD elements' names as the user sees them, for runtime faults (model/places.py)
    places: ProjectPlaces | None = field(default=None, repr=False, compare=False)
    #: method ``<FB>.<M>`` -> {function block -> the method it runs for ``M``}: for calls with ``virtual`` set
    dispatch: dict[str, dict[str, str]] = field(default_factory=dict)
    #: function blocks whose body a derived one runs with ``SUPER^()`` (``FbCall.body``), upper case
    base_bodies: frozenset[str] = frozenset()
    #: FB -> the FB_init methods its instances run, base first (ir/fb_init.py); only FBs with one in their lineage
    fb_inits: dict[str, list[str]] = field(default_factory=dict)
    #: FB -> the FB_exit methods its instances run before a restart, base first (ir/fb_init.py reverses them)
    fb_exits: dict[str, list[str]] = field(default_factory=dict)
    #: FB -> the methods its instances call after FB_init and the declaration's values (call_after_init), base first
    after_inits: dict[str, list[str]] = field(default_factory=dict)
    #: FB or PROGRAM -> its properties (upper case) shown online ({attribute 'monitoring'}, ir/monitoring.py)
    monitored: dict[str, dict[str, MonitoredProperty]] = field(default_factory=dict)
    #: FB instances may be mocked (a unit test program, engine/doubles.py swaps an instance's class): the standard
    #: FB bodies pasted in place of their calls are guarded by the instance's class
    mockable: bool = False
    #: named global variable list (upper case) -> its variables (upper case) -> the global each is (its own name, or
    #: ``LIST.X`` when lists share the name): ``GVL_IO.x`` paths
    gvls: dict[str, dict[str, str]] = field(default_factory=dict)
    #: CODESYS typing: a pointer may be taken as a number, so ADR() / REF() and VAR_IN_OUT arguments tell the engine
    #: which variable a part belongs to (engine/codegen/addresses.py)
    addresses: bool = False

    def program_instances(self) -> list[ProgramInstance]:
        """The instances to create: ``instances``, or one per PROGRAM named after it."""
        if self.instances is not None:
            return self.instances
        return [ProgramInstance(name.upper(), name.upper()) for name, pou in self.pous.items() if pou.kind == "program"]

    def task_specs(self) -> list[TaskSpec]:
        """The tasks to run: ``tasks``; for IR built without tasks or instances, one of 10 ms running every
        PROGRAM but the plants, which run in the plant task (a configuration without tasks runs nothing)."""
        if self.tasks or self.instances is not None:
            return self.tasks
        plants = {name.upper() for name, pou in self.pous.items() if pou.plant}
        instances = [i.name for i in self.program_instances()]
        programs = [name for name in instances if name not in plants]
        specs = [TaskSpec("DEFAULT", 10, 0, programs)] if programs or not plants else []
        if plants:
            specs.append(TaskSpec(PLANT_TASK, 10, 0, [name for name in instances if name in plants], plant=True))
        return specs
