"""A whole ST file -> the project model (types / globals / POU declarations and bodies as texts).

The model keeps each POU's declarations and body as separate texts; this cuts a
parsed file along the AST spans so imported libraries and the spec's worked
examples can go through ``check_project`` exactly like edited projects.
"""

from __future__ import annotations

import bisect
from typing import Any, NamedTuple

from ..model.diagnostics import Diagnostic
from ..model.project import (
    Accessor,
    Configuration,
    GlobalVariableList,
    Method,
    Pou,
    PouAction,
    ProgramInstance,
    Project,
    Property,
    Resource,
    Task,
)
from . import ast
from .gvl_text import gvl_heading
from .il_parser import blank_il_bodies
from .parser import parse_source
from .pragmas import (
    attributed_headers,
    block_text,
    headed_by,
    monitored_properties,
    monitoring_pragma,
    with_call_after_init,
)
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
        #: the FUNCTION_BLOCK and METHOD headers {attribute 'call_after_init'} stands above (st/pragmas.py)
        self.attributed = attributed_headers(text)
        #: the PROPERTY headers {attribute 'monitoring'} stands above, with its mode (st/monitoring.py)
        self.monitored = monitored_properties(text)

    def declarations(self, node, text: str) -> str:
        """The declarations text of ``node`` (a POU or a method), headed by the call_after_init attribute when it
        stood above the node's header (the model keeps it there: st/call_after_init.py)."""
        return with_call_after_init(text) if (node.span.line, node.span.column) in self.attributed else text

    def offset(self, line: int, column: int) -> int:
        return self.starts[line - 1] + column - 1

    def position(self, offset: int) -> tuple[int, int]:
        """The (line, column) of a character offset."""
        line = bisect.bisect_right(self.starts, offset)
        return line, offset - self.starts[line - 1] + 1

    def between(self, start: tuple[int, int], end: tuple[int, int]) -> str:
        return self.text[self.offset(*start) : self.offset(*end)]

    def of(self, node) -> str:
        """A node's text as written."""
        return self.between((node.span.line, node.span.column), (node.span.end_line, node.span.end_column))

    def kept(self, nodes: list) -> str:
        """The text of ``nodes`` (VAR blocks), padded so its line numbers are the file's (diagnostics point in it)."""
        if not nodes:
            return ""
        first = nodes[0].span
        return _keep_lines("\n".join(self.of(n) for n in nodes), (first.line, first.column))


class ReadSource(NamedTuple):
    """A file read into a project: its diagnostics, and among them the warnings a check of the project cannot
    repeat (on text the project does not keep, as a pragma above a PROGRAM, or about how the file was cut)."""

    project: Project | None
    diagnostics: list[Diagnostic]
    unkept: list[Diagnostic]


def source_to_project(
    text: str, name: str = "imported", *, nested_comments: bool = False
) -> tuple[Project | None, list[Diagnostic]]:
    read = read_source(text, name, nested_comments=nested_comments)
    return read.project, read.diagnostics


