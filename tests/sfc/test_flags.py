"""SFC-07: the SFC flags a POU declares (seed 003, "Флаги SFC"), scan by scan.

S0 [N A0] -(go)-> S1 [N A1, at most 30 ms] -(back)-> S2 [N A2, at most 10 ms] -(go)-> S0; each action counts its
runs. The seed: SFCInit returns to the initial step and resets the flags, the initial step is active but not
executed while SFCInit is TRUE; SFCReset is the same but execution goes on (so the initial step may clear
SFCReset itself); SFCPause stops the chart while TRUE; SFCError becomes TRUE when a step is active longer than its
time (with SFCEnableLimit TRUE), SFCErrorStep and SFCErrorPOU name it, later timeouts are not recorded until
SFCError is reset; SFCQuitError pauses and clears the error, and the active steps' times restart when it falls;
SFCTrans is TRUE when a transition fires; SFCCurrentStep names the active step (of parallel ones, the right-most);
with SFCTipMode a transition fires only while SFCTip is TRUE. docs/sfc.md lists the decisions where the seed leaves
a choice.
"""

from __future__ import annotations

from .support import jump, par, project, run_table, sfc_pou, step, tr

ACTIONS = {
    "A0": "n0 := n0 + 1;",
    "A1": "n1 := n1 + 1;",
    "A2": "n2 := n2 + 1;",
}


def chart_with(flags: str, actions: dict[str, str] | None = None):
    decls = f"VAR go, back : BOOL; n0, n1, n2 : INT; {flags} END_VAR"
    chart = [
        step("S0", "N A0"),
        tr("go"),
        step("S1", "N A1", max_time="T#30ms"),
        tr("back"),
        step("S2", "N A2", max_time="T#10ms"),
        tr("go"),
        jump("S0"),
    ]
    return project(sfc_pou("Main", decls, chart, {**ACTIONS, **(actions or {})}))


def test_sfcinit_holds_the_initial_step_without_running_it():
    run_table(
        chart_with("SFCInit : BOOL; SFCCurrentStep : STRING;"),
        """
        scan go SFCInit || S0.X S1.X n0 n1 SFCCurrentStep
        0    1  0       || 0    1    1  0  'S1'
        1    0  0       || 0    1    2  1  'S1'     # A0's final run
        2    0  1       || 1    0    2  1  'S0'     # back to S0, which does not run
        3    1  1       || 1    0    2  1  'S0'     # nor does any transition
        4    0  0       || 1    0    3  1  'S0'     # released: S0 runs; A1 got no final run
        5    1  0       || 0    1    4  1  'S1'
        """,
    )


def test_sfcreset_goes_back_to_the_initial_step_and_runs_on_so_the_initial_step_can_clear_it():
    run_table(
        chart_with("SFCReset : BOOL;", {"A0": "n0 := n0 + 1; SFCReset := FALSE;"}),
        """
        scan go SFCReset || S0.X S1.X n0 n1 SFCReset
        0    1  0        || 0    1    1  0  0
        1    0  0        || 0    1    2  1  0
        2    0  1        || 1    0    3  1  0          # reset, then S0 runs in the same scan and clears SFCReset
        3    0  -        || 1    0    4  1  0
        """,
    )


def test_sfcpause_stops_actions_and_transitions():
    run_table(
        chart_with("SFCPause : BOOL;"),
        """
        scan go back SFCPause || S1.X S2.X n1 n2
        0    1  0    0        || 1    0    0  0
        1    0  0    0        || 1    0    1  0
        2    0  1    1        || 1    0    1  0
        3    0  1    1        || 1    0    1  0
        4    0  1    0        || 0    1    2  0
        5    0  0    0        || 0    1    3  1          # A1's final run
        """,
    )


FLAGS = "SFCError, SFCEnableLimit : BOOL; SFCErrorStep, SFCErrorPOU : STRING;"


