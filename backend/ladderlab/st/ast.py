"""Typed AST of IEC 61131-3 Structured Text.

Every node carries a ``span`` (1-based line/column of its first and last
character, end column exclusive like lark's). Spans, declaration comments and the
checker's annotations (``ty``, ``ref``) are excluded from equality, so
``parse(print(ast)) == ast`` compares structure only.

Names are kept as written (IEC names are case-insensitive: compare with
``.upper()``); keywords and operators are stored in canonical upper case.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, NamedTuple


class Span(NamedTuple):
    """1-based line/column of a node's first character and just after its last (a tuple: every node has one)."""

    line: int = 0
    column: int = 0
    end_line: int = 0
    end_column: int = 0


NO_SPAN = Span()


def _span() -> Any:
    return field(default=NO_SPAN, compare=False, repr=False)


def _annotation() -> Any:
    """A slot the checker fills in (resolved type or symbol); not part of equality."""
    return field(default=None, compare=False, repr=False)


# ---------------------------------------------------------------- expressions


@dataclass(slots=True)
class IntLit:
    value: int
    base: int = 10
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class RealLit:
    value: float
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class BoolLit:
    value: bool
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class StringLit:
    value: str
    wide: bool = False
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class TimeLit:
    """``kind`` is TIME, DATE, TIME_OF_DAY or DATE_AND_TIME.

    ``value`` is milliseconds: a (possibly fractional) duration for TIME,
    since midnight for TIME_OF_DAY, since 1970-01-01 for DATE and DATE_AND_TIME.
    """

    kind: str
    value: int | float
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class TypedLit:
    """``INT#5``, ``BYTE#16#FF``, ``REAL#-2.0``, ``TColor#red``: ``value`` is the literal or enum name."""

    type_name: str
    value: Expr
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class Name:
    name: str
    span: Span = _span()
    ty: Any = _annotation()
    ref: Any = _annotation()
    deref: Any = _annotation()  # True: a REFERENCE TO read through (the checker sets it)


@dataclass(slots=True)
class DirectAddr:
    """A directly represented variable such as ``%IX0.1``, ``%QW5`` or ``%MD48``."""

    address: str
    span: Span = _span()
    ty: Any = _annotation()
    ref: Any = _annotation()


@dataclass(slots=True)
class Member:
    """``base.name``: struct field, FB instance pin, or bit access (``name`` is digits)."""

    base: Expr
    name: str
    span: Span = _span()
    ty: Any = _annotation()
    ref: Any = _annotation()
    deref: Any = _annotation()  # True: a REFERENCE TO read through (the checker sets it)


@dataclass(slots=True)
class Index:
    base: Expr
    indices: list[Expr]
    span: Span = _span()
    ty: Any = _annotation()
    deref: Any = _annotation()  # True: a REFERENCE TO read through (the checker sets it)


@dataclass(slots=True)
class Deref:
    base: Expr
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class Arg:
    """One call argument: positional (``name`` None), input ``n := v`` or output ``n => v``."""

    name: str | None
    value: Expr
    output: bool = False
    negated: bool = False
    span: Span = _span()


@dataclass(slots=True)
class Call:
    """A function call in an expression, or an FB/program call as a statement.

    ``ref`` is set by the checker to the called POU, stdlib entry or instance symbol.
    """

    callee: Expr
    args: list[Arg]
    span: Span = _span()
    ty: Any = _annotation()
    ref: Any = _annotation()


@dataclass(slots=True)
class Unary:
    op: str  # "-" or "NOT"
    operand: Expr
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class Binary:
    op: str  # OR XOR AND = <> < > <= >= + - * / MOD **
    left: Expr
    right: Expr
    span: Span = _span()
    ty: Any = _annotation()


@dataclass(slots=True)
class Fit:
    """Not written by anyone: CODESYS typing's register pass (st/registers.py) wraps ``operand``, a narrow operation
    computed as CODESYS's register computes it (its type DINT), where what the target does with that register value
    would decide the result (``INT_TO_DWORD(pos - 1)``). The value must lie in ``ty``, the operation's own type: there
    every target gives the same result; outside it the run faults, located (never one target's value silently)."""

    operand: Expr
    span: Span = _span()
    ty: Any = _annotation()


Expr = (
    IntLit
    | RealLit
    | BoolLit
    | StringLit
    | TimeLit
    | TypedLit
    | Name
    | DirectAddr
    | Member
    | Index
    | Deref
    | Call
    | Unary
    | Binary
    | Fit
)
LITERALS = (IntLit, RealLit, BoolLit, StringLit, TimeLit, TypedLit)

