"""Type checking of ST statements and expressions inside one POU.

Fills the AST annotations in place: ``expr.ty`` (resolved type), ``Name.ref`` /
``Member.ref`` (Symbol, enum value or POU), ``Call.ref`` (PouInfo, StdFunction,
or the FB instance Symbol). Reports through ``report`` and never raises.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..iec import stdlib
from ..iec.addresses import PART_NAMES, parse_address, part_type, partial_access, same_location
from ..iec.elementary import LONG_TIME_TYPES, SHORT_TO_LONG
from ..iec.literals import textless_character, textless_message
from ..iec.spelling import did_you_mean
from . import ast
from . import types as t
from .calls import check_call, unreferable
from .cases import check_case
from .context_typing import default_type, settle, untyped_leaves, untyped_result
from .gvls import check_unqualified, list_member, shared_use
from .interfaces import check_attempt, reference_comparison
from .methods import check_property, is_self, own_property, this_type, unknown_member_hint
from .rules import EnumValue, assignable_or_report, constant_value, root_name
from .symbols import CheckResult, PouInfo, PropertyRef, Symbol, TypeDef
from .types import ERROR, Type

_ACCESSES = (ast.Name, ast.Member, ast.Index)
Report = Callable[..., None]  # report(code, message, node, severity="error")

_ARITHMETIC = {"+", "-", "*", "/"}
_COMPARISON = {"=", "<>", "<", ">", "<=", ">="}
_LOGIC = {"AND", "OR", "XOR"}
#: CODESYS' short-circuit operators: the right operand is evaluated only when the left does not decide.
_SHORT_CIRCUIT = {"AND_THEN", "OR_ELSE"}
# TIME and date arithmetic (ST-21, ST-22, FUN-85): (op, left category, right category) -> result type name
_TIME_RULES = {
    ("+", "time", "time"): "TIME",
    ("-", "time", "time"): "TIME",
    ("+", "tod", "time"): "TIME_OF_DAY",
    ("-", "tod", "time"): "TIME_OF_DAY",
    ("-", "tod", "tod"): "TIME",
    ("+", "dt", "time"): "DATE_AND_TIME",
    ("-", "dt", "time"): "DATE_AND_TIME",
    ("-", "dt", "dt"): "TIME",
    ("-", "date", "date"): "TIME",
}


def time_rule(op: str, left: Type, right: Type) -> t.Type | None:
    """The result type of a TIME/date operation (_TIME_RULES), in the long forms (LTIME, LDT ...) when both operands
    are long; None when the operands mix a long and a short type (an explicit conversion is needed)."""
    rule = _TIME_RULES.get((op, t.category(left), t.category(right)))
    if rule is None:
        return None
    longs = {isinstance(x, t.Elementary) and x.name in LONG_TIME_TYPES for x in (left, right)}
    if len(longs) > 1:
        return None
    return t.Elementary(SHORT_TO_LONG[rule] if True in longs else rule)


class BodyChecker:
    def __init__(self, result: CheckResult, pou: PouInfo | None, report: Report):
        self.result = result
        self.pou = pou
        self.report = report
        self.loop_depth = 0
        self.loop_vars: list[Symbol] = []
        self.result_assigned = False
        #: The access typed as the REFERENCE TO itself, not read through (REF='s target, ^'s base, __ISVALIDREF)
        self.keep_reference: ast.Expr | None = None
        #: While a POU's declarations are checked: its VAR CONSTANTs, also those declared further down, so
        #: ``fifo : ARRAY[0..n] OF DWORD`` may come before ``VAR CONSTANT n : INT := 16;`` (CODESYS, OSCAT's FIFO_16)
        self.constants_ahead: dict[str, Symbol] = {}

    # ------------------------------------------------------------ names
    def lookup(self, name: str) -> Symbol | None:
        upper = name.upper()
        if self.pou is not None and upper in self.pou.symbols:
            return self.pou.symbols[upper]
        if self.constants_ahead and upper in self.constants_ahead:
            return self.constants_ahead[upper]
        if self.pou is not None and self.pou.method is not None and upper in self.pou.method.owner.symbols:
            return self.pou.method.owner.symbols[upper]  # a method works on its instance's variables
        return self.result.globals.get(upper)

    def enum_values(self, name: str) -> list[EnumValue]:
        upper = name.upper()
        found, seen = [], set()
        for typedef in self.result.types.values():
            for enum in _enums_in(typedef.type):
                if upper in enum.values and id(enum) not in seen:  # a named enum also appears in structs using it
                    seen.add(id(enum))
                    written, value = enum.values[upper]
                    found.append(EnumValue(enum, written, value))
        return found

    def _visible_names(self) -> list[str]:
        names = [s.name for s in self.result.globals.values()]
        if self.pou is not None:
            names += [s.name for s in self.pou.symbols.values()]
        return names

    # ------------------------------------------------------------ expressions
    def expr(self, node: ast.Expr, expected: Type | None = None) -> Type:
        """Type a whole expression where it is used (an assignment's value, a condition, an argument ...): its
        literals and generic operations take their types from ``expected`` (st/context_typing.py)."""
        ty = self._expr(node, expected)
        node.ty = ty
        if type(node) is not ast.Name and ty is not ERROR:  # a declared variable, the commonest, has nothing to fix
            settle(self, node, expected)
        return node.ty

    def typed(self, node: ast.Expr, expected: Type | None = None) -> Type:
        """An operand's own type before its context is known (literals untyped, see ``expr``)."""
        ty = self._expr(node, expected)
        node.ty = ty
        return ty

    def settle(self, node: ast.Expr, context: Type | None) -> None:
        settle(self, node, context)

    def _expr(self, node: ast.Expr, expected: Type | None) -> Type:
        check = _EXPRESSION_CHECKS.get(type(node))
        ty = check(self, node, expected) if check is not None else self._binary(node)
        if (
            isinstance(ty, t.PointerType)
            and ty.implicit
            and type(node) in _ACCESSES
            and node is not self.keep_reference
        ):
            node.deref = True  # a CODESYS REFERENCE TO stands for its target (lowered as r^)
            return ty.target
        return ty

    def reference(self, node: ast.Expr) -> Type:
        """Type an access as the reference itself: a REFERENCE TO is not read through here."""
        saved, self.keep_reference = self.keep_reference, node
        try:
            return self.expr(node)
        finally:
            self.keep_reference = saved

    def _deref(self, node: ast.Deref) -> Type:
        this = this_type(self, node)
        if this is not None:
            return this
        base = self.reference(node.base)  # r^ on a REFERENCE TO too, as IronPLC accepts
        if isinstance(base, t.PointerType):
            return base.target
        if base is not ERROR:
            self.report("ST-TYPE-MISMATCH", f"'^' needs a pointer, not {base}", node)
        return ERROR

    def _string_literal(self, node: ast.StringLit) -> Type:
        """A STRING or WSTRING literal, whose characters a string must hold (ST-RANGE otherwise: no byte or WORD is
        made up for them)."""
        textless = textless_character(node.value)
        if textless is not None:
            self.report("ST-RANGE", textless_message(textless), node)
        return t.StringType(node.wide)

    def _typed_literal(self, node: ast.TypedLit) -> Type:
        target = t.elementary(node.type_name)
        if target is None:
            typedef = self.result.types.get(node.type_name.upper())
            if typedef is not None and isinstance(typedef.type, t.EnumType) and isinstance(node.value, ast.Name):
                return typedef.type if self._enum_member(typedef, node.value.name, node) is not None else ERROR
            self.report("ST-UNKNOWN-TYPE", f"unknown type '{node.type_name}' in typed literal", node)
            return ERROR
        value = self.typed(node.value)
        if isinstance(value, t.UNTYPED) and t.takes_literal(target, value):
            self.settle(node.value, target)  # reports a value out of the type's range (ST-RANGE)
        else:
            assignable_or_report(self, target, value, node, f"{node.type_name}# literal")
        return target

    def _name(self, node: ast.Name, expected: Type | None) -> Type:
        symbol = self.lookup(node.name)
        if symbol is not None:
            node.ref = symbol
            if self.result.listed:
                check_unqualified(self, node, symbol)
            return symbol.type
        if self.result.shared and shared_use(self.result, self.report, node, node.name):
            return ERROR
        if self.pou is not None and self.pou.kind == "FUNCTION" and node.name.upper() == _result_name(self.pou):
            node.ref = self.pou
            return self.pou.return_type or ERROR
        found = own_property(self, node)
        if found is not None:
            return found
        program = self.result.pous.get(node.name.upper())
        if program is not None and program.kind == "PROGRAM":  # its outputs and SFC steps are read (ST-60, SFC-06)
            node.ref = program
            return t.FbType(program.name, pou=program)
        values = self.enum_values(node.name)
        if isinstance(expected, t.EnumType):
            values = [v for v in values if v.type is expected] or values
        if len(values) == 1:
            node.ref = values[0]
            return values[0].type
        if len(values) > 1:
            names = ", ".join(f"{v.type.name}#{v.name}" for v in values)
            self.report("ST-AMBIGUOUS", f"'{node.name}' is a value of several enumerations: write {names}", node)
            return ERROR
        if node.name.upper() == "NULL":  # IEC 61131-3 ed. 3: the reference to nothing (unless declared otherwise)
            return t.NULL
        self.report(
            "ST-UNKNOWN-VAR", f"unknown variable '{node.name}'" + did_you_mean(node.name, self._visible_names()), node
        )
        return ERROR

    def _direct(self, node: ast.DirectAddr) -> Type:
        """A direct address: the variable declared AT it (in this POU, else globally), else one of its size's
        default type (ST-13, iec/addresses.py)."""
        try:
            address = parse_address(node.address)
        except ValueError as error:
            self.report("ST-ADDRESS", str(error), node)
            return ERROR
        for scope in (self.pou.symbols.values() if self.pou else (), self.result.globals.values()):
            for symbol in scope:
                if symbol.address and same_location(symbol.address, address):
                    node.ref = symbol
                    return symbol.type
        return t.Elementary(address.default_type)

    def _member(self, node: ast.Member) -> Type:
        listed = list_member(self, node)
        if listed is not None:
            return listed
        qualified = self._qualified_enum_value(node)
        if qualified is not None:
            return qualified
        base = self.expr(node.base)
        upper = node.name.upper()
        if base is ERROR:
            return ERROR
        if isinstance(base, t.StructType):
            if upper in base.fields:
                return base.fields[upper][1]
            self.report(
                "ST-UNKNOWN-MEMBER",
                f"{base.name} has no field '{node.name}'"
                + did_you_mean(node.name, [f[0] for f in base.fields.values()]),
                node,
            )
            return ERROR
        if isinstance(base, t.FbType):
            return self._fb_member(node, base)
        if isinstance(base, t.InterfaceType):  # its methods are called, its properties read and written
            found = check_property(self, node, base.info)
            if found is not None:
                return found
            if base.info.find_method(node.name) is not None:
                self.report("ST-NOT-CALLABLE", f"'{node.name}' is a method of {base.name}: call it (add the ( ))", node)
                return ERROR
            members = [m.method for i in base.info.all_interfaces() for m in i.methods.values()]
            what = "method or property" if any(m.key != m.name.upper() for m in members) else "method"
            names = list(dict.fromkeys(m.name for m in members))
            message = f"{base.name} has no {what} '{node.name}'" + did_you_mean(node.name, names)
            self.report("ST-UNKNOWN-MEMBER", message, node)
            return ERROR
        part = partial_access(node.name)
        if part is not None and isinstance(base, t.Elementary) and base.category in ("bits", "int"):
            return self._part(node, base, *part)
        self.report("ST-UNKNOWN-MEMBER", f"'{node.name}' cannot be selected from a {base}", node)
        return ERROR

    def _part(self, node: ast.Member, base: t.Elementary, width: int, index: int) -> Type:
        """Bit access ``x.3`` / ``x.%X3`` and partial access ``x.%B1``, ``.%W0``, ``.%D1``, ``.%L0`` (IEC 61131-3
        ed. 3, 6.5.6; on integers too, as CODESYS allows), numbered from the least significant part."""
        bits = base.info.bits
        if index >= bits // width:
            what = PART_NAMES[width]
            self.report(
                "ST-UNKNOWN-MEMBER",
                f"'{node.name}' is outside a {base}: it has {what} 0..{bits // width - 1}"
                if bits >= width
                else f"a {base} has no {what}: it is {bits} bits wide",
                node,
            )
            return ERROR
        return t.elementary(part_type(width)) or ERROR

    def _qualified_enum_value(self, node: ast.Member) -> Type | None:
        """CODESYS's ``Color.Green`` for IEC's ``Color#Green`` (ed. 3 writes the type name too, with '#'): the base
        names an enumeration type and no variable, program or property. None: not such a name."""
        base = node.base
        if not isinstance(base, ast.Name) or self.lookup(base.name) is not None:
            return None
        typedef = self.result.types.get(base.name.upper())
        if typedef is None or not isinstance(typedef.type, t.EnumType) or base.name.upper() in self.result.pous:
            return None
        member = self._enum_member(typedef, node.name, node)
        if member is None:
            return ERROR
        node.ref = EnumValue(typedef.type, *member)
        return typedef.type

    def _enum_member(self, typedef: TypeDef, name: str, node: Any) -> tuple[str, int] | None:
        """(name as declared, value) of ``name`` in the enumeration ``typedef`` (``E#A``, ``E.A``); None, reported
        at ``node``, when it has no such value."""
        values = typedef.type.values
        if name.upper() in values:
            return values[name.upper()]
        message = f"'{name}' is not a value of {typedef.name}"
        self.report("ST-UNKNOWN-VAR", message + did_you_mean(name, [v[0] for v in values.values()]), node)
        return None

    def _fb_member(self, node: ast.Member, base: t.FbType) -> Type:
        upper = node.name.upper()
        if base.std is not None:
            for pin in (*base.std.inputs, *base.std.outputs):
                if pin.name == upper:
                    node.ref = pin
                    return t.elementary(pin.type) or ERROR
            if upper in ("EN", "ENO"):
                return t.BOOL
            pins = [p.name for p in (*base.std.inputs, *base.std.outputs)]
            self.report(
                "ST-UNKNOWN-MEMBER", f"{base.name} has no pin '{node.name}'" + did_you_mean(node.name, pins), node
            )
            return ERROR
        symbol = base.pou.symbols.get(upper)
        if symbol is None:
            found = check_property(self, node, base.pou)
            if found is not None:
                return found
        if symbol is None and base.pou.find_method(upper) is not None:
            self.report("ST-NOT-CALLABLE", f"'{node.name}' is a method of {base.name}: call it (add the ( ))", node)
            return ERROR
        if symbol is None:
            self.report(
                "ST-UNKNOWN-MEMBER",
                f"{base.name} has no input or output '{node.name}'" + unknown_member_hint(base.pou, node.name),
                node,
            )
            return ERROR
        node.ref = symbol
        if symbol.var_class == "VAR_IN_OUT":
            self.report(
                "ST-NOT-ACCESSIBLE",
                f"'{node.name}' is an in-out of {base.name}: it stands for the caller's variable during a call "
                "only, so it cannot be read or written from outside (pass the variable in the call)",
                node,
            )
        elif symbol.var_class not in ("VAR_INPUT", "VAR_OUTPUT") and not _sfc_state(symbol) and not is_self(node.base):
            self.report(
                "ST-NOT-ACCESSIBLE",
                f"'{node.name}' is internal to {base.name}: only its inputs and outputs can be used from outside",
                node,
            )
        return symbol.type

    def _index(self, node: ast.Index) -> Type:
        base = self.expr(node.base)
        for index in node.indices:
            index_type = self.expr(index)
            if index_type is not ERROR and not t.counts(index_type):
                self.report("ST-TYPE-MISMATCH", f"an array index must be an integer (ANY_INT), not {index_type}", index)
        if isinstance(base, t.ArrayType):
            if len(node.indices) != len(base.dims):
                self.report("ST-INDEX", f"{base} needs {len(base.dims)} index(es), got {len(node.indices)}", node)
            self._constant_indices_in_bounds(node, base)
            return base.element
        if isinstance(base, t.StringType):
            return t.StringType(base.wide)
        if isinstance(base, t.PointerType):
            return base.target
        if base is not ERROR:
            self.report("ST-INDEX", f"'[...]' needs an array, not {base}", node)
        return ERROR

    def _constant_indices_in_bounds(self, node: ast.Index, array: t.ArrayType) -> None:
        """A constant index outside the declared bounds is a compile-time error (it would fault every scan)."""
        for index, dims in zip(node.indices, array.dims):
            value = constant_value(self, index)
            if dims is not None and isinstance(value, int) and not dims[0] <= value <= dims[1]:
                self.report("ST-INDEX", f"constant array index {value} is outside {array}", index)

    def _unary(self, node: ast.Unary) -> Type:
        operand = self.typed(node.operand)
        if operand is ERROR:
            return ERROR
        if node.op == "NOT":
            if t.in_family(operand, "ANY_BIT"):
                return t.BOOL if isinstance(operand, t.UntypedInt) and operand.value in (0, 1) else operand
            self.report("ST-TYPE-MISMATCH", f"NOT needs BOOL or a bit string (ANY_BIT), not {operand}", node)
            return ERROR
        if isinstance(operand, t.UNTYPED):
            return type(operand)(-operand.value if operand.value is not None else None)
        if t.in_family(operand, "ANY_NUM") or t.category(operand) == "time":
            return operand
        if t.category(operand) == "bits" and t.codesys_typing():  # the unsigned number it holds, negated (registers.py)
            return operand
        self.report("ST-TYPE-MISMATCH", f"unary '-' needs a number or TIME, not {operand}", node)
        return ERROR

    def _binary(self, node: ast.Binary) -> Type:
        left = self.typed(node.left)
        right = self.typed(node.right)
        if left is ERROR or right is ERROR:
            return ERROR
        op = node.op
        if op == "**":
            return self._power(node, left, right)
        if op in _SHORT_CIRCUIT:
            return self._short_circuit(node, left, right)
        time_result = time_rule(op, left, right)
        if time_result:
            return time_result
        if op in ("*", "/") and t.category(left) == "time" and t.in_family(right, "ANY_NUM"):
            return left  # ST-21: TIME * ANY_NUM, TIME / ANY_NUM (the number keeps its own type); LTIME alike
        if op == "*" and t.category(right) == "time" and t.in_family(left, "ANY_NUM"):
            return right
        if op in ("+", "-") and isinstance(left, t.PointerType) and t.moves_a_pointer(right):
            return left  # pointer arithmetic in bytes (TYP-43; CODESYS: also by a bit string)
        if op in ("=", "<>") and reference_comparison(left, right):
            return t.BOOL
        if op in _COMPARISON and (t.holds_address(left, right) or t.holds_address(right, left)):
            return t.BOOL  # CODESYS typing: the pointer's address compared with the number
        if op == "+" and isinstance(left, t.StringType) and isinstance(right, t.StringType):
            return left  # FUN-82 (Mosaic): '+' concatenates
        combined, verdict = t.common(left, right)
        if isinstance(combined, t.UNTYPED):
            combined = untyped_result(op, left, right) if op not in _COMPARISON else combined
        if verdict == "error":
            self.report("ST-TYPE-MISMATCH", _mixed_operands(op, left, right), node)
            return ERROR
        if verdict == "widen":
            self.report(
                "ST-IMPLICIT-CONV",
                f"{left} and {right} are mixed in '{op}': the narrower one is converted implicitly",
                node,
                severity="warning",
            )
        return self._operator_result(node, combined)

    def _short_circuit(self, node: ast.Binary, left: Type, right: Type) -> Type:
        """AND_THEN / OR_ELSE take BOOL operands only (CODESYS), and give a BOOL."""
        for side, operand in ((left, node.left), (right, node.right)):
            if side != t.BOOL:
                self.report("ST-TYPE-MISMATCH", f"{node.op} needs BOOL operands, not {side}", operand)
                return ERROR
        return t.BOOL

    def _operator_result(self, node: ast.Binary, combined: Type) -> Type:
        op = node.op
        if op in _COMPARISON:
            if isinstance(combined, t.EnumType) and op not in ("=", "<>"):
                self.report("ST-TYPE-MISMATCH", "enumeration values can only be compared with = and <>", node)
            elif isinstance(combined, (t.ArrayType, t.StructType, t.FbType)):
                self.report("ST-TYPE-MISMATCH", f"cannot compare values of type {combined}", node)
            operands = t.concrete(combined) if not isinstance(combined, t.UNTYPED) else None
            if operands is None:  # two literal expressions: the smallest type that fits both
                operands = default_type(untyped_leaves(node.left) + untyped_leaves(node.right))
            self.settle(node.left, operands)
            self.settle(node.right, operands)
            return t.BOOL
        if op in _LOGIC:
            if t.in_family(combined, "ANY_BIT"):
                return combined
            self.report("ST-TYPE-MISMATCH", f"{op} needs BOOL or bit strings (ANY_BIT), not {combined}", node)
            return ERROR
        if t.codesys_typing() and t.category(combined) == "bits":
            return combined  # CODESYS: arithmetic on a bit string, as the unsigned integer of its width
        if op == "MOD":
            if t.in_family(combined, "ANY_INT"):
                return combined
            self.report("ST-TYPE-MISMATCH", f"MOD needs integers (ANY_INT), not {combined}", node)
            return ERROR
        if t.in_family(combined, "ANY_NUM"):
            return combined
        self.report("ST-TYPE-MISMATCH", f"'{op}' needs numbers (ANY_NUM), not {combined}", node)
        return ERROR

    def _power(self, node: ast.Binary, left: Type, right: Type) -> Type:
        if isinstance(left, t.UntypedInt):
            left = t.UntypedReal(left.value)  # FUN-33: an untyped integer base is promoted
        if t.real_from_integer(left):
            self.report(
                "ST-IMPLICIT-CONV",
                f"'**' computes in LREAL (CODESYS typing): its {left} base is converted implicitly",
                node.left,
                severity="warning",
            )
            left = t.LREAL
        if not t.in_family(left, "ANY_REAL"):
            self.report(
                "ST-TYPE-MISMATCH",
                f"the base of '**' must be REAL or LREAL, not {left}; convert it (e.g. {left}_TO_REAL)",
                node.left,
            )
            return ERROR
        if not t.in_family(right, "ANY_NUM"):
            self.report("ST-TYPE-MISMATCH", f"the exponent of '**' must be a number, not {right}", node.right)
        return left

    # ------------------------------------------------------------ calls
    def call(self, node: ast.Call, statement: bool) -> Type:
        return check_call(self, node, statement)

    # ------------------------------------------------------------ statements
    def statements(self, body: list[ast.Stmt]) -> None:
        if any(isinstance(s, ast.CallStmt) and isinstance(s.call, ast.Call) and s.call.args for s in body):
            body[:] = self._with_action_inputs(body)
        for stmt in body:
            self.statement(stmt)

    def _with_action_inputs(self, body: list[ast.Stmt]) -> list[ast.Stmt]:
        """``Inst.Reset(In := FALSE);`` calls an ACTION: the instance's inputs are assigned first (methods.py)."""
        from .methods import action_inputs  # methods imports this module

        silent = BodyChecker(self.result, self.pou, lambda *args, **kwargs: None)
        out: list[ast.Stmt] = []
        for stmt in body:
            if isinstance(stmt, ast.CallStmt) and isinstance(stmt.call, ast.Call):
                out += action_inputs(silent, stmt.call)
            out.append(stmt)
        return out

    def _names_program(self, node: ast.Expr) -> bool:
        """Whether ``node`` is a bare name that means a PROGRAM POU (no variable of that name hides it)."""
        if not isinstance(node, ast.Name):
            return False
        program = self.result.pous.get(node.name.upper())
        return program is not None and program.kind == "PROGRAM" and self.lookup(node.name) is None

    def statement(self, stmt: ast.Stmt) -> None:
        if isinstance(stmt, ast.Assign):
            self.assign(stmt)
        elif isinstance(stmt, ast.RefAssign):
            self.ref_assign(stmt)
        elif isinstance(stmt, ast.CallStmt):
            if self._names_program(stmt.call):  # ``PRGexample2;`` calls the program (seed 003, CODESYS)
                stmt.call = ast.Call(stmt.call, [], stmt.call.span)
            if isinstance(stmt.call, ast.Call):
                stmt.call.ty = self.call(stmt.call, statement=True)  # its generic arguments settle by it (below)
                ref = stmt.call.ref
                if isinstance(ref, Symbol) and ref.implicit is not None:
                    self.report(
                        "ST-NOT-CALLABLE", f"'{ref.name}' is a {ref.implicit} of the SFC: the chart runs it", stmt
                    )
                self.settle(stmt.call, None)
            else:
                self.expr(stmt.call)
                self.report(
                    "ST-NO-EFFECT", "this statement does nothing: expected an assignment ':=' or a call '(...)'", stmt
                )
        elif isinstance(stmt, ast.If):
            for cond, body in stmt.branches:
                self.condition(cond, "IF")
                self.statements(body)
            self.statements(stmt.else_body or [])
        elif isinstance(stmt, ast.Case):
            check_case(self, stmt)
        elif isinstance(stmt, ast.For):
            self.for_loop(stmt)
        elif isinstance(stmt, ast.While):
            self.condition(stmt.cond, "WHILE")
            self.loop(stmt.body)
        elif isinstance(stmt, ast.Repeat):
            self.loop(stmt.body)
            self.condition(stmt.until, "UNTIL")
        elif isinstance(stmt, ast.Exit) and self.loop_depth == 0:
            self.report("ST-EXIT-OUTSIDE-LOOP", "EXIT is only allowed inside FOR, WHILE or REPEAT", stmt)
        elif isinstance(stmt, ast.Continue) and self.loop_depth == 0:
            self.report("ST-EXIT-OUTSIDE-LOOP", "CONTINUE is only allowed inside FOR, WHILE or REPEAT", stmt)

    def loop(self, body: list[ast.Stmt]) -> None:
        self.loop_depth += 1
        self.statements(body)
        self.loop_depth -= 1

    def condition(self, cond: ast.Expr, keyword: str) -> None:
        ty = self.expr(cond, t.BOOL)
        if ty is not ERROR and not t.same(ty, t.BOOL):
            self.report("ST-TYPE-MISMATCH", f"the {keyword} condition must be BOOL, not {ty}", cond)

    def assign(self, stmt: ast.Assign) -> None:
        if stmt.attempt:
            check_attempt(self, stmt)
            return
        target = self.target(stmt.target)
        value = self.expr(stmt.value, target)
        assignable_or_report(self, target, value, stmt.value, "assign")

    def ref_assign(self, stmt: ast.RefAssign) -> None:
        """``r REF= x`` (CODESYS): r, a REFERENCE TO T, refers to the variable x of type T from now on."""
        target = self.reference(stmt.target)
        value = self.expr(stmt.value)
        if target is ERROR or value is ERROR:
            return
        if not (isinstance(target, t.PointerType) and target.implicit):
            self.report("ST-TYPE-MISMATCH", f"REF= binds a REFERENCE TO variable, not {target}", stmt.target)
        elif not isinstance(stmt.value, (ast.Name, ast.Member, ast.Index, ast.Deref)):
            self.report(
                "ST-NOT-LVALUE", "REF= needs a variable on its right: the one the reference will refer to", stmt.value
            )
        elif not t.same(target.target, value) and not t.derived(target.target, value):
            self.report("ST-TYPE-MISMATCH", f"a {target} cannot refer to a {value}", stmt.value)
        else:
            problem = unreferable(self, stmt.value)
            if problem is not None:
                self.report("ST-REF", f"REF= cannot refer to {problem}", stmt.value)

    def target(self, node: ast.Expr) -> Type:
        """Type an assignment target and check it may be written (ST-20, POU-23, VAR-21, ST-73)."""
        if not isinstance(node, (ast.Name, ast.Member, ast.Index, ast.Deref, ast.DirectAddr)):
            self.expr(node)
            self.report(
                "ST-NOT-LVALUE", "only a variable, array element, field or pointer target can be assigned", node
            )
            return ERROR
        ty = self.expr(node)
        if isinstance(getattr(node, "ref", None), PropertyRef) and node.ref.setter is None:
            self.report("ST-READONLY", f"the property {node.ref.name} has no SET: it can be read, not assigned", node)
        root = root_name(node)
        if root is not None and root.ref is self.pou and self.pou is not None:  # F := ..., F[2] := ..., F.a := ...
            self.result_assigned = True
        symbol = root.ref if root is not None else None
        read_only = _implicit_in(node)
        if read_only is not None:
            self.report(
                "ST-READONLY",
                f"'{read_only.name}' is a{'n' if read_only.implicit == 'action' else ''} {read_only.implicit} of the "
                "SFC: the chart sets it, a program can only read it",
                node,
            )
        if isinstance(symbol, Symbol):
            if symbol.constant:
                self.report("ST-CONST-WRITE", f"'{symbol.name}' is a CONSTANT and cannot be assigned", node)
            if symbol in self.loop_vars and node is root:
                self.report(
                    "ST-LOOP-VAR",
                    f"'{symbol.name}' is the FOR loop variable: it must not be changed inside the loop",
                    node,
                )
            if symbol.var_class == "VAR_INPUT" and node is root and self.pou is not None and not root.deref:
                self.report(
                    "ST-INPUT-WRITE",
                    f"'{symbol.name}' is an input of {self.pou.name}: assigning it overwrites the caller's value",
                    node,
                    severity="warning",
                )
        elif root is not None and isinstance(root.ref, EnumValue):
            self.report("ST-NOT-LVALUE", f"'{root.name}' is an enumeration value and cannot be assigned", node)
        if isinstance(node, ast.Member) and isinstance(node.base.ty, t.FbType) and _is_output(node):
            self.report(
                "ST-READONLY",
                f"'{node.name}' is an output of {node.base.ty.name}: it can be read but not assigned from outside",
                node,
            )
        return ty

    def for_loop(self, stmt: ast.For) -> None:
        var_type = self.expr(stmt.var)
        if var_type is not ERROR and not t.in_family(var_type, "ANY_INT"):
            self.report("ST-LOOP-VAR", f"the FOR variable must be an integer (ANY_INT), not {var_type}", stmt.var)
        for part in (stmt.start, stmt.end, stmt.step):
            if part is not None:
                assignable_or_report(self, var_type, self.expr(part, var_type), part, "FOR bound or step")
        if stmt.step is not None and constant_value(self, stmt.step) == 0:
            self.report("ST-LOOP-VAR", "the FOR step is 0: the loop would never end", stmt.step)
        symbol = stmt.var.ref if isinstance(stmt.var.ref, Symbol) else None
        if symbol is not None:
            self.loop_vars.append(symbol)
        self.loop(stmt.body)
        if symbol is not None:
            self.loop_vars.pop()


# How each kind of expression node is typed (a table: expressions are typed by the hundred thousand in large
# diagrams); methods are looked up on the checker, so subclasses may override them.
_EXPRESSION_CHECKS: dict[type, Callable[[BodyChecker, Any, Type | None], Type]] = {
    ast.IntLit: lambda checker, node, expected: t.UntypedInt(node.value),
    ast.RealLit: lambda checker, node, expected: t.UntypedReal(node.value),
    ast.BoolLit: lambda checker, node, expected: t.BOOL,
    ast.StringLit: lambda checker, node, expected: checker._string_literal(node),
    ast.TimeLit: lambda checker, node, expected: t.Elementary(node.kind),
    ast.TypedLit: lambda checker, node, expected: checker._typed_literal(node),
    ast.Name: lambda checker, node, expected: checker._name(node, expected),
    ast.DirectAddr: lambda checker, node, expected: checker._direct(node),
    ast.Member: lambda checker, node, expected: checker._member(node),
    ast.Index: lambda checker, node, expected: checker._index(node),
    ast.Deref: lambda checker, node, expected: checker._deref(node),
    ast.Call: lambda checker, node, expected: checker.call(node, statement=False),
    ast.Unary: lambda checker, node, expected: checker._unary(node),
    ast.Binary: lambda checker, node, expected: checker._binary(node),
}


#: Implicit SFC variables other POUs may read (``sfc1.step1.X``); named transitions stay internal.
SFC_PUBLIC = ("step", "action")


def _sfc_state(symbol: Symbol) -> bool:
    """A step or action of an SFC, implicit or (in its ST export) declared as an SFC_STEP / ACTION_CONTROL: other
    POUs may read it."""
    if symbol.implicit in SFC_PUBLIC:
        return True
    ty = symbol.type
    return isinstance(ty, t.FbType) and ty.std is not None and ty.std.name in ("SFC_STEP", "ACTION_CONTROL")


def _implicit_in(node: ast.Expr) -> Symbol | None:
    """The implicit SFC variable (step, action) an assignment target writes into, if any: the root or a member."""
    while isinstance(node, (ast.Member, ast.Index, ast.Deref)):
        ref = getattr(node, "ref", None)
        if isinstance(ref, Symbol) and ref.implicit in SFC_PUBLIC:
            return ref
        node = node.base
    ref = getattr(node, "ref", None)
    return ref if isinstance(ref, Symbol) and ref.implicit in SFC_PUBLIC else None


def _result_name(pou: PouInfo) -> str:
    """The name a function's (or a method's) body assigns its result to."""
    return (pou.method.name if pou.method is not None else pou.name).upper()


def _is_output(node: ast.Member) -> bool:
    ref = node.ref
    if isinstance(ref, Symbol):
        return ref.var_class == "VAR_OUTPUT"
    return isinstance(ref, stdlib.Pin) and any(p is ref for p in node.base.ty.std.outputs)


def _enums_in(ty: Type):
    if isinstance(ty, t.EnumType):
        yield ty
    elif isinstance(ty, t.StructType):
        for _, field_type in ty.fields.values():
            yield from _enums_in(field_type)


def _mixed_operands(op: str, left: Type, right: Type) -> str:
    """What ST-TYPE-MISMATCH says of two operands of different types: a conversion to write, or, for a pointer
    compared with 0 under IEC typing, that its "no variable" is NULL."""
    if t.zero_for_null(left, right) or t.zero_for_null(right, left):
        first, second = ("0" if isinstance(side, t.UntypedInt) else str(side) for side in (left, right))
        return f"'{op}' needs operands of the same type: {first} and {second}: {t.NULL_NOT_ZERO}"
    return (
        f"'{op}' needs operands of the same type: {left} and {right}; convert one of them (e.g. {_hint(left, right)})"
    )


def _hint(left: Type, right: Type) -> str:
    if not (isinstance(left, t.Elementary) and isinstance(right, t.Elementary)):
        return "a *_TO_* conversion"
    if left.name in LONG_TIME_TYPES and right.category == "time":  # LTOD + TIME: the duration becomes an LTIME
        return f"{right.name}_TO_LTIME"
    if right.name in LONG_TIME_TYPES and left.category == "time":
        return f"{left.name}_TO_LTIME"
    return f"{right.name}_TO_{left.name}"
