"""``p := 0`` for a pointer (issue 25, audit item 5). CODESYS code writes the null address as 0 (``p := 0;``,
``IF p <> 0 THEN``): under CODESYS typing the literal 0 stored in a POINTER TO or REF_TO is NULL, in an assignment,
an initial value and an argument. IEC 61131-3 ed. 3 (6.4.4.10.2) gives a reference no other value than NULL or
REF(): under IEC typing ``p := 0`` stays ST-TYPE-MISMATCH, saying NULL is the reference to no variable. No other
integer is an address.
"""

from __future__ import annotations

from ladderlab.simulation.build import build_project
from ladderlab.st.project_text import source_to_project

TEXT = """FUNCTION IsSet : BOOL
VAR_INPUT q : POINTER TO INT; END_VAR
IsSet := q <> 0;
END_FUNCTION
PROGRAM Main
VAR x : INT := 7; p : POINTER TO INT := 0; r : REF_TO INT; was, after, given, start : BOOL; y : INT; END_VAR
start := p = 0;
p := ADR(x); r := REF(x); y := p^;
was := p <> 0;
p := 0; r := 0;
after := p = 0 AND r = NULL;
given := IsSet(0);
END_PROGRAM
"""


def _build(text: str, typing: str):
    project, diagnostics = source_to_project(text, "zero")
    assert project is not None
    result = build_project(project.model_copy(update={"typing": typing}))
    return [d.format() for d in [*diagnostics, *result.diagnostics] if d.severity == "error"], result


def test_codesys_typing_stores_the_literal_0_in_a_pointer_as_null():
    found, result = _build(TEXT, "codesys")
    assert found == []
    sim = result.simulation()
    sim.cycle(1)
    assert sim.fault is None
    values = [sim.read(f"Main.{name}") for name in ("start", "y", "was", "after", "given", "p", "r")]
    assert values == [True, 7, True, True, False, "NULL", "NULL"]


def test_iec_typing_refuses_0_for_a_reference_and_names_null():
    text = "PROGRAM Main\nVAR r : REF_TO INT := 0; x : INT; END_VAR\nr := REF(x);\nr := 0;\nr := 1;\nEND_PROGRAM\n"
    found, _ = _build(text, "iec")
    hint = "under IEC typing a reference to no variable is NULL (CODESYS typing also takes 0)"
    assert found == [
        f"Main/declarations:2:23, POU Main: error ST-TYPE-MISMATCH: cannot initialise REF_TO INT with 0: {hint}",
        f"Main/body:4:6, POU Main: error ST-TYPE-MISMATCH: cannot assign 0 to REF_TO INT: {hint}",
        "Main/body:5:6, POU Main: error ST-TYPE-MISMATCH: cannot assign ANY_INT literal to REF_TO INT",
    ]


def test_codesys_typing_takes_no_other_integer_for_an_address():
    text = "PROGRAM Main\nVAR p : POINTER TO INT; END_VAR\np := 1;\nEND_PROGRAM\n"
    found, _ = _build(text, "codesys")
    assert found == ["Main/body:3:6, POU Main: error ST-TYPE-MISMATCH: cannot assign ANY_INT literal to REF_TO INT"]


def test_iec_typing_refuses_a_pointer_compared_with_0_where_it_stands():
    """IEC ed. 3 compares a reference with NULL and other references only: ``p = 0`` / ``0 <> r`` are the located
    ST-TYPE-MISMATCH of mixed operands (CODESYS typing takes them: the first test); a REFERENCE TO compares its
    target's value, so ``q <> 0`` stays an INT comparison."""
    text = (
        "PROGRAM Main\nVAR x : INT; p : POINTER TO INT; r : REF_TO INT; q : REFERENCE TO INT; a : BOOL; END_VAR\n"
        "q REF= x;\na := p = 0;\na := 0 <> r;\na := q <> 0 AND p = NULL AND r <> NULL;\nEND_PROGRAM\n"
    )
    found, _ = _build(text, "iec")
    hint = "under IEC typing a reference to no variable is NULL (CODESYS typing also takes 0)"
    assert found == [
        f"Main/body:4:6, POU Main: error ST-TYPE-MISMATCH: '=' needs operands of the same type: REF_TO INT and 0: {hint}",
        f"Main/body:5:6, POU Main: error ST-TYPE-MISMATCH: '<>' needs operands of the same type: 0 and REF_TO INT: {hint}",
    ]
    found, _ = _build(text, "codesys")
    assert found == []