# ---------------------------------------------------------------- statements


@dataclass(slots=True)
class Assign:
    """``target := value``; ``attempt``: ``target ?= value`` (IEC 61131-3 ed. 3: NULL when the value's instance
    does not implement the target's interface)."""

    target: Expr
    value: Expr
    span: Span = _span()
    attempt: bool = False


@dataclass(slots=True)
class RefAssign:
    """CODESYS ``r REF= x``: the REFERENCE TO ``r`` now refers to the variable ``x``."""

    target: Expr
    value: Expr
    span: Span = _span()


@dataclass(slots=True)
class CallStmt:
    """``inst(...);`` or ``f(...);``. The parser also accepts a bare ``x;`` here; the checker rejects it."""

    call: Expr
    span: Span = _span()


@dataclass(slots=True)
class If:
    branches: list[tuple[Expr, list[Stmt]]]
    else_body: list[Stmt] | None = None
    span: Span = _span()


@dataclass(slots=True)
class CaseRange:
    low: Expr
    high: Expr
    span: Span = _span()


@dataclass(slots=True)
class CaseBranch:
    labels: list[Expr | CaseRange]
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class Case:
    selector: Expr
    branches: list[CaseBranch]
    else_body: list[Stmt] | None = None
    span: Span = _span()


@dataclass(slots=True)
class For:
    var: Name
    start: Expr
    end: Expr
    step: Expr | None
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class While:
    cond: Expr
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class Repeat:
    body: list[Stmt]
    until: Expr
    span: Span = _span()


@dataclass(slots=True)
class Exit:
    span: Span = _span()


@dataclass(slots=True)
class Continue:
    """CONTINUE (IEC 61131-3 ed. 3): the rest of the innermost loop's body is skipped for this iteration."""

    span: Span = _span()


@dataclass(slots=True)
class Return:
    span: Span = _span()


@dataclass(slots=True)
class Empty:
    span: Span = _span()


@dataclass(slots=True)
class Label:
    """A jump target of an IL body (IL-02); ST has none. Lowered as the start of a labelled IR block."""

    name: str
    span: Span = _span()


@dataclass(slots=True)
class Goto:
    """An IL jump (JMP, JMPC, JMPCN: IL-23) to a ``Label`` of the same body when ``cond`` holds (None: always)."""

    label: str
    cond: Expr | None
    span: Span = _span()


Stmt = (
    Assign | RefAssign | CallStmt | If | Case | For | While | Repeat | Exit | Continue | Return | Empty | Label | Goto
)

# ---------------------------------------------------------------- types and declarations


@dataclass(slots=True)
class NamedType:
    name: str
    span: Span = _span()


@dataclass(slots=True)
class SizedType:
    """``STRING[80]`` / ``WSTRING(10)``: a type name with a length."""

    name: str
    size: Expr
    span: Span = _span()


@dataclass(slots=True)
class SubrangeType:
    base: str
    low: Expr
    high: Expr
    span: Span = _span()


@dataclass(slots=True)
class ArrayType:
    ranges: list[tuple[Expr, Expr] | None]  # None is ``*`` (variable-length, VAR_IN_OUT only)
    element: TypeSpec
    span: Span = _span()


@dataclass(slots=True)
class PointerType:
    kind: str  # "POINTER TO", "REF_TO", Mosaic "PTR_TO" or "REFERENCE TO" (CODESYS: dereferenced implicitly)
    target: TypeSpec
    span: Span = _span()


@dataclass(slots=True)
class EnumValue:
    name: str
    value: Expr | None = None
    span: Span = _span()


@dataclass(slots=True)
class EnumType:
    """``(red, green)``; with ``base`` (an integer type name), ``INT (a := 0, b := 10)`` (IEC ed. 3 6.4.4.3)."""

    values: list[EnumValue]
    span: Span = _span()
    base: str | None = None


@dataclass(slots=True)
class StructType:
    members: list[VarDecl]
    span: Span = _span()


@dataclass(slots=True)
class InstanceArgsType:
    """CODESYS: ``F[(n := 1), (n := 2)]``, an array's element type with each element's FB_init arguments."""

    name: str
    elements: list[StructInit]
    span: Span = _span()


@dataclass(slots=True)
class PositionalArgsType:
    """CODESYS: ``F('', 5)``, a function block type with its instance's FB_init arguments by position."""

    name: str
    args: list[Expr]
    span: Span = _span()


