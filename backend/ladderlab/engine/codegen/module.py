"""A whole IR Program -> one Python module's source, plus the tables that map it back to the IR."""

from __future__ import annotations

from dataclasses import dataclass

from ...ir import nodes as ir
from ...model.diagnostics import Diagnostic
from .context import CodegenError, ModuleContext, PausePoint, diagnostic
from .pou import emit_function, emit_inits, emit_instance_class, emit_struct
from .scope import global_owner
from .source import Source

VARIANTS = ("fast", "debug")


@dataclass
class Generated:
    """The source of one program in one variant, and what is needed to run it and explain faults."""

    source: str
    variant: str
    line_origins: list[int | None]
    origins: list[ir.Origin]
    origin_statements: dict[int, ir.Stmt]
    pauses: list[PausePoint]
    bound: dict[str, object]
    context: ModuleContext
    diagnostics: list[Diagnostic]

    @property
    def ok(self) -> bool:
        return not any(d.severity == "error" for d in self.diagnostics)


def generate(program: ir.Program, variant: str = "fast") -> Generated:
    if variant not in VARIANTS:
        raise ValueError(f"variant must be one of {', '.join(VARIANTS)}, not {variant!r}")
    module = ModuleContext(program, debug=variant == "debug")
    src = Source()
    src.line(f"# LadderLab generated code, {variant} variant: one class per PROGRAM / FUNCTION_BLOCK,")
    src.line("# one function per FUNCTION. IEC names appear as v_NAME (variables), P_NAME (POUs),")
    src.line("# f_NAME (functions), S_NAME (structures); ll_* are engine helpers.")
    src.line()
    for pou in module.pous.values():
        try:
            if pou.kind == "function":
                emit_function(module, pou, src)
            else:
                emit_instance_class(module, pou, src)
        except CodegenError as error:
            module.diagnostics.append(diagnostic(str(error), ir.Origin(pou.name)))
    _emit_globals(module, src)
    emitted: set[str] = set()
    while len(emitted) < len(module.structs):
        for struct, cls in list(module.structs.items()):
            if cls not in emitted:
                emitted.add(cls)
                emit_struct(module, struct, cls, src)
    return Generated(
        source=src.text(), variant=variant, line_origins=src.line_origins, origins=module.origins,
        origin_statements=module.origin_statements, pauses=module.pauses, bound=module.bound, context=module,
        diagnostics=module.diagnostics,
    )


def _emit_globals(module: ModuleContext, src: Source) -> None:
    layout = module.globals
    assert layout is not None
    for slot in program_globals(module):
        module.visit_type(slot.type)
    for page in range(layout.pages):
        src.line(f"class ll_Globals{page or ''}(ll_Addressable):")
        with src.indent():
            src.line("# VAR_GLOBAL" + (f", page {page}" if page else ""))
            src.line(f"__slots__ = {tuple(layout.page_attrs(page))!r}")
        src.line()
    src.line("def ll_init_globals(warm):")
    with src.indent():
        emit_inits(module, list(layout.places.values()), lambda p: f"{global_owner(p.page)}.{p.attr}", "globals", src)
    src.line()
    for page in range(layout.pages):
        src.line(f"{global_owner(page)} = ll_Globals{page or ''}()")


def program_globals(module: ModuleContext) -> list[ir.Slot]:
    return [p.slot for p in module.globals.places.values()]  # type: ignore[union-attr]


__all__ = ["Generated", "VARIANTS", "generate"]
