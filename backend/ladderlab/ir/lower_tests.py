"""A test file -> the project's IR program plus one FUNCTION_BLOCK per TEST (docs/testing.md).

Each TEST becomes the POU ``TEST__<n>`` (``live_clock``: its FB calls see ADVANCE_TIME and the scans it
runs): its slots are the SETUP's and the TEST's variables and one VAR_IN_OUT link per PROGRAM (the runner
binds them to the configuration's instances), its body ``IF <teardown phase> THEN teardown ELSE setup;
test END_IF``. Every verb is a call of a *host function*: a user FUNCTION ``TEST__HOST_<k>`` with an empty
body, one per signature, which the runner replaces by its own dispatcher (``Simulation.replace_function``).
The first argument of every host call is the number of its ``Site``, which says what the verb is and
where it stands. Assertions pass the operands of their comparison, already converted to the type the
checker compared them in (each operand is evaluated once); the runner compares and reports.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model.diagnostics import Diagnostic, has_errors
from ..model.project import Project
from ..st import ast
from ..st.checker import ProjectChecker
from ..st.parser import parse_tests
from ..st.printer import print_expression
from ..st.testfile import SCAN_VERBS, TEST_POU, CheckedTest, TestFileChecker, VerbUse
from .context import PouContext
from .lower_expr import lower_access, lower_expr, lower_to
from .lower_project import lower_project
from .lower_st import lower_call_statement, lower_statements
from .lower_types import LoweringError, ir_default
from .nodes import (
    Assign,
    Binary,
    Block,
    Call,
    Const,
    Expr,
    FnCall,
    If,
    Origin,
    Pou,
    Program,
    Slot,
    Stmt,
    Unary,
    Var,
    While,
)
from .types import BOOL, Elementary, IrType

DINT = Elementary("DINT")
LINT = Elementary("LINT")
LREAL = Elementary("LREAL")
TIME = Elementary("TIME")
HOST = "TEST__HOST_{}"
#: The Site number of the host call that tells the body whether it runs the TEARDOWN (TRUE) or the test.
PHASE_SITE = 0


@dataclass(frozen=True)
class Site:
    """One verb call in a test file: what it does (``verb``), where (1-based line and column of the file),
    the source text of its operands (for messages), the IEC types of the values it passes, and for FORCE /
    RELEASE / FAULT / CLEAR_FAULT the variable's path, for FAULT its mode, for MOCK_FUNCTION the function's name."""

    verb: str
    line: int
    column: int
    operands: tuple[str, ...] = ()
    types: tuple[IrType, ...] = ()
    path: str | None = None
    function: str | None = None
    mode: str | None = None


@dataclass(frozen=True)
class LoweredTest:
    name: str
    pou: str  # TEST__<n>
    line: int
    links: dict[str, str]  # VAR_IN_OUT slot of the test POU -> the PROGRAM it names
    scans: bool  # does it run the configuration (RUN_*, WARM_START, COLD_START)?


@dataclass
class TestProgram:
    """``program`` is None when the project or the test file has errors (``diagnostics``)."""

    program: Program | None
    tests: list[LoweredTest] = field(default_factory=list)
    sites: list[Site] = field(default_factory=list)
    hosts: list[str] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def lower_test_file(project: Project, text: str, file: str) -> TestProgram:
    """Check and lower ``project`` with the test file ``text`` (named ``file`` in diagnostics)."""
    parsed = parse_tests(text, file=file)
    checker = ProjectChecker(project)
    checked = checker.run()
    lowered = lower_project(project, checked)
    diagnostics = list(lowered.diagnostics) + parsed.diagnostics
    if parsed.ast is None:
        return TestProgram(None, diagnostics=diagnostics)
    tests = TestFileChecker(checker, parsed.ast, file)
    tests.duplicate_names()
    builder = _Builder(file)
    # Addresses the tests use without a declaration join the program's (PouContext.direct): one process image.
    image = (
        {slot.name: slot for slot in lowered.program.globals if slot.address == slot.name} if lowered.program else {}
    )
    known = set(image)
    pous: dict[str, Pou] = {}
    for index in range(len(parsed.ast.tests)):
        test = tests.test(index)
        if lowered.program is not None and not has_errors(tests.diagnostics):
            pous[test.info.name.upper()] = builder.test_pou(test, checked, parsed.ast, image)
    diagnostics += tests.diagnostics + builder.diagnostics
    if lowered.program is None or has_errors(diagnostics):
        return TestProgram(None, diagnostics=diagnostics)
    globals_ = lowered.program.globals + [slot for name, slot in image.items() if name not in known]
    program = Program(
        {**lowered.program.pous, **pous, **builder.stubs},
        globals_,
        lowered.program.tasks,
        access=lowered.program.access,
        places=lowered.program.places,
        dispatch=lowered.program.dispatch,
        base_bodies=lowered.program.base_bodies,
        fb_inits=lowered.program.fb_inits,
        fb_exits=lowered.program.fb_exits,
        after_inits=lowered.program.after_inits,
        mockable=True,
        gvls=lowered.program.gvls,
        addresses=lowered.program.addresses,
    )
    return TestProgram(program, builder.tests, builder.sites, list(builder.stubs), diagnostics)


class _Builder:
    """Lowers the tests of one file, collecting their sites and the host functions they call."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.sites: list[Site] = [Site("PHASE", 0, 0)]
        self.stubs: dict[str, Pou] = {}
        self._signatures: dict[tuple, str] = {}
        self.tests: list[LoweredTest] = []
        self.diagnostics: list[Diagnostic] = []

    # ------------------------------------------------------------ POUs
    def test_pou(self, test: CheckedTest, checked, tests: ast.TestFile, image: dict[str, Slot]) -> Pou:
        ctx = PouContext(checked, test.info, self.diagnostics, image)
        ctx.extra_statements = {
            ast.CallStmt: self._call_statement,
            ast.MockStmt: self._mock,
            ast.MockFunctionStmt: self._mock_function,
        }
        for symbol in test.info.symbols.values():
            try:
                ctx.add_slot(ctx.types.slot(symbol))
            except LoweringError as error:
                ctx.report_error(error, symbol, self.file)
        self._scans = False
        setup = lower_statements(tests.setup.body, ctx) if tests.setup else []
        body = lower_statements(test.case.body, ctx)
        teardown = lower_statements(tests.teardown.body, ctx) if tests.teardown else []
        phase = self._host(PHASE_SITE, [], BOOL)
        origin = Origin(ctx.name, test.case.span.line, test.case.span.column)
        statements: list[Stmt] = [If([(phase, teardown)], setup + body, origin)]
        for diagnostic in self.diagnostics:  # the lowering locates problems in the POU's "body": the file
            if diagnostic.pou == test.info.name:
                diagnostic.pou, diagnostic.file = None, self.file
        links = {symbol.name.upper(): program for program, symbol in test.links.items()}
        self.tests.append(LoweredTest(test.name, ctx.name, test.case.span.line, links, self._scans))
        return Pou(ctx.name, "function_block", ctx.slots, [Block(statements, origin)], live_clock=True)

    def _stub(self, types: tuple[IrType, ...], in_outs: tuple[IrType, ...], result: IrType) -> str:
        """The host function of one signature (created on first use)."""
        key = (types, in_outs, result)
        name = self._signatures.get(key)
        if name is None:
            name = self._signatures[key] = HOST.format(len(self._signatures) + 1)
            slots = [Slot(f"A{i}", "VAR_INPUT", ty, ir_default(ty)) for i, ty in enumerate(types)]
            slots += [Slot(f"R{i}", "VAR_IN_OUT", ty) for i, ty in enumerate(in_outs)]
            slots.append(Slot(name, "VAR_OUTPUT", result, ir_default(result)))
            self.stubs[name] = Pou(name, "function", slots, [Block([], Origin(name))], result)
        return name

    def _host(self, site: int, args: list[Expr], result: IrType = BOOL, in_outs: tuple[Var, ...] = ()) -> Call:
        values = (Const(site, DINT), *args)
        types = tuple(a.type for a in values)
        name = self._stub(types, tuple(v.type for v in in_outs), result)
        return Call(name, values, types, result, user=True, in_outs=in_outs)

    def _site(self, use_verb: str, node, operands=(), types=(), **extra) -> int:
        span = node.span
        self.sites.append(Site(use_verb, span.line, span.column, tuple(operands), tuple(types), **extra))
        return len(self.sites) - 1

    # ------------------------------------------------------------ statements
    def _call_statement(self, statement: ast.CallStmt, ctx: PouContext) -> list[Stmt]:
        call = statement.call
        use = call.ref if isinstance(call, ast.Call) else None
        if not isinstance(use, VerbUse):
            return lower_call_statement(statement, ctx)
        self._scans = self._scans or use.verb in SCAN_VERBS
        origin = ctx.origin(statement)
        return getattr(self, f"_verb_{_LOWERINGS.get(use.verb, 'plain')}")(use, statement, ctx, origin)

    def _call(self, site: int, args: list[Expr], origin: Origin, in_outs: tuple[Var, ...] = ()) -> FnCall:
        return FnCall(self._host(site, args, BOOL, in_outs), None, origin)

    def _message(self, use: VerbUse, count: int, ctx: PouContext) -> list[Expr]:
        return [lower_expr(use.args[count], ctx)] if len(use.args) > count else []

    def _verb_compare(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        compared = lower_expr(use.compare, ctx)
        if isinstance(compared, Binary):  # the operands as the checker compares them (converted to one type)
            args = [compared.left, compared.right]
        else:  # folded (two literals): each operand, in the type of the first
            actual = lower_expr(use.args[0], ctx)
            args = [actual, lower_to(use.args[1], ctx, actual.type)]
        if use.verb == "ASSERT_NEAR":
            args.append(lower_to(use.args[2], ctx, args[0].type))
        operands = [print_expression(a) for a in use.args[: len(args)]]
        site = self._site(use.verb, statement, operands, [a.type for a in args])
        return [self._call(site, args + self._message(use, len(args), ctx), origin)]

    def _verb_condition(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        site = self._site(use.verb, statement, [print_expression(use.args[0])], [BOOL])
        return [self._call(site, [lower_to(use.args[0], ctx, BOOL), *self._message(use, 1, ctx)], origin)]

    def _verb_plain(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        """ADVANCE_TIME, RUN_FOR (a TIME), RUN_SCANS (a count), FORCE (a value), RELEASE, restarts."""
        target = {"RUN_SCANS": LINT, "ADVANCE_TIME": TIME, "RUN_FOR": TIME}.get(use.verb)
        if use.verb == "FORCE":
            args = [lower_to(use.args[1], ctx, lower_access(use.args[0], ctx).type)]
        else:
            args = [lower_to(a, ctx, target) for a in use.args] if target else []
        operands = [print_expression(a) for a in use.args]
        site = self._site(use.verb, statement, operands, [a.type for a in args], path=use.path)
        return [self._call(site, args, origin)]

    def _verb_fault(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        """FAULT passes its value when it has one: what ``stuck`` holds (the variable's type) or the noise (LREAL)."""
        variable = lower_access(use.args[0], ctx).type
        args = [lower_to(v, ctx, variable if use.mode == "stuck" else LREAL) for v in use.args[2:]]
        operands = [print_expression(a) for a in use.args]
        site = self._site("FAULT", statement, operands, [a.type for a in args], path=use.path, mode=use.mode)
        return [self._call(site, args, origin)]

    def _verb_run_until(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        """``start := now; WHILE NOT cond DO <one scan, failing once timeout has passed since start> END_WHILE``."""
        cond, timeout = use.args
        site = self._site("RUN_UNTIL", statement, [print_expression(cond), print_expression(timeout)])
        start = ctx.hidden("RUN_UNTIL_START", TIME, var_class="VAR_TEMP")
        now = self._host(site, [], TIME)
        step = self._call(site, [start, lower_to(timeout, ctx, TIME)], origin)
        return [Assign(start, now, origin), While(Unary("NOT", lower_to(cond, ctx, BOOL), BOOL), [step], origin)]

    def _verb_instance(self, use: VerbUse, statement, ctx: PouContext, origin: Origin) -> list[Stmt]:
        instance = lower_access(use.args[0], ctx)
        args = [lower_to(a, ctx, LINT) for a in use.args[1:]]
        site = self._site(use.verb, statement, [print_expression(a) for a in use.args])
        return [self._call(site, args, origin, (instance,))]

    def _mock(self, statement: ast.MockStmt, ctx: PouContext) -> list[Stmt]:
        instance = lower_access(statement.target, ctx)
        site = self._site("MOCK", statement, [print_expression(statement.target)])
        return [self._call(site, [], ctx.origin(statement), (instance,))]

    def _mock_function(self, statement: ast.MockFunctionStmt, ctx: PouContext) -> list[Stmt]:
        result = ctx.types_for(statement.ref.name).type_of(statement.ref.return_type)
        value = lower_to(statement.value, ctx, result)
        site = self._site("MOCK_FUNCTION", statement, [print_expression(statement.value)], function=statement.ref.name)
        return [self._call(site, [value], ctx.origin(statement))]


_LOWERINGS = {
    **{verb: "compare" for verb in ("ASSERT_EQ", "ASSERT_NEQ", "ASSERT_GT", "ASSERT_LT", "ASSERT_GE", "ASSERT_LE")},
    "ASSERT_NEAR": "compare",
    "ASSERT_TRUE": "condition",
    "ASSERT_FALSE": "condition",
    "ASSERT": "condition",
    "RUN_UNTIL": "run_until",
    "MOCK_VERIFY_CALLED": "instance",
    "MOCK_VERIFY_CALL_COUNT": "instance",
    "FAULT": "fault",
}


__all__ = ["TEST_POU", "LoweredTest", "Site", "TestProgram", "lower_test_file"]
