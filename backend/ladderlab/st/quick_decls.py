"""Declaration texts of the plainest shape, read without the LALR parser.

The declarations of a generated or large project are mostly ``a, b : BOOL;``
lines: 20,000 of them take the pure-Python LALR parser about 0.7 s, a line
scanner about 0.05 s. ``quick_declarations`` reads a text made only of VAR
blocks (with qualifiers) holding ``name {, name} : Type;`` declarations and
builds exactly the AST the parser builds for it, spans included
(``tests/st/test_quick_decls.py`` compares both on generated texts). Anything
else - a comment, an initial value, ``AT``, an edge qualifier, a sized or
structured type, any keyword where a name stands, a syntax error - returns None
and the caller uses the parser, which also reports the diagnostics.
"""

from __future__ import annotations

import re

from . import ast

# Tokens as the grammar's lexer sees them (its WS is [ \t\f\r\n]; IDENT is ASCII).
_TOKEN = re.compile(r"[ \t\f\r]*(?:([A-Za-z_][A-Za-z0-9_]*)|([:;,]))")
_BLANK = re.compile(r"[ \t\f\r]*")
_KINDS = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_GLOBAL", "VAR_EXTERNAL", "VAR_TEMP"}
_QUALIFIERS = {"CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"}

Token = tuple[str, int, int]  # text, line, column (1-based, like lark's)


def quick_declarations(text: str, keywords: frozenset[str]) -> list[ast.VarBlock] | None:
    """The ``list[VarBlock]`` of ``text``, or None when it is not of the plain shape.

    ``keywords``: every keyword of the grammar (upper case); none of them may stand where a name does.
    """
    tokens = _tokens(text)
    if tokens is None:
        return None
    return _Reader(tokens, keywords).blocks()


def _tokens(text: str) -> list[Token] | None:
    tokens: list[Token] = []
    for number, line in enumerate(text.split("\n"), 1):
        position, end = 0, len(line)
        while position < end:
            match = _TOKEN.match(line, position)
            if match is None:
                if _BLANK.match(line, position).end() != end:  # type: ignore[union-attr]
                    return None  # a comment, a literal, an operator ...: the parser's job
                break
            start = match.start(1) if match.group(1) is not None else match.start(2)
            tokens.append((match.group(1) or match.group(2), number, start + 1))
            position = match.end()
    return tokens


class _Reader:
    def __init__(self, tokens: list[Token], keywords: frozenset[str]):
        self.tokens, self.keywords, self.index = tokens, keywords, 0

    def blocks(self) -> list[ast.VarBlock] | None:
        blocks = []
        while self.index < len(self.tokens):
            block = self.block()
            if block is None:
                return None
            blocks.append(block)
        return blocks

    def block(self) -> ast.VarBlock | None:
        first = self.next()
        kind = first[0].upper() if first else ""
        if kind not in _KINDS:
            return None
        qualifiers = []
        while (token := self.peek()) is not None and token[0].upper() in _QUALIFIERS:
            qualifiers.append(token[0].upper())
            self.index += 1
        decls = []
        while True:
            token = self.peek()
            if token is None:
                return None
            if token[0].upper() == "END_VAR":
                self.index += 1
                return ast.VarBlock(kind, qualifiers, decls, _span(first, token))
            decl = self.decl()
            if decl is None:
                return None
            decls.append(decl)

    def decl(self) -> ast.VarDecl | None:
        names = []
        while True:
            name = self.name()
            if name is None:
                return None
            names.append(ast.DeclName(name[0], None, _span(name, name)))
            separator = self.next()
            if separator is None or separator[0] not in ",:":
                return None
            if separator[0] == ":":
                break
        type_name = self.name()
        if type_name is None or (end := self.next()) is None or end[0] != ";":
            return None
        spec = ast.NamedType(type_name[0], _span(type_name, type_name))
        return ast.VarDecl(names, spec, None, None, ast.Span(names[0].span.line, names[0].span.column,
                                                              spec.span.end_line, spec.span.end_column))

    def name(self) -> Token | None:
        token = self.next()
        if token is None or not (token[0][0].isalpha() or token[0][0] == "_") or token[0].upper() in self.keywords:
            return None
        return token

    def next(self) -> Token | None:
        token = self.peek()
        self.index += token is not None
        return token

    def peek(self) -> Token | None:
        return self.tokens[self.index] if self.index < len(self.tokens) else None


def _span(first: Token, last: Token) -> ast.Span:
    return ast.Span(first[1], first[2], last[1], last[2] + len(last[0]))
