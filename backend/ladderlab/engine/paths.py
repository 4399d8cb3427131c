"""Variable paths of a running simulation: ``MAIN.T1.Q``, ``GVL.START`` or ``START``, ``MAIN.ARR[3]``, ``MAIN.S.F``,
``MAIN.P^`` / ``MAIN.P^.X`` through a pointer or reference (ON-11; a member after a reference steps through it
too, as CODESYS ``REFERENCE TO`` reads: ``MAIN.R.X``), a bit or part of an integer or bit string: ``MAIN.W.%X3``
(also written ``MAIN.W.3``), ``MAIN.D.%B1`` (issue 25, as ST's partial access reads and writes it).

Names are matched case-insensitively against the IR's canonical names; the
first segment is a VAR_ACCESS name, else ``GVL`` (the globals), else a global:
program instances are globals (codegen/tasks.py), so ``MAIN.X`` is the variable X
of the instance MAIN.
``resolve`` turns text into a ``Location``, which walks the live objects on
every access (so it stays valid across a reset). Unknown names raise
``UnknownPath`` (a KeyError) with a did-you-mean hint; malformed text and bad
indices raise ValueError. ``snapshot`` lists every elementary variable.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from ..iec import values
from ..iec.addresses import PART_NAMES, PARTS, Address, parse_address, part_type, partial_access, same_location
from ..iec.literals import textless_character, textless_message
from ..iec.spelling import did_you_mean
from ..ir import nodes as ir
from ..ir import types as t
from ..ir.types import describe
from .codegen import names
from .codegen.context import ModuleContext, std_fb_class, std_pin_type
from .codegen.runtime import reference_text
from .codegen.scope import global_owner
from .codegen.typeinfo import is_composite, runtime_name
from .errors import PlcRuntimeError
from .process_image import ProcessImage, image_view_name, key_of, located_address, view_kind

GLOBALS_PREFIX = "GVL"
VIEW_PREFIX = "ll_io_"
_DEREF = object()  # step into a VAR_IN_OUT reference
_TOKEN = re.compile(
    r"\s*(?:(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<int>[+-]?\d+)|(?P<part>%[XBWDL]\d+)|(?P<punct>[.\[\],^]))",
    re.IGNORECASE,
)


#: Why no path reaches a FUNCTION's or METHOD's variables (CODESYS shows them only in a halted call, too).
_ONE_CALL = (
    "its variables live for one call only, so no path names them; they are shown while a scan is halted in it "
    "(the call stack, and inline in its editor)"
)

#: Why no path reaches a PROPERTY without CODESYS's {attribute 'monitoring'}: reading one runs its GET, code that may
#: change variables (issue 25).
_ACCESSOR = (
    "its value is what its GET returns when the program calls it, and watching or tracing never runs code that may "
    "change variables; watch or trace the variables its GET reads, or mark the property {attribute 'monitoring' := "
    "'variable'} (its last value) or 'call' (its GET run between scans)"
)
#: Why a property monitored as 'variable' is not written: CODESYS allows only reading it.
_LAST_VALUE = (
    "a property monitored as 'variable' shows the value of its last GET or SET, and is read only (CODESYS); "
    "assign the property in the program or write the variables its SET writes"
)
#: Why a property monitored as 'call' without SET is not written (with one, a write runs it: CODESYS).
_CALLED = "a property monitored as 'call' is written by running its SET, and it has none"


class UnknownPath(KeyError):
    def __str__(self) -> str:
        return str(self.args[0])


class NoTarget(ValueError):
    """A path through a pointer that is NULL (or points outside its array) now: it names no variable; or one through
    a pointer seeing other memory (engine/codegen/views.py) whose bytes hold no value of its type, or cannot hold the
    value written (a subrange left, a BOOL byte of 2)."""


class AccessorFault(NoTarget):
    """The GET (SET) of a property monitored as 'call' faulted when run to show its value (to write it): ``fault`` is
    the located fault (engine/codegen/faults.py); no value is shown (written on), the program's tasks go on."""

    def __init__(self, message: str, fault: object) -> None:
        super().__init__(message)
        self.fault = fault


@dataclass(frozen=True)
class _Pointee:
    """A key that steps through the REF_TO / POINTER TO value at ``pointer`` (a path) to what it points to."""

    pointer: str


