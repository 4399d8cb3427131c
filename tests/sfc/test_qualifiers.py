"""SFC-05: every action qualifier, scan by scan (10 ms scans: scan k runs at t = (k + 1) * 10 ms).

Expected tables come from IEC 61131-3's action control (ed. 2, figure 15: ``Q := NOT R AND (N OR (L AND NOT
L_TMR.Q) OR D_TMR.Q OR P_TRIG.Q OR S_FF.Q OR SD_TMR.Q OR DS_FF.Q OR (SL_FF.Q AND NOT SL_TMR.Q))``, ``A := Q OR
falling edge of Q OR P1 pulse OR P0 pulse``, the timers being TONs called once per scan) and the seed's scan order
(SFC-04: a step activated by a transition acts from the next scan; a deactivated action runs one final time, so
every action runs at least twice, P included). The action ``A`` counts its runs in ``n`` and its runs with Q TRUE in
``nq``; the tables show A.Q and A.A after each scan.
"""

from __future__ import annotations

from .support import jump, project, run_table, sfc_pou, step, tr

DECLS = "VAR go, back : BOOL; n, nq : INT; Lamp : BOOL; END_VAR"
BODY = {"A": "n := n + 1;\nIF A.Q THEN nq := nq + 1; END_IF;"}


def two_steps(association: str):
    """S0 -(go)-> S1 [association] -(back)-> S0."""
    chart = [step("S0"), tr("go"), step("S1", association), tr("back"), jump("S0")]
    return project(sfc_pou("Main", DECLS, chart, BODY))


def four_steps(association: str):
    """S0 -(go)-> S1 [association] -(back)-> S2 -(go)-> S3 [R A] -(back)-> S0: stored actions outlive S1 until S3."""
    chart = [
        step("S0"),
        tr("go"),
        step("S1", association),
        tr("back"),
        step("S2"),
        tr("go"),
        step("S3", "R A"),
        tr("back"),
        jump("S0"),
    ]
    return project(sfc_pou("Main", DECLS, chart, BODY))


def test_n_runs_while_the_step_is_active_then_once_more_with_q_false():
    """N: active while S1 is (scans 2-5), then the final run with Q FALSE in scan 6 (SFC-04)."""
    run_table(
        two_steps("N A"),
        """
        scan go back || S0.X S1.X A.Q A.A n nq
        0    0  0    || 1    0    0   0   0 0
        1    1  0    || 0    1    0   0   0 0   # S1 is activated at the end of scan 1
        2    0  0    || 0    1    1   1   1 1   # and acts from scan 2
        3    0  0    || 0    1    1   1   2 2
        4    0  0    || 0    1    1   1   3 3
        5    0  1    || 1    0    1   1   4 4   # S1 acts in scan 5, then is left
        6    0  0    || 1    0    0   1   5 4   # the final run: Q FALSE, A TRUE
        7    0  0    || 1    0    0   0   5 4
        """,
    )


def test_a_bool_variable_associated_with_a_step_follows_q():
    """SFC-04: a BOOL variable associated with a step is TRUE on each activation; IEC: its value is Q."""
    run_table(
        two_steps("N Lamp"),
        """
        scan go back || S1.X Lamp
        0    0  0    || 0    0
        1    1  0    || 1    0
        2    0  0    || 1    1
        3    0  1    || 0    1
        4    0  0    || 0    0
        5    1  0    || 1    0
        6    0  0    || 1    1
        """,
    )


def test_d_becomes_active_after_its_time_while_the_step_stays_active():
    """D T#30ms: D_TMR starts in S1's first scan (2, ET 0) and reaches 30 ms in scan 5."""
    run_table(
        two_steps("D A T#30ms"),
        """
        scan go back || S1.X A.Q A.A n nq
        0    0  0    || 0    0   0   0 0
        1    1  0    || 1    0   0   0 0
        2    0  0    || 1    0   0   0 0   # ET 0
        3    0  0    || 1    0   0   0 0   # ET 10
        4    0  0    || 1    0   0   0 0   # ET 20
        5    0  0    || 1    1   1   1 1   # ET 30: Q
        6    0  0    || 1    1   1   2 2
        7    0  1    || 0    1   1   3 3
        8    0  0    || 0    0   1   4 3   # final run
        9    0  0    || 0    0   0   4 3
        """,
    )


