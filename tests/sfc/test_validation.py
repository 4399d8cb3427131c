"""SFC charts that cannot run: located errors (POU, file, element) in the user's words, never a crash."""

from __future__ import annotations

import pytest

from ladderlab.ir.lower_project import lower_project
from ladderlab.model import Pou

from .support import alt, assoc, jump, ld_network, par, project, sfc_pou, step, tr

DECLS = "VAR go, x, Lamp : BOOL; n : INT; t1 : TON; END_VAR"


def problems(*pous: Pou, severity: str = "error") -> list[tuple[str, str | None, str | None, str]]:
    result = lower_project(project(*pous))
    return [(d.code, d.file, d.element, d.message) for d in result.diagnostics if d.severity == severity]


def one(chart: list, actions: dict | None = None, **kw) -> list:
    return problems(sfc_pou("Main", DECLS, chart, actions, **kw))


def codes(found: list) -> set[tuple[str, str | None]]:
    return {(code, element) for code, _, element, _ in found}


def test_an_empty_chart_has_no_initial_step():
    found = one([])
    assert [(c, m) for c, _, _, m in found] == [("SFC-EMPTY", "the chart has no step: add the initial step")]


def test_a_step_after_a_step_and_a_transition_after_a_transition():
    s1, s2, t1, t2 = step("S1"), step("S2"), tr("go"), tr("x")
    found = one([s1, s2, t1, t2, jump("S1")])
    assert ("SFC-ORDER", s2["id"]) in codes(found)
    assert ("SFC-ORDER", t2["id"]) in codes(found)
    assert all(file == "Main/chart" for _, file, _, _ in found)


def test_a_transition_that_leads_nowhere():
    t = tr("go")
    found = one([step("S0"), t])
    assert codes(found) == {("SFC-DANGLING", t["id"])}
    assert "add a step or a jump after it" in found[0][3]


def test_elements_after_a_jump_are_unreachable():
    after = step("S9")
    found = one([step("S0"), tr("go"), jump("S0"), after, tr("x"), jump("S0")])
    assert ("SFC-UNREACHABLE", after["id"]) in codes(found)
    assert "nothing reaches this step (S9): it follows a jump" in [m for c, _, e, m in found if e == after["id"]]


def test_elements_after_an_alternative_whose_branches_all_jump_are_unreachable():
    after = step("S3")
    chart = [step("S0"), alt([tr("go"), jump("S0")], [tr("x"), jump("S0")]), after, tr("go"), jump("S0")]
    assert ("SFC-UNREACHABLE", after["id"]) in codes(one(chart))


def test_a_simultaneous_branch_that_ends_in_a_jump_is_unsafe():
    j = jump("S0")
    chart = [step("S0"), tr("go"), par([step("A"), tr("x"), j], [step("B")]), tr("go"), jump("S0")]
    found = one(chart)
    assert ("SFC-UNSAFE", j["id"]) in codes(found)


def test_a_jump_into_a_simultaneous_branch_is_unsafe():
    j = jump("A2")
    chart = [
        step("S0"),
        tr("go"),
        par([step("A1"), tr("x"), step("A2")], [step("B")]),
        tr("go"),
        step("S3"),
        tr("x"),
        j,
    ]
    found = one(chart)
    assert ("SFC-UNSAFE", j["id"]) in codes(found)
    assert "only jumps within the same branch are safe" in next(m for c, _, e, m in found if e == j["id"])


def test_a_jump_to_no_step():
    j = jump("Nowhere")
    found = one([step("S0"), tr("go"), j])
    assert codes(found) == {("SFC-JUMP", j["id"])}
    assert "'Nowhere', which is no step (steps: S0)" in found[0][3]


def test_two_steps_with_one_name_and_two_elements_with_one_id():
    twin = step("S0")
    first = step("S1")
    copy = step("S2")
    copy["id"] = first["id"]
    found = one([step("S0"), tr("go"), twin, tr("x"), first, tr("x"), copy, tr("x"), jump("S0")])
    assert ("SFC-DUPLICATE", twin["id"]) in codes(found)
    assert ("SFC-DUPLICATE", first["id"]) in codes(found)


def test_names_of_steps_actions_and_variables_must_differ():
    found = one([step("Lamp"), tr("go"), jump("Lamp")], {"n": "x := TRUE;"})
    messages = {(c, f): m for c, f, _, m in found}
    assert messages[("SFC-DUPLICATE", "Main/chart")] == (
        "step Lamp has the name of the variable Lamp: names of steps, actions, transitions and variables must differ"
    )
    assert ("SFC-DUPLICATE", "Main/actions/n") in messages


@pytest.mark.parametrize("qualifier", ["L", "D", "SD", "DS", "SL"])
def test_a_time_qualifier_without_a_time(qualifier):
    s = step("S0", f"{qualifier} A")
    found = one([s, tr("go"), jump("S0")], {"A": "n := 1;"})
    assert [(c, e, m) for c, _, e, m in found] == [
        ("SFC-TIME", s["actions"][0]["id"], f"the qualifier {qualifier} needs a time (e.g. T#5s)")
    ]


def test_a_time_on_a_qualifier_that_takes_none_and_a_time_that_is_no_time():
    s = step("S0", "N A T#1s", "L A 5")
    found = one([s, tr("go"), jump("S0")], {"A": "n := 1;"})
    assert ("SFC-TIME", s["actions"][0]["id"]) in codes(found)
    assert any(e == s["actions"][1]["id"] and c == "ST-TYPE-MISMATCH" for c, _, e, _ in found)


