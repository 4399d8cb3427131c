"""CODESYS's ``{attribute 'monitoring' := 'variable' | 'call'}``: which PROPERTYs show their value online.

From CODESYS's online help ("Attribute: monitoring", "Compiler Warning C0344"): the attribute stands in the
declaration of the property; with ``'variable'`` an implicit variable takes the property's value whenever the
program calls its Get or Set, and the last value stored is shown ("only read access is possible"); with ``'call'``
monitoring calls the Get itself (side effects possible; read and written by calling the property), only for a
property of a simple type or a pointer - on a structured one the attribute is ignored with a warning (C0344).

The model keeps no header line for a property: the attribute heads the declarations text of its GET (else of its
SET), as ``{attribute 'call_after_init'}`` heads a method's (st/call_after_init.py); IEC text writes it above
``PROPERTY`` (storage/st_text.py). ``check_monitoring`` sets ``PouInfo.monitoring`` on the accessors of each
property that has it and reports each misuse at its attribute; ir/monitoring.py builds what the engine runs.
"""

from __future__ import annotations

from ..model.diagnostics import Diagnostic, Severity
from ..model.project import Project, Property
from . import types as t
from .methods import method_file, property_of
from .pragmas import head_monitoring, monitoring_misplaced
from .symbols import CheckResult, PouInfo, PropertyRef

MODES = ("variable", "call")
#: What monitoring 'call' may call: a property of a simple data type or a pointer (CODESYS).
_SIMPLE = (t.Elementary, t.StringType, t.PointerType, t.EnumType)


def check_monitoring(result: CheckResult, project: Project) -> None:
    """Mark the accessors of each monitored property (once every method is declared) and report misuses."""
    for pou in project.pous:
        info = result.pous.get(pou.name.upper())
        if info is None or info.name != pou.name:
            continue
        for prop in pou.properties:
            _mark(result, info, prop)
        heads = [(pou.declarations, f"{pou.name}/declarations", pou.name)]
        heads += [
            (m.declarations, method_file(pou.name, m.name, "declarations"), f"{pou.name}.{m.name}") for m in pou.methods
        ]
        for text, file, label in heads:  # a function block's, program's or method's own: it shows no property
            found = head_monitoring(text)
            if found is not None:
                why = "on a method" if "." in label else f"on {label} itself"
                _placed(result, found[1], monitoring_misplaced(file, label, why))


def _mark(result: CheckResult, info: PouInfo, prop: Property) -> None:
    heads = [
        (kind, accessor.declarations, method_file(info.name, f"{prop.name}.{kind}", "declarations"))
        for kind, accessor in (("GET", prop.get), ("SET", prop.set))
        if accessor is not None
    ]
    found = [(head_monitoring(text), file) for _, text, file in heads]
    placed = [(mode_place, file) for mode_place, file in found if mode_place is not None]
    if not placed:
        return
    (mode, place), file = placed[0]
    label = f"{info.name}.{prop.name}"
    for (_, other_place), other_file in placed[1:]:
        _report(result, other_place, other_file, label, "error", f"{prop.name} has it twice (once is enough)")
    if mode not in MODES:
        _report(result, place, file, label, "error", f"'{mode}' is no mode of it: write 'variable' or 'call'")
        return
    accessors = {kind: info.methods.get(f"{prop.name}.{kind}".upper()) for kind, _, _ in heads}
    getter = accessors.get("GET")
    found_prop = property_of(info, prop.name)
    if mode == "call" and getter is None:
        _report(result, place, file, label, "warning", f"{prop.name} has no GET to call: the attribute is ignored")
        return
    if mode == "call" and found_prop is not None and not isinstance(found_prop.type, _SIMPLE):
        why = f"{prop.name} is of a structured type, and 'call' calls only a property of a simple type or a pointer"
        _report(result, place, file, label, "warning", f"{why} (CODESYS C0344): the attribute is ignored")
        return
    for accessor in accessors.values():
        if accessor is not None:
            accessor.monitoring = mode


def _report(
    result: CheckResult, place: tuple[int, int, int, int], file: str, pou: str, severity: Severity, why: str
) -> None:
    """ST-PRAGMA at the attribute on the property ``pou``, saying ``why``."""
    message = f"the attribute 'monitoring' on the property {pou}: {why}"
    _placed(result, place, Diagnostic(severity=severity, code="ST-PRAGMA", message=message, file=file, pou=pou))


def _placed(result: CheckResult, place: tuple[int, int, int, int], diagnostic: Diagnostic) -> None:
    line, column, end_line, end_column = place
    where = {"line": line, "column": column, "end_line": end_line, "end_column": end_column}
    result.diagnostics.append(diagnostic.model_copy(update=where))


def property_names(fb: PouInfo) -> dict[str, None]:
    """The upper-case names of the properties of ``fb`` (its own and inherited), in declaration order."""
    found: dict[str, None] = {}
    for pou in reversed(fb.lineage()):
        for key in pou.methods:
            if key.endswith((".GET", ".SET")):
                found.setdefault(key.rsplit(".", 1)[0], None)
    return found


def monitored_property(fb: PouInfo, name: str) -> tuple[PropertyRef, str] | None:
    """The property ``name`` of ``fb`` (as its nearest declaration in ``fb``'s lineage) and its monitoring mode, if
    the attribute marks it."""
    found = property_of(fb, name)
    if found is None:
        return None
    mode = next((m.monitoring for m in (found.getter, found.setter) if m is not None and m.monitoring), None)
    return (found, mode) if mode is not None else None