def _target(ref: object, step: _Pointee) -> tuple[object, object]:
    """The ``(container, key)`` a pointer value points to; NoTarget when it is NULL or outside its array."""
    if ref is None:
        raise NoTarget(f"{step.pointer} is NULL: {step.pointer}^ is no variable now")
    try:
        return ref.pair  # type: ignore[attr-defined, no-any-return]  # a Ref (engine/codegen/runtime.py)
    except PlcRuntimeError as error:  # a moved pointer beyond its array
        raise NoTarget(f"{step.pointer}^: {error.message}") from None


@dataclass(frozen=True)
class Accessors:
    """The last key of a property monitored as 'call' (``{attribute 'monitoring' := 'call'}``): its value is what
    its GET ``getter`` returns when run on the instance before it, and a write runs its SET ``setter`` (None: it
    has none), between scans (``Roots.run_accessor``); ``*_dispatched``: by the instance's function block."""

    getter: str
    get_dispatched: bool
    setter: str | None
    set_dispatched: bool


@dataclass(frozen=True)
class _Part:
    """A key that picks ``width`` bits from bit ``shift`` of the integer or bit string before it (``w.%X3``); an
    integer's parts are those of its two's complement pattern, ``bits`` wide (``signed``: wrapped back on a write)."""

    width: int
    shift: int
    bits: int
    signed: bool


class _Bits:
    """The variable at ``container[key]`` as the container of its parts: reading one reads the variable's bits,
    writing one writes the variable's new pattern (the other bits kept), as ST's ``w.%X3 := b`` does."""

    def __init__(self, container: Any, key: object) -> None:  # Any: an instance, a structure, a list or a view
        self.container, self.key = container, key

    def __getitem__(self, part: _Part) -> object:
        value = (self.container[self.key] >> part.shift) & ((1 << part.width) - 1)
        return bool(value) if part.width == 1 else value

    def __setitem__(self, part: _Part, value: object) -> None:
        mask = ((1 << part.width) - 1) << part.shift
        old = self.container[self.key]
        pattern = ((old & ~mask) | (int(value) << part.shift)) & ((1 << part.bits) - 1)  # type: ignore[call-overload]  # a BOOL or an integer: coerce_for checked it
        if part.signed and pattern >> (part.bits - 1):
            pattern -= 1 << part.bits
        self.container[self.key] = pattern


def _step(obj: object, key: object) -> object:
    if key is _DEREF:
        return obj[0][obj[1]]  # type: ignore[index]  # a VAR_IN_OUT's (container, key)
    if isinstance(key, _Pointee):
        container, inner = _target(obj, key)
        return container[inner]  # type: ignore[index]  # what the Ref's container holds
    return obj[key]  # type: ignore[index]  # an instance, a structure, a list or a view


@dataclass(frozen=True)
class Location:
    """An elementary or composite variable: ``path`` in canonical form, its IR type, how to reach it."""

    path: str
    type: t.IrType
    root: tuple[str, str]  # ("global", a G page or a process image view) or ("attached", an instance's name)
    keys: tuple[object, ...]
    read_only: bool = False  # a READ_ONLY access path (VAR_ACCESS)
    write_root: tuple[str, str] | None = None  # where writes go when not to ``root`` (the world's side of I/Q)
    refusal: str = ""  # why it is never written (a monitored property), else ""

    @property
    def elementary(self) -> bool:
        return not is_composite(self.type)

    @property
    def called(self) -> bool:
        """It is a property monitored as 'call': reading it runs code (its GET), between scans only."""
        return isinstance(self.keys[-1], Accessors)

    @property
    def through_pointer(self) -> bool:
        """It is reached through a pointer or reference (``p^``), so it may name no variable at times."""
        return any(isinstance(key, _Pointee) for key in self.keys)

    def _container(self, roots: Roots, writing: bool = False) -> tuple[object, object]:
        return _pair(roots.get(self.write_root if writing and self.write_root is not None else self.root), self.keys)

    def get(self, roots: Roots) -> object:
        call = self.keys[-1]
        if isinstance(call, Accessors):
            reference = _pair(roots.get(self.root), self.keys[:-1])
            return roots.run_accessor(self.path, call.getter, call.get_dispatched, reference, ())
        container, key = self._container(roots)
        try:
            return container[key]  # type: ignore[index]
        except PlcRuntimeError as error:  # through a pointer that sees other memory
            raise NoTarget(f"{self.path}: {error.message}") from None

    def set(self, roots: Roots, value: object) -> None:
        call = self.keys[-1]
        if isinstance(call, Accessors) and call.setter is not None:  # (coerce_for refuses one without a SET)
            reference = _pair(roots.get(self.root), self.keys[:-1])
            roots.run_accessor(self.path, call.setter, call.set_dispatched, reference, (value,))
            return
        container, key = self._container(roots, writing=True)
        try:
            container[key] = value  # type: ignore[index]
        except PlcRuntimeError as error:  # as above
            raise NoTarget(f"{self.path}: {error.message}") from None

    def trial(self, roots: Roots, value: object) -> None:
        """NoTarget when writing ``value`` here now would fault (through a pointer that sees other memory: a
        subrange left, a BOOL byte of 2); writes nothing, so a user's write is refused when it is given."""
        container, key = self._container(roots, writing=True)
        trial = getattr(container, "trial", None)  # a views.ViewRef (its pair is (the view, "v")) or what it sees
        if trial is None:
            return
        try:
            trial(key, value)
        except PlcRuntimeError as error:
            raise NoTarget(f"{self.path}: {error.message}") from None

    def reference(self, roots: Roots) -> tuple[object, object]:
        """A VAR_IN_OUT reference ``(container, key)`` to this location, as generated code passes one."""
        return self._container(roots)


