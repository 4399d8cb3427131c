"""IEC textual SFC (INITIAL_STEP, STEP, TRANSITION FROM ... TO ..., ACTION) in .st files, read and written."""

from __future__ import annotations

from hypothesis import given, settings

from ladderlab.interchange.st.export import export_pou_st
from ladderlab.interchange.st.project import export_project_st
from ladderlab.model import Pou, Task
from ladderlab.model.sfc import SfcBody, SfcChart
from ladderlab.st.parser import parse_source
from ladderlab.st.printer import print_source
from ladderlab.st.project_text import source_to_project
from tests.support import external

from .strategies import sfc_bodies
from .support import build, jump, ld_network, par, project, run_table, sfc_pou, step, tr
from .test_plcopen import semantics, sfc_project

COUNTER = """FUNCTION_BLOCK CounterSFC
  VAR_INPUT Reset : BOOL; END_VAR
  VAR_OUTPUT OUT : INT; END_VAR
  VAR Cnt : INT; END_VAR
  INITIAL_STEP Start:
  END_STEP
  TRANSITION FROM Start TO ResetCounter
    := Reset;
  END_TRANSITION
  STEP ResetCounter:
    RESETCOUNTER_INLINE1(N);
    RESETCOUNTER_INLINE2(N);
  END_STEP
  ACTION RESETCOUNTER_INLINE1:
    Cnt := 17; (* ResetCounterValue *)
  END_ACTION
  ACTION RESETCOUNTER_INLINE2:
    OUT := Cnt;
  END_ACTION
  TRANSITION FROM ResetCounter TO Start
    := NOT Reset;
  END_TRANSITION
  TRANSITION FROM Start TO Count
    := NOT Reset;
  END_TRANSITION
  STEP Count:
    COUNT_INLINE3(N);
    COUNT_INLINE4(N);
  END_STEP
  ACTION COUNT_INLINE3:
    Cnt := Cnt + 1;
  END_ACTION
  ACTION COUNT_INLINE4:
    OUT := Cnt;
  END_ACTION
  TRANSITION FROM Count TO Start
    := Reset;
  END_TRANSITION
END_FUNCTION_BLOCK

PROGRAM Check
  VAR Reset : BOOL; sfc : CounterSFC; END_VAR
  sfc(Reset := Reset);
END_PROGRAM
"""


def test_a_textual_sfc_function_block_reads_and_runs_like_its_plcopen_twin():
    """Beremiz first_steps' CounterSFC as ironplc writes it (first_steps_function_block_counter_sfc.st): the same
    scan table as the PLCopen import (tests/interchange/test_plcopen_fixtures.py)."""
    project, diagnostics = source_to_project(COUNTER, "counter")
    assert [d.format() for d in diagnostics] == []
    counter = project.pou("CounterSFC")
    assert counter.language == "sfc"
    assert counter.body.actions[0].body == "Cnt := 17; (* ResetCounterValue *)"
    sim = build(project.model_copy(update={"tasks": [Task(name="t", interval="T#100ms", programs=["Check"])]}))
    counts = []
    for scan in range(30):
        sim.write("Check.Reset", scan in (10, 11, 25))
        sim.cycle(1)
        counts.append(sim.read("Check.sfc.OUT"))
    assert counts == [*range(0, 12), 17, 17, *range(18, 30), 30, *range(31, 34)]


def test_ironplc_sfc_files_read_as_charts():
    text = external("ironplc", "compiler", "resources", "test", "sfc.st").read_text()
    project, diagnostics = source_to_project(text, "sfc")
    assert [d.format() for d in diagnostics] == []
    (pou,) = project.pous
    start, condition, mid = pou.body.chart.elements
    assert (start.name, condition.condition, mid.name, mid.actions[0].action) == ("Start", "FALSE", "MidStep", "RESET")
    assert [(a.name, a.body) for a in pou.body.actions] == [("RESET", "COUNT := 0;")]


def test_the_printer_writes_textual_sfc_that_parses_back_to_the_same_tree():
    tree = parse_source(COUNTER).ast
    assert parse_source(print_source(tree)).ast == tree


