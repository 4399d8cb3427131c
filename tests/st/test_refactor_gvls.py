"""Rename everywhere (st/refactor.py) and find references with named global variable lists: a list's variable is renamed bare and
as ``GVL.x`` (in ST, LD operands and the list's own text), a list renamed renames its qualifier in every use."""

from __future__ import annotations

from ladderlab.model import GlobalVariableList, Pou, Project
from ladderlab.st.refactor import new_name_problem, references, rename
from tests.ir.diagram_support import coil, contact, ld_pou, rung

IO = GlobalVariableList(name="GVL_IO", qualified_only=True, text="VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR")
BODY = "IF GVL_IO.bStart THEN\n    s.bStart := FALSE; (* a field of that name is no use *)\nEND_IF;"
MAIN = Pou(name="Main", kind="program", language="st", declarations="VAR s : Pair; END_VAR", body=BODY)
RUNGS = ld_pou("Rungs", "", rung("n1", contact("c1", "GVL_IO.bStart"), coil("q1", "GVL_IO.bStart")))


def project() -> Project:
    return Project(name="p", gvls=[IO], pous=[MAIN, RUNGS])  # (Pair: a struct with a field bStart, not shown)


def test_renaming_a_lists_variable_renames_its_qualified_uses_and_no_field_of_that_name():
    renamed, changes = rename(project(), "bStart", "bGo")
    assert renamed.gvls[0].text == "VAR_GLOBAL\n    bGo : BOOL;\nEND_VAR"
    assert renamed.pous[0].body == BODY.replace("GVL_IO.bStart", "GVL_IO.bGo")
    rung_elements = renamed.pous[1].body.networks[0].elements
    assert [e.var for e in rung_elements] == ["GVL_IO.bGo", "GVL_IO.bGo"]
    assert [(c.part, c.pou, c.file, c.line) for c in changes] == [
        ("gvl", None, "gvls/GVL_IO", 2),
        ("body", "Main", None, 1),
        ("network", "Rungs", None, None),
        ("network", "Rungs", None, None),
    ]


def test_renaming_a_list_renames_its_qualifier_everywhere():
    renamed, _ = rename(project(), "GVL_IO", "GVL_Inputs")
    assert [g.name for g in renamed.gvls] == ["GVL_Inputs"]
    assert renamed.pous[0].body.startswith("IF GVL_Inputs.bStart THEN")
    assert [e.var for e in renamed.pous[1].body.networks[0].elements] == ["GVL_Inputs.bStart"] * 2


def test_references_to_a_list_list_its_uses():
    found = references(project(), "GVL_IO")
    assert [(r.pou, r.part, r.text) for r in found] == [
        ("Main", "body", "IF GVL_IO.bStart THEN"),
        ("Rungs", "network", "GVL_IO.bStart"),
        ("Rungs", "network", "GVL_IO.bStart"),
    ]


def test_a_new_name_taken_by_a_list_is_refused():
    assert new_name_problem(project(), "Main", "gvl_io") == "there is already a global variable list called GVL_IO"
