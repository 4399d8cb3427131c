"""lark Transformer that builds ``ladderlab.st.ast`` nodes while the LALR parser reduces.

It is passed to the ``Lark`` constructor, so no parse tree is ever built. It is
stateless (one shared instance). Spans come from the first and last child that
has a position; keyword tokens that start a construct are kept in the grammar
for that reason.
"""

from __future__ import annotations

from typing import Any

from lark import Token, Transformer

from ..iec.literals import decode_integer, decode_real, decode_string, decode_time_literal
from . import ast


class StSyntaxError(Exception):
    """A construct the grammar accepts but ST does not (reported as a parse diagnostic)."""

    def __init__(self, message: str, span: ast.Span):
        super().__init__(message)
        self.span = span


def _start(item: Any) -> tuple[int, int] | None:
    if isinstance(item, Token):
        return item.line, item.column
    span = getattr(item, "span", None)
    if span is not None and span.line:
        return span.line, span.column
    if isinstance(item, (list, tuple)):
        for sub in item:
            found = _start(sub)
            if found:
                return found
    return None


def _end(item: Any) -> tuple[int, int] | None:
    if isinstance(item, Token):
        return item.end_line, item.end_column
    span = getattr(item, "span", None)
    if span is not None and span.line:
        return span.end_line, span.end_column
    if isinstance(item, (list, tuple)):
        for sub in reversed(item):
            found = _end(sub)
            if found:
                return found
    return None


def span_of(children: Any) -> ast.Span:
    """From the start of the first child to the end of the last one that has a place (runs for most nodes: the
    usual case, a first and last child that are tokens or placed nodes, is decided without the walk)."""
    start = end = None
    if children.__class__ is list and children:
        first, last = children[0], children[-1]
        if isinstance(first, Token):
            start = first.line, first.column
        else:
            span = getattr(first, "span", None)
            if span is not None and span.line:
                start = span.line, span.column
        if isinstance(last, Token):
            end = last.end_line, last.end_column
        else:
            span = getattr(last, "span", None)
            if span is not None and span.line:
                end = span.end_line, span.end_column
    if start is None:
        start = _start(children)
    if end is None:
        end = _end(children)
    if start is None or end is None:
        return ast.NO_SPAN
    return ast.Span(start[0], start[1], end[0], end[1])


class _Labels(list):
    """The labels of one CASE branch, while the flat CASE body is being grouped."""

    span = ast.NO_SPAN


class _Else(list):
    """Statements of an ELSE part (distinguishes ``ELSE`` with no statements from no ELSE)."""

    span = ast.NO_SPAN


def _present(children: list[Any]) -> list[Any]:
    return [c for c in children if c is not None]


