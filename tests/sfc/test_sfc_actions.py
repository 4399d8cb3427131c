"""SFC-02, issue 24 item 1: actions written in SFC (a chart as the body of an action), scan by scan.

IEC 61131-3 (ed. 2 2.6.4.1, ed. 3 6.7.4) lets an action be a sequential function chart. LadderLab runs it as the
action's body with the rules of SFC-04 applied to the inner chart: while the action is active (Q) the inner chart
runs one scan per scan of the POU (its actions, then its transitions; a step activated by a transition acts from
the next scan; a deactivated action runs once more). In the action's final run (Q FALSE, A TRUE) the inner chart
closes: its active steps are left, their actions get their final runs, no transition fires, and the initial step
is set again, so the next activation starts from it (docs/sfc.md states the decision).

Main:  M0 [N Seq] -(go)-> M1 -(back)-> M0
Seq:   I0 [N IncA] -(next)-> I1 [N IncB] -(FALSE)-> I0        IncA: a := a + 1;   IncB: b := b + 1;
"""

from __future__ import annotations

from ladderlab.ir.lower_project import lower_project

from .support import build, jump, project, run_table, sfc_pou, step, tr

DECLS = "VAR go, next, back : BOOL; a, b : INT; END_VAR"


def seq_action(elements: list) -> dict:
    return {"name": "Seq", "language": "sfc", "body": {"elements": elements}}


def chart(inner: list | None = None, main: list | None = None, actions: dict | None = None):
    inner = inner or [step("I0", "N IncA"), tr("next"), step("I1", "N IncB"), tr("FALSE"), jump("I0")]
    main = main or [step("M0", "N Seq"), tr("go"), step("M1"), tr("back"), jump("M0")]
    return project(
        sfc_pou(
            "Main",
            DECLS,
            main,
            actions or {"IncA": "a := a + 1;", "IncB": "b := b + 1;"},
            extra_actions=[seq_action(inner)],
        )
    )


def test_an_sfc_action_runs_its_chart_while_active_and_closes_it_in_its_final_run():
    run_table(
        chart(),
        """
        scan go next back || Seq.Q Seq.A I0.X I1.X a b M0.X M1.X
        0    0  0    0    || 1     1     1    0    1 0 1    0      # M0 and I0 initial: IncA runs
        1    0  1    0    || 1     1     0    1    2 0 1    0      # IncA runs, then I0 -> I1
        2    0  0    0    || 1     1     0    1    3 1 1    0      # IncA's final run; IncB from this scan
        3    1  0    0    || 1     1     0    1    3 2 0    1      # Seq still runs, then M0 -> M1
        4    0  0    0    || 0     1     1    0    3 3 0    1      # Seq's final run: I1 left (IncB's final run), I0 set
        5    0  0    0    || 0     0     1    0    3 3 0    1      # Seq inactive: its chart stands still
        6    0  0    1    || 0     0     1    0    3 3 1    0      # M1 -> M0
        7    0  0    0    || 1     1     1    0    4 3 1    0      # Seq again, from I0
        """,
    )


def test_the_inner_chart_takes_steps_only_while_its_action_runs():
    """``next`` TRUE while Seq is inactive moves nothing; I0's transition fires in Seq's first active scan."""
    run_table(
        chart(main=[step("M0"), tr("go"), step("M1", "N Seq"), tr("back"), jump("M0")]),
        """
        scan go next back || Seq.Q I0.X I1.X a b
        0    0  1    0    || 0     1    0    0 0     # Seq inactive: I0 stays, IncA does not run
        1    1  1    0    || 0     1    0    0 0     # M0 -> M1
        2    0  1    0    || 1     0    1    1 0     # Seq active: IncA runs, then I0 -> I1
        3    0  0    0    || 1     0    1    2 1     # IncA's final run, IncB
        """,
    )


def errors(proj) -> list[tuple[str, str | None, str]]:
    result = lower_project(proj)
    return [(d.code, d.file, d.message) for d in result.diagnostics if d.severity == "error"]


def test_an_sfc_action_as_an_entry_action_is_refused():
    main = [step("M0", entry="Seq"), tr("go"), jump("M0")]
    assert errors(chart(main=main)) == [
        (
            "SFC-ACTION",
            "Main/chart",
            "the entry action of step M0 is Seq, which is written in SFC: a chart runs while its action is active, "
            "so associate it (N) instead",
        )
    ]


def test_an_action_used_in_two_charts_is_refused():
    main = [step("M0", "N Seq", "N IncB"), tr("go"), jump("M0")]
    assert errors(chart(main=main)) == [
        (
            "SFC-ACTION",
            "Main/actions/Seq",
            "the action IncB is used in the POU's chart and in the chart of action Seq: an action belongs to one chart",
        )
    ]


def test_an_sfc_action_inside_its_own_chart_is_refused():
    inner = [step("I0", "N Seq"), tr("next"), jump("I0")]
    assert errors(chart(inner=inner, main=[step("M0"), tr("go"), jump("M0")])) == [
        ("SFC-ACTION", "Main/actions/Seq", "the action Seq is written in SFC and is used inside its own chart")
    ]


def test_an_element_id_of_an_action_chart_must_differ_from_the_pou_chart():
    inner = [step("I0", "N IncA"), tr("next"), jump("I0")]
    inner[0]["id"] = "m0"
    main = [step("M0", "N Seq"), tr("go"), jump("M0")]
    main[0]["id"] = "m0"
    assert errors(chart(inner=inner, main=main)) == [
        ("SFC-DUPLICATE", "Main/actions/Seq", "the id 'm0' is used in another chart of the POU")
    ]


def test_a_breakpoint_on_a_step_of_an_action_chart_halts_while_the_action_runs_it():
    """ON-17 inside an SFC action: the step's breakpoint halts in the scan its action runs the chart, before the
    inner step's actions (I1 active from scan 2: IncB has not run, b = 0)."""
    proj = chart()
    i1 = proj.pous[0].body.action("Seq").body.elements[2].id
    sim = build(proj, "debug")
    sim.set_breakpoint("Main", element=i1)
    assert sim.cycle(1) == 1 and sim.halted is None
    sim.write("Main.next", True)
    assert sim.cycle(1) == 1 and sim.halted is None  # I0 -> I1 at the end of this scan
    sim.write("Main.next", False)
    assert sim.cycle(1) == 0
    assert sim.halted.point.element == i1 and sim.halted.origin.body is None
    assert (sim.read("Main.I1.X"), sim.read("Main.b")) == (True, 0)
