"""What CODESYS's ``{attribute 'monitoring'}`` on a PROPERTY (st/monitoring.py) makes the engine run.

``'variable'``: an implicit variable of the function block (or program), named like the property (upper case, as
every slot is), that its GET stores the value it returns into before it returns and its SET stores the value written
into as it starts ("an implicit variable ... assigned the current property value when the application calls the Set
or Get method"); a path reads it, read only. ``'call'``: nothing is added; a path runs the GET between scans
(engine/paths.py).
"""

from __future__ import annotations

from ..st.monitoring import monitored_property, property_names
from ..st.symbols import CheckResult, PouInfo
from .context import PouContext
from .lower_types import LoweringError, TypeLowering
from .nodes import Assign, Member, MonitoredProperty, Slot, Stmt, Var

_HOLDERS = ("FUNCTION_BLOCK", "PROGRAM")


def monitored_slots(info: PouInfo, ctx: PouContext) -> list[Slot]:
    """The implicit variables of ``info``'s (and its bases') properties monitored as 'variable'."""
    if info.kind not in _HOLDERS:
        return []
    slots = []
    for name in property_names(info):
        found = monitored_property(info, name)
        if found is not None and found[1] == "variable":
            try:
                slots.append(Slot(found[0].name.upper(), "VAR", ctx.types.type_of(found[0].type)))
            except LoweringError:  # the type is reported where the property declares it
                continue
    return slots


def accessor_notes(info: PouInfo, ctx: PouContext) -> tuple[list[Stmt], list[Stmt]]:
    """The statements that store a 'variable' property's value in its implicit variable, for the accessor
    ``info``: (before its SET's body, before its GET returns)."""
    method = info.method
    if method is None or info.monitoring != "variable" or not method.key.endswith((".GET", ".SET")):
        return [], []
    this = ctx.this_var()
    if method.key.endswith(".GET"):
        result = ctx.result_var()
        implicit = Var("local", this.name, result.type, (Member(method.name.upper()),))
        return [], [Assign(implicit, result, ctx.origin(None))]
    value = ctx.var_for(info.symbols[method.name.upper()])
    implicit = Var("local", this.name, value.type, (Member(method.name.upper()),))
    return [Assign(implicit, value, ctx.origin(None))], []


def monitored_table(checked: CheckResult) -> dict[str, dict[str, MonitoredProperty]]:
    """For each function block and program: its monitored properties (its own and inherited) by upper-case name."""
    table: dict[str, dict[str, MonitoredProperty]] = {}
    for info in checked.pous.values():
        if info.kind not in _HOLDERS or info.method is not None:
            continue
        for name in property_names(info):
            found = monitored_property(info, name)
            if found is None:
                continue
            prop, mode = found
            getter = prop.getter.name.upper() if prop.getter is not None else None
            setter = prop.setter.name.upper() if prop.setter is not None else None
            try:
                ty = TypeLowering(checked, info).type_of(prop.type)
            except LoweringError:
                continue
            table.setdefault(info.name.upper(), {})[name] = MonitoredProperty(prop.name, mode, ty, getter, setter)
    return table
