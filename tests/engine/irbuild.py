"""A small builder for IR programs in tests (the lowering is tested elsewhere; these tests start from IR).

Statements are written without origins; ``pou()`` gives each ST statement the
next line number (1, 2, ...) in order of appearance, and ``network()`` gives
its statements the network id (and ``element=`` where a helper passed one).

    A = v("A", INT)
    main = pou("MAIN", [slot("A", INT)], [assign(A, add(A, c(1, INT)))])
    sim = Simulation(prog(main))
"""

from __future__ import annotations

from dataclasses import fields, is_dataclass

from ladderlab.iec.elementary import ELEMENTARY
from ladderlab.ir import nodes as ir
from ladderlab.ir import types as t

T = {name: t.Elementary(name) for name in ELEMENTARY}
BOOL, SINT, INT, DINT, LINT = T["BOOL"], T["SINT"], T["INT"], T["DINT"], T["LINT"]
USINT, UINT, UDINT, ULINT = T["USINT"], T["UINT"], T["UDINT"], T["ULINT"]
BYTE, WORD, DWORD, LWORD = T["BYTE"], T["WORD"], T["DWORD"], T["LWORD"]
REAL, LREAL, TIME, STRING = T["REAL"], T["LREAL"], T["TIME"], T["STRING"]

_PENDING = "?"  # origin placeholder filled in by pou() / network()


def string(n: int) -> t.Elementary:
    return t.Elementary("STRING", n)


def array(element: t.IrType, *dims: tuple[int, int]) -> t.Array:
    return t.Array(element, tuple(dims))


def struct(name: str, *members: tuple) -> t.Struct:
    """struct("PT", ("X", INT), ("Y", INT, 5)) - (name, type[, initial])."""
    return t.Struct(name, tuple(t.StructField(m[0], m[1], m[2] if len(m) > 2 else None) for m in members))


def fb(name: str) -> t.FbInstance:
    return t.FbInstance(name)


# ------------------------------------------------------------------ expressions


def c(value: object, ty: t.IrType) -> ir.Const:
    return ir.Const(value, ty)


def v(name: str, ty: t.IrType, *path: ir.Index | ir.Member) -> ir.Var:
    return ir.Var("local", name, ty, tuple(path))


def g(name: str, ty: t.IrType, *path: ir.Index | ir.Member) -> ir.Var:
    return ir.Var("global", name, ty, tuple(path))


def ix(*indices: ir.Expr) -> ir.Index:
    return ir.Index(tuple(indices))


def m(name: str) -> ir.Member:
    return ir.Member(name)


_COMPARISONS = {"EQ", "NE", "LT", "LE", "GT", "GE"}


def binop(op: str, left: ir.Expr, right: ir.Expr) -> ir.Binary:
    return ir.Binary(op, left, right, BOOL if op in _COMPARISONS else left.type)  # type: ignore[arg-type]


def add(a, b):
    return binop("ADD", a, b)


def sub(a, b):
    return binop("SUB", a, b)


def mul(a, b):
    return binop("MUL", a, b)


def div(a, b):
    return binop("DIV", a, b)


def and_(a, b):
    return binop("AND", a, b)


def or_(a, b):
    return binop("OR", a, b)


def gt(a, b):
    return binop("GT", a, b)


def ge(a, b):
    return binop("GE", a, b)


def lt(a, b):
    return binop("LT", a, b)


def eq(a, b):
    return binop("EQ", a, b)


def ne(a, b):
    return binop("NE", a, b)


def not_(a: ir.Expr) -> ir.Unary:
    return ir.Unary("NOT", a, a.type)


def neg(a: ir.Expr) -> ir.Unary:
    return ir.Unary("NEG", a, a.type)


def call(
    function: str, *args: ir.Expr, type: t.IrType | None = None, user: bool = False, in_outs: tuple[ir.Var, ...] = ()
) -> ir.Call:
    return ir.Call(function, tuple(args), tuple(a.type for a in args), type or args[0].type, user, tuple(in_outs))


def conv(e: ir.Expr, to: t.IrType) -> ir.Convert:
    return ir.Convert(e, e.type, to)


# ------------------------------------------------------------------ statements


def at(
    line: int | None = None, *, network: str | None = None, element: str | None = None, column: int = 1
) -> ir.Origin:
    return ir.Origin(_PENDING, line=line, column=column if line is not None else None, network=network, element=element)


def assign(target: ir.Var, value: ir.Expr, origin: ir.Origin | None = None) -> ir.Assign:
    return ir.Assign(target, value, origin or at())


def if_(*branches: tuple[ir.Expr, list], orelse: list | None = None, origin: ir.Origin | None = None) -> ir.If:
    return ir.If([(cond, list(body)) for cond, body in branches], list(orelse or []), origin or at())


def case(selector: ir.Expr, *branches: tuple[list, list], orelse: list | None = None) -> ir.Case:
    return ir.Case(selector, [(list(labels), list(body)) for labels, body in branches], list(orelse or []), at())


