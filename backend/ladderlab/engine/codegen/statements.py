"""IR statements and blocks -> Python statements.

Loops check the watchdog on their back-edge, counting down one budget per scan:
the task's countdown lives in ``ll_wb[0]``; the outermost loop of a function
copies it into the local ``ll_w`` on entry (nested loops count on that same
local: an inner loop does not start a fresh count) and stores it back when it
ends or returns, so loops in called POUs draw on the same budget. The clock is
read when the countdown runs out, every ``WATCHDOG_EVERY`` back-edges
(``ll_wd``). A POU whose blocks are jump targets runs them inside a dispatch
loop (``ll_b`` is the segment to resume at; a jump sets it and ``continue``s,
backward jumps are back-edges of that loop). A long body is split into chunk functions (chunks.py); a jump to
another chunk returns its target segment. The monitor and debug variants record
probes (``ll_pr[i] = value``, and ``ll_px[g] = ll_k`` once per straight run of
code: context.ProbeTable). In the debug variant every pause point is
``if ll_halt[id]: yield (id, self)``; the debugger arms ``ll_halt``.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager, nullcontext
from typing import ClassVar

from ...iec.values import article, store_expr
from ...ir import nodes as ir
from ...ir import types as t
from ...ir.types import describe
from . import names
from .chunks import ChunkPlan
from .context import CodegenError, diagnostic, std_fb_class
from .expressions import Expressions, literal
from .inline_fbs import inline_body
from .liveness import dead_stores
from .mentions import calls_in, expression_vars, nested, walk
from .runtime import UNSET
from .scope import Scope
from .source import Source
from .typeinfo import is_composite, runtime_name, store_code, store_whole


class Statements:
    """Emits the statements of one chunk of a POU body (``plan``: its chunks and segments, chunks.py)."""

    def __init__(
        self, scope: Scope, src: Source, plan: ChunkPlan, chunk: int = 0, deferred: frozenset[int] = frozenset()
    ) -> None:
        self.scope = scope
        self.module = scope.module
        self.x = Expressions(scope)
        self.src = src
        self.plan = plan
        self.chunk = chunk
        self.loops = 0  # ST loops around the statement being emitted (EXIT needs one)
        self.blocks = 0  # Python loops around it in the function being written (CPython allows 20)
        self.outlined = False  # writing an outlined body (``_outline``): RETURN and EXIT return a signal
        #: The nested functions of outlined bodies; the POU's emitter puts them at the top of its function.
        self.outlines = Source()
        self.outlines.depth = src.depth
        self.segment = plan.first_segment[chunk]
        self.now = "ll_now" if scope.function or scope.pou.live_clock else "now"
        self.me = "None" if scope.function else "self"
        self.debug = self.module.debug
        self.probes = self.module.probe_table(scope.pou.name) if self.module.probes else None
        self.group: int | None = None  # the probe group of the straight run of code being emitted
        self.probed = False  # a probe was emitted: the chunk loads ll_pr, ll_px, ll_k
        self.guarded = False  # a network's probes depend on ``ll_v`` (``block``): the chunk loads it (``ll_view``)
        self.network: int | None = None  # the viewed network whose probes are being emitted
        self._following: ir.Probe | None = None  # the probe after the statement being emitted
        self._fused = False  # the last assignment also recorded the probe after it
        #: The last ``ll_pr[i] = <temporary> = value`` line (``_set``): its Source, line count after it, group,
        #: temporary and probe number, for a probe right after it of the same temporary (``_same_probe``)
        self._probed_temp: tuple[Source, int, int | None, str, int] | None = None
        #: the last line of an inlined FB body when it stores an output: (its source, line index, ``ll_fb.Q``, the
        #: value stored)
        self._output_line: tuple[Source, int, str, str] | None = None
        #: the last inlined FB body (``_output_into``): its source, first line index, line count after it, FB type,
        #: known inputs, indentation depth and origin
        self._inline_lines: tuple[Source, int, int, str, tuple[tuple[str, str], ...], int, int | None] | None = None
        self.deferred = deferred  # id() of the probes read after the scan (deferred.py)
        self.reads: list[str] = []  # their ``ll_pr[i] = value`` lines, for the chunk's ll_read_probes part
        self._line: int | None = None
        self.counting = False  # ``ll_w`` holds the watchdog countdown (inside a loop or the jump dispatch loop)
        #: id() of the statements whose store into a temporary local nothing reads (liveness.py), left out where no
        #: probe is recorded
        self.dead: set[int] = set()
        #: id() of the stores into a temporary local only the next statement reads (liveness.py, ``_fold``), mapped
        #: to whether a variable's read may replace it there; where no probe is recorded
        self.folds: dict[int, bool] = {}
        #: id() of the networks filled in from a lowering template whose liveness is their template's for the
        #: temporaries live after them (liveness.py, ``_Known``): those temporaries and their statements walked
        self.filled_liveness: dict[int, tuple[frozenset[str], list[ir.Stmt]]] = {}
        self.temps = frozenset(scope.temp_locals.values())  # the temporaries' locals
        if scope.temp_locals and not self.debug:
            temps = frozenset(scope.temp_locals)
            live_out = frozenset() if plan.inline else temps  # (the next chunk takes the temporaries over)
            self.dead, self.folds = dead_stores(
                plan.chunks[chunk], temps, live_out, self.module.probes, self.filled_liveness
            )

    # ------------------------------------------------------------------ blocks

    def body(self) -> None:
        """This chunk's blocks: in a dispatch loop over its segments when the POU jumps."""
        blocks = self.plan.chunks[self.chunk]
        if not blocks:  # an empty body (a new LD/FBD POU has no network yet)
            self.src.line("pass")
            return
        if not self.plan.jumps:
            for run in self._runs(blocks):
                self.view_run(run)
            return
        for block in self.plan.duplicates:
            if any(block is mine for mine in blocks):
                self._report(f"label {block.label} is used twice", block.origin)
        if self.plan.inline:
            self.src.line("ll_b = 0")
        self.src.line("ll_w = ll_wb[0]")
        self.counting = True
        self.src.line("while True:")
        with self.src.indent():
            segment = self.segment - 1
            for i, block in enumerate(blocks):
                if block.label is not None or i == 0:
                    segment += 1
                    self.segment = segment
                    self.src.line(f"if ll_b <= {segment}:")
                with self.src.indent():
                    self.view_run([block])
            self._store_countdown()
            self.src.line("break" if self.plan.inline else f"return {self.plan.ends(self.chunk)}")
        self.counting = False

    def _runs(self, blocks: list[ir.Block]) -> Iterator[list[ir.Block]]:
        """The blocks in runs that share one view flag (``view_run``): up to VIEW_RUN consecutive viewable networks
        (a flag per network would cost a sixth of a plain network's scan), every other block alone."""
        run: list[ir.Block] = []
        for block in blocks:
            viewable = self._viewable(block)
            if run and (not viewable or len(run) == VIEW_RUN):
                yield run
                run = []
            if viewable:
                run.append(block)
            else:
                yield [block]
        if run:
            yield run

    def view_run(self, run: list[ir.Block]) -> None:
        """Blocks whose probes the monitor variant stores only while a client views them: ``if ll_view[u]:`` the
        blocks with their probes, ``else:`` without (the fast variant's code). ``u`` numbers the run in the POU's
        ProbeTable (``networks``, ``network_of``), the same in the debug variant, which stores every probe."""
        unit = self.probes.new_network() if self._viewable(run[0]) else None  # type: ignore[union-attr]
        if unit is None or self.debug:
            for block in run:
                self.block(block, unit)
            return
        self.guarded = True
        self.src.line(f"if ll_view[{unit}]:  # viewed by a monitor: record the power flow")
        with self.src.indent():
            for block in run:
                self.block(block, unit)
        self.src.line("else:")
        with self.src.indent():
            probes, self.probes = self.probes, None
            try:
                for block in run:
                    self.block(block)
            finally:
                self.probes = probes

    def block(self, block: ir.Block, unit: int | None = None) -> None:
        """One block; ``unit``: its run of viewed networks (``view_run``), whose blocks each start a probe group."""
        origin = block.origin
        if origin.network is not None:
            self.src.line(
                f"# network {names.comment_text(origin.network)}"
                + (f" label {names.comment_text(block.label)}" if block.label else "")
            )
            self._line = None
        if self.module.debug:
            with self.src.at(self.module.origin(origin)):
                self.pause("network" if origin.network is not None else "entry", origin)
        if unit is None:
            if (
                self.scope.templates is not None
                and self.probes is None
                and origin.network is not None
                and not self.plan.jumps
            ):
                self.scope.templates.emit(self, block, not self.plan.straight)  # (a network of this shape before)
            else:
                self.statements(block.statements, own_group=not self.plan.straight)
            return
        self.network = unit
        self.statements(block.statements)
        self.network, self.group = None, None  # the probes after it run whether or not it was viewed

    def _viewable(self, block: ir.Block) -> bool:
        """Whether the monitor variant stores the block's probes only while it is viewed (``ll_v``): a network of
        a PROGRAM or FUNCTION_BLOCK body (not of one a derived FB runs with ``SUPER^()``, whose probes go
        elsewhere). Else its probes are stored in every scan."""
        pou = self.scope.pou
        return not (
            self.probes is None
            or block.origin.network is None
            or pou.kind == "function"
            or self.scope.function
            or pou.name.upper() in self.module.program.base_bodies
        )

    def statements(self, statements: list[ir.Stmt], own_group: bool = True) -> None:
        """``own_group``: the probes here start a group of their own (else the blocks of a straight
        chunk share one, so a scan stamps it once per chunk)."""
        deep = own_group and statements and (self.src.depth >= OUTLINE_DEPTH or self.blocks >= OUTLINE_BLOCKS)
        if deep and not any(isinstance(x, ir.Jump) for x in walk(statements)):  # (a jump stays in its function)
            self._outline(statements)
            return
        before = len(self.src.lines)
        outer = self.group
        if own_group:
            self.group = None
        fused = False
        probes = self.probes is not None
        if not probes:  # the fast variant records none: more than half the statements of an LD/FBD body
            dead = self.dead
            statements = [
                s for s in statements if type(s) is not ir.Probe and not (type(s) is ir.Assign and id(s) in dead)
            ]
        self.x.alias = None
        self.x.forward = {}
        folds = self.folds if not probes else None
        folded: tuple[str, str] | None = None  # a temporary's local and the value the statement reads in its place
        for i, s in enumerate(statements):
            if fused:  # the previous statement recorded this probe
                fused = False
                continue
            if type(s) is not ir.Assign and type(s) is not ir.Probe:
                self.x.alias = None  # (only an assignment surely leaves ``ll_fb`` as the last FB call set it)
                self.x.forward = {}
            if folded is not None:
                self.x.forward[folded[0]] = folded[1]
            if folds and isinstance(s, ir.Assign) and id(s) in folds:
                fold = self._fold(s, folds[id(s)])  # (its value may read the one before, folded too)
                if fold is not None:
                    if folded is not None:
                        self.x.forward.pop(folded[0], None)
                    folded = fold
                    continue
            if probes:
                following = statements[i + 1] if i + 1 < len(statements) else None
                self._following = following if isinstance(following, ir.Probe) else None
            self._fused = False
            self.statement(s)
            if folded is not None:
                self.x.forward.pop(folded[0], None)
                folded = None
            fused = self._fused and isinstance(s, (ir.Assign, ir.FnCall))
            if not isinstance(s, _STRAIGHT) and not _straight(s):
                self.group = None  # what follows may run without what came before
        self.x.alias = None
        self.x.forward = {}
        if own_group:
            self.group = outer
        if all(line.lstrip().startswith("#") for line in self.src.lines[before:]):  # nothing but comments, or nothing
            self.src.line("pass")

    def pause(self, kind: str, origin: ir.Origin, element: str | None = None) -> None:
        pid = self.module.pause(kind, origin, element)
        self.src.line(f"if ll_halt[{pid}]: yield ({pid}, {self.me})")

    # ------------------------------------------------------------------ statements

    def statement(self, s: ir.Stmt) -> None:
        origin = s.origin
        if origin.line is not None and origin.line != self._line and origin.network is None:
            self._line = origin.line
            self.src.line(f"# line {origin.line}")
        oid = self.module.origin(origin, s)
        mark, saved = len(self.src.lines), self.src.origin
        self.src.origin = oid  # (not Source.at: this runs once per statement of 10,000-network programs)
        self.x.sink = self.src  # a deep expression's parts are computed on lines before the statement
        try:
            if self.debug and origin.line is not None and not isinstance(s, ir.Probe):
                stops = self.scope.pou.step_lines  # IL: a step stops at loads, jumps and calls only (ON-04)
                self.pause("statement" if stops is None or origin.line in stops else "line", origin)
            handler = self._HANDLERS.get(type(s))
            if handler is None:
                raise CodegenError(f"unknown statement {type(s).__name__}")
            handler(self, s, oid)
        except CodegenError as error:
            del self.src.lines[mark:], self.src.line_origins[mark:]
            self._report(str(error), origin)
        finally:
            self.src.origin = saved

    def _report(self, message: str, origin: ir.Origin) -> None:
        self.module.diagnostics.append(diagnostic(message, origin))

    def _assign(self, s: ir.Assign, oid: int) -> None:
        self.store(s.target, s.value, self._take_probe())

    def _take_probe(self) -> ir.Probe | None:
        """The probe right after this statement, which it may record itself (see ``_set``)."""
        probe, self._following, self._fused = self._following, None, False
        return probe

    def _set(self, code: str, value: str, probe: ir.Probe | None) -> None:
        """``code = value``; a ``probe`` of the target or of the very variable stored is recorded in the same
        statement (``ll_pr[i] = self.v_X = ...``: one load less per element in the monitor variant)."""
        if probe is not None and id(probe) in self.deferred:
            self.src.line(f"{code} = {value}")
            self._defer(probe)
            self._fused = True
        elif probe is not None and isinstance(probe.value, ir.Var) and self.x.expr(probe.value) in (code, value):
            source = self._same_probe(value)
            index = self._record(probe)
            comment = names.comment_text(probe.element)
            if source is not None:
                self.probes.aliases[index] = source  # type: ignore[union-attr]  # a probe was just recorded
                self.src.line(f"{code} = {value}  # ll_pr[{index}] is ll_pr[{source}]  # {comment}")
            else:
                stored = code if self._output_into(code, value) else f"{code} = {value}"
                self.src.line(f"ll_pr[{index}] = {stored}  # {comment}")
                if code in self.temps:
                    self._probed_temp = (self.src, len(self.src.lines), self.group, code, index)
            self._fused = True
            self._paused(probe)
        elif self._chained(code, value) or (probe is None and self._output_into(code, value)):
            return
        else:
            self.src.line(f"{code} = {value}")

    def _same_probe(self, value: str) -> int | None:
        """The probe number whose store holds ``value`` already, so a probe of it need not be stored (a coil right
        after the contact or box that computed its power flow: ``ll_pr[i] = ll_t___P_1 = ..`` then
        ``self.v_C = ll_t___P_1``): the line before (comments aside) stored that temporary with its probe, in the
        same group, so both probes are recorded together or not at all. Only in the monitor variant's viewed networks
        (``block``): the debug variant can halt between the two and shows the elements that ran so far, and a
        FUNCTION's probe lists are part of a captured state, which a debug simulation may restore
        (``ProbeTable.aliases``; the monitor variant fills them in when it switches to the debug one)."""
        last = self._probed_temp
        if last is None or self.debug or self.network is None or self.group is None:
            return None
        src, count, group, temp, index = last
        if src is not self.src or group != self.group or temp != value:
            return None
        if any(not line.lstrip().startswith("#") for line in src.lines[count:]):
            return None
        return index

    def _chained(self, code: str, value: str) -> bool:
        """``code = value`` merged into the line before when that line is an inlined FB body's last, storing the
        output ``value`` reads (``ll_fb.Q = ll_fb.CV >= 5``): ``self.v_Y0 = ll_fb.Q = ll_fb.CV >= 5`` spares the
        read of the output just stored. Exact: nothing runs between, and both stores are plain attribute stores
        (the target's order does not matter: neither store can fault or be seen before the other)."""
        held = self._output_line
        if held is None or held[0] is not self.src or len(self.src.lines) != held[1] + 1 or held[2] != value:
            return False
        if not _PLAIN_CHAIN.fullmatch(code):
            return False
        line = self.src.lines[held[1]]
        indent = line[: len(line) - len(line.lstrip())]
        self.src.lines[held[1]] = f"{indent}{code} = {value} = {held[3]}"
        self._output_line = self._inline_lines = None  # (the body is no longer as inline_body wrote it)
        return True

    def _output_into(self, code: str, value: str) -> bool:
        """``code = value`` done by the inlined FB body just emitted when ``code`` is a temporary local and ``value``
        an output of that body's instance (``ll_t___P_3 = ll_fb.Q`` after a TON): the body is emitted again storing
        the output into the local wherever it stores it (``inline_fbs._output_copied``), sparing the read of the
        output. Exact: nothing runs between the body and the copy, and the local then holds what the output holds."""
        held = self._inline_lines
        if held is None or held[0] is not self.src or len(self.src.lines) != held[2] or code not in self.temps:
            return False
        pin = value.removeprefix("ll_fb.")
        if pin == value or not pin.isidentifier():
            return False
        src, first, _, fb, known, depth, origin = held
        lines = inline_body(fb, "ll_fb", self.now, known, (pin, code))
        if lines is None:
            return False
        src.lines[first:] = ["    " * depth + line if line else "" for line in lines]
        src.line_origins[first:] = [origin] * len(lines)
        self._inline_lines = self._output_line = None
        return True

    def store(self, target: ir.Var, value: ir.Expr, probe: ir.Probe | None = None) -> None:
        forward = self.x.forward
        if forward and (calls_in(value) or calls_in(target)):
            forward.clear()  # a call may write any variable before the read
        code, ty = self.x.access(target)
        if isinstance(ty, t.FbInstance):
            raise CodegenError("an FB instance cannot be assigned")
        if is_composite(ty):
            self.src.line(f"ll_assign({code}, {store_whole(self.x.expr(value), value.type, ty)})")
            forward.clear()
            return
        stored = self.x.stored(value, ty)
        self._set(code, stored, probe)
        self._forward(code, stored)

    def _fold(self, s: ir.Assign, once: bool) -> tuple[str, str] | None:
        """The temporary's local and the value of ``s`` (a store into it that only the next statement reads,
        liveness.py) when the next statement reads that value in its place (None: ``s`` is emitted): a local or a
        constant, or, where the next statement is an assignment reading the temporary once, any value of at most
        ``FOLDED_PARENTHESES`` parentheses (computing it once there instead of here changes nothing: it is pure)."""
        if not once and isinstance(s.value, ir.Var) and s.value.path:
            return None  # (an FB's output, ``ll_fb.Q``: a read of memory)
        code, ty = self.x.access(s.target)
        value = self.x.stored(s.value, ty)
        if value in self.temps or value.isdigit() or value in ("True", "False"):
            return code, value
        if once and value.count("(") <= FOLDED_PARENTHESES:
            return code, value
        return None

    def _forward(self, code: str, stored: str) -> None:
        """After ``code = stored``: where no probe is recorded, reads of the variable ``code`` take the temporary
        local ``stored`` until anything but an assignment to a temporary local runs (a store to memory may reach
        the variable through another path). Exact: the variable holds that very value meanwhile."""
        forward = self.x.forward
        if code in self.temps:
            for key in [key for key, local in forward.items() if local == code]:
                del forward[key]  # the local changes: the variable no longer holds it
            return
        forward.clear()
        if self.probes is None and not self.debug and stored in self.temps and _PLAIN_CHAIN.fullmatch(code):
            forward[code] = stored

    def _if(self, s: ir.If, oid: int) -> None:
        if self.probes is None and _only_probes(s):
            return  # e.g. the EN-guarded probes of a box: nothing left to run in the fast variant
        self._chain([(self._condition(cond), body) for cond, body in s.branches], s.orelse)

    def _condition(self, e: ir.Expr) -> tuple[str, Source]:
        """A condition's source and the lines that compute its parts first (a deep expression), unplaced."""
        before = Source()
        before.origin = self.src.origin
        saved, self.x.sink = self.x.sink, before
        try:
            return self.x.expr(e), before
        finally:
            self.x.sink = saved

    def _chain(self, branches: list[tuple[tuple[str, Source], list[ir.Stmt]]], orelse: list[ir.Stmt]) -> None:
        """``if``/``elif``/``else`` over (condition, body) pairs. CPython's compiler recurses once per ``elif``,
        and a condition computed on lines of its own cannot follow an ``elif``, so a chain longer than
        CHAIN_BRANCHES, or one with such a condition after its first branch, continues in flat groups:
        ``if ll_pendingN:``, where ``ll_pendingN`` says that no branch has been taken yet (not ``ll_pN``: that is
        the local holding page N of a POU's slots)."""
        split = [i for i, ((_, before), _) in enumerate(branches) if i and (i % CHAIN_BRANCHES == 0 or before.lines)]
        pending = self.scope.temp("pending") if split else None
        if pending:
            self.src.line(f"{pending} = False")
        starts = [0, *split]
        for number, start in enumerate(starts):
            group = branches[start : starts[number + 1] if number + 1 < len(starts) else len(branches)]
            last = number + 1 == len(starts)
            with self.src.indent() if start else nullcontext():
                if start:
                    self.src.line(f"{pending} = False")
                for i, ((condition, before), body) in enumerate(group):
                    if before.lines:
                        self._place(before)
                    self.src.line(f"{'elif' if i else 'if'} {condition}:")
                    with self.src.indent():
                        self.statements(body)
                if not last:
                    self.src.line("else:")
                    with self.src.indent():
                        self.src.line(f"{pending} = True")
                elif orelse and not pending:
                    self.src.line("else:")
                    with self.src.indent():
                        self.statements(orelse)
                elif orelse:
                    self.src.line("else:")
                    with self.src.indent():
                        self.src.line(f"{pending} = True")
            if not last:
                self.src.line(f"if {pending}:")
        if orelse and pending:
            self.src.line(f"if {pending}:")
            with self.src.indent():
                self.statements(orelse)

    def _place(self, before: Source) -> None:
        """Write lines computed for a condition at the current depth."""
        for line, origin in zip(before.lines, before.line_origins):
            saved, self.src.origin = self.src.origin, origin
            self.src.line(line)
            self.src.origin = saved

    def _case(self, s: ir.Case, oid: int) -> None:
        selector = self.scope.temp("sel")
        self.src.line(f"{selector} = {self.x.expr(s.selector)}")
        branches = []
        for labels, body in s.branches:
            tests = []
            singles = [label for label in labels if isinstance(label, int)]
            if singles:
                tests.append(
                    f"{selector} == {literal(singles[0])}"
                    if len(singles) == 1
                    else f"{selector} in ({', '.join(map(literal, singles))})"
                )
            for label in labels:
                if isinstance(label, tuple):
                    lo, hi = label
                    tests.append(f"{literal(lo)} <= {selector} <= {literal(hi)}")
                elif not isinstance(label, int) or isinstance(label, bool):
                    raise CodegenError(f"CASE label {label!r} is not an integer")
            branches.append(((" or ".join(tests) or "False", Source()), body))
        if not branches:
            branches.append((("False", Source()), []))
        self._chain(branches, s.orelse)

    @contextmanager
    def _counted(self) -> Iterator[None]:
        """Around a loop: the outermost one of the function takes the task's countdown and gives it back."""
        if self.counting:
            yield
            return
        self.src.line("ll_w = ll_wb[0]")
        self.counting = True
        try:
            yield
        finally:
            self.counting = False
        self._store_countdown()

    def _store_countdown(self) -> None:
        self.src.line("ll_wb[0] = ll_w")

    def _back_edge(self, oid: int) -> None:
        self.src.line("ll_w -= 1")
        self.src.line(f"if not ll_w: ll_w = ll_wd({oid})")

    def _loop_body(self, body: list[ir.Stmt]) -> None:
        self.loops += 1
        self.blocks += 1
        try:
            self.statements(body)
        finally:
            self.loops -= 1
            self.blocks -= 1

    def _outline(self, statements: list[ir.Stmt]) -> None:
        """Emit a deeply nested body as a nested function defined at the top of the function being written
        and call it here: CPython's tokenizer allows 100 levels of indentation and its compiler 20 nested
        loops per function. The function sees the POU's variables as the body would (a FUNCTION's locals
        through ``nonlocal``); it returns 1 for an EXIT of a loop around it, 2 for a RETURN, 3 for a CONTINUE."""
        name = self.scope.temp("o")
        body = Source()
        body.depth, body.origin = self.outlines.depth + 1, self.src.origin
        saved = self.src, self.blocks, self.outlined, self.counting
        # its loops take the watchdog countdown from ll_wb[0] and give it back, as a called POU's do
        self.src, self.blocks, self.outlined, self.counting = body, 0, True, False
        exits = self.loops > 0
        try:
            self.statements(statements)
        finally:
            self.src, self.blocks, self.outlined, self.counting = saved
        self.outlines.line(f"def {name}():")
        with self.outlines.indent():
            if self.scope.function:
                local = [names.slot(s.name) for s in self.scope.slots.values() if _bound_local(s)]
                if local:
                    self.outlines.line(f"nonlocal {', '.join(local)}")
        self.outlines.extend(body)
        with self.outlines.indent():
            self.outlines.line("return 0")
            if self.debug:
                self.outlines.line("yield  # a generator even when no pause point is reached")
        signal = self.scope.temp("s")
        if self.counting:
            self._store_countdown()
        self.src.line(f"{signal} = yield from {name}()" if self.debug else f"{signal} = {name}()")
        if self.counting:
            self.src.line("ll_w = ll_wb[0]")
        kinds = {type(x) for x in walk(statements)}
        if exits and ir.Exit in kinds:
            self.src.line(f"if {signal} == 1: break")
        if exits and ir.Continue in kinds:
            self.src.line(f"if {signal} == 3: continue")
        if ir.Return in kinds:
            self.src.line(f"if {signal} == 2: {self._return_text()}")

    def _for(self, s: ir.For, oid: int) -> None:
        var, ty = self.x.access(s.var)
        if is_composite(ty):
            raise CodegenError(f"a FOR variable cannot be {article(describe(ty))}")
        self.store(s.var, s.start)
        values = self.scope.temp("r")
        end, step = self.x.expr(s.end), self.x.expr(s.step)
        if isinstance(s.step, ir.Const) and isinstance(s.step.value, int) and s.step.value:
            stop = f"{end} + 1" if s.step.value > 0 else f"{end} - 1"
            self.src.line(f"{values} = range({var}, {stop}, {step})")
        else:
            self.src.line(f"{values} = ll_for_range({var}, {end}, {step})")
        with self._counted():
            self.src.line(f"for {var} in {values}:")
            with self.src.indent():
                self._back_edge(oid)
                self._loop_body(s.body)
            self.src.line("else:")  # normal end: the first value that failed the test (ST-71), stored like any value
            with self.src.indent():
                self.src.line(f"if {values}: {var} = {self._next(values, ty)}")

    def _next(self, values: str, ty: t.IrType) -> str:
        """The value after the last one of the range, stored in the FOR variable's type."""
        stored = store_expr(f"{values}[-1] + {values}.step", runtime_name(ty))  # type: ignore[arg-type]
        if isinstance(ty, t.Subrange):
            return f"ll_sub({stored}, {ty.low!r}, {ty.high!r})"
        return stored

    def _while(self, s: ir.While, oid: int) -> None:
        condition, before = self._condition(s.cond)
        with self._counted():
            if not before.lines:
                self.src.line(f"while {condition}:")
                with self.src.indent():
                    self._back_edge(oid)
                    self._loop_body(s.body)
                return
            self.src.line("while True:")  # the condition's parts are computed before each test
            with self.src.indent():
                self._back_edge(oid)
                self._place(before)
                self.src.line(f"if not {condition}:")
                with self.src.indent():
                    self.src.line("break")
                self._loop_body(s.body)

    def _repeat(self, s: ir.Repeat, oid: int) -> None:
        if _continues(s.body):
            self._repeat_continued(s, oid)
            return
        with self._counted():
            self.src.line("while True:")
            with self.src.indent():
                self._back_edge(oid)
                self._loop_body(s.body)
                with self.src.at(oid):
                    self.src.line(f"if {self.x.expr(s.until)}:")
                    with self.src.indent():
                        self.src.line("break")

    def _repeat_continued(self, s: ir.Repeat, oid: int) -> None:
        """A REPEAT whose body CONTINUEs: the UNTIL test opens every iteration but the first, so ``continue`` (the
        next iteration) tests it as IEC says, and EXIT's ``break`` still leaves the loop."""
        first = self.scope.temp("f")
        self.src.line(f"{first} = True")
        with self._counted():
            self.src.line("while True:")
            with self.src.indent():
                with self.src.at(oid):
                    self.src.line(f"if not {first} and {self.x.expr(s.until)}:")
                    with self.src.indent():
                        self.src.line("break")
                self.src.line(f"{first} = False")
                self._back_edge(oid)
                self._loop_body(s.body)

    def _exit(self, s: ir.Exit, oid: int) -> None:
        if not self.loops:
            raise CodegenError("EXIT outside a loop")
        self.src.line("return 1" if self.outlined and not self.blocks else "break")

    def _continue(self, s: ir.Continue, oid: int) -> None:
        if not self.loops:
            raise CodegenError("CONTINUE outside a loop")
        self.src.line("return 3" if self.outlined and not self.blocks else "continue")

    def _return(self, s: ir.Return, oid: int) -> None:
        if self.counting:
            self._store_countdown()
        self.src.line(self._return_text())

    def _return_text(self) -> str:
        if self.outlined:  # out of an outlined body: its caller returns (``_outline``)
            return "return 2"
        if self.plan.inline:
            return self.scope.return_statement()
        return "return -1" if self.plan.jumps else "return True"  # out of a chunk function: execute stops

    def _jump(self, s: ir.Jump, oid: int) -> None:
        target = self.plan.segments.get(s.label.upper()) if self.plan.jumps else None
        if target is None:
            raise CodegenError(f"jump to unknown label {s.label}")
        if self.loops:
            raise CodegenError("a jump cannot leave a loop")
        if s.cond is not None:
            self.src.line(f"if {self.x.expr(s.cond)}:")
        with self.src.indent() if s.cond is not None else nullcontext():
            if self.plan.segment_chunk[target] != self.chunk:  # to another chunk: execute dispatches it
                if target <= self.segment:  # a back-edge of the dispatch
                    self._back_edge(oid)
                self._store_countdown()
                self.src.line(f"return {target}")
                return
            if target <= self.segment:  # backward (or to its own segment): a loop back-edge
                self._back_edge(oid)
            self.src.line(f"ll_b = {target}")
            self.src.line("continue")

    def _probe(self, s: ir.Probe, oid: int) -> None:  # (the fast variant never gets here: see ``statements``)
        if id(s) in self.deferred:
            self._defer(s)
        elif isinstance(s.value, ir.Const):  # the table holds the value: only the group stamp says it ran
            value = self.x.const_value(s.value)
            self.src.line(f"# ll_pr[{self._record(s, value)}] is {literal(value)}  # {names.comment_text(s.element)}")
        else:
            self.src.line(f"ll_pr[{self._record(s)}] = {self.x.expr(s.value)}  # {names.comment_text(s.element)}")
        self._paused(s)

    def _record(self, s: ir.Probe, constant: object = UNSET) -> int:
        """Number the probe (opening a group, with its stamp line, when none is open); its index in ``ll_pr``."""
        self.probed = True
        if self.group is None:
            self.group = self.probes.new_group()  # type: ignore[union-attr]
            self.src.line(f"ll_px[{self.group}] = ll_k")
        origin = -1 if self.src.origin is None else self.src.origin  # (a statement's: ``statement`` sets it)
        return self.probes.probe(s.element, self.group, origin, constant, self.network)  # type: ignore[union-attr]

    def _defer(self, s: ir.Probe) -> None:
        index = self._record(s)
        self.probes.deferred.append(index)  # type: ignore[union-attr]
        var: ir.Var = s.value  # type: ignore[assignment]  # deferred.py: a variable of the program, members only
        self.probes.deferred_paths[index] = ".".join([var.name, *(m.name for m in var.path)])  # type: ignore
        # read after the scan, in another function: no lines before it, no local of this one
        saved, self.x.sink, alias, self.x.alias = self.x.sink, None, self.x.alias, None
        try:
            self.reads.append(f"ll_pr[{index}] = {self.x.expr(s.value)}  # {names.comment_text(s.element)}")
        finally:
            self.x.sink, self.x.alias = saved, alias
        self.src.line(f"# ll_pr[{index}] is read after the scan  # {names.comment_text(s.element)}")

    def _paused(self, s: ir.Probe) -> None:
        if self.module.debug:
            self.pause(s.kind, s.origin, s.element)

    # ------------------------------------------------------------------ calls

    def _guarded(self, en: ir.Expr | None, eno: ir.Var | None, emit) -> None:
        """Run ``emit`` under EN (when given) and set ENO: TRUE when it ran, FALSE when EN was FALSE."""
        if en is None:
            emit()
            return
        self.src.line(f"if {self.x.expr(en)}:")
        with self.src.indent():
            emit()
        if eno is not None:
            self.src.line("else:")
            with self.src.indent():
                self.src.line(f"{self.x.var(eno)} = False")

    def _fbcall(self, s: ir.FbCall, oid: int) -> None:
        code, ty = self.x.access(s.instance)
        if not isinstance(ty, t.FbInstance):
            raise CodegenError(f"{s.instance.name} is not an FB instance")
        user = self.module.user_fb(ty.fb)
        if user is None and std_fb_class(ty.fb) is None:
            raise CodegenError(f"unknown function block {ty.fb}")

        def emit() -> None:
            fb = "ll_fb"  # FB calls do not nest: one temporary serves them all
            self.src.line(f"{fb} = {code}")
            known = []
            once = self.stored_once(s) if inline_body(ty.fb, fb, self.now) is not None else frozenset()
            for pin, value in s.inputs:
                assigned = self._fb_input(fb, ty, user, pin, value, pin.upper() not in once)
                if assigned is not None and _local_or_constant(assigned[1]):
                    known.append(assigned)
            call = f"{fb}.execute({self.now})"
            inline = None if user is not None or self.module.debug else inline_body(ty.fb, fb, self.now, tuple(known))
            if s.body is not None:
                self._base_body(fb, s.body)
            elif inline is not None and not self.module.program.mockable:  # the body of its execute (inline_fbs.py)
                first = len(self.src.lines)
                for line in inline:
                    self.src.line(line)
                last = _OUTPUT_STORE.fullmatch(inline[-1])
                if s.en is None:
                    if last is not None and self.probes is None:
                        self._output_line = (self.src, len(self.src.lines) - 1, last[1], last[2])
                    where = (self.src.depth, self.src.origin)
                    self._inline_lines = (self.src, first, len(self.src.lines), ty.fb, tuple(known), *where)
            elif inline is not None:  # a unit test may mock the instance: the body for the FB's own class only
                self.src.line(f"if {fb}.__class__ is {names.std_fb(ty.fb.upper())}:")
                with self.src.indent():
                    for line in inline:
                        self.src.line(line)
                self.src.line("else:")
                with self.src.indent():
                    self.src.line(call)
            else:
                self.src.line(f"yield from {call}" if user is not None and self.module.debug else call)
            for pin, target in s.outputs:
                owner, attr = self.x.member_parts(fb, ty, pin)
                pin_type = self.x.member_type(ty, pin)
                self._copy_out(f"{owner}.{attr}", pin_type, target)
            if eno is not None:
                self.src.line(f"{self.x.var(eno)} = True")

        eno = self._eno(s)
        self._guarded(s.en, eno, emit)
        if s.en is None and user is None and not self.debug and _PLAIN_CHAIN.fullmatch(code):
            self.x.alias = (code, "ll_fb")  # the outputs read next: ``ll_fb.Q``, not ``self.v_T1.Q`` again

    def stored_once(self, s: ir.FbCall) -> frozenset[str]:
        """The inputs of a standard FB call that its instance holds from its initialisation on, so an inlined call
        does not store them (constant_inputs.py; not in the debug variant, which calls ``execute``)."""
        if self.module.debug or s.instance.scope != "local" or s.instance.path:
            return _NONE_STORED
        return self.module.constant_pin_names.get((self.scope.pou.name.upper(), s.instance.name.upper()), _NONE_STORED)

    def _eno(self, s: ir.FbCall | ir.FnCall) -> ir.Var | None:
        """The call's ENO target, None when it has none or its store is dead where no probe is recorded."""
        return None if self.probes is None and id(s) in self.dead else s.eno

    def _base_body(self, fb: str, base: str) -> None:
        """``SUPER^()``: the base's body on the instance ``fb``; its probes go to the base class's
        ``ll_super_probes`` meanwhile, not into the instance's own (numbered for its own body)."""
        run = f"{names.execute_function(base)}({fb}, {self.now})"
        run = f"yield from {run}" if self.module.debug else run
        if not self.module.probes:
            self.src.line(run)
            return
        saved = self.scope.temp("own_probes")
        self.src.line(f"{saved} = {fb}.ll_pr, {fb}.ll_px")
        self.src.line(f"{fb}.ll_pr, {fb}.ll_px = {names.pou_class(base)}.ll_super_probes")
        self.src.line("try:")
        with self.src.indent():
            self.src.line(run)
        self.src.line("finally:")
        with self.src.indent():
            self.src.line(f"{fb}.ll_pr, {fb}.ll_px = {saved}")

    def _fb_input(
        self, fb: str, ty: t.FbInstance, user: ir.Pou | None, pin: str, value: ir.Expr, store: bool = True
    ) -> tuple[str, str] | None:
        """Assign an input pin (``store`` False: the instance holds it already, ``stored_once``); returns (attribute
        of ``fb``, code assigned) for a scalar input of ``fb`` itself."""
        owner, attr = self.x.member_parts(fb, ty, pin)
        pin_type = self.x.member_type(ty, pin)
        if user is not None:
            slot = self.module.layouts[user.name.upper()].get(pin).slot  # type: ignore[union-attr]
            if slot.var_class == "VAR_IN_OUT":
                if not isinstance(value, ir.Var):
                    raise CodegenError(f"VAR_IN_OUT {pin} needs a variable")
                self.src.line(f"{owner}.{attr} = {self.x.in_out_argument(value, slot.type)}")
                return None
            if slot.var_class != "VAR_INPUT":
                raise CodegenError(f"{pin} is not an input of {user.name}")
        elif pin.upper() not in std_fb_class(ty.fb).INPUTS:  # type: ignore[union-attr]
            raise CodegenError(f"{pin} is not an input of {ty.fb}")
        if is_composite(pin_type):
            self.src.line(f"ll_assign({owner}.{attr}, {store_whole(self.x.expr(value), value.type, pin_type)})")
            return None
        code = self.x.stored(value, pin_type)
        if store:
            self.src.line(f"{owner}.{attr} = {code}")
        return (attr, code) if owner == fb else None

    def _copy_out(
        self, source: str, source_type: t.IrType, target: ir.Var, checked: bool = True, probe: ir.Probe | None = None
    ) -> None:
        """Copy an FB output pin or a call result into ``target``; ``checked``: already stored in ``source_type``."""
        code, ty = self.x.access(target)
        if is_composite(ty):
            self.src.line(f"ll_assign({code}, {store_whole(source, source_type, ty)})")
        else:
            self._set(code, store_code(source, source_type, ty, checked=checked), probe)

    def _fncall(self, s: ir.FnCall, oid: int) -> None:
        call = s.call
        probe = self._take_probe() if s.en is None and s.eno is None else None
        eno = self._eno(s)

        def emit() -> None:
            if eno is not None and not call.user:
                types = tuple(self.x.scalar(ty, call.function) for ty in call.arg_types)
                wrapped = self.x.wrapped(call.function, types, runtime_name(call.type))
                if wrapped is not None:  # typed arithmetic inline: ENO is "the result fits"
                    exact, value = self.scope.temp("x"), self.scope.temp("v")
                    self.src.line(f"{exact} = {wrapped[0].format(*(self.x.expr(a) for a in call.args))}")
                    self.src.line(f"{value} = {wrapped[1].format(exact)}")
                    if s.target is not None:
                        self._copy_out(value, call.type, s.target, checked=False)
                    self.src.line(f"{self.x.var(eno)} = {exact} == {value}")
                    return
                fn = self.x.checked(call.function, types, runtime_name(call.type))
                value, warning = self.scope.temp("v"), self.scope.temp("warn")
                args = ", ".join(self.x.expr(a) for a in call.args)
                self.src.line(f"{value}, {warning} = {fn}({args})")
                if s.target is not None:
                    self._copy_out(value, call.type, s.target, checked=False)
                self.src.line(f"{self.x.var(eno)} = {warning} is None")
                return
            result = self.x.expr(call)
            if s.target is not None:
                self._copy_out(result, call.type, s.target, checked=call.user, probe=probe)
            else:
                self.src.line(result)
            if eno is not None:
                self.src.line(f"{self.x.var(eno)} = True")

        self._guarded(s.en, eno, emit)

    _HANDLERS: ClassVar[dict[type, Callable[..., None]]] = {
        ir.Assign: _assign,
        ir.If: _if,
        ir.Case: _case,
        ir.For: _for,
        ir.While: _while,
        ir.Repeat: _repeat,
        ir.Exit: _exit,
        ir.Continue: _continue,
        ir.Return: _return,
        ir.Jump: _jump,
        ir.Probe: _probe,
        ir.FbCall: _fbcall,
        ir.FnCall: _fncall,
    }


