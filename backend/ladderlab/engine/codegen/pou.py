"""One POU -> Python: a class for a PROGRAM / FUNCTION_BLOCK, a function for a FUNCTION.

An instance class has ``__slots__`` for its variables, ``ll_init(warm)``
(cold: everything to its initial value; warm: RETAIN slots keep theirs, user
FB instances are re-initialised in place so their own RETAIN slots survive, then
get their declaration's values again)
and ``execute(now)``: the same protocol as the standard FBs (set inputs,
execute with the scan's clock, read outputs). VAR_TEMP slots are re-initialised
at every call. A FUNCTION is a Python function of its inputs (then its
VAR_IN_OUT references) returning its result; its variables are locals (VAR-43).
Classes are declarations, the same in the monitor and the debug variant;
``execute`` (with its chunk functions) and functions are code, which differs: in
the debug variant they are generators.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager, nullcontext

from ...ir import nodes as ir
from ...ir import types as t
from . import names
from .chunks import ChunkPlan
from .chunks import plan as chunk_plan
from .constructors import construct
from .context import CodegenError, ModuleContext, diagnostic
from .deferred import deferred_probes
from .expressions import literal
from .layout import Place, slots_source
from .mentions import boxed_locals
from .scope import Scope, framed_variables, global_owner
from .source import LazyPiece, Source
from .statements import Statements
from .typeinfo import is_composite


def _user_fb(module: ModuleContext, ty: t.IrType) -> bool:
    return isinstance(ty, t.FbInstance) and module.user_fb(ty.fb) is not None


def _init_value(module: ModuleContext, slot: ir.Slot, pou: str) -> str | None:
    """Source of a slot's fresh initial value (a reference cell for a VAR_IN_OUT); None after a diagnostic."""
    try:
        value = construct(slot.type, slot.initial, module)
    except CodegenError as error:
        module.diagnostics.append(diagnostic(f"{slot.name}: {error}", ir.Origin(pou)))
        return None
    return f"ll_ref({value})" if slot.var_class == "VAR_IN_OUT" else value


def emit_instance_class(module: ModuleContext, pou: ir.Pou, decls: Source, code: Source) -> None:
    """The class (slots, ``__init__``, ``ll_init``) into ``decls``; ``execute`` and its chunks into ``code``.

    ``execute`` is a function bound to the class afterwards (``P_X.execute = ll_x_X``), so a
    simulation can switch between the monitor and the debug code of its instances between scans.
    """
    cls = names.pou_class(pou.name)
    layout = module.layouts[pou.name.upper()]
    scope = Scope(module, pou)
    for slot in scope.slots.values():
        module.visit_type(slot.type)
    _emit_execute(module, pou, scope, code)  # first: it numbers the probes the class allocates
    key = names.escape(pou.name)
    for page in range(1, layout.pages):  # each page in its own compile piece (a 10,000-network POU has 110)
        decls.piece()
        decls.line(f"class {cls}_page{page}(ll_Addressable):")
        with decls.indent():
            decls.line(f"__slots__ = {slots_source(layout.page_attrs(page))}")
        decls.line()
        decls.line(f"def ll_i{page}_{key}(self, warm):")
        with decls.indent():
            decls.line(f"ll_p{page} = self.ll_p{page}")
            emit_inits(module, layout.page_places(page), _target, pou.name, decls)
        decls.line()
    decls.piece()
    decls.line(f"class {cls}(ll_Addressable):")
    with decls.indent():
        decls.line(f"# {pou.kind.upper().replace('_', ' ')} {names.comment_text(pou.name)} ({pou.language.upper()})")
        extra = [f"ll_p{page}" for page in range(1, layout.pages)] + (
            ["ll_pr", "ll_px", "ll_v"] if module.probes else []
        )
        decls.line(f"__slots__ = {slots_source(layout.page_attrs(0) + extra)}")
        decls.line()
        decls.line("def __init__(self):")
        with decls.indent():
            for page in range(1, layout.pages):
                decls.line(f"self.ll_p{page} = {cls}_page{page}()")
            if module.probes:
                table = module.probe_table(pou.name)
                decls.line(f"self.ll_pr = [ll_unset] * {len(table.elements)}")
                decls.line(f"self.ll_px = [-1] * {table.group_count}")
                decls.line(f"self.ll_v = [True] * {table.networks}  # networks viewed (Simulation.view)")
            decls.line("self.ll_init(False)")
        decls.line()
        _emit_init(module, pou, scope, decls)
    decls.line()
    if module.probes and pou.name.upper() in module.program.base_bodies:  # (statements.py, SUPER^())
        table = module.probe_table(pou.name)
        decls.line(f"{cls}.ll_super_probes = [ll_unset] * {len(table.elements)}, [-1] * {table.group_count}")
        decls.line()


