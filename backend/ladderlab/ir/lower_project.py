"""A whole project -> ``ir.Program``: the globals, every POU (slots and body blocks) and the tasks.

Bodies are lowered by language through ``LOWER_BODY`` (ST here; the LD and FBD
lowerings register themselves). The diagnostics are the project's whole check
(``validate_project`` + the ST checker, as ``ladderlab.simulation.check``) plus the
lowering's own; ``program`` is None as soon as any of them is an error.

Program instances and tasks come from ``lower_configuration`` (the project's tasks
or its configuration; a project without either runs every PROGRAM, in project order,
in one cyclic task ``DEFAULT_TASK`` every 10 ms: issue 4, a ``.st`` file without a
configuration).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ..collector import collector_paused
from ..deep import deep_call
from ..model.diagnostics import Diagnostic, has_errors
from ..model.places import ProjectPlaces
from ..model.project import Pou as ModelPou
from ..model.project import Project
from ..model.validate import validate_project
from ..st import types as st_types
from ..st.checker import check_project
from ..st.libraries import with_libraries
from ..st.symbols import CheckResult, PouInfo, Symbol
from .build_limits import data_too_large, source_too_large
from .context import PouContext
from .fb_init import after_init_chains, method_chains
from .lower_configuration import lower_configuration
from .lower_fbd import lower_cfc_body, lower_fbd_body
from .lower_il import lower_il_body
from .lower_ld import lower_ld_body
from .lower_sfc import lower_sfc_body
from .lower_st import lower_st_body
from .lower_types import LoweringError
from .method_outputs import declare_output_references
from .monitoring import accessor_notes, monitored_slots, monitored_table
from .nodes import Assign, Binary, Block, Origin, Pou, Program, Slot, Stmt, Unary, Var
from .types import BOOL

#: Body lowering per ``Pou.language``; the LD and FBD lowerings add "ld" and "fbd".
LOWER_BODY: dict[str, Callable[[ModelPou, PouContext], list[Block]]] = {
    "st": lower_st_body,
    "ld": lower_ld_body,
    "fbd": lower_fbd_body,
    "cfc": lower_cfc_body,
    "sfc": lower_sfc_body,
    "il": lower_il_body,
}

_KIND = {"PROGRAM": "program", "FUNCTION_BLOCK": "function_block", "FUNCTION": "function"}


@dataclass
class LoweringResult:
    program: Program | None
    diagnostics: list[Diagnostic]


def lower_project(project: Project, checked: CheckResult | None = None) -> LoweringResult:
    """Check (unless ``checked`` is given) and lower ``project``; never raises for any project content."""
    with collector_paused():  # see ladderlab.collector: the cyclic GC is most of the cost of a large build
        return deep_call(_lower_project, project, checked)  # recursion per nesting level: ladderlab.deep


def _lower_project(project: Project, checked: CheckResult | None) -> LoweringResult:
    with st_types.typing_rules(project.typing):  # the checker's type rules, which the lowering mirrors (in this thread)
        return _lower_typed_project(project, checked)


def _lower_typed_project(project: Project, checked: CheckResult | None) -> LoweringResult:
    project = with_libraries(project)
    too_large = source_too_large(project)
    if too_large is not None:  # refused before it is parsed: a build needs ~800 MB per MB of ST
        return LoweringResult(None, [too_large])
    if checked is None:
        checked = check_project(project)
    diagnostics = validate_project(project) + list(checked.diagnostics)
    image: dict[str, Slot] = {}  # addresses the bodies use without a declaration: located globals (ST-13)
    globals_ = lower_globals(checked, diagnostics)
    pous: dict[str, Pou] = {}
    models = {pou.name.upper(): pou for pou in project.pous}
    for pou in project.pous:
        info = checked.pou(pou.name)
        if info is not None and info.name == pou.name and pou.name.upper() not in pous:  # (a duplicate: reported)
            _lower_with_base(pou, info, _Lowering(checked, diagnostics, image, models, pous))
    for interface in checked.interfaces.values():  # prototypes: what a call through an interface passes
        for prototype in interface.methods.values():
            pous[prototype.name.upper()] = lower_pou(None, prototype, checked, diagnostics, image)
    instances, tasks, access = lower_configuration(checked, diagnostics, image)
    diagrams = [(pou.name, pou.body) for pou in project.pous if not isinstance(pou.body, str)]
    program = Program(pous, globals_ + list(image.values()), tasks, instances, access, ProjectPlaces(diagrams))
    program.dispatch = dispatch_tables(checked)
    program.fb_inits = method_chains(checked, "FB_INIT")
    program.fb_exits = method_chains(checked, "FB_EXIT")
    program.after_inits = after_init_chains(checked)
    program.monitored = monitored_table(checked)
    program.gvls = {key: {k: s.name.upper() for k, s in gvl.members.items()} for key, gvl in checked.gvls.items()}
    program.addresses = st_types.codesys_typing()
    program.base_bodies = frozenset(
        info.base.name.upper() for info in checked.pous.values() if info.runs_base_body and info.base is not None
    )
    too_much = data_too_large(program)
    if too_much is not None:
        diagnostics.append(too_much)
    return LoweringResult(None if has_errors(diagnostics) else program, diagnostics)


@dataclass
class _Lowering:
    """What lowering one POU after another shares: the check, the diagnostics, the located globals the bodies use,
    the model's POUs by upper-case name and the IR POUs lowered so far."""

    checked: CheckResult
    diagnostics: list[Diagnostic]
    image: dict[str, Slot]
    models: dict[str, ModelPou]
    pous: dict[str, Pou]


