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


def test_an_action_written_in_sfc_is_refused_by_name():
    from .test_sfc_actions import chart

    result = export_pou_st(chart(), "Main")
    assert result.text == ""
    assert (
        "EXPORT-UNSUPPORTED",
        "Main/actions/Seq",
        "the action Seq is written in SFC; the ST export writes one chart per POU: move its chart into a "
        "function block written in SFC and call that in an action",
    ) in [(d.code, d.file, d.message) for d in result.diagnostics]