def _emit_init(module: ModuleContext, pou: ir.Pou, scope: Scope, src: Source) -> None:
    layout = scope.layout
    assert layout is not None
    src.line("def ll_init(self, warm):")
    with src.indent():
        emit_inits(module, layout.page_places(0), _target, pou.name, src)
        emit_located_inits(module, list(layout.located.values()), src)
        for page in range(1, layout.pages):
            src.line(f"ll_i{page}_{names.escape(pou.name)}(self, warm)")
        emit_reference_inits(module, layout, lambda page: "self" if page == 0 else f"self.ll_p{page}", src)


def emit_reference_inits(module: ModuleContext, layout, holder, src: Source) -> None:
    """``r : REF_TO T := REF(x)``: each such reference is made once every slot of the scope is (``holder(page)``:
    the object holding a page of ``layout``; globals are held by their own pages)."""
    for place in layout.places.values():
        initial = place.slot.initial
        if not isinstance(initial, ir.ReferenceInit):
            continue
        if initial.scope == "local":
            target = layout.get(initial.name)
            owner = holder(target.page)
        else:
            target = module.globals.get(initial.name)
            owner = global_owner(target.page)
        container, key = owner, repr(target.attr)
        if initial.index:  # an array element: the list of its last dimension and its offset there
            container = f"{owner}.{target.attr}" + "".join(f"[{o}]" for o in _offsets(target.slot, initial)[:-1])
            key = str(_offsets(target.slot, initial)[-1])
        ref = f"ll_Ref({container}, {key}, {initial.text!r})"
        if initial.view is not None:
            ref = f"ll_seen({ref}, {initial.view[0]!r}, {initial.view[1]!r})"
        src.line(f"{holder(place.page)}.{place.attr} = {ref}")


def _offsets(array: ir.Slot, initial: ir.ReferenceInit) -> list[int]:
    """The list offsets of ``initial``'s element in the array slot (CodegenError: outside its bounds)."""
    dims = array.type.dims if isinstance(array.type, t.Array) else ()
    if len(dims) != len(initial.index) or any(not lo <= i <= hi for i, (lo, hi) in zip(initial.index, dims)):
        raise CodegenError(f"{initial.text}: the index is outside the array {array.name}")
    return [i - lo for i, (lo, _) in zip(initial.index, dims)]


def emit_located_inits(module: ModuleContext, slots: list[ir.Slot], src: Source) -> None:
    """Located variables declared with an initial value store it into the image (the others keep the image's)."""
    for slot in slots:
        if slot.initial is not None:
            view, key = module.image_view(slot)
            src.line(f"{view}[{key}] = {construct(slot.type, slot.initial, module)}")


def emit_inits(
    module: ModuleContext, places: list, target, owner: str, src: Source, kept: frozenset[str] = frozenset()
) -> None:
    """The body of an ``ll_init(warm)``: RETAIN slots only when cold, user FB instances in place when warm. The
    instances named in ``kept`` (upper case, None until made) are made once and then initialised in place, so
    references to them stay valid across restarts (program instances: a test's links to them). They come last: a
    program's reference to an element of a global array (``p : PTR_TO INT := ADR(arr[0])``) needs the array."""
    before = len(src.lines)
    instances = [p for p in places if p.slot.name.upper() in kept] if kept else []
    if kept:
        places = [p for p in places if p.slot.name.upper() not in kept]
    retained = [p for p in places if p.slot.retain]
    if retained:
        src.line("if not warm:")
        with src.indent():
            _plain_inits(module, retained, target, owner, src)
    fresh: list = []
    for place in places:
        if place.slot.retain:
            continue
        if not _user_fb(module, place.slot.type):
            fresh.append(place)
            continue
        _plain_inits(module, fresh, target, owner, src)
        fresh = []
        src.line("if warm:")
        with src.indent():
            src.line(f"{target(place)}.ll_init(True)")
            _declared_again(module, target(place), place.slot.type, place.slot.initial, src)
        src.line("else:")
        with src.indent():
            value = _init_value(module, place.slot, owner)
            src.line(f"{target(place)} = {value}" if value is not None else "pass")
    _plain_inits(module, fresh, target, owner, src)
    for place in instances:
        src.line(f"if {target(place)} is None:")
        with src.indent():
            src.line(f"{target(place)} = {_init_value(module, place.slot, owner)}")
        src.line("elif not warm:" if place.slot.retain else "else:")
        with src.indent():
            src.line(f"{target(place)}.ll_init({'False' if place.slot.retain else 'warm'})")
    if len(src.lines) == before:
        src.line("pass")