def read_source(text: str, name: str = "imported", *, nested_comments: bool = False) -> ReadSource:
    st_text, il_pous = blank_il_bodies(text)  # IL bodies are read from ``text`` (docs/il.md)
    parsed = parse_source(st_text, nested_comments=nested_comments)
    if parsed.ast is None:
        return ReadSource(None, parsed.diagnostics, [])
    source = _Text(text)
    diagnostics = list(parsed.diagnostics)
    kept: list[ast.Span] = []  # the items whose text the project keeps: the check reads them again
    types, globals_, pous, configurations = [], [], [], []
    gvls: list[tuple[str, bool, list[str]]] = []  # named lists: (name, qualified_only, block texts)
    listing = False  # the VAR_GLOBAL blocks go on the last list (no other item since its pragma)
    end = (1, 1)
    for item in parsed.ast.items:
        before, end = source.between(end, item.span[:2]), (item.span.end_line, item.span.end_column)
        heading = gvl_heading(before) if isinstance(item, ast.VarBlock) else None
        known = next((g for g in gvls if heading and g[0].upper() == heading[0].upper()), None)
        if known is not None:  # the list again: its blocks join it (pydantic refuses two lists of a name)
            message = f"a second global variable list called {known[0]}: its blocks are added to the first"
            diagnostics.append(Diagnostic(code="ST-DUPLICATE", message=message, line=item.span.line))
            gvls.append(gvls.pop(gvls.index(known)))
        elif heading is not None:
            gvls.append((*heading, []))
        listing = isinstance(item, ast.VarBlock) and (listing or heading is not None)
        if isinstance(item, (ast.VarBlock, ast.TypeBlock, ast.InterfaceDecl)) or (
            isinstance(item, ast.Pou) and item.sfc is None
        ):
            kept.append(item.span)
        if listing:
            gvls[-1][2].append(source.of(item))
        elif isinstance(item, ast.TypeBlock):
            head = source.between(item.span[:2], item.decls[0].span[:2]) if item.decls else ""
            types.append(block_text(item, source.of(item), head))
        elif isinstance(item, ast.InterfaceDecl):  # INTERFACEs live in the types text
            types.append(source.of(item))
        elif isinstance(item, ast.VarBlock):
            globals_.append(source.of(item))
        elif isinstance(item, ast.Pou) and item.sfc is not None:
            made, problems = _sfc_pou(item, source)
            pous.append(made)
            diagnostics += problems
        elif isinstance(item, ast.Pou):
            pous.append(_pou(item, source, "il" if item.name.upper() in il_pous else "st"))
        else:
            configurations.append(item)
    for extra in configurations[1:]:
        diagnostics.append(_problem(extra, "a project runs one CONFIGURATION: this second one is left out"))
    configuration = _configuration(configurations[0], source, diagnostics) if configurations else None
    project = Project(
        name=name,
        types="\n".join(types),
        globals="\n".join(globals_),
        gvls=[GlobalVariableList(name=n, qualified_only=q, text="\n".join(blocks)) for n, q, blocks in gvls],
        pous=pous,
        configuration=configuration,
    )
    own = diagnostics[len(parsed.diagnostics) :]  # how the file was cut: no check says it again
    unkept = [d for d in parsed.diagnostics if not _within(d, kept)] + own
    return ReadSource(project, diagnostics, [d for d in unkept if d.severity == "warning"])


def _within(diagnostic: Diagnostic, spans: list[ast.Span]) -> bool:
    """Whether a diagnostic lies in one of ``spans``."""
    at = (diagnostic.line or 0, diagnostic.column or 0)
    return any((span.line, span.column) <= at < (span.end_line, span.end_column) for span in spans)


def _pou(pou: ast.Pou, source: _Text, language: str) -> Pou:
    end = (pou.span.end_line, pou.span.end_column - len(f"END_{pou.kind}"))
    members = sorted(pou.methods + pou.properties + pou.actions, key=lambda m: (m.span.end_line, m.span.end_column))
    declarations, body = _parts(pou, pou.var_blocks + members, end, source, language)
    return Pou(
        name=pou.name,
        kind=_KIND[pou.kind],
        language=language,
        return_type=_type_text(pou.return_type, source),
        declarations=source.declarations(pou, _keep_lines(*declarations) if declarations[0] else ""),
        body=_keep_lines(*body),
        **_object_parts(pou, source),
    )


def _object_parts(pou: ast.Pou, source: _Text) -> dict[str, Any]:
    """The model fields of a POU's object orientation (methods, properties, actions, EXTENDS, ...), for an ST or IL
    POU and an SFC one alike."""
    return {
        "methods": [_method(method, source) for method in pou.methods],
        "properties": [_property(prop, source) for prop in pou.properties],
        "actions": [_action(action, source) for action in pou.actions],
        "extends": pou.extends,
        "implements": pou.implements,
        "abstract": pou.modifier == "ABSTRACT",
        "final": pou.modifier == "FINAL",
    }


