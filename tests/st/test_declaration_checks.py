"""Declarations the checker leaves unchecked (st/checker.py ``_nothing_to_check``, issue 27) check as when every one
is checked: the same diagnostics and the same symbols, on generated declarations that mix plain elementary ones with
what the declaration checks look at (edges, initial values, CONSTANT, AT, FB instances with and without FB_init
arguments, abstract FBs, pointers, names declared twice, keywords as names) in programs, function blocks and
functions.
"""

from __future__ import annotations

import re

import pytest
from benchmarks.lowering_digest import LIBRARY
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.st import checker
from ladderlab.st.checker import check_project
from ladderlab.st.project_text import source_to_project
from tests.support import fuzz_settings

NAMES = st.sampled_from(["a", "b", "Start", "x_1", "q", "x__y", "ends_", "INT", "T1"])
TYPES = st.sampled_from(
    ["BOOL", "int", "LREAL", "TON", "MyStruct", "Fb", "Abstract", "Fb2", "Fb2(n := 2)", "Fb(3)", "Unknown"]
    + ["POINTER TO INT", "STRING[5]", "ARRAY [0..1] OF Fb2[(n := 1), (n := 2)]"]
)
EXTRAS = st.sampled_from(["", "", "", " := TRUE", " := 3"])
KINDS = st.sampled_from(
    ["VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_TEMP", "VAR CONSTANT", "VAR RETAIN", "VAR_EXTERNAL"]
)


@st.composite
def declaration(draw) -> str:
    names = ", ".join(draw(st.lists(NAMES, min_size=1, max_size=3)))
    form = draw(st.sampled_from(["plain", "plain", "edge", "at"]))
    if form == "edge":
        return f"{names} : {draw(TYPES)} {draw(st.sampled_from(['R_EDGE', 'F_EDGE']))};"
    if form == "at":
        return f"{names.split(',')[0]} AT %IX0.{draw(st.integers(0, 7))} : {draw(TYPES)};"
    return f"{names} : {draw(TYPES)}{draw(EXTRAS)};"


@st.composite
def program(draw) -> str:
    blocks = [
        f"{draw(KINDS)}\n  " + "\n  ".join(draw(st.lists(declaration(), max_size=5))) + "\nEND_VAR"
        for _ in range(draw(st.integers(1, 3)))
    ]
    kind = draw(st.sampled_from(["PROGRAM", "FUNCTION_BLOCK", "FUNCTION"]))
    header = f"{kind} Main" + (" : INT" if kind == "FUNCTION" else "")
    return LIBRARY + header + "\n" + "\n".join(blocks) + "\n;\nEND_" + kind + "\n"


def _checked(text: str) -> tuple[list[str], list[tuple]]:
    project, diagnostics = source_to_project(text, "p")
    assert project is not None and not diagnostics, [d.format() for d in diagnostics]
    result = check_project(project)
    symbols = [
        (info.name, key, repr(symbol), str(symbol.type), symbol.span)
        for info in result.pous.values()
        for key, symbol in info.symbols.items()
    ]
    return [d.format() for d in result.diagnostics], symbols


@fuzz_settings(40)
@given(program())
def test_unchecked_declarations_check_as_checked_ones(text):
    quick = _checked(text)
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(checker, "_nothing_to_check", lambda *args: False)
        assert quick == _checked(text)


def test_only_plain_elementary_declarations_are_left_unchecked(monkeypatch: pytest.MonkeyPatch) -> None:
    """The shortcut is taken, and only where it may be (the property above would hold without it)."""
    answers: dict[str, bool] = {}
    nothing = checker._nothing_to_check

    def recorded(ty, decl, *rest):
        answers[decl.names[0].name] = nothing(ty, decl, *rest)
        return answers[decl.names[0].name]

    monkeypatch.setattr(checker, "_nothing_to_check", recorded)
    declarations = "VAR a, b : BOOL; c : INT := 1; d : Fb; e : BOOL R_EDGE; END_VAR VAR CONSTANT k : INT; END_VAR"
    _checked(LIBRARY + f"PROGRAM Main\n{declarations}\n;\nEND_PROGRAM\n")
    assert {name: answers[name] for name in "acdek"} == {"a": True, "c": False, "d": False, "e": False, "k": False}


@fuzz_settings(200)
@given(
    st.text(alphabet="aZq09_", max_size=70)
    | st.sampled_from(["IF", "int", "Time", "x__y", "end_", "_a", "a" * 64, "a" * 65, "A1" * 32, "é", "a\n"])
)
def test_plain_names_get_the_full_identifier_check_s_verdict(name):
    """``check_identifier`` leaves plain names (letters and digits) to the keyword check alone: the same reports as
    the full check (LEX-13, LEX-15, KW-02)."""

    def reports(checking) -> list[tuple]:
        found: list[tuple] = []
        checking(name, None, lambda *args, **kwargs: found.append((args, kwargs)))
        return found

    quick = reports(checker.check_identifier)
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(checker, "_PLAIN_NAME", re.compile(r"(?!)"))  # matches nothing: every name checked fully
        assert quick == reports(checker.check_identifier)
