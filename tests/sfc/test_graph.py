"""model/sfc_graph.py: a chart as its step/transition graph and a graph (PLCopen, textual SFC) back as a chart."""

from __future__ import annotations

import pytest
from hypothesis import given

from ladderlab.model.sfc import SfcChart
from ladderlab.model.sfc_graph import (
    ImportedStep,
    ImportedTransition,
    UnstructuredChart,
    chart_graph,
    graph_chart,
)

from .strategies import charts
from .support import alt, jump, par, step, tr


def edges(chart: SfcChart) -> list[tuple[tuple[str, ...], tuple[str, ...], str]]:
    graph = chart_graph(chart)
    assert not [p for p in graph.problems if p.severity == "error"], graph.problems
    return sorted(
        (tuple(sorted(t.sources)), tuple(sorted(t.targets)), t.transition.condition) for t in graph.transitions
    )


def imported(chart: SfcChart) -> tuple[list[ImportedStep], list[ImportedTransition]]:
    graph = chart_graph(chart)
    steps = [ImportedStep(s.step, s.initial) for s in graph.steps.values()]
    transitions = [ImportedTransition(t.transition, list(t.sources), list(t.targets)) for t in graph.transitions]
    return steps, transitions


def test_the_graph_of_a_chart_with_both_branch_kinds():
    chart = SfcChart.model_validate(
        {
            "elements": [
                step("S0"),
                alt(
                    [tr("a"), step("S1"), tr("b")],
                    [tr("c"), par([step("P1")], [step("P2"), tr("d"), step("P3")]), tr("e")],
                ),
                step("S4"),
                tr("f"),
                jump("S0"),
            ]
        }
    )
    assert edges(chart) == [
        (("P1", "P3"), ("S4",), "e"),
        (("P2",), ("P3",), "d"),
        (("S0",), ("P1", "P2"), "c"),
        (("S0",), ("S1",), "a"),
        (("S1",), ("S4",), "b"),
        (("S4",), ("S0",), "f"),
    ]
    graph = chart_graph(chart)
    assert graph.initial is not None and graph.initial.step.name == "S0"
    assert [t.transition.condition for t in graph.transitions] == ["a", "b", "c", "d", "e", "f"]


def test_priorities_come_before_drawing_order():
    chart = SfcChart.model_validate(
        {"elements": [step("S0"), alt([tr("a"), jump("S0")], [tr("b", 2), jump("S0")], [tr("c", 1), jump("S0")])]}
    )
    assert [t.transition.condition for t in chart_graph(chart).evaluation_order()] == ["c", "b", "a"]


@given(charts())
def test_a_chart_rebuilt_from_its_graph_has_the_same_graph(elements):
    """Whatever the chart, rebuilding it from its graph gives a chart of the same steps and transitions, and the
    transitions leaving one step keep their left-to-right order (their priority)."""
    chart = SfcChart.model_validate({"elements": elements})
    steps, transitions = imported(chart)
    rebuilt, unreachable = graph_chart(steps, transitions)
    assert unreachable == []
    assert edges(rebuilt) == edges(chart)
    before, after = chart_graph(chart), chart_graph(rebuilt)
    assert [s for s in before.steps] == sorted(before.steps, key=list(before.steps).index)
    assert set(before.steps) == set(after.steps)
    for source in before.steps:
        order = [t.transition.condition for t in before.evaluation_order() if source in t.sources]
        assert order == [t.transition.condition for t in after.evaluation_order() if source in t.sources]


