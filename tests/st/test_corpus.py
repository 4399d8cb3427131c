"""External corpora (../shared/external): parse rates with floors, OSCAT print round-trip.

Each corpus is parsed once per session. Files that use constructs outside this
front end are listed here with the reason (see docs/st.md); a change in that list
fails the test so it gets noticed.
"""

from __future__ import annotations

import json

import pytest

from ladderlab.st.parser import parse_source, split_units
from ladderlab.st.printer import print_source
from ladderlab.st.types import typing_rules
from tests.support import PASS_RATES, external

IRONPLC_UNSUPPORTED = {
    "program.st": "VAR_ACCESS inside a PROGRAM (a configuration's VAR_ACCESS is supported, CFG-08)",
    "oscat.st": "CODESYS export header with text outside any comment",
    "if.st": "missing ';' after END_IF followed by another statement (ST-40 makes it an error)",
    "first_steps_syntax_error.st": "deliberately invalid (missing ';')",
}


@pytest.fixture(scope="module")
def oscat():
    text = external("oscat", "oscat.st").read_text(encoding="utf-8")
    return text, parse_source(text, file="oscat.st", nested_comments=True)


def test_oscat_basic_pous_parse(oscat):
    text, result = oscat
    total = sum(1 for unit in split_units(text) if unit.pou)
    failing = {d.pou for d in result.diagnostics if d.severity == "error"}
    passed = sum(1 for pou in result.ast.pous if pou.name not in failing)
    PASS_RATES["oscat BASIC 3.33 (POUs)"] = (passed, total)
    assert total >= 540 and passed / total >= 0.99
    assert failing == {"REAL_TO_FRAC"}  # four ';' missing after END_IF in the library itself


def test_oscat_prints_and_reparses_to_the_same_ast(oscat):
    _, result = oscat
    again = parse_source(print_source(result.ast))
    assert again.diagnostics == []
    assert again.ast == result.ast


def test_ironplc_corpus_files():
    folder = external("ironplc", "compiler", "resources", "test")
    files = sorted(folder.glob("*.st"))
    failing = {f.name for f in files if not parse_source(f.read_text(encoding="utf-8"), nested_comments=True).ok}
    PASS_RATES["ironplc compiler/resources/test (files)"] = (len(files) - len(failing), len(files))
    assert failing == set(IRONPLC_UNSUPPORTED)


def test_what_st40_refuses_in_the_corpora_parses_under_codesys_typing(oscat):
    """ironplc's if.st and OSCAT's REAL_TO_FRAC have END_IF / END_REPEAT without ';' before another statement: an
    error by ST-40, a warning each under CODESYS typing (docs/st.md "CODESYS typing")."""
    text = external("ironplc", "compiler", "resources", "test", "if.st").read_text(encoding="utf-8")
    with typing_rules("codesys"):
        result = parse_source(text)
        oscat_result = parse_source(oscat[0], nested_comments=True)
    assert [(d.severity, d.message, d.line) for d in result.diagnostics] == [
        ("warning", "expected ';' after END_IF", 4),
        ("warning", "expected ';' after END_IF", 7),
    ]
    assert oscat_result.ok
    assert [(d.pou, d.message, d.line) for d in oscat_result.diagnostics if d.pou == "REAL_TO_FRAC"] == [
        ("REAL_TO_FRAC", "expected ';' after END_IF", 21325),
        ("REAL_TO_FRAC", "expected ';' after END_IF", 21329),
        ("REAL_TO_FRAC", "expected ';' after END_REPEAT", 21333),
        ("REAL_TO_FRAC", "expected ';' after END_IF", 21340),
    ]


def test_ironplc_end_to_end_programs():
    cases = json.loads(external("ironplc", "end_to_end_cases.json").read_text(encoding="utf-8"))["cases"]
    runnable = [c for c in cases if c["kind"] != "compile_error"]
    failing = [c for c in runnable if not parse_source(c["source"]).ok]
    PASS_RATES["ironplc end_to_end_cases (programs)"] = (len(runnable) - len(failing), len(runnable))
    assert [c["id"] for c in failing] == []  # REFERENCE TO, the last refused, is read since issue 25


def test_ironplc_benchmark_programs_all_parse():
    files = sorted(external("ironplc-benchmarks", "programs").glob("*.st"))
    failing = [f.name for f in files if not parse_source(f.read_text(encoding="utf-8")).ok]
    PASS_RATES["ironplc-benchmarks (programs)"] = (len(files) - len(failing), len(files))
    assert len(files) == 13 and failing == []


def test_rusty_cfc_drivers():
    files = sorted(external("rusty-cfc").rglob("*.st"))
    results = {f.name: parse_source(f.read_text(encoding="utf-8")) for f in files}
    failing = {name for name, result in results.items() if not result.ok}
    PASS_RATES["rusty-cfc ST drivers (files)"] = (len(files) - len(failing), len(files))
    # RuSTy closes FUNCTIONs with END_PROGRAM, sometimes after a statement without ';' (MANIFEST).
    messages = {r.diagnostics[0].message for n, r in results.items() if n in failing}
    assert messages == {"expected END_FUNCTION, found 'END_PROGRAM'", "expected ';', found 'END_PROGRAM'"}
    assert len(files) - len(failing) >= 11