TypeSpec = (
    NamedType
    | SizedType
    | SubrangeType
    | ArrayType
    | PointerType
    | EnumType
    | StructType
    | InstanceArgsType
    | PositionalArgsType
)


@dataclass(slots=True)
class RepeatInit:
    """``n(value)`` inside an array initialiser; ``value`` None is ``n()`` (n defaults)."""

    count: int
    value: Init | None
    span: Span = _span()


@dataclass(slots=True)
class ArrayInit:
    items: list[Init | RepeatInit]
    span: Span = _span()


@dataclass(slots=True)
class StructInit:
    fields: list[tuple[str, Init]]
    span: Span = _span()


Init = Expr | ArrayInit | StructInit


@dataclass(slots=True)
class DeclName:
    """One declared name with its optional ``AT`` address; ``name`` None is ``AT %X0.0 : BOOL``."""

    name: str | None
    address: str | None = None
    span: Span = _span()


@dataclass(slots=True)
class VarDecl:
    names: list[DeclName]
    type: TypeSpec
    init: Init | None = None
    edge: str | None = None  # "R_EDGE" / "F_EDGE"
    span: Span = _span()
    comment: str | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class VarBlock:
    kind: str  # VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_GLOBAL, VAR_EXTERNAL, VAR_TEMP
    qualifiers: list[str]  # CONSTANT, RETAIN, NON_RETAIN, PERSISTENT
    decls: list[VarDecl]
    span: Span = _span()

    @property
    def constant(self) -> bool:
        return "CONSTANT" in self.qualifiers

    @property
    def retain(self) -> bool:
        return "RETAIN" in self.qualifiers or "PERSISTENT" in self.qualifiers


@dataclass(slots=True)
class TypeDecl:
    name: str
    type: TypeSpec
    init: Init | None = None
    span: Span = _span()
    pack_mode: str | None = None  # CODESYS's {attribute 'pack_mode' := '...'} above it, as written (st/pragmas.py)


@dataclass(slots=True)
class TypeBlock:
    decls: list[TypeDecl]
    span: Span = _span()


@dataclass(slots=True)
class SfcAssociation:
    """``action(qualifier, time, indicator...)`` in a textual step: ``args`` as written after the qualifier."""

    action: str
    qualifier: str | None
    args: list[Expr]
    span: Span = _span()


@dataclass(slots=True)
class SfcStep:
    name: str
    initial: bool
    associations: list[SfcAssociation]
    span: Span = _span()


@dataclass(slots=True)
class SfcTransition:
    """``TRANSITION [name] [(PRIORITY := n)] FROM steps TO steps := condition; END_TRANSITION``, or ``... TO steps:
    IL instructions END_TRANSITION`` (``condition`` None: the instructions are read from the source)."""

    name: str | None
    priority: int | None
    sources: list[str]
    targets: list[str]
    condition: Expr | None
    span: Span = _span()


@dataclass(slots=True)
class SfcAction:
    """``ACTION name: statements END_ACTION``, or a chart of its own (an action written in SFC)."""

    name: str
    body: list[Stmt] | Sfc
    span: Span = _span()


@dataclass(slots=True)
class Sfc:
    """A textual SFC body (IEC 61131-3 B.1.6): steps, transitions and actions in the order written."""

    items: list[SfcStep | SfcTransition | SfcAction]
    span: Span = _span()


@dataclass(slots=True)
class MethodDecl:
    """``METHOD [PUBLIC|PRIVATE|PROTECTED|INTERNAL] [FINAL|ABSTRACT] name [: type] ... END_METHOD``."""

    name: str
    modifiers: list[str]  # upper case, as written
    return_type: TypeSpec | None
    var_blocks: list[VarBlock]
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class AccessorDecl:
    """A PROPERTY's ``GET ... END_GET`` or ``SET ... END_SET``."""

    kind: str  # GET or SET
    var_blocks: list[VarBlock]
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class PropertyDecl:
    """``PROPERTY [access] name : type [GET ... END_GET] [SET ... END_SET] END_PROPERTY``."""

    name: str
    modifiers: list[str]
    type: TypeSpec
    accessors: list[AccessorDecl]
    span: Span = _span()


@dataclass(slots=True)
class ActionDecl:
    """A function block's ``ACTION name: statements END_ACTION`` (outside SFC, CODESYS)."""

    name: str
    body: list[Stmt]
    span: Span = _span()


@dataclass(slots=True)
class InterfaceDecl:
    """``INTERFACE name [EXTENDS i, ...] METHOD and PROPERTY prototypes END_INTERFACE``."""

    name: str
    extends: list[str]
    methods: list[MethodDecl]
    span: Span = _span()
    properties: list[PropertyDecl] = field(default_factory=list)  # PROPERTY prototypes: accessors without body


