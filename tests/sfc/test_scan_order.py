"""SFC-04: the order of one scan, the first scan, entry and exit actions, the implicit variables (SFC-06).

Expected values from seed 003 (SFC-04: the actions of the active steps run once, then the transitions are
evaluated; a newly active step acts from the next scan; an exit action runs once in the scan after its transition
fired; a deactivated action runs once more; first the deactivated actions run, then the active ones, in
alphabetical order) and IEC 61131-3 (Step.X, Step.T: the time since the step became active).
"""

from __future__ import annotations

from ladderlab.model import Pou

from .support import build, jump, project, run_table, sfc_pou, step, tr

LOG = "VAR go, back : BOOL; log : STRING; n : INT; END_VAR"


def logger(*names: str) -> dict[str, str]:
    return {name: f"log := CONCAT(log, '{name}');" for name in names}


def test_the_initial_step_acts_in_the_first_scan_and_its_p_action_pulses():
    chart = [step("S0", "N Count", "P Pulse"), tr("go"), step("S1"), tr("back"), jump("S0")]
    actions = {"Count": "n := n + 1;", "Pulse": "IF Pulse.Q THEN log := CONCAT(log, 'P'); END_IF;"}
    run_table(
        project(sfc_pou("Main", LOG, chart, actions)),
        """
        scan go || S0.X n log
        0    0  || 1    1 'P'
        1    0  || 1    2 'P'
        2    1  || 0    3 'P'
        3    0  || 0    4 'P'    # Count's final run
        4    0  || 0    4 'P'
        """,
    )


def test_a_step_activated_in_a_scan_acts_from_the_next_one():
    """A chain of transitions that are all TRUE moves one step per scan: each step must act before it is left."""
    chart = [
        step("S0", "N A0"),
        tr("TRUE"),
        step("S1", "N A1"),
        tr("TRUE"),
        step("S2", "N A2"),
        tr("FALSE"),
        jump("S0"),
    ]
    run_table(
        project(
            sfc_pou(
                "Main",
                LOG,
                chart,
                {"A0": "log := CONCAT(log, '0');", "A1": "log := CONCAT(log, '1');", "A2": "log := CONCAT(log, '2');"},
            )
        ),
        """
        scan || S0.X S1.X S2.X log
        0    || 0    1    0    '0'
        1    || 0    0    1    '001'      # A0's final run, then A1 active
        2    || 0    0    1    '00112'    # A1's final run, then A2
        3    || 0    0    1    '001122'
        """,
    )


def test_deactivated_actions_run_first_then_the_active_ones_in_alphabetical_order():
    """Z (left with S0) runs its final time before A and M (active in S1), which run alphabetically whatever the
    order of the step's associations."""
    chart = [step("S0", "N Z"), tr("go"), step("S1", "N M", "N A"), tr("FALSE"), jump("S0")]
    run_table(
        project(sfc_pou("Main", LOG, chart, logger("A", "M", "Z"))),
        """
        scan go || log
        0    0  || 'Z'
        1    1  || 'ZZ'
        2    0  || 'ZZZAM'
        3    0  || 'ZZZAMAM'
        """,
    )


def test_entry_action_runs_in_the_first_active_scan_and_exit_action_in_the_scan_after_leaving():
    """SFC-01/SFC-04: entry once on activation; exit once, in the scan after its transition became TRUE."""
    chart = [
        step("S0"),
        tr("go"),
        step("S1", "N Body", entry="In", exit="Out"),
        tr("back"),
        step("S2"),
        tr("FALSE"),
        jump("S0"),
    ]
    run_table(
        project(sfc_pou("Main", LOG, chart, logger("Body", "In", "Out"))),
        """
        scan go back || S1.X log
        0    0  0    || 0    ''
        1    1  0    || 1    ''
        2    0  0    || 1    'InBody'
        3    0  0    || 1    'InBodyBody'
        4    0  1    || 0    'InBodyBodyBody'
        5    0  0    || 0    'InBodyBodyBodyOutBody'    # exit action, then Body's final run
        6    0  0    || 0    'InBodyBodyBodyOutBody'
        """,
    )


def test_step_time_counts_from_the_first_active_scan_and_keeps_its_value_after():
    """SFC-06 Step.T: T#0s in the step's first scan, +10 ms per scan; after the step is left it keeps its last value;
    a new activation starts again from T#0s."""
    chart = [step("S0"), tr("go"), step("S1"), tr("back"), jump("S0")]
    run_table(
        project(sfc_pou("Main", LOG, chart)),
        """
        scan go back || S1.X S1.T
        0    0  0    || 0    0
        1    1  0    || 1    0
        2    0  0    || 1    0
        3    0  0    || 1    10
        4    0  1    || 0    20
        5    0  0    || 0    20
        6    1  0    || 1    20
        7    0  0    || 1    0
        8    0  0    || 1    10
        """,
    )