def test_d_never_runs_when_the_step_is_left_before_its_time():
    run_table(
        two_steps("D A T#30ms"),
        """
        scan go back || S1.X A.Q A.A n
        0    0  0    || 0    0   0   0
        1    1  0    || 1    0   0   0
        2    0  0    || 1    0   0   0
        3    0  1    || 0    0   0   0
        4    0  0    || 0    0   0   0
        5    0  0    || 0    0   0   0
        6    0  0    || 0    0   0   0
        """,
    )


def test_l_is_active_for_its_time_at_most_then_runs_once_more():
    """L T#30ms: Q while L_TMR.ET < 30 ms (scans 2-4), the final run in scan 5; S1 stays active until scan 7."""
    run_table(
        two_steps("L A T#30ms"),
        """
        scan go back || S1.X A.Q A.A n nq
        0    0  0    || 0    0   0   0 0
        1    1  0    || 1    0   0   0 0
        2    0  0    || 1    1   1   1 1
        3    0  0    || 1    1   1   2 2
        4    0  0    || 1    1   1   3 3
        5    0  0    || 1    0   1   4 3   # ET 30: Q falls, final run
        6    0  0    || 1    0   0   4 3
        7    0  1    || 0    0   0   4 3
        8    0  0    || 0    0   0   4 3
        """,
    )


def test_l_ends_with_the_step():
    run_table(
        two_steps("L A T#50ms"),
        """
        scan go back || S1.X A.Q A.A n
        0    0  0    || 0    0   0   0
        1    1  0    || 1    0   0   0
        2    0  0    || 1    1   1   1
        3    0  1    || 0    1   1   2
        4    0  0    || 0    0   1   3
        5    0  0    || 0    0   0   3
        """,
    )


def test_p_runs_once_with_q_then_once_more_without():
    """P: P_TRIG pulses in S1's first scan (Q), then the final run (seed: "this holds for P too")."""
    run_table(
        two_steps("P A"),
        """
        scan go back || S1.X A.Q A.A n nq
        0    0  0    || 0    0   0   0 0
        1    1  0    || 1    0   0   0 0
        2    0  0    || 1    1   1   1 1
        3    0  0    || 1    0   1   2 1
        4    0  0    || 1    0   0   2 1
        5    0  1    || 0    0   0   2 1
        6    0  0    || 0    0   0   2 1
        7    1  0    || 1    0   0   2 1
        8    0  0    || 1    1   1   3 2   # activated again: pulses again
        """,
    )


def test_p1_runs_once_on_activation_with_q_false():
    """P1 (IEC ed. 2 2003): one run when the step is activated, Q FALSE (NOTE 2), no final run (NOTE 3)."""
    run_table(
        two_steps("P1 A"),
        """
        scan go back || S1.X A.Q A.A n nq
        0    0  0    || 0    0   0   0 0
        1    1  0    || 1    0   0   0 0
        2    0  0    || 1    0   1   1 0
        3    0  0    || 1    0   0   1 0
        4    0  1    || 0    0   0   1 0
        5    0  0    || 0    0   0   1 0
        """,
    )


def test_p0_runs_once_when_the_step_is_left():
    """P0: one run (Q FALSE) in the scan after S1 is left: its falling edge."""
    run_table(
        two_steps("P0 A"),
        """
        scan go back || S1.X A.Q A.A n nq
        0    0  0    || 0    0   0   0 0
        1    1  0    || 1    0   0   0 0
        2    0  0    || 1    0   0   0 0
        3    0  1    || 0    0   0   0 0
        4    0  0    || 0    0   1   1 0
        5    0  0    || 0    0   0   1 0
        """,
    )


def test_s_stays_active_after_the_step_until_r_resets_it():
    """S / R: set in S1 (scan 2), active through S2 (no association), reset by R in S3 (scan 6) with a final run."""
    run_table(
        four_steps("S A"),
        """
        scan go back || S1.X S2.X S3.X A.Q A.A n nq
        0    0  0    || 0    0    0    0   0   0 0
        1    1  0    || 1    0    0    0   0   0 0
        2    0  0    || 1    0    0    1   1   1 1
        3    0  1    || 0    1    0    1   1   2 2
        4    0  0    || 0    1    0    1   1   3 3   # stored: S1 is no longer active
        5    1  0    || 0    0    1    1   1   4 4
        6    0  0    || 0    0    1    0   1   5 4   # R in S3: reset, final run
        7    0  0    || 0    0    1    0   0   5 4
        """,
    )


