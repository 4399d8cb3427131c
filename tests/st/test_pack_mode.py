"""CODESYS's ``{attribute 'pack_mode' := 'N'}`` in the TYPE text (issue 25 item 1, docs/st.md): the pragma belongs to
the TYPE declaration it stands above ("Insert location: above the declaration of the data structure", CODESYS's
"Attribute: pack_mode"), it survives printing, saving and ST import, and a value CODESYS does not know (0, 1, 2, 4,
8) or a pack_mode on what is no STRUCT is a located error; one above anything else (a function block, a variable, a
member, a statement) packs nothing and is a located warning. Its effect on the bytes:
tests/engine/test_struct_pack_mode.py.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderlab.model import Project
from ladderlab.model.project import Method, Pou
from ladderlab.simulation.build import build_project
from ladderlab.st.checker import check_project
from ladderlab.st.parser import parse_source
from ladderlab.st.printer import print_source
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

TYPES = (
    "{attribute 'pack_mode' := '1'}\n"
    "TYPE A : STRUCT a : BYTE; b : DINT; END_STRUCT; END_TYPE\n"
    "(* a comment and another pragma between *) {attribute 'qualified_only'}\n"
    "TYPE\n"
    "    B : STRUCT a : BYTE; END_STRUCT;\n"
    "    {ATTRIBUTE 'pack_mode' := '2'} (* inside the block, above the name *)\n"
    "    C : STRUCT a : BYTE; END_STRUCT;\n"
    "    D : STRUCT {attribute 'pack_mode' := '4'} a : BYTE; END_STRUCT; (* above a member: no TYPE's *)\n"
    "END_TYPE\n"
    "TYPE E : STRUCT s : STRING := '{attribute $'pack_mode$' := $'8$'}'; END_STRUCT; END_TYPE // in a string\n"
    "(* {attribute 'pack_mode' := '8'} *) TYPE F : STRUCT a : BYTE; END_STRUCT; END_TYPE\n"
)


def pack_modes(text: str) -> dict[str, str | None]:
    parsed = parse_source(text)
    assert parsed.ok, parsed.diagnostics
    return {decl.name: decl.pack_mode for item in parsed.ast.items for decl in item.decls}


def test_the_pragma_belongs_to_the_type_declaration_it_stands_above():
    """Above TYPE or above the name in the block, past comments and other pragmas; not one above a member, in a
    string or in a comment."""
    assert pack_modes(TYPES) == {"A": "1", "B": None, "C": "2", "D": None, "E": None, "F": None}


def test_printing_keeps_the_pragma_above_the_declaration():
    printed = print_source(parse_source(TYPES).ast)
    assert "TYPE\n    {attribute 'pack_mode' := '1'}\n    A : STRUCT\n" in printed
    assert pack_modes(printed) == pack_modes(TYPES)


def test_st_import_keeps_a_pragma_above_type_in_the_types_text():
    """A whole ST file cut into the project model: the TYPE block's text starts at TYPE, the pragma above it
    comes along."""
    project, diagnostics = source_to_project(TYPES + "PROGRAM Main\nVAR\n  a : A;\nEND_VAR\nEND_PROGRAM\n")
    assert [(d.code, d.line, d.column) for d in diagnostics] == [("ST-PRAGMA", 8, 16)] and project is not None
    assert project.types.startswith("{attribute 'pack_mode' := '1'}\nTYPE A : STRUCT")
    assert pack_modes(project.types) == pack_modes(TYPES)


def test_a_saved_project_keeps_the_pragma(tmp_path: Path):
    workspace = Workspace(tmp_path / "ws")
    workspace.create(Project(name="packed", types=TYPES.rstrip()))
    assert workspace.load("packed").project.types == TYPES.rstrip()
    assert (tmp_path / "ws" / "packed" / "types.st").read_text(encoding="utf-8").startswith(TYPES[:40])


@pytest.mark.parametrize(
    ("types", "message", "line"),
    [
        (
            "TYPE N : INT; END_TYPE\n\n{attribute 'pack_mode' := '3'}\nTYPE P : STRUCT\n  a : BYTE;\nEND_STRUCT\nEND_TYPE\n",
            "the attribute 'pack_mode' of the STRUCT 'P' is '3': CODESYS packs with '0' or '1' (no padding), '2', '4' "
            "or '8' (members aligned to at most that many bytes)",
            4,
        ),
        (
            "TYPE\n  {attribute 'pack_mode' := ''}\n  P : STRUCT a : BYTE; END_STRUCT;\nEND_TYPE\n",
            "the attribute 'pack_mode' of the STRUCT 'P' is '': CODESYS packs with '0' or '1' (no padding), '2', '4' "
            "or '8' (members aligned to at most that many bytes)",
            3,
        ),
        (
            "TYPE S : STRUCT a : BYTE; END_STRUCT; END_TYPE\nTYPE\n  {attribute 'pack_mode' := '1'}\n  P : S;\nEND_TYPE\n",
            "the attribute 'pack_mode' packs a STRUCT, and the type 'P' is not one: put it above a STRUCT's TYPE "
            "declaration, or remove it",
            4,
        ),
    ],
)
def test_a_pack_mode_codesys_does_not_know_is_a_located_error(types, message, line):
    """Never laid out naturally instead: the value (or the type it stands above) is wrong, at the declaration."""
    result = check_project(Project(name="p", types=types))
    assert [(d.code, d.message, d.file, d.line) for d in result.diagnostics] == [("ST-DECL", message, "types", line)]


NO_EFFECT = (
    "the attribute 'pack_mode' has no effect here: it packs a STRUCT when it stands above the STRUCT's TYPE "
    "declaration (a function block, a variable or a member keeps its layout); move it there or remove it"
)


def test_a_pack_mode_above_a_member_a_variable_or_a_statement_is_a_located_warning():
    """Wherever the project keeps it - above a STRUCT's member in the types, a global, a POU's variable, a method's
    variable, a statement - the pragma packs nothing: ST-PRAGMA at the pragma (file, line, column to just after its
    closing brace), and the project still builds; the one above the STRUCT's TYPE packs it and says nothing."""
    types = (
        "{attribute 'pack_mode' := '1'}\nTYPE A : STRUCT a : BYTE; b : DINT; END_STRUCT; END_TYPE\n"
        "TYPE B : STRUCT\n  {attribute 'pack_mode' := '2'}\n  a : BYTE;\nEND_STRUCT\nEND_TYPE\n"
    )
    globals_ = "VAR_GLOBAL\n  {attribute 'pack_mode' := '1'} g : A;\nEND_VAR"
    block = Pou(
        name="F",
        kind="function_block",
        language="st",
        declarations="VAR\n    {attribute 'pack_mode' := '4'}\n    x : B;\nEND_VAR",
        body="x.a := 1;\n{attribute 'pack_mode' := '8'}\nx.a := 2;",
        methods=[Method(name="M", declarations="VAR\n{attribute 'pack_mode' := '1'}\nv : INT;\nEND_VAR", body="")],
    )
    main = Pou(name="Main", kind="program", language="st", declarations="VAR f : F; END_VAR", body="f();")
    project = Project(name="p", types=types, globals=globals_, pous=[block, main])
    found = check_project(project).diagnostics
    assert [(d.severity, d.code, d.message) for d in found] == [("warning", "ST-PRAGMA", NO_EFFECT)] * 5
    assert [(d.file, d.pou, d.line, d.column, d.end_line, d.end_column) for d in found] == [
        ("types", None, 4, 3, 4, 33),
        ("globals", None, 2, 3, 2, 33),
        ("F/declarations", "F", 2, 5, 2, 35),
        ("F/body", "F", 2, 1, 2, 31),
        ("F.M/declarations", "F.M", 2, 1, 2, 31),
    ]
    assert not [d for d in build_project(project).diagnostics if d.severity == "error"]


def test_st_import_warns_of_a_pack_mode_above_a_function_block():
    """In an ST file a pragma above a FUNCTION_BLOCK (CODESYS's Telegram example shape) is a warning at its line and
    column, named by no POU (it stands outside every one); the FB is read as without it."""
    text = "TYPE S : STRUCT a : BYTE; END_STRUCT; END_TYPE\n\n  {attribute 'pack_mode' := '1'}\nFUNCTION_BLOCK F\n"
    text += "VAR h : BYTE; n : DINT; END_VAR\nEND_FUNCTION_BLOCK\n"
    project, diagnostics = source_to_project(text)
    assert project is not None and [p.name for p in project.pous] == ["F"]
    assert [(d.severity, d.code, d.message, d.pou, d.line, d.column) for d in diagnostics] == [
        ("warning", "ST-PRAGMA", NO_EFFECT, None, 3, 3)
    ]
