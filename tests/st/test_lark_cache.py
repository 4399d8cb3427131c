"""The ST and IL parsers' LALR tables are kept in the user's cache directory (issue 27): a second process loads
them instead of building them, and a cache directory that cannot be written changes nothing but the speed."""

from __future__ import annotations

import subprocess
import sys

from ladderlab.st import lark_cache
from ladderlab.st.parser import _STARTS, GRAMMAR

PARSE = (
    "from ladderlab.st.parser import parse_source; from ladderlab.st.il_parser import parse_il;"
    "r = parse_source('PROGRAM P VAR x : INT; END_VAR x := x + 1; END_PROGRAM');"
    "i = parse_il('LD x\\nST y\\n');"
    "print(r.ok, r.ast.items[0].name, not i.diagnostics)"
)


def _parse_in_a_fresh_process(cache: str) -> str:
    done = subprocess.run(
        [sys.executable, "-c", PARSE],
        env={"LADDERLAB_CACHE_DIR": cache, "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        check=True,
    )
    return done.stdout.strip() + done.stderr.strip()


def test_the_first_process_saves_the_tables_and_the_next_one_parses_with_them(tmp_path):
    cache = tmp_path / "cache"
    assert _parse_in_a_fresh_process(str(cache)) == "True P True"
    saved = sorted(p.name.split("-")[0] for p in cache.iterdir())
    assert saved == ["il", "st"]
    stamps = {p: p.stat().st_mtime_ns for p in cache.iterdir()}
    assert _parse_in_a_fresh_process(str(cache)) == "True P True"
    assert {p: p.stat().st_mtime_ns for p in cache.iterdir()} == stamps  # read, not written again


def test_an_unwritable_cache_directory_only_costs_the_build(tmp_path):
    blocked = tmp_path / "a-file"
    blocked.write_text("not a directory")
    assert _parse_in_a_fresh_process(str(blocked / "cache")) == "True P True"
    assert blocked.read_text() == "not a directory"


def test_the_file_name_changes_with_the_grammar_and_the_options(tmp_path, monkeypatch):
    monkeypatch.setenv(lark_cache.CACHE_ENV, str(tmp_path))
    grammar = GRAMMAR.read_text(encoding="utf-8")
    st = lark_cache.cache_file("st", grammar, {"start": _STARTS})
    assert st.parent == tmp_path
    assert lark_cache.cache_file("st", grammar + "\n", {"start": _STARTS}) != st
    assert lark_cache.cache_file("st", grammar, {"start": ["start_tests"]}) != st
    assert lark_cache.cache_file("st", grammar, {"start": _STARTS, "transformer": object()}) == st
