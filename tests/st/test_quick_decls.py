"""The parser-free reading of plain declaration texts (st/quick_decls) builds exactly the parser's AST.

Compared field by field, spans and comments included (AST equality ignores them), on generated texts
that mix the plain shape with what only the parser reads (comments, initial values, AT, edges, sized
types, keywords as names, syntax errors): the quick reader must either decline or agree.
"""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.st import ast
from ladderlab.st import parser as st_parser
from ladderlab.st.parser import _run, grammar_keywords, parse_declarations
from ladderlab.st.quick_decls import quick_declarations

NAMES = st.sampled_from(["a", "B1", "Start", "x_1", "_t", "motorOn", "IN", "q"])
TYPES = st.sampled_from(["BOOL", "int", "TON", "STRING", "MyStruct", "LREAL"])
KINDS = st.sampled_from(["VAR", "var_input", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_GLOBAL", "VAR_EXTERNAL", "VAR_TEMP"])
BLANK = st.sampled_from([" ", "  ", "\t", "\n", "\r\n", "\n\n    ", " \f "])
GAP = st.one_of(st.just(""), BLANK)
# Pieces only the parser reads: the quick reader must decline every text containing one.
OTHER = st.sampled_from(
    [
        "(* note *)",
        "// note",
        ":= TRUE",
        "AT %IX0.0",
        "R_EDGE",
        "[80]",
        "IF",
        "END_IF",
        "{pragma}",
        ";",
        ":",
        "1",
        "'s'",
        "ON",
    ]
)


@st.composite
def declaration(draw) -> str:
    names = draw(st.lists(NAMES, min_size=1, max_size=3))
    text = names[0] + "".join(f"{draw(GAP)},{draw(GAP)}{name}" for name in names[1:])  # (blanks on either side)
    text += f"{draw(GAP)}:{draw(GAP)}{draw(TYPES)}{draw(GAP)};"
    return text


@st.composite
def block(draw) -> str:
    qualifiers = draw(st.lists(st.sampled_from(["CONSTANT", "retain", "NON_RETAIN", "PERSISTENT"]), max_size=2))
    decls = draw(st.lists(declaration(), max_size=4))
    return " ".join([draw(KINDS), *qualifiers]) + draw(BLANK) + draw(BLANK).join(decls) + draw(BLANK) + "END_VAR"


@st.composite
def declarations_text(draw) -> str:
    pieces = draw(st.lists(block(), max_size=3))
    text = draw(GAP) + draw(BLANK).join(pieces) + draw(GAP)
    if draw(st.booleans()):  # something only the parser reads, somewhere
        at = draw(st.integers(0, len(text)))
        text = text[:at] + f" {draw(OTHER)} " + text[at:]
    return text


def full(node):
    """Every field of an AST, spans and comments included."""
    if isinstance(node, list):
        return [full(item) for item in node]
    if dataclasses.is_dataclass(node):
        return (type(node).__name__, *(full(getattr(node, f.name)) for f in dataclasses.fields(node)))
    return node


@settings(max_examples=400, deadline=None)
@given(declarations_text())
def test_quick_reading_declines_or_equals_the_parser(text):
    quick = quick_declarations(text, grammar_keywords())
    parsed = _run(text, "start_decls", None)
    if quick is not None:
        assert not parsed.diagnostics
        assert full(quick) == full(parsed.ast)


def test_plain_blocks_are_read_without_the_parser():
    text = "VAR_INPUT\n  a, b : BOOL;\nEND_VAR\nVAR RETAIN\n\tT1 : TON; n : INT;\r\nEND_VAR"
    quick = quick_declarations(text, grammar_keywords())
    assert full(quick) == full(_run(text, "start_decls", None).ast)
    assert [b.kind for b in quick] == ["VAR_INPUT", "VAR"] and quick[1].retain
    assert quick[1].decls[0].span == ast.Span(5, 2, 5, 10)  # 'T1 : TON' without the ';'
    assert quick_declarations("", grammar_keywords()) == []


def test_anything_else_goes_to_the_parser_with_its_diagnostics():
    for text in [
        "VAR a : BOOL := TRUE; END_VAR",
        "VAR a : BOOL; (* x *) END_VAR",
        "VAR a : BOOL END_VAR",
        "VAR if : BOOL; END_VAR",
        "VAR a : STRING[10]; END_VAR",
        "VAR a : BOOL;",
        "a : BOOL;",
    ]:
        assert quick_declarations(text, grammar_keywords()) is None, text
    result = parse_declarations("VAR\n  a : BOOL\n  b : INT;\nEND_VAR")
    assert [(d.code, d.line) for d in result.diagnostics] == [("ST-PARSE", 2)]  # the missing ";"


def test_trailing_comments_still_attach_to_quickly_read_declarations():
    result = parse_declarations("VAR\n  a : BOOL; (* the start button *)\nEND_VAR", nested_comments=True)
    assert result.ast[0].decls[0].comment == "the start button"


_LONG = (
    "VAR\n"
    + "".join(f"  A{i}, B{i} : BOOL;\n  T{i} : TON;\n" for i in range(3000))
    + "END_VAR\nVAR_INPUT RETAIN x : INT; END_VAR"
)


def test_quick_declarations_of_any_length_skip_the_nesting_walk(monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 27: they nest 3 levels (st/nesting.py's count: block, declaration, name or type) however long, so the
    parser does not walk 200,000 of them (~0.3 s of a 50,000-network build)."""

    def walked(root: object) -> None:
        raise AssertionError("the nesting walk ran")

    monkeypatch.setattr(st_parser, "too_deep", walked)
    result = parse_declarations(_LONG)
    assert result.ast is not None and not result.diagnostics


def test_quick_declarations_are_still_refused_below_their_depth(monkeypatch: pytest.MonkeyPatch) -> None:
    """Exact, not assumed: with the expression limit set below their 3 levels they are refused as the parser's
    would be (ST-TOO-DEEP), at 3 accepted."""
    monkeypatch.setenv("LADDERLAB_MAX_EXPRESSION_DEPTH", "2")
    refused = parse_declarations(_LONG)
    assert refused.ast is None and [d.code for d in refused.diagnostics] == ["ST-TOO-DEEP"]
    monkeypatch.setenv("LADDERLAB_MAX_EXPRESSION_DEPTH", "3")
    accepted = parse_declarations(_LONG)
    assert accepted.ast is not None and not accepted.diagnostics
