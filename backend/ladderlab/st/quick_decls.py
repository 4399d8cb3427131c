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

import bisect
import re

from . import ast

# The grammar's lexer: WS is [ \t\f\r\n], IDENT is ASCII.
_BLANK = " \t\f\r\n"
_WS = rf"[{_BLANK}]*"
_IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
_WORD = re.compile(rf"{_WS}({_IDENT})")
_DECL = re.compile(rf"{_WS}({_IDENT}(?:{_WS},{_WS}{_IDENT})*){_WS}:{_WS}({_IDENT}){_WS};")
_NAME = re.compile(_IDENT)
_END = re.compile(rf"{_WS}$")
_KINDS = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_GLOBAL", "VAR_EXTERNAL", "VAR_TEMP"}
_QUALIFIERS = {"CONSTANT", "RETAIN", "NON_RETAIN", "PERSISTENT"}
#: ``ast.Span(*fields)`` without the named tuple's constructor, which handles defaults: ~0.3 us less for each of the
#: 400,000 spans of a 50,000-network program's declarations (issue 27)
_SPAN = tuple.__new__
#: How deeply the AST of such a text nests, as st/nesting.py counts (a VarBlock, a VarDecl, its name or type),
#: whatever its length: the parser's nesting walk need not visit it (~0.3 s for 200,000 declarations)
DEPTH = 3


def quick_declarations(text: str, keywords: frozenset[str]) -> list[ast.VarBlock] | None:
    """The ``list[VarBlock]`` of ``text``, or None when it is not of the plain shape.

    ``keywords``: every keyword of the grammar (upper case); none of them may stand where a name does.
    """
    return _Reader(text, keywords).blocks()


class _Reader:
    def __init__(self, text: str, keywords: frozenset[str]):
        self.text, self.keywords, self.position = text, keywords, 0
        self.lines = [0] + [match.end() for match in re.finditer("\n", text)]  # offset where each line starts

    def blocks(self) -> list[ast.VarBlock] | None:
        blocks = []
        while not _END.match(self.text, self.position):
            block = self.block()
            if block is None:
                return None
            blocks.append(block)
        return blocks

    def block(self) -> ast.VarBlock | None:
        kind = _WORD.match(self.text, self.position)
        if kind is None or kind.group(1).upper() not in _KINDS:
            return None
        self.position = kind.end()
        qualifiers = []
        while (word := _WORD.match(self.text, self.position)) is not None and word.group(1).upper() in _QUALIFIERS:
            qualifiers.append(word.group(1).upper())
            self.position = word.end()
        decls = self.decls()
        word = _WORD.match(self.text, self.position)
        if decls is None or word is None or word.group(1).upper() != "END_VAR":
            return None
        self.position = word.end()
        return ast.VarBlock(kind.group(1).upper(), qualifiers, decls, self.span(kind.start(1), word.end()))

    def decls(self) -> list[ast.VarDecl] | None:
        """The declarations from ``position`` on, up to what is not one (END_VAR, or something only the parser
        reads), or None when one names a keyword. (END_VAR can only begin a declaration that names it: declined.)
        One loop over a block's declarations, the line followed as it goes, not searched: a 50,000-network
        program's declarations are 100,000 (issue 27)."""
        text, keywords, lines, position = self.text, self.keywords, self.lines, self.position
        line, count = bisect.bisect_right(lines, position), len(lines)  # (the line at ``position``; how many)
        decls: list[ast.VarDecl] = []
        while (match := _DECL.match(text, position)) is not None:
            start, position = match.start(1), match.end()
            while line < count and lines[line] <= start:
                line += 1
            if line < count and lines[line] < position:  # a declaration across lines
                decl = self.decl_across_lines(match)
                if decl is None:
                    return None
                decls.append(decl)
                continue
            offset = lines[line - 1] - 1  # columns are 1-based
            names, piece_start, written = [], start, match.group(1)
            for piece in written.split(",") if "," in written else (written,):
                word, first = piece.strip(_BLANK), piece_start
                if len(word) != len(piece):  # (blanks around the name)
                    first += piece.index(word)
                if word.upper() in keywords:
                    return None
                last = first + len(word)
                names.append(ast.DeclName(word, None, _SPAN(ast.Span, (line, first - offset, line, last - offset))))
                piece_start += len(piece) + 1  # (past the comma)
            type_name = match.group(2)
            if type_name.upper() in keywords:
                return None
            first, last = match.span(2)
            spec = ast.NamedType(type_name, _SPAN(ast.Span, (line, first - offset, line, last - offset)))
            decls.append(
                ast.VarDecl(names, spec, None, None, _SPAN(ast.Span, (line, start - offset, line, last - offset)))
            )
        self.position = position
        return decls

    def decl_across_lines(self, match: re.Match[str]) -> ast.VarDecl | None:
        """The declaration ``match`` read when line breaks separate its tokens."""
        span = self.span
        names = []
        for name in _NAME.finditer(self.text, match.start(1), match.end(1)):
            text = name.group()
            if text.upper() in self.keywords:
                return None
            names.append(ast.DeclName(text, None, span(*name.span())))
        type_name = match.group(2)
        if type_name.upper() in self.keywords:
            return None
        spec = ast.NamedType(type_name, span(*match.span(2)))
        first, last = names[0].span, spec.span
        return ast.VarDecl(names, spec, None, None, _SPAN(ast.Span, (first[0], first[1], last[2], last[3])))

    def span(self, start: int, end: int) -> ast.Span:
        """Offsets -> 1-based line/column, the end column exclusive (lark's spans); a token is on one line."""
        line = bisect.bisect_right(self.lines, start)
        end_line = line if end - start < 2 else bisect.bisect_right(self.lines, end - 1)
        return ast.Span(line, start - self.lines[line - 1] + 1, end_line, end - self.lines[end_line - 1] + 1)