def _pair(obj: object, keys: tuple[object, ...]) -> tuple[object, object]:
    """The ``(container, key)`` that ``keys`` reach from ``obj``; a part's container is its variable's bits."""
    *steps, last = keys
    if isinstance(last, _Part):
        return _Bits(*_pair(obj, tuple(steps))), last
    for key in steps:
        obj = _step(obj, key)
    if last is _DEREF:
        return obj  # type: ignore[return-value]  # the reference itself is (container, key)
    if isinstance(last, _Pointee):
        return _target(obj, last)
    return obj, last


class Roots:
    """The live objects paths start from: the global pages (program instances are globals) of a module, the
    process image's views (made on first use: a path may read an address through a view no code uses) and the
    instances attached outside the tasks (``Simulation.attach``)."""

    def __init__(
        self,
        ns: dict[str, object],
        attached: dict[str, tuple[object, str]],
        run_accessor: Callable[[str, str, bool, tuple[object, object], tuple[object, ...]], object] | None = None,
    ) -> None:
        self.ns = ns
        self.attached = attached  # upper-case name -> (instance, upper-case POU name)
        #: runs a 'call' property's GET or SET (path, function, dispatched, instance reference, inputs): Simulation's
        #: between scans, a fault located
        self.run_accessor = run_accessor or _no_accessor

    def get(self, root: tuple[str, str]) -> object:
        kind, name = root
        if kind == "attached":
            return self.attached[name][0]
        found = self.ns.get(name)
        if found is None and name.startswith(VIEW_PREFIX):
            buffer, kind = name[len(VIEW_PREFIX) :].split("_", 1)
            image = self.ns["ll_image"]
            assert isinstance(image, ProcessImage)
            found = self.ns[name] = image.view(buffer, kind)
        return found


def _no_accessor(path: str, function: str, dispatched: bool, reference: object, inputs: tuple[object, ...]) -> object:
    raise NoTarget(f"{path}: its GET and SET run only in a simulation, between scans")


def tokens(text: str) -> list[tuple[str, str]]:
    found, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if not match or match.end() == pos:
            raise ValueError(f"{text!r} is not a variable path (unexpected {text[pos:].strip()[:10]!r})")
        kind = match.lastgroup
        found.append((kind, match.group(kind)))  # type: ignore[arg-type]
        pos = match.end()
    return found


