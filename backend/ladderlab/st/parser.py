"""ST parse entry points: text -> AST plus located diagnostics, never an exception.

One LALR parser (contextual lexer, AST built during parsing) is created on first
use and shared. On a syntax error the parser reports it and recovers where it
can: a missing ``;`` is inserted and parsing continues; any other error ends the
current top-level unit, and ``parse_source`` then re-parses the file unit by unit
so every POU with an error gets its own diagnostic and the good ones still yield
an AST.
"""

from __future__ import annotations

import functools
import pathlib
import re
from dataclasses import dataclass, field
from typing import Any

from lark import Lark, Token
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

from .. import limits
from ..iec.elementary import ALIASES, ELEMENTARY, GENERIC, STRING_TYPES
from ..model.diagnostics import Diagnostic
from . import ast
from .comments import attach_comments, blank_nested_comments
from .errors import describe_unexpected, last_token, literal_problem, would_accept
from .fast_lalr import NotFast, fast_parse
from .lark_cache import cached_lark
from .nesting import too_deep
from .pragmas import attach_pack_modes, misplaced_call_after_init, misplaced_monitoring, misplaced_pack_modes
from .quick_decls import DEPTH as QUICK_DEPTH
from .quick_decls import quick_declarations
from .transformer import AstBuilder, StSyntaxError
from .types import codesys_typing

GRAMMAR = pathlib.Path(__file__).with_name("iec61131.lark")
_STARTS = ["start_source", "start_pou", "start_decls", "start_stmts", "start_expr", "start_type", "start_config_blocks"]
# Test files get a parser of their own from the same grammar: built from start_tests alone, its tables are
# the only ones where the test keywords (END_TEST, MOCK ...) may follow a statement. (One LALR table for
# all starts would merge them into the lookaheads of statements everywhere: ``x := 1; mock := 2;`` in a
# program would then read ``mock`` as the keyword.)
_TEST_STARTS = ["start_tests"]
_MAX_ERRORS_PER_UNIT = 25
_END_KEYWORDS = {"END_IF", "END_CASE", "END_FOR", "END_WHILE", "END_REPEAT"}


@dataclass
class ParseResult:
    """``ast`` is None when nothing usable was parsed; ``diagnostics`` lists every problem found."""

    ast: Any
    diagnostics: list[Diagnostic] = field(default_factory=list)
    tokens: int | None = field(default=None, compare=False, repr=False)  # how many, when the fast loop counted

    @property
    def ok(self) -> bool:
        return not any(d.severity == "error" for d in self.diagnostics)


_KEYWORD_RE = re.compile(r'^_?[A-Z_]+: "([A-Z_]+)"i$', re.MULTILINE)
# Textual SFC's words, keywords only inside an SFC body, which starts with INITIAL_STEP (OSCAT names variables
# step); INITIAL_STEP and END_* stay reserved. The editors' highlighter reads them so too (st/vocabulary.py).
SFC_WORDS = frozenset({"STEP", "TRANSITION", "FROM", "PRIORITY", "ACTION"})
# Keywords that only mean something in one spot (after a type, in a RESOURCE): real libraries use them as names.
# The operator words are also the standard functions AND(...), MOD(...), so they may stand where a name does.
_SOFT_KEYWORDS = {
    "ON",
    "WITH",
    "TASK",
    "RESOURCE",
    "R_EDGE",
    "F_EDGE",
    "NON_RETAIN",
    "PERSISTENT",
    "POINTER",
    "REFERENCE",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "MOD",
    *SFC_WORDS,
    # object orientation's words (IEC 61131-3 ed. 3): reserved there, but edition 2 programs use them as names
    "METHOD",
    "PUBLIC",
    "PRIVATE",
    "PROTECTED",
    "INTERNAL",
    "FINAL",
    "ABSTRACT",
    "OVERRIDE",
    "EXTENDS",
    "IMPLEMENTS",
    "INTERFACE",
    "PROPERTY",
}
# Keywords of test files only (start_tests): names like ``test`` or ``setup`` stay free in programs.
TEST_KEYWORDS = frozenset(
    {"TEST", "END_TEST", "SETUP", "END_SETUP", "TEARDOWN", "END_TEARDOWN", "MOCK", "MOCK_FUNCTION", "RETURNS"}
)


@functools.cache
def grammar_keywords() -> frozenset[str]:
    """Every keyword of the grammar, upper case (the contextual and the test files' ones too)."""
    return frozenset(_KEYWORD_RE.findall(GRAMMAR.read_text(encoding="utf-8")))


@functools.cache
def keywords() -> frozenset[str]:
    """Words that are never names (KW-01, KW-02's hard keywords): the grammar's keywords but the contextual ones
    (``_SOFT_KEYWORDS``, used as names by real libraries) and the test files' ones, TRUE/FALSE and the operator
    words."""
    return (grammar_keywords() - _SOFT_KEYWORDS - TEST_KEYWORDS) | {"TRUE", "FALSE", "AND", "OR", "XOR", "NOT", "MOD"}


