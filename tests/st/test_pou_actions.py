"""ACTIONs of a function block outside SFC (CODESYS; IL-08's third call form, seed 003): statements that run on
the instance's variables, called ``Inst.Reset();`` in ST, ``CAL Inst.Reset`` in IL, ``Reset();`` inside the FB.

Expected values follow seed 003's example by hand: ``CAL Inst.Reset(In := FALSE) / LD Inst.out / ST ERG`` - the
inputs given to an action are the instance's, set before the action runs.
"""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou, PouAction, Project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.st_text import compose_pou_text
from tests.ir.helpers import lower_source

COUNTER = """
FUNCTION_BLOCK Counter
VAR_INPUT In : BOOL; END_VAR
VAR_OUTPUT out : INT; END_VAR
ACTION Reset:
    IF NOT In THEN
        out := 0;
    END_IF;
END_ACTION
IF In THEN out := out + 1; END_IF;
END_FUNCTION_BLOCK
"""

DECLS = "VAR Inst : Counter; ERG, before : INT; go : BOOL; END_VAR"


def run(source: str, gos: list[bool]) -> list[tuple[int, int]]:
    """Scan by scan with ``go`` written first: (before, ERG)."""
    result = lower_source(source + COUNTER)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    rows = []
    for go in gos:
        sim.write("P.go", go)
        sim.cycle()
        assert sim.fault is None
        rows.append((sim.read("P.before"), sim.read("P.ERG")))
    return rows


# Two calls with In TRUE count 2 a scan; the reset (when go) sets out to 0 with In FALSE: scan 1 -> 2, scan 2 -> 4
# then reset to 0, scan 3 -> 0 + 2.
EXPECTED = [(2, 2), (4, 0), (2, 2)]


IL_CALL = f"""PROGRAM P
{DECLS}
CAL Inst(In := TRUE)
CAL Inst(In := TRUE)
LD Inst.out
ST before
LD go
CALC Inst.Reset(In := FALSE)
LD Inst.out
ST ERG
END_PROGRAM
"""


def test_an_action_called_with_the_instances_input_in_il_IL_08():
    """``CALC Inst.Reset(In := FALSE)``: the seed's call, conditional on the CR (IL-14)."""
    assert run(IL_CALL, [False, True, False]) == EXPECTED


def test_the_same_action_call_in_st_IL_08():
    source = f"""PROGRAM P
{DECLS}
Inst(In := TRUE);
Inst(In := TRUE);
before := Inst.out;
IF go THEN
    Inst.Reset(In := FALSE);
END_IF;
ERG := Inst.out;
END_PROGRAM
"""
    assert run(source, [False, True, False]) == EXPECTED


def test_cal_of_an_action_without_inputs_IL_08():
    """``CAL Inst.Reset`` runs the action with the instance's inputs as they are: In is FALSE after
    ``Inst(In := FALSE)``, so out goes to 0; with In TRUE it stays."""
    source = """PROGRAM P
VAR Inst : Counter; ERG, before : INT; go : BOOL; END_VAR
CAL Inst(In := TRUE)
LD Inst.out
ST before
CAL Inst(In := go)
CAL Inst.Reset
LD Inst.out
ST ERG
END_PROGRAM
"""
    # scan 1: out 1, then (go FALSE) In FALSE: out stays 1, reset -> 0; scan 2: out 1, go TRUE: 2, no reset
    assert run(source, [False, True]) == [(1, 0), (1, 2)]


def test_an_action_called_inside_its_function_block():
    """``Wrap();`` in the FB's own body runs on the instance running it: out counts 1, 2, 0, 1, 2."""
    fb = """
FUNCTION_BLOCK Counter
VAR_OUTPUT out : INT; END_VAR
ACTION Wrap:
    out := 0;
END_ACTION
out := out + 1;
IF out > 2 THEN
    Wrap();
END_IF;
END_FUNCTION_BLOCK
"""
    result = lower_source(
        "PROGRAM P\nVAR Inst : Counter; ERG : INT; END_VAR\nInst();\nERG := Inst.out;\nEND_PROGRAM\n" + fb
    )
    assert [d.format() for d in result.diagnostics] == []
    sim = Simulation(result.program)
    values = []
    for _ in range(5):
        sim.cycle()
        values.append(sim.read("P.ERG"))
    assert values == [1, 2, 0, 1, 2]


