"""CODESYS typing: operations computed as CODESYS's registers compute them (ST-20, CODESYS help "Operators").

CODESYS computes intermediate results "with the native size of the target": at least 32 bits on x86 and ARM, 64 on
x64 (CODESYS help, "Operators", overflow/underflow in the data type: ``dwVar := wVar + 1`` gives 65536 when wVar is
65535, and ``(wVar1 + 1) = wVar2`` is FALSE). The checker types ``+ - *`` in the operands' type (INT + INT is an
INT); this pass, run on a checked body, finds where that would give another value than the register:

* a value cut to that type's width (or less) before anything else looks at it is exact as it is (arithmetic modulo
  2^n): stored in a variable, a user POU's input or a string function's INT input that wide (CODESYS's example 3),
  converted with ``TO_WORD`` or ``DINT_TO_WORD`` (example 4), or an operand of another ``+ - *`` so cut;
* anywhere else (a comparison, a division, an index, a REAL, a wider variable) a signed operation narrower than 32
  bits, and an unsigned ``+``, compute in DINT instead, as the 32-bit register does (their node's type becomes DINT;
  an unsigned ``+`` of two 16-bit values never leaves DINT); a division, MOD or negation of such a value too; a
  negation ``-x`` of a narrow ``x`` is the register's ``0 - x``; an unsigned ``-`` or ``*`` cut to at most 32 bits
  (into a WORD or DINT variable, an INT input) too: those bits are the same in every register;
* where the register's value is target dependent (an unsigned ``-`` or ``*`` used uncut or cut to more than 32 bits:
  the register's sign and width) or its user would give a target's result for it (a typed conversion
  ``INT_TO_REAL`` of a promoted value: converted before or after the cut?; SHR; a FOR loop's end or step), the
  operation computes in DINT and is wrapped in ``ast.Fit``: its value must lie in the operation's own type, where the
  cut changes nothing and every target gives the same result; the run faults, located, when it does not
  (``INT_TO_DWORD(pos - 1)`` for any pos but -32768). A user that gives another result for the same value in a wider
  register (a bitwise operation, NOT, another shift or function of a promoted value) is refused with
  ST-CODESYS-REGISTER, located at the operation. MIN, MAX, LIMIT, SEL, MUX and MOVE
  of a promoted value give one of their inputs: they compute in DINT too.

Operations of 32 bits wrap in 32 bits, as on a 32-bit target (x86, ARM); CODESYS on x64 computes them in 64 bits and
may give another value on an overflow (docs/st.md "CODESYS typing").
"""

from __future__ import annotations

from typing import Any

from ..iec import stdlib
from . import ast
from . import types as t
from .symbols import PouInfo, Symbol

#: Intermediate results are at least this wide on every CODESYS target.
REGISTER_BITS = 32
_MODULAR = frozenset({"+", "-", "*"})
_COMPARISONS = frozenset({"=", "<>", "<", ">", "<=", ">="})
_COMPARING = frozenset({"GT", "GE", "EQ", "LE", "LT", "NE"})
#: Standard functions whose result is one of their (generic) inputs.
_SELECTING = frozenset({"MIN", "MAX", "LIMIT", "SEL", "MUX", "MOVE"})
DINT = t.Elementary("DINT")
_BITWISE = frozenset({"AND", "OR", "XOR"})
#: ``expr``'s answer for a value computed in DINT that is target independent only within its own type: whoever uses
#: it wraps it in ``ast.Fit`` (an unsigned ``-`` or ``*`` used uncut).
FIT = "fit"


def check_registers(body: list[ast.Stmt], report: Any) -> None:
    """Report every ``+ - *`` in ``body`` whose value CODESYS's register would change (see the module docstring)."""
    if t.codesys_typing():
        _Walker(report).statements(body)


def _width(ty: Any) -> int | None:
    """The bits of an integer or bit-string type (None for anything else)."""
    if isinstance(ty, t.Elementary) and ty.category in ("int", "bits"):
        return ty.info.bits
    return None


