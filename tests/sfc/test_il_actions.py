"""SFC-02: actions and named transitions written in IL (issue 24 item 2), scan by scan.

An IL action runs like an ST action (SFC-04: once per scan while its step is active, once more when it is left; RET
ends the action, not the POU); an IL named transition is, as in CODESYS, the accumulator (CR) after its last line,
which must be a BOOL (SFC-03: it assigns nothing and calls no FB). Every expected value is worked out by hand from
IEC 61131-3's IL (LD/GE/JMPC/ADD/ST, RET) and the scan order of docs/sfc.md.

Main:  S0 [N Count] -(T1)-> S1 -(back)-> S0

    Count (IL)              T1 (IL)
        LD   n                  LD   n
        GE   3                  GE   2
        JMPC Done               AND  go
        LD   n
        ADD  1
        ST   n
        RET
    Done:
        LD   TRUE
        ST   full
"""

from __future__ import annotations

import pytest

from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.interchange.st.export import export_pou_st
from ladderlab.ir.lower_project import lower_project
from ladderlab.st.project_text import source_to_project
from tests.interchange.plcopen_helpers import strip_ladderlab, xsd_errors
from tests.interchange.st_support import exported, same_traces

from .support import build, jump, project, run_table, sfc_pou, step, tr

DECLS = "VAR go, back, full : BOOL; n : INT; END_VAR"
COUNT = "LD   n\nGE   3\nJMPC Done\nLD   n\nADD  1\nST   n\nRET\nDone:\nLD   TRUE\nST   full"
T1 = "LD   n\nGE   2\nAND  go"


def il_chart(count: str = COUNT, t1: str | None = T1):
    """The chart above; ``t1`` None: T1's condition written in the chart (``n >= 2 AND go``, the same value)."""
    condition = "T1" if t1 is not None else "n >= 2 AND go"
    main = [step("S0", "N Count"), tr(condition), step("S1"), tr("back"), jump("S0")]
    return project(
        sfc_pou(
            "Main",
            DECLS,
            main,
            extra_actions=[{"name": "Count", "language": "il", "body": count}],
            transitions=[{"name": "T1", "language": "il", "body": t1}] if t1 is not None else [],
        )
    )


TABLE = """
scan go back || n full S0.X S1.X T1 Count.Q
0    0  0    || 1 0    1    0    0  1       # S0 initial: Count runs (n 0 -> 1, RET before Done)
1    1  0    || 2 0    0    1    1  1       # Count: n = 2; then T1 = (2 >= 2) AND go fires
2    0  0    || 3 0    0    1    0  0       # Count's final run: n = 3; T1 = 3 >= 2 AND FALSE
3    0  1    || 3 0    1    0    0  0       # S1 -> S0 (S1 has no actions)
4    0  0    || 3 1    1    0    0  1       # Count: n >= 3 jumps to Done: full := TRUE, n stays 3
"""


def test_an_il_action_and_an_il_transition_run_scan_by_scan():
    run_table(il_chart(), TABLE)


def errors(proj) -> list[tuple[str, str | None, int | None, int | None, str]]:
    result = lower_project(proj)
    return [(d.code, d.file, d.line, d.column, d.message) for d in result.diagnostics if d.severity == "error"]


def test_an_il_error_in_an_action_is_located_in_the_action():
    """IL-TYPE inside the action: file Main/actions/Count, its line and column."""
    found = errors(il_chart(count="LD   n\nADD  full\nST   n"))
    assert [(code, file, line) for code, file, line, _, _ in found] == [("IL-TYPE", "Main/actions/Count", 2)]
    assert "the accumulator holds INT, the operand is BOOL" in found[0][4]


def test_an_il_syntax_error_in_an_action_is_located_in_the_action():
    found = errors(il_chart(count="LD   n\n:= 3\nST   n"))
    assert found == [("IL-PARSE", "Main/actions/Count", 2, 1, "IL syntax error: unexpected ':='")]


@pytest.mark.parametrize(
    ("body", "line", "message"),
    [
        ("LD   go\nST   full\nLD   go", 2, "a transition cannot assign full: it only gives its value (T1)"),
        ("LD   go\nS    full\nLD   go", 2, "a transition cannot assign full: it only gives its value (T1)"),
        (
            "LD   go\nRETC\nLD   back",
            2,
            "the transition T1 is the accumulator after its last line: RET has no place in it",
        ),
        ("LD   n\nADD  1", 2, "the transition T1 is the accumulator after its last line, a BOOL: there it holds INT"),
    ],
)
def test_an_il_transition_that_assigns_returns_or_is_no_bool_is_refused_sfc03(body, line, message):
    found = errors(il_chart(t1=body))
    assert [(code, file, at, text) for code, file, at, _, text in found] == [
        ("SFC-CONDITION", "Main/transitions/T1", line, message)
    ]


def test_an_il_transition_that_calls_a_function_block_is_refused_sfc03():
    proj = il_chart(t1="CAL  tm(IN := go, PT := T#1s)\nLD   tm.Q")
    proj.pous[0].declarations = DECLS + " VAR tm : TON; END_VAR"
    found = errors(proj)
    assert [(code, file, line, text) for code, file, line, _, text in found] == [
        ("SFC-CONDITION", "Main/transitions/T1", 1, "a transition cannot call tm: call it in an action")
    ]