@dataclass(slots=True)
class Pou:
    kind: str  # PROGRAM, FUNCTION_BLOCK, FUNCTION
    name: str
    return_type: TypeSpec | None
    var_blocks: list[VarBlock]
    body: list[Stmt]
    span: Span = _span()
    sfc: Sfc | None = None  # a body written in textual SFC (``body`` is then empty)
    methods: list[MethodDecl] = field(default_factory=list)  # a function block's or a program's METHODs
    properties: list[PropertyDecl] = field(default_factory=list)  # a function block's or a program's PROPERTYs
    actions: list[ActionDecl] = field(default_factory=list)  # a function block's ACTIONs (outside SFC)
    modifier: str | None = None  # a function block's FINAL or ABSTRACT
    extends: str | None = None  # the function block it EXTENDS
    implements: list[str] = field(default_factory=list)  # the INTERFACEs it IMPLEMENTS


@dataclass(slots=True)
class TaskConfig:
    name: str
    properties: list[tuple[str, Expr]]
    span: Span = _span()


@dataclass(slots=True)
class ProgramConfig:
    name: str
    task: str | None
    type_name: str
    args: list[Arg] | None = None  # None: no parentheses
    retain: str | None = None  # RETAIN / NON_RETAIN
    span: Span = _span()


@dataclass(slots=True)
class AccessDecl:
    """``name : path : type [READ_WRITE | READ_ONLY];`` of VAR_ACCESS: a named access path (CFG-08)."""

    name: str
    path: Expr
    type: TypeSpec
    direction: str | None = None  # READ_WRITE / READ_ONLY (None: READ_ONLY, IEC's default)
    span: Span = _span()


@dataclass(slots=True)
class AccessBlock:
    decls: list[AccessDecl]
    span: Span = _span()


@dataclass(slots=True)
class ConfigDecl:
    """``inst.var [AT %addr] : type [:= value];`` of VAR_CONFIG: an instance variable's address or initial value."""

    path: Expr
    address: str | None
    type: TypeSpec
    init: Init | None = None
    span: Span = _span()


@dataclass(slots=True)
class ConfigBlock:
    decls: list[ConfigDecl]
    span: Span = _span()


@dataclass(slots=True)
class Resource:
    name: str | None  # None: a configuration's tasks and programs written without a RESOURCE block
    on: str | None
    items: list[TaskConfig | ProgramConfig | VarBlock]
    span: Span = _span()


@dataclass(slots=True)
class Configuration:
    name: str
    items: list[Resource | TaskConfig | ProgramConfig | VarBlock | AccessBlock | ConfigBlock]
    span: Span = _span()


@dataclass(slots=True)
class Source:
    """A whole ST file: TYPE blocks, VAR_GLOBAL blocks, POUs and configurations in source order."""

    items: list[TypeBlock | VarBlock | Pou | Configuration | InterfaceDecl]
    span: Span = _span()

    @property
    def pous(self) -> list[Pou]:
        return [item for item in self.items if isinstance(item, Pou)]


# ---------------------------------------------------------------- test files (docs/testing.md)


@dataclass(slots=True)
class MockStmt:
    """``MOCK inst;``: the instance's body does not run from here on; its calls are counted."""

    target: Expr
    span: Span = _span()


@dataclass(slots=True)
class MockFunctionStmt:
    """``MOCK_FUNCTION f RETURNS value;``: every call of the user FUNCTION ``f`` returns ``value`` from here on."""

    name: str
    value: Expr
    span: Span = _span()
    ref: Any = _annotation()


TestStmt = Stmt | MockStmt | MockFunctionStmt


@dataclass(slots=True)
class TestCase:
    """``TEST 'name' VAR..END_VAR statements END_TEST``."""

    name: str
    var_blocks: list[VarBlock]
    body: list[TestStmt]
    span: Span = _span()


@dataclass(slots=True)
class TestSetup:
    """``SETUP``: its variables belong to every test of the file; its statements run before each test."""

    var_blocks: list[VarBlock]
    body: list[TestStmt]
    span: Span = _span()


@dataclass(slots=True)
class TestTeardown:
    """``TEARDOWN``: statements run after each test, also after a failed one."""

    body: list[TestStmt]
    span: Span = _span()


@dataclass(slots=True)
class TestFile:
    setup: TestSetup | None
    teardown: TestTeardown | None
    tests: list[TestCase]
    span: Span = _span()
