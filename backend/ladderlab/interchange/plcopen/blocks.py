"""Pin lists of the blocks a diagram calls, and which pins carry LD power flow.

A PLCopen ``<block>`` lists its pins, and an LD box in the project model has one
power input and one power output. Both directions need the callee's interface:
standard functions and FBs come from the ST catalogue (``st/stdlib.py``), user
POUs from their own declarations (parsed with the ST parser).

Power pins (the LD lowering's rule, ``ir/lower_ld.py``): power enters ``EN`` when
the box has ``en``, else the first input that can be BOOL and is not given an
operand or series list; it leaves through ``ENO`` when the box has ``en``, else
through the first output that can be BOOL. "Can be BOOL" means declared BOOL or
of a generic family that contains BOOL (ANY_BIT, ANY, ANY_ELEMENTARY), e.g. IN1 of
AND or G of SEL; whether a generic function result is BOOL depends on the
actual operands, which only the lowering knows.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from ...iec import stdlib
from ...iec.elementary import GENERIC, canonical_type_name
from ...model.project import Pou
from ...st import ast
from ...st.parser import parse_declarations

#: Name of a function's result pin on a block (the PLCopen / Beremiz convention).
RESULT_PIN = "OUT"


@dataclass(frozen=True)
class Signature:
    """A callee's pins in declaration order, with their type names (generic families for standard functions)."""

    kind: str  # "function", "function_block" or "program"
    inputs: tuple[tuple[str, str], ...]
    outputs: tuple[tuple[str, str], ...]
    in_outs: tuple[tuple[str, str], ...] = ()
    extensible: bool = False
    generic_bool: bool = field(default=False, compare=False)  # the generic T may be BOOL (result of AND, SEL...)

    def can_be_bool(self, type_name: str) -> bool:
        name = canonical_type_name(type_name)
        if name == "BOOL":
            return True
        if name == stdlib.T:
            return self.generic_bool
        return "BOOL" in GENERIC.get(name, ())

    def power_in(self, en: bool, used: Iterable[str] = ()) -> str | None:
        """EN, or the first input that can be BOOL and is not ``used`` (given an operand or series list)."""
        if en:
            return "EN"
        taken = {u.upper() for u in used}
        return next((name for name, ty in self.inputs if self.can_be_bool(ty) and name.upper() not in taken), None)

    def bool_inputs(self) -> list[str]:
        return [name for name, ty in self.inputs if self.can_be_bool(ty)]

    def power_out(self, en: bool) -> str | None:
        if en:
            return "ENO"
        return next((name for name, ty in self.outputs if self.can_be_bool(ty)), None)

    def input_names(self, used: Iterable[str] = ()) -> list[str]:
        """Declared inputs, then any extra ones ``used`` (IN3, IN4 ... of extensible functions)."""
        names = [name for name, _ in self.inputs]
        known = {n.upper() for n in names} | {n.upper() for n, _ in self.in_outs}
        return names + [u for u in used if u.upper() not in known and u.upper() != "EN"]


def _std_function(fn: stdlib.StdFunction) -> Signature:
    generic_bool = any(pin.generic and "BOOL" in GENERIC.get(pin.type, ()) for pin in fn.inputs)
    return Signature(
        "function",
        tuple((p.name, p.type) for p in fn.inputs),
        ((RESULT_PIN, fn.result),),
        extensible=fn.extensible,
        generic_bool=generic_bool,
    )


def _std_block(fb: stdlib.StdFunctionBlock) -> Signature:
    return Signature(
        "function_block", tuple((p.name, p.type) for p in fb.inputs), tuple((p.name, p.type) for p in fb.outputs)
    )


def _type_name(spec: ast.TypeSpec) -> str:
    return spec.name if isinstance(spec, (ast.NamedType, ast.SizedType)) else "ANY"


def pou_signature(pou: Pou) -> Signature:
    """A user POU's interface from its declarations (blocks that do not parse contribute nothing)."""
    parsed = parse_declarations(pou.declarations, pou=pou.name)
    pins: dict[str, list[tuple[str, str]]] = {"VAR_INPUT": [], "VAR_OUTPUT": [], "VAR_IN_OUT": []}
    for block in parsed.ast or []:
        if block.kind in pins:
            pins[block.kind] += [(n.name, _type_name(d.type)) for d in block.decls for n in d.names if n.name]
    outputs = pins["VAR_OUTPUT"]
    if pou.kind == "function":
        outputs = [(RESULT_PIN, pou.return_type or "ANY"), *outputs]
    return Signature(pou.kind, tuple(pins["VAR_INPUT"]), tuple(outputs), tuple(pins["VAR_IN_OUT"]))


class Signatures:
    """Look up a callee by name (case-insensitive): the project's POUs first, then the standard library."""

    def __init__(self, pous: Iterable[Pou]):
        self._user = {pou.name.upper(): pou for pou in pous}
        self._cache: dict[str, Signature | None] = {}

    def __call__(self, name: str) -> Signature | None:
        key = name.upper()
        if key not in self._cache:
            self._cache[key] = self._find(key)
        return self._cache[key]

    def _find(self, key: str) -> Signature | None:
        if key in self._user:
            return pou_signature(self._user[key])
        fb = stdlib.function_block(key)
        if fb is not None:
            return _std_block(fb)
        fn = stdlib.function(key)
        return _std_function(fn) if fn is not None else None