class Resolver:
    _CACHE_LIMIT = 10_000

    def __init__(self, context: ModuleContext) -> None:
        self.context = context
        self.access = {name.upper(): target for name, target in context.program.access.items()}
        self.attached: dict[str, str] = {}  # root name of an instance outside the tasks -> its POU (upper case)
        self._cache: dict[str, Location] = {}

    def attach(self, name: str, pou: str) -> None:
        """Resolve paths starting with ``name`` in an instance of ``pou`` (``Simulation.attach``)."""
        self.attached[name.upper()] = pou.upper()
        self._cache.clear()

    def resolve(self, text: str) -> Location:
        """The location a path names; resolved paths are remembered (locations walk from the live roots, so
        they stay valid), so reading the same paths every scan does not parse them every scan."""
        location = self._cache.get(text) if isinstance(text, str) else None
        if location is None:
            location = self._resolve(text)
            if len(self._cache) < self._CACHE_LIMIT:
                self._cache[text] = location
        return location

    def _resolve(self, text: str) -> Location:
        if not isinstance(text, str):
            raise ValueError(f"a variable path must be text, not {text!r}")
        if text.strip().startswith("%"):
            return self._address(text.strip())
        toks = tokens(text)
        if not toks or toks[0][0] != "name":
            raise ValueError(f"{text!r} is not a variable path (it must start with a name)")
        first = toks[0][1].upper()
        rest = toks[1:]
        if first in self.access:  # a VAR_ACCESS name stands for its path
            target, read_only = self.access[first]
            located = self._resolve(target + text.strip()[len(toks[0][1]) :])
            return Location(located.path, located.type, located.root, located.keys, read_only)
        if first in self.attached:
            if not rest:
                raise ValueError(f"{text!r}: expected '.name' after {first}")
            return self._walk(text, first, ("attached", first), t.FbInstance(self.attached[first]), (), rest)
        listed = self.context.program.gvls.get(first)
        if listed is not None and rest[:1] == [("punct", ".")]:  # GVL_IO.x: a named list's variable
            name, after = self._member_name(rest, text)
            if name.upper() in listed:
                return self._global(text, listed[name.upper()], after)
            if first != GLOBALS_PREFIX:  # a list called GVL: GVL.x is any global still
                raise UnknownPath(f"the global variable list {toks[0][1]} has no variable {name!r}")
        if first == GLOBALS_PREFIX and rest[:1] == [("punct", ".")]:
            name, rest = self._member_name(rest, text)
            return self._global(text, name, rest)
        return self._global(text, toks[0][1], rest, top=True)

    def _member_name(self, rest: list, text: str) -> tuple[str, list]:
        if len(rest) < 2 or rest[0] != ("punct", ".") or rest[1][0] != "name":
            raise ValueError(f"{text!r}: expected '.name' after {text.split('.')[0].split('[')[0].strip()}")
        return rest[1][1], rest[2:]

    def _address(self, text: str) -> Location:
        """``%IX0.1``: the address with the type of the variable declared at it, else its size's default; it
        must lie in the process image (the addresses the program uses)."""
        address = parse_address(text)
        declared = next((s for s in self.context.located if same_location(s.address, address)), None)
        image = self.context.image_sizes()
        if address.end > image.get(address.area, 0):
            used = image.get(address.area, 0)
            raise UnknownPath(
                f"{address.text} is outside the process image: the program uses {used} byte(s) of %{address.area}"
                + (f" (%{address.area}B0..%{address.area}B{used - 1})" if used else "")
            )
        ty = declared.type if declared is not None else t.Elementary(address.default_type)
        return located_location(address.text, ty, address)

    def _global(self, text: str, name: str, rest: list, top: bool = False) -> Location:
        place = self.context.globals.get(name)
        located = self.context.globals.located.get(name.upper()) if place is None else None
        if located is not None:
            return self._steps_located(text, located.name, located, rest)
        if place is None and top:
            instance = self._only_instance(name)
            if instance is not None:  # PLC_PRG.x for the one instance of PLC_PRG, whatever its name
                place = self.context.globals.get(instance)
                if place is not None:
                    root = ("global", global_owner(place.page))
                    return self._steps(text, name.upper(), root, (place.attr,), place.slot, rest)
        if place is None:
            shared = [
                f"{key}.{name.upper()}"
                for key, listed in self.context.program.gvls.items()
                if "." in listed.get(name.upper(), "")
            ]
            if shared:  # a name several lists declare (st/gvls.py)
                raise UnknownPath(f"{name} is declared in several global variable lists: write {' or '.join(shared)}")
            candidates = [p.slot.name for p in self.context.globals.places.values() if not p.slot.hidden]
            if top:
                pou = self.context.pous.get(name.upper())
                if pou is not None and pou.kind == "function":
                    raise UnknownPath(f"{name} is a FUNCTION: {_ONE_CALL}")
                candidates += list(self.access)
                raise UnknownPath(f"unknown variable or program {name!r}{did_you_mean(name, candidates)}")
            raise UnknownPath(f"unknown global variable {name!r}{did_you_mean(name, candidates)}")
        root = ("global", global_owner(place.page))
        return self._steps(text, place.slot.name, root, (place.attr,), place.slot, rest)

    def _only_instance(self, name: str) -> str | None:
        """The instance of PROGRAM ``name`` when it has exactly one (a configuration may name it otherwise)."""
        pou = self.context.pous.get(name.upper())
        if pou is None or pou.kind != "program":
            return None
        names = [i.name for i in self.context.instances if i.pou.upper() == name.upper()]
        if len(names) > 1:
            raise UnknownPath(f"PROGRAM {name} has {len(names)} instances ({', '.join(names)}): name one")
        return names[0] if names else None

    def _steps(self, text, path, root, keys, slot: ir.Slot, rest) -> Location:
        if slot.var_class == "VAR_IN_OUT":
            keys = (*keys, _DEREF)
        return self._walk(text, path, root, slot.type, keys, rest)

    def _walk(self, text, path, root, ty: t.IrType, keys, rest) -> Location:
        while rest:
            kind, value = rest[0]
            if isinstance(ty, t.Reference) and (kind, value) == ("punct", "."):
                ty, keys = ty.target, (*keys, _Pointee(path))  # CODESYS REFERENCE TO: r.x reads through r
            if (kind, value) == ("punct", ".") and len(rest) > 1 and rest[1][0] in ("part", "int"):
                path, ty, keys = self._part(path, ty, keys, rest[1][1])
                rest = rest[2:]
            elif (kind, value) == ("punct", "."):
                member, rest = self._member_name(rest, text)
                monitored = self._monitored(ty, member)
                if monitored is not None:
                    return self._property(path, ty, keys, root, monitored, rest)
                path, ty, keys = self._member(path, ty, keys, member)
                if isinstance(keys, Location):  # a located variable of an FB or program instance
                    return self._located_part(keys, rest)
            elif (kind, value) == ("punct", "["):
                indices, rest = self._indices(rest[1:], text)
                path, ty, keys = self._index(path, ty, keys, indices)
            elif (kind, value) == ("punct", "^"):
                if not isinstance(ty, t.Reference):
                    raise ValueError(f"{path} is {_a(ty)}, not a pointer or reference: '^' cannot follow it")
                path, ty, keys, rest = f"{path}^", ty.target, (*keys, _Pointee(path)), rest[1:]
            else:
                raise ValueError(f"{text!r} is not a variable path (unexpected {value!r})")
        return Location(path, ty, root, keys)

    def _monitored(self, ty: t.IrType, member: str) -> ir.MonitoredProperty | None:
        """The property ``member`` of an instance of type ``ty`` when {attribute 'monitoring'} shows it online."""
        if not isinstance(ty, t.FbInstance):
            return None
        return self.context.program.monitored.get(ty.fb.upper(), {}).get(member.upper())

    def _property(self, path, ty, keys, root, prop: ir.MonitoredProperty, rest) -> Location:
        """A monitored property of the instance at ``keys``: its implicit variable ('variable'), or its GET run
        when read ('call'); neither is written online, and its value is one value (no member, element or part)."""
        if rest:
            raise ValueError(f"{path}.{prop.name.upper()} is a property shown online: watch it whole, not a part of it")
        if prop.mode == "variable":
            path, ty, keys = self._member(path, ty, keys, prop.name)
            return Location(path, ty, root, keys, refusal=_LAST_VALUE)
        path = f"{path}.{prop.name.upper()}"  # (as the implicit variable of 'variable' is named)
        assert prop.getter is not None  # (st/monitoring.py: 'call' without a GET is ignored)
        dispatch = self.context.program.dispatch
        call = Accessors(prop.getter, prop.getter in dispatch, prop.setter, prop.setter in dispatch)
        return Location(path, prop.type, root, (*keys, call), refusal="" if prop.setter else _CALLED)

    def _steps_located(self, text: str, name: str, slot: ir.Slot, rest: list[tuple[str, str]]) -> Location:
        return self._located_part(located_location(name, slot.type, located_address(slot.address)), rest)

    def _located_part(self, location: Location, rest: list[tuple[str, str]]) -> Location:
        """A located variable, or a bit or part of it (``inputs.%X3``): read from and written to the image."""
        if not rest:
            return location
        if len(rest) != 2 or rest[0] != ("punct", ".") or rest[1][0] not in ("part", "int"):
            raise ValueError(f"{location.path} is {_a(location.type)} in the process image: it has no members")
        path, ty, keys = self._part(location.path, location.type, location.keys, rest[1][1])
        return Location(path, ty, location.root, keys, write_root=location.write_root)

    def _indices(self, rest: list, text: str) -> tuple[list[int], list]:
        indices = []
        while True:
            if not rest or rest[0][0] != "int":
                raise ValueError(f"{text!r}: array indices must be integers")
            indices.append(int(rest[0][1]))
            if rest[1:2] == [("punct", ",")]:
                rest = rest[2:]
            elif rest[1:2] == [("punct", "]")]:
                return indices, rest[2:]
            else:
                raise ValueError(f"{text!r}: expected ',' or ']' after an index")

    def _member(self, path, ty, keys, member):
        if isinstance(ty, t.FbInstance):
            user = self.context.user_fb(ty.fb)
            if user is not None:
                layout = self.context.layouts[user.name.upper()]
                inner = layout.get(member)
                if inner is None and member.upper() in layout.located:
                    slot = layout.located[member.upper()]
                    location = located_location(f"{path}.{slot.name}", slot.type, located_address(slot.address))
                    return location.path, location.type, location
                if inner is None and f"{user.name}.{member}".upper() in self.context.pous:
                    raise UnknownPath(f"{path}.{member} is a METHOD of {user.name}: {_ONE_CALL}")
                if (
                    inner is None
                    and {f"{user.name}.{member}.{a}".upper() for a in ("GET", "SET")} & self.context.pous.keys()
                ):
                    raise UnknownPath(f"{path}.{member} is a PROPERTY of {user.name}: {_ACCESSOR}")
                if inner is None:
                    what = path if path.upper() == ty.fb.upper() else f"{path} ({ty.fb})"  # a program instance: MAIN
                    raise UnknownPath(f"{what} has no variable {member!r}{did_you_mean(member, _visible(layout))}")
                step = (inner.attr,) if inner.page == 0 else (f"ll_p{inner.page}", inner.attr)
                deref = (_DEREF,) if inner.slot.var_class == "VAR_IN_OUT" else ()
                return f"{path}.{inner.slot.name}", inner.slot.type, (*keys, *step, *deref)
            pin_type = std_pin_type(ty.fb, member)
            if pin_type is None:
                pins = [*std_fb_class(ty.fb).INPUTS, *std_fb_class(ty.fb).OUTPUTS]
                raise UnknownPath(f"{path} ({ty.fb}) has no pin {member!r}{did_you_mean(member, pins)}")
            return f"{path}.{member.upper()}", pin_type, (*keys, member.upper())
        if isinstance(ty, t.Struct):
            for f in ty.fields:
                if f.name.upper() == member.upper():
                    return f"{path}.{f.name}", f.type, (*keys, names.slot(f.name))
            fields = [f.name for f in ty.fields]
            raise UnknownPath(f"{path} ({ty.name}) has no field {member!r}{did_you_mean(member, fields)}")
        raise ValueError(f"{path} is {_a(ty)}: it has no member {member!r}")

    def _part(
        self, path: str, ty: t.IrType, keys: tuple[object, ...], member: str
    ) -> tuple[str, t.IrType, tuple[object, ...]]:
        """``.%X3``, ``.3``, ``.%B1`` of an integer or bit string (the ST checker's rule and numbering)."""
        width, index = partial_access(member) or (0, 0)
        info = ty.info if isinstance(ty, t.Elementary) else None
        if info is None or info.category not in ("bits", "int") or width == 0:
            raise ValueError(f"{path} is {_a(ty)}: it has no bit or part {member!r}")
        if index >= info.bits // width:
            what, count = PART_NAMES[width], info.bits // width
            raise ValueError(
                f"{path}.{member} is outside {path}, a {ty.name}: it has {what} 0..{count - 1}"
                if count
                else f"{path}.{member}: a {ty.name} has no {what}, it is {info.bits} bits wide"
            )
        letter = next(name for name, (bits, _) in PARTS.items() if bits == width)
        part = _Part(width, index * width, info.bits, info.signed)
        return f"{path}.%{letter}{index}", t.Elementary(part_type(width)), (*keys, part)

    def _index(self, path, ty, keys, indices):
        if not isinstance(ty, t.Array):
            raise ValueError(f"{path} is {_a(ty)}: it cannot be indexed")
        if len(indices) > len(ty.dims):
            raise ValueError(f"{path} has {len(ty.dims)} dimension(s), not {len(indices)}")
        for index, (lo, hi) in zip(indices, ty.dims):
            if not lo <= index <= hi:
                raise ValueError(f"index {index} of {path} is outside {lo}..{hi}")
            keys = (*keys, index - lo)
        rest = ty.dims[len(indices) :]
        return f"{path}[{', '.join(map(str, indices))}]", (t.Array(ty.element, rest) if rest else ty.element), keys


