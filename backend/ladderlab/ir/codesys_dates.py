"""CODESYS typing: a DATE or a DT converted to or from a number counts seconds since 1970-01-01, as CODESYS stores
them (a DWORD; "Conversion: DATE, DT, TOD"), not the ms LadderLab holds them in (IEC typing keeps its ms count).

``DATE_TO_DWORD(d)`` becomes ``CODESYS_DATE_SECONDS(d)``, ``DATE_TO_INT(d)`` ``DWORD_TO_INT`` of it (CODESYS
converts its DWORD: DATE_TO_INT(D#1970-01-15) = 29952, 1209600 cut to 16 bits), ``UDINT_TO_DATE(n)``
``CODESYS_SECONDS_DATE(UDINT_TO_DWORD(n))`` (engine/stdlib/codesys_dates.py; a DATE that would not be a whole
day faults there). A REAL into a DATE or DT is refused: how CODESYS rounds it to seconds is not documented.
"""

from __future__ import annotations

from ..iec.elementary import ELEMENTARY
from ..st import types as st_types
from .lower_types import LoweringError
from .nodes import Call, Expr
from .types import Elementary

DWORD = Elementary("DWORD")
#: The short types CODESYS stores as seconds in a DWORD (the long ones, LDATE and LDT, count ns as LadderLab does).
_SECONDS_TYPES = frozenset({"DATE", "DATE_AND_TIME"})
_NUMBERS = frozenset({"int", "bits", "real"})


def in_seconds(call: Call) -> Call:
    """``call`` itself, or under CODESYS typing, when it converts a DATE or DT to a number or back, the same in
    CODESYS's seconds."""
    name = call.function.upper()
    if not st_types.codesys_typing() or len(call.args) != 1 or not ("_TO_" in name or name.startswith("TO_")):
        return call
    source, target = call.arg_types[0], call.type
    if not isinstance(source, Elementary) or not isinstance(target, Elementary):
        return call
    if source.name in _SECONDS_TYPES and ELEMENTARY[target.name].category in _NUMBERS:
        stored = Call("CODESYS_DATE_SECONDS", call.args, (source,), DWORD)
        return stored if target == DWORD else Call(f"DWORD_TO_{target.name}", (stored,), (DWORD,), target)
    if target.name in _SECONDS_TYPES and ELEMENTARY[source.name].category in _NUMBERS:
        if ELEMENTARY[source.name].category == "real":
            raise LoweringError(
                f"{name} under CODESYS typing: CODESYS stores a {target.name} as whole seconds, and how it rounds a "
                "REAL to them is not documented; convert the REAL to a DWORD first"
            )
        dword: Expr = call.args[0] if source == DWORD else Call(f"{source.name}_TO_DWORD", call.args, (source,), DWORD)
        return Call("CODESYS_SECONDS_DATE", (dword,), (DWORD,), target)
    return call