_STRAIGHT = (ir.Assign, ir.Probe, ir.FbCall, ir.FnCall)  # statements that never skip what follows
#: A local variable of the generated function or a number / BOOL constant: what an inlined standard FB body may read
#: in place of the input just assigned it (nothing between the assignment and the body can change it)
_LOCAL_OR_CONSTANT = re.compile(r"(?!ll_s_|ll_fb\b)[A-Za-z_][A-Za-z0-9_]*|\(?-?\d+(?:\.\d+)?(?:e[+-]?\d+)?\)?")


#: An FB instance reached through attributes only (no index, no in-out reference): the same object all along
_PLAIN_CHAIN = re.compile(r"[A-Za-z_]\w*(?:\.\w+)*")
#: An inlined FB body's last line when it stores one output at the body's top level (``ll_fb.Q = ll_fb.CV >= 5``;
#: not ``ll_fb._running = ll_fb.Q = False``)
_OUTPUT_STORE = re.compile(r"(ll_fb\.[A-Za-z]\w*) = ((?:(?! = ).)+)")


_NONE_STORED: frozenset[str] = frozenset()


def _local_or_constant(code: str) -> bool:
    return _LOCAL_OR_CONSTANT.fullmatch(code) is not None


#: Parentheses a folded value may have (``_fold``): folds of folds nest, and CPython's parser refuses 200 levels
FOLDED_PARENTHESES = 8
#: Branches of one if/elif chain (CPython's compiler recurses once per elif); longer chains go in groups.
CHAIN_BRANCHES = 64
#: Consecutive networks sharing one view flag (``view_run``): viewing 20 networks records at most 32.
VIEW_RUN = 8
#: A body nested this deep (indentation levels), or inside this many loops of one Python function, is
#: moved into a function of its own (``Statements._outline``): CPython allows 100 and 20.
OUTLINE_DEPTH = 60
OUTLINE_BLOCKS = 15