def test_the_printer_writes_a_function_blocks_methods_before_its_textual_sfc_body():
    """A METHOD and a PROPERTY stand between the VAR blocks and the SFC body (the grammar's order): printed there,
    the text parses back to the same tree, and the SFC words in the method's body stay names (``step``)."""
    text = """FUNCTION_BLOCK Seq
VAR step : INT; END_VAR
METHOD Next : INT
step := step + 1;
Next := step;
END_METHOD
PROPERTY Now : INT
GET
Now := step;
END_GET
END_PROPERTY
INITIAL_STEP S0:
END_STEP
STEP S1:
END_STEP
TRANSITION FROM S0 TO S1
:= step > 2;
END_TRANSITION
END_FUNCTION_BLOCK
"""
    result = parse_source(text)
    assert result.diagnostics == []
    tree = result.ast
    printed = print_source(tree)
    assert "    METHOD Next : INT\n        step := step + 1;\n" in printed
    assert printed.index("END_PROPERTY") < printed.index("INITIAL_STEP S0:")
    assert parse_source(printed).ast == tree


@given(sfc_bodies(named=True))
@settings(max_examples=30)
def test_written_textual_sfc_reads_back_as_the_same_chart(body):
    """Random charts, some of whose transitions read named transitions in ST or IL: the same chart and the same
    named transitions come back; the read chart is drawn from its graph (branches may change places), and its text
    read and written again is the same text."""
    original = sfc_project(body)
    result = export_project_st(original, sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics if d.severity == "error"] == []
    assert semantics(again.pou("Seq").body) == semantics(original.pou("Seq").body)
    assert _named(again.pou("Seq").body) == _named(original.pou("Seq").body)
    written = export_project_st(again, sfc_text=True).text  # the chart redrawn from its graph: then stable
    assert export_project_st(source_to_project(written, "third")[0], sfc_text=True).text == written


def _named(body: SfcBody) -> list[tuple[str, str, object]]:
    """The named transitions (their order in the text is that of the chart, not of the list)."""
    return sorted((t.name, t.language, t.body) for t in body.transitions)


def test_parallel_branches_and_priorities_in_text():
    chart = [
        step("S0", "N A"),
        tr("go", priority=1),
        par([step("L1", "L A T#20ms"), tr("back"), step("L2")], [step("R1")]),
        tr("go"),
        jump("S0"),
    ]
    pou = sfc_pou("Main", "VAR go, back : BOOL; n : INT; END_VAR", chart, {"A": "n := n + 1;"})
    text = export_pou_st(project(pou), "Main", sfc_text=True).text
    assert "TRANSITION (PRIORITY := 1) FROM S0 TO (L1, R1)" in text
    assert "TRANSITION FROM (L2, R1) TO S0" in text and "A(L, T#20ms);" in text
    again, diagnostics = source_to_project(text, "again")
    assert diagnostics == [] and semantics(again.pou("Main").body) == semantics(pou.body)


def test_what_textual_sfc_cannot_say_is_refused_by_name():
    chart = [step("S0", entry="A"), tr("go"), jump("S0")]
    pou = sfc_pou("Main", "VAR go : BOOL; n : INT; END_VAR", chart, {"A": "n := 1;"})
    result = export_pou_st(project(pou), "Main", sfc_text=True)
    assert result.text == "" and [d.message for d in result.diagnostics] == [
        "step S0 has entry or exit actions or time limits, which textual SFC cannot say"
    ]


def test_a_chart_that_cannot_be_drawn_is_a_located_error():
    text = """PROGRAM P
  VAR a : BOOL; END_VAR
  INITIAL_STEP A:
  END_STEP
  STEP B:
  END_STEP
  STEP C:
  END_STEP
  STEP D:
  END_STEP
  TRANSITION FROM A TO (B, C, D)
    := a;
  END_TRANSITION
  TRANSITION FROM (B, C) TO A
    := a;
  END_TRANSITION
END_PROGRAM
"""
    project_, diagnostics = source_to_project(text, "p")
    assert [(d.code, d.pou, d.line) for d in diagnostics] == [("ST-SFC", "P", 3)]
    assert "do not join at one transition" in diagnostics[0].message
    assert isinstance(project_.pou("P"), Pou)


