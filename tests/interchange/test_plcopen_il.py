"""IL bodies in PLCopen XML (issue 26 item 4): imported as IL POUs that run, exported as ``<IL>`` text."""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from ladderlab.interchange.plcopen.exporter import export_plcopen
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou, Task
from ladderlab.st.project_text import source_to_project
from tests.ir.test_il_examples import USER_FUN
from tests.support import external


def test_openplc_multi_language_il_counter_counts_like_its_st_twin():
    """OpenPLC Multi_Language: CounterIL (JMPC / JMP / labels, issue 26) and CounterST give the same output scan by
    scan, counting up and loading ResetCounterValue on Reset."""
    data = external("openplc-examples", "examples", "Multi_Language", "plc.xml").read_bytes()
    result = import_plcopen(data, file="plc.xml")
    project = result.project
    assert {p.name: p.language for p in project.pous}["CounterIL"] == "il"
    check = Pou(
        name="Check",
        kind="program",
        language="st",
        declarations="VAR\n    Reset : BOOL;\n    st : CounterST;\n    il : CounterIL;\nEND_VAR",
        body="st(Reset := Reset);\nil(Reset := Reset);",
    )
    counters = [p for p in project.pous if p.name in ("CounterST", "CounterIL")]
    program = project.model_copy(
        update={"pous": [*counters, check], "tasks": [Task(name="t", programs=["Check"])], "configuration": None}
    )
    lowered = lower_project(program)
    assert [d.format() for d in lowered.diagnostics if d.severity == "error"] == []
    sim = Simulation(lowered.program)
    outputs = []
    for scan in range(30):
        sim.write("Check.Reset", scan in (10, 11, 25))
        sim.cycle(1)
        outputs.append((sim.read("Check.st.OUT"), sim.read("Check.il.Out")))
    assert all(st == il for st, il in outputs)
    assert [st for st, _ in outputs[:12]] == [*range(1, 11), 17, 17]  # ResetCounterValue is 17 in the project


def test_il_pous_go_out_as_il_text_and_come_back_unchanged():
    text = "PROGRAM P\nVAR r : INT; END_VAR\n  LD 50\n  UserFun 100, 1000\n  ST r\nEND_PROGRAM\n" + USER_FUN
    project, _ = source_to_project(text, "il")
    project = project.model_copy(
        update={"pous": [p.model_copy(update={"declarations": p.declarations.strip("\n")}) for p in project.pous]}
    )
    xml = export_plcopen(project)
    assert xml.count(b"<IL>") == 2 and b"<ST>" not in xml
    back = import_plcopen(xml, name="il")
    assert [d.format() for d in back.diagnostics] == []
    assert back.project.pous == project.pous