def located_location(path: str, ty: t.IrType, address: Address) -> Location:
    """A located variable or an address: read from and written to the program's image; a write to an input also
    sets the inputs the next scans read (engine/process_image.py)."""
    kind = view_kind(address, runtime_name(ty))
    read, write = (image_view_name(ProcessImage.path_buffer(address.area, w), kind) for w in (False, True))
    return Location(path, ty, ("global", read), (key_of(address),), write_root=("global", write))


def _visible(layout) -> list[str]:
    return [p.slot.name for p in layout.places.values() if not p.slot.hidden]


def _a(ty: t.IrType) -> str:
    return values.article(describe(ty))


def coerce_for(location: Location, value: object) -> object:
    """A user value (Python or IEC literal text) for an elementary location; ValueError naming the path."""
    ty = location.type
    if location.read_only:
        raise ValueError(f"{location.path} is reached through a READ_ONLY access path: it cannot be written")
    if location.refusal:
        raise ValueError(f"{location.path} cannot be written: {location.refusal}")
    if not location.elementary:
        raise ValueError(f"{location.path} is {_a(ty)}: write its elements one by one")
    if isinstance(ty, t.Reference):
        raise ValueError(f"{location.path} is {_a(ty)}: a reference is set by the program (REF(...)), not online")
    try:
        if isinstance(ty, t.Enum):
            return _enum_value(ty, value)
        coerced = values.coerce(value, runtime_name(ty))  # type: ignore[arg-type]
        if isinstance(ty, t.Subrange) and not ty.low <= coerced <= ty.high:  # type: ignore[operator]
            raise ValueError(f"{coerced} is outside the subrange {ty.low}..{ty.high}")
        textless = textless_character(coerced) if isinstance(coerced, str) else None
        if textless is not None:  # as in a literal (iec/literals.py)
            raise ValueError(textless_message(textless))
        return coerced
    except ValueError as error:
        raise ValueError(f"{location.path}: {error}") from None