NESTED = """PROGRAM Main
  VAR go, next, back : BOOL; a, b : INT; END_VAR
  INITIAL_STEP M0:
    Seq(N);
  END_STEP
  TRANSITION FROM M0 TO M1
    := go;
  END_TRANSITION
  STEP M1:
  END_STEP
  TRANSITION FROM M1 TO M0
    := back;
  END_TRANSITION
  ACTION Seq:
    INITIAL_STEP I0:
      IncA(N);
    END_STEP
    TRANSITION FROM I0 TO I1
      := next;
    END_TRANSITION
    STEP I1:
      IncB(N);
    END_STEP
    TRANSITION FROM I1 TO I0
      := FALSE;
    END_TRANSITION
  END_ACTION
  ACTION IncA:
    a := a + 1;
  END_ACTION
  ACTION IncB:
    b := b + 1;
  END_ACTION
END_PROGRAM
"""


def test_an_action_written_in_sfc_reads_from_text_and_runs_like_the_drawn_one():
    """SFC-02 in textual SFC: IEC's ``ACTION name: function_block_body END_ACTION`` takes a chart as the body
    (B.1.6); the action Seq of test_sfc_actions written so reads as an SFC action and runs the same scan table as
    the drawn one (test_an_sfc_action_runs_its_chart_while_active_and_closes_it_in_its_final_run)."""
    proj, diagnostics = source_to_project(NESTED, "nested")
    assert [d.format() for d in diagnostics] == []
    seq = proj.pou("Main").body.action("Seq")
    assert seq.language == "sfc" and [e.name for e in seq.body.elements if e.type == "step"] == ["I0", "I1"]
    run_table(
        proj,
        """
        scan go next back || Seq.Q Seq.A I0.X I1.X a b M0.X M1.X
        0    0  0    0    || 1     1     1    0    1 0 1    0
        1    0  1    0    || 1     1     0    1    2 0 1    0
        2    0  0    0    || 1     1     0    1    3 1 1    0
        3    1  0    0    || 1     1     0    1    3 2 0    1
        4    0  0    0    || 0     1     1    0    3 3 0    1
        5    0  0    0    || 0     0     1    0    3 3 0    1
        6    0  0    1    || 0     0     1    0    3 3 1    0
        7    0  0    0    || 1     1     1    0    4 3 1    0
        """,
    )


def test_an_action_written_in_sfc_is_written_as_a_chart_inside_its_action():
    from .test_sfc_actions import chart

    result = export_pou_st(chart(), "Main", sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    assert "    ACTION Seq:\n        INITIAL_STEP I0:\n            IncA(N);\n        END_STEP\n" in result.text
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics] == []
    assert _nested_semantics(again.pou("Main").body) == _nested_semantics(chart().pou("Main").body)
    tree = parse_source(result.text).ast
    assert parse_source(print_source(tree)).ast == tree


def _nested_semantics(body: SfcBody) -> tuple:
    """The POU chart's semantics and each SFC action's chart's (ids differ after a round trip)."""
    charts = {a.name: semantics(SfcBody(chart=a.body)) for a in body.actions if isinstance(a.body, SfcChart)}
    plain = body.model_copy(update={"actions": [a for a in body.actions if not isinstance(a.body, SfcChart)]})
    return semantics(plain), charts


@given(sfc_bodies(nested=True, named=True))
@settings(max_examples=30)
def test_written_textual_sfc_with_an_action_chart_reads_back_as_the_same_charts(body):
    original = sfc_project(body)
    result = export_project_st(original, sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics if d.severity == "error"] == []
    assert _nested_semantics(again.pou("Seq").body) == _nested_semantics(original.pou("Seq").body)
    assert _named(again.pou("Seq").body) == _named(original.pou("Seq").body)


