"""ST export of SFC POUs (interchange/st/sfc.py): readable ST that runs like the chart.

The equivalence contract of the ST export (tests/interchange/st_support.py): the project as drawn and the project
with the SFC POU replaced by its exported ST run side by side with the same random writes before every scan (the
SFC flags included), and every variable they have in common (steps' X and T, actions' Q and A) must agree after
every scan.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderlab.interchange.st.export import export_pou_st
from ladderlab.interchange.st.project import export_project_st
from ladderlab.storage import load_project_path
from tests.interchange.st_support import exported, same_traces
from tests.support import EXAMPLES

from .strategies import sfc_bodies
from .support import jump, par, project, sfc_pou, step, tr
from .test_flags import chart_with
from .test_plcopen import sfc_project

ALL_FLAGS = (
    "SFCInit, SFCReset, SFCPause, SFCError, SFCEnableLimit, SFCTrans, SFCQuitError, SFCTip, SFCTipMode : BOOL; "
    "SFCErrorStep, SFCErrorPOU, SFCCurrentStep : STRING;"
)


def test_the_example_exports_to_st_that_runs_like_the_chart():
    project = load_project_path(EXAMPLES / "car_wash_sfc")
    text = exported(project, "Wash").text
    assert "Idle : SFC_STEP := (X := TRUE);" in text and "CountCar(P := Welcome.X, R := FALSE);" in text
    assert "FOR sfc_pass := 0 TO 3 DO" in text
    same_traces(project, scans=300)


def test_every_flag_exports_and_runs_alike():
    same_traces(chart_with(ALL_FLAGS), scans=300, seed=3)


@given(sfc_bodies(), st.integers(0, 1000))
@settings(max_examples=20)
def test_random_charts_export_to_st_that_runs_identically(body, seed):
    same_traces(sfc_project(body), scans=60, seed=seed)


def test_entry_exit_actions_time_limits_and_bool_variables_export_alike():
    decls = "VAR go, back, lamp : BOOL; n, m : INT; SFCError : BOOL; SFCErrorStep : STRING; END_VAR"
    chart = [
        step("S0", "N A", "S lamp"),
        tr("go"),
        par(
            [step("L1", "L B T#30ms", entry="In", exit="Out", max_time="T#40ms"), tr("back"), step("L2")],
            [step("R1", "R lamp", "P0 B")],
        ),
        tr("go AND L1.T >= T#0ms"),
        jump("S0"),
    ]
    actions = {"A": "n := n + 1;", "B": "m := m + 1;", "In": "n := n * 2;", "Out": "n := n - 3;"}
    same_traces(project(sfc_pou("Main", decls, chart, actions)), scans=200, seed=7)


def test_an_action_that_returns_cannot_be_exported():
    pou = sfc_pou(
        "Main",
        "VAR go : BOOL; n : INT; END_VAR",
        [step("S0", "N A"), tr("go"), jump("S0")],
        {"A": "IF go THEN RETURN; END_IF;\nn := n + 1;"},
    )
    result = export_pou_st(project(pou), "Main")
    assert result.text == ""
    assert ("EXPORT-UNSUPPORTED", "Main/actions/A") in {(d.code, d.file) for d in result.diagnostics}


def test_the_project_export_reads_back_with_other_pous_reading_the_steps():
    """Status reads Wash.Idle.X: in the exported project Idle is an SFC_STEP variable, still readable."""
    result = export_project_st(load_project_path(EXAMPLES / "car_wash_sfc"))
    assert [d.format() for d in result.diagnostics] == [] and "Busy := NOT Wash.Idle.X;" in result.text


def test_the_error_analysis_flags_export_and_run_alike():
    """SFCErrorAnalyzationTable and SFCErrorAnalyzation (tests/sfc/test_error_analysis.py) in the exported ST."""
    from .test_error_analysis import CONDITION, LIMIT, chart

    flags = LIMIT + " SFCErrorAnalyzation : STRING; SFCErrorAnalyzationTable : ARRAY [1..3] OF ExpressionResult;"
    proj = chart(flags)
    text = exported(proj, "Main").text
    assert f"IF NOT ({CONDITION}) AND NOT (b OR NOT c) THEN" in text
    assert "SFCErrorAnalyzationTable[sfc_analysis_n + 1].address := '%IX0.1';" in text
    same_traces(proj, scans=300, seed=5)


@given(sfc_bodies(nested=True), st.integers(0, 1000))
@settings(max_examples=20)
def test_random_charts_with_an_action_written_in_sfc_export_to_st_that_runs_identically(body, seed):
    """SFC-02 in the ST export: a random chart whose initial step associates ``Sub``, an action written in SFC (a
    random chart of its own), with a random qualifier; both run scan by scan alike under random writes."""
    same_traces(sfc_project(body), scans=60, seed=seed)


def test_an_action_written_in_sfc_exports_its_chart_final_run_and_restart():
    """The ST export of test_sfc_actions' chart: Seq's chart runs inside Seq's IF, closes in Seq's final run (its
    steps left, IncB's final run) and starts again from I0. The traces agree scan by scan, and the random writes
    reached every case the docs name: Seq's final run (A without Q) with I1 active before it, and a later
    activation starting from I0."""
    from .test_sfc_actions import chart

    proj = chart()
    text = exported(proj, "Main").text
    assert "Seq_closing := NOT Seq.Q;" in text and "FOR sfc_pass_Seq := 2 TO 3 DO" in text
    trace = same_traces(proj, scans=400, seed=11)
    finals = [i for i, row in enumerate(trace) if row["MAIN.SEQ.A"] and not row["MAIN.SEQ.Q"]]
    assert any(trace[i - 1]["MAIN.I1.X"] for i in finals if i), "no final run with I1 active in the trace"
    assert all(trace[i]["MAIN.I0.X"] and not trace[i]["MAIN.I1.X"] for i in finals)


def test_an_action_chart_with_entry_exit_actions_limits_and_flags_exports_alike():
    """Entry and exit actions and a time limit inside an action's chart, with SFCInit, SFCReset, SFCPause,
    SFCQuitError, SFCError and SFCCurrentStep written at random (they reset the inner chart too)."""
    from .test_sfc_actions import seq_action

    decls = f"VAR go, next, back : BOOL; a, b, c : INT; {ALL_FLAGS} END_VAR"
    inner = [
        step("I0", "N IncA", entry="In", exit="Out"),
        tr("next"),
        step("I1", "N IncB", max_time="T#30ms"),
        tr("back AND I1.T > T#20ms"),
        jump("I0"),
    ]
    main = [step("M0", "N Seq"), tr("go"), step("M1", "P IncC"), tr("back"), jump("M0")]
    actions = {
        "IncA": "a := a + 1;",
        "IncB": "b := b + 1;",
        "IncC": "c := c + 1;",
        "In": "c := c * 2;",
        "Out": "c := c - 1;",
    }
    proj = project(sfc_pou("Main", decls, main, actions, extra_actions=[seq_action(inner)]))
    same_traces(proj, scans=400, seed=13)