class AstBuilder(Transformer):
    """One method per grammar rule or alias; see iec61131.lark.

    ``reserved`` holds the grammar's keywords (upper case): the contextual lexer
    lets a keyword through as a name where the keyword itself cannot occur, and
    KW-02 says such hard keywords are never identifiers.
    """

    def __init__(self, reserved: frozenset[str]):
        super().__init__()
        self.reserved = reserved

    # ------------------------------------------------------------ entry points
    def start_source(self, c):
        return ast.Source(c, span_of(c))

    def start_pou(self, c):
        return c[0]

    def start_decls(self, c):
        return c

    def start_stmts(self, c):
        return c

    def start_expr(self, c):
        return c[0]

    def start_type(self, c):
        return c[0]

    def start_config_blocks(self, c):
        return c

    def start_tests(self, c):
        setups = [x for x in c if isinstance(x, ast.TestSetup)]
        teardowns = [x for x in c if isinstance(x, ast.TestTeardown)]
        for extra in (setups[1:] + teardowns[1:])[:1]:
            what = "SETUP" if isinstance(extra, ast.TestSetup) else "TEARDOWN"
            raise StSyntaxError(f"a test file has at most one {what} block", extra.span)
        tests = [x for x in c if isinstance(x, ast.TestCase)]
        return ast.TestFile(setups[0] if setups else None, teardowns[0] if teardowns else None, tests, span_of(c))

    # ------------------------------------------------------------ test files
    def setup_block(self, c):
        blocks = [x for x in c[1:-1] if isinstance(x, ast.VarBlock)]
        return ast.TestSetup(blocks, [x for x in c[1:-1] if not isinstance(x, ast.VarBlock)], span_of(c))

    def teardown_block(self, c):
        return ast.TestTeardown(c[1:-1], span_of(c))

    def test_case(self, c):
        rest = c[2:-1]
        blocks = [x for x in rest if isinstance(x, ast.VarBlock)]
        body = [x for x in rest if not isinstance(x, ast.VarBlock)]
        return ast.TestCase(decode_string(str(c[1])), blocks, body, span_of(c))

    def mock_statement(self, c):
        return ast.MockStmt(c[1], span_of(c))

    def mock_function_statement(self, c):
        return ast.MockFunctionStmt(str(c[1]), c[3], span_of(c))

    # ------------------------------------------------------------ POUs and types
    def pou(self, c):
        kind = c[0].type
        if kind == "FUNCTION_BLOCK":
            return self._function_block(c)
        return_type = c[2] if kind == "FUNCTION" else None
        rest = c[3:-1] if kind == "FUNCTION" else c[2:-1]
        blocks = [x for x in rest if isinstance(x, ast.VarBlock)]
        sfc = next((x for x in rest if isinstance(x, ast.Sfc)), None)
        methods = [x for x in rest if isinstance(x, ast.MethodDecl)]  # a PROGRAM's (CODESYS)
        properties = [x for x in rest if isinstance(x, ast.PropertyDecl)]
        members = (ast.VarBlock, ast.Sfc, ast.MethodDecl, ast.PropertyDecl)
        body = [x for x in rest if not isinstance(x, members)]
        return ast.Pou(
            kind, str(c[1]), return_type, blocks, body, span_of(c), sfc, methods=methods, properties=properties
        )

    def _function_block(self, c):
        """``FUNCTION_BLOCK [FINAL|ABSTRACT] name [EXTENDS base] [IMPLEMENTS i, ...] VARs METHODs body``."""
        modifier, name, extends, implements = c[1], str(c[2]), c[3], c[4] or []
        rest = c[5:-1]
        blocks = [x for x in rest if isinstance(x, ast.VarBlock)]
        methods = [x for x in rest if isinstance(x, ast.MethodDecl)]
        sfc = next((x for x in rest if isinstance(x, ast.Sfc)), None)
        properties = [x for x in rest if isinstance(x, ast.PropertyDecl)]
        actions = [x for x in rest if isinstance(x, ast.ActionDecl)]
        members = (ast.VarBlock, ast.Sfc, ast.MethodDecl, ast.PropertyDecl, ast.ActionDecl)
        body = [x for x in rest if not isinstance(x, members)]
        return ast.Pou(
            "FUNCTION_BLOCK",
            name,
            None,
            blocks,
            body,
            span_of(c),
            sfc,
            methods=methods,
            properties=properties,
            actions=actions,
            modifier=modifier,
            extends=extends,
            implements=implements,
        )

    def pou_action(self, c):
        return ast.ActionDecl(str(c[1]), list(c[2:-1]), span_of(c))

    def property_decl(self, c):
        modifiers = [x for x in c[1:] if isinstance(x, str) and not isinstance(x, Token)]
        name_at = 1 + len(modifiers)
        accessors = [x for x in c[name_at + 2 :] if isinstance(x, ast.AccessorDecl)]
        return ast.PropertyDecl(str(c[name_at]), modifiers, c[name_at + 1], accessors, span_of(c))

    def property_accessor(self, c):
        kind = str(c[0]).upper()
        if kind not in ("GET", "SET") or c[-1].type != f"END_{kind}":
            raise StSyntaxError(f"a property holds GET ... END_GET and SET ... END_SET, not '{c[0]}'", span_of(c))
        rest = c[1:-1]
        blocks = [x for x in rest if isinstance(x, ast.VarBlock)]
        return ast.AccessorDecl(kind, blocks, [x for x in rest if not isinstance(x, ast.VarBlock)], span_of(c))

    def fb_modifier(self, c):
        return c[0].type

    def fb_extends(self, c):
        return str(c[1])

    def fb_implements(self, c):
        return [str(x) for x in c[1:]]

    def interface_decl(self, c):
        methods = [x for x in c if isinstance(x, ast.MethodDecl)]
        properties = [x for x in c if isinstance(x, ast.PropertyDecl)]
        return ast.InterfaceDecl(str(c[1]), c[2] or [], methods, span_of(c), properties)

    def fb_extends_interfaces(self, c):
        return [str(x) for x in c[1:]]

    def assignment_attempt(self, c):
        return ast.Assign(c[0], c[1], span_of(c), attempt=True)

    def method_modifier(self, c):
        return c[0].type

    def method_decl(self, c):
        modifiers = [x for x in c[1:] if isinstance(x, str) and not isinstance(x, Token)]
        name_at = 1 + len(modifiers)
        rest = c[name_at + 2 : -1]
        blocks = [x for x in rest if isinstance(x, ast.VarBlock)]
        body = [x for x in rest if not isinstance(x, ast.VarBlock)]
        return ast.MethodDecl(str(c[name_at]), modifiers, c[name_at + 1], blocks, body, span_of(c))

    def sfc(self, c):
        return ast.Sfc(list(c), span_of(c))

    def sfc_step(self, c):
        associations = [x for x in c[2:] if isinstance(x, ast.SfcAssociation)]
        return ast.SfcStep(str(c[1]), c[0].type == "INITIAL_STEP", associations, span_of(c))

    sfc_initial_step = sfc_step

    def sfc_association(self, c):
        qualifier = str(c[1]) if len(c) > 1 and c[1] is not None else None
        return ast.SfcAssociation(str(c[0]), qualifier, [x for x in c[2:] if x is not None], span_of(c))

    def sfc_transition(self, c):
        name = next((str(x) for x in c[1:2] if isinstance(x, Token) and x.type == "IDENT"), None)
        priority = next((int(str(x)) for x in c if isinstance(x, Token) and x.type == "INTEGER"), None)
        steps = [x for x in c if isinstance(x, list)]
        condition = c[-2] if not isinstance(c[-2], list) else None  # None: IL, read from the source
        return ast.SfcTransition(name, priority, steps[0], steps[1], condition, span_of(c))

    def sfc_steps(self, c):
        return [str(x) for x in c]

    def sfc_action(self, c):
        rest = [x for x in c[2:-1] if x is not None]
        body = rest[0] if len(rest) == 1 and isinstance(rest[0], ast.Sfc) else rest
        return ast.SfcAction(str(c[1]), body, span_of(c))

    def type_block(self, c):
        return ast.TypeBlock(c[1:-1], span_of(c))

    def type_decl(self, c):
        return ast.TypeDecl(str(c[0]), c[1], c[2] if len(c) > 2 else None, span_of(c))

    def named_type(self, c):
        return ast.NamedType(str(c[0]), span_of(c))

    def sized_type(self, c):
        return ast.SizedType(str(c[0]), c[1], span_of(c))

    def subrange_type(self, c):
        return ast.SubrangeType(str(c[0]), c[1], c[2], span_of(c))

    def array_type(self, c):
        return ast.ArrayType(c[1:-1], c[-1], span_of(c))

    def array_range(self, c):
        return None if isinstance(c[0], Token) and c[0].type == "STAR" else (c[0], c[1])

    def pointer_type(self, c):
        kind = {"POINTER": "POINTER TO", "REFERENCE": "REFERENCE TO", "PTR_TO": "PTR_TO"}.get(c[0].type, "REF_TO")
        return ast.PointerType(kind, c[1], span_of(c))

    def enum_type(self, c):
        return ast.EnumType(c[:-1], span_of(c))

    def based_enum_type(self, c):
        return ast.EnumType(c[1:-1], span_of(c), str(c[0]))

    def instance_args_type(self, c):
        return ast.InstanceArgsType(str(c[0]), c[1:-1], span_of(c))

    def positional_args_type(self, c):
        return ast.PositionalArgsType(str(c[0]), c[1:-1], span_of(c))

    def codesys_based_enum_type(self, c):
        return ast.EnumType(c[:-2], span_of(c), str(c[-1]))

    def enum_value(self, c):
        return ast.EnumValue(str(c[0]), c[1], span_of(c))

    def struct_type(self, c):
        return ast.StructType(c[1:-1], span_of(c))

    # ------------------------------------------------------------ declarations
    def var_block(self, c):
        qualifiers = [t.type for t in c[1:-1] if isinstance(t, Token)]
        decls = [d for d in c[1:] if isinstance(d, ast.VarDecl)]
        return ast.VarBlock(c[0].type, qualifiers, decls, span_of(c))

    def var_decl(self, c):
        names = [x for x in c if isinstance(x, ast.DeclName)]
        rest = c[len(names) :]
        type_spec = rest[0]
        edge = next((t.type for t in rest[1:] if isinstance(t, Token) and t.type in ("R_EDGE", "F_EDGE")), None)
        init = rest[-1] if len(rest) > 1 and not isinstance(rest[-1], Token) else None
        return ast.VarDecl(names, type_spec, init, edge, span_of(c))

    def decl_name(self, c):
        c = _present(c)
        if c[0].type == "DIRECT":
            return ast.DeclName(None, str(c[0]), span_of(c))
        return ast.DeclName(str(c[0]), str(c[1]) if len(c) > 1 else None, span_of(c))

    def array_init(self, c):
        return ast.ArrayInit(_present(c), span_of(c))

    def array_init_item(self, c):
        return c[0]

    def repeat_init(self, c):
        return ast.RepeatInit(decode_integer(c[0])[0], c[1], span_of(c))

    def struct_init(self, c):
        return ast.StructInit(c, span_of(c))

    def field_init(self, c):
        return (str(c[0]), c[1])

    # ------------------------------------------------------------ configuration
    def configuration(self, c):
        return ast.Configuration(str(c[1]), c[2:-1], span_of(c))

    def resource(self, c):
        return ast.Resource(str(c[1]), str(c[2]) if c[2] is not None else None, c[3:], span_of(c))

    def task_config(self, c):
        return ast.TaskConfig(str(c[1]), _present(c[2:]), span_of(c))

    def task_prop(self, c):
        return (str(c[0]), c[1])

    def access_block(self, c):
        return ast.AccessBlock(c[1:-1], span_of(c))

    def access_decl(self, c):
        name, path, type_spec, direction = c[0], c[1], c[2], c[3]
        return ast.AccessDecl(str(name), path, type_spec, direction.type if direction is not None else None, span_of(c))

    def config_block(self, c):
        return ast.ConfigBlock(c[1:-1], span_of(c))

    def config_decl(self, c):
        path, address, type_spec, init = c[0], c[1], c[2], c[3]
        return ast.ConfigDecl(path, str(address).upper() if address is not None else None, type_spec, init, span_of(c))

    def program_config(self, c):
        retain, name, task, type_name, args = c[1], c[2], c[3], c[4], c[5]
        return ast.ProgramConfig(
            str(name),
            str(task) if task is not None else None,
            str(type_name),
            args or [],
            retain.type if retain is not None else None,
            span_of(c),
        )

    # ------------------------------------------------------------ statements
    def assignment(self, c):
        return ast.Assign(c[0], c[1], span_of(c))

    def ref_assignment(self, c):
        return ast.RefAssign(c[0], c[2], span_of(c))

    def call_statement(self, c):
        return ast.CallStmt(c[0], span_of(c))

    def if_statement(self, c):
        c, end = c[:-1], c[-1]  # the END_x keyword, kept so the span covers it
        else_part = c[-1]
        middle = c[2:-1]
        body = [x for x in middle if not isinstance(x, tuple)]
        branches = [(c[1], body)] + [x for x in middle if isinstance(x, tuple)]
        return ast.If(branches, list(else_part) if else_part is not None else None, span_of([c, end]))

    def elsif_part(self, c):
        return (c[1], c[2:])

    def else_part(self, c):
        part = _Else(c[1:])
        part.span = span_of(c)
        return part

    def case_statement(self, c):
        c, end = c[:-1], c[-1]  # the END_x keyword, kept so the span covers it
        else_part = c[-1]
        branches: list[ast.CaseBranch] = []
        for item in c[2:-1]:
            if isinstance(item, _Labels):
                branches.append(ast.CaseBranch(list(item), [], item.span))
            elif not branches:
                raise StSyntaxError("expected a CASE label such as '1:' before the first statement", item.span)
            else:
                branches[-1].body.append(item)
        for branch in branches:
            branch.span = span_of([branch.span, branch.body])
        return ast.Case(c[1], branches, list(else_part) if else_part is not None else None, span_of([c, end]))

    def case_labels(self, c):
        labels = _Labels(c)
        labels.span = span_of(c)
        return labels

    def case_range(self, c):
        return ast.CaseRange(c[0], c[1], span_of(c))

    def for_statement(self, c):
        c, end = c[:-1], c[-1]  # the END_x keyword, kept so the span covers it
        var = ast.Name(str(c[1]), span_of(c[1]))
        return ast.For(var, c[2], c[3], c[4], c[5:], span_of([c, end]))

    def while_statement(self, c):
        c, end = c[:-1], c[-1]  # the END_x keyword, kept so the span covers it
        return ast.While(c[1], c[2:], span_of([c, end]))

    def repeat_statement(self, c):
        c, end = c[:-1], c[-1]  # the END_x keyword, kept so the span covers it
        return ast.Repeat(c[1:-1], c[-1], span_of([c, end]))

    def exit_statement(self, c):
        return ast.Exit(span_of(c))

    def continue_statement(self, c):
        return ast.Continue(span_of(c))

    def return_statement(self, c):
        return ast.Return(span_of(c))

    def empty_statement(self, c):
        return ast.Empty(span_of(c))

    # ------------------------------------------------------------ expressions
    def binary(self, c):
        op = c[1].type
        symbol = "AND" if op == "AMP" else str(c[1]).upper()
        return ast.Binary(symbol, c[0], c[2], span_of(c))

    def unary(self, c):
        return ast.Unary(str(c[0]).upper(), c[1], span_of(c))

    def unary_plus(self, c):
        return c[1]

    def name(self, c):
        if c[0].upper() in self.reserved:
            raise StSyntaxError(f"'{c[0]}' is a keyword and cannot be used as a name", span_of(c))
        return ast.Name(str(c[0]), span_of(c))

    def direct(self, c):
        return ast.DirectAddr(str(c[0]).upper(), span_of(c))

    def member(self, c):
        return ast.Member(c[0], str(c[1]), span_of(c))

    def index(self, c):
        return ast.Index(c[0], c[1:-1], span_of(c))

    def deref(self, c):
        return ast.Deref(c[0], span_of(c))

    def call(self, c):
        return ast.Call(c[0], c[1] or [], span_of(c))

    def call_args(self, c):
        return c

    def input_arg(self, c):
        return ast.Arg(str(c[0]), c[1], span=span_of(c))

    def output_arg(self, c):
        negated = len(c) == 3
        return ast.Arg(str(c[-2]), c[-1], output=True, negated=negated, span=span_of(c))

    def positional_arg(self, c):
        return ast.Arg(None, c[0], span=span_of(c))

    # ------------------------------------------------------------ literals
    def int_literal(self, c):
        value, base = decode_integer(c[0])
        return ast.IntLit(value, base, span_of(c))

    def real_literal(self, c):
        return ast.RealLit(decode_real(c[0]), span_of(c))

    def bool_literal(self, c):
        return ast.BoolLit(c[0].type == "TRUE", span_of(c))

    def string_literal(self, c):
        return ast.StringLit(decode_string(c[0]), c[0].type == "WSTRING", span_of(c))

    def time_literal(self, c):
        try:
            kind, value = decode_time_literal(c[0])
        except ValueError as error:  # D#2024-02-30, TOD#25:00: the grammar's shape, not a real date or time
            raise StSyntaxError(f"{c[0]} is not a valid date or time: {error}", span_of(c)) from None
        return ast.TimeLit(kind, value, span_of(c))

    def typed_literal(self, c):
        prefix, tokens = c[0], _present(c[1:])
        return ast.TypedLit(str(prefix)[:-1], _typed_value(tokens), span_of(c))


def _typed_value(tokens: list[Token]) -> ast.Expr:
    token = tokens[-1]
    negative = len(tokens) == 2 and tokens[0].type == "MINUS"
    span = span_of(tokens)
    if token.type in ("INTEGER", "BASED_INTEGER"):
        value, base = decode_integer(token)
        return ast.IntLit(-value if negative else value, base, span)
    if token.type == "REAL_NUMBER":
        value = decode_real(token)
        return ast.RealLit(-value if negative else value, span)
    if token.type in ("TRUE", "FALSE"):
        return ast.BoolLit(token.type == "TRUE", span)
    if token.type in ("STRING", "WSTRING"):
        return ast.StringLit(decode_string(token), token.type == "WSTRING", span)
    return ast.Name(str(token), span)