NAMED = [  # (name, language, body): T1 the accumulator after its last line (IL), T2 an ST expression
    ("T1", "il", "LD n\nGE 2\nAND go"),
    ("T2", "st", "back OR n >= 5"),
]


def named_chart():
    """S0 [N Inc] -(T1)-> S1 -(T2, PRIORITY 1)-> S0: a drawn chart whose two transitions are named ones."""
    chart = [step("S0", "N Inc"), tr("T1"), step("S1"), tr("T2", priority=1), jump("S0")]
    transitions = [{"name": n, "language": language, "body": body} for n, language, body in NAMED]
    pou = sfc_pou(
        "Main", "VAR go, back : BOOL; n : INT; END_VAR", chart, {"Inc": "n := n + 1;"}, transitions=transitions
    )
    return project(pou)


NAMED_TABLE = """
scan go back || n S0.X S1.X T1 T2
0    0  0    || 1 1    0    0  0   # Inc: n = 1; T1 = 1 >= 2 AND go
1    1  0    || 2 0    1    1  0   # Inc: n = 2; T1 = 2 >= 2 AND TRUE fires
2    0  0    || 3 0    1    0  0   # Inc's final run: n = 3; T2 = back OR 3 >= 5
3    0  0    || 3 0    1    0  0
4    0  1    || 3 1    0    0  1   # T2 = back fires
5    0  0    || 4 1    0    0  0
6    0  0    || 5 1    0    0  1   # T2 = 5 >= 5 is TRUE, but S1 is not active
7    1  0    || 6 0    1    1  1   # T1 fires
8    0  0    || 7 1    0    0  1   # Inc's final run: n = 7; T2 = 7 >= 5 fires at once
9    0  0    || 8 1    0    0  1
"""


def test_named_transitions_in_st_and_il_are_written_as_iec_transitions_and_read_back_the_same():
    """IEC 61131-3 B.1.6 ``TRANSITION name [(PRIORITY := n)] FROM steps TO steps transition_condition``: an ST named
    transition (SFC-03) as ``:= expression;``, an IL one as ``:`` and its instructions (the accumulator's final value,
    as CODESYS's IL transition). Read back they are the same named transitions, the text written again is the same
    text, and the read project runs the drawn chart's scan table (worked out by hand from docs/sfc.md's scan order:
    actions, then the named transitions and the conditions, then the transitions that fire)."""
    drawn = named_chart()
    run_table(drawn, NAMED_TABLE)
    result = export_pou_st(drawn, "Main", sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    assert "    TRANSITION T1 FROM S0 TO S1:\n        LD n\n        GE 2\n        AND go\n    END_TRANSITION\n" in (
        result.text
    )
    assert "    TRANSITION T2 (PRIORITY := 1) FROM S1 TO S0\n        := back OR n >= 5;\n    END_TRANSITION\n" in (
        result.text
    )
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics] == []
    body = again.pou("Main").body
    assert sorted((t.name, t.language, t.body) for t in body.transitions) == sorted(NAMED)
    assert semantics(body) == semantics(drawn.pou("Main").body)
    assert export_pou_st(again, "Main", sfc_text=True).text == result.text
    run_table(again, NAMED_TABLE)


def test_a_named_transition_used_twice_is_written_at_both_and_read_back_once():
    """Two chart transitions read T1: each is written ``TRANSITION T1 ...`` with T1's condition, and the text reads
    back as one named transition read by both."""
    chart = [step("S0"), tr("T1"), step("S1"), tr("T1"), jump("S0")]
    pou = sfc_pou("Main", "VAR go : BOOL; END_VAR", chart, transitions=[{"name": "T1", "body": "go"}])
    text = export_pou_st(project(pou), "Main", sfc_text=True).text
    assert text.count("TRANSITION T1 FROM") == 2 and text.count(":= go;") == 2
    again, diagnostics = source_to_project(text, "again")
    assert diagnostics == []
    body = again.pou("Main").body
    assert [(t.name, t.language, t.body) for t in body.transitions] == [("T1", "st", "go")]
    assert semantics(body) == semantics(pou.body)


