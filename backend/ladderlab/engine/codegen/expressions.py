"""IR expressions -> Python expression source.

Every emitted expression yields a value already stored in its IR type, so
statements copy it without further work. Operators and standard functions
go through the runtime library: its inline template when it has one (each
argument evaluated once, in order), else a specialised callable bound as a
module global. Every operand is evaluated, left to right (ST-06 [REC]).
"""

from __future__ import annotations

import math
import re
from functools import cache, lru_cache

from ...iec import values
from ...ir import nodes as ir
from ...ir import types as t
from ...ir.byte_layout import byte_layout, in_out_view
from ...ir.lower_types import byte_size
from ...ir.types import describe
from ..stdlib import specialised
from . import names
from .context import CodegenError, std_fb_class, std_pin_type
from .mentions import calls_in, var_text
from .scope import Scope
from .source import Source
from .typeinfo import is_composite, runtime_name, store_code, store_value, store_whole

_OPERATOR_FUNCTIONS = {
    op: op for op in ("ADD", "SUB", "MUL", "DIV", "MOD", "EXPT", "AND", "OR", "XOR", "EQ", "NE", "LT", "LE", "GT", "GE")
}
_ATOM = re.compile(r"(?:[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*|\d+)\Z")
_COMPARISONS = frozenset({"EQ", "NE", "LT", "LE", "GT", "GE"})
_SHORT_CIRCUIT = {"AND_THEN": "and", "OR_ELSE": "or"}
_ORDERINGS = {"LT": "<", "LE": "<=", "GT": ">", "GE": ">="}
#: BOOL AND / OR whose right operand is a plain read (below): Python's ``and`` / ``or`` skip the read when the left
#: operand decides, which changes nothing (the read has no effect and cannot fault) and halves an LD series's cost.
_BOOL_LOGIC = {"AND": "and", "OR": "or"}


def _atom(code: str) -> bool:
    """A name, attribute or non-negative number (needs no parentheses); most expressions fail the first test."""
    return " " not in code and "(" not in code and _ATOM.match(code) is not None


#: The variable an ``ADR(x...)`` / ``REF(x...)`` text starts from.
_WRITTEN_ROOT = re.compile(r"\w+\(\s*([A-Za-z_]\w*)")


def _holds_instances(ty: t.IrType) -> bool:
    """An FB or program instance, or an array of them: no byte layout, its members are variables of their own."""
    while isinstance(ty, t.Array):
        ty = ty.element
    return isinstance(ty, t.FbInstance)


def _plain_read(e: ir.Expr, code: str) -> bool:
    """Whether ``e`` (emitted as ``code``) is a BOOL constant, a BOOL variable read as a plain name or attribute
    chain, or NOT of one: evaluating it has no effect and cannot fault, so it may be skipped. Indexed, dereferenced
    and VAR_IN_OUT reads are not atoms and stay evaluated."""
    if isinstance(e, ir.Unary) and e.op == "NOT":
        return code.startswith("(not ") and code.endswith(")") and _plain_read(e.operand, code[5:-1])
    return isinstance(e, (ir.Var, ir.Const)) and e.type == t.BOOL and _atom(code)