def test_the_rebuilt_chart_of_first_steps_joins_both_branches_and_jumps_back():
    """Beremiz first_steps' CounterSFC as a graph: Start -> (NOT Reset) Count | (Reset) ResetCounter -> Start."""
    start, count, reset = (step(n) for n in ("Start", "Count", "ResetCounter"))
    models = SfcChart.model_validate({"elements": [start, tr("x"), count, tr("x"), reset, tr("x"), jump("Start")]})
    by_name = {s.name: s for s in models.elements if s.type == "step"}  # type: ignore[union-attr]
    t = {
        c: SfcChart.model_validate({"elements": [step("Q"), tr(c), jump("Q")]}).elements[1]
        for c in ("NOT Reset", "Reset", "Reset ", "NOT Reset ")
    }
    graph_steps = [
        ImportedStep(by_name["Start"], True),
        ImportedStep(by_name["ResetCounter"]),
        ImportedStep(by_name["Count"]),
    ]
    graph_transitions = [
        ImportedTransition(t["NOT Reset"], ["Start"], ["Count"]),
        ImportedTransition(t["Reset"], ["Start"], ["ResetCounter"]),
        ImportedTransition(t["Reset "], ["Count"], ["Start"]),
        ImportedTransition(t["NOT Reset "], ["ResetCounter"], ["Start"]),
    ]
    chart, unreachable = graph_chart(graph_steps, graph_transitions)
    assert unreachable == []
    shape = [e.type for e in chart.elements]
    assert shape == ["step", "alternative"]
    branches = chart.elements[1].branches  # type: ignore[union-attr]
    assert [[e.type for e in b] for b in branches] == [["transition", "step", "transition", "jump"]] * 2


def test_a_graph_no_chart_can_draw_is_refused_with_the_reason():
    s = {n: SfcChart.model_validate({"elements": [step(n)]}).elements[0] for n in ("A", "B", "C")}
    cond = SfcChart.model_validate({"elements": [step("Q"), tr("x"), jump("Q")]}).elements[1]
    with pytest.raises(UnstructuredChart, match="several initial steps"):
        graph_chart([ImportedStep(s["A"], True), ImportedStep(s["B"], True)], [])
    d = SfcChart.model_validate({"elements": [step("D")]}).elements[0]
    join = SfcChart.model_validate({"elements": [step("Q"), tr("y"), jump("Q")]}).elements[1]
    with pytest.raises(UnstructuredChart, match="do not join at one transition"):  # B and C join, D never does
        graph_chart(
            [ImportedStep(s["A"], True), ImportedStep(s["B"]), ImportedStep(s["C"]), ImportedStep(d)],
            [ImportedTransition(cond, ["A"], ["B", "C", "D"]), ImportedTransition(join, ["B", "C"], ["A"])],
        )


def test_steps_nothing_reaches_are_named():
    s = {n: SfcChart.model_validate({"elements": [step(n)]}).elements[0] for n in ("A", "B", "Lost")}
    cond = SfcChart.model_validate({"elements": [step("Q"), tr("x"), jump("Q")]}).elements[1]
    chart, unreachable = graph_chart(
        [ImportedStep(s["A"], True), ImportedStep(s["B"]), ImportedStep(s["Lost"])],
        [ImportedTransition(cond, ["A"], ["B"])],
    )
    assert unreachable == ["Lost"]
    assert [e.type for e in chart.elements] == ["step", "transition", "step"]


def test_a_forward_jump_round_trips():
    """S0 -(a)-> S1 | -(b)-> jump S3; S1 -> S2 -> S3: the jump goes to a step drawn after it."""
    chart = SfcChart.model_validate(
        {
            "elements": [
                step("S0"),
                alt([tr("a"), step("S1"), tr("c")], [tr("b"), jump("S3")]),
                step("S2"),
                tr("d"),
                step("S3"),
                tr("e"),
                jump("S0"),
            ]
        }
    )
    rebuilt, unreachable = graph_chart(*imported(chart))
    assert unreachable == [] and edges(rebuilt) == edges(chart)


def loop_back_into_a_branch() -> list[dict]:
    """An alternative after S1 meeting at the simultaneous divergence S25 | S33, whose join jumps back into the first
    branch (S4); S8, reached only from S4, belongs to that branch (minimised from a hypothesis failure)."""
    return [
        step("S1"),
        alt(
            [tr("c3"), step("S4"), alt([tr("c6")], [tr("c7"), step("S8"), tr("c10"), jump("S1")])],
            [tr("c22")],
        ),
        par([step("S25")], [step("S33")]),
        tr("c38"),
        jump("S4"),
    ]


