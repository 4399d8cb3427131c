"""Builders for LD/FBD POUs and projects, and the IR invariants of diagram lowerings (docs/diagrams.md).

Used by tests/ir/test_lower_ld*.py, test_lower_fbd*.py and test_diagram*.py.
"""

from __future__ import annotations

from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_project import LoweringResult, lower_project
from ladderlab.model import fbd, ld
from ladderlab.model.project import Pou, Project
from tests.ir import invariants

# ------------------------------------------------------------------ LD


def contact(id: str, var: str, mode: str = "no") -> ld.Contact:
    return ld.Contact(id=id, var=var, mode=mode)


def coil(id: str, var: str, mode: str = "normal") -> ld.Coil:
    return ld.Coil(id=id, var=var, mode=mode)


def compare(id: str, op: str, left: str, right: str) -> ld.Compare:
    return ld.Compare(id=id, op=op, left=left, right=right)


def parallel(id: str, *branches: list) -> ld.Parallel:
    return ld.Parallel(id=id, branches=list(branches))


def box(
    id: str, call: str, instance: str | None = None, en: bool = False, outputs: dict | None = None, **inputs
) -> ld.Box:
    return ld.Box(id=id, call=call, instance=instance, en=en, inputs=inputs, outputs=outputs or {})


def jump(id: str, target: str) -> ld.Jump:
    return ld.Jump(id=id, target=target)


def ret(id: str) -> ld.Return:
    return ld.Return(id=id)


def rung(id: str, *elements, label: str | None = None) -> ld.LdNetwork:
    return ld.LdNetwork(id=id, label=label, elements=list(elements))


def ld_pou(name: str, declarations: str, *networks: ld.LdNetwork, kind: str = "program") -> Pou:
    return Pou(name=name, kind=kind, language="ld", declarations=declarations, body=ld.LdBody(networks=list(networks)))


# ------------------------------------------------------------------ FBD


def inp(id: str, expr: str, x: float | None = None, y: float | None = None) -> fbd.InputNode:
    return fbd.InputNode(id=id, expr=expr, pos=_pos(x, y))


def out(id: str, var: str, mode: str = "normal", x: float | None = None, y: float | None = None) -> fbd.OutputNode:
    return fbd.OutputNode(id=id, var=var, mode=mode, pos=_pos(x, y))


def blk(
    id: str,
    call: str,
    instance: str | None = None,
    en: bool = False,
    x: float | None = None,
    y: float | None = None,
    **pins: dict,
) -> fbd.Block:
    flags = {pin: fbd.PinFlags(**value) for pin, value in pins.items()} or None
    return fbd.Block(id=id, call=call, instance=instance, en=en, pins=flags, pos=_pos(x, y))


def fjump(id: str, target: str) -> fbd.FbdJump:
    return fbd.FbdJump(id=id, target=target)


def flabel(id: str, name: str) -> fbd.FbdLabel:
    return fbd.FbdLabel(id=id, name=name)


def fret(id: str) -> fbd.FbdReturn:
    return fbd.FbdReturn(id=id)


def connector(id: str, name: str) -> fbd.Connector:
    return fbd.Connector(id=id, name=name)


def continuation(id: str, name: str) -> fbd.Continuation:
    return fbd.Continuation(id=id, name=name)


def wire(source: str, target: str) -> fbd.Wire:
    """``wire("add.OUT", "out.IN")``."""
    (a, p), (b, q) = source.split("."), target.split(".")
    return fbd.Wire.model_validate({"from": {"node": a, "pin": p}, "to": {"node": b, "pin": q}})


def net(
    id: str, nodes: list, wires: list[tuple[str, str]], label: str | None = None, order: list[str] | None = None
) -> fbd.FbdNetwork:
    return fbd.FbdNetwork(id=id, label=label, nodes=nodes, wires=[wire(a, b) for a, b in wires], order=order)


def fbd_pou(name: str, declarations: str, *networks: fbd.FbdNetwork, kind: str = "program") -> Pou:
    return Pou(
        name=name, kind=kind, language="fbd", declarations=declarations, body=fbd.FbdBody(networks=list(networks))
    )


def _pos(x: float | None, y: float | None) -> fbd.Position | None:
    return fbd.Position(x=x, y=y) if x is not None and y is not None else None


# ------------------------------------------------------------------ projects


def project(*pous: Pou, globals: str = "", types: str = "") -> Project:
    return Project(name="t", pous=list(pous), globals=globals, types=types)


def errors(*pous: Pou, globals: str = "") -> list[str]:
    """The formatted error and warning diagnostics of lowering a project of ``pous``."""
    return [d.format() for d in lower_project(project(*pous, globals=globals)).diagnostics]


def lower_ok(*pous: Pou, globals: str = "") -> ir.Program:
    """Lower; no errors allowed, and the IR must satisfy docs/ir.md and the diagram invariants."""
    result: LoweringResult = lower_project(project(*pous, globals=globals))
    found = [d.format() for d in result.diagnostics if d.severity == "error"]
    assert found == [], found
    assert result.program is not None
    check_diagram_program(result.program)
    return result.program


