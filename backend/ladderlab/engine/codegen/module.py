"""A whole IR Program -> one Python module's source, plus the tables that map it back to the IR."""

from __future__ import annotations

from dataclasses import dataclass

from ...ir import nodes as ir
from ...model.diagnostics import Diagnostic
from ..variants import VARIANTS
from . import names
from .context import CodegenError, ModuleContext, PausePoint, diagnostic
from .layout import slots_source
from .pou import emit_function, emit_inits, emit_instance_class, emit_located_inits, emit_reference_inits, emit_struct
from .scope import global_owner
from .source import LazyPiece, Source
from .tasks import emit_tasks


@dataclass
class Generated:
    """The source of one program in one variant, and what is needed to run it and explain faults."""

    source: str
    variant: str
    pieces: list[tuple[int, int, int]]  # compiled separately: (first line, 0-based; start, end in ``source``)
    code_from: int  # pieces from this one on are the variant's code; those before, declarations
    lazy: dict[int, LazyPiece]  # piece index -> the function it defines, compiled at first use (compile.py)
    line_origins: list[int | None]
    origins: list[ir.Origin]
    origin_statements: list[ir.Stmt | None]  # by origin index
    pauses: list[PausePoint]
    bound: dict[str, object]
    context: ModuleContext
    diagnostics: list[Diagnostic]

    @property
    def ok(self) -> bool:
        return not any(d.severity == "error" for d in self.diagnostics)


def generate(program: ir.Program, variant: str = "fast") -> Generated:
    """The module: declarations (classes, globals, probe lists), then the variant's code (execute, functions).

    Declarations depend only on the IR and whether probes exist, so the monitor and
    debug variants of one program have the same, and a simulation can exchange the code.
    """
    if variant not in VARIANTS:
        raise ValueError(f"variant must be one of {', '.join(VARIANTS)}, not {variant!r}")
    module = ModuleContext(program, variant)
    decls, code = Source(), Source()
    decls.line("# LadderLab generated code: one class per PROGRAM / FUNCTION_BLOCK, one function per FUNCTION.")
    decls.line("# IEC names appear as v_NAME (variables), P_NAME (POUs), f_NAME (functions), S_NAME (structures);")
    decls.line("# ll_* are engine helpers. Declarations first, then the code of the variant.")
    decls.line()
    _emit_image(module, decls)
    code.line(f"# ---- {variant} variant: code")
    code.line()
    for pou in module.pous.values():
        try:
            if pou.kind == "function":
                emit_function(module, pou, decls, code)
            else:
                emit_instance_class(module, pou, decls, code)
        except CodegenError as error:
            module.diagnostics.append(diagnostic(str(error), ir.Origin(pou.name)))
    decls.piece()
    _emit_globals(module, decls)
    emit_tasks(module, code)
    _emit_dispatch(module, code)
    emitted: set[object] = set()  # by structure, not class name: each round emits at least one, so it ends
    while pending := [(struct, cls) for struct, cls in module.structs.items() if struct not in emitted]:
        for struct, cls in pending:  # emitting one may register the structures of its fields
            emitted.add(struct)
            emit_struct(module, struct, cls, decls)
    src = Source()
    src.extend(decls)
    src.piece()
    code_line = len(src.lines)
    src.extend(code)
    del decls, code  # their lists of lines: not held at the peak, when the text is joined
    pieces = _pieces(src)
    return Generated(
        source=src.text(),
        variant=variant,
        pieces=pieces,
        code_from=sum(1 for first in {0, *src.breaks} if first < code_line),
        lazy={index: src.lazy[first] for index, (first, _, _) in enumerate(pieces) if first in src.lazy},
        line_origins=src.line_origins,
        origins=module.origins,
        origin_statements=module.origin_statements,
        pauses=module.pauses,
        bound=module.bound,
        context=module,
        diagnostics=module.diagnostics,
    )


def _emit_dispatch(module: ModuleContext, code: Source) -> None:
    """Each overridden method's table: instance class -> the variant's function that implements it for that FB."""
    if not module.program.dispatch:
        return
    code.piece()
    for method, table in module.program.dispatch.items():
        entries = ", ".join(f"{names.pou_class(fb)}: {names.function(impl)}" for fb, impl in table.items())
        code.line(f"{names.dispatch_table(method)} = {{{entries}}}")
    code.line()


def _pieces(src: Source) -> list[tuple[int, int, int]]:
    """(first line, start, end character in ``src.text()``) of each piece."""
    lines = src.lines
    starts = sorted({0, *(b for b in src.breaks if b < len(lines))})
    offsets, at = [], 0
    for start, end in zip(starts, [*starts[1:], len(lines)]):
        offsets.append(at)
        at += sum(map(len, lines[start:end])) + end - start  # (each line and its newline)
    offsets.append(at)
    return list(zip(starts, offsets, offsets[1:]))


def _emit_globals(module: ModuleContext, src: Source) -> None:
    layout = module.globals
    assert layout is not None
    for slot in program_globals(module):
        module.visit_type(slot.type)
    target = lambda p: f"{global_owner(p.page)}.{p.attr}"  # noqa: E731
    instances = frozenset(i.name.upper() for i in module.instances)  # made once below, initialised in place
    for page in range(layout.pages):  # each page in its own compile piece
        src.piece()
        src.line(f"class ll_Globals{page or ''}(ll_Addressable):")
        with src.indent():
            src.line("# VAR_GLOBAL" + (f", page {page}" if page else ""))
            src.line(f"__slots__ = {slots_source(layout.page_attrs(page))}")
        src.line()
        src.line(f"def ll_init_globals{page or ''}(warm):")
        with src.indent():
            emit_inits(module, layout.page_places(page), target, "globals", src, instances)
            if not page:
                emit_located_inits(module, list(layout.located.values()), src)
            if not page:
                for later in range(1, layout.pages):
                    src.line(f"ll_init_globals{later}(warm)")
                emit_reference_inits(module, layout, global_owner, src)
        src.line()
    src.piece()
    for page in range(layout.pages):
        src.line(f"{global_owner(page)} = ll_Globals{page or ''}()")
    for instance in module.instances:  # made by the first ll_init_globals, initialised in place by the later ones
        src.line(f"{target(layout.places[instance.name.upper()])} = None")


def _emit_image(module: ModuleContext, src: Source) -> None:
    """The process image of the addresses the program uses, and the views its located variables go through."""
    located = module.located
    addresses = sorted({slot.address for slot in located})  # validated addresses (iec/addresses.py): safe text
    src.line(f"ll_image = ll_ProcessImage({tuple(addresses)!r})")
    worlds = (False, True) if module.world_views else (False,)
    for view in sorted({module.image_view(slot, world)[0] for slot in located for world in worlds}):
        area, kind = view[len("ll_io_") :].split("_", 1)
        src.line(f"{view} = ll_image.view({area!r}, {kind!r})")
    src.line()


def program_globals(module: ModuleContext) -> list[ir.Slot]:
    return [p.slot for p in module.globals.places.values()]


__all__ = ["Generated", "generate"]
