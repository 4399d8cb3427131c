"""SFC-08: alternative and simultaneous branches, jumps, transition priorities, scan by scan.

Alternative branches are evaluated left to right and the first TRUE transition wins (SFC-08); an explicit priority
(lower first, IEC 61131-3 textual ``PRIORITY``) comes before drawing order. A simultaneous divergence activates the
first step of every branch at once; the step after the join becomes active only when the last step of every
branch is active and the transition is TRUE (SFC-08).
"""

from __future__ import annotations

from .support import alt, jump, par, project, run_table, sfc_pou, step, tr

DECLS = "VAR c1, c2, c3, a, b, done, join : BOOL; END_VAR"


def alternative(p1=None, p2=None, p3=None):
    chart = [
        step("S0"),
        alt(
            [tr("c1", p1), step("S1"), tr("done")],
            [tr("c2", p2), step("S2"), tr("done")],
            [tr("c3", p3), step("S3"), tr("done")],
        ),
        step("S4"),
        tr("join"),
        jump("S0"),
    ]
    return project(sfc_pou("Main", DECLS, chart))


def test_the_left_most_true_transition_of_an_alternative_wins():
    run_table(
        alternative(),
        """
        scan c1 c2 c3 done join || S0.X S1.X S2.X S3.X S4.X
        0    0  1  1  0    0    || 0    0    1    0    0     # c2 and c3: the left one
        1    0  0  0  1    0    || 0    0    0    0    1     # the branches join at S4
        2    0  0  0  0    1    || 1    0    0    0    0
        3    1  1  1  0    0    || 0    1    0    0    0     # all three: the left-most
        4    0  0  0  0    0    || 0    1    0    0    0
        5    0  0  0  1    0    || 0    0    0    0    1
        """,
    )


def test_an_explicit_priority_comes_before_drawing_order():
    """PRIORITY 1 on the right-most branch and 2 on the middle one: c3 wins over c2, c2 over c1 (no priority)."""
    run_table(
        alternative(p2=2, p3=1),
        """
        scan c1 c2 c3 done join || S1.X S2.X S3.X
        0    1  1  1  0    0    || 0    0    1
        1    0  0  0  1    0    || 0    0    0
        2    0  0  0  0    1    || 0    0    0
        3    1  1  0  0    0    || 0    1    0
        """,
    )


def test_a_simultaneous_divergence_starts_every_branch_and_joins_when_all_have_ended():
    chart = [
        step("S0"),
        tr("c1"),
        par([step("A1"), tr("a"), step("A2")], [step("B1"), tr("b"), step("B2")]),
        tr("join"),
        step("S4"),
        tr("done"),
        jump("S0"),
    ]
    run_table(
        project(sfc_pou("Main", DECLS, chart)),
        """
        scan c1 a b join done || S0.X A1.X A2.X B1.X B2.X S4.X
        0    1  0 0 0    0    || 0    1    0    1    0    0      # both branches start
        1    0  0 0 1    0    || 0    1    0    1    0    0      # join TRUE, but no branch has ended
        2    0  1 0 1    0    || 0    0    1    1    0    0      # A ends; B still runs
        3    0  0 0 1    0    || 0    0    1    1    0    0
        4    0  0 1 0    0    || 0    0    1    0    1    0      # both ended, join FALSE
        5    0  0 0 1    0    || 0    0    0    0    0    1      # join TRUE: S4
        6    0  0 0 0    1    || 1    0    0    0    0    0
        """,
    )


def test_alternatives_nest_in_simultaneous_branches_and_jumps_loop_within_a_branch():
    chart = [
        step("S0"),
        tr("c1"),
        par(
            [step("A1"), alt([tr("a"), step("A2"), tr("b"), jump("A1")], [tr("done")]), step("A3")],
            [step("B1")],
        ),
        tr("join"),
        jump("S0"),
    ]
    run_table(
        project(sfc_pou("Main", DECLS, chart)),
        """
        scan c1 a b done join || A1.X A2.X A3.X B1.X S0.X
        0    1  0 0 0    0    || 1    0    0    1    0
        1    0  1 0 0    0    || 0    1    0    1    0
        2    0  0 1 0    0    || 1    0    0    1    0      # the jump back to A1, within the branch
        3    0  0 0 1    1    || 0    0    1    1    0      # join waits: A3 was not active during the scan
        4    0  0 0 0    1    || 0    0    0    0    1
        """,
    )


def test_only_one_transition_takes_a_step_even_when_later_ones_are_also_true():
    """Two alternative transitions TRUE in the same scan never both fire (the step would be taken twice)."""
    chart = [
        step("S0"),
        alt([tr("c1"), step("S1"), tr("FALSE")], [tr("c1"), step("S2"), tr("FALSE")]),
        step("S3"),
        tr("FALSE"),
        jump("S0"),
    ]
    run_table(
        project(sfc_pou("Main", DECLS, chart)),
        """
        scan c1 || S0.X S1.X S2.X
        0    1  || 0    1    0
        1    0  || 0    1    0
        """,
    )