def test_a_named_transition_in_ld_or_used_by_no_chart_transition_is_refused_by_name():
    """An LD (or FBD) named transition has no textual form (B.1.6's textual transitions are ST or IL); nor has a
    named transition that no chart transition has as its whole condition (it would be lost): EXPORT-UNSUPPORTED in
    the transition's file."""
    ld = {
        "name": "Ready",
        "language": "ld",
        "body": ld_network({"type": "contact", "id": "c1", "var": "go"}, {"type": "coil", "id": "k1", "var": "Ready"}),
    }
    unused = {"name": "Spare", "language": "st", "body": "go"}
    chart = [step("S0"), tr("Ready"), step("S1"), tr("NOT Spare"), jump("S0")]
    pou = sfc_pou("Main", "VAR go : BOOL; END_VAR", chart, transitions=[ld, unused])
    result = export_pou_st(project(pou), "Main", sfc_text=True)
    assert result.text == ""
    assert [(d.code, d.pou, d.file, d.message) for d in result.diagnostics] == [
        (
            "EXPORT-UNSUPPORTED",
            "Main",
            "Main/transitions/Ready",
            "the named transition Ready is written in LD: textual SFC has transition conditions in ST and IL",
        ),
        (
            "EXPORT-UNSUPPORTED",
            "Main",
            "Main/transitions/Spare",
            "the named transition Spare is the whole condition of no transition of the chart: textual SFC writes it "
            "only as a TRANSITION of its own name",
        ),
    ]


def test_textual_transitions_that_name_no_one_condition_are_located_errors():
    """A name written twice with two conditions, and an IL condition without a name (the model keeps IL conditions
    as named transitions only): ST-SFC at the TRANSITION's line."""
    text = """PROGRAM P
  VAR a, b : BOOL; END_VAR
  INITIAL_STEP A:
  END_STEP
  TRANSITION T1 FROM A TO B
    := a;
  END_TRANSITION
  STEP B:
  END_STEP
  TRANSITION T1 FROM B TO C
    := b;
  END_TRANSITION
  STEP C:
  END_STEP
  TRANSITION FROM C TO A:
    LD a
  END_TRANSITION
END_PROGRAM
"""
    _, diagnostics = source_to_project(text, "p")
    assert [(d.code, d.pou, d.line, d.message) for d in diagnostics] == [
        ("ST-SFC", "P", 10, "the transition T1 is written again with another condition: one name, one condition"),
        (
            "ST-SFC",
            "P",
            15,
            "an IL transition condition is kept as a named transition: give it a name (TRANSITION name FROM)",
        ),
    ]


def test_a_hand_written_il_transition_condition_reads_as_a_named_il_transition():
    """B.1.6 ``transition_condition ::= ':' simple_instruction_list``, keywords in any case, a priority and a
    simultaneous divergence before the ``:``; a step called TOP and a comment do not disturb the reader."""
    text = """PROGRAM P
  VAR a, b : BOOL; END_VAR
  INITIAL_STEP TOP:
  END_STEP
  transition Go (PRIORITY := 2) from TOP to (S1, S2):
    LD a (* TO x: *)
    AND b
  end_transition
  STEP S1:
  END_STEP
  STEP S2:
  END_STEP
  TRANSITION FROM (S1, S2) TO TOP
    := NOT a;
  END_TRANSITION
END_PROGRAM
"""
    proj, diagnostics = source_to_project(text, "p")
    assert [d.format() for d in diagnostics] == []
    body = proj.pou("P").body
    assert [(t.name, t.language, t.body) for t in body.transitions] == [("Go", "il", "LD a (* TO x: *)\nAND b")]
    top, go = body.chart.elements[:2]
    assert (top.name, go.condition, go.priority) == ("TOP", "Go", 2)
    run_table(
        proj,
        """
        scan a b || Go TOP.X S1.X S2.X
        0    1 0 || 0  1     0   0
        1    1 1 || 1  0     1   1
        2    1 1 || 1  0     1   1
        3    0 1 || 0  1     0   0
        """,
        pou="P",
    )
