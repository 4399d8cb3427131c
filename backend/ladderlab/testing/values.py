"""Values as a PLC programmer reads them in a test report: IEC literals of their type."""

from __future__ import annotations

from ..iec.literals import encode_string
from ..iec.value_text import format_value
from ..ir import types as t


def literal(value: object, ty: t.IrType) -> str:
    """``5``, ``2.5``, ``TRUE``, ``T#1s500ms``, ``'text'``, ``TCOLOR#Red`` (an enumeration's value as declared): the
    value as IEC text."""
    if isinstance(ty, t.Enum):
        return ty.literal(value)
    if isinstance(ty, t.Subrange):
        ty = ty.base
    if isinstance(ty, t.Elementary):
        if ty.name in ("STRING", "WSTRING"):
            return encode_string(str(value), ty.name == "WSTRING")
        try:
            return format_value(value, ty.name)
        except (KeyError, ValueError, TypeError):
            return repr(value)
    return repr(value)