class _Walker:
    def __init__(self, report: Any):
        self.report = report
        self.narrow: dict[int, Any] = {}  # id of a promoted node -> its type before (what its ast.Fit checks)

    def statements(self, value: Any) -> None:
        """Every expression in a statement, a list of them or a part of one (an IF's branch, a CASE label ...)."""
        if isinstance(value, ast.Assign):
            self.expr(value.target, None)
            self.operand(value, "value", _width(getattr(value.target, "ty", None)))
        elif isinstance(value, ast.For):
            self.operand(value, "start", _width(getattr(value.var, "ty", None)))
            for bound in ("end", "step"):  # compared with the variable each time: not cut
                if getattr(value, bound) is not None:
                    self.operand(value, bound, None, exact=True)
            self.statements(value.body)
        elif isinstance(value, _EXPRESSIONS):  # an IF's or a WHILE's condition: a BOOL
            self.expr(value, None)
        elif isinstance(value, (list, tuple)):
            for item in value:
                self.statements(item)
        elif hasattr(value, "__slots__") and not isinstance(value, ast.LITERALS):
            for name in value.__slots__:
                if name in ("span", "ty", "ref"):
                    continue
                if isinstance(getattr(value, name), _EXPRESSIONS):  # a CASE's selector ...
                    self.operand(value, name, None)
                else:
                    self.statements(getattr(value, name))

    def operand(self, holder: Any, key: str | int, cut: int | None, exact: bool = False) -> bool:
        """Walk the expression ``holder.key`` (``holder[key]`` in a list), cut to ``cut`` bits (None: it is not), and
        wrap it in ``ast.Fit`` when it is a FIT or, ``exact``, when its user would give a target's result for a
        promoted value. True when it stays promoted (a DINT)."""
        node = holder[key] if isinstance(key, int) else getattr(holder, key)
        state = self.expr(node, cut)
        if state == FIT or (state and exact):
            fit = ast.Fit(node, node.span, self.narrow[id(node)])
            if isinstance(key, int):
                holder[key] = fit
            else:
                setattr(holder, key, fit)
            return False
        return bool(state)

    def expr(self, node: Any, cut: int | None) -> bool | str:
        """Walk ``node``, whose value is cut to ``cut`` bits before anything else sees it (None: it is not); True
        when its type became DINT (computed as the register does), FIT when its user must check it too."""
        if isinstance(node, ast.Binary):
            return self.binary(node, cut)
        if isinstance(node, ast.Unary):
            width = _width(node.ty)
            if node.op == "-" and _narrow(node):  # the register's 0 - x
                return self.modular(node, cut, width, ("operand",))
            inner = min(cut, width) if cut is not None and width is not None else None
            if self.operand(node, "operand", inner):
                return self._promote(node) if node.op == "-" else self._refuse(node, "NOT of")
            return False
        if isinstance(node, ast.Call):
            return self.call(node, cut)
        if isinstance(node, (ast.Member, ast.Deref)):
            self.expr(node.base, None)
        elif isinstance(node, ast.Index):
            self.expr(node.base, None)
            for position in range(len(node.indices)):
                self.operand(node.indices, position, None)
        return False

    def binary(self, node: ast.Binary, cut: int | None) -> bool | str:
        width = _width(node.ty)
        if node.op in _MODULAR and _narrow(node) and ((cut is not None and cut <= width) or not _literal_only(node)):
            return self.modular(node, cut, width, ("left", "right"))
        if node.op in ("=", "<>"):
            return self.equality(node)
        inner = min(cut, width) if node.op in _BITWISE and cut is not None and width is not None else None
        promoted = self.operand(node, "left", inner) | self.operand(node, "right", inner)
        if not promoted or node.op in _COMPARISONS:  # a comparison works in its operands' lub (the lowering)
            return False
        if node.op in ("/", "MOD", "+", "-", "*"):
            return self._promote(node)
        return self._refuse(node, f"'{node.op}' on")

    def modular(self, node: Any, cut: int | None, width: int, operands: tuple[str, ...]) -> bool | str:
        """A ``+ - *`` or a negation narrower than the register. Cut to its width (or less): exact modulo 2^width,
        operands promoted or not. Else it computes in DINT as the register does; an unsigned ``-`` or ``*`` (the
        negation too) is below 0 or above the type in a register read signed or unsigned, 32 or 64 bits wide, so it is
        a FIT unless its value is cut to at most 32 bits (a DINT, an INT input): those bits are the same in every
        such register (``inc(cnt, -step, mx)`` with a BYTE step passes -step to the INT input)."""
        if cut is not None and cut <= width:
            for key in operands:
                self.operand(node, key, width)
            return False
        for key in operands:
            self.operand(node, key, None)
        register_sign_decides = not node.ty.info.signed and node.op != "+" and (cut is None or cut > REGISTER_BITS)
        self._promote(node)
        return FIT if register_sign_decides else True

    def equality(self, node: ast.Binary) -> bool:
        """``(w2 - 1) = w1`` on unsigned narrow operands is FALSE on every target (CODESYS "Operators", example 2):
        a register below 0, read signed or unsigned, equals no value of a narrow unsigned type. So an unsigned
        ``-`` compared for equality with one computes in DINT too."""
        for side, other in (("left", node.right), ("right", node.left)):
            operation = getattr(node, side)
            if _unsigned_narrow(other.ty) and _unsigned_subtraction(operation):
                self.operand(operation, "left", None)
                self.operand(operation, "right", None)
                self._promote(operation)
                continue
            self.operand(node, side, None)
        return False

    def call(self, node: ast.Call, cut: int | None) -> bool:
        name = node.callee.name.upper() if isinstance(node.callee, ast.Name) else ""
        target = _conversion_target(name)
        promoted = False
        for position, arg in enumerate(node.args):
            width = _width(t.elementary(target)) if target is not None else _width(_input_type(node.ref, position, arg))
            wide = target is None and _any_integer(node.ref, position, arg)  # SHL's N takes a DINT as well
            exact = not wide and _same_for_its_own_values(node.ref, name)
            if self.operand(arg, "value", width, exact=exact):
                promoted |= not wide
        if not promoted or name.startswith("TO_"):  # an overloaded TO_x takes the promoted type as it is
            return False
        if name in _COMPARING:  # GT(a, b) ...: compares in its arguments' lub, as the operators do
            return False
        if name in _SELECTING and isinstance(node.ref, stdlib.StdFunction) and node.ref.result == stdlib.T:
            return self._promote(node)  # MIN, LIMIT, SEL ... give one of their inputs: the register's value
        return self._refuse(node, "a call of")

    def _promote(self, node: Any) -> bool:
        self.narrow.setdefault(id(node), node.ty)
        node.ty = DINT
        return True

    def _refuse(self, node: Any, what: str) -> bool:
        self.report(
            "ST-CODESYS-REGISTER",
            f"CODESYS computes this in a register of at least {REGISTER_BITS} bits, and what {what} its value gives "
            "depends on the target: cut the value first (TO_INT(...), TO_WORD(...)) or compute in a wider type "
            "(TO_DINT(...))",
            node,
        )
        return False


