"""Constant inputs stored once (issue 27): a standard FB's input that every call gives the same constant.

A PROGRAM calling ``T1(IN := x, PT := T#5s)`` stores PT on every call, though between calls the pin holds T#5s
anyway. Where nothing but those calls can write or read the pin, the pin is set when the instance is made, at every
initialisation (``ll_pins(self, 'v_T1 v_T2', 'PT', 5000)`` in ``ll_init``, pou.py), and the inlined calls of the
fast and monitor variants leave the store out (the inlined body reads the constant itself). The debug variant,
which calls ``execute``, still stores it. What an online write, force or injected fault changes, IEC's next call
would store over: ``StoredOnce`` (engine/stored_once.py) puts the constants back before the next scan that runs the
program. Before the first call the pin shows the constant instead of the type's initial value.

A pin qualifies when its instance is a VAR of a PROGRAM without jumps or RETURN, not called from any POU, whose
every call of the instance is a statement of a network (or ST body) itself, not nested in a condition or loop,
without EN, assigning the pin the same constant of the pin's type; and no code anywhere (any POU, an access path)
mentions the instance other than through those calls and its outputs' reads: a read or write of ``T1.PT`` or
``MAIN.T1.PT``, ``T1`` passed whole or its address taken. Names are compared across POUs, so a pin of another
POU's instance of the same name disqualifies it too (conservative, never wrong).
"""

from __future__ import annotations

import itertools

from ...ir import nodes as ir
from ...ir import types as t
from .context import ModuleContext, std_fb_class, std_pin_type
from .mentions import Walk
from .typeinfo import store_value

#: POU (upper case) -> instance slot (upper case) -> ((PIN, constant value), ...)
ConstantPins = dict[str, dict[str, tuple[tuple[str, object], ...]]]


def constant_inputs(module: ModuleContext) -> ConstantPins:
    """The pins stored once, by POU and instance (empty for a unit test program, whose instances may be mocked)."""
    program = module.program
    if program.mockable:
        return {}
    called = {  # PROGRAMs some POU calls as an FB (not only their task): they may run twice in a scan
        s.instance.type.fb.upper()
        for pou in module.pous.values()
        for s in module.mentions(pou).fb_calls
        if isinstance(s.instance.type, t.FbInstance)
    }
    candidates = {
        name: _program_pins(module, pou)
        for name, pou in module.pous.items()
        if pou.kind == "program" and name not in called
    }
    found: ConstantPins = {}
    if not any(candidates.values()):
        return found
    pairs, wholes = _mentioned(module)
    for name, instances in candidates.items():
        kept = {
            slot: held
            for slot, pins in instances.items()
            if slot not in wholes and (held := tuple(p for p in pins if (slot, p[0]) not in pairs))
        }
        if kept:
            found[name] = kept
    return found


def _program_pins(module: ModuleContext, pou: ir.Pou) -> dict[str, tuple[tuple[str, object], ...]]:
    """The candidate pins of one PROGRAM: every call of the instance a top-level statement, the same constant."""
    found = module.mentions(pou)
    if found.jumps or found.returns or not found.fb_calls:
        return {}
    places, nested = module.layouts[pou.name.upper()].places, found.nested_fb_calls
    pins: dict[str, dict[str, ir.Const] | None] = {}
    for s in found.fb_calls:
        var = s.instance
        place = places.get(var.name.upper()) if var.scope == "local" and not var.path else None
        if place is None or place.slot.var_class != "VAR" or type(place.slot.type) is not t.FbInstance:
            continue
        slot, fb = var.name.upper(), place.slot.type.fb
        if id(s) in nested or s.en is not None or s.body is not None or std_fb_class(fb) is None:
            pins[slot] = None
            continue
        constants = {}
        for pin, value in s.inputs:
            if type(value) is ir.Const and type(value.value) in _SCALARS:
                pin = pin.upper()
                wanted = std_pin_type(fb, pin)
                if value.type is wanted or value.type == wanted:
                    constants[pin] = value
        before = pins.get(slot)
        if before is not None:
            constants = {p: c for p, c in constants.items() if p in before and before[p] == c}
        pins[slot] = None if slot in pins and before is None else constants
    stored: _Converted = {}
    return {
        slot: tuple(sorted(_stored(stored, pin, c) for pin, c in kept.items())) for slot, kept in pins.items() if kept
    }


#: (pin, value, its Python type, IR type) -> (pin, the value as the pin stores it)
_Converted = dict[tuple[str, object, type, object], tuple[str, object]]


def _stored(stored: _Converted, pin: str, c: ir.Const) -> tuple[str, object]:
    """(pin, the constant as the pin stores it), converted once per distinct constant (10,000 timers: one T#100ms)."""
    key = (pin, c.value, type(c.value), c.type)
    found = stored.get(key)
    if found is None:
        found = stored[key] = (pin, store_value(c.value, c.type))
    return found


_SCALARS = (bool, int, float)


def _mentioned(module: ModuleContext) -> tuple[set[tuple[str, str]], set[str]]:
    """(NAME, MEMBER) pairs some code or access path names (``T1.PT``), and the instance names it names whole."""
    pairs: set[tuple[str, str]] = set()
    wholes: set[str] = set()
    for pou in module.pous.values():
        found = module.mentions(pou)
        for var in found.paths:
            _add(var, pairs, wholes)
        wholes |= found.whole_fbs
        for s in found.fb_calls:
            if s.instance.path:  # an instance called through a path: another program's, an array's element
                _add(s.instance, pairs, wholes)
    for instance in module.instances:  # VAR_CONFIG initial values (``MAIN.T1.PT``)
        for var, _, _ in instance.init:
            _add(var, pairs, wholes)
    for path, _ in module.program.access.values():
        parts = path.upper().replace("[", ".").split(".")
        pairs.update(itertools.pairwise(parts))
        wholes.add(parts[-1])
    for task in module.tasks:
        walked = Walk()
        walked.statements(task.body or [])
        for var in [*walked.paths, *(s.instance for s in walked.fb_calls if s.instance.path)]:
            _add(var, pairs, wholes)
        wholes |= walked.whole_fbs
    return pairs, wholes


def _add(var: ir.Var, pairs: set[tuple[str, str]], wholes: set[str]) -> None:
    name = var.name.upper()
    for selector in var.path:
        if type(selector) is ir.Member:
            member = selector.name.upper()
            pairs.add((name, member))
            name = member
    if type(var.type) is t.FbInstance:
        wholes.add(name)
