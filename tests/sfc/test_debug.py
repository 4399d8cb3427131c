"""SFC online (SFC-09, ON-03, ON-04, ON-17): probes of steps and transitions, breakpoints on a step, a transition or
an action's line or network, and stepping to the next transition that fires."""

from __future__ import annotations

import pytest

from .support import build, jump, project, sfc_pou, step, tr

DECLS = "VAR go, back, lit : BOOL; n, m : INT; END_VAR"
LD_ACTION = {
    "name": "Lamp",
    "language": "ld",
    "body": {
        "networks": [
            {
                "id": "n1",
                "elements": [{"type": "contact", "id": "c1", "var": "go"}, {"type": "coil", "id": "k1", "var": "lit"}],
            },
            {"id": "n2", "label": "L2", "elements": [{"type": "jump", "id": "j1", "target": "L3"}]},
            {
                "id": "n3",
                "label": "L3",
                "elements": [
                    {"type": "contact", "id": "c2", "var": "TRUE"},
                    {"type": "coil", "id": "k2", "var": "lit"},
                ],
            },
        ]
    },
}


def chart():
    s0, t1, s1, t2 = step("S0", "N Count"), tr("go"), step("S1", "N Lamp"), tr("back AND n > 0")
    pou = sfc_pou(
        "Main", DECLS, [s0, t1, s1, t2, jump("S0")], {"Count": "n := n + 1;\nm := n * 2;"}, extra_actions=[LD_ACTION]
    )
    return project(pou), {"S0": s0["id"], "S1": s1["id"], "T1": t1["id"], "T2": t2["id"]}


def test_probes_show_the_active_steps_and_every_transition_condition():
    proj, ids = chart()
    sim = build(proj, "monitor")
    sim.cycle(1)
    view = sim.probes("MAIN")
    assert ids["S0"] in view.executed and ids["S1"] not in view.executed  # active steps are highlighted
    assert view.values[f"{ids['T1']}.COND"] is False
    assert view.values[f"{ids['T2']}.COND"] is False  # the condition of a transition whose step is inactive too
    sim.write("Main.go", True)
    sim.write("Main.back", True)
    sim.cycle(1)
    view = sim.probes("MAIN")
    assert view.values[f"{ids['T1']}.COND"] is True and ids["T1"] in view.executed  # it fired
    assert view.values[f"{ids['T2']}.COND"] is True and ids["T2"] not in view.executed  # TRUE, S1 was not active
    assert "actions/Lamp/c1" not in view.values  # Lamp has not run yet
    sim.cycle(1)
    view = sim.probes("MAIN", ["actions/Lamp/c1", "actions/Lamp/k2", ids["S1"]])
    assert view.values["actions/Lamp/c1"] is True and ids["S1"] in view.executed


def test_a_breakpoint_on_a_step_halts_while_it_is_active():
    proj, ids = chart()
    sim = build(proj, "debug")
    sim.set_breakpoint("Main", element=ids["S1"])
    assert sim.cycle(3) == 3 and sim.halted is None  # S1 inactive
    sim.write("Main.go", True)
    assert sim.cycle(1) == 1 and sim.halted is None  # S1 is activated at the end of this scan
    assert sim.cycle(1) == 0 and sim.halted.point.element == ids["S1"] and sim.halted.origin.body is None
    assert sim.read("Main.S1.X") is True and sim.read("Main.m") == 8  # halted before the actions run (n = 4)


def test_a_breakpoint_on_a_transition_halts_when_it_fires_before_the_steps_change():
    proj, ids = chart()
    sim = build(proj, "debug")
    sim.set_breakpoint("Main", element=ids["T1"])
    assert sim.cycle(2) == 2
    sim.write("Main.go", True)
    assert sim.cycle(1) == 0
    assert (sim.halted.point.kind, sim.halted.point.element, sim.halted.reason) == (
        "transition",
        ids["T1"],
        "breakpoint",
    )
    assert (sim.read("Main.S0.X"), sim.read("Main.S1.X")) == (True, False)
    assert sim.resume() is None and (sim.read("Main.S0.X"), sim.read("Main.S1.X")) == (False, True)


def test_breakpoints_on_a_line_of_an_st_action_and_a_network_of_an_ld_action():
    proj, ids = chart()
    sim = build(proj, "debug")
    sim.set_breakpoint("Main", line=2, body="actions/Count")
    assert sim.cycle(1) == 0
    halt = sim.halted
    assert (halt.origin.body, halt.origin.line, halt.point.kind) == ("actions/Count", 2, "statement")
    assert sim.read("Main.n") == 1 and sim.read("Main.m") == 0  # line 1 ran, line 2 not yet
    sim.resume()
    sim.clear_breakpoints()
    sim.set_breakpoint("Main", network="n3", body="actions/Lamp")
    sim.write("Main.go", True)
    assert sim.cycle(2) == 1  # S1 acts in the second scan
    assert (sim.halted.origin.body, sim.halted.origin.network) == ("actions/Lamp", "n3")
    with pytest.raises(ValueError, match="no pause points in actions/Nothing"):
        sim.set_breakpoint("Main", line=1, body="actions/Nothing")
    with pytest.raises(ValueError, match="has no statement at line 7"):
        sim.set_breakpoint("Main", line=7, body="actions/Count")


def test_step_to_the_next_transition_waits_for_scans_until_one_fires():
    """ON-04 for SFC: "continue up to the next step" - the step halts where a transition fires, however many scans
    that takes; then the chart moves on from there."""
    proj, ids = chart()
    sim = build(proj, "debug")
    assert sim.step("transition") is None  # no transition fired in this scan: still waiting
    assert sim.debugger.waiting_for_transition and sim.scan_count == 1
    assert sim.cycle(5) == 5  # nothing fires
    sim.write("Main.go", True)
    assert sim.cycle(5) == 0 and sim.halted.point.element == ids["T1"] and sim.halted.reason == "step"
    assert not sim.debugger.waiting_for_transition
    assert sim.resume() is None and sim.read("Main.S1.X") is True
    sim.write("Main.go", False)
    assert sim.cycle(3) == 3  # the step is over: scans run freely
    sim.write("Main.back", True)
    halt = sim.step("transition")  # fires at once in the next scan
    assert halt is not None and halt.point.element == ids["T2"]


def test_a_runtime_error_in_an_action_names_the_action_and_line():
    pou = sfc_pou("Main", DECLS, [step("S0", "N Bad"), tr("go"), jump("S0")], {"Bad": "n := 1;\nm := 10 / (n - 1);"})
    sim = build(project(pou))
    sim.cycle(1)
    assert sim.fault is not None
    assert "POU MAIN, action Bad, line 2" in sim.fault.text()
    assert sim.fault.diagnostic().file == "MAIN/actions/Bad"