def _declared_again(module: ModuleContext, target: str, ty: t.IrType, initial: object, src: Source) -> None:
    """After a warm restart re-initialised the instance ``target`` in place with its FB's values (its RETAIN
    variables keep theirs), the values its declaration gives the others (``fb : F := (x := 1)``), as a cold start
    makes it with them."""
    user = module.user_fb(ty.fb) if isinstance(ty, t.FbInstance) else None
    if user is None or not isinstance(initial, tuple):
        return
    layout = module.layouts[user.name.upper()]
    for name, value in initial:
        place = layout.get(name)
        if place is None or place.page or place.slot.retain:
            continue  # (a cold start reports what it cannot make)
        member = f"{target}.{place.attr}"
        if _user_fb(module, place.slot.type):
            _declared_again(module, member, place.slot.type, value, src)
            continue
        try:
            src.line(f"{member} = {construct(place.slot.type, value, module)}")
        except CodegenError:
            continue


def _plain_inits(module: ModuleContext, places: list, target, owner: str, src: Source) -> None:
    """Initialise slots; consecutive slots of one object with one immutable literal value share one ``ll_fill``
    (a 10,000-network POU has runs of a dozen FALSE slots: one call compiles much faster than the assignments).
    ``target(place)`` is ``<the object holding the place's page>.<its attribute>``."""
    run: list[str] = []  # attributes of ``holder``
    holder = shared = ""
    page, mine = -1, ""  # the page of the last place and the object holding it
    #: the value of a slot with a scalar initial value (the lowering gives one to each slot declared without: its
    #: type's default) and whether it is immutable, by its type's identity and that value: the same for each slot of
    #: that type object (a 50,000-network POU has 200,000 slots of a handful of types and values; each entry holds its
    #: type, which so keeps its id)
    values: dict[tuple[int, type, object], tuple[t.IrType, str, bool]] = {}
    for place in places:
        slot = place.slot
        initial = slot.initial
        key = (
            (id(slot.type), type(initial), initial)
            if type(initial) in _SHARED and slot.var_class != "VAR_IN_OUT"
            else None
        )
        known = values.get(key) if key is not None else None
        if known is None:
            value = _init_value(module, slot, owner)
            if value is None:
                continue
            immutable = _immutable(value)
            if key is not None:
                values[key] = slot.type, value, immutable
        else:
            _, value, immutable = known
        if place.page != page:
            page, mine = place.page, target(place).rpartition(".")[0]
        if run and (not immutable or value != shared or mine != holder):
            _fill(holder, run, shared, src)
            run = []
        if immutable:
            run.append(place.attr)
            holder, shared = mine, value
        else:
            src.line(f"{mine}.{place.attr} = {value}")
    if run:
        _fill(holder, run, shared, src)
    _pin_constants(module, places, target, src)


#: the kinds of initial value whose slots of one type object share their initialiser's text (not floats: -0.0 and 0.0
#: are equal keys; the kinds apart: 1 and True are too)
_SHARED = (type(None), bool, int, str)


def _pin_constants(module: ModuleContext, places: list[Place], target: Callable[[Place], str], src: Source) -> None:
    """The constant inputs the standard FB instances among ``places`` hold from their making on (constant_inputs.py),
    set once they are made: one ``ll_pins`` per object, pin and value (``ll_pins(self, 'v_T0 v_T1', 'PT', 100)``),
    which compiles as one call where ``ll_with(fb_TON(), PT=100)`` per instance costs a call each."""
    constants = module.constant_slots
    if not constants:
        return
    runs: dict[tuple[str, str, str], list[str]] = {}
    for place in [place for place in places if id(place.slot) in constants]:
        holder, _, attr = target(place).rpartition(".")
        for pin, value in constants[id(place.slot)]:
            runs.setdefault((holder, pin, literal(value)), []).append(attr)
    for (holder, pin, value), attrs in runs.items():
        src.line(f"ll_pins({holder}, {' '.join(attrs)!r}, {pin!r}, {value})")