def test_a_step_after_a_loop_back_into_a_branch_is_drawn_in_that_branch():
    """S8 is not placed after the meeting point (the chart after it never reaches S8 but through S4, which the first
    branch places). The rebuild once refused the graph: "a simultaneous divergence activates step S25, which is also
    reached another way"."""
    chart = SfcChart.model_validate({"elements": loop_back_into_a_branch()})
    assert chart_graph(chart).problems == []
    rebuilt, unreachable = graph_chart(*imported(chart))
    assert unreachable == [] and edges(rebuilt) == edges(chart)
    assert chart_graph(rebuilt).problems == []


def test_an_alternative_whose_other_branch_loops_through_its_own_simultaneous_divergence_meets_after_it():
    """In the first branch of P4, S5's alternative either goes on to S17 or opens S10 | S12, whose join jumps back
    to S5: that join is no way out of the branch, so the alternative meets at S17, which ends the simultaneous branch
    (the rebuild once drew S17 inside the alternative, leaving P4's branch without a last step)."""
    loop = [tr("c8"), par([step("S10")], [step("S12")]), tr("c14"), jump("S5")]
    start = [step("S1"), tr("c3"), par([step("S5"), alt([tr("c7")], loop), step("S17")], [step("S19")])]
    for ending in ([], [tr("c21"), step("S22")]):  # the chart ends in the branches, or they join
        chart = SfcChart.model_validate({"elements": [*start, *ending]})
        assert chart_graph(chart).problems == []
        rebuilt, unreachable = graph_chart(*imported(chart))
        assert unreachable == [] and edges(rebuilt) == edges(chart)
        assert chart_graph(rebuilt).problems == []


def test_an_alternative_no_branch_of_which_reaches_the_tried_meeting_point_tries_the_next():
    """S1's branches could meet at S17 (both reach it, and a jump goes to it) or at S45; at S17 no branch comes
    together (the first jumps to it from inside, the second to S45), so S17 was kept for after the alternative but
    never drawn (the rebuild once named it unreachable): they meet at S45."""
    chart = SfcChart.model_validate(
        {
            "elements": [
                step("S1"),
                alt(
                    [
                        tr("c3"),
                        step("S5"),
                        alt([tr("c12"), step("S13"), tr("c15")], [tr("c16"), step("S17"), tr("c19")], [tr("c24")]),
                    ],
                    [tr("c32")],
                ),
                step("S45"),
                alt([tr("c53")], [tr("c59"), jump("S17")]),
                step("S63"),
            ]
        }
    )
    assert chart_graph(chart).problems == []
    rebuilt, unreachable = graph_chart(*imported(chart))
    assert unreachable == [] and edges(rebuilt) == edges(chart)
    assert chart_graph(rebuilt).problems == []


def test_a_simultaneous_branch_is_rebuilt_to_end_with_a_step():
    """S5's alternative in the first branch of P4 could meet at S12 (both branches reach it) and go on with S12's
    loop back to S5, but then the simultaneous branch would end with that jump (the rebuild once drew it so,
    SFC-UNSAFE): it meets at S8 and the branch ends with S28, as drawn."""
    loop = alt([tr("c10")], [tr("c11"), step("S12"), tr("c14"), jump("S5")])
    first = [step("S5"), alt([tr("c7"), step("S8"), loop], [tr("c25"), jump("S12")]), step("S28")]
    chart = SfcChart.model_validate({"elements": [step("S1"), tr("c3"), par(first, [step("S30")])]})
    assert chart_graph(chart).problems == []
    rebuilt, unreachable = graph_chart(*imported(chart))
    assert unreachable == [] and edges(rebuilt) == edges(chart)
    assert chart_graph(rebuilt).problems == []