@functools.cache
def reserved_words() -> frozenset[str]:
    """Words that cannot be declared as variable, field or type names: ``keywords()`` and the names of the
    elementary and generic types (KW-02). (IEC 61131-3 ed. 3 types LadderLab does not have yet, such as LDT,
    stay usable, as in edition 2.)"""
    return keywords() | ELEMENTARY.keys() | ALIASES.keys() | GENERIC.keys() | set(STRING_TYPES)


@functools.cache
def _parser(tests: bool = False) -> Lark:
    reserved = grammar_keywords() - {"TRUE", "FALSE"} - _SOFT_KEYWORDS - TEST_KEYWORDS
    return cached_lark(
        "st-tests" if tests else "st",
        GRAMMAR.read_text(encoding="utf-8"),
        lexer="contextual",
        start=_TEST_STARTS if tests else _STARTS,
        transformer=AstBuilder(reserved),
        maybe_placeholders=True,
    )


#: The lexer's prefixed literal terminals (LEX-21, LEX-40..52).
_LITERAL_TERMINALS = ("DURATION", "DATE_LITERAL", "TOD_LITERAL", "DT_LITERAL", "BASED_INTEGER")


@functools.cache
def literal_patterns() -> dict[str, str]:
    """Terminal name -> the regular expression the lexer reads that literal with (case-insensitive)."""
    return {t.name: t.pattern.value for t in _parser().terminals if t.name in _LITERAL_TERMINALS}


def _complete_literal(text: str) -> bool:
    """Whether ``text`` (trailing spaces aside) is one whole literal of the lexer's prefixed forms."""
    stripped = text.strip()
    return any(re.fullmatch(p, stripped, re.IGNORECASE) for p in literal_patterns().values())


@functools.cache
def _terminal_text() -> dict[str, str]:
    """Terminal name -> literal text for keywords and punctuation (for error messages)."""
    return {t.name: t.pattern.value for t in _parser().terminals if t.pattern.type == "str"}


def parse_source(text: str, *, file: str | None = None, nested_comments: bool = False) -> ParseResult:
    """A whole file: TYPE blocks, VAR_GLOBAL blocks, POUs and CONFIGURATIONs."""
    prepared = _prepare(text, nested_comments)
    result = _run(prepared, "start_source", file)
    if result.ast is not None:
        result.diagnostics += attach_pack_modes(result.ast, prepared, file)
        _name_pous(result)
        return _finish(result, text, file, place="source")
    items: list[Any] = []
    diagnostics: list[Diagnostic] = []
    for unit in split_units(prepared):
        padded = "\n" * (unit.line - 1) + " " * (unit.column - 1) + unit.text
        part = _run(padded, "start_source", file, pou=unit.pou)
        diagnostics += part.diagnostics
        if part.ast is not None and part.ok:
            items += part.ast.items
    if not diagnostics:  # the split hid the problem (e.g. text outside any unit): keep the whole-file report
        diagnostics = result.diagnostics
    source = ast.Source(items, ast.NO_SPAN)
    diagnostics += attach_pack_modes(source, prepared, file)
    return _finish(ParseResult(source, diagnostics), text, file, place="source")


def parse_pou(text: str, *, file: str | None = None, nested_comments: bool = False) -> ParseResult:
    """Exactly one PROGRAM, FUNCTION_BLOCK or FUNCTION."""
    return _finish(_run(_prepare(text, nested_comments), "start_pou", file), text, file, place="source")


def parse_declarations(
    text: str, *, file: str | None = None, nested_comments: bool = False, pou: str | None = None
) -> ParseResult:
    """A sequence of VAR...END_VAR blocks (the model's ``declarations`` / ``globals`` text): ``list[VarBlock]``.

    Plain ``name, name : Type;`` blocks are read without the LALR parser (``quick_decls``), with the same result.
    """
    prepared = _prepare(text, nested_comments)
    quick = quick_declarations(prepared, grammar_keywords())
    if quick is not None:
        return _finish(ParseResult(quick), text, file, pou, depth=QUICK_DEPTH, place="declarations")
    result = _run(prepared, "start_decls", file, pou=pou)
    result.diagnostics += misplaced_pack_modes(prepared, file, pou)  # no TYPE here for one to pack
    return _finish(result, text, file, pou, place="declarations")


def parse_statements(
    text: str, *, file: str | None = None, nested_comments: bool = False, pou: str | None = None
) -> ParseResult:
    """A statement list (an ST POU body): ``list[Stmt]``."""
    prepared = _prepare(text, nested_comments)
    result = _run(prepared, "start_stmts", file, pou=pou)
    result.diagnostics += misplaced_pack_modes(prepared, file, pou)
    return _finish(result, text, file, pou)


