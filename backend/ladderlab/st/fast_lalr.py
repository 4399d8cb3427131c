"""A faster run of a lark LALR parser (contextual lexer) over text without errors: the same tables, the same
terminals, the same callbacks (so the same AST, spans included), one loop instead of lark's layers.

lark's own loop spends most of its time between the lexer and the parser (a generator, a lexer object per
state, a line counter object, ``feed_token`` per token). ``fast_parse`` does the same steps inline. It only
handles input lark parses without an error: at the first token the lexer or the tables do not accept it raises
``NotFast``, and the caller parses the text again with lark itself, which reports and recovers as before
(parser.py). Which lark internals it reads is listed in ``_Tables``; ``tests/st/test_fast_lalr.py`` compares it
with lark on every parser test input and on random programs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from lark import Lark, Token
from lark.lexer import UnlessCallback
from lark.parse_tree_builder import ExpandSingleChild
from lark.parsers.lalr_analysis import Shift

_new_str = str.__new__


def _new_token(
    kind: str, value: str, start_pos: int, line: int, column: int, end_line: int, end_column: int, end_pos: int
) -> Token:
    """``Token(kind, value, ...)`` as lark's ``Token._future_new`` makes it, without its layers of calls."""
    token = _new_str(Token, value)
    token.type, token.start_pos, token.value, token.line, token.column = kind, start_pos, value, line, column
    token.end_line, token.end_column, token.end_pos = end_line, end_column, end_pos
    return token


class NotFast(Exception):
    """The text has an error (or something the fast loop does not do): parse it with lark."""


@dataclass(frozen=True)
class _Scanner:
    """What lark's ``BasicLexer`` of one parser state matches with: its regexes (``Scanner._mres``), the
    keyword check of names (``UnlessCallback``), and which terminals are skipped or may hold line breaks."""

    patterns: tuple[Any, ...]
    callbacks: dict[str, Any]
    ignore: frozenset[str]
    newline: frozenset[str]
    keywords: dict[str, dict[str, str]]  # terminal -> its keywords' upper case -> their terminal (UnlessCallback's)


class _Tables:
    """lark's parse table, callbacks and per-state lexers of one ``Lark`` object, read once."""

    def __init__(self, parser: Lark) -> None:
        frontend = parser.parser
        table = frontend.parser._parse_table
        self.start_states = table.start_states
        self.end_states = table.end_states
        self.callbacks = callbacks = frontend.parser.parser.callbacks
        # state -> terminal or rule name -> a shift's next state (an int), or a reduction as
        # (symbols it pops, the rule's callback, the rule's name): no Rule hashed or looked into per step
        reductions: dict[Any, tuple[int, Any, str]] = {}
        self.states: dict[int, dict[str, Any]] = {}
        for state, actions in table.states.items():
            row: dict[str, Any] = {}
            for kind, (action, arg) in actions.items():
                if action is Shift:
                    row[kind] = arg
                else:
                    reduction = reductions.get(arg)
                    if reduction is None:
                        callback = callbacks[arg]
                        if len(arg.expansion) == 1 and type(callback) is ExpandSingleChild:
                            callback = None  # ``?rule: one_symbol``: its value is its child's, nothing to call
                        reduction = reductions[arg] = (len(arg.expansion), callback, arg.origin.name)
                    row[kind] = reduction
            self.states[state] = row
        lexers = frontend.lexer.lexers
        made: dict[int, _Scanner] = {}
        self.scanners: dict[int, _Scanner] = {}
        for state, lexer in lexers.items():
            scanner = made.get(id(lexer))
            if scanner is None:
                built = lexer.scanner  # builds lark's scanner and its callbacks
                scanner = _Scanner(
                    tuple(built._mres),
                    dict(lexer.callback),
                    frozenset(lexer.ignore_types),
                    lexer.newline_types,
                    {kind: words for kind, callback in lexer.callback.items() if (words := _keywords(callback))},
                )
                made[id(lexer)] = scanner
            self.scanners[state] = scanner
        self.skip_blanks = _only_ws_starts_blank(parser)


def _keywords(callback: Any) -> dict[str, str] | None:
    """lark's keyword check of a name (``UnlessCallback``: the first case-insensitive keyword the name matches
    in full) as a table by upper case, when all its keywords are case-insensitive words; else None."""
    if type(callback) is not UnlessCallback:
        return None
    words: dict[str, str] = {}
    for terminal in callback.scanner.terminals:
        if terminal.pattern.type != "str" or list(terminal.pattern.flags) != ["i"]:
            return None
        words.setdefault(terminal.pattern.value.upper(), terminal.name)
    return words


