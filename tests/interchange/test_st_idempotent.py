"""The exported ST is already in printed form (issue 28): parsing it and printing it again gives the same statements
(only the network comments, which the parser drops, are missing), and printing is idempotent; the aligned
declarations read exactly as the unaligned ones and aligning twice changes nothing."""

from __future__ import annotations

import json
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

import tests.ir.test_diagram_equivalence as generated
from ladderlab.st.columns import align_declarations
from ladderlab.st.parser import parse_declarations, parse_pou
from ladderlab.st.printer import print_statements
from tests.interchange.st_support import exported
from tests.interchange.test_st_equivalence import controls, with_controls
from tests.interchange.test_st_fbd_equivalence import programs
from tests.ir.diagram_support import project


def reprinted(text: str) -> tuple[str, str]:
    """The exported body without its comment lines, and the body printed from the parse of the text."""
    parsed = parse_pou(text)
    assert parsed.ok, [d.format() for d in parsed.diagnostics]
    body = text.split("END_VAR\n")[-1].rsplit("END_", 1)[0]
    statements = "".join(line + "\n" for line in _without_comments(body.splitlines()))
    return statements, print_statements(parsed.ast.body)


def _without_comments(lines: list[str]) -> list[str]:
    kept, inside = [], False
    for line in lines:
        stripped = line.strip()
        if not inside and stripped.startswith("(*"):
            inside = not stripped.endswith("*)")
            continue
        if inside:
            inside = not stripped.endswith("*)")
            continue
        kept.append(line)
    return kept


def assert_stable(text: str) -> None:
    statements, printed = reprinted(text)
    assert printed == statements
    again = parse_pou(text.replace(statements, printed))
    assert print_statements(again.ast.body) == printed


@given(st.lists(generated.rungs, min_size=1, max_size=4), controls)
def test_property_exported_ld_and_fbd_reprint_to_themselves(program, choices):
    for pou in (generated.ld_program(program), generated.fbd_program(program)):
        assert_stable(exported(project(with_controls(pou, choices)), "Main").text)


@given(programs())
def test_property_exported_rich_fbd_reprints_to_itself(pou):
    assert_stable(exported(project(pou), "Main").text)


names = st.from_regex(r"[A-Za-z][A-Za-z0-9_]{0,11}", fullmatch=True).filter(
    lambda n: n.upper() not in {"AT", "VAR", "END_VAR", "TRUE", "FALSE", "OR", "AND", "XOR", "NOT", "MOD", "IF", "DO"}
)
declaration = st.tuples(
    names,
    st.sampled_from(["BOOL", "INT", "TON", "ARRAY [0..3] OF INT", "STRING[20]", "TIME"]),
    st.sampled_from(["", " := 0", " := TRUE"]),
    st.sampled_from(["", " (* a comment *)", " // another"]),
    st.sampled_from([" ", "  ", "\t", ""]),
)


@given(
    st.lists(st.lists(declaration, min_size=1, max_size=6, unique_by=lambda d: d[0].upper()), min_size=1, max_size=3)
)
def test_property_aligned_declarations_read_the_same_and_align_once(blocks):
    lines = []
    for block in blocks:
        lines.append("VAR")
        for name, type_text, init, comment, gap in block:
            if (init == " := TRUE") != (type_text == "BOOL") or (init == " := 0" and type_text not in ("INT",)):
                init = ""
            lines.append(f"  {name}{gap}:{gap}{type_text}{init};{gap}{comment}")
        lines.append("END_VAR")
    text = "\n".join(lines)
    aligned = align_declarations(text)
    original = parse_declarations(text)
    assert original.ok
    assert parse_declarations(aligned).ast == original.ast
    assert [d.comment for b in parse_declarations(aligned).ast for d in b.decls] == [
        d.comment for b in original.ast for d in b.decls
    ]
    assert align_declarations(aligned) == aligned
    for block in parse_declarations(aligned).ast:  # the colons of a block line up
        columns = {aligned.splitlines()[d.span.line - 1].index(":") for d in block.decls}
        assert len(columns) == 1


def test_declarations_are_aligned_as_an_engineer_aligns_them():
    text = (
        "VAR\n  RunTimer : TON; (* motor has been running for 5 s *)\n    StartCounter:CTU;\n"
        "  Lamp : BOOL := TRUE;   // on\nEND_VAR\nVAR_INPUT x : INT; END_VAR"
    )
    assert align_declarations(text) == (
        "VAR\n"
        "    RunTimer     : TON;             (* motor has been running for 5 s *)\n"
        "    StartCounter : CTU;\n"
        "    Lamp         : BOOL := TRUE;    // on\n"
        "END_VAR\n"
        "VAR_INPUT x : INT; END_VAR"
    )


def test_the_export_aligns_declarations_like_the_browser():
    """tests/fixtures/declaration_columns.json holds the cases the frontend's alignDeclarations meets too."""
    cases = json.loads((Path(__file__).parents[1] / "fixtures" / "declaration_columns.json").read_text())["cases"]
    for case in cases:
        assert align_declarations(case["input"]) == case["expected"]