def test_r_overrides_n_in_the_same_step():
    """R is the overriding reset: with N and R on one action in S1 the action never becomes active."""
    chart = [step("S0"), tr("go"), step("S1", "N A", "R A"), tr("back"), jump("S0")]
    run_table(
        project(sfc_pou("Main", DECLS, chart, BODY)),
        """
        scan go back || S1.X A.Q A.A n
        0    0  0    || 0    0   0   0
        1    1  0    || 1    0   0   0
        2    0  0    || 1    0   0   0
        3    0  1    || 0    0   0   0
        4    0  0    || 0    0   0   0
        """,
    )


def test_sd_starts_its_time_at_once_and_stays_until_reset():
    """SD T#30ms: SD_FF set in scan 2, SD_TMR reaches 30 ms in scan 5 although S1 was left after scan 3."""
    run_table(
        four_steps("SD A T#30ms"),
        """
        scan go back || S1.X S2.X S3.X A.Q A.A n nq
        0    0  0    || 0    0    0    0   0   0 0
        1    1  0    || 1    0    0    0   0   0 0
        2    0  0    || 1    0    0    0   0   0 0
        3    0  1    || 0    1    0    0   0   0 0
        4    0  0    || 0    1    0    0   0   0 0
        5    0  0    || 0    1    0    1   1   1 1   # ET 30
        6    0  0    || 0    1    0    1   1   2 2
        7    1  0    || 0    0    1    1   1   3 3
        8    0  0    || 0    0    1    0   1   4 3   # R in S3
        9    0  0    || 0    0    1    0   0   4 3
        """,
    )


def test_ds_needs_the_step_active_for_its_time_then_stays_until_reset():
    """DS T#30ms: S1 active in scans 2-5, DS_TMR reaches 30 ms in scan 5, stored through S2 until R in S3."""
    run_table(
        four_steps("DS A T#30ms"),
        """
        scan go back || S1.X S2.X S3.X A.Q A.A n
        0    0  0    || 0    0    0    0   0   0
        1    1  0    || 1    0    0    0   0   0
        2    0  0    || 1    0    0    0   0   0
        3    0  0    || 1    0    0    0   0   0
        4    0  0    || 1    0    0    0   0   0
        5    0  1    || 0    1    0    1   1   1
        6    0  0    || 0    1    0    1   1   2
        7    1  0    || 0    0    1    1   1   3
        8    0  0    || 0    0    1    0   1   4
        9    0  0    || 0    0    1    0   0   4
        """,
    )


def test_ds_does_nothing_when_the_step_ends_before_its_time():
    run_table(
        four_steps("DS A T#30ms"),
        """
        scan go back || S1.X S2.X A.Q A.A n
        0    0  0    || 0    0    0   0   0
        1    1  0    || 1    0    0   0   0
        2    0  0    || 1    0    0   0   0
        3    0  1    || 0    1    0   0   0
        4    0  0    || 0    1    0   0   0
        5    0  0    || 0    1    0   0   0
        6    0  0    || 0    1    0   0   0
        """,
    )


def test_sl_is_active_for_its_time_even_after_the_step():
    """SL T#30ms (the standard's meaning, spec section 8): set in scan 2, active until SL_TMR reaches 30 ms in scan 5,
    although S1 was left after scan 3; then the final run."""
    run_table(
        four_steps("SL A T#30ms"),
        """
        scan go back || S1.X S2.X A.Q A.A n nq
        0    0  0    || 0    0    0   0   0 0
        1    1  0    || 1    0    0   0   0 0
        2    0  0    || 1    0    1   1   1 1
        3    0  1    || 0    1    1   1   2 2
        4    0  0    || 0    1    1   1   3 3
        5    0  0    || 0    1    0   1   4 3
        6    0  0    || 0    1    0   0   4 3
        """,
    )


def test_the_time_of_an_association_may_be_a_time_variable():
    """L with a TIME variable: the time is read while the step is active."""
    decls = "VAR go, back : BOOL; n, nq : INT; limit : TIME := T#20ms; END_VAR"
    chart = [step("S0"), tr("go"), step("S1", "L A limit"), tr("back"), jump("S0")]
    run_table(
        project(sfc_pou("Main", decls, chart, BODY)),
        """
        scan go back || A.Q A.A n
        0    0  0    || 0   0   0
        1    1  0    || 0   0   0
        2    0  0    || 1   1   1
        3    0  0    || 1   1   2
        4    0  0    || 0   1   3
        5    0  0    || 0   0   3
        """,
    )