def literal(value: object) -> str:
    """Python source for a stored constant: ``repr``, with non-finite floats by name, negatives in parentheses."""
    if isinstance(value, (bool, str)):
        return repr(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "ll_nan"
        if math.isinf(value):
            return "ll_inf" if value > 0 else "(-ll_inf)"
        return f"({value!r})" if math.copysign(1.0, value) < 0 else repr(value)
    if isinstance(value, int):
        return f"({value!r})" if value < 0 else repr(value)
    raise CodegenError(f"constant {value!r} of unsupported kind")


#: IR levels emitted as one Python expression. CPython's tokenizer allows 200 nested parentheses and each
#: level takes one to three, so a deeper expression is emitted one operation per line (``linear``).
NESTED_LEVELS = 40


class _TooDeep(Exception):
    """An expression nests deeper than NESTED_LEVELS: it is emitted again, linearly."""


class Expressions:
    def __init__(self, scope: Scope) -> None:
        self.scope = scope
        self.module = scope.module
        self.depth = 0
        self.linear = False
        #: Where the lines computing a deep expression's parts go (just before the statement that uses it);
        #: None where no line may go (a condition the statement re-evaluates: see Statements).
        self.sink: Source | None = None
        #: (code, local): an FB instance's code and the local that holds it right after its call (``ll_fb``), read
        #: through the local while the statements after the call are assignments (Statements sets and clears it)
        self.alias: tuple[str, str] | None = None
        #: variable code -> the temporary local it was just assigned from: a read takes the local (Statements.store)
        self.forward: dict[str, str] = {}

    # ------------------------------------------------------------------ dispatch

    def expr(self, e: ir.Expr) -> str:
        """Python source of ``e``. Deeper than NESTED_LEVELS, every operation is computed into a temporary on
        a line of its own first, in the order the nested expression would evaluate them (operands left to
        right, an operation after its operands), so the values and faults are the same."""
        if self.depth or self.linear:
            return self._expr(e)
        try:
            return self._expr(e)
        except _TooDeep:
            if self.sink is None:
                raise CodegenError("this expression nests too deeply to be evaluated here") from None
            self.depth, self.linear = 0, True
            try:
                return self._expr(e)
            finally:
                self.linear = False

    def _expr(self, e: ir.Expr) -> str:
        handler = _HANDLERS.get(type(e))
        if handler is None:
            raise CodegenError(f"unknown expression {type(e).__name__}")
        self.depth += 1
        try:
            if self.depth > NESTED_LEVELS and not self.linear:
                raise _TooDeep
            code = handler(self, e)
        finally:
            self.depth -= 1
        if self.linear and not isinstance(e, ir.Const):  # variables too: a later call may change them
            temp = self.scope.temp("e")
            self.sink.line(f"{temp} = {code}")  # type: ignore[union-attr]  # expr() sets it before linear mode
            return temp
        return code

    def const(self, c: ir.Const) -> str:
        if isinstance(c.type, t.Reference):
            if c.value is not None:
                raise CodegenError(f"a constant reference {c.value!r}")
            return "None"  # NULL
        return literal(self.const_value(c))

    @staticmethod
    def const_value(c: ir.Const) -> object:
        """The engine value of a constant, stored in its type."""
        if is_composite(c.type):
            raise CodegenError(f"a constant of type {describe(c.type)} is not supported")
        try:
            return store_value(c.value, c.type)
        except ValueError as error:
            raise CodegenError(f"constant: {error}") from None

    def unary(self, u: ir.Unary) -> str:
        operand = self.expr(u.operand)
        name = self.scalar(u.operand.type, u.op)
        if u.op == "NOT":
            return self.standard("NOT", [operand], (name,), None)
        if values.resolve(name).category in ("int", "bits", "time"):
            return f"({values.wrap_expr(f'-{operand}', name)})"
        if values.resolve(name).category == "real":
            return f"(-{operand})"  # negating a float32 value is exact
        raise CodegenError(f"NEG is not defined for {name}")

    def binary(self, b: ir.Binary) -> str:
        if b.op in _SHORT_CIRCUIT:
            return self.short_circuit(b)
        left, right = self.expr(b.left), self.expr(b.right)
        if isinstance(b.type, t.Reference):  # p + n, p - n: bytes along the array p points into (runtime.pointer_add)
            offset = right if b.op == "ADD" else f"-({right})"
            what = f"the pointer {var_text(b.left)}" if isinstance(b.left, ir.Var) else "the pointer"
            spec = byte_layout(b.type.target)
            layout = spec if isinstance(spec, tuple) else None  # none to see: whole elements only
            return f"ll_ptr_add({left}, {offset}, {byte_size(b.type.target)}, {what!r}, {layout!r})"
        if isinstance(b.left.type, t.Reference) and b.op in ("EQ", "NE"):  # one variable (byte: addresses.py), NULL
            return f"({'' if b.op == 'EQ' else 'not '}ll_addr.same({left}, {right}))"
        if isinstance(b.left.type, t.Reference):  # LT ...: the bytes two pointers into one variable point to
            sizes = f"{byte_size(b.left.type.target)}, {byte_size(b.right.type.target)}"  # type: ignore[union-attr]  # both pointers (checker)
            return f"ll_addr.order({left}, {right}, {sizes}, {_ORDERINGS[b.op]!r})"
        if b.op in _BOOL_LOGIC and b.type == t.BOOL and _plain_read(b.right, right):
            # ``x AND x`` is x: an LD contact on the coil just set (``C`` read through the local it was set from)
            return left if left == right else f"({left} {_BOOL_LOGIC[b.op]} {right})"
        types = (self.scalar(b.left.type, b.op), self.scalar(b.right.type, b.op))
        result = None if b.op in _COMPARISONS else self.scalar(b.type, b.op)
        return self.standard(_OPERATOR_FUNCTIONS[b.op], [left, right], types, result)

    def short_circuit(self, b: ir.Binary) -> str:
        """AND_THEN / OR_ELSE: Python's ``and`` / ``or`` evaluate the right operand only when the left does not
        decide. A part of it computed on a line of its own (a very deep expression) would run regardless."""
        left = self.expr(b.left)
        if self.linear:
            raise CodegenError(f"{b.op} nests too deeply: split the expression with a variable")
        return f"({left} {_SHORT_CIRCUIT[b.op]} {self.expr(b.right)})"

    def call(self, c: ir.Call) -> str:
        if c.user:
            return self.user_call(c)
        args = [self.expr(a) for a in c.args]
        types = tuple([self.scalar(ty, c.function) for ty in c.arg_types])
        return self.standard(c.function, args, types, runtime_name(c.type))

    def address_of(self, a: ir.AddressOf) -> str:
        """``REF(x)``: a ``runtime.Ref`` to the variable's ``(container, key)``; a ``FrameRef`` to a variable of
        this call that has a frame (a FUNCTION's own, a VAR_TEMP), which dangles once the call returned. Of a
        variable reached through a pointer or a VAR_IN_OUT, ``ll_io_ref`` gives the frame of the call whose
        variable that is, if any (runtime.in_out_ref)."""
        var, ref = a.var, self.ref(a.var)
        derefs = [n for n, selector in enumerate(var.path) if isinstance(selector, ir.Deref)]
        if derefs and not calls_in(var):  # (the pointer's pair is read again: no call in the path)
            pointer = self.ref(ir.Var(var.scope, var.name, var.type, var.path[: derefs[-1] + 1]))
            return f"ll_io_ref({pointer}, *{ref}, {a.text!r})"
        framed = var.scope == "local" and var.name.upper() in self.scope.framed
        slot = self.scope.slots.get(var.name.upper()) if var.scope == "local" else None
        if slot is not None and slot.var_class == "VAR_IN_OUT":
            return f"ll_io_ref(r_{names.escape(slot.name)}, *{ref}, {a.text!r})"
        code = f"ll_FrameRef(*{ref}, {a.text!r}, ll_fr)" if framed else f"ll_Ref(*{ref}, {a.text!r})"
        written = _WRITTEN_ROOT.match(a.text)  # the root as written (``buf``; the IR's is ``BUF``)
        return self.telling_outer(code, var, framed, written.group(1) if written else None)

    def telling_outer(self, code: str, var: ir.Var, framed: bool, written: str | None) -> str:
        """``code`` (a reference to ``var``, or its pair), under CODESYS typing telling the engine the outermost
        variable ``var`` is part of (engine/codegen/addresses.py), named as ``written`` (its root as written; None:
        not written, the IR's name until an ADR() names it). Not of a variable reached through a pointer or a
        VAR_IN_OUT, whose outermost variable is the one the caller told of, if any."""
        if not self.module.program.addresses or any(isinstance(selector, ir.Deref) for selector in var.path):
            return code
        slot = self.scope.slots.get(var.name.upper()) if var.scope == "local" else None
        if slot is not None and slot.var_class == "VAR_IN_OUT":
            return code
        outer = self.outer_variable(var)
        if outer is None:
            return code
        spec = byte_layout(outer[1])  # its layout, or why it has none (its parts then have no exact address)
        name = (written or var.name) + var_text(outer[0])[len(var.name) :]
        frame = "ll_fr" if framed else "None"
        return f"ll_addr.part({code}, {self.ref(outer[0])}, {spec!r}, {name!r}, {frame}, {written is not None})"

    def outer_variable(self, var: ir.Var) -> tuple[ir.Var, t.IrType] | None:
        """The outermost variable ``var`` is part of that has a byte layout or would have one (a program's, an FB
        instance's, a FUNCTION's, a global: every variable but one inside a STRUCT or an array), and its type; None
        when a call in the path would run again to reach it."""
        _, ty = self.scope.root(var)
        depth = 0
        while depth < len(var.path) and _holds_instances(ty):
            _, ty = self.select("x", ty, var.path[depth])  # type: ignore[arg-type]  # no Deref (telling_outer)
            depth += 1
        outer = ir.Var(var.scope, var.name, ty, var.path[:depth])
        return None if calls_in(outer) else (outer, ty)

    def in_out_argument(self, v: ir.Var, parameter: t.IrType) -> str:
        """``ref(v)`` passed to a VAR_IN_OUT of type ``parameter``; a variable of this call that has a frame passes it
        along (``runtime.FramedPair``), so a REF() the callee takes of its in-out dies with this call. A subrange
        passed for its base (or the other way round) is passed as a view's ``(view, "v")`` that keeps the variable
        in its range, as a pointer of the base type does (engine/codegen/views.py)."""
        code = self.ref(v)
        own = v.scope == "local" and not any(isinstance(selector, ir.Deref) for selector in v.path)
        framed = own and v.name.upper() in self.scope.framed
        specs = in_out_view(v.type, parameter)
        if isinstance(specs, str):
            raise CodegenError(specs)
        if specs is not None:
            text = f"the VAR_IN_OUT argument {var_text(v)}"
            ref = f"ll_FrameRef(*{code}, {text!r}, ll_fr)" if framed else f"ll_Ref(*{code}, {text!r})"
            code = f"ll_seen({ref}, {specs[0]!r}, {specs[1]!r}).pair"
        elif framed:
            code = f"ll_Pair(*{code}, ll_fr)"
        if not self.module.in_outs_addressed or (self._call_local(v) and not framed):
            return code  # no ADR() of a VAR_IN_OUT to tell; a variable of this call dies with it untold of
        return self.telling_outer(code, v, framed, None)

    def _call_local(self, v: ir.Var) -> bool:
        """A variable of this call: a FUNCTION's own, a VAR_TEMP."""
        if v.scope != "local":
            return False
        slot = self.scope.slots.get(v.name.upper())
        return self.scope.function or (slot is not None and slot.var_class == "VAR_TEMP")

    def view(self, v: ir.View) -> str:
        """A pointer seeing its target's bytes as another type (engine/codegen/views.py)."""
        return f"ll_seen({self.expr(v.value)}, {v.whole!r}, {v.seen!r})"

    def attempt(self, a: ir.Attempt) -> str:
        """``?=``: the reference when its instance's class is one of the FBs implementing the interface, else NULL."""
        classes = "".join(f"{names.pou_class(fb)}, " for fb in a.blocks)
        return f"ll_attempt({self.expr(a.value)}, ({classes}))"

    def convert(self, c: ir.Convert) -> str:
        operand = self.expr(c.operand)
        if isinstance(c.source, t.Reference):  # ``dw := pt`` (CODESYS typing): its synthetic address (addresses.py)
            number = f"ll_addr.address({operand}, {byte_layout(c.source.target)!r})"
            return self.standard(f"ULINT_TO_{self.scalar(c.type, 'conversion')}", [number], ("ULINT",), None)
        if isinstance(c.type, t.Reference):  # ``pt := dw``: the variable that number lies in, or none
            return f"ll_addr.pointer({operand}, {byte_layout(c.type.target)!r})"
        source, target = self.scalar(c.source, "conversion"), self.scalar(c.type, "conversion")
        src, dst = values.resolve(source).name, values.resolve(target).name
        if src == dst:  # subrange <-> base, enum <-> DINT, STRING[n] <-> STRING[m]
            return store_code(operand, c.source, c.type, checked=isinstance(c.operand, ir.Var))
        converted = self.standard(f"{src}_TO_{dst}", [operand], (source,), target)
        if isinstance(c.type, t.Subrange):
            return f"ll_sub({converted}, {c.type.low!r}, {c.type.high!r})"
        return converted

    def fit(self, f: ir.Fit) -> str:
        """A register value checked to lie in its operation's own type (CODESYS typing, st/registers.py)."""
        name = self.scalar(f.type, "a register check")
        low, high = values.value_range(name)  # type: ignore[misc]  # an integer or bit-string type (st/registers.py)
        return f"ll_fit({self.expr(f.operand)}, {low!r}, {high!r}, {f.text!r}, {name!r})"

    # ------------------------------------------------------------------ calls

    def standard(self, name: str, args: list[str], types: tuple[str, ...], result: str | None) -> str:
        """A standard function call: inline template or bound specialised callable."""
        try:
            built = specialised(name, types, result)
        except (ValueError, TypeError) as error:
            raise CodegenError(f"{name}({', '.join(types)}): {error}") from None
        if built.template is not None:
            template = _unparenthesised(built.template, tuple([_atom(arg) for arg in args]))
            text = template.format(*args)
            return text if template == "({0})" or _atom(text) else f"({text})"
        fn = self.module.bind(("fast", name.upper(), types, result), f"fn_{names.escape(name)}", lambda: built.fast)
        return f"{fn}({', '.join(args)})"

    def checked(self, name: str, types: tuple[str, ...], result: str | None) -> str:
        """The bound checked form of a standard function (returns value, warning) for ENO."""
        try:
            built = specialised(name, types, result)
        except (ValueError, TypeError) as error:
            raise CodegenError(f"{name}({', '.join(types)}): {error}") from None
        return self.module.bind(
            ("checked", name.upper(), types, result), f"fn_{names.escape(name)}_eno", lambda: built.checked
        )

    def wrapped(self, name: str, types: tuple[str, ...], result: str | None) -> tuple[str, str] | None:
        """The checked form of a standard function as templates (exact value, its store), when its only warning
        is a wrap (stdlib ``Specialised.wrapped``); None: call ``checked``."""
        try:
            return specialised(name, types, result).wrapped
        except (ValueError, TypeError):
            return None

    def user_call(self, c: ir.Call) -> str:
        callee = self.module.pous.get(c.function.upper())
        if callee is None or callee.kind != "function":
            raise CodegenError(f"{c.function} is not a user function")
        inputs = [s for s in callee.slots if s.var_class == "VAR_INPUT"]
        in_outs = [s for s in callee.slots if s.var_class == "VAR_IN_OUT"]
        if len(c.args) != len(inputs) or len(c.in_outs) != len(in_outs):
            raise CodegenError(
                f"{callee.name} takes {len(inputs)} inputs and {len(in_outs)} in-outs, "
                f"the call passes {len(c.args)} and {len(c.in_outs)}"
            )
        args = [self.value_for(a, slot.type) for a, slot in zip(c.args, inputs)]
        args += [self.in_out_argument(v, slot.type) for v, slot in zip(c.in_outs, in_outs)]
        if c.virtual and c.function.upper() in self.module.program.dispatch:  # a method: by its instance's FB
            call = f"ll_virtual({names.dispatch_table(callee.name)}, {len(inputs)}, {', '.join(args)})"
        else:
            call = f"{names.function(callee.name)}({', '.join(args)})"
        return f"(yield from {call})" if self.module.debug else call

    def value_for(self, e: ir.Expr, target: t.IrType) -> str:
        """``e`` as a value to store in a variable of type ``target`` (a private copy for composites)."""
        if is_composite(target):
            if isinstance(target, t.FbInstance):
                raise CodegenError("an FB instance cannot be passed by value")
            return f"ll_copy({store_whole(self.expr(e), e.type, target)})"
        return self.stored(e, target)

    def stored(self, e: ir.Expr, target: t.IrType) -> str:
        """``e`` stored into a scalar of type ``target`` (wrapped, cut or range-checked as needed)."""
        return store_code(self.expr(e), e.type, target, checked=isinstance(e, (ir.Var, ir.Const)))

    # ------------------------------------------------------------------ variables

    def var(self, v: ir.Var) -> str:
        return self.access(v)[0] if v.path else self.scope.root(v)[0]

    def read(self, v: ir.Var) -> str:
        """``var`` as read in an expression: the local a variable was just assigned from, if any (``forward``)."""
        code = self.var(v)
        return self.forward.get(code, code) if self.forward else code

    def access(self, v: ir.Var) -> tuple[str, t.IrType]:
        """Source of the variable ``v`` (readable and assignable) and its declared type."""
        code, ty = self.scope.root(v)
        for number, selector in enumerate(v.path):
            if self.alias is not None and code == self.alias[0]:
                code = self.alias[1]
            if isinstance(selector, ir.Deref):
                if not isinstance(ty, t.Reference):
                    raise CodegenError(f"'^' on {values.article(describe(ty))}")
                code, ty = f"{_dereferenced(code, ir.Var(v.scope, v.name, ty, v.path[:number]))}.v", ty.target
            else:
                code, ty = self.select(code, ty, selector)
        return code, ty

    def ref(self, v: ir.Var) -> str:
        """Source of a ``(container, key)`` reference to the variable ``v`` (VAR_IN_OUT argument)."""
        if not v.path:
            return self.scope.root_ref(v)
        code, ty = self.access(ir.Var(v.scope, v.name, v.type, v.path[:-1]))
        last = v.path[-1]
        if isinstance(last, ir.Deref):  # the variable the reference refers to: its own (container, key)
            return f"{_dereferenced(code, ir.Var(v.scope, v.name, ty, v.path[:-1]))}.pair"
        if isinstance(last, ir.Index):
            container, _ = self.select(code, ty, ir.Index(last.indices[:-1])) if len(last.indices) > 1 else (code, ty)
            array = ty
            assert isinstance(array, t.Array)
            lo, hi = array.dims[len(last.indices) - 1]
            return f"({container}, {self.index(last.indices[-1], lo, hi)})"
        located = self.located_member(ty, last.name)
        if located is not None:
            return f"({located[0]}, {located[1]})"
        owner, attr = self.member_parts(code, ty, last.name)
        return f"({owner}, {attr!r})"

    def select(self, code: str, ty: t.IrType, selector: ir.Index | ir.Member) -> tuple[str, t.IrType]:
        if isinstance(selector, ir.Index):
            if not isinstance(ty, t.Array):
                raise CodegenError(f"cannot index {values.article(describe(ty))}")
            if not 0 < len(selector.indices) <= len(ty.dims):
                raise CodegenError(f"{len(selector.indices)} indices for an array of {len(ty.dims)} dimensions")
            for index, (lo, hi) in zip(selector.indices, ty.dims):
                code = f"{code}[{self.index(index, lo, hi)}]"
            rest = ty.dims[len(selector.indices) :]
            return code, (t.Array(ty.element, rest) if rest else ty.element)
        located = self.located_member(ty, selector.name)
        if located is not None:
            return f"{located[0]}[{located[1]}]", located[2]
        owner, attr = self.member_parts(code, ty, selector.name)
        return f"{owner}.{attr}", self.member_type(ty, selector.name)

    def located_member(self, ty: t.IrType, member: str) -> tuple[str, int, t.IrType] | None:
        """(view, key, type) of a program's located variable read from outside it (``Main.Motor`` in a test):
        a program has one instance, so its located variables live in the process image, not in the instance."""
        if not isinstance(ty, t.FbInstance):
            return None
        user = self.module.user_fb(ty.fb)
        if user is None or user.kind != "program":
            return None
        slot = self.module.layouts[user.name.upper()].located.get(member.upper())
        if slot is None:
            return None
        view, key = self.module.image_view(slot, world=self.scope.pou.live_clock)
        return view, key, slot.type

    def index(self, e: ir.Expr, lo: int, hi: int) -> str:
        if isinstance(e, ir.Const) and isinstance(e.value, int) and lo <= e.value <= hi:
            return repr(e.value - lo)
        return f"ll_ix({self.expr(e)}, {lo!r}, {hi!r})"

    def member_parts(self, code: str, ty: t.IrType, member: str) -> tuple[str, str]:
        """(object source, attribute name) of ``member`` of a structure or FB instance value ``code``."""
        if isinstance(ty, t.Struct):
            if not any(f.name.upper() == member.upper() for f in ty.fields):
                raise CodegenError(f"{ty.name} has no field {member}")
            return code, names.slot(member)
        if isinstance(ty, t.FbInstance):
            user = self.module.user_fb(ty.fb)
            if user is not None:
                place = self.module.layouts[user.name.upper()].get(member)
                if place is None:
                    raise CodegenError(f"{user.name} has no variable {member}")
                return self.module.layouts[user.name.upper()].owner(code, place), place.attr
            if std_pin_type(ty.fb, member) is None:
                raise CodegenError(
                    f"{ty.fb} has no pin {member}" if std_fb_class(ty.fb) else f"unknown function block {ty.fb}"
                )
            return code, member.upper()
        raise CodegenError(f"{values.article(describe(ty))} has no members")

    def member_type(self, ty: t.IrType, member: str) -> t.IrType:
        if isinstance(ty, t.Struct):
            return next(f.type for f in ty.fields if f.name.upper() == member.upper())
        assert isinstance(ty, t.FbInstance)
        user = self.module.user_fb(ty.fb)
        if user is not None:
            return self.module.layouts[user.name.upper()].get(member).slot.type  # type: ignore[union-attr]
        return std_pin_type(ty.fb, member)  # type: ignore[return-value]

    def scalar(self, ty: t.IrType, what: str) -> str:
        """The runtime type name of a non-composite type; CodegenError for composites and unknown names."""
        name = _scalar_name(ty)
        if name is None:
            raise CodegenError(f"{what} on a value of type {describe(ty) if is_composite(ty) else repr(ty)}")
        return name


_HANDLERS = {
    ir.Const: Expressions.const,
    ir.Var: Expressions.read,
    ir.Binary: Expressions.binary,
    ir.Unary: Expressions.unary,
    ir.Call: Expressions.call,
    ir.Convert: Expressions.convert,
    ir.Fit: Expressions.fit,
    ir.AddressOf: Expressions.address_of,
    ir.View: Expressions.view,
    ir.Attempt: Expressions.attempt,
}


def _dereferenced(code: str, reference: ir.Var) -> str:
    """``code`` (the reference ``reference``) checked not to be NULL, to be read or assigned through."""
    return f"ll_deref({code}, {var_text(reference)!r})"


@lru_cache(maxsize=1024)  # bounded: a long-running server compiles many projects
def _scalar_name(ty: t.IrType) -> str | None:
    """The runtime name of a non-composite type (None for others; CodegenError for an unknown one), worked
    out once per type: ``Expressions.scalar`` is asked for every operand."""
    name = runtime_name(ty) if isinstance(ty, (t.Elementary, t.Subrange, t.Enum)) else None
    if name is not None:
        try:
            values.resolve(name)
        except ValueError as error:
            raise CodegenError(str(error)) from None
    return name


@cache
def _unparenthesised(template: str, atoms: tuple[bool, ...]) -> str:
    """``template`` without the parentheses around the arguments that are atoms (a name, an attribute or
    a non-negative number needs none); once per template and pattern, not per call."""
    for i, atom in enumerate(atoms):
        if atom:
            template = template.replace(f"({{{i}}})", f"{{{i}}}")
    return template