def _only_ws_starts_blank(parser: Lark) -> bool:
    """Whether blanks can be skipped without asking the state's scanner: ``WS`` is the ignored ``[ \\t\\f\\r\\n]+``
    and no other terminal matches text that starts with a blank (so lark's scanner would always pick ``WS``)."""
    terminals = {t.name: t.pattern.to_regexp() for t in parser.terminals}
    ws = terminals.get("WS")
    if ws is None or "WS" not in parser.lexer_conf.ignore:
        return False
    if {chr(c) for c in range(256) if re.fullmatch(ws, chr(c) * 2)} != set(_BLANK_CHARS):
        return False
    samples = [blank + rest for blank in _BLANK_CHARS for rest in ("", "a", "1", "'", "(", "*)", "\n")]
    others = [re.compile(regexp, parser.options.g_regex_flags) for name, regexp in terminals.items() if name != "WS"]
    return not any(other.match(sample) for other in others for sample in samples)


_BLANK_CHARS = " \t\f\r\n"
_BLANKS = re.compile(r"[ \t\f\r\n]+")


_tables: dict[int, _Tables] = {}
_NO_TABLES: Any = object()  # the lark in use is not laid out as _Tables expects


def fast_parse(parser: Lark, text: str, start: str) -> tuple[Any, int]:
    """What ``parser.parse(text, start=start)`` returns, for a text it parses without an error, and how many
    tokens the text has (comments and blanks aside); else ``NotFast``."""
    tables = _tables.get(id(parser))
    if tables is None:
        try:
            tables = _Tables(parser)
        except (AttributeError, KeyError, TypeError):  # another lark's internals: lark alone parses (slower)
            tables = None
        tables = _tables[id(parser)] = tables or _NO_TABLES
    if tables is _NO_TABLES:
        raise NotFast
    states = tables.states
    scanners = tables.scanners
    callbacks = tables.callbacks
    end_state = tables.end_states[start]
    state_stack = [tables.start_states[start]]
    value_stack: list[Any] = []
    pos, line, line_start, end = 0, 1, 0, len(text)
    token = None
    tokens = 0
    skip_blanks = tables.skip_blanks
    while True:
        if pos < end:
            if skip_blanks and text[pos] in _BLANK_CHARS:  # the commonest ignored text, without the state's scanner
                value = _BLANKS.match(text, pos).group(0)  # type: ignore[union-attr]  # text[pos] is a blank
                breaks = value.count("\n")
                if breaks:
                    line += breaks
                    line_start = pos + value.rindex("\n") + 1
                pos += len(value)
                continue
            state = state_stack[-1]
            scanner = scanners[state]
            for pattern in scanner.patterns:
                match = pattern.match(text, pos)
                if match:
                    break
            else:
                raise NotFast
            value = match.group(0)
            kind = match.lastgroup
            start_pos, start_line, start_column = pos, line, pos - line_start + 1
            if kind in scanner.newline:
                breaks = value.count("\n")
                if breaks:
                    line += breaks
                    line_start = pos + value.rindex("\n") + 1
            pos += len(value)
            if kind in scanner.ignore:
                if kind in scanner.callbacks:
                    raise NotFast  # an ignored terminal with a callback (none in our grammars)
                continue
            token = _new_token(kind, value, start_pos, start_line, start_column, line, pos - line_start + 1, pos)
            tokens += 1
            words = scanner.keywords.get(kind)
            if words is not None and value.isascii():  # (re's IGNORECASE also folds a few non-ASCII letters)
                keyword = words.get(value.upper())
                if keyword is not None:
                    token.type = keyword  # a keyword matched as a name gets the keyword's type
            else:
                callback = scanner.callbacks.get(kind)
                if callback is not None:
                    token = callback(token)
            is_end = False
        else:
            token = Token.new_borrow_pos("$END", "", token) if token is not None else Token("$END", "", 0, 1, 1)
            is_end = True
        kind = token.type
        while True:  # lark's ParserState.feed_token, raising NotFast where lark raises UnexpectedToken
            action = states[state_stack[-1]].get(kind)
            if action is None:
                raise NotFast
            if action.__class__ is int:  # shift
                if is_end:
                    raise NotFast
                state_stack.append(action)
                callback = callbacks.get(kind)
                value_stack.append(token if callback is None else callback(token))
                break
            size, callback, name = action
            if callback is None:  # a single child that is its own value: only the state changes
                new_state = state_stack[-1] = states[state_stack[-2]][name]
            else:
                if size:
                    values = value_stack[-size:]
                    del state_stack[-size:]
                    del value_stack[-size:]
                else:
                    values = []
                value = callback(values)
                new_state = states[state_stack[-1]][name]
                state_stack.append(new_state)
                value_stack.append(value)
            if is_end and new_state == end_state:
                return value_stack[-1], tokens