def test_an_unknown_input_of_an_action_call_is_a_located_error():
    source = f"PROGRAM P\n{DECLS}\nInst.Reset(Nope := FALSE);\nEND_PROGRAM\n" + COUNTER
    assert [d.format() for d in lower_source(source).diagnostics] == [
        "P/body:3:12, POU P: error ST-UNKNOWN-MEMBER: Counter has no input or output 'Nope'"
    ]


def test_actions_belong_to_function_blocks():
    program = "PROGRAM P\nVAR x : INT; END_VAR\nACTION Clear:\n    x := 0;\nEND_ACTION\nx := x + 1;\nEND_PROGRAM\n"
    project, diagnostics = source_to_project(program)
    assert project.pous == [] and [d.format() for d in diagnostics] == [
        "POU P line 3 column 1: error ST-PARSE: expected ';', CASE, CONTINUE or ..., found 'ACTION'"
    ]  # a program's actions are not supported (docs/st.md, "Actions")
    fb = Pou(
        name="F", kind="function_block", language="st", body="", actions=[PouAction(name="A"), PouAction(name="a")]
    )
    assert [d.format() for d in lower_project(Project(name="t", pous=[fb])).diagnostics] == [
        "F.a/declarations, POU F.a: error ST-DUPLICATE: F has two methods, properties or actions called 'a'"
    ]


def test_an_action_round_trips_through_the_st_text():
    """Written after the VAR blocks as ``ACTION name: ... END_ACTION`` (st_text.compose_pou_text) and read back."""
    project, diagnostics = source_to_project(COUNTER)
    assert diagnostics == []
    pou = project.pous[0]
    assert [(a.name, a.body.strip()) for a in pou.actions] == [
        ("Reset", "IF NOT In THEN\n        out := 0;\n    END_IF;")
    ]
    assert pou.body.strip() == "IF In THEN out := out + 1; END_IF;"
    again, _ = source_to_project(compose_pou_text(pou))
    assert [(a.name, a.body.strip()) for a in again.pous[0].actions] == [(a.name, a.body.strip()) for a in pou.actions]
    assert again.pous[0].body.strip() == pou.body.strip()


def test_actions_go_through_plcopen_as_tc6_actions_IL_08():
    """TC6 ``<actions><action name><body><ST>`` on a non-SFC function block: exported, valid against the XSD,
    imported back the same, and the imported project runs the seed's call (the same values as above)."""
    import xml.etree.ElementTree as ET

    from ladderlab.interchange.plcopen.exporter import export_plcopen
    from ladderlab.interchange.plcopen.importer import import_plcopen
    from tests.interchange.plcopen_helpers import xsd_errors

    source = f"PROGRAM P\n{DECLS}\nInst(In := TRUE);\nInst(In := TRUE);\nbefore := Inst.out;\n"
    source += "IF go THEN\n    Inst.Reset(In := FALSE);\nEND_IF;\nERG := Inst.out;\nEND_PROGRAM\n" + COUNTER
    project, _ = source_to_project(source)
    data = export_plcopen(project)
    assert xsd_errors(data) == []
    ns = "{http://www.plcopen.org/xml/tc6_0201}"
    action = ET.fromstring(data).find(f".//{ns}pou[@name='Counter']/{ns}actions/{ns}action")
    assert action.get("name") == "Reset" and action.find(f"{ns}body/{ns}ST") is not None
    result = import_plcopen(data)
    assert [d.format() for d in result.diagnostics] == []
    counter = result.project.pou("Counter")
    assert [(a.name, a.body.strip()) for a in counter.actions] == [
        (a.name, a.body.strip()) for a in project.pou("Counter").actions
    ]
    lowered = lower_project(result.project)
    assert [d.format() for d in lowered.diagnostics if d.severity == "error"] == []
    sim = Simulation(lowered.program)
    rows = []
    for go in (False, True, False):
        sim.write("P.go", go)
        sim.cycle()
        rows.append((sim.read("P.before"), sim.read("P.ERG")))
    assert rows == EXPECTED


def test_the_il_call_of_an_action_exports_as_st_that_runs_alike_IL_08():
    """``CALC Inst.Reset(In := FALSE)`` as ST: ``IF go THEN Inst.In := FALSE; Inst.Reset(); END_IF;`` - the same
    traces as the IL over 200 random scans."""
    from tests.interchange.st_support import body, exported, same_traces

    project, diagnostics = source_to_project(IL_CALL + COUNTER)
    assert diagnostics == []
    text = body(exported(project, "P").text)
    assert "IF go THEN\n    Inst.In := FALSE;\n    Inst.Reset();\nEND_IF;" in text
    same_traces(project)
