"""State shared while generating one module: POU tables, layouts, origins, bound runtime objects."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

from ...iec import stdlib as catalogue
from ...ir import nodes as ir
from ...ir import types as t
from ...model.diagnostics import Diagnostic
from ..process_image import ProcessImage, image_view_name, key_of, located_address, view_kind
from ..stdlib import STANDARD_FBS
from . import names
from .layout import Layout
from .mentions import Mentions, addresses_in_out, mentions
from .runtime import UNSET
from .typeinfo import runtime_name

COMPILE_ERROR = "ENGINE-COMPILE"


class CodegenError(Exception):
    """The IR asks for something the generator cannot produce; reported as a located Diagnostic."""


def diagnostic(message: str, origin: ir.Origin | None, code: str = COMPILE_ERROR) -> Diagnostic:
    if origin is None:
        return Diagnostic(code=code, message=message)
    return Diagnostic(
        code=code,
        message=message,
        file=f"{origin.pou}/{origin.body}" if origin.body is not None else None,
        pou=origin.pou,
        line=origin.line,
        column=origin.column,
        end_line=origin.end_line,
        end_column=origin.end_column,
        network=origin.network,
        element=origin.element,
    )


@dataclass(frozen=True)
class PausePoint:
    """Where the debug variant may halt: before a network (``network``), an ST statement (``statement``)
    or at an element's probe (``element``); ``line``: an IL line a single step passes (not a load, jump or
    call, ON-04), which a breakpoint on the line still halts at."""

    id: int
    kind: str
    origin: ir.Origin
    element: str | None = None  # the probe's element id ("E1" or "E1.PIN")


@dataclass
class ProbeTable:
    """The probes of one POU, numbered at code generation.

    Monitoring code stores element ``i``'s value in ``ll_pr[i]`` (a list per POU
    instance, or per FUNCTION) and, once per straight run of code, the scan's stamp
    in ``ll_px[g]``: element ``i`` executed in a scan when one of ``groups[i]`` holds
    that scan's stamp. Numbering depends only on the IR, so the monitor and the
    debug variant of a program share it (and switch between scans).
    """

    elements: list[str] = field(default_factory=list)
    groups: list[list[int]] = field(default_factory=list)
    group_count: int = 0
    constants: dict[int, object] = field(default_factory=dict)  # probes of constants: no store, the value is here
    deferred: list[int] = field(default_factory=list)  # read after the scan by ll_read_probes (codegen/deferred.py)
    #: The variable each deferred probe reads, as a path below the program instance (``T1.Q``), so a monitor
    #: can read a few of them without ``ll_read_probes`` reading them all.
    deferred_paths: dict[int, str] = field(default_factory=dict)
    #: Probes whose value is another's, stored once (``Statements._same_probe``): probe number -> the probe
    #: number it reads (monitor variant; its readers go through ``frames.frame_plan``)
    aliases: dict[int, int] = field(default_factory=dict)
    #: Networks whose probes the monitor variant stores only while a client views them (``ll_v[n]``, see
    #: ``Statements.block``): their count, and each probe's network (absent: stored in every scan).
    networks: int = 0
    network_of: dict[int, int] = field(default_factory=dict)
    #: The origin id (``ModuleContext.origins``, numbered in emission order) of the statement storing each probe,
    #: its last one: the probes a fault stopped are those of its network from its statement on (engine/stopped.py)
    origins: list[int] = field(default_factory=list)
    _index: dict[str, int] = field(default_factory=dict)

    def index(self, element: str) -> int | None:
        """The probe number of ``element`` (None: not probed)."""
        return self._index.get(element)

    def probe(self, element: str, group: int, origin: int, constant: object = UNSET, network: int | None = None) -> int:
        index = self._index.get(element)
        if index is None:
            index = self._index[element] = len(self.elements)
            self.elements.append(element)
            self.groups.append([])
            self.origins.append(origin)
            if network is not None:
                self.network_of[index] = network
        else:
            self.origins[index] = origin
        groups = self.groups[index]
        if not groups or groups[-1] != group:  # groups are numbered in emission order
            groups.append(group)
        if constant is not UNSET:
            self.constants[index] = constant
        return index

    def new_group(self) -> int:
        self.group_count += 1
        return self.group_count - 1

    def new_network(self) -> int:
        self.networks += 1
        return self.networks - 1


@dataclass
class ModuleContext:
    program: ir.Program
    variant: str
    pous: dict[str, ir.Pou] = field(default_factory=dict)
    layouts: dict[str, Layout] = field(default_factory=dict)
    globals: Layout = field(init=False)  # set in __post_init__
    structs: dict[t.Struct, str] = field(default_factory=dict)
    bound: dict[str, object] = field(default_factory=dict)
    origins: list[ir.Origin] = field(default_factory=list)
    #: The statement of each origin, None for those of no statement (a statement's variables are read back for a
    #: fault report; a list, not a dict by index: a 50,000-network program has 140,000)
    origin_statements: list[ir.Stmt | None] = field(default_factory=list)
    pauses: list[PausePoint] = field(default_factory=list)
    probe_tables: dict[str, ProbeTable] = field(default_factory=dict)  # upper-case POU name -> its probes
    instances: list[ir.ProgramInstance] = field(default_factory=list)
    tasks: list[ir.TaskSpec] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    _bound_keys: dict[object, str] = field(default_factory=dict)
    _mentions: dict[str, Mentions] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.pous = {name.upper(): pou for name, pou in self.program.pous.items()}
        self.layouts = {name: Layout(pou.slots) for name, pou in self.pous.items() if pou.kind != "function"}
        self.instances = self.program.program_instances()
        self.tasks = self.program.task_specs()
        instance_slots = [  # program instances live among the globals, first (docs/runtime.md)
            ir.Slot(i.name.upper(), "VAR_GLOBAL", t.FbInstance(i.pou.upper()), None, i.retain) for i in self.instances
        ]
        self.globals = Layout(instance_slots + self.program.globals)

    @cached_property
    def in_outs_addressed(self) -> bool:
        """Whether some POU takes REF()/ADR() of its own VAR_IN_OUT (mentions.addresses_in_out): only then does a
        call pass its own call's variables to an in-out with the call's frame (runtime.FramedPair)."""
        return any(addresses_in_out(self.mentions(pou)) for pou in self.pous.values())

    @cached_property
    def constant_pins(self) -> dict[str, dict[str, tuple[tuple[str, object], ...]]]:
        """The standard FB inputs stored once, at initialisation (constant_inputs.py): POU -> instance -> pins."""
        from .constant_inputs import constant_inputs  # (it reads this context's POUs and mentions)

        return constant_inputs(self)

    @cached_property
    def constant_pin_names(self) -> dict[tuple[str, str], frozenset[str]]:
        """(POU, instance) -> the names of the pins ``constant_pins`` holds for it (what its calls do not store)."""
        return {
            (pou, slot): frozenset(pin for pin, _ in held)
            for pou, instances in self.constant_pins.items()
            for slot, held in instances.items()
        }

    @cached_property
    def constant_slots(self) -> dict[int, tuple[tuple[str, object], ...]]:
        """``constant_pins`` by the id of the instance's ``ir.Slot`` (its initialisation sets them)."""
        pins = self.constant_pins
        return {
            id(self.layouts[pou].places[slot].slot): held
            for pou, instances in pins.items()
            for slot, held in instances.items()
        }

    def mentions(self, pou: ir.Pou) -> Mentions:
        """What the POU's body mentions (mentions.mentions), walked once per POU: several questions need it."""
        found = self._mentions.get(pou.name.upper())
        if found is None or found.pou is not pou:
            found = self._mentions[pou.name.upper()] = mentions(pou)
        return found

    @property
    def located(self) -> list[ir.Slot]:
        """Every located variable: the globals' (addresses used without a declaration among them), the POUs'."""
        found = list(self.globals.located.values())
        for layout in self.layouts.values():
            found += layout.located.values()
        return found

    def image_sizes(self) -> dict[str, int]:
        """Bytes of each process image area: up to the last byte a located variable uses."""
        sizes: dict[str, int] = {}
        for slot in self.located:
            address = located_address(slot.address)
            sizes[address.area] = max(sizes.get(address.area, 0), address.end)
        return sizes

    def image_view(self, slot: ir.Slot, world: bool = False) -> tuple[str, int]:
        """(the name of the view a located slot is read and written through, its key in that view). ``world``:
        the code stands for the world outside the program (a test's body): what it writes to an input also sets
        the inputs the next scans read, as a path's write does (ProcessImage.path_buffer)."""
        address = located_address(slot.address)
        buffer = ProcessImage.path_buffer(address.area, writing=world)
        return image_view_name(buffer, view_kind(address, runtime_name(slot.type))), key_of(address)

    @property
    def world_views(self) -> bool:
        """Whether some POU stands for the world (a test's body, ``live_clock``): it writes inputs as the world."""
        return any(p.live_clock for p in self.pous.values())

    def instance(self, name: str) -> ir.ProgramInstance | None:
        """The program instance called ``name``."""
        upper = name.upper()
        return next((i for i in self.instances if i.name.upper() == upper), None)

    @property
    def debug(self) -> bool:
        """Generators with pause points (breakpoints, stepping)."""
        return self.variant == "debug"

    @property
    def probes(self) -> bool:
        """Probes record power flow: the monitor and the debug variant."""
        return self.variant != "fast"

    def probe_table(self, pou: str) -> ProbeTable:
        """The table to number ``pou``'s probes in (code generation)."""
        return self.probe_tables.setdefault(pou.upper(), ProbeTable())

    def probes_of(self, pou: str) -> ProbeTable:
        """``pou``'s probes (empty when it has none); changes nothing, so any thread may ask."""
        return self.probe_tables.get(pou.upper()) or ProbeTable()

    def origin(self, origin: ir.Origin, statement: ir.Stmt | None = None) -> int:
        self.origins.append(origin)
        self.origin_statements.append(statement)
        return len(self.origins) - 1

    def pause(self, kind: str, origin: ir.Origin, element: str | None = None) -> int:
        point = PausePoint(len(self.pauses), kind, origin, element)
        self.pauses.append(point)
        return point.id

    def bind(self, key: object, prefix: str, make: Callable[[], object]) -> str:
        """A module global holding ``make()``, created once per ``key``; returns its generated name."""
        name = self._bound_keys.get(key)
        if name is None:
            name = f"{prefix}_{len(self._bound_keys)}"
            self._bound_keys[key] = name
            self.bound[name] = make()
        return name

    def struct_class(self, struct: t.Struct) -> str:
        name = self.structs.get(struct)
        if name is None:
            base = name = names.struct_class(struct.name)
            taken = set(self.structs.values())
            number = 0
            while name in taken:  # two structures of one name (anonymous or per POU), or one named like a suffix
                number += 1
                name = f"{base}_{number}"
            self.structs[struct] = name
            for f in struct.fields:
                self.visit_type(f.type)
        return name

    def visit_type(self, ty: t.IrType) -> None:
        """Register the structure classes a type needs."""
        if isinstance(ty, t.Struct):
            self.struct_class(ty)
        elif isinstance(ty, t.Array):
            self.visit_type(ty.element)

    def user_fb(self, fb: str) -> ir.Pou | None:
        pou = self.pous.get(fb.upper())
        return pou if pou is not None and pou.kind != "function" else None


def std_fb_class(fb: str) -> type | None:
    return STANDARD_FBS.get(fb.upper())


@lru_cache(maxsize=1024)  # bounded: FB names come from user text
def std_pin_type(fb: str, pin: str) -> t.IrType | None:
    """Type of a pin (or named memory, e.g. the M of R_TRIG) of a standard FB; None when it has no such pin."""
    cls = std_fb_class(fb)
    if cls is None:
        return None
    pin = pin.upper()
    info = catalogue.function_block(fb)
    if info is not None:
        for p in (*info.inputs, *info.outputs):
            if p.name == pin:
                return t.Elementary(p.type)
    if pin in cls.MEMORY:
        return t.BOOL
    return None