def for_(var: ir.Var, start: ir.Expr, end: ir.Expr, body: list, step: ir.Expr | None = None) -> ir.For:
    return ir.For(var, start, end, step or c(1, var.type), list(body), at())


def while_(cond: ir.Expr, body: list) -> ir.While:
    return ir.While(cond, list(body), at())


def repeat(body: list, until: ir.Expr) -> ir.Repeat:
    return ir.Repeat(list(body), until, at())


def exit_() -> ir.Exit:
    return ir.Exit(at())


def ret() -> ir.Return:
    return ir.Return(at())


def fbcall(
    instance: ir.Var,
    inputs: dict | None = None,
    outputs: dict | None = None,
    *,
    en: ir.Expr | None = None,
    eno: ir.Var | None = None,
    origin: ir.Origin | None = None,
) -> ir.FbCall:
    return ir.FbCall(instance, list((inputs or {}).items()), list((outputs or {}).items()), origin or at(), en, eno)


def fncall(
    c_: ir.Call,
    target: ir.Var | None = None,
    *,
    en: ir.Expr | None = None,
    eno: ir.Var | None = None,
    origin: ir.Origin | None = None,
) -> ir.FnCall:
    return ir.FnCall(c_, target, origin or at(), en, eno)


def jump(label: str, cond: ir.Expr | None = None, origin: ir.Origin | None = None) -> ir.Jump:
    return ir.Jump(label, cond, origin or at())


def probe(element: str, value: ir.Expr) -> ir.Probe:
    return ir.Probe(element, value, at(element=element))


# ------------------------------------------------------------------ POUs and programs


def slot(
    name: str,
    ty: t.IrType,
    var_class: str = "VAR",
    initial: object = None,
    *,
    retain: bool = False,
    hidden: bool = False,
) -> ir.Slot:
    return ir.Slot(name, var_class, ty, initial, retain=retain, hidden=hidden)  # type: ignore[arg-type]


def network(name: str, statements: list, label: str | None = None) -> ir.Block:
    """One LD/FBD network: its statements get the network id as origin (element ids kept)."""
    for s in _statements(statements):
        if s.origin.pou == _PENDING:
            s.origin = ir.Origin(_PENDING, network=name, element=s.origin.element)
    return ir.Block(list(statements), ir.Origin(_PENDING, network=name), label)


def pou(
    name: str,
    slots: list[ir.Slot],
    body: list,
    *,
    kind: str = "program",
    return_type: t.IrType | None = None,
    language: str | None = None,
) -> ir.Pou:
    """A POU; ``body`` is a list of statements (one ST block) or of network Blocks."""
    blocks = body if body and isinstance(body[0], ir.Block) else [ir.Block(list(body), ir.Origin(_PENDING, line=1))]
    line = 0
    for block in blocks:
        block.origin = _fill(block.origin, name, None)
        for s in _statements(block.statements):
            if s.origin.pou == _PENDING and s.origin.line is None and s.origin.network is None:
                line += 1
                s.origin = _fill(s.origin, name, line)
            else:
                s.origin = _fill(s.origin, name, s.origin.line)
    if kind == "function" and not any(s.name.upper() == name.upper() for s in slots):
        slots = [*slots, slot(name, return_type, "VAR_OUTPUT")]
    lang = language or ("st" if not isinstance(body[0] if body else None, ir.Block) else "ld")
    return ir.Pou(name, kind, slots, blocks, return_type, lang)  # type: ignore[arg-type]


def _fill(origin: ir.Origin, pou_name: str, line: int | None) -> ir.Origin:
    if origin.pou != _PENDING:
        return origin
    return ir.Origin(
        pou_name, line=line, column=1 if line is not None else None, network=origin.network, element=origin.element
    )


def _statements(statements: list):
    for s in statements:
        yield s
        for f in fields(s):
            value = getattr(s, f.name)
            if f.name in ("body", "orelse") and isinstance(value, list):
                yield from _statements(value)
            elif f.name == "branches":
                for _, body in value:
                    yield from _statements(body)


def function(name: str, return_type: t.IrType, slots: list[ir.Slot], body: list) -> ir.Pou:
    return pou(name, slots, body, kind="function", return_type=return_type)


def prog(*pous: ir.Pou, globals: list[ir.Slot] = (), tasks: list[ir.TaskSpec] = ()) -> ir.Program:
    return ir.Program({p.name: p for p in pous}, list(globals), list(tasks))


def task(name: str, interval_ms: int, priority: int, *programs: str) -> ir.TaskSpec:
    return ir.TaskSpec(name, interval_ms, priority, list(programs))


assert is_dataclass(ir.Assign)


def trace(sim, paths: list[str], scans: int) -> list[tuple]:
    """Run ``scans`` scans; the values of ``paths`` after each."""
    rows = []
    for _ in range(scans):
        sim.cycle()
        rows.append(tuple(sim.read(p) for p in paths))
    return rows
