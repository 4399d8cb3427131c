"""Checking test files (``tests/<name>.st``, docs/testing.md): each TEST as a POU of its own.

A TEST's scope is its own VAR blocks, the SETUP's VAR blocks, one VAR_IN_OUT link per PROGRAM of the
project (``Main.Start := TRUE`` writes the configuration's instance; the runner binds the links) and the
globals. Test code may read and write any variable of an instance (inputs, outputs and internals: white-box
testing). The test verbs (``VERBS``) are checked here and annotated on their call (``call.ref`` is a
``VerbUse``); the IR lowering of tests (ir/lower_tests.py) turns them into calls of the test runner.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..iec.spelling import did_you_mean
from ..model.diagnostics import Diagnostic
from ..model.faults import FAULT_MODES, fault_refusal, signal_kind
from . import ast
from . import types as t
from .body import BodyChecker
from .checker import ProjectChecker, Reporter, check_init
from .printer import print_expression
from .rules import assignable_or_report, constant_value, root_name
from .symbols import CheckResult, PouInfo, Symbol
from .types import ERROR, VOID, Type

#: Verb -> (fewest, most arguments). ASSERT_* take a last STRING message; ASSERT is IEC 61131-3 ed. 4's.
VERBS: dict[str, tuple[int, int]] = {
    "ASSERT_EQ": (2, 3),
    "ASSERT_NEQ": (2, 3),
    "ASSERT_GT": (2, 3),
    "ASSERT_LT": (2, 3),
    "ASSERT_GE": (2, 3),
    "ASSERT_LE": (2, 3),
    "ASSERT_NEAR": (3, 4),
    "ASSERT_TRUE": (1, 2),
    "ASSERT_FALSE": (1, 2),
    "ASSERT": (1, 1),
    "ADVANCE_TIME": (1, 1),
    "RUN_SCANS": (1, 1),
    "RUN_FOR": (1, 1),
    "RUN_UNTIL": (2, 2),
    "FORCE": (2, 2),
    "RELEASE": (1, 1),
    "WARM_START": (0, 0),
    "COLD_START": (0, 0),
    "MOCK_VERIFY_CALLED": (1, 1),
    "MOCK_VERIFY_CALL_COUNT": (2, 2),
    "FAULT": (2, 3),
    "CLEAR_FAULT": (1, 1),
}
#: What the test file editor's completion shows after each verb and MOCK statement (docs/testing.md); the
#: browser reads it from shared_schema/iec.json (``test_verbs``).
SIGNATURES: dict[str, str] = {
    **{verb: "(actual, expected [, 'message'])" for verb in ("ASSERT_EQ", "ASSERT_NEQ")},
    **{verb: "(actual, threshold [, 'message'])" for verb in ("ASSERT_GT", "ASSERT_LT", "ASSERT_GE", "ASSERT_LE")},
    "ASSERT_NEAR": "(actual, expected, tolerance [, 'message'])",
    "ASSERT_TRUE": "(condition [, 'message'])",
    "ASSERT_FALSE": "(condition [, 'message'])",
    "ASSERT": "(condition)",
    "ADVANCE_TIME": "(T#...)",
    "RUN_SCANS": "(n)",
    "RUN_FOR": "(T#...)",
    "RUN_UNTIL": "(condition, T#timeout)",
    "FORCE": "(variable, value)",
    "RELEASE": "(variable)",
    "WARM_START": "",
    "COLD_START": "",
    "MOCK": " instance",
    "MOCK_FUNCTION": " f RETURNS value",
    "MOCK_VERIFY_CALLED": "(instance)",
    "MOCK_VERIFY_CALL_COUNT": "(instance, n)",
    "FAULT": "(variable, 'mode' [, value])",
    "CLEAR_FAULT": "(variable)",
}
#: The comparison each ASSERT_x checks, as the ST operator.
COMPARISONS = {
    "ASSERT_EQ": "=",
    "ASSERT_NEQ": "<>",
    "ASSERT_GT": ">",
    "ASSERT_LT": "<",
    "ASSERT_GE": ">=",
    "ASSERT_LE": "<=",
}
#: Verbs that run the configuration's scans or restart it.
SCAN_VERBS = frozenset({"RUN_SCANS", "RUN_FOR", "RUN_UNTIL", "WARM_START", "COLD_START"})
#: The name of a TEST's POU: ``__`` cannot appear in an IEC identifier (LEX-13), so it names no user POU.
TEST_POU = "TEST__{}"


@dataclass
class VerbUse:
    """A checked verb call: ``compare`` is the expression checked in place of an assertion's operands
    (``actual = expected``, ``actual - expected`` for ASSERT_NEAR); ``path`` the variable FORCE/RELEASE name."""

    verb: str
    args: list[ast.Expr]
    compare: ast.Expr | None = None
    path: str | None = None


@dataclass
class CheckedTest:
    """One TEST: its POU scope (``info.symbols``), its body, and the links to the configuration's programs."""

    name: str
    index: int
    case: ast.TestCase
    info: PouInfo
    links: dict[str, Symbol] = field(default_factory=dict)  # upper-case program name -> link symbol


