"""``PouContext``: what every body lowering (ST, LD, FBD) of one POU shares.

It owns the POU's slots (declared ones, then hidden ones added while lowering),
maps checker symbols to IR variable accesses, and collects located diagnostics.
One context per POU, so hidden slot names are unique within it.
"""

from __future__ import annotations

from typing import Any

from ..model.diagnostics import Diagnostic
from ..model.places import Places
from ..st import ast
from ..st import types as t
from ..st.body import BodyChecker
from ..st.rules import assignable_or_report
from ..st.symbols import THIS, CheckResult, PouInfo, Symbol
from .lower_types import LoweringError, TypeLowering, ir_default
from .nodes import SELF, Member, Origin, Slot, Stmt, Var, VarClass, upper_name
from .types import FbInstance, IrType

#: Hidden slot names start with two underscores, which an IEC identifier must not contain (LEX-13); they
#: get a number suffix if a declared name (the parser does not refuse ``__x``) or another hidden one is taken.
HIDDEN_PREFIX = "__"


def _identity(diagnostic: Diagnostic) -> tuple:
    """What makes two diagnostics equal (their fields), as a hashable key."""
    return tuple(getattr(diagnostic, name) for name in Diagnostic.model_fields)


class PouContext:
    """The per-POU lowering state: checked symbols, slots, hidden slots, diagnostics.

    ``info`` is None for the globals scope (initial values of VAR_GLOBAL).
    Body lowerings read ``slots`` only through ``var_for``/``hidden``; the
    project lowering builds the ``ir.Pou`` from them afterwards.
    """

    def __init__(
        self,
        checked: CheckResult,
        info: PouInfo | None,
        diagnostics: list[Diagnostic] | None = None,
        image: dict[str, Slot] | None = None,
    ):
        self.checked = checked
        self.image: dict[str, Slot] = image if image is not None else {}  # addresses used without a declaration
        self.info = info
        self.name = info.name.upper() if info is not None else ""
        self.diagnostics: list[Diagnostic] = diagnostics if diagnostics is not None else []
        self.places: Places | None = None  # an LD/FBD body's names for networks and elements (set by its lowering)
        self.types = TypeLowering(checked, info)
        self.slots: list[Slot] = []
        self.edges: dict[str, Var] = {}  # R_EDGE/F_EDGE input name -> hidden slot holding the detected edge
        self._taken: set[str] = set()
        self._counters: dict[str, int] = {}
        self._callees: dict[str, TypeLowering] = {}
        self._errors_found = False
        self._seen: set[tuple] = set()  # see _reported
        self._seen_upto = 0
        # var_for's answers (IR nodes are immutable); asked for by the bodies only, after edge_preamble set edges
        self._vars: dict[Symbol, Var] = {}
        self.fb_pins: dict[tuple[str, bool], dict] = {}  # lower_st.fb_pins' answers, by FB type name and std-ness
        self.signatures: dict[tuple, tuple] = {}  # lower_expr's standard function call signatures (see _signature)
        # Statement-level state of the ST lowering: where calls with EN/ENO are lifted to (None: not allowed
        # here), and how many variable reads / user function calls the current statement evaluated so far.
        self.lifts: list[Stmt] | None = None
        self.reads = 0
        self.calls = 0
        # The text being lowered when it is not the POU's body: an SFC POU's chart or one of its actions or named
        # transitions (``<POU>/chart``, ``<POU>/actions/<name>``): where diagnostics without a file of their own go.
        self.default_file: str | None = None
        # What runs before the POU returns (a METHOD's outputs copied to its caller: ir/method_outputs.py)
        self.before_return: list[Stmt] = []
        # A front end's own statements, lowered before the ST ones (test files' verbs: ir/lower_tests.py)
        self.extra_statements: dict[type, Any] = {}

    # ------------------------------------------------------------ diagnostics
    def report(
        self,
        code: str,
        message: str,
        *,
        network: str | None = None,
        element: str | None = None,
        pin: str | None = None,
        line: int | None = None,
        column: int | None = None,
        end_line: int | None = None,
        end_column: int | None = None,
        file: str | None = None,
        severity: str = "error",
    ) -> None:
        """Append a located diagnostic for this POU (``file`` e.g. ``"Main/body"`` for ST line/column).

        A diagnostic already in the list is not added again (a bad TYPE initial value
        is met wherever the type is used).
        """
        if file is None:
            file = self.default_file
        diagnostic = Diagnostic(
            severity=severity,
            code=code,
            message=message,
            file=file,
            network=network,
            element=element,
            pin=pin,
            place=self.places.where(network, element, pin) if network is not None and self.places is not None else None,
            pou=self.info.name if self.info is not None and file != "types" else None,
            line=line,
            column=column,
            end_line=end_line,
            end_column=end_column,
        )
        key = _identity(diagnostic)
        if key not in self._reported():
            self.diagnostics.append(diagnostic)
            self._seen.add(key)

    def retract(self, count: int) -> None:
        """Drop the diagnostics reported after the first ``count`` (what checking a box call template's placeholder
        version reported: its messages name placeholders, not the user's operands)."""
        del self.diagnostics[count:]
        self._seen, self._seen_upto = set(), 0

    def _reported(self) -> set[tuple]:
        """The identities of the diagnostics in the (shared, append-only) list, brought up to date: one set lookup
        per report, where comparing with the whole list made a diagram with thousands of problems quadratic."""
        for diagnostic in self.diagnostics[self._seen_upto :]:
            self._seen.add(_identity(diagnostic))
        self._seen_upto = len(self.diagnostics)
        return self._seen

    def report_at(self, code: str, message: str, node: Any, file: str | None = None) -> None:
        """Report at an ST AST node's span (``file`` defaults to this POU's body text)."""
        span = getattr(node, "span", None) or ast.NO_SPAN
        if file is None and self.info is not None:
            file = self.default_file or f"{self.info.name}/body"
        self.report(
            code,
            message,
            file=file,
            line=span.line or None,
            column=span.column or None,
            end_line=span.end_line or None,
            end_column=span.end_column or None,
        )

    def report_error(self, error: LoweringError, fallback: Any = None, file: str | None = None, **where: Any) -> None:
        """Report a ``LoweringError`` (silent when the checker already reported its cause).

        Located at the error's AST node (or ``fallback``) in ``file`` (default: this POU's
        ST body), or at ``where`` (``network=``, ``element=``, ``pin=``) for a diagram.
        """
        if error.message is None:
            if not self._checker_found_errors():  # nothing explains the failure: never drop code silently
                self.report_at(
                    "IR-INTERNAL",
                    "this could not be lowered (an internal error of LadderLab: please report it)",
                    error.node if error.node is not None else fallback,
                    file,
                )
            return
        file = error.file or file
        if where:
            self.report(error.code, error.message, file=file, **where)
        else:
            self.report_at(error.code, error.message, error.node if error.node is not None else fallback, file)

    def _checker_found_errors(self) -> bool:
        """Did checking report an error in this POU, or in the types or globals it may use? (Once it has, it
        stays so: the lists only grow.)"""
        if not self._errors_found:
            mine = self.info.name if self.info is not None else None
            self._errors_found = any(
                d.severity == "error" and d.pou in (mine, None) for d in self.checked.diagnostics + self.diagnostics
            )
        return self._errors_found

    def checker_error_in(self, span: ast.Span) -> bool:
        """Did the checker report an error on the lines of ``span`` in this POU's ST body (or the SFC action being
        lowered)?"""
        file = (self.default_file or f"{self.info.name}/body") if self.info is not None else None
        return any(
            d.severity == "error" and d.file == file and d.line is not None and span.line <= d.line <= span.end_line
            for d in self.checked.diagnostics
        )

    def check_en_eno(self, node: ast.Expr, function: str, output: bool) -> None:
        """Type an EN value / ENO target the checker left untyped (it skips them in standard function calls).

        Reports like the checker: ST-TYPE-MISMATCH, ST-UNKNOWN-VAR, ST-NOT-LVALUE ...
        """
        checker = BodyChecker(
            self.checked,
            self.info,
            lambda code, message, at, severity="error": (
                self.report_at(code, message, at) if severity == "error" else None
            ),
        )
        if not output:
            assignable_or_report(checker, t.BOOL, checker.expr(node, t.BOOL), node, f"input EN of {function}")
        elif t.assignable(checker.target(node), t.BOOL) == "error":
            checker.report(
                "ST-TYPE-MISMATCH", f"output ENO of {function} is BOOL and cannot be stored in {node.ty}", node
            )

    def origin(self, node: Any) -> Origin:
        """An ST statement's origin: this POU and the node's span (body-relative, 1-based)."""
        span = getattr(node, "span", None) or ast.NO_SPAN
        return Origin(self.name, span.line or None, span.column or None, span.end_line or None, span.end_column or None)

    # ------------------------------------------------------------ types and slots
    def ir_type(self, ty: t.Type) -> IrType:
        """``lower_types.ir_type`` with this project's TYPE declarations (struct field initials, subranges)."""
        return self.types.type_of(ty)

    def types_for(self, pou: str | None) -> TypeLowering:
        """Type lowering in the scope of another POU (a callee's parameter types and initial values)."""
        key = (pou or "").upper()
        if key == self.name:
            return self.types
        if key not in self._callees:
            self._callees[key] = TypeLowering(self.checked, self.checked.pou(key))
        return self._callees[key]

    def add_slot(self, slot: Slot) -> None:
        self.slots.append(slot)
        self._taken.add(slot.name)

    def add_slots(self, slots: list[Slot]) -> None:
        """``add_slot`` for each of ``slots`` (a POU's declared variables: 200,000 in a 50,000-network program)."""
        self.slots += slots
        self._taken.update([slot.name for slot in slots])

    def has_slot(self, name: str) -> bool:
        return name in self._taken

    def reserve(self, slots: list[Slot]) -> None:
        """Keep ``hidden`` from naming a slot like one of ``slots`` (a base's, which SUPER^() shares)."""
        self._taken.update(slot.name for slot in slots)

    def hidden(self, hint: str, type: IrType, initial: object = None, var_class: VarClass = "VAR") -> Var:
        """A new hidden slot (unique name from ``hint``), e.g. an edge memory or a power-flow temporary.

        ``initial`` None means the type's default. VAR slots keep their value between calls;
        pass ``var_class="VAR_TEMP"`` for a value that is recomputed before every use.
        """
        stem = HIDDEN_PREFIX + "".join(c if c.isalnum() else "_" for c in hint.upper())
        name = stem
        while name in self._taken:
            self._counters[stem] = self._counters.get(stem, 0) + 1
            name = f"{stem}_{self._counters[stem]}"
        if initial is None:
            initial = ir_default(type)
        self.add_slot(Slot(name, var_class, type, initial, hidden=True))
        return Var("local", name, type)

    def var_for(self, symbol: Symbol) -> Var:
        """The IR access of a declared variable: a local slot, or a global (VAR_GLOBAL, VAR_EXTERNAL).

        Inside a POU an R_EDGE/F_EDGE input reads as its detected edge (a hidden slot).
        """
        var = self._vars.get(symbol)
        if var is None:
            var = self._vars[symbol] = self._var_for(symbol)
        return var

    def _var_for(self, symbol: Symbol) -> Var:
        name = upper_name(symbol.name)
        if symbol.var_class == "VAR_EXTERNAL" and symbol.address and name not in self.checked.globals:
            return self.direct(symbol.address, self.types.type_of(symbol.type, symbol.type_spec))  # AT %X0.0
        if symbol.pou is None or symbol.var_class == "VAR_EXTERNAL":
            target = self.checked.globals.get(name, symbol)
            return Var("global", name, self.types.type_of(target.type, target.type_spec))
        if name in self.edges and self.info is not None and symbol.pou.upper() == self.name:
            return self.edges[name]
        method = self.info.method if self.info is not None else None
        if method is not None and method.owner.symbols.get(name) is symbol:  # the instance's (inherited too), via THIS
            this = self.var_for(self.info.symbols[THIS])
            owner = self.types_for(method.owner.name)
            return Var("local", this.name, owner.type_of(symbol.type, symbol.type_spec), (Member(name),))
        return Var("local", name, self.types.type_of(symbol.type, symbol.type_spec))

    def this_var(self) -> Var:
        """``THIS^``: in a METHOD its in-out ``THIS``; in a function block's body the instance running it
        (``SELF``, a root without a slot: the engine's ``self``)."""
        if self.info is not None and self.info.method is not None:
            return self.var_for(self.info.symbols[THIS])
        return Var("local", SELF, FbInstance(self.name))

    def direct(self, address: str, type: IrType) -> Var:
        """An address used without a declaration (``q := %IX0.1``): a located global of its default type, one per
        address text, shared by every POU of the project (``image``)."""
        canonical = address.upper()
        slot = self.image.get(canonical)
        if slot is None:
            slot = self.image[canonical] = Slot(canonical, "VAR_GLOBAL", type, None, address=canonical)
        return Var("global", canonical, slot.type)

    def result_var(self) -> Var:
        """The result slot of the FUNCTION being lowered (assigning the function's name)."""
        if self.info is None or self.info.return_type is None:
            raise LoweringError(None)
        return Var("local", self.name, self.types.type_of(self.info.return_type, self.info.return_spec))
