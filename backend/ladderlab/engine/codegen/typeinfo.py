"""What the code generator needs to know about IR types: runtime type names, defaults, stores.

Every expression the generator emits yields a value already stored in its own
type (the runtime templates wrap, round to float32 and cut strings), so a
store only needs work when the target type differs from the value's type, or
when the target is a subrange (checked on every store).
"""

from __future__ import annotations

from ...iec import values
from ...ir import types as t

COMPOSITE = (t.Array, t.Struct, t.FbInstance)


def runtime_name(ty: t.IrType) -> str | None:
    """The runtime library's name for an elementary-valued type (``INT``, ``STRING[20]``); None for composites.

    Subranges compute in their base type and enumerations are ints (DINT is wide enough).
    """
    if isinstance(ty, t.Elementary):
        if ty.name == "STRING" and ty.length is not None:
            return f"STRING[{ty.length}]"
        return ty.name
    if isinstance(ty, t.Subrange):
        return runtime_name(ty.base)
    if isinstance(ty, t.Enum):
        return "DINT"
    return None


def is_composite(ty: t.IrType) -> bool:
    return isinstance(ty, COMPOSITE)


def scalar_default(ty: t.IrType) -> object:
    """Default of a non-composite type (TYP-05): the type default, an enum's first value, a subrange's low bound."""
    if isinstance(ty, t.Enum):
        return ty.values[0][1] if ty.values else 0
    if isinstance(ty, t.Subrange):
        default = values.default_value(ty.base.name)
        return default if ty.low <= default <= ty.high else ty.low
    return values.default_value(runtime_name(ty))  # type: ignore[arg-type]


def store_value(value: object, ty: t.IrType) -> object:
    """A constant stored into ``ty`` at compile time (wrap, float32, cut); ValueError when it cannot be."""
    if isinstance(ty, t.Enum):
        if isinstance(value, str):
            for name, number in ty.values:
                if name.upper() == value.upper():
                    return number
            raise ValueError(f"{value!r} is not a value of {ty.name}")
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"{value!r} is not a value of {ty.name}")
        return value
    name = runtime_name(ty)
    category = values.resolve(name).category
    if category == "bool":
        if value in (0, 1) and isinstance(value, int):  # True, False, 1, 0
            return bool(value)
        raise ValueError(f"{value!r} is not a BOOL")
    expected = {"string": str, "real": (int, float)}.get(category, int)
    if not isinstance(value, expected) or isinstance(value, bool):
        raise ValueError(f"{value!r} is not {values.article(name)}")
    stored = values.store_fn(name)(float(value) if category == "real" else value)  # type: ignore[arg-type]
    if isinstance(ty, t.Subrange) and not ty.low <= stored <= ty.high:
        raise ValueError(f"{value} is outside the subrange {ty.low}..{ty.high}")
    return stored


def same_storage(a: t.IrType, b: t.IrType) -> bool:
    """A value of type ``a`` needs no conversion to be stored in ``b`` (subrange checks aside)."""
    if a is b or a == b:
        return True
    ra, rb = runtime_name(a), runtime_name(b)
    return ra is not None and ra == rb


def store_code(code: str, source: t.IrType, target: t.IrType, *, checked: bool = False) -> str:
    """Source storing the value ``code`` (of type ``source``) into ``target``.

    A subrange target is range-checked unless ``checked`` says the value was
    already stored in that very subrange (a variable or pin of the type):
    arithmetic typed as a subrange computes in the base type and may leave it.
    """
    if (source is target or source == target) and (checked or not isinstance(target, t.Subrange)):
        return code  # the common case, first
    if isinstance(target, t.Reference):
        return code  # a reference is stored as it is (lowering checked its target type)
    if isinstance(target, t.Subrange):
        if checked and source == target:
            return code
        inner = code if same_storage(source, target.base) else values.store_expr(code, runtime_name(target))  # type: ignore[arg-type]
        return f"ll_sub({inner}, {target.low!r}, {target.high!r})"
    if same_storage(source, target) or is_composite(target) or isinstance(target, t.Enum):
        return code
    return values.store_expr(code, runtime_name(target))  # type: ignore[arg-type]


def store_whole(code: str, source: t.IrType, target: t.IrType) -> str:
    """Source of the array value ``code`` (of type ``source``) assigned whole into ``target``: each element checked
    (``ll_in_range``) when ``target``'s elements are a subrange that ``source``'s are not (``ARRAY OF INT`` into
    ``ARRAY OF INT (0..100)``); structures and other arrays as they are."""
    element, given = target, source
    while isinstance(element, t.Array) and isinstance(given, t.Array):
        element, given = element.element, given.element
    if isinstance(element, t.Subrange) and given != element:
        return f"ll_in_range({code}, {element.low!r}, {element.high!r})"
    return code
