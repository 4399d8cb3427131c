"""A whole ST file -> the project model (types / globals / POU declarations and bodies as texts).

The model keeps each POU's declarations and body as separate texts; this cuts a
parsed file along the AST spans so imported libraries and the spec's worked
examples can go through ``check_project`` exactly like edited projects.
"""

from __future__ import annotations

from ..model.diagnostics import Diagnostic
from ..model.project import Pou, Project, Task
from . import ast
from .parser import parse_source
from .printer import print_expression
from .sfc_text import sfc_from_text

_KIND = {"PROGRAM": "program", "FUNCTION_BLOCK": "function_block", "FUNCTION": "function"}


class _Text:
    """Slices of the source by 1-based (line, column) positions."""

    def __init__(self, text: str):
        self.text = text
        self.starts = [0]
        for index, char in enumerate(text):
            if char == "\n":
                self.starts.append(index + 1)

    def offset(self, line: int, column: int) -> int:
        return self.starts[line - 1] + column - 1

    def between(self, start: tuple[int, int], end: tuple[int, int]) -> str:
        return self.text[self.offset(*start) : self.offset(*end)]


def source_to_project(
    text: str, name: str = "imported", *, nested_comments: bool = False
) -> tuple[Project | None, list[Diagnostic]]:
    parsed = parse_source(text, nested_comments=nested_comments)
    if parsed.ast is None:
        return None, parsed.diagnostics
    source = _Text(text)
    types, globals_, pous, tasks = [], [], [], []
    sfc_problems: list[Diagnostic] = []
    for item in parsed.ast.items:
        span = (item.span.line, item.span.column), (item.span.end_line, item.span.end_column)
        if isinstance(item, ast.TypeBlock):
            types.append(source.between(*span))
        elif isinstance(item, ast.VarBlock):
            globals_.append(source.between(*span))
        elif isinstance(item, ast.Pou) and item.sfc is not None:
            made, problems = _sfc_pou(item, source)
            pous.append(made)
            sfc_problems += problems
        elif isinstance(item, ast.Pou):
            pous.append(_pou(item, source))
        else:
            tasks += _tasks(item)
    project = Project(name=name, types="\n".join(types), globals="\n".join(globals_), pous=pous, tasks=tasks)
    return project, parsed.diagnostics + sfc_problems


def _pou(pou: ast.Pou, source: _Text) -> Pou:
    end = (pou.span.end_line, pou.span.end_column - len(f"END_{pou.kind}"))
    if pou.var_blocks:
        first, last = pou.var_blocks[0].span, pou.var_blocks[-1].span
        declarations = _keep_lines(
            source.between((first.line, first.column), (last.end_line, last.end_column)), (first.line, first.column)
        )
        body_start = (last.end_line, last.end_column)
    else:
        declarations = ""
        body_start = (pou.body[0].span.line, pou.body[0].span.column) if pou.body else end
    body = source.between(body_start, end)
    return_type = None
    if pou.return_type is not None:
        return_type = pou.return_type.name if isinstance(pou.return_type, ast.NamedType) else None
    return Pou(
        name=pou.name,
        kind=_KIND[pou.kind],
        language="st",
        return_type=return_type,
        declarations=declarations,
        body=_keep_lines(body, body_start),
    )


def _sfc_pou(pou: ast.Pou, source: _Text) -> tuple[Pou, list[Diagnostic]]:
    """A POU written in textual SFC: its declarations as typed, the chart drawn from its steps and transitions."""
    declarations = ""
    if pou.var_blocks:
        first, last = pou.var_blocks[0].span, pou.var_blocks[-1].span
        declarations = source.between((first.line, first.column), (last.end_line, last.end_column))
    body, problems = sfc_from_text(pou, source.between)
    kind = _KIND[pou.kind]
    return Pou(name=pou.name, kind=kind, language="sfc", declarations=declarations, body=body), problems


def _keep_lines(body: str, start: tuple[int, int]) -> str:
    """Pad a slice so its line numbers match the file's (diagnostics then point into the original)."""
    return "\n" * (start[0] - 1) + " " * (start[1] - 1) + body


def _tasks(config: ast.Configuration) -> list[Task]:
    items = [i for r in config.items if isinstance(r, ast.Resource) for i in r.items] + list(config.items)
    programs = [p for p in items if isinstance(p, ast.ProgramConfig)]
    tasks = []
    for task in (i for i in items if isinstance(i, ast.TaskConfig)):
        props = {name.upper(): value for name, value in task.properties}
        # A task without INTERVAL is free-running (CFG-04, Mosaic process P0): the model's default cycle.
        interval = {"interval": print_expression(props["INTERVAL"])} if "INTERVAL" in props else {}
        priority = props.get("PRIORITY")
        tasks.append(
            Task(
                name=task.name,
                **interval,
                priority=priority.value if isinstance(priority, ast.IntLit) else 0,
                programs=[p.type_name for p in programs if (p.task or "").upper() == task.name.upper()],
            )
        )
    return tasks
