"""An independent checker of the IR invariants of docs/ir.md, applied to every lowering result in the tests.

Written against docs/ir.md only (not the lowering code): typed expressions whose
operands have one value type, variables that name existing slots with the
path's type, engine values in constants and initial values, upper-case names,
and an origin on every statement.
"""

from __future__ import annotations

from ladderlab.ir import nodes as ir
from ladderlab.ir import types as t

COMPARISONS = {"EQ", "NE", "LT", "LE", "GT", "GE"}


def value_type(ty: t.IrType) -> t.IrType:
    """docs/ir.md: a Subrange counts as its base, a STRING of any length as STRING."""
    if isinstance(ty, t.Subrange):
        return ty.base
    if isinstance(ty, t.Elementary) and ty.name == "STRING":
        return t.Elementary("STRING")
    return ty


def check_value(value: object, ty: t.IrType, where: str) -> None:
    """``value`` is an engine value of ``ty`` (docs/ir.md invariant 1 and the initial-value representation)."""
    if isinstance(ty, t.Elementary):
        category = ty.info.category
        expected = {"bool": bool, "real": float, "string": str}.get(category, int)
        assert type(value) is expected, f"{where}: {value!r} is not a {ty.name} value"
        if category in ("int", "bits", "time"):
            assert ty.info.min <= value <= ty.info.max, f"{where}: {value} outside {ty.name}"  # type: ignore[operator]
        if category == "string":
            assert len(value) <= ty.max_length, f"{where}: {value!r} longer than {ty.max_length}"  # type: ignore[arg-type]
    elif isinstance(ty, t.Subrange):
        assert type(value) is int and ty.low <= value <= ty.high, f"{where}: {value!r} outside {ty.low}..{ty.high}"
    elif isinstance(ty, t.Enum):
        assert value in [v for _, v in ty.values], f"{where}: {value!r} is not a value of {ty.name}"
    elif isinstance(ty, t.Array):
        (low, high), *rest = ty.dims
        assert isinstance(value, tuple) and len(value) == high - low + 1, f"{where}: {value!r} for {ty}"
        inner = t.Array(ty.element, tuple(rest)) if rest else ty.element
        for item in value:
            check_value(item, inner, where)
    elif isinstance(ty, t.Struct):
        assert isinstance(value, tuple) and len(value) == len(ty.fields), f"{where}: {value!r} for {ty.name}"
        for item, field in zip(value, ty.fields):
            check_value(item, field.type, f"{where}.{field.name}")
    elif isinstance(ty, t.Reference):
        assert value is None or isinstance(value, ir.ReferenceInit), f"{where}: reference initial {value!r}"
    else:
        assert value is None or isinstance(value, tuple), f"{where}: FB instance initial {value!r}"


