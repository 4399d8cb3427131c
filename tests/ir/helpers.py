"""Building small projects from ST text and lowering them, with the IR invariants checked on every result."""

from __future__ import annotations

from ladderlab.ir import nodes as ir
from ladderlab.ir.lower_project import LoweringResult, lower_project
from ladderlab.ir.types import Elementary
from ladderlab.model import Task
from ladderlab.st.project_text import source_to_project
from tests.ir.invariants import check_program

BOOL, INT, DINT, REAL, LREAL = (Elementary(n) for n in ("BOOL", "INT", "DINT", "REAL", "LREAL"))
SINT, WORD, BYTE, TIME, STRING = (Elementary(n) for n in ("SINT", "WORD", "BYTE", "TIME", "STRING"))
TOD, DT, DATE = Elementary("TIME_OF_DAY"), Elementary("DATE_AND_TIME"), Elementary("DATE")


def lower_source(text: str) -> LoweringResult:
    project, diagnostics = source_to_project(text, "test")
    assert project is not None, [d.format() for d in diagnostics]
    return lower_project(project)


def lower_ok(text: str) -> ir.Program:
    """Lower ``text``; it must have no errors, and the IR must satisfy the invariants of docs/ir.md."""
    result = lower_source(text)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    assert result.program is not None
    check_program(result.program)
    return result.program


def lower_with_tasks(text: str, tasks: dict[str, list[str]]) -> ir.Program:
    """``text`` lowered with the project's tasks ``{task: [programs]}`` (10 ms each), checked like lower_ok."""
    project, diagnostics = source_to_project(text, "test")
    assert project is not None, [d.format() for d in diagnostics]
    project.tasks = [Task(name=name, interval="T#10ms", programs=programs) for name, programs in tasks.items()]
    result = lower_project(project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    assert result.program is not None
    check_program(result.program)
    return result.program


def program_body(declarations: str, body: str, extra: str = "") -> list[ir.Stmt]:
    """The statements of ``PROGRAM P VAR <declarations> END_VAR <body> END_PROGRAM <extra>``; the body starts on line 3."""
    program = lower_ok(f"PROGRAM P\nVAR {declarations} END_VAR\n{body}\nEND_PROGRAM\n{extra}\n")
    (block,) = program.pous["P"].blocks
    return block.statements


def errors(text: str) -> list[str]:
    """The formatted error diagnostics of lowering ``text`` (checker and lowering)."""
    result = lower_source(text)
    return [d.format() for d in result.diagnostics if d.severity == "error"]


def local(name: str, type, *path) -> ir.Var:
    return ir.Var("local", name, type, tuple(path))


def const(value, type) -> ir.Const:
    return ir.Const(value, type)


def at(line: int, column: int, end_line: int, end_column: int, pou: str = "P") -> ir.Origin:
    return ir.Origin(pou, line, column, end_line, end_column)
