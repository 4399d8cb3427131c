"""Probes the monitor variant need not store during the scan: their value is still there after it.

A probe costs a list store per element per scan. When a probe reads a PROGRAM's own
variable (or a member of it, e.g. an FB instance's output ``T1.Q``) at the top level of
a POU body without jumps or RETURN, and nothing in the body writes that variable
afterwards, the variable still holds the probed value when the scan ends: a PROGRAM
runs at most once per scan and no other POU writes its variables. Such a probe is
*deferred*: the monitor variant reads it after the scan, only when a monitor asks
(``ll_read_probes``), and records only its group stamp during the scan. The debug
variant, which can halt mid-scan, stores every probe.
"""

from __future__ import annotations

from ...ir import nodes as ir
from ...ir import types as t
from .context import std_fb_class
from .mentions import calls_in, own_expressions, walk

_STORED = ("VAR", "VAR_INPUT", "VAR_OUTPUT")


def deferred_probes(pou: ir.Pou) -> set[int]:
    """``id()`` of the probes of ``pou`` whose value can be read after the scan."""
    if pou.kind != "program":
        return set()
    top = [s for block in pou.blocks for s in block.statements]
    if any(isinstance(s, (ir.Jump, ir.Return)) for s in walk(top)):
        return set()
    classes = {slot.name.upper(): slot.var_class for slot in pou.slots}
    found: set[int] = set()
    written: set[str] = set()  # roots written by the statements after the one looked at
    for s in reversed(top):
        if isinstance(s, ir.Probe) and _own_variable(s.value, classes) and s.value.name.upper() not in written:
            found.add(id(s))
        written |= _writes(s)
    return found


def _own_variable(e: ir.Expr, classes: dict[str, str]) -> bool:
    return (
        isinstance(e, ir.Var)
        and e.scope == "local"
        and classes.get(e.name.upper()) in _STORED
        and all(isinstance(selector, ir.Member) for selector in e.path)
    )


def _writes(s: ir.Stmt) -> set[str]:
    """Roots of the local variables ``s`` (nested statements included) may write."""
    targets: list[ir.Var | None] = []
    for x in walk([s]):
        if isinstance(x, ir.Assign):
            targets.append(x.target)
        elif isinstance(x, ir.FnCall):
            targets += [x.target, x.eno]
        elif isinstance(x, ir.FbCall):  # the call writes the instance's pins; a user FB may write its in-outs
            targets += [x.instance, x.eno, *(v for _, v in x.outputs)]
            if not isinstance(x.instance.type, t.FbInstance) or std_fb_class(x.instance.type.fb) is None:
                targets += [e for _, e in x.inputs if isinstance(e, ir.Var)]
        elif isinstance(x, ir.For):
            targets.append(x.var)
        for e in own_expressions(x):
            for call in calls_in(e):
                targets += list(call.in_outs)
    return {v.name.upper() for v in targets if isinstance(v, ir.Var) and v.scope == "local"}