def _lower_with_base(pou: ModelPou, info: PouInfo, done: _Lowering) -> None:
    """``pou`` and its methods; a base whose body ``pou`` runs (SUPER^()) first, as its slots are ``pou``'s.
    (A module function, not a closure calling itself: that closure was a reference cycle holding the check's
    symbol tables until a collection; issue 27.)"""
    base = info.base if info.runs_base_body else None
    if base is not None and base.name.upper() not in done.pous and base.name.upper() in done.models:
        _lower_with_base(done.models[base.name.upper()], base, done)
    base_ir = done.pous.get(base.name.upper()) if base is not None else None
    done.pous[pou.name.upper()] = lower_pou(pou, info, done.checked, done.diagnostics, done.image, base_ir)
    for method in info.methods.values():
        done.pous[method.name.upper()] = lower_pou(None, method, done.checked, done.diagnostics, done.image)


def dispatch_tables(checked: CheckResult) -> dict[str, dict[str, str]]:
    """For each method that a derived function block overrides, and each INTERFACE's: which method each FB
    descending from its own (implementing the interface) runs for that name (dynamic dispatch, st/inheritance.py,
    st/interfaces.py). Methods nobody overrides are called directly."""
    blocks = [info for info in checked.pous.values() if info.kind == "FUNCTION_BLOCK"]
    tables: dict[str, dict[str, str]] = {}
    for owner in [*blocks, *checked.interfaces.values()]:
        for method in owner.methods.values():
            table = {}
            for fb in blocks:
                if fb.derives_from(owner) or fb.implements(owner):
                    found = fb.find_method(method.method.key)
                    if found is not None:
                        table[fb.name.upper()] = found.name.upper()
            if owner.kind == "INTERFACE" or any(name != method.name.upper() for name in table.values()):
                tables[method.name.upper()] = table
    return tables


def lower_globals(checked: CheckResult, diagnostics: list[Diagnostic]) -> list[Slot]:
    ctx = PouContext(checked, None, diagnostics)
    slots = (_slot(symbol, ctx, "globals") for symbol in checked.globals.values() if symbol.var_class == "VAR_GLOBAL")
    return [slot for slot in slots if slot is not None]