def _enum_value(ty: t.Enum, value: object) -> int:
    if isinstance(value, str):
        text = value.strip().upper()
        if "#" in text:
            prefix, text = text.split("#", 1)
            if prefix != ty.name.upper():
                raise ValueError(f"{value!r} is not a value of {ty.name}")
        for name, number in ty.values:
            if name.upper() == text:
                return number
    elif isinstance(value, int) and not isinstance(value, bool) and value in {n for _, n in ty.values}:
        return value
    raise ValueError(f"{value!r} is not a value of {ty.name} ({', '.join(n for n, _ in ty.values)})")


def leaves(context: ModuleContext, roots: Roots) -> Iterator[tuple[str, object]]:
    """Every elementary variable (hidden slots and VAR_IN_OUT references left out) with its value: the attached
    instances', the program instances', then the other globals'."""
    for name, (obj, pou) in roots.attached.items():
        yield from _instance_leaves(context, name, context.layouts[pou], obj, roots)
    for place in context.globals.places.values():
        if not place.slot.hidden:
            obj = roots.ns[global_owner(place.page)]
            yield from _value_leaves(context, place.slot.name, place.slot.type, getattr(obj, place.attr), roots)
    yield from _located_leaves("", context.globals, roots)


def _located_leaves(prefix: str, layout, roots: Roots) -> Iterator[tuple[str, object]]:
    for slot in layout.located.values():
        location = located_location(f"{prefix}{slot.name}", slot.type, located_address(slot.address))
        yield location.path, location.get(roots)


