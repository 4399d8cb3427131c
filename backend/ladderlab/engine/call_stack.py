"""The call stack of a halted scan: each POU call the scan stands in, and a FUNCTION's or METHOD's own variables.

CODESYS shows, while halted at a breakpoint, the call stack (each POU call with where it stands) and the
variables of a function or method called (ON-03): they live for one call only, so no path reaches them
(``inst.M.x`` is no variable between calls). The debug variant's code is generators, one per POU call
(``yield from``; docs/runtime.md "Pause points"), so a halted scan is the chain of suspended generators under
the scan's own; each generator's frame holds the call's variables as the code generator named them
(codegen/scope.py), read through ``FrameReader`` as fault reports read them.

Exact by construction: a FUNCTION's (and METHOD's) variables are assigned their initial values at the call's
entry, before its first pause point (codegen/pou.py ``emit_function``), so a variable the call has not assigned
yet holds its initial value; the frames are suspended, so nothing moves while they are read; a value that
cannot be read is listed without one, with the reason.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from types import FrameType, GeneratorType
from typing import Literal

from ..ir import nodes as ir
from ..ir import types as t
from .codegen import names
from .codegen.frame_reader import FrameReader
from .codegen.module import Generated
from .debug import Halt
from .paths import plain

FrameKind = Literal["program", "function_block", "function", "method"]
VariableKind = Literal["input", "output", "in_out", "var", "temp", "result"]

_KINDS: dict[str, VariableKind] = {
    "VAR_INPUT": "input",
    "VAR_OUTPUT": "output",
    "VAR_IN_OUT": "in_out",
    "VAR": "var",
    "VAR_TEMP": "temp",
}
#: The hidden in-out of a METHOD: its instance, shown as the frame's ``instance`` (st/methods.py).
_THIS = "THIS"


@dataclass(frozen=True)
class StackVariable:
    """A variable of a FUNCTION's or METHOD's call: its value as plain data (``paths.plain``, as every online
    value), or no value and the reason it could not be read exactly."""

    name: str
    kind: VariableKind
    type: t.IrType
    value: object = None
    reason: str | None = None


@dataclass(frozen=True)
class CallFrame:
    """One POU call of the halted scan: where it stands (the halt point in the innermost call, the call it makes
    in the others) and, for a FUNCTION or METHOD, its own variables in declaration order."""

    pou: str
    kind: FrameKind
    instance: str | None  # a PROGRAM's, FB's or METHOD's instance path; None in a FUNCTION or unreachable by path
    origin: ir.Origin
    element: str | None
    variables: tuple[StackVariable, ...] = ()


def call_stack(
    chain: Iterable[GeneratorType],
    halt: Halt,
    generated: Generated,
    instance_path: Callable[[object], str | None],
) -> tuple[CallFrame, ...]:
    """The calls of a halted scan, outermost first. ``chain``: the generators of the scan below the scheduler's
    (the task's first), each suspended in the next (``gi_yieldfrom``)."""
    pous = _pous_by_code(generated)
    calls: list[tuple[ir.Pou, GeneratorType, GeneratorType]] = []  # (POU, its call's generator, the deepest part)
    for generator in chain:
        pou = pous.get(generator.gi_code.co_name)
        if pou is not None:
            calls.append((pou, generator, generator))
        elif calls:  # a chunk or an outlined part of the body (codegen/statements.py): the call stands where it does
            calls[-1] = (calls[-1][0], calls[-1][1], generator)
        # (before the first POU call: the task's function, codegen/tasks.py)
    frames = []
    for number, (pou, call, deepest) in enumerate(calls):
        innermost = number == len(calls) - 1
        origin = halt.origin if innermost else _origin(generated, deepest.gi_frame, pou)
        element = (halt.point.element or origin.element) if innermost else origin.element
        frames.append(_frame(generated, pou, call.gi_frame, origin, element, instance_path))
    return tuple(frames)


def _pous_by_code(generated: Generated) -> dict[str, ir.Pou]:
    """Each POU by the name of the generated function that runs one call of it."""
    return {
        (names.function(pou.name) if pou.kind == "function" else names.execute_function(pou.name)): pou
        for pou in generated.context.pous.values()
    }


def _origin(generated: Generated, frame: FrameType, pou: ir.Pou) -> ir.Origin:
    """The origin of the statement a suspended call stands in (making a call: ``yield from``); just its POU for a
    generated line that belongs to no statement (none is known to make a call)."""
    oid = generated.line_origins[frame.f_lineno - 1]
    return generated.origins[oid] if oid is not None else ir.Origin(pou.name)


def _frame(
    generated: Generated,
    pou: ir.Pou,
    frame: FrameType,
    origin: ir.Origin,
    element: str | None,
    instance_path: Callable[[object], str | None],
) -> CallFrame:
    if pou.kind != "function":
        return CallFrame(pou.name, pou.kind, instance_path(frame.f_locals["self"]), origin, element)
    reader = FrameReader(generated.context, frame, {}, pou.name)
    method = "." in pou.name  # ``<FB>.<M>`` (a property's accessor ``<FB>.<P>.GET``): no FUNCTION has a dot
    instance = None
    variables = []
    for slot in pou.slots:
        if slot.hidden or slot.var_class == "VAR_EXTERNAL":
            continue
        if method and slot.name == _THIS:
            instance = instance_path(_read(reader, slot)[0])
            continue
        variables.append(_variable(reader, pou, slot))
    return CallFrame(pou.name, "method" if method else "function", instance, origin, element, tuple(variables))


def _variable(reader: FrameReader, pou: ir.Pou, slot: ir.Slot) -> StackVariable:
    result = slot.name.upper() == pou.name.upper()  # the result: the slot named like the POU (codegen/scope.py)
    # A method's result is assigned to the method's name (``Start := ...``), a property's GET to the property's.
    name = pou.name.split(".")[1] if result and "." in pou.name else slot.name
    kind: VariableKind = "result" if result else _KINDS[slot.var_class]
    value, reason = _read(reader, slot)
    if reason is not None:
        return StackVariable(name, kind, slot.type, reason=reason)
    return StackVariable(name, kind, slot.type, plain(reader.context, slot.type, value))


def _read(reader: FrameReader, slot: ir.Slot) -> tuple[object, str | None]:
    """A slot's value in the call's frame, or None and why it cannot be read."""
    try:
        return reader.read(ir.Var("local", slot.name, slot.type)), None
    except KeyError as missing:  # not among the frame's locals: the generated code holds it elsewhere
        return None, f"not held in the call's frame ({missing})"
