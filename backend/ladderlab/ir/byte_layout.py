"""How a CODESYS PLC (x86/ARM: little-endian) lays a variable out in bytes, for pointers that see memory as another
type (``POINTER TO BYTE`` over a STRING, ``POINTER TO DWORD`` over a REAL). The engine reads and writes those bytes
from the value (engine/codegen/views.py); the specs here are what it is given.

A spec is ``("int", size, signed)`` for the integers and bit strings, ``("real", size)``, ``("bool",)`` (one byte),
``("string", n)`` (STRING[n]: n + 1 bytes, a NUL after the text, one Latin-1 byte a character), ``("wstring", n)``
(WSTRING[n]: 2 * (n + 1) bytes, a UCS-2 WORD a character, little-endian, a NUL WORD after the text), ``("range", low,
high, base spec)`` (a subrange: its base's bytes, which must decode to low..high), ``("enum", name, values, base spec)``
(an enumeration: its base's bytes, as CODESYS stores it, which must decode to one of its members' values), ``("array",
count, element spec)`` (the elements one after another; a multi-dimensional array is an array of arrays, the first
dimension outermost) or ``("struct", name, size, pack_mode, ((member, offset, spec), ...))`` (a STRUCT: its members in
declaration order at CODESYS's alignment, padding bytes between and after them; pack_mode as declared, None without
one).

CODESYS aligns each member of a STRUCT to its natural alignment (a number's size) capped by the STRUCT's pack_mode
(https://content.helpme-codesys.com/en/CODESYS%20Development%20System/_cds_pragma_attribute_pack_mode.html). A
STRUCT without the attribute has the target's default pack mode, 4 on some targets and 8 on others: it matters only
to 8-byte members, so such a layout is worked out both ways and kept only when both agree. CODESYS documents no
alignment for a WSTRING member (an array of WORDs: 2, or 1 as a STRING's): a STRUCT holding one is laid out both
ways too, and kept only when both agree (each WSTRING at an even byte, an even size, or a pack_mode of 1).
"""

from __future__ import annotations

from ..iec.values import article
from .types import Array, Elementary, Enum, IrType, Reference, Struct, Subrange, describe

Spec = tuple

#: SIZEOF of a pointer (POINTER TO, REF_TO): an address of a 32-bit target; a 64-bit CODESYS target has 8.
POINTER_BYTES = 4


def byte_layout(ty: IrType, addresses: bool = False) -> Spec | str:
    """The spec of ``ty``, or why LadderLab cannot lay it out exactly as CODESYS does. With ``addresses`` (for
    SIZEOF only: nothing reads these bytes) a pointer member is ``("address", POINTER_BYTES)``: a linked list's
    ``next`` counts as the 32-bit target's address, as SIZEOF of a pointer does."""
    narrow, wide = _layout(ty, 4, addresses=addresses), _layout(ty, 8, addresses=addresses)
    if isinstance(narrow, str) or isinstance(wide, str):
        return narrow
    if narrow != wide:
        name, what = _moved(narrow, wide)
        return (
            f"the STRUCT {name}, {what} depending on the target (without a pack_mode CODESYS aligns 8-byte members "
            f"to 4 or 8 bytes by target): give {name} the target's pack_mode ({{attribute 'pack_mode' := '4'}} or '8' "
            "above its TYPE), or order its members so that each 8-byte one lies at a multiple of 8 and so does the size"
        )
    if _layout(ty, 4, wstring_align=2, addresses=addresses) != narrow:
        inner = _innermost(ty)
        name = inner.name if isinstance(inner, Struct) else describe(ty)
        return (
            f"the STRUCT {name}, which holds a WSTRING at an odd byte or has an odd size (CODESYS documents no "
            "alignment for a WSTRING member: 1 or 2 bytes): place each WSTRING at an even byte and make each STRUCT's "
            "size even (a BYTE of padding), or give the STRUCT {attribute 'pack_mode' := '1'}"
        )
    return narrow