def _parts(pou, leading: list, end: tuple[int, int], source: _Text, language: str = "st"):
    """A POU's or a method's declarations and body texts with where each starts: the VAR blocks, then the body
    after whatever ``leading`` holds (VAR blocks, then a function block's METHODs) up to ``end``."""
    declarations = ("", (1, 1))
    if pou.var_blocks:
        first, last = pou.var_blocks[0].span, pou.var_blocks[-1].span
        start = (first.line, first.column)
        declarations = (source.between(start, (last.end_line, last.end_column)), start)
    if leading:
        body_start = (leading[-1].span.end_line, leading[-1].span.end_column)
    else:
        body_start = (pou.body[0].span.line, pou.body[0].span.column) if pou.body else end
        if language == "il":  # the blanked IL body left no statements: it starts on the line after the header
            body_start = min((pou.span.line + 1, 1), end)
    return declarations, (source.between(body_start, end), body_start)


def _action(action: ast.ActionDecl, source: _Text) -> PouAction:
    """The statements between ``ACTION name:`` and ``END_ACTION``, as written."""
    end = (action.span.end_line, action.span.end_column - len("END_ACTION"))
    start = source.position(source.text.index(":", source.offset(action.span.line, action.span.column)) + 1)
    return PouAction(name=action.name, body=_keep_lines(source.between(start, end), start))


def _method(method: ast.MethodDecl, source: _Text) -> Method:
    end = (method.span.end_line, method.span.end_column - len("END_METHOD"))
    declarations, body = _parts(method, method.var_blocks, end, source)
    access = [m for m in method.modifiers if m in ("PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL")]
    return Method(
        name=method.name,
        access=access[-1] if access else "PUBLIC",
        final="FINAL" in method.modifiers,
        abstract="ABSTRACT" in method.modifiers,
        return_type=_type_text(method.return_type, source),
        declarations=source.declarations(method, _keep_lines(*declarations) if declarations[0] else ""),
        body=_keep_lines(*body),
    )


def _property(prop: ast.PropertyDecl, source: _Text) -> Property:
    accessors = {}
    for accessor in prop.accessors:
        end = (accessor.span.end_line, accessor.span.end_column - len(f"END_{accessor.kind}"))
        declarations, body = _parts(accessor, accessor.var_blocks, end, source)
        accessors[accessor.kind.lower()] = Accessor(
            declarations=_keep_lines(*declarations) if declarations[0] else "", body=_keep_lines(*body)
        )
    mode = source.monitored.get((prop.span.line, prop.span.column))
    first = next(iter(accessors), None)
    if mode is not None and first is not None:  # the model keeps it heading the GET's (else SET's) declarations
        head = accessors[first]
        headed = headed_by(monitoring_pragma(mode), head.declarations)
        accessors[first] = head.model_copy(update={"declarations": headed})
    access = [m for m in prop.modifiers if m in ("PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL")]
    return Property(
        name=prop.name, type=_type_text(prop.type, source) or "", access=access[-1] if access else "PUBLIC", **accessors
    )


def _type_text(spec: ast.TypeSpec | None, source: _Text) -> str | None:
    """A result type as written: STRING[20], ARRAY [1..3] OF INT, INT (0..100) ..."""
    if spec is None:
        return None
    span = spec.span
    return source.between((span.line, span.column), (span.end_line, span.end_column)).strip()


def _sfc_pou(pou: ast.Pou, source: _Text) -> tuple[Pou, list[Diagnostic]]:
    """A POU written in textual SFC: its declarations as typed, the chart drawn from its steps and transitions."""
    declarations = ""
    if pou.var_blocks:
        first, last = pou.var_blocks[0].span, pou.var_blocks[-1].span
        declarations = source.between((first.line, first.column), (last.end_line, last.end_column))
    body, problems = sfc_from_text(pou, source.between)
    kind = _KIND[pou.kind]
    made = Pou(
        name=pou.name, kind=kind, language="sfc", declarations=declarations, body=body, **_object_parts(pou, source)
    )
    return made, problems