_EXPRESSIONS = (ast.Binary, ast.Unary, ast.Call, ast.Member, ast.Deref, ast.Index, ast.Name)


def _conversion_target(name: str) -> str | None:
    """``WORD`` for ``TO_WORD`` / ``DINT_TO_WORD`` (an integer or bit-string conversion), else None."""
    target = (
        name.removeprefix("TO_") if name.startswith("TO_") else name.rpartition("_TO_")[2] if "_TO_" in name else ""
    )
    return target if _width(t.elementary(target)) is not None else None


def _same_for_its_own_values(callee: Any, name: str) -> bool:
    """Whether ``callee`` is a standard function (``name``) that gives the same result for a value of its input's
    narrow type whether that value is cut or still in a wider register: a typed conversion (``INT_TO_DWORD``: a
    value, converted) and SHR (floor(value / 2^N), signed or not, whatever the width). Not SHL or ROL (bits leave the
    narrow type), ABS (ABS(-32768) overflows an INT only), an overloaded TO_x (it takes the register's type), a user
    function (whatever its name)."""
    if not isinstance(callee, stdlib.StdFunction):
        return False
    return name == "SHR" or ("_TO_" in name and not name.startswith("TO_"))


def _input_type(callee: Any, position: int, arg: ast.Arg) -> Any:
    """The declared type of the input ``arg`` is passed to, when passing it stores it in a variable of that type: a
    user function's or FB's VAR_INPUT, a standard function's input of one named type (LEFT's L: INT). None for a
    generic input (MIN, LIMIT ... compute in the register), an output, and anything unknown."""
    if arg.output:
        return None
    if isinstance(callee, Symbol) and isinstance(callee.type, t.FbType):
        callee = callee.type.pou
    if isinstance(callee, PouInfo):
        inputs = [s for s in callee.symbols.values() if s.var_class == "VAR_INPUT"]
        if arg.name is not None:
            return next((s.type for s in inputs if s.name.upper() == arg.name.upper()), None)
        return inputs[position].type if position < len(inputs) else None
    if isinstance(callee, stdlib.StdFunction) and callee.group == "string":  # CODESYS's Standard library: INT
        name = arg.name if arg.name is not None else callee.input_name(position)
        pin = callee.pin(name) if name is not None else None
        return t.INT if pin is not None and t.in_family(t.INT, pin.type) else None
    return None


def _any_integer(callee: Any, position: int, arg: ast.Arg) -> bool:
    """Whether ``arg`` goes to a standard function's non-generic ANY_INT input (SHL's N): it takes a DINT as well."""
    if not isinstance(callee, stdlib.StdFunction):
        return False
    name = arg.name if arg.name is not None else callee.input_name(position)
    pin = callee.pin(name) if name is not None else None
    return pin is not None and not pin.generic and pin.type == "ANY_INT"


def _narrow(node: Any) -> bool:
    """Whether ``node`` is an integer or bit-string operation narrower than the register (not of literals only)."""
    width = _width(node.ty)
    return width is not None and width < REGISTER_BITS and not isinstance(node.ty, t.UNTYPED)


def _unsigned_subtraction(node: Any) -> bool:
    return isinstance(node, ast.Binary) and node.op == "-" and _unsigned_narrow(node.ty) and not _literal_only(node)


def _unsigned_narrow(ty: Any) -> bool:
    width = _width(ty)
    return width is not None and width < REGISTER_BITS and not ty.info.signed


def _literal_only(node: Any) -> bool:
    return isinstance(node.ty, t.UNTYPED)