def parse_expression(
    text: str, *, file: str | None = None, nested_comments: bool = False, pou: str | None = None
) -> ParseResult:
    """One operand or expression, e.g. an LD contact's ``T1.Q`` or a pin's ``arr[i] + 1``."""
    return _finish(_run(_prepare(text, nested_comments), "start_expr", file, pou=pou), text, file, pou)


def parse_type(text: str, *, file: str | None = None, pou: str | None = None) -> ParseResult:
    """One type specification, e.g. a function's result type: ``INT``, ``STRING[20]``, ``ARRAY [1..3] OF TRec``."""
    return _run(text, "start_type", file, pou=pou)


def parse_config_blocks(text: str, *, file: str | None = None) -> ParseResult:
    """VAR_ACCESS and VAR_CONFIG blocks (a configuration's texts): ``list[AccessBlock | ConfigBlock]``."""
    return _finish(_run(text, "start_config_blocks", file), text)


def parse_tests(text: str, *, file: str | None = None, nested_comments: bool = False) -> ParseResult:
    """A test file (``tests/<name>.st``): SETUP, TEARDOWN and TEST blocks (``ast.TestFile``, docs/testing.md)."""
    return _finish(_run(_prepare(text, nested_comments), "start_tests", file), text)


def _name_pous(result: ParseResult) -> None:
    """Give each diagnostic of a whole-file parse the POU it lies in."""
    pous = result.ast.pous
    for diagnostic in result.diagnostics:
        line = diagnostic.line or 0
        diagnostic.pou = next((p.name for p in pous if p.span.line <= line <= p.span.end_line), None)


def _prepare(text: str, nested_comments: bool) -> str:
    return blank_nested_comments(text) if nested_comments else text


def _finish(
    result: ParseResult,
    original: str,
    file: str | None = None,
    pou: str | None = None,
    depth: int | None = None,
    place: str = "",
) -> ParseResult:
    """``depth``: how deeply the AST is known to nest (expression levels; no statements), when it is; ``place``:
    what the text is for the call_after_init and monitoring attributes (st/pragmas.py)."""
    interfaces = (
        [(i.span.line, i.span.end_line) for i in result.ast.items if isinstance(i, ast.InterfaceDecl)]
        if place == "source" and isinstance(result.ast, ast.Source)
        else []
    )
    result.diagnostics += misplaced_call_after_init(original, file, pou, place, interfaces)
    result.diagnostics += misplaced_monitoring(original, file, pou, place, interfaces)
    if result.ast is not None and (
        depth > limits.EXPRESSION_DEPTH.value if depth is not None else _may_nest_too_deep(result, original)
    ):
        deep = too_deep(result.ast)
        if deep is not None:  # nothing after the parser may meet nesting beyond the limits (st/nesting.py)
            message, span = deep
            result.diagnostics.append(syntax_diagnostic(message, span, file, pou, code="ST-TOO-DEEP"))
            result.ast = None
    if result.ast is not None:
        attach_comments(result.ast, original)
    return result


def _may_nest_too_deep(result: ParseResult, original: str) -> bool:
    """Whether the text is long enough to cross a nesting limit as set now (shorter ones skip the walk). In
    characters: every level of an expression takes at least one of its own (an operator, a bracket, a name),
    every level of statements at least 15 (``IF a THEN`` ... ``END_IF``; CASE, FOR, WHILE and REPEAT take
    more). In tokens, when the fast loop counted them: an expression level takes a token of its own but for
    nodes that wrap one child without a token (a positional argument, a typed literal's value), never two
    such in a row, so at most 2 levels a token; a statement level takes at least 4 (``IF c THEN END_IF``)."""
    expression_limit, statement_limit = limits.EXPRESSION_DEPTH.value, limits.STATEMENT_DEPTH.value
    if result.tokens is not None:
        return 2 * result.tokens > expression_limit or result.tokens > 4 * statement_limit
    return len(original) >= min(expression_limit, statement_limit * 15)


def _run(text: str, start: str, file: str | None, pou: str | None = None) -> ParseResult:
    diagnostics: list[Diagnostic] = []
    report = _Reporter(diagnostics, file, pou, text)
    parser = _parser(start in _TEST_STARTS)
    tokens = None
    try:
        try:
            tree, tokens = fast_parse(parser, text, start)
        except NotFast:  # an error: lark reports it and recovers where it can
            tree = parser.parse(text, start=start, on_error=report.recover)
    except UnexpectedInput as error:
        if not report.seen(error):
            report.add(error)
        return ParseResult(None, diagnostics)
    except StSyntaxError as error:
        diagnostics.append(syntax_diagnostic(str(error), error.span, file, pou))
        return ParseResult(None, diagnostics)
    except RecursionError:
        diagnostics.append(syntax_diagnostic("the text is nested too deeply to parse", ast.Span(1, 1, 1, 1), file, pou))
        return ParseResult(None, diagnostics)
    return ParseResult(tree, diagnostics, tokens)