def test_a_transition_on_the_step_time_and_a_d_action_of_the_same_time_agree():
    chart = [step("S0", "D A T#30ms"), tr("S0.T >= T#30ms"), step("S1"), tr("FALSE"), jump("S0")]
    run_table(
        project(sfc_pou("Main", LOG, chart, logger("A"))),
        """
        scan || S0.X S0.T A.Q log
        0    || 1    0    0   ''
        1    || 1    10   0   ''
        2    || 1    20   0   ''
        3    || 0    30   1   'A'
        4    || 0    30   0   'AA'
        """,
    )


def test_other_pous_read_the_implicit_variables():
    """SFC-06: ``boolvar1 := sfc1.step1.x;`` - the steps and actions of a program are readable from other POUs."""
    chart = [step("S0", "N A"), tr("go"), step("S1"), tr("back"), jump("S0")]
    other = Pou(
        name="Other",
        kind="program",
        language="st",
        declarations="VAR b0, b1, q : BOOL; t : TIME; END_VAR",
        body="b0 := Main.S0.X; b1 := Main.s1.x; t := Main.S1.T; q := Main.A.Q;",
    )
    run_table(
        project(sfc_pou("Main", LOG, chart, logger("A")), other),
        """
        scan go back || Other.b0 Other.b1 Other.q Other.t
        0    0  0    || 1        0        1       0
        1    1  0    || 0        1        1       0
        2    0  0    || 0        1        0       0
        3    0  1    || 1        0        0       10
        """,
    )


def test_a_program_that_runs_under_another_instance_name_is_read_through_that_name():
    """Program instances live among the globals (docs/runtime.md): ``Main.S0.X`` reads the instance named after
    Main; when the configuration names it otherwise, the read is a located error that names the instance."""
    from ladderlab.ir.lower_project import lower_project
    from ladderlab.model.project import Configuration, ProgramInstance, Resource, Task

    chart = [step("S0"), tr("go"), step("S1"), tr("back"), jump("S0")]
    other = Pou(
        name="Other", kind="program", language="st", declarations="VAR b : BOOL; END_VAR", body="b := Main.S0.X;"
    )
    proj = project(sfc_pou("Main", LOG, chart), other)
    task = Task(
        name="t", programs=[ProgramInstance(name="Line1", type="Main"), ProgramInstance(name="O", type="Other")]
    )
    configured = proj.model_copy(
        update={"configuration": Configuration(name="Plant", resources=[Resource(tasks=[task])])}
    )
    errors = [d for d in lower_project(configured).diagnostics if d.severity == "error"]
    assert [(d.file, d.line, d.message) for d in errors] == [
        (
            "Other/body",
            1,
            "the program Main runs as its instance Line1: other POUs read the instance named like the program "
            "(PROGRAM Main : Main in the configuration)",
        )
    ]


def test_a_function_block_may_be_written_in_sfc_and_each_instance_has_its_own_chart():
    fb = sfc_pou(
        "Seq",
        "VAR_INPUT go : BOOL; END_VAR VAR_OUTPUT busy : BOOL; END_VAR",
        [step("Idle"), tr("go"), step("Working", "N busy"), tr("NOT go"), jump("Idle")],
        kind="function_block",
    )
    main = Pou(
        name="Main",
        kind="program",
        language="st",
        declarations="VAR a, b : Seq; ga, gb : BOOL; ra, rb, busy_a : BOOL; END_VAR",
        body="a(go := ga); b(go := gb); ra := a.Working.X; rb := b.Working.X; busy_a := a.busy;",
    )
    run_table(
        project(fb, main),
        """
        scan ga gb || ra rb busy_a
        0    1  0  || 1  0  0
        1    1  0  || 1  0  1
        2    0  1  || 0  1  1
        3    0  1  || 0  1  0
        """,
    )


def test_the_chart_sets_the_implicit_variables_and_programs_cannot_write_them():
    chart = [step("S0"), tr("go"), step("S1"), tr("back"), jump("S0")]
    from ladderlab.ir.lower_project import lower_project

    writer = Pou(name="Other", kind="program", language="st", declarations="", body="Main.S0.X := TRUE;")
    inside = sfc_pou("Main", LOG, chart, {"A": "S1.X := TRUE;"})
    result = lower_project(project(inside, writer))
    found = {(d.code, d.file) for d in result.diagnostics if d.severity == "error"}
    assert ("ST-READONLY", "Other/body") in found  # one error: a program's members are refused like an FB's
    assert ("ST-READONLY", "Main/actions/A") in found


def test_writes_and_forces_on_a_step_flag_move_the_chart_online():
    """Online, a write to Step.X activates the step (its entry action runs, its time starts); a force holds it."""
    chart = [step("S0"), tr("go"), step("S1", "N A", entry="In"), tr("back"), jump("S0")]
    sim = build(project(sfc_pou("Main", LOG, chart, logger("A", "In"))))
    sim.cycle(1)
    sim.write("Main.S0.X", False)
    sim.write("Main.S1.X", True)
    sim.cycle(1)
    assert (sim.read("Main.S0.X"), sim.read("Main.S1.X"), sim.read("Main.log")) == (False, True, "InA")
    sim.force("Main.S1.X", "FALSE")
    sim.cycle(2)
    assert sim.read("Main.S1.X") is False and sim.read("Main.log") == "InAA"  # the final run, then nothing
