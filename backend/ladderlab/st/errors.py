"""Turn lark's parse errors into messages a PLC programmer understands.

"expected ';' after statement" rather than "Unexpected token Token('IDENT', 'x')
... Expected one of: SEMI, PLUS, ...": keywords and punctuation are named as they
are written, operators are left out when a keyword or ';' would fit, and a
missing ';' is reported at the end of the line where it belongs.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from lark import Token, Tree
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken
from lark.parsers.lalr_analysis import Shift

from ..iec.literals import literal_form
from . import ast

_FRIENDLY = {
    "IDENT": "a name",
    "INTEGER": "a number",
    "BASED_INTEGER": "a number",
    "REAL_NUMBER": "a number",
    "STRING": "a string",
    "WSTRING": "a string",
    "DURATION": "a TIME literal",
    "DATE_LITERAL": "a DATE literal",
    "TOD_LITERAL": "a TIME_OF_DAY literal",
    "DT_LITERAL": "a DATE_AND_TIME literal",
    "TYPE_PREFIX": "a typed literal",
    "DIRECT": "an address such as %IX0.0",
    "$END": "end of text",
    "EXPRESSION": "an expression",
}
_PUNCTUATION = {
    "SEMI": ";",
    "COLON": ":",
    "COMMA": ",",
    "DOT": ".",
    "LPAR": "(",
    "RPAR": ")",
    "LSQB": "[",
    "RSQB": "]",
    "STAR": "*",
    "SLASH": "/",
    "POW": "**",
    "PLUS": "+",
    "MINUS": "-",
    "AMP": "&",
    "EQ": "=",
    "NE": "<>",
    "LT": "<",
    "GT": ">",
    "LE": "<=",
    "GE": ">=",
    "CARET": "^",
}
_OPERATORS = {
    "STAR",
    "SLASH",
    "POW",
    "PLUS",
    "MINUS",
    "AMP",
    "EQ",
    "NE",
    "LT",
    "GT",
    "LE",
    "GE",
    "CARET",
    "DOT",
    "LSQB",
    "LPAR",
    "OR",
    "XOR",
    "AND",
    "AND_THEN",
    "OR_ELSE",
    "MOD",
}
_EXPRESSION_START = {
    "IDENT",
    "INTEGER",
    "BASED_INTEGER",
    "REAL_NUMBER",
    "STRING",
    "WSTRING",
    "DURATION",
    "DATE_LITERAL",
    "TOD_LITERAL",
    "DT_LITERAL",
    "TYPE_PREFIX",
    "DIRECT",
    "TRUE",
    "FALSE",
    "NOT",
    "MINUS",
    "PLUS",
    "LPAR",
}
_MAX_ALTERNATIVES = 4


def describe_unexpected(error: UnexpectedInput, terminal_text: dict[str, str]) -> tuple[str, ast.Span]:
    """Message and span for a lark error; ``terminal_text`` maps terminal names to their literal text."""
    if isinstance(error, UnexpectedCharacters):
        return _bad_character(error)
    assert isinstance(error, UnexpectedToken)
    token = error.token
    expected = set(error.accepts or error.expected)
    previous = last_token(error.interactive_parser.parser_state.value_stack) if error.interactive_parser else None
    if "SEMI" in expected and previous is not None and previous.type.lstrip("_").startswith("END_"):
        return f"expected ';' after {str(previous).upper()}", ast.Span(
            previous.end_line, previous.end_column, previous.end_line, previous.end_column + 1
        )
    if (
        "SEMI" in expected
        and previous is not None
        and token.type != "$END"
        and previous.end_line < token.line
        and would_accept(error.interactive_parser.parser_state, ["SEMI", token.type])
    ):
        context = _context(error)
        message = "expected ';' after " + context if context else "expected ';' at the end of the line"
        return message, ast.Span(previous.end_line, previous.end_column, previous.end_line, previous.end_column + 1)
    if (
        token.type == "STAR"
        and previous is not None
        and previous.type == "LPAR"
        and (previous.end_line, previous.end_column) == (token.line, token.column)
    ):
        return "unterminated comment: '(*' without a matching '*)'", ast.Span(
            previous.line, previous.column, token.end_line, token.end_column
        )
    found = "end of text" if token.type == "$END" else f"'{token}'"
    closers = {e for e in expected if e.lstrip("_").startswith("END_")}
    if closers and token.type.lstrip("_").startswith("END_"):  # e.g. END_PROGRAM closing a FUNCTION
        expected = closers
    message = f"expected {_alternatives(expected, terminal_text)}, found {found}"
    if token.type == "$END" or not getattr(token, "line", None):
        line, column = (previous.end_line, previous.end_column) if previous is not None else (1, 1)
        return message, ast.Span(line, column, line, column + 1)
    return message, ast.Span(token.line, token.column, token.end_line, token.end_column)


_LITERAL_PREFIX = re.compile(r"(?<![A-Za-z0-9_])([A-Za-z_]+|[0-9]+)#")
_LITERAL_UP_TO_ERROR = re.compile(r"(?:[A-Za-z_]+|[0-9]+)#[A-Za-z0-9_.:+\-]*\s*")
_LITERAL_REST = re.compile(r"[A-Za-z0-9_.:#+\-]*")


def literal_problem(text: str, line: int, column: int, complete: Callable[[str], bool]) -> str | None:
    """When the parse error at ``line``:``column`` lies in a prefixed literal (``T#2 s``, ``16#FG``, ``T#``): the
    literal as typed and what a valid one looks like, instead of the parser's view ("expected end of text").
    ``complete(text)``: whether ``text`` is a whole valid literal (then a word after it is not part of it)."""
    rows = text.split("\n")
    if not 1 <= line <= len(rows):
        return None
    row, at = rows[line - 1], column - 1
    starts = [m for m in _LITERAL_PREFIX.finditer(row) if m.start() <= at]
    if not starts:
        return None
    start = starts[-1]
    form = literal_form(start.group(1))
    before = row[start.start() : max(at, start.end())]
    if form is None or not _LITERAL_UP_TO_ERROR.fullmatch(before) or (before[-1:].isspace() and complete(before)):
        return None
    rest = _LITERAL_REST.match(row, max(at, start.end()))
    shown = row[start.start() : rest.end() if rest else at].rstrip()
    return f"'{shown}' is not a valid {form.name} literal: {form.hint()}"


def _bad_character(error: UnexpectedCharacters) -> tuple[str, ast.Span]:
    char = error.char
    span = ast.Span(error.line, error.column, error.line, error.column + 1)
    if char in "'\"":
        return "unterminated string, or a '$' escape that is not $$, $', $L, $N, $P, $R, $T or $hh", span
    if char == "(" or char == "*":
        return "unterminated comment: '(*' without a matching '*)'", span
    return f"unexpected character '{char}'", span


def _context(error: UnexpectedToken) -> str | None:
    """'statement' or 'declaration', from the innermost parser state that is inside a list of either."""
    state = error.interactive_parser.parser_state
    table = state.parse_conf.parse_table.states
    for number in reversed(state.state_stack):
        actions = table[number]
        if "var_decl" in actions:
            return "declaration"
        if "statement" in actions or "assignment" in actions:
            return "statement"
    return None


def _alternatives(expected: set[str], terminal_text: dict[str, str]) -> str:
    if {"IDENT", "INTEGER"} <= expected:
        expected = (expected - _EXPRESSION_START) | {"EXPRESSION"}
    words = sorted({_display(name, terminal_text) for name in expected if name not in _OPERATORS})
    if not words:
        words = sorted({_display(name, terminal_text) for name in expected})
    if "';'" in words:
        words.remove("';'")
        words.insert(0, "';'")
    if len(words) > _MAX_ALTERNATIVES:
        words = words[: _MAX_ALTERNATIVES - 1] + ["..."]
    return " or ".join(words) if len(words) < 3 else ", ".join(words[:-1]) + " or " + words[-1]


def _display(name: str, terminal_text: dict[str, str]) -> str:
    if name in _FRIENDLY:
        return _FRIENDLY[name]
    if name in _PUNCTUATION:
        return f"'{_PUNCTUATION[name]}'"
    text = terminal_text.get(name, name.lstrip("_"))
    return text.upper() if text.replace("_", "").isalpha() else f"'{text}'"


def last_token(stack: list[Any]) -> Token | None:
    """The last thing shifted (a token, or an AST node's end) - where a missing ';' belongs."""
    for item in reversed(stack):
        if isinstance(item, Tree):  # lark's helper for a repeated item (statement*, var_block*)
            item = item.children
        if isinstance(item, Token):
            return item
        span = getattr(item, "span", None)
        if span is not None and span.line:
            return Token(
                "NODE", "", line=span.line, column=span.column, end_line=span.end_line, end_column=span.end_column
            )
        if isinstance(item, list) and item:
            found = last_token(item)
            if found is not None:
                return found
    return None


def would_accept(state: Any, token_types: list[str]) -> bool:
    """Run the LALR automaton on a copy of the state stack only (no callbacks, no copying of AST values)."""
    table = state.parse_conf.parse_table.states
    stack = list(state.state_stack)
    for token_type in token_types:
        while True:
            action = table[stack[-1]].get(token_type)
            if action is None:
                return False
            kind, argument = action
            if kind is Shift:
                stack.append(argument)
                break
            if argument.expansion:
                del stack[-len(argument.expansion) :]
            stack.append(table[stack[-1]][argument.origin.name][1])
    return True