class TestChecker(BodyChecker):
    """The body checker of test code: verbs, MOCK statements, and every member of an instance visible."""

    _WHITE_BOX = frozenset({"ST-NOT-ACCESSIBLE", "ST-READONLY"})

    def __init__(self, result: CheckResult, pou: PouInfo, report, links: dict[str, Symbol]):
        super().__init__(result, pou, self._filtered(report))
        self.links = links

    def _filtered(self, report):
        def filtered(code: str, message: str, node, severity: str = "error") -> None:
            if code not in self._WHITE_BOX:
                report(code, message, node, severity)

        return filtered

    # ------------------------------------------------------------ statements
    def statement(self, stmt) -> None:
        if isinstance(stmt, ast.MockStmt):
            self._instance(stmt.target, "MOCK")
        elif isinstance(stmt, ast.MockFunctionStmt):
            self._mock_function(stmt)
        elif isinstance(stmt, ast.CallStmt) and isinstance(stmt.call, ast.Name) and _verb_name(stmt.call) in VERBS:
            call = ast.Call(stmt.call, [], stmt.span)
            stmt.call = call
            self.call(call, statement=True)
        else:
            super().statement(stmt)

    def _mock_function(self, stmt: ast.MockFunctionStmt) -> None:
        pou = self.result.pous.get(stmt.name.upper())
        if pou is None or pou.kind != "FUNCTION":
            functions = [p.name for p in self.result.pous.values() if p.kind == "FUNCTION"]
            self.report(
                "TEST-MOCK",
                f"MOCK_FUNCTION replaces a FUNCTION of the project; '{stmt.name}' is none"
                + did_you_mean(stmt.name, functions),
                stmt,
            )
            self.expr(stmt.value)
            return
        stmt.ref = pou
        target = pou.return_type or ERROR
        assignable_or_report(self, target, self.expr(stmt.value, target), stmt.value, "return from MOCK_FUNCTION")

    # ------------------------------------------------------------ verbs
    def call(self, node: ast.Call, statement: bool) -> Type:
        name = _verb_name(node.callee)
        if name not in VERBS:
            return super().call(node, statement)
        if not statement:
            self.report("TEST-VERB", f"{name} is a statement of its own: it has no value", node)
            return ERROR
        fewest, most = VERBS[name]
        if any(arg.name is not None or arg.output for arg in node.args):
            self.report("TEST-VERB", f"{name} takes its arguments by position, without names", node)
            return VOID
        args = [arg.value for arg in node.args]
        if not fewest <= len(args) <= most:
            wanted = str(fewest) if fewest == most else f"{fewest} or {most}"
            self.report("TEST-VERB", f"{name} takes {wanted} argument(s), not {len(args)}", node)
            for arg in args:
                self.expr(arg)
            return VOID
        use = VerbUse(name, args)
        node.ref = use
        getattr(self, f"_verb_{_CHECKS.get(name, name.lower())}")(use, node)
        return VOID

    def _message(self, use: VerbUse, count: int) -> None:
        if len(use.args) > count:
            message = use.args[count]
            ty = self.expr(message)
            if ty is not ERROR and not isinstance(ty, t.StringType):
                self.report("TEST-VERB", f"the message of {use.verb} must be a STRING, not {ty}", message)

    def _verb_compare(self, use: VerbUse, node: ast.Call) -> None:
        actual, expected = use.args[:2]
        if not _elementary(self.expr(actual)):
            self.report("TEST-VERB", f"{use.verb} compares elementary values, not {actual.ty}", actual)
            self.expr(expected)
        else:
            use.compare = ast.Binary(COMPARISONS[use.verb], actual, expected, node.span)
            self._as_verb(use, lambda: self.expr(use.compare))
        self._message(use, 2)

    def _verb_near(self, use: VerbUse, node: ast.Call) -> None:
        actual, expected, tolerance = use.args[:3]
        use.compare = ast.Binary("-", actual, expected, node.span)
        ty = self._as_verb(use, lambda: self.expr(use.compare))
        if ty is not ERROR:
            assignable_or_report(self, ty, self.expr(tolerance, ty), tolerance, "ASSERT_NEAR tolerance")
        self._message(use, 3)

    def _as_verb(self, use: VerbUse, check):
        """Check the expression an assertion stands for, its problems told with the verb's name, not the
        operator's the user never wrote ('=' needs ... -> ASSERT_EQ needs ...)."""
        report, operator = self.report, f"'{use.compare.op}' "  # type: ignore[union-attr]  # operands were checked when the test file was lowered

        def renamed(code: str, message: str, at, severity: str = "error") -> None:
            report(code, message.replace(operator, use.verb + " ", 1), at, severity)

        self.report = renamed
        try:
            return check()
        finally:
            self.report = report

    def _verb_condition(self, use: VerbUse, node: ast.Call) -> None:
        self.condition(use.args[0], use.verb)
        self._message(use, 1)

    def _verb_time(self, use: VerbUse, node: ast.Call) -> None:
        duration = use.args[-1]
        assignable_or_report(self, t.TIME, self.expr(duration, t.TIME), duration, f"{use.verb} duration")
        value = constant_value(self, duration)
        if isinstance(value, (int, float)) and value < 0:
            self.report("TEST-VERB", f"{use.verb} needs a duration of zero or more, not a negative one", duration)

    def _verb_run_scans(self, use: VerbUse, node: ast.Call) -> None:
        count = use.args[0]
        ty = self.expr(count)
        if ty is not ERROR and not (isinstance(ty, t.UntypedInt) or t.in_family(ty, "ANY_INT")):
            self.report("TEST-VERB", f"RUN_SCANS counts scans with an integer, not {ty}", count)

    def _verb_run_until(self, use: VerbUse, node: ast.Call) -> None:
        self.condition(use.args[0], "RUN_UNTIL")
        self._verb_time(use, node)

    def _verb_force(self, use: VerbUse, node: ast.Call) -> None:
        ty = self._path(use)
        if len(use.args) > 1:
            assignable_or_report(self, ty, self.expr(use.args[1], ty), use.args[1], "force")

    def _verb_fault(self, use: VerbUse, node: ast.Call) -> None:
        """FAULT(variable, 'mode' [, value]): the mode a constant of FAULT_MODES that fits the signal; the value
        is what ``stuck`` holds (default: the value when the fault starts), or a noisy fault's flip rate (BOOL)
        or amplitude (a number)."""
        ty = self._path(use)
        mode_arg = use.args[1]
        self.expr(mode_arg)
        mode = mode_arg.value if isinstance(mode_arg, ast.StringLit) else None
        if mode not in FAULT_MODES:
            modes = ", ".join(f"'{m}'" for m in FAULT_MODES)
            self.report("TEST-VERB", f"FAULT's mode is a STRING literal, one of {modes}", mode_arg)
            return
        use.mode = mode
        kind = signal_kind(ty.category) if isinstance(ty, t.Elementary) else None
        refused = fault_refusal(mode, kind, str(ty)) if ty is not ERROR else None
        if refused is not None:
            self.report("TEST-FORCE", f"FAULT on {use.path}: {refused}", node)
            return
        if len(use.args) < 3:
            return
        value = use.args[2]
        if mode == "stuck":
            assignable_or_report(self, ty, self.expr(value, ty), value, "FAULT value")
        elif mode == "noisy":
            assignable_or_report(self, t.LREAL, self.expr(value, t.LREAL), value, "FAULT noise")
        else:
            self.report("TEST-VERB", f"FAULT '{mode}' takes no value: only 'stuck' and 'noisy' do", value)

    def _verb_restart(self, use: VerbUse, node: ast.Call) -> None:
        pass

    def _verb_verify(self, use: VerbUse, node: ast.Call) -> None:
        self._instance(use.args[0], use.verb)
        if len(use.args) > 1:
            count = use.args[1]
            ty = self.expr(count)
            if ty is not ERROR and not (isinstance(ty, t.UntypedInt) or t.in_family(ty, "ANY_INT")):
                self.report("TEST-VERB", f"the call count must be an integer, not {ty}", count)

    def _instance(self, node: ast.Expr, verb: str) -> None:
        ty = self.expr(node)
        if ty is not ERROR and not isinstance(ty, t.FbType):
            self.report("TEST-MOCK", f"{verb} needs a function block instance, not {ty}", node)

    def _path(self, use: VerbUse) -> Type:
        """FORCE, RELEASE, FAULT and CLEAR_FAULT name a variable of the configuration (a program's or a global)
        by constant indices."""
        node = use.args[0]
        ty = self.expr(node)
        root = root_name(node)
        symbol = root.ref if root is not None else None
        if ty is ERROR:
            return ERROR
        if not isinstance(symbol, Symbol) or not (symbol in self.links.values() or symbol.var_class == "VAR_GLOBAL"):
            self.report(
                "TEST-FORCE", f"{use.verb} acts on a variable of a program or a global, not on a test variable", node
            )
            return ERROR
        if not _elementary(ty):
            self.report("TEST-FORCE", f"{use.verb} acts on an elementary variable, not on {ty}", node)
            return ERROR
        if not _constant_indices(self, node):
            self.report("TEST-FORCE", f"{use.verb} needs constant array indices", node)
            return ERROR
        use.path = print_expression(node)
        return ty