def _keep_lines(body: str, start: tuple[int, int]) -> str:
    """Pad a slice so its line numbers match the file's (diagnostics then point into the original)."""
    return "\n" * (start[0] - 1) + " " * (start[1] - 1) + body


def _configuration(config: ast.Configuration, source: _Text, diagnostics: list[Diagnostic]) -> Configuration:
    """The AST of a CONFIGURATION as the project model holds it: texts of its VAR blocks, structured tasks."""
    resources = [item for item in config.items if isinstance(item, ast.Resource)]
    direct = [item for item in config.items if isinstance(item, (ast.TaskConfig, ast.ProgramConfig))]
    if direct:  # tasks and programs without a RESOURCE block: the configuration's single resource
        resources.insert(0, ast.Resource(None, None, list(direct), direct[0].span))
    return Configuration(
        name=config.name,
        globals=source.kept([i for i in config.items if isinstance(i, ast.VarBlock)]),
        resources=[_resource(r, source, diagnostics) for r in resources],
        access=source.kept([i for i in config.items if isinstance(i, ast.AccessBlock)]),
        config=source.kept([i for i in config.items if isinstance(i, ast.ConfigBlock)]),
    )


def _resource(resource: ast.Resource, source: _Text, diagnostics: list[Diagnostic]) -> Resource:
    programs = [_instance(p, diagnostics) for p in resource.items if isinstance(p, ast.ProgramConfig)]
    tasks = []
    for task in (i for i in resource.items if isinstance(i, ast.TaskConfig)):
        props = {}
        for prop, value in task.properties:
            if prop.upper() in props or prop.upper() not in ("INTERVAL", "SINGLE", "PRIORITY", "NUMBER"):
                message = f"task {task.name}: {prop} is not INTERVAL, SINGLE, PRIORITY or (Mosaic) NUMBER"
                diagnostics.append(_problem(value, message))
            props[prop.upper()] = value
        priority = props.get("PRIORITY")
        if priority is not None and not isinstance(priority, ast.IntLit):
            diagnostics.append(_problem(priority, f"task {task.name}: PRIORITY must be an integer literal"))
        single = print_expression(props["SINGLE"]) if "SINGLE" in props else None
        # Neither INTERVAL nor SINGLE (Mosaic: Number := n): a free-running task (CFG-04, CFG-05), the default cycle.
        interval = print_expression(props["INTERVAL"]) if "INTERVAL" in props else None if single else "T#10ms"
        tasks.append(
            Task(
                name=task.name,
                interval=interval,
                single=single,
                priority=priority.value if isinstance(priority, ast.IntLit) else 0,
                programs=[p for p, c in programs if (c.task or "").upper() == task.name.upper()],
            )
        )
    known = {t.name.upper() for t in tasks}
    for _, config in programs:
        if config.task is not None and config.task.upper() not in known:
            diagnostics.append(
                _problem(config, f"program {config.name}: there is no task {config.task} in this resource")
            )
    return Resource(
        name=resource.name,
        on=resource.on,
        globals=source.kept([i for i in resource.items if isinstance(i, ast.VarBlock)]),
        tasks=tasks,
        programs=[p for p, c in programs if c.task is None],
    )


def _instance(config: ast.ProgramConfig, diagnostics: list[Diagnostic]) -> tuple[ProgramInstance, ast.ProgramConfig]:
    inputs, outputs = {}, {}
    for arg in config.args or []:
        if arg.name is None:
            diagnostics.append(_problem(arg, f"program {config.name}: name each parameter (name := value)"))
        elif arg.output:
            outputs[arg.name] = print_expression(arg.value)
        else:
            inputs[arg.name] = print_expression(arg.value)
    instance = ProgramInstance(
        name=config.name, type=config.type_name, retain=config.retain, inputs=inputs, outputs=outputs
    )
    return instance, config


def _problem(node, message: str) -> Diagnostic:
    return Diagnostic(code="ST-CONFIG", message=message, line=node.span.line or None, column=node.span.column or None)
