"""Source that builds a fresh value of a type with its initial value (TYP-05, TYP-25, TYP-33).

Initial values follow docs/ir.md ("Initial values"): an engine value for
elementary, subrange and enumeration types; for an ARRAY one tuple level per
dimension (``((a, b, c), (d, e, f))`` for ``[1..2, 1..3]``); for a STRUCT a
tuple of its field values in field order; for an FB instance a tuple of
``(PIN, value)`` overrides. ``None`` anywhere means the type's own initial
value (the default). Shorter sequences leave the rest at the default.
"""

from __future__ import annotations

import math
from functools import lru_cache

from ...ir import nodes as ir
from ...ir import types as t
from ...ir.lower_types import merged_initial
from ...ir.types import describe
from . import names
from .context import CodegenError, ModuleContext, std_fb_class, std_pin_type
from .expressions import literal
from .typeinfo import scalar_default, store_value


def construct(ty: t.IrType, initial: object, module: ModuleContext) -> str:
    if isinstance(ty, t.Array):
        return _array(ty, initial, module)
    if isinstance(ty, t.Struct):
        values = _sequence(initial, ty.name, len(ty.fields))
        overrides = {
            names.slot(f.name): construct(f.type, merged_initial(f.type, f.initial, value), module)
            for f, value in zip(ty.fields, values)
            if value is not None and value != f.initial
        }
        return _with(f"{module.struct_class(ty)}()", overrides)
    if isinstance(ty, t.FbInstance):
        return _instance(ty, initial, module)
    if isinstance(ty, t.Reference):  # NULL; a REF(x) initial is set after every slot (pou.emit_reference_inits)
        if initial is not None and not isinstance(initial, ir.ReferenceInit):
            raise CodegenError("a reference starts as NULL or as REF(...) of a variable")
        return "None"
    if not isinstance(ty, (t.Elementary, t.Subrange, t.Enum)):
        raise CodegenError(f"unknown type {ty!r}")
    try:
        # floats are not cached: -0.0 == 0.0 would share one entry
        scalar = _scalar if type(initial) in _CACHED else _scalar.__wrapped__
        return scalar(ty, type(initial), initial)
    except (ValueError, KeyError) as error:
        raise CodegenError(f"initial value: {error}") from None


_CACHED = (type(None), bool, int, str)


@lru_cache(maxsize=4096)  # bounded: a long-running server compiles many projects
def _scalar(ty: t.Elementary | t.Subrange | t.Enum, kind: type, initial: object) -> str:
    """The literal of a scalar's initial value, once per distinct (type, value): a program of 10,000
    networks has 40,000 slots with a handful of initial values. ``kind`` keeps True and 1 apart."""
    return literal(scalar_default(ty) if initial is None else store_value(initial, ty))


def _sequence(initial: object, owner: str, most: int) -> list:
    if initial is None:
        return []
    if not isinstance(initial, (tuple, list)) or len(initial) > most:
        raise CodegenError(f"{initial!r} is not an initial value for {owner} ({most} values at most)")
    return list(initial)


def _with(ctor: str, overrides: dict[str, str]) -> str:
    if not overrides:
        return ctor
    return f"ll_with({ctor}, {', '.join(f'{k}={v}' for k, v in overrides.items())})"


def _instance(ty: t.FbInstance, initial: object, module: ModuleContext) -> str:
    pairs = _sequence(initial, ty.fb, 1 << 16)
    if not all(isinstance(p, (tuple, list)) and len(p) == 2 and isinstance(p[0], str) for p in pairs):
        raise CodegenError(f"the initial value of an instance of {ty.fb} must be (PIN, value) pairs, not {initial!r}")
    user = module.user_fb(ty.fb)
    overrides = {}
    if user is not None:
        layout = module.layouts[user.name.upper()]
        for name, value in pairs:
            place = layout.get(name)
            if place is None or place.page:
                raise CodegenError(f"{user.name} has no variable {name} that can be initialised here")
            value = merged_initial(place.slot.type, place.slot.initial, value)
            overrides[place.attr] = construct(place.slot.type, value, module)
        return _with(f"{names.pou_class(user.name)}()", overrides)
    if std_fb_class(ty.fb) is None:
        raise CodegenError(f"unknown function block {ty.fb}")
    for name, value in pairs:
        pin_type = std_pin_type(ty.fb, name)
        if pin_type is None:
            raise CodegenError(f"{ty.fb} has no pin {name}")
        overrides[name.upper()] = construct(pin_type, value, module)
    return _with(f"{names.std_fb(ty.fb)}()", overrides)


def _array(ty: t.Array, initial: object, module: ModuleContext) -> str:
    sizes = [hi - lo + 1 for lo, hi in ty.dims]
    if any(size < 1 for size in sizes):
        raise CodegenError(f"empty array bounds in {describe(ty)}")
    default = construct(ty.element, None, module)
    ctors = _flatten(initial, sizes, ty, module, default)
    composite = isinstance(ty.element, (t.Array, t.Struct, t.FbInstance))
    return _nested(sizes, ctors, composite)


def _flatten(initial: object, sizes: list[int], ty: t.Array, module: ModuleContext, default: str) -> list[str]:
    """Element constructors in row-major order from one sequence level per dimension."""
    items = _sequence(initial, describe(ty), sizes[0])
    if len(sizes) == 1:
        ctors = [construct(ty.element, item, module) if item is not None else default for item in items]
        return ctors + [default] * (sizes[0] - len(ctors))
    inner = math.prod(sizes[1:])
    ctors = []
    for i in range(sizes[0]):
        ctors += _flatten(items[i], sizes[1:], ty, module, default) if i < len(items) else [default] * inner
    return ctors


def _nested(sizes: list[int], ctors: list[str], composite: bool) -> str:
    if len(sizes) == 1:
        return _row(ctors, composite)
    inner = math.prod(sizes[1:])
    parts = [_nested(sizes[1:], ctors[i * inner : (i + 1) * inner], composite) for i in range(sizes[0])]
    if all(p == parts[0] for p in parts):
        return f"[{parts[0]} for _ in range({sizes[0]})]"
    return "[" + ", ".join(parts) + "]"


def _row(ctors: list[str], composite: bool) -> str:
    """One dimension: runs of equal scalars as ``[x] * n``; composites are built one by one."""
    if composite:
        if all(c == ctors[0] for c in ctors):
            return f"[{ctors[0]} for _ in range({len(ctors)})]"
        return "[" + ", ".join(ctors) + "]"
    runs: list[tuple[str, int]] = []
    for c in ctors:
        if runs and runs[-1][0] == c:
            runs[-1] = (c, runs[-1][1] + 1)
        else:
            runs.append((c, 1))
    parts: list[str] = []
    loose: list[str] = []
    for value, count in runs:
        if count >= 4:
            if loose:
                parts.append("[" + ", ".join(loose) + "]")
                loose = []
            parts.append(f"[{value}] * {count}")
        else:
            loose += [value] * count
    if loose:
        parts.append("[" + ", ".join(loose) + "]")
    return " + ".join(parts)