_CHECKS = {
    **{verb: "compare" for verb in COMPARISONS},
    "ASSERT_NEAR": "near",
    "ASSERT_TRUE": "condition",
    "ASSERT_FALSE": "condition",
    "ASSERT": "condition",
    "ADVANCE_TIME": "time",
    "RUN_FOR": "time",
    "FORCE": "force",
    "RELEASE": "force",
    "CLEAR_FAULT": "force",
    "WARM_START": "restart",
    "COLD_START": "restart",
    "MOCK_VERIFY_CALLED": "verify",
    "MOCK_VERIFY_CALL_COUNT": "verify",
}


def _verb_name(node: ast.Expr) -> str | None:
    return node.name.upper() if isinstance(node, ast.Name) else None


def _elementary(ty: Type) -> bool:
    return not isinstance(ty, (t.FbType, t.ArrayType, t.StructType, t.PointerType))


def _constant_indices(checker: BodyChecker, node: ast.Expr) -> bool:
    while isinstance(node, (ast.Member, ast.Index)):
        if isinstance(node, ast.Index) and not all(isinstance(constant_value(checker, i), int) for i in node.indices):
            return False
        node = node.base
    return True


class TestFileChecker:
    """Declares the SETUP's and each TEST's variables in the project's checked scope; checks their bodies."""

    def __init__(self, checker: ProjectChecker, tests: ast.TestFile, file: str):
        self.checker, self.tests, self.file = checker, tests, file
        self.result: CheckResult = checker.result
        self.diagnostics: list[Diagnostic] = []
        self._seen: set[tuple] = set()

    def report(self, pou: str | None = None) -> Reporter:
        return Reporter(self.diagnostics, self.file, pou)

    def test(self, index: int) -> CheckedTest:
        """Declare and check TEST number ``index`` (SETUP and TEARDOWN bodies with it); annotations stay valid
        until the next call, so lower each test before checking the next."""
        case = self.tests.tests[index]
        before = len(self.diagnostics)
        name = TEST_POU.format(index + 1)
        info = PouInfo(name, "FUNCTION_BLOCK", "st", None)
        report = Reporter(self.diagnostics, self.file, None)
        checker = BodyChecker(self.result, info, report)
        setup = self.tests.setup
        for block in (*(setup.var_blocks if setup else ()), *case.var_blocks):
            if block.kind not in ("VAR", "VAR_TEMP"):
                report("TEST-DECL", f"a test declares VAR blocks only, not {block.kind}", block)
            self.checker.declare_block(block, info.symbols, checker, info)
        links: dict[str, Symbol] = {}
        for pou in self.result.pous.values():
            key = pou.name.upper()
            if pou.kind == "PROGRAM" and key not in info.symbols:
                links[key] = info.symbols[key] = Symbol(
                    pou.name, "VAR_IN_OUT", t.FbType(pou.name, pou=pou), ast.NamedType(pou.name), pou=name
                )
        for symbol in info.symbols.values():
            if symbol.init is not None and symbol not in links.values():
                check_init(checker, symbol.type, symbol.init)
        body_checker = TestChecker(self.result, info, report, links)
        for part in (setup.body if setup else [], case.body, self.tests.teardown.body if self.tests.teardown else []):
            body_checker.statements(part)
        self._dedupe(before)
        return CheckedTest(case.name, index, case, info, links)

    def _dedupe(self, before: int) -> None:
        """The SETUP and TEARDOWN are checked with every test: report their problems once."""
        new = self.diagnostics[before:]
        del self.diagnostics[before:]
        for diagnostic in new:
            key = (diagnostic.code, diagnostic.message, diagnostic.line, diagnostic.column)
            if key not in self._seen:
                self._seen.add(key)
                self.diagnostics.append(diagnostic)

    def duplicate_names(self) -> None:
        """Two tests of one file with the same name cannot be told apart in a report."""
        seen: set[str] = set()
        for case in self.tests.tests:
            if case.name in seen:
                self.report()("TEST-DUPLICATE", f"there is already a test called '{case.name}' in this file", case)
            seen.add(case.name)
