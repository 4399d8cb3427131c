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
from .support import build, jump, par, project, run_table, sfc_pou, step, tr
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


@given(sfc_bodies())
@settings(max_examples=30)
def test_written_textual_sfc_reads_back_as_the_same_chart(body):
    original = sfc_project(body)
    result = export_project_st(original, sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics if d.severity == "error"] == []
    assert semantics(again.pou("Seq").body) == semantics(original.pou("Seq").body)


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


@given(sfc_bodies(nested=True))
@settings(max_examples=30)
def test_written_textual_sfc_with_an_action_chart_reads_back_as_the_same_charts(body):
    original = sfc_project(body)
    result = export_project_st(original, sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics if d.severity == "error"] == []
    assert _nested_semantics(again.pou("Seq").body) == _nested_semantics(original.pou("Seq").body)