def test_sfcerror_records_the_first_step_over_its_time_until_it_is_reset():
    """S1 is active from scan 1 (T#0s) and passes 30 ms in scan 5; S2 passes 10 ms in scan 9 while SFCError is
    still TRUE (not recorded); after the user clears SFCError in scan 10 it is recorded in that scan."""
    run_table(
        chart_with(FLAGS),
        """
        scan go back SFCEnableLimit SFCError || S1.T SFCError SFCErrorStep SFCErrorPOU
        0    1  0    1              -        || 0    0        ''           ''
        1    0  0    1              -        || 0    0        ''           ''
        2    0  0    1              -        || 10   0        ''           ''
        3    0  0    1              -        || 20   0        ''           ''
        4    0  0    1              -        || 30   0        ''           ''
        5    0  0    1              -        || 40   1        'S1'         'Main'
        6    0  1    1              -        || 50   1        'S1'         'Main'
        7    0  0    1              -        || 50   1        'S1'         'Main'   # S2: T#0s
        8    0  0    1              -        || 50   1        'S1'         'Main'   # S2: 10 ms
        9    0  0    1              -        || 50   1        'S1'         'Main'   # S2: 20 ms, not recorded
        10   0  0    1              0        || 50   1        'S2'         'Main'
        """,
    )


def test_time_limits_are_not_checked_without_sfcenablelimit():
    run_table(
        chart_with(FLAGS),
        """
        scan go SFCEnableLimit || S1.T SFCError SFCErrorStep
        0    1  0              || 0    0        ''
        1    0  0              || 0    0        ''
        2    0  0              || 10   0        ''
        3    0  0              || 20   0        ''
        4    0  0              || 30   0        ''
        5    0  0              || 40   0        ''   # over its time, but limits are off
        6    0  1              || 50   1        'S1'
        """,
    )


def test_sfcquiterror_pauses_clears_the_error_and_restarts_the_step_times_when_it_falls():
    run_table(
        chart_with(FLAGS + " SFCQuitError : BOOL;"),
        """
        scan go SFCEnableLimit SFCQuitError || S1.X S1.T SFCError SFCErrorStep n1
        0    1  1              0            || 1    0    0        ''           0
        1    0  1              0            || 1    0    0        ''           1
        2    0  1              0            || 1    10   0        ''           2
        3    0  1              0            || 1    20   0        ''           3
        4    0  1              0            || 1    30   0        ''           4
        5    0  1              0            || 1    40   1        'S1'         5
        6    0  1              1            || 1    40   0        ''           5    # paused, error cleared
        7    0  1              1            || 1    40   0        ''           5
        8    0  1              0            || 1    0    0        ''           6    # the time restarts
        9    0  1              0            || 1    10   0        ''           7
        """,
    )


def test_sfctrans_is_true_in_the_scans_a_transition_fires():
    run_table(
        chart_with("SFCTrans : BOOL;"),
        """
        scan go back || SFCTrans S0.X S1.X
        0    0  0    || 0        1    0
        1    1  0    || 1        0    1
        2    0  0    || 0        0    1
        3    0  1    || 1        0    0
        4    0  0    || 0        0    0
        """,
    )


def test_sfccurrentstep_names_the_right_most_of_parallel_steps():
    decls = "VAR go, a : BOOL; SFCCurrentStep : STRING; END_VAR"
    chart = [step("S0"), tr("go"), par([step("L1"), tr("a"), step("L2")], [step("R1")]), tr("FALSE"), jump("S0")]
    run_table(
        project(sfc_pou("Main", decls, chart)),
        """
        scan go a || SFCCurrentStep
        0    0  0 || 'S0'
        1    1  0 || 'R1'
        2    0  1 || 'R1'
        """,
    )


def test_with_sfctipmode_a_transition_fires_only_while_sfctip_is_true():
    run_table(
        chart_with("SFCTip, SFCTipMode : BOOL;"),
        """
        scan go back SFCTipMode SFCTip || S0.X S1.X S2.X
        0    1  0    1          0      || 1    0    0
        1    1  0    1          0      || 1    0    0
        2    1  0    1          1      || 0    1    0
        3    0  1    1          0      || 0    1    0
        4    0  1    1          1      || 0    0    1
        5    1  0    0          0      || 1    0    0
        """,
    )


def test_a_flag_of_the_wrong_type_is_a_located_error():
    from ladderlab.ir.lower_project import lower_project

    result = lower_project(chart_with("SFCError : INT;"))
    found = [d for d in result.diagnostics if d.code == "SFC-FLAG" and d.severity == "error"]
    assert len(found) == 1 and found[0].file == "Main/declarations" and "must be a BOOL, not INT" in found[0].message
