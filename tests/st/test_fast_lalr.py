"""The fast parse loop (st/fast_lalr.py, issue 27) gives exactly lark's AST, spans and annotations included, or
hands the text back to lark (``NotFast``): random programs, mutated programs, OSCAT and the benchmark's file."""

from __future__ import annotations

import dataclasses
from typing import Any

import pytest
from benchmarks.parse import generated
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.st import ast
from ladderlab.st.comments import blank_nested_comments
from ladderlab.st.fast_lalr import NotFast, fast_parse
from ladderlab.st.nesting import too_deep
from ladderlab.st.parser import _parser, split_units
from ladderlab.st.printer import print_source, print_statements
from ladderlab.st.transformer import StSyntaxError
from tests.st.test_properties import VALID, pous, statements
from tests.support import external


def every_field(node: Any) -> Any:
    """``node`` as nested tuples of all its fields (the AST's ``==`` leaves spans out)."""
    if dataclasses.is_dataclass(node) and not isinstance(node, type):
        values = tuple(every_field(getattr(node, f.name)) for f in dataclasses.fields(node))
        return (type(node).__name__, *values)
    if isinstance(node, (list, tuple)):
        return tuple(every_field(item) for item in node)
    if isinstance(node, dict):
        return tuple((key, every_field(value)) for key, value in node.items())
    return (type(node).__name__, node)


def outcome(parse, text: str, start: str) -> Any:
    """The tree's fields, or the AST builder's refusal (a keyword as a name ...) with its place."""
    try:
        return every_field(parse(text, start=start))
    except StSyntaxError as error:
        return ("refused", str(error), every_field(error.span))


def same_as_lark(text: str, start: str = "start_source") -> bool:
    """Whether the fast loop gives lark's outcome for ``text``; False when it hands the text back (an error)."""
    parser = _parser()
    try:
        fast = outcome(lambda text, start: fast_parse(parser, text, start)[0], text, start)
    except NotFast:
        return False
    assert fast == outcome(parser.parse, text, start)
    return True


def test_a_program_parses_to_lark_s_tree_with_its_spans() -> None:
    assert same_as_lark(VALID)
    tree, tokens = fast_parse(_parser(), VALID, "start_source")
    assert isinstance(tree, ast.Source) and tree.items[0].span == ast.Span(1, 1, 7, 19)
    assert tokens == len(list(_parser().lex(VALID)))


def test_a_syntax_error_is_handed_back_to_lark() -> None:
    assert not same_as_lark(VALID.replace("END_IF;", "END_IF"))
    with pytest.raises(NotFast):
        fast_parse(_parser(), "PROGRAM p\nx := ;\nEND_PROGRAM", "start_source")


@given(st.lists(pous, min_size=1, max_size=2))
def test_random_programs_parse_to_lark_s_trees(items) -> None:
    assert same_as_lark(print_source(ast.Source(items)))


@given(statements)
def test_random_statements_parse_to_lark_s_trees(tree) -> None:
    assert same_as_lark(print_statements(tree), "start_stmts")


@given(
    st.lists(
        st.tuples(
            st.integers(0, len(VALID)),
            st.integers(0, 6),
            st.sampled_from(["", ";", "(", ")", "END_IF", "'", "(*", ":=", "x", "\n", "[", ".", "// c\n", "16#F"]),
        ),
        max_size=4,
    )
)
def test_mutated_programs_parse_to_lark_s_trees_or_go_back_to_lark(edits) -> None:
    text = VALID
    for position, length, insert in edits:
        text = text[:position] + insert + text[position + length :]
    same_as_lark(text)  # asserts the trees are equal whenever the fast loop accepts the text


def test_the_benchmark_s_generated_file_parses_to_lark_s_tree() -> None:
    assert same_as_lark(generated(600))


def test_every_oscat_unit_parses_to_lark_s_tree() -> None:
    text = blank_nested_comments(external("oscat", "oscat.st").read_text(encoding="utf-8"))
    fast = sum(same_as_lark(unit.text) for unit in split_units(text))
    assert fast > 500  # the units lark parses without an error (all but a few of OSCAT's)


def _comment_text(text: str) -> str:
    while "(*" in text or "*)" in text:
        text = text.replace("(*", "(").replace("*)", ")")
    return text


@given(st.text(alphabet="ab(*)\n\r\t é", max_size=30), st.text(alphabet="ab(*)\n\r\t é", max_size=30))
def test_blanked_comments_keep_only_their_line_breaks(outer, inner) -> None:
    """ST-04: a nested comment becomes spaces, its line breaks kept, so every later line and column stays."""
    text = f"x (* {_comment_text(outer)} (* {_comment_text(inner)} *) *) y"
    blanked = blank_nested_comments(text)
    assert len(blanked) == len(text) and blanked.startswith("x ") and blanked.endswith(" y")
    assert all(b == (c if c == "\n" else " ") for b, c in zip(blanked[2:-2], text[2:-2], strict=True))


def nesting_bound_holds(text: str, start: str = "start_source") -> None:
    """The parser skips the nesting walk when 2 levels a token (expressions) or 4 tokens a level (statements)
    cannot reach the limit (parser._may_nest_too_deep): the walk itself finds nothing deeper then."""
    try:
        tree, tokens = fast_parse(_parser(), text, start)
    except (NotFast, StSyntaxError):
        return
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("LADDERLAB_MAX_EXPRESSION_DEPTH", str(2 * tokens))
        patch.setenv("LADDERLAB_MAX_STATEMENT_DEPTH", str(max(1, tokens // 4)))
        assert too_deep(tree) is None, text


@pytest.mark.parametrize(
    "body",
    [
        "x := " + "-" * 30 + "1;",
        "x := " + "f(" * 20 + "1" + ")" * 20 + ";",
        "x := " + "-" * 20 + "INT#5;",
        "x := " + "NOT " * 20 + "TRUE;",
        "x := a" + ".b" * 20 + ";",
        "x := a" + "[1]" * 20 + ";",
        "x := a" + "^" * 20 + ";",
        "IF a THEN " * 20 + "END_IF;" * 20,
        "WHILE a DO " * 20 + "END_WHILE;" * 20,
        "REPEAT " * 20 + "UNTIL a END_REPEAT;" * 20,
        "CASE a OF 1: " * 20 + "END_CASE;" * 20,
    ],
)
def test_the_nesting_walk_is_skipped_only_where_nothing_can_be_too_deep(body: str) -> None:
    nesting_bound_holds(body, "start_stmts")
    nesting_bound_holds(f"PROGRAM p\nVAR x : INT := {'-' * 10}1; END_VAR\n{body}\nEND_PROGRAM\n")


@given(st.lists(pous, min_size=1, max_size=2))
def test_random_programs_nest_within_the_bound_of_their_tokens(items) -> None:
    nesting_bound_holds(print_source(ast.Source(items)))


def test_oscat_units_nest_within_the_bound_of_their_tokens() -> None:
    text = blank_nested_comments(external("oscat", "oscat.st").read_text(encoding="utf-8"))
    for unit in split_units(text):
        nesting_bound_holds(unit.text)