def _fill(holder: str, attrs: list[str], value: str, src: Source) -> None:
    if len(attrs) == 1:
        src.line(f"{holder}.{attrs[0]} = {value}")
    else:
        src.line(f"ll_fill({holder}, {' '.join(attrs)!r}, {value})")


def _immutable(value: str) -> bool:
    """A literal (number, string, TRUE/FALSE), never a constructed list or object that must not be shared."""
    return value.startswith("(-") or ("(" not in value and not value.startswith("["))


def _target(place) -> str:
    return f"{'self' if place.page == 0 else f'll_p{place.page}'}.{place.attr}"


def _emit_execute(module: ModuleContext, pou: ir.Pou, scope: Scope, src: Source) -> None:
    """``ll_x_NAME(self, now)``: VAR_TEMP initialisation, then the body inline or its chunk functions in order.

    A body whose VAR_TEMP need a frame (``scope.framed``: scope.framed_variables) makes a ``runtime.Frame`` per
    call, ended however the call ends (``try``/``finally``), and is never chunked: the frame is a local of
    ``execute``."""
    cls, key = names.pou_class(pou.name), names.escape(pou.name)
    scope.framed = framed_variables(module, pou)
    plan = chunk_plan(pou.blocks, chunked=not scope.framed)
    deferred = frozenset(deferred_probes(pou)) if module.variant == "monitor" else frozenset()
    calls, reads = [], []
    if not plan.inline:
        for number in range(len(plan.chunks)):
            chunk = names.chunk_function(number, key)
            start = len(src.lines)
            src.piece()
            src.line(f"def {chunk}(self, now{', ll_b' if plan.jumps else ''}):")
            first, last = plan.chunks[number][0].origin, plan.chunks[number][-1].origin
            if first.network is not None:
                with src.indent():
                    src.line(f"# networks {names.comment_text(first.network)} .. {names.comment_text(last.network)}")
            table = module.probe_table(pou.name) if module.probes else None
            runs = table.networks if table is not None else 0
            reads.append(_emit_chunk(scope, plan, number, src, deferred))
            src.line()
            if table is not None and table.networks > runs and not module.debug and not plan.jumps:
                calls.append(_emit_unviewed_twin(scope, plan, number, key, src, (runs, table.networks)))
                src.lazy[start] = LazyPiece(chunk, pou.name.upper(), range(runs, table.networks))
            else:
                calls.append(f"{chunk}(self, now)")
    src.piece()
    execute = names.execute_function(pou.name)
    src.line(f"def {execute}(self, now):")
    with src.indent():
        src.line(f"# {cls}.execute")
        if scope.framed:  # references into this call's VAR_TEMP dangle once it returns
            src.line(_new_frame(pou))
        loaded: set[int] = set()
        for slot in scope.slots.values():
            if slot.var_class == "VAR_TEMP":
                value = _init_value(module, slot, pou.name)
                local = scope.temp_locals.get(slot.name.upper())
                if local is not None and plan.inline:  # the body is right here: the local is the variable
                    src.line(f"{local} = {value}")
                    continue
                place = scope.layout.get(slot.name)  # type: ignore[union-attr]
                if place.page and place.page not in loaded:
                    loaded.add(place.page)
                    src.line(f"ll_p{place.page} = self.ll_p{place.page}")
                if value is not None:
                    src.line(f"{_target(place)} = {value}")
        if plan.inline:
            with _ending_frame(scope, src):
                reads.append(_emit_chunk(scope, plan, 0, src, deferred, prologue_depth=0))
        elif plan.jumps:
            _emit_dispatch(module, plan, [call.removesuffix("(self, now)") for call in calls], src)
        else:
            if any("ll_view" in call for call in calls):
                src.line("ll_view = self.ll_v")
            for call in calls:
                src.line(f"if (yield from {call}): return" if module.debug else f"if {call}: return")
        if module.debug:
            src.line("return")
            src.line("yield  # a generator even when no pause point is reached")
    src.line(f"{cls}.execute = {execute}")
    src.line()
    if any(reads):
        _emit_reader(cls, key, reads, src)


@contextmanager
def _ending_frame(scope: Scope, src: Source) -> Iterator[None]:
    """The body emitted inside ends the call's frame however it leaves (its end, a RETURN, a fault), if it has one."""
    if not scope.framed:
        yield
        return
    src.line("try:")
    with src.indent():
        yield
    src.line("finally:")
    with src.indent():
        src.line("ll_fr.end(None)")