def _instance_leaves(context, path, layout, obj, roots: Roots | None = None) -> Iterator[tuple[str, object]]:
    for place in layout.places.values():
        if place.slot.hidden or place.slot.var_class == "VAR_IN_OUT":
            continue
        owner = obj if place.page == 0 else getattr(obj, f"ll_p{place.page}")
        yield from _value_leaves(
            context, f"{path}.{place.slot.name}", place.slot.type, getattr(owner, place.attr), roots
        )
    if roots is not None:
        yield from _located_leaves(f"{path}.", layout, roots)


def _value_leaves(context, path, ty, value, roots: Roots | None = None) -> Iterator[tuple[str, object]]:
    if isinstance(ty, t.Array):
        yield from _array_leaves(context, path, ty, value, [], roots)
    elif isinstance(ty, t.Struct):
        for f in ty.fields:
            yield from _value_leaves(context, f"{path}.{f.name}", f.type, getattr(value, names.slot(f.name)), roots)
    elif isinstance(ty, t.Reference):
        yield path, reference_text(value)
    elif isinstance(ty, t.FbInstance):
        user = context.user_fb(ty.fb)
        if user is not None:
            yield from _instance_leaves(context, path, context.layouts[user.name.upper()], value, roots)
        else:
            cls = std_fb_class(ty.fb)
            for pin in (*cls.INPUTS, *cls.OUTPUTS, *cls.MEMORY):  # type: ignore[union-attr]
                yield f"{path}.{pin}", getattr(value, pin)
    else:
        yield path, value