def _bound_local(slot: ir.Slot) -> bool:
    """Whether a FUNCTION's slot is a Python local of its function (a scalar VAR_IN_OUT is a reference)."""
    return slot.var_class != "VAR_EXTERNAL" and not (slot.var_class == "VAR_IN_OUT" and not is_composite(slot.type))


def _straight(s: ir.Stmt) -> bool:
    """The next statement runs whenever this one did (faults aside), so probes around it share a group."""
    if isinstance(s, _STRAIGHT):
        return True
    return not isinstance(s, _LEAVING) and not any(isinstance(x, _LEAVING) for x in walk([s]))


_LEAVING = (ir.Jump, ir.Return, ir.Exit, ir.Continue)


def _continues(body: list[ir.Stmt]) -> bool:
    """Whether a CONTINUE in ``body`` belongs to the loop around it (not to a loop nested in it)."""
    return any(
        isinstance(s, ir.Continue) or (not isinstance(s, _LOOPS) and any(_continues(b) for b in nested(s)))
        for s in body
    )


_LOOPS = (ir.For, ir.While, ir.Repeat)


def _only_probes(s: ir.If) -> bool:
    """True when an IF holds probes and nothing else, and testing its conditions cannot call or fault."""
    bodies = [body for _, body in s.branches] + [s.orelse]
    statements = list(walk([statement for body in bodies for statement in body]))
    if not any(isinstance(x, ir.Probe) for x in statements):
        return False
    if not all(isinstance(x, (ir.Probe, ir.If)) for x in statements):
        return False
    conditions = [cond for x in [s, *statements] if isinstance(x, ir.If) for cond, _ in x.branches]
    return all(
        not any(isinstance(sel, ir.Index) for var in expression_vars(c) for sel in var.path) and not calls_in(c)
        for c in conditions
    )