def _emit_unviewed_twin(
    scope: Scope, plan: ChunkPlan, number: int, key: str, src: Source, runs: tuple[int, int]
) -> str:
    """The chunk once more without probes (the fast variant's code), run while none of its ``runs`` (first, end)
    of networks is viewed; returns the call choosing between the two. The chunk with its ``if ll_view[u]:`` runs
    holds every run twice, and that code, never run, still costs the cache room of a large program (~1.5x the
    fast scan at 10,000 networks with nothing viewed): its twin scans like the fast variant."""
    twin = names.chunk_function(number, key).replace("ll_k", "ll_kf", 1)
    src.piece()
    src.line(f"def {twin}(self, now):")
    with src.indent():
        src.line("# the chunk above without probes: none of its networks is viewed")
    _emit_chunk(scope, plan, number, src, frozenset(), probes=False)
    src.line()
    chunk = names.chunk_function(number, key)
    return f"({chunk} if True in ll_view[{runs[0]}:{runs[1]}] else {twin})(self, now)"


def _emit_reader(cls: str, key: str, reads: list[list[str]], src: Source) -> None:
    """``ll_read_probes(self)``: store the deferred probes' values (codegen/deferred.py), one part per chunk."""
    parts = []
    for number, lines in enumerate(reads):
        if lines:
            parts.append(f"ll_r{number}_{key}")
            src.piece()
            src.line(f"def {parts[-1]}(self, ll_pr):")
            with src.indent():
                for page in sorted({int(page) for line in lines for page in _PAGE.findall(line)}):
                    src.line(f"ll_p{page} = self.ll_p{page}")
                for line in lines:
                    src.line(line)
            src.line()
    src.piece()
    src.line(f"def ll_r_{key}(self):")
    with src.indent():
        src.line("# the probes read after the scan, when a monitor asks")
        for part in parts:
            src.line(f"{part}(self, self.ll_pr)")
    src.line(f"{cls}.ll_read_probes = ll_r_{key}")
    src.line()


_PAGE = re.compile(r"\bll_p(\d+)\.")


def _emit_chunk(
    scope: Scope,
    plan: ChunkPlan,
    number: int,
    src: Source,
    deferred: frozenset[int],
    prologue_depth: int = 1,
    probes: bool = True,
) -> list[str]:
    """The statements of one chunk, after loading the pages, references and probe lists they use (``probes``
    False: without its probes, ``_emit_unviewed_twin``).

    Returns the lines reading its deferred probes."""
    module = scope.module
    body = Source()
    body.depth = src.depth + prologue_depth
    scope.pages_used, scope.temps_used = set(), set()
    statements = Statements(scope, body, plan, number, deferred)
    if not probes:
        statements.probes = None
    statements.body()
    # a chunk function takes its temporaries from the slots and hands them on (scope.temp_locals); an inline
    # body has them from the VAR_TEMP initialisation, and after it they are dead
    handed = {name: scope.slot_source(name) for name in sorted(scope.temps_used)} if prologue_depth else {}
    if number < len(plan.chunks) - 1:
        for name, slot in handed.items():
            body.line(f"{slot} = {scope.temp_locals[name]}")
    with src.indent() if prologue_depth else nullcontext():
        for page in sorted(scope.pages_used):
            src.line(f"ll_p{page} = self.ll_p{page}")
        for name, slot in handed.items():
            src.line(f"{scope.temp_locals[name]} = {slot}")
        for slot in scope.in_outs:
            src.line(f"r_{names.escape(slot.name)} = self.{_slot_attr(scope, slot)}")
            _unpack_reference(slot, src)
        if statements.probed:
            src.line("ll_pr, ll_px, ll_k = self.ll_pr, self.ll_px, ll_scan")
        if statements.guarded:
            src.line("ll_view = self.ll_v")
        src.extend(statements.outlines)
        src.extend(body)
        if module.debug and prologue_depth:
            src.line("return")
            src.line("yield  # a generator even when no pause point is reached")
    return statements.reads


def _emit_dispatch(module: ModuleContext, plan: ChunkPlan, calls: list[str], src: Source) -> None:
    """Run the chunk holding segment ``ll_b`` until one returns -1 (the end, or a RETURN)."""
    src.line("ll_b = 0")
    src.line("while ll_b >= 0:")
    with src.indent():
        for number, chunk in enumerate(calls):
            call = f"{chunk}(self, now, ll_b)"
            run = f"ll_b = yield from {call}" if module.debug else f"ll_b = {call}"
            if number == len(calls) - 1:
                src.line("else:")
            else:
                src.line(f"{'if' if number == 0 else 'elif'} ll_b < {plan.first_segment[number + 1]}:")
            with src.indent():
                src.line(run)