def syntax_diagnostic(
    message: str, span: ast.Span, file: str | None, pou: str | None, severity: str = "error", code: str = "ST-PARSE"
) -> Diagnostic:
    return Diagnostic(
        severity=severity,
        code=code,
        message=message,
        file=file,
        pou=pou,
        line=span.line,
        column=span.column,
        end_line=span.end_line,
        end_column=span.end_column,
    )


class _Reporter:
    """lark ``on_error`` handler: records each error and decides whether parsing can go on."""

    def __init__(self, diagnostics: list[Diagnostic], file: str | None, pou: str | None, text: str):
        self.diagnostics = diagnostics
        self.file = file
        self.pou = pou
        self.text = text
        self._reported: set[int] = set()

    def seen(self, error: UnexpectedInput) -> bool:
        return id(error) in self._reported

    def add(self, error: UnexpectedInput, severity: str = "error") -> None:
        self._reported.add(id(error))
        message, span = describe_unexpected(error, _terminal_text())
        message = literal_problem(self.text, span.line, span.column, _complete_literal) or message
        last = self.diagnostics[-1] if self.diagnostics else None
        if last is not None and (last.message, last.line) == (message, span.line):
            return  # one malformed literal can trip the lexer twice
        self.diagnostics.append(syntax_diagnostic(message, span, self.file, self.pou, severity))

    def recover(self, error: UnexpectedInput) -> bool:
        if len(self.diagnostics) >= _MAX_ERRORS_PER_UNIT:
            return False
        if isinstance(error, UnexpectedCharacters):
            self.add(error)
            return error.char not in "'\""  # lark skips a stray character; a broken string would cascade
        if isinstance(error, UnexpectedToken):
            return self._insert_semicolon(error)
        return False

    def _insert_semicolon(self, error: UnexpectedToken) -> bool:
        """The commonest slip: a statement or declaration whose ``;`` is missing at the end of a line."""
        parser = error.interactive_parser
        previous = last_token(parser.parser_state.value_stack)
        if "SEMI" not in error.accepts or previous is None:
            return False
        at_end = error.token.type == "$END"
        # ST-40 wants the ';' after END_x; ST-65 tolerates it missing on the last statement of a body, and CODESYS
        # before any statement (OSCAT's REAL_TO_FRAC): under CODESYS typing that only warns too.
        lenient = previous.type.lstrip("_") in _END_KEYWORDS and (
            at_end or error.token.type.lstrip("_").startswith("END_") or codesys_typing()
        )
        if not lenient and (at_end or previous.end_line >= error.token.line):
            return False
        if not at_end and not would_accept(parser.parser_state, ["SEMI", error.token.type]):
            return False
        self.add(error, "warning" if lenient else "error")
        parser.feed_token(Token("SEMI", ";"))
        if not at_end:
            parser.feed_token(error.token)
        return True


# ---------------------------------------------------------------- unit splitting

_UNIT_RE = re.compile(
    r"'(?:[^'$\n]|\$.)*'|\"(?:[^\"$\n]|\$.)*\"|\(\*[\s\S]*?\*\)|//[^\n]*|/\*[\s\S]*?\*/"
    r"|\b(FUNCTION_BLOCK|FUNCTION|PROGRAM|TYPE|VAR_GLOBAL|CONFIGURATION|END_CONFIGURATION)\b",
    re.IGNORECASE,
)
_POU_NAME_RE = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)")


@dataclass
class Unit:
    text: str
    line: int
    column: int
    pou: str | None


def split_units(text: str) -> list[Unit]:
    """Cut a source file at each top-level POU/TYPE/VAR_GLOBAL/CONFIGURATION keyword."""
    starts: list[tuple[int, str]] = []
    in_configuration = False
    for match in _UNIT_RE.finditer(text):
        keyword = (match.group(1) or "").upper()
        if not keyword:
            continue
        if keyword == "END_CONFIGURATION":
            in_configuration = False
        elif not in_configuration:
            starts.append((match.start(), keyword))
            in_configuration = keyword == "CONFIGURATION"
    units = []
    for i, (offset, keyword) in enumerate(starts):
        end = starts[i + 1][0] if i + 1 < len(starts) else len(text)
        line = text.count("\n", 0, offset) + 1
        column = offset - (text.rfind("\n", 0, offset) + 1) + 1
        pou = None
        if keyword in ("FUNCTION", "FUNCTION_BLOCK", "PROGRAM"):
            name = _POU_NAME_RE.match(text, offset + len(keyword))
            pou = name.group(1) if name else None
        units.append(Unit(text[offset:end], line, column, pou))
    return units