def test_an_association_with_no_action_and_no_bool_variable():
    s = step("S0", "N Fill", "N n")
    found = one([s, tr("go"), jump("S0")])
    assert ("ST-UNKNOWN-VAR", s["actions"][0]["id"]) in codes(found)
    assert ("SFC-ACTION", s["actions"][1]["id"]) in codes(found)


def test_an_entry_action_that_does_not_exist():
    s = step("S0", entry="Start")
    found = one([s, tr("go"), jump("S0")])
    assert codes(found) == {("SFC-ACTION", s["id"])}


@pytest.mark.parametrize(
    ("condition", "code"),
    [
        ("x := TRUE", "SFC-CONDITION"),
        ("LIMIT(0, n, 10) > 5 AND go", None),
        ("n", "ST-TYPE-MISMATCH"),
        ("undeclared", "ST-UNKNOWN-VAR"),
    ],
)
def test_a_transition_condition_is_a_bool_expression_without_assignment(condition, code):
    t = tr(condition)
    found = one([step("S0"), t, jump("S0")])
    assert codes(found) == ({(code, t["id"])} if code else set())


def test_a_transition_written_in_ld_may_not_assign_or_call_a_function_block():
    transition = {
        "name": "Ready",
        "language": "ld",
        "body": ld_network(
            {"type": "contact", "id": "c1", "var": "go"},
            {"type": "box", "id": "b1", "call": "TON", "instance": "t1", "inputs": {"PT": "T#1s"}},
            {"type": "coil", "id": "k1", "var": "Lamp"},
            {"type": "coil", "id": "k2", "var": "Ready"},
        ),
    }
    found = problems(sfc_pou("Main", DECLS, [step("S0"), tr("Ready"), jump("S0")], transitions=[transition]))
    sfc03 = [(f, e, m) for c, f, e, m in found if c == "SFC-CONDITION"]
    assert (
        "Main/transitions/Ready",
        "b1",
        "a transition cannot call the function block instance t1: call it in an action",
    ) in sfc03
    assert ("Main/transitions/Ready", "k1", "a transition cannot assign Lamp: it only gives its own value (Ready)") in (
        sfc03
    )


def test_a_function_cannot_be_written_in_sfc():
    pou = sfc_pou("Fn", "VAR_INPUT a : BOOL; END_VAR", [step("S0"), tr("a"), jump("S0")], kind="function")
    pou.return_type = "BOOL"
    found = problems(pou)
    assert ("SFC-KIND", "Main/chart".replace("Main", "Fn")) in {(c, f) for c, f, _, _ in found}


def test_errors_in_st_actions_are_located_in_the_action():
    found = one([step("S0", "N A"), tr("go"), jump("S0")], {"A": "n := 1;\nn := undeclared;"})
    assert [(c, f) for c, f, _, _ in found] == [("ST-UNKNOWN-VAR", "Main/actions/A")]
    result = lower_project(
        project(sfc_pou("Main", DECLS, [step("S0", "N A"), tr("go"), jump("S0")], {"A": "n := 1;\nn := undeclared;"}))
    )
    located = next(d for d in result.diagnostics if d.code == "ST-UNKNOWN-VAR")
    assert (located.line, located.column) == (2, 6)


def test_an_action_nothing_uses_is_a_warning():
    found = problems(
        sfc_pou("Main", DECLS, [step("S0"), tr("go"), jump("S0")], {"Idle": "n := 1;"}), severity="warning"
    )
    assert ("SFC-UNUSED", "Main/actions/Idle") in {(c, f) for c, f, _, _ in found}


def test_a_bad_association_qualifier_is_refused_by_the_model():
    from pydantic import ValidationError

    bad = assoc("N A")
    bad["qualifier"] = "X"
    with pytest.raises(ValidationError):
        sfc_pou("Main", DECLS, [{**step("S0"), "actions": [bad]}])


def test_a_divergence_with_one_branch_is_no_divergence():
    """SFC-07 (alternative) and SFC-08 (simultaneous): a divergence selects or starts two sequences or more."""
    one_alt = alt([tr("go"), jump("S0")])
    found = one([step("S0"), one_alt])
    assert ("SFC-BRANCHES", one_alt["id"]) in codes(found)
    assert "an alternative divergence needs two branches or more" in [m for c, _, e, m in found if e == one_alt["id"]]
    one_par = par([step("S1"), tr("x")])
    found = one([step("S0"), tr("go"), one_par, jump("S0")])
    assert [m for c, _, e, m in found if c == "SFC-BRANCHES"] == [
        "a simultaneous divergence needs two branches or more"
    ]


def test_an_alternative_branch_ending_with_a_step_is_a_warning():
    """A branch that ends in a step stops the chart there: a warning naming the branch, the chart still runs."""
    last = step("S2")
    chart = [step("S0"), alt([tr("go"), last], [tr("x"), jump("S0")])]
    warnings = problems(sfc_pou("Main", DECLS, chart), severity="warning")
    assert [(c, e) for c, _, e, _ in warnings] == [("SFC-BRANCH-END", last["id"])]
    assert warnings[0][3].startswith("branch 1 of the alternative ends with a step, so the chart stops there")