def _slot_attr(scope: Scope, slot: ir.Slot) -> str:
    place = scope.layout.get(slot.name)  # type: ignore[union-attr]
    return place.attr if place.page == 0 else f"ll_p{place.page}.{place.attr}"  # type: ignore[union-attr]


def _unpack_reference(slot: ir.Slot, src: Source) -> None:
    key = names.escape(slot.name)
    if is_composite(slot.type):
        src.line(f"{names.slot(slot.name)} = r_{key}[0][r_{key}[1]]")
    else:
        src.line(f"ll_c_{key}, ll_k_{key} = r_{key}")


def emit_function(module: ModuleContext, pou: ir.Pou, decls: Source, code: Source) -> None:
    """The function into ``code`` (never chunked: its variables are locals); its probe lists into ``decls``."""
    scope = Scope(module, pou)
    scope.boxed = boxed_locals(module.mentions(pou))
    scope.framed = framed_variables(module, pou)
    scope.result_slot()  # raises when missing
    inputs = [s for s in pou.slots if s.var_class == "VAR_INPUT"]
    params = [names.slot(s.name) for s in inputs] + [f"r_{names.escape(s.name)}" for s in scope.in_outs]
    body = Source()
    body.depth = code.depth + 1
    statements = Statements(scope, body, chunk_plan(pou.blocks, chunked=False))
    statements.body()
    code.piece()
    code.line(f"def {names.function(pou.name)}({', '.join(params)}):")
    with code.indent():
        code.line(f"# FUNCTION {names.comment_text(pou.name)} ({pou.language.upper()})")
        if scope.framed:  # references into this call dangle once it returns (runtime.Frame)
            code.line(_new_frame(pou))
        for slot in scope.in_outs:
            _unpack_reference(slot, code)
        for slot in inputs:
            if slot.name.upper() in scope.boxed:
                code.line(f"{names.slot(slot.name)} = [{names.slot(slot.name)}]")
        for slot in scope.slots.values():
            if slot.var_class in ("VAR_INPUT", "VAR_IN_OUT"):
                continue
            module.visit_type(slot.type)
            try:
                value = construct(slot.type, slot.initial, module)
            except CodegenError as error:
                module.diagnostics.append(diagnostic(f"{slot.name}: {error}", ir.Origin(pou.name)))
                continue
            boxed = slot.name.upper() in scope.boxed
            code.line(f"{names.slot(slot.name)} = {'[' + value + ']' if boxed else value}")
        if statements.probed:
            key = names.escape(pou.name)
            code.line(f"ll_pr, ll_px, ll_k = ll_pr_{key}, ll_px_{key}, ll_scan")
        code.extend(statements.outlines)
        code.extend(body)
        code.line(scope.return_statement())
        if module.debug:
            code.line("yield  # a generator even when no pause point is reached")
    code.line()
    if module.probes:
        table = module.probe_table(pou.name)
        key = names.escape(pou.name)
        decls.line(
            f"ll_pr_{key} = [ll_unset] * {len(table.elements)}  # probes of FUNCTION {names.comment_text(pou.name)}"
        )
        decls.line(f"ll_px_{key} = [-1] * {table.group_count}")


def _new_frame(pou: ir.Pou) -> str:
    """The line making a call's ``runtime.Frame``, named as the fault names the call (a METHOD is an ``<FB>.<M>``
    function: no FUNCTION has a dot)."""
    kind = pou.kind.upper() if pou.kind != "function" else "METHOD" if "." in pou.name else "FUNCTION"
    return f"ll_fr = ll_Frame({pou.name!r}{'' if kind == 'FUNCTION' else f', {kind!r}'})"


def emit_struct(module: ModuleContext, struct: t.Struct, cls: str, src: Source) -> None:
    attrs = tuple(names.slot(f.name) for f in struct.fields)
    src.line(f"class {cls}(ll_Structure):")
    with src.indent():
        src.line(f"# STRUCT {names.comment_text(struct.name)}")
        src.line(f"__slots__ = ll_fields = {attrs!r}")
        src.line()
        src.line("def __init__(self):")
        with src.indent():
            for f, attr in zip(struct.fields, attrs):
                try:
                    src.line(f"self.{attr} = {construct(f.type, f.initial, module)}")
                except CodegenError as error:
                    module.diagnostics.append(diagnostic(f"{struct.name}.{f.name}: {error}", None))
            if not struct.fields:
                src.line("pass")
    src.line()