def _array_leaves(context, path, ty: t.Array, value, prefix: list[int], roots=None) -> Iterator[tuple[str, object]]:
    depth = len(prefix)
    lo, _hi = ty.dims[depth]
    for offset, item in enumerate(value):
        indices = [*prefix, lo + offset]
        if depth + 1 < len(ty.dims):
            yield from _array_leaves(context, path, ty, item, indices, roots)
        else:
            yield from _value_leaves(context, f"{path}[{', '.join(map(str, indices))}]", ty.element, item, roots)


def plain(context: ModuleContext, ty: t.IrType, value: object, *, enum_literals: bool = False) -> object:
    """A value as plain data: arrays as (nested) lists, structures and FB instances as dicts, references as text;
    with ``enum_literals`` an enumeration's value as its literal (``TCOLOR#Red``, what the CLI prints), else its
    number."""
    if isinstance(ty, t.Reference):
        return reference_text(value)
    if isinstance(ty, t.Enum):
        return ty.literal(value) if enum_literals else value
    if isinstance(ty, t.Array):
        inner = t.Array(ty.element, ty.dims[1:]) if len(ty.dims) > 1 else ty.element
        return [plain(context, inner, item, enum_literals=enum_literals) for item in value]  # type: ignore[attr-defined]
    if isinstance(ty, t.Struct):
        return {
            f.name: plain(context, f.type, getattr(value, names.slot(f.name)), enum_literals=enum_literals)
            for f in ty.fields
        }
    if isinstance(ty, t.FbInstance):
        user = context.user_fb(ty.fb)
        if user is None:
            cls = std_fb_class(ty.fb)
            return {pin: getattr(value, pin) for pin in (*cls.INPUTS, *cls.OUTPUTS, *cls.MEMORY)}  # type: ignore[union-attr]
        layout = context.layouts[user.name.upper()]
        result = {}
        for place in layout.places.values():
            if place.slot.hidden or place.slot.var_class == "VAR_IN_OUT":
                continue
            owner = value if place.page == 0 else getattr(value, f"ll_p{place.page}")
            result[place.slot.name] = plain(
                context, place.slot.type, getattr(owner, place.attr), enum_literals=enum_literals
            )
        return result
    return value


class LocationReader:
    """Reads many locations fast: each distinct container (a program instance, an array, a structure)
    is reached once per read, then its members are indexed. Locations walk from the roots on every
    read, so they stay valid across resets; so does this."""

    def __init__(self, locations: dict[str, Location], roots: Roots, ctx: ModuleContext) -> None:
        self.roots, self.ctx = roots, ctx
        groups: dict[tuple, list[tuple[str, object, t.IrType | None]]] = {}  # members: (path, key, composite type)
        self.single: list[tuple[str, Location]] = []  # ends in a VAR_IN_OUT reference: read on its own
        #: the paths of 'call' properties whose GET faulted at the last read -> the fault
        self.faults: dict[str, object] = {}
        for path, location in locations.items():
            last = location.keys[-1]
            if isinstance(last, (str, int)):
                plain_type = (
                    None if location.elementary and not isinstance(location.type, t.Reference) else location.type
                )
                groups.setdefault((location.root, location.keys[:-1]), []).append((path, last, plain_type))
            else:
                self.single.append((path, location))
        self.groups = [
            (root, Location("", t.Elementary("BOOL"), root, parent) if parent else None, members)
            for (root, parent), members in groups.items()
        ]

    def read(self) -> dict[str, object]:
        values: dict[str, object] = {}
        for root, parent, members in self.groups:
            try:
                container = parent.get(self.roots) if parent is not None else self.roots.get(root)
            except Exception:
                values.update((path, None) for path, _, _ in members)
                continue
            for path, key, composite in members:
                value = container[key]  # type: ignore[index]
                values[path] = value if composite is None else plain(self.ctx, composite, value)
        self.faults = {}
        for path, location in self.single:
            try:
                value = location.get(self.roots)
                values[path] = plain(self.ctx, location.type, value)
            except AccessorFault as error:
                values[path], self.faults[path] = None, error.fault
            except Exception:
                values[path] = None
        return values