def lower_pou(
    pou: ModelPou | None,
    info: PouInfo,
    checked: CheckResult,
    diagnostics: list[Diagnostic],
    image: dict[str, Slot] | None = None,
    base: Pou | None = None,
) -> Pou:
    """One POU: a slot per declared variable (not VAR_EXTERNAL), the function result, the body blocks.
    ``image`` collects the addresses the body uses without a declaration (PouContext.direct). ``pou`` None: a
    METHOD (``info.method``), lowered as a function of ST whose in-out ``THIS`` is its instance. ``base``: the
    lowered base of a function block that runs its body (SUPER^()): its slots, hidden ones too, come first, in its
    order, so the base's body runs on an instance of this one."""
    ctx = PouContext(checked, info, diagnostics, image)
    if base is not None:
        ctx.reserve(base.slots)
    file = f"{info.name}/declarations"
    declared = [_slot(symbol, ctx, file) for symbol in info.symbols.values() if symbol.var_class != "VAR_EXTERNAL"]
    ctx.add_slots([slot for slot in declared if slot is not None])
    for slot in monitored_slots(info, ctx):
        if not ctx.has_slot(slot.name):
            ctx.add_slot(slot)
    ctx.before_return = declare_output_references(ctx)
    return_type = None
    if info.kind == "FUNCTION" and info.return_type is not None:
        try:
            return_type = ctx.types.type_of(info.return_type, info.return_spec)
            initial = ctx.types.default(info.return_type, info.return_spec)  # a TYPE's own initial value (TYP-11)
            ctx.add_slot(Slot(ctx.name, "VAR_OUTPUT", return_type, initial))
        except LoweringError as error:
            ctx.report_error(error, file=f"{info.name}/return_type")
    elif info.method is not None:  # a method without a value: the engine's functions all return one, never read
        return_type = BOOL
        ctx.add_slot(Slot(ctx.name, "VAR_OUTPUT", BOOL, False, hidden=True))
    noted, returned = accessor_notes(info, ctx)
    ctx.before_return += returned
    preamble = edge_preamble(ctx) + noted
    language, plant = (pou.language, pou.kind == "plant") if pou is not None else ("st", False)
    lower = LOWER_BODY.get(language)
    blocks: list[Block] = []
    if lower is None:
        ctx.report("IR-UNSUPPORTED", f"{language.upper()} POUs cannot be run yet")
    else:
        blocks = lower(pou, ctx)
    if ctx.before_return:  # (a method: ST, one block)
        if blocks:
            blocks[-1].statements.extend(ctx.before_return)
            blocks[-1].filled = None  # (its statements are no longer its template's)
        else:
            blocks.append(Block(list(ctx.before_return), Origin(ctx.name)))
    if preamble:
        if language == "st" and blocks:
            blocks[0].statements[:0] = preamble
        else:
            blocks.insert(0, Block(preamble, Origin(ctx.name)))
    if base is not None:
        ctx.slots = base_slots_first(base.slots, ctx.slots)
    kind = _KIND[info.kind]
    step_lines = info.il_step_lines if language == "il" else None
    return Pou(ctx.name, kind, ctx.slots, blocks, return_type, language, plant, step_lines=step_lines)  # type: ignore[arg-type]


def base_slots_first(base: list[Slot], own: list[Slot]) -> list[Slot]:
    """The slots of a function block that runs its base's body: the base's (its inherited variables, its hidden
    ones) in the base's order - the engine places each at the same attribute and page - then its own."""
    names = {slot.name.upper() for slot in base}
    return [*base, *(slot for slot in own if slot.name.upper() not in names)]


def _slot(symbol: Symbol, ctx: PouContext, file: str) -> Slot | None:
    try:
        return ctx.types.slot(symbol)
    except LoweringError as error:
        ctx.report_error(error, symbol, file)
        return None


def edge_preamble(ctx: PouContext) -> list[Stmt]:
    """R_EDGE / F_EDGE inputs (VAR-22): a hidden memory of the input and a hidden edge flag the body reads.

    ``edge := x AND NOT m`` (F_EDGE: ``NOT x AND m``) then ``m := x``, before the body.
    The input itself keeps the caller's value, so a call that does not pass it
    sees no new edge; the first call with a TRUE input is a rising edge, like R_TRIG.
    """
    out: list[Stmt] = []
    if ctx.info is None or ctx.info.kind == "FUNCTION":
        return out
    origin = Origin(ctx.name)
    for symbol in ctx.info.symbols.values():
        if symbol.edge is None or symbol.var_class != "VAR_INPUT" or symbol.type != st_types.BOOL:
            continue
        upper = symbol.name.upper()
        raw = Var("local", upper, BOOL)
        memory = ctx.hidden(f"{upper}_{symbol.edge}_M", BOOL)
        edge = ctx.hidden(f"{upper}_{symbol.edge}", BOOL, var_class="VAR_TEMP")
        if symbol.edge == "R_EDGE":
            detected = Binary("AND", raw, Unary("NOT", memory, BOOL), BOOL)
        else:
            detected = Binary("AND", Unary("NOT", raw, BOOL), memory, BOOL)
        out += [Assign(edge, detected, origin), Assign(memory, raw, origin)]
        ctx.edges[upper] = edge
    return out