def _layout(ty: IrType, default: int, wstring_align: int = 1, addresses: bool = False) -> Spec | str:
    """The spec of ``ty`` on a target whose STRUCTs without a pack_mode have the pack mode ``default`` and whose
    WSTRING members are aligned to ``wstring_align`` bytes."""
    if isinstance(ty, Subrange):
        base = _layout(ty.base, default)
        return ("range", ty.low, ty.high, base) if isinstance(base, tuple) else base
    if isinstance(ty, Elementary):
        info = ty.info
        if info.category in ("int", "bits"):
            return ("int", info.bits // 8, info.signed) if info.bits > 1 else ("bool",)
        if info.category == "bool":
            return ("bool",)
        if info.category == "real":
            return ("real", info.bits // 8)
        if ty.name == "STRING":
            return ("wstring" if ty.wide else "string", ty.max_length)
        return f"{article(describe(ty))} (its bytes in CODESYS are not the value LadderLab keeps)"
    if isinstance(ty, Array):
        spec = _layout(ty.element, default, wstring_align, addresses)
        if isinstance(spec, str):
            return spec
        for lo, hi in reversed(ty.dims):
            spec = ("array", hi - lo + 1, spec)
        return spec
    if isinstance(ty, Struct):
        return _struct_layout(ty, default, wstring_align, addresses)
    if isinstance(ty, Enum):
        values = tuple(sorted({value for _, value in ty.values}))
        return ("enum", ty.name, values, _layout(Elementary(ty.base), default))
    if isinstance(ty, Reference):
        if addresses:
            return ("address", POINTER_BYTES)
        return f"{article(describe(ty))} (an address: 4 or 8 bytes depending on the target)"
    return f"{article(describe(ty))} (it has no byte layout)"


def same_target(referred: IrType, target: IrType) -> bool:
    """A reference to ``target`` reaches a variable of ``referred`` directly: one type. A subrange (an enumeration)
    and its base differ: a write through a base-typed pointer must not leave the subrange (give a value that is none
    of the enumeration's), a read through a subrange-typed (enumeration-typed) one must not return one, so those go
    through a view; so does a STRING of another length (a ``POINTER TO STRING`` over a STRING[4]), whose view knows
    where the variable ends."""
    if referred == target:
        return True
    if not isinstance(referred, Elementary) or not isinstance(target, Elementary) or referred.name != target.name:
        return False
    return referred.name != "STRING" or (referred.wide, referred.max_length) == (target.wide, target.max_length)


def view_specs(referred: IrType, target: IrType) -> tuple[Spec, Spec] | str:
    """``(whole, seen)``: the byte layouts through which a ``REF_TO target`` sees a variable of ``referred``, or why
    it cannot (the message of the refusal)."""
    whole, seen = byte_layout(referred), byte_layout(target)
    if isinstance(whole, tuple) and isinstance(seen, tuple):
        return whole, seen
    problem = whole if isinstance(whole, str) else seen
    return f"a REF_TO {describe(target)} cannot see {article(describe(referred))} as bytes: {problem}"


def in_out_view(argument: IrType, parameter: IrType) -> tuple[Spec, Spec] | str | None:
    """How a VAR_IN_OUT of type ``parameter`` reaches the variable ``argument`` passed to it: directly (None); through
    a view (its specs) when the two are one integer type but for a subrange (``INT`` and ``INT (0..100)``), which
    keeps the variable in its range; or not at all (why): an array whose elements differ so (or by an enumeration),
    which the callee would reach element by element unchecked."""
    if argument == parameter:
        return None
    if isinstance(argument, Elementary | Subrange) and isinstance(parameter, Elementary | Subrange):
        whole, seen = byte_layout(argument), byte_layout(parameter)
        same_base = _base(argument) == _base(parameter)
        return (whole, seen) if same_base and isinstance(whole, tuple) and isinstance(seen, tuple) else None
    elements = _innermost(argument), _innermost(parameter)
    checked = [element for element in elements if isinstance(element, Subrange | Enum)]
    if elements[0] != elements[1] and checked:
        what = "subrange" if isinstance(checked[0], Subrange) else "enumeration"
        return (
            f"{article(describe(argument))} cannot be passed to a VAR_IN_OUT {describe(parameter)}: the {what} of "
            "its elements would go unchecked (pass an array of the parameter's element type)"
        )
    return None


def has_checked_values(ty: IrType) -> bool:
    """``ty`` is a subrange or an enumeration, or an array of them: not every value of its base is one of its own."""
    return isinstance(_innermost(ty), Subrange | Enum)


def _innermost(ty: IrType) -> IrType:
    """An array's element type, through every dimension; ``ty`` itself for anything else."""
    return _innermost(ty.element) if isinstance(ty, Array) else ty


def _base(ty: Elementary | Subrange) -> Elementary:
    return ty.base if isinstance(ty, Subrange) else ty


def _struct_layout(ty: Struct, default: int, wstring_align: int, addresses: bool) -> Spec | str:
    """Each member at the next multiple of its alignment (capped by the pack mode), the size a multiple of the
    largest one: CODESYS's layout, and C's."""
    members, end, largest = [], 0, 1
    pack = ty.pack_mode or default
    for field in ty.fields:
        spec = _layout(field.type, default, wstring_align, addresses)
        if isinstance(spec, str):
            return f"the STRUCT {ty.name}, whose member {field.name} is {spec}"
        align = min(_alignment(spec, default, wstring_align), pack)
        end += -end % align
        members.append((field.name, end, spec))
        end += _spec_size(spec)
        largest = max(largest, align)
    return ("struct", ty.name, end + -end % largest, ty.pack_mode, tuple(members))


def _alignment(spec: Spec, default: int, wstring_align: int) -> int:
    """The alignment of a member (a STRUCT member lies at a multiple of it): a number's size, 1 for BOOL and
    STRING, ``wstring_align`` for WSTRING, an array's element's, a STRUCT's largest member's capped by its pack
    mode."""
    kind = spec[0]
    if kind in ("int", "real", "address"):
        return spec[1]
    if kind in ("range", "enum"):
        return _alignment(spec[3], default, wstring_align)
    if kind == "array":
        return _alignment(spec[2], default, wstring_align)
    if kind == "struct":
        largest = max((_alignment(member, default, wstring_align) for _, _, member in spec[4]), default=1)
        return min(largest, spec[3] or default)
    return wstring_align if kind == "wstring" else 1


def _moved(narrow: Spec, wide: Spec) -> tuple[str, str]:
    """The STRUCT of a layout that differs between the default pack modes 4 and 8, and how: a member that moves
    (in a STRUCT with a pack_mode, only because the member is a STRUCT without one), or its size."""
    if narrow[0] == "array":
        return _moved(narrow[2], wide[2])
    for (name, at4, spec4), (_, at8, spec8) in zip(narrow[4], wide[4], strict=True):
        if at4 != at8 and narrow[3] is not None:
            while spec4[0] == "array":
                spec4 = spec4[2]
            return spec4[1], "aligned to 4 or 8 bytes"
        if at4 != at8:
            return narrow[1], f"whose member {name} lies at byte {at4} or {at8}"
        if spec4 != spec8:
            return _moved(spec4, spec8)
    return narrow[1], f"{narrow[2]} or {wide[2]} bytes"


def _spec_size(spec: Spec) -> int:
    """How many bytes a variable laid out as ``spec`` takes."""
    kind = spec[0]
    if kind in ("int", "real", "address"):
        return spec[1]
    if kind in ("string", "wstring"):
        return (spec[1] + 1) * (2 if kind == "wstring" else 1)
    if kind in ("range", "enum"):
        return _spec_size(spec[3])
    if kind == "array":
        return spec[1] * _spec_size(spec[2])
    return spec[2] if kind == "struct" else 1