def test_a_breakpoint_on_a_line_of_an_il_action_halts_before_it_and_shows_the_accumulator():
    """ON-17 in an IL action: a breakpoint on line 6 (ST n) halts before it runs: n is still 0 while the
    accumulator (the probe of line 5, ADD 1) already holds 1."""
    sim = build(il_chart(), "debug")
    sim.set_breakpoint("Main", line=6, body="actions/Count")
    assert sim.cycle(1) == 0
    halt = sim.halted
    assert (halt.origin.body, halt.origin.line) == ("actions/Count", 6)
    assert sim.read("Main.n") == 0


def test_online_the_accumulator_of_every_line_of_an_il_action_and_transition():
    """IL online view (docs/il.md) inside an SFC POU: the probes of the IL parts carry their body as prefix. Scan 0:
    Count with n = 0 (LD n 0, GE 3 FALSE, JMPC keeps FALSE, LD n 0, ADD 1 1, ST n 1, RET 1), then T1 with n = 1
    (LD n 1, GE 2 FALSE, AND go FALSE)."""
    sim = build(il_chart(), "monitor")
    sim.cycle(1)
    values = sim.probes("Main").values
    count = {key.split("/", 2)[2]: v for key, v in values.items() if key.startswith("actions/Count/L")}
    assert {line: count.get(line) for line in ("L1:INT", "L2:BOOL", "L3:BOOL", "L4:INT", "L5:INT", "L6:INT")} == {
        "L1:INT": 0, "L2:BOOL": False, "L3:BOOL": False, "L4:INT": 0, "L5:INT": 1, "L6:INT": 1,
    }  # fmt: skip
    t1 = {key.split("/", 2)[2]: v for key, v in values.items() if key.startswith("transitions/T1/L")}
    assert t1 == {"L1:INT": 1, "L2:BOOL": False, "L3:BOOL": False}


def test_il_actions_and_transitions_export_to_st_that_runs_alike():
    """The ST export of an SFC POU with an IL action (a jump, a RET that ends only the action) and an IL
    transition: readable ST (RET becomes the skip of the rest, the transition its accumulator's expression) that
    runs scan by scan like the chart under random writes (tests/interchange/st_support.py)."""
    proj = il_chart()
    text = exported(proj, "Main").text
    assert "T1 := n >= 2 AND go;" in text
    indent = " " * 8
    action = ["IF n >= 3 THEN", "    full := TRUE;", "ELSE", "    n := n + 1;", "END_IF;"]
    assert "\n".join(indent + line for line in action) in text  # JMPC Done ... RET ... Done: as IF/ELSE
    same_traces(proj, scans=300, seed=17)


def test_an_il_action_with_a_backward_jump_is_refused_by_the_st_export_with_its_line():
    proj = il_chart(count="Again:\nLD   n\nADD  1\nST   n\nLT   3\nJMPC Again")
    result = export_pou_st(proj, "Main")
    assert result.text == ""
    assert (
        "EXPORT-IL-JUMP",
        "Main/actions/Count",
        6,
        "the jump to Again goes backwards or out of an enclosing jump: ST has no jumps, so the IL action Count "
        "cannot be exported as ST",
    ) in [(d.code, d.file, d.line, d.message) for d in result.diagnostics]


def test_il_actions_and_transitions_travel_through_plcopen_as_il_bodies():
    """PLCopen TC6: the action's and the named transition's <body><IL> text; the file validates, comes back equal,
    and without LadderLab's addData still has IL parts that run the scan table above."""
    proj = il_chart()
    data = export_plcopen(proj)
    assert xsd_errors(data) == []
    assert b"<IL>" in data
    assert import_plcopen(data).project == proj
    stripped = import_plcopen(strip_ladderlab(data))
    assert [d.format() for d in stripped.diagnostics if d.severity == "error"] == []
    body = stripped.project.pou("Main").body
    assert (body.action("Count").language, body.action("Count").body) == ("il", COUNT)
    assert (body.transition("T1").language, body.transition("T1").body) == ("il", T1)
    run_table(stripped.project, TABLE)


def test_textual_sfc_writes_an_il_action_inside_its_action_and_reads_it_back_as_il():
    """IEC's ``ACTION name: function_block_body END_ACTION`` takes an instruction list too (B.1.6): the IL action
    is written as its instructions, read back as an IL action (the .st reader blanks it for the ST parser, as it
    does IL POU bodies), and the read project runs the same scan table (without T1's columns: its condition is
    written in the chart)."""
    proj = il_chart(t1=None)
    result = export_pou_st(proj, "Main", sfc_text=True)
    assert [d.format() for d in result.diagnostics] == []
    assert "    ACTION Count:\n        LD   n\n        GE   3\n        JMPC Done\n" in result.text
    again, diagnostics = source_to_project(result.text, "again")
    assert [d.format() for d in diagnostics] == []
    action = again.pou("Main").body.action("Count")
    assert (action.language, action.body) == ("il", COUNT)
    run_table(
        again,
        """
        scan go back || n full S0.X S1.X Count.Q
        0    0  0    || 1 0    1    0    1
        1    1  0    || 2 0    0    1    1
        2    0  0    || 3 0    0    1    0
        3    0  1    || 3 0    1    0    0
        4    0  0    || 3 1    1    0    1
        """,
    )