class _Checker:
    def __init__(self, program: ir.Program, pou: ir.Pou):
        self.program, self.pou = program, pou
        self.locals = {s.name: s for s in pou.slots}
        self.globals = {s.name: s for s in program.globals}
        for instance in program.program_instances():  # the engine keeps program instances among the globals
            fb = t.FbInstance(instance.pou)
            self.globals[instance.name] = ir.Slot(instance.name, "VAR_GLOBAL", fb, None)

    def var(self, v: ir.Var) -> None:
        assert v.name == v.name.upper(), v
        slots = self.locals if v.scope == "local" else self.globals
        assert v.name in slots, f"{self.pou.name}: {v.scope} {v.name} has no slot"
        ty = slots[v.name].type
        for selector in v.path:
            if isinstance(selector, ir.Deref):
                assert isinstance(ty, t.Reference), (v, ty)
                ty = ty.target
            elif isinstance(selector, ir.Index):
                assert isinstance(ty, t.Array) and len(selector.indices) == len(ty.dims), (v, ty)
                for index in selector.indices:
                    self.expr(index)
                    assert value_type(index.type).info.category == "int", index  # type: ignore[union-attr]
                ty = ty.element
            else:
                assert selector.name == selector.name.upper(), v
                if isinstance(ty, t.Struct):
                    ty = next(f.type for f in ty.fields if f.name == selector.name)
                else:
                    assert isinstance(ty, t.FbInstance), (v, ty)
                    ty = v.type if selector is v.path[-1] else self._fb_member(ty, selector.name)
        assert ty == v.type, f"{v}: the path's type is {ty}"

    def _fb_member(self, ty: t.FbInstance, name: str) -> t.IrType:
        pou = self.program.pous.get(ty.fb)
        assert pou is not None, f"nested member of standard FB {ty.fb}"
        return next(s.type for s in pou.slots if s.name == name)

    def expr(self, e: ir.Expr) -> None:
        if isinstance(e, ir.Const):
            check_value(e.value, e.type, f"{self.pou.name}: Const")
        elif isinstance(e, ir.Var):
            self.var(e)
        elif isinstance(e, ir.AddressOf):
            self.var(e.var)
            assert isinstance(e.type, t.Reference) and value_type(e.type.target) == value_type(e.var.type), e
        elif isinstance(e, ir.View):
            self.expr(e.value)
            assert isinstance(e.type, t.Reference) and isinstance(e.value.type, t.Reference), e
        elif isinstance(e, ir.Unary):
            self.expr(e.operand)
            assert value_type(e.operand.type) == value_type(e.type), e  # type: ignore[union-attr]
        elif isinstance(e, ir.Binary):
            self.expr(e.left)
            self.expr(e.right)
            operand = value_type(e.left.type)  # type: ignore[union-attr]
            if isinstance(e.type, t.Reference):  # pointer arithmetic: p +/- an integer number of bytes
                assert e.op in ("ADD", "SUB") and operand == e.type, e
                assert e.right.type.info.category == "int", e  # type: ignore[union-attr]
                return
            assert operand == value_type(e.right.type), f"Binary operands differ: {e}"  # type: ignore[union-attr]
            assert e.type == (t.BOOL if e.op in COMPARISONS else operand), e
        elif isinstance(e, ir.Call):
            assert len(e.args) == len(e.arg_types), e
            for arg, ty in zip(e.args, e.arg_types):
                self.expr(arg)
                assert value_type(arg.type) == value_type(ty), f"{e.function}: argument {arg} is not {ty}"  # type: ignore[union-attr]
            for v in e.in_outs:
                self.var(v)
            if e.user:
                callee = self.program.pous[e.function]
                inputs = [s.type for s in callee.slots if s.var_class == "VAR_INPUT"]
                assert list(e.arg_types) == inputs and callee.return_type == e.type, e
                assert len(e.in_outs) == sum(s.var_class == "VAR_IN_OUT" for s in callee.slots), e
        else:
            assert isinstance(e, ir.Convert), e
            self.expr(e.operand)
            assert value_type(e.operand.type) == e.source and e.source != e.type, e  # type: ignore[union-attr]

    def stmts(self, statements: list[ir.Stmt]) -> None:
        for s in statements:
            assert s.origin.pou == self.pou.name, s
            self.stmt(s)

    def stmt(self, s: ir.Stmt) -> None:
        if isinstance(s, ir.Assign):
            self.var(s.target)
            self.expr(s.value)
            assert value_type(s.value.type) == value_type(s.target.type), f"Assign types differ: {s}"  # type: ignore[union-attr]
        elif isinstance(s, ir.If):
            for cond, body in s.branches:
                self.expr(cond)
                assert cond.type == t.BOOL, s  # type: ignore[union-attr]
                self.stmts(body)
            self.stmts(s.orelse)
        elif isinstance(s, ir.Case):
            self.expr(s.selector)
            for labels, body in s.branches:
                assert all(isinstance(x, int) or (isinstance(x, tuple) and len(x) == 2) for x in labels), s
                self.stmts(body)
            self.stmts(s.orelse)
        elif isinstance(s, ir.For):
            self.var(s.var)
            for part in (s.start, s.end, s.step):
                self.expr(part)
                assert value_type(part.type) == value_type(s.var.type), s  # type: ignore[union-attr]
            self.stmts(s.body)
        elif isinstance(s, ir.While):
            self.expr(s.cond)
            self.stmts(s.body)
        elif isinstance(s, ir.Repeat):
            self.stmts(s.body)
            self.expr(s.until)
        elif isinstance(s, ir.FbCall):
            self.var(s.instance)
            assert isinstance(s.instance.type, t.FbInstance), s
            for name, value in s.inputs:
                assert name == name.upper(), s
                self.expr(value)
            for name, target in s.outputs:
                self.var(target)
            self._en_eno(s.en, s.eno)
        elif isinstance(s, ir.FnCall):
            self.expr(s.call)
            if s.target is not None:
                self.var(s.target)
            self._en_eno(s.en, s.eno)
        elif isinstance(s, ir.Jump):  # IL jumps (invariant 4): to a labelled block of the same POU
            assert s.label in {b.label for b in self.pou.blocks if b.label is not None}, s
            if s.cond is not None:
                self.expr(s.cond)
                assert s.cond.type == t.BOOL, s  # type: ignore[union-attr]
        elif isinstance(s, ir.Probe) and self.pou.language == "il":  # the accumulator after a line (online)
            assert s.element.startswith("L") and ":" in s.element, s
            self.expr(s.value)
        else:
            assert isinstance(s, (ir.Exit, ir.Return)), f"unexpected statement in ST: {s}"

    def _en_eno(self, en: ir.Expr | None, eno: ir.Var | None) -> None:
        if en is not None:
            self.expr(en)
            assert en.type == t.BOOL  # type: ignore[union-attr]
        if eno is not None:
            self.var(eno)
            assert eno.type == t.BOOL


def check_program(program: ir.Program) -> None:
    """Assert the invariants of docs/ir.md on a whole lowered program."""
    for slot in program.globals:
        assert slot.name == slot.name.upper() and slot.var_class == "VAR_GLOBAL", slot
        if slot.address is None or slot.initial is not None:  # a located one without: the image holds its value
            check_value(slot.initial, slot.type, slot.name)
    for name, pou in program.pous.items():
        assert name == pou.name == pou.name.upper()
        names = [s.name for s in pou.slots]
        assert len(names) == len(set(names)) and all(n == n.upper() for n in names), names
        for slot in pou.slots:
            assert slot.var_class != "VAR_EXTERNAL"
            if slot.var_class != "VAR_IN_OUT" and (slot.address is None or slot.initial is not None):
                check_value(slot.initial, slot.type, f"{name}.{slot.name}")
        checker = _Checker(program, pou)
        labels = [block.label for block in pou.blocks if block.label is not None]
        assert len(labels) == len(set(labels)) and all(label == label.upper() for label in labels), labels
        for block in pou.blocks:
            assert block.origin.pou == name and (block.label is None or pou.language == "il")
            checker.stmts(block.statements)
    instances = {i.name: i for i in program.program_instances()}
    assert all(program.pous[i.pou].kind == "program" for i in instances.values()), instances
    for task in program.tasks:
        assert all(p in instances for p in task.programs), task