# ------------------------------------------------------------------ invariants


class _DiagramChecker(invariants._Checker):
    """docs/ir.md's checks, plus the statements only diagrams produce (probes, jumps)."""

    def stmt(self, s: ir.Stmt) -> None:
        if isinstance(s, ir.Probe):
            self.expr(s.value)
        elif isinstance(s, ir.Jump):
            assert s.label in self.labels, s
            if s.cond is not None:
                self.expr(s.cond)
        else:
            super().stmt(s)


def check_diagram_program(program: ir.Program) -> None:
    """Every POU's statements are typed and name slots; diagram POUs' labels are unique and jumps hit them;
    every hidden power temporary is written in a block before it is read there (invariant 5)."""
    for pou in program.pous.values():
        if pou.language == "st":
            continue
        labels = [b.label for b in pou.blocks if b.label is not None]
        assert len(labels) == len(set(labels)), labels
        checker = _DiagramChecker(program, pou)
        checker.labels = set(labels)
        temps = {s.name for s in pou.slots if s.hidden and s.var_class == "VAR_TEMP"}
        for block in pou.blocks:
            checker.stmts(block.statements)
            assert all(s.origin.network == block.origin.network for s in block.statements), block
            _written_before_read(block.statements, temps, set())


def _written_before_read(statements: list[ir.Stmt], temps: set[str], written: set[str]) -> None:
    for s in statements:
        for value in _reads(s):
            for name in _names(value):
                assert name not in temps or name in written, f"temporary {name} read before written: {s}"
        if isinstance(s, ir.If):
            for _, body in s.branches:
                _written_before_read(body, temps, set(written))
        for target in _writes(s):
            written.add(target.name)


def _reads(s: ir.Stmt) -> list[ir.Expr]:
    if isinstance(s, (ir.Assign, ir.Probe)):
        return [s.value]
    if isinstance(s, ir.If):
        return [c for c, _ in s.branches]
    if isinstance(s, ir.Jump):
        return [s.cond] if s.cond is not None else []
    if isinstance(s, ir.FnCall):
        return [s.call] + ([s.en] if s.en is not None else [])
    if isinstance(s, ir.FbCall):
        return [v for _, v in s.inputs] + ([s.en] if s.en is not None else [])
    return []


def _writes(s: ir.Stmt) -> list[ir.Var]:
    if isinstance(s, ir.Assign):
        return [s.target]
    if isinstance(s, ir.FnCall):
        return [v for v in (s.target, s.eno) if v is not None]
    if isinstance(s, ir.FbCall):
        return [v for _, v in s.outputs] + ([s.eno] if s.eno is not None else [])
    return []


def _names(e: ir.Expr):
    if isinstance(e, ir.Var):
        yield e.name
    elif isinstance(e, ir.Unary):
        yield from _names(e.operand)
    elif isinstance(e, ir.Binary):
        yield from _names(e.left)
        yield from _names(e.right)
    elif isinstance(e, ir.Call):
        for arg in e.args:
            yield from _names(arg)
    elif isinstance(e, ir.Convert):
        yield from _names(e.operand)


def statements(program: ir.Program, pou: str, network: str) -> list[ir.Stmt]:
    (block,) = [b for b in program.pous[pou.upper()].blocks if b.origin.network == network]
    return block.statements


def probes(program: ir.Program, pou: str) -> list[str]:
    """The probe ids of a POU in statement order (nested ones included)."""
    found: list[str] = []

    def visit(stmts: list[ir.Stmt]) -> None:
        for s in stmts:
            if isinstance(s, ir.Probe):
                found.append(s.element)
            elif isinstance(s, ir.If):
                for _, body in s.branches:
                    visit(body)

    for block in program.pous[pou.upper()].blocks:
        visit(block.statements)
    return found


# ------------------------------------------------------------------ running


def simulate(*pous: Pou, globals: str = "", interval: str = "T#10ms", variant: str = "fast"):
    """A Simulation of the lowered project; every PROGRAM runs in one task of ``interval``."""
    from ladderlab.engine.simulation import Simulation
    from ladderlab.model.project import Task

    programs = [p.name for p in pous if p.kind == "program"]
    lowered = project(*pous, globals=globals)
    lowered.tasks = [Task(name="main", interval=interval, programs=programs)]
    result = lower_project(lowered)
    found = [d.format() for d in result.diagnostics if d.severity == "error"]
    assert found == [], found
    check_diagram_program(result.program)
    return Simulation(result.program, variant=variant)


def trace(sim, pou: str, scans: list[dict[str, object]], outputs: list[str]) -> list[tuple]:
    """Per scan: write the inputs (``{name: value}``), run one scan, read ``outputs`` of ``pou``."""
    rows = []
    for inputs in scans:
        for name, value in inputs.items():
            sim.write(f"{pou}.{name}", value)
        sim.cycle(1)
        assert sim.fault is None, sim.fault
        rows.append(tuple(sim.read(f"{pou}.{name}") for name in outputs))
    return rows
