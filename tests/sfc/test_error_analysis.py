"""SFC-07: SFCErrorAnalyzationTable (ARRAY [0..n] OF ExpressionResult) and SFCErrorAnalyzation (STRING).

Seed 003 ("Флаги SFC"): when a step's time limit is exceeded, the table gets, for each part of the transition's
condition that makes it FALSE and so holds the transition, its name, address, comment and current value; at
most as many entries as the array has. The parts are worked out here by hand from Boolean logic, as CODESYS's
Analyzation library describes them: a FALSE ``p AND q`` is held by its FALSE operands, a FALSE ``p OR q`` by
all of its operands, ``NOT p`` by ``p`` being TRUE. Scans are 10 ms: S1 becomes active in scan 1 (T#0s) and is
over its 30 ms in scan 5 (40 ms), so SFCError is recorded in scan 5.
"""

from __future__ import annotations

from ladderlab.ir.lower_project import lower_project

from .support import build, jump, project, sfc_pou, step, tr

CONDITION = "(b OR NOT c) AND x > 5 AND sensor AND a"
LIMIT = "SFCError, SFCEnableLimit, SFCQuitError : BOOL; SFCErrorStep : STRING;"


def chart(flags: str, condition: str = CONDITION):
    decls = f"VAR go, a, b, c : BOOL; x : INT;\n  sensor AT %IX0.1 : BOOL; (* door closed *)\n  {flags}\nEND_VAR"
    elements = [step("S0"), tr("go"), step("S1", max_time="T#30ms"), tr(condition), jump("S0")]
    return project(sfc_pou("Main", decls, elements))


def run_to_timeout(proj, a=True, b=False, c=True, x=3, sensor=False):
    """Scans 0..5 with go in scan 0 and the condition's inputs as given; returns the simulation after scan 5."""
    sim = build(proj)
    for name, value in (("a", a), ("b", b), ("c", c), ("x", x), ("sensor", sensor), ("SFCEnableLimit", True)):
        sim.write(f"Main.{name}", value)
    sim.write("Main.go", True)
    sim.cycle(1)
    sim.write("Main.go", False)
    for scan in range(1, 5):
        sim.cycle(1)
        assert sim.read("Main.SFCError") is False, f"no error before scan 5 (scan {scan})"
    sim.cycle(1)
    assert sim.fault is None
    assert sim.read("Main.SFCError") is True and sim.read("Main.SFCErrorStep") == "S1"
    return sim


def entries(sim, count: int, fields=("name", "address", "comment", "value", "failed")) -> list[tuple]:
    return [tuple(sim.read(f"Main.SFCErrorAnalyzationTable[{i}].{field}") for field in fields) for i in range(count)]


def test_the_table_lists_the_parts_that_hold_the_transition_with_address_comment_and_value():
    """a TRUE (not listed), b FALSE and c TRUE hold ``b OR NOT c``; x = 3 holds ``x > 5``; sensor FALSE."""
    sim = run_to_timeout(chart(LIMIT + " SFCErrorAnalyzationTable : ARRAY [0..5] OF ExpressionResult;"))
    assert entries(sim, 6) == [
        ("b", "", "", False, True),
        ("c", "", "", True, True),
        ("x > 5", "", "", False, True),
        ("sensor", "%IX0.1", "door closed", False, True),
        ("", "", "", False, False),
        ("", "", "", False, False),
    ]


def test_the_string_joins_the_parts_and_a_short_table_keeps_the_first_ones():
    flags = LIMIT + " SFCErrorAnalyzation : STRING; SFCErrorAnalyzationTable : ARRAY [1..2] OF ExpressionResult;"
    sim = run_to_timeout(chart(flags), a=False, b=True, x=7, sensor=True)
    # b TRUE: ``b OR NOT c`` is TRUE; x = 7: ``x > 5`` TRUE; sensor TRUE; only a FALSE holds it
    assert sim.read("Main.SFCErrorAnalyzation") == "a"
    assert entries(sim, 0) == []
    assert sim.read("Main.SFCErrorAnalyzationTable[1].name") == "a"
    assert sim.read("Main.SFCErrorAnalyzationTable[2].name") == ""
    sim2 = run_to_timeout(chart(flags))
    assert sim2.read("Main.SFCErrorAnalyzation") == "b | c | x > 5 | sensor"
    assert [sim2.read(f"Main.SFCErrorAnalyzationTable[{i}].name") for i in (1, 2)] == ["b", "c"]


def test_the_analysis_keeps_its_values_of_the_timeout_scan_until_sfcquiterror_clears_it():
    flags = LIMIT + " SFCErrorAnalyzation : STRING; SFCErrorAnalyzationTable : ARRAY [0..3] OF ExpressionResult;"
    sim = run_to_timeout(chart(flags))
    sim.write("Main.b", True)  # the condition is still held by x > 5 and sensor, but the record stays as it was
    sim.cycle(1)
    assert sim.read("Main.SFCErrorAnalyzation") == "b | c | x > 5 | sensor"
    assert sim.read("Main.SFCErrorAnalyzationTable[0].value") is False
    sim.write("Main.SFCQuitError", True)
    sim.cycle(1)
    assert sim.read("Main.SFCError") is False
    assert sim.read("Main.SFCErrorAnalyzation") == ""
    assert entries(sim, 4, ("name", "value", "failed")) == [("", False, False)] * 4


def test_a_not_over_an_or_is_held_by_the_true_operands():
    """``NOT (p OR q)`` is FALSE when p or q is TRUE: only the TRUE ones hold it (p TRUE, q FALSE: p)."""
    flags = LIMIT + " SFCErrorAnalyzation : STRING; p, q : BOOL;"
    proj = chart(flags, "NOT (p OR q) AND NOT (b AND c)")
    sim = build(proj)
    for name, value in (("p", True), ("q", False), ("b", True), ("c", True), ("SFCEnableLimit", True)):
        sim.write(f"Main.{name}", value)
    sim.write("Main.go", True)
    sim.cycle(1)
    sim.write("Main.go", False)
    sim.cycle(5)
    # NOT (b AND c) is FALSE because b AND c is TRUE: both b and c hold it
    assert sim.read("Main.SFCErrorAnalyzation") == "p | b | c"


def test_a_table_of_the_wrong_type_is_a_located_error():
    result = lower_project(chart(LIMIT + " SFCErrorAnalyzationTable : ARRAY [0..3] OF INT;"))
    found = [d for d in result.diagnostics if d.code == "SFC-FLAG" and d.severity == "error"]
    assert len(found) == 1 and found[0].file == "Main/declarations"
    assert found[0].message == (
        "the SFC flag SFCErrorAnalyzationTable must be an ARRAY [0..n] OF ExpressionResult, not an array of INT"
    )


def test_a_user_type_of_its_own_with_name_and_value_is_accepted():
    """A project that declares ExpressionResult itself (as a CODESYS library would bring it) keeps its TYPE."""
    proj = chart(LIMIT + " SFCErrorAnalyzationTable : ARRAY [0..3] OF ExpressionResult;")
    proj = proj.model_copy(
        update={"types": "TYPE ExpressionResult : STRUCT name : STRING; value : BOOL; END_STRUCT; END_TYPE"}
    )
    sim = run_to_timeout(proj)
    assert entries(sim, 2, ("name", "value")) == [("b", False), ("c", True)]
