"""External PLCopen fixtures (../shared/external): import, check and run (issue 8, Tests: import of all fixtures).

Every ``.xml``/``.cfc`` under beremiz-examples, openplc-examples, rusty-cfc and
ironplc imports: LD, FBD and ST POUs without errors (counts printed in the
terminal summary, floors asserted), SFC and IL POUs reported as unsupported and
kept with their interface and an empty body.
Imported projects then go through ``check_project``; the ones that fail are
listed with the reason, which lies in the source, not in the import. Finally
the imported programs run: Beremiz first_steps' LD, FBD and ST counters agree
scan for scan, OpenPLC's LD Blink behaves like its ST twin, and RuSTy's CFC
fixtures give the results RuSTy's own tests state.
"""

from __future__ import annotations

import json
from collections import Counter
from typing import ClassVar

import pytest

from ladderlab.engine.simulation import Simulation
from ladderlab.interchange.plcopen.importer import import_plcopen
from ladderlab.ir.lower_project import lower_project
from ladderlab.model.project import Pou, Project, Task
from ladderlab.simulation.check import check_project
from ladderlab.st.project_text import source_to_project
from ladderlab.storage.load import project_from_st
from tests.interchange.plcopen_helpers import FOLDERS, IMPORT_ERRORS
from tests.support import EXTERNAL, external

VENDOR = "blocks or types of the vendor's runtime library (OpenPLC, Beremiz SVGHMI/LOGGER/RTC), not IEC"
OUTSIDE_GLOBALS = "its VAR_EXTERNALs live in the Arduino sketch, outside the PLCopen file"
OTHER_FILE = "a single RuSTy POU calling a POU that lives in another file"
RUSTY_INPUTS = "writes its own VAR_INPUTs, which RuSTy allows and IEC 61131-3 does not"
BROKEN = "deliberately broken upstream (RuSTy validation tests)"
GRAMMAR = "a syntax-highlighting sample, not a valid program"

#: Fixtures whose imported project does not pass check_project: the error codes, and why.
CHECK_FAILS = {
    "beremiz-examples/exemples/svghmi_traffic_light/plc.xml": ({"ST-UNKNOWN-TYPE"}, VENDOR),
    "beremiz-examples/tests/projects/iec61131_lang_test/plc.xml": (
        {"ST-UNKNOWN-TYPE", "ST-UNKNOWN-VAR", "FBD-UNKNOWN-CALL"},
        VENDOR,
    ),
    "openplc-examples/examples/Arduino_7_Segments/plc.xml": ({"ST-EXTERNAL"}, OUTSIDE_GLOBALS),
    "openplc-examples/examples/Arduino_Cloud/plc.xml": ({"LD-UNKNOWN-CALL", "ST-UNKNOWN-TYPE"}, VENDOR),
    "openplc-examples/examples/Arduino_LCD_Screen/plc.xml": ({"ST-EXTERNAL"}, OUTSIDE_GLOBALS),
    "openplc-examples/examples/Arduino_Serial_Print/plc.xml": ({"ST-EXTERNAL"}, OUTSIDE_GLOBALS),
    "openplc-examples/examples/Blink_P1AM/plc.xml": ({"LD-UNKNOWN-CALL", "ST-UNKNOWN-TYPE"}, VENDOR),
    "openplc-examples/examples/MQTT_Send/plc.xml": ({"LD-UNKNOWN-CALL", "ST-UNKNOWN-TYPE"}, VENDOR),
    "openplc-examples/examples/MQTT_Send_Receive/plc.xml": ({"LD-UNKNOWN-CALL", "ST-UNKNOWN-TYPE"}, VENDOR),
    "openplc-examples/examples/STM32CAN_Read_Write_FBD/plc.xml": ({"ST-UNKNOWN-TYPE", "FBD-UNKNOWN-CALL"}, VENDOR),
    "openplc-examples/examples/TCP_socket/plc.xml": ({"LD-UNKNOWN-CALL", "ST-UNKNOWN-TYPE"}, VENDOR),
    "rusty-cfc/compiler/plc_xml/res/program.xml": ({"ST-UNKNOWN-TYPE", "FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "rusty-cfc/tests/integration/data/cfc/chained_calls.cfc": ({"FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "rusty-cfc/tests/integration/data/cfc/chained_calls_galore.cfc": ({"FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "rusty-cfc/tests/integration/data/cfc/conditional_return.cfc": ({"FBD-INPUT-WRITE"}, RUSTY_INPUTS),
    "rusty-cfc/tests/integration/data/cfc/conditional_return_block.cfc": (
        {"FBD-INPUT-WRITE", "FBD-UNKNOWN-CALL"},
        f"{RUSTY_INPUTS}; {OTHER_FILE}",
    ),
    "rusty-cfc/tests/integration/data/cfc/conditional_return_negated.cfc": ({"FBD-INPUT-WRITE"}, RUSTY_INPUTS),
    "rusty-cfc/tests/integration/data/cfc/conditional_return_simple.cfc": ({"FBD-INPUT-WRITE"}, RUSTY_INPUTS),
    "rusty-cfc/tests/integration/data/cfc/connection_block_source_multi_sink.cfc": ({"FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "rusty-cfc/tests/integration/data/cfc/connection_var_source_multi_sink.cfc": ({"FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "rusty-cfc/tests/integration/data/cfc/duplicate_label.cfc": ({"FBD-DUPLICATE-LABEL"}, BROKEN),
    "rusty-cfc/tests/integration/data/cfc/early_return.cfc": ({"FBD-INPUT-WRITE"}, RUSTY_INPUTS),
    "rusty-cfc/tests/integration/data/cfc/early_return_negated.cfc": ({"FBD-INPUT-WRITE"}, RUSTY_INPUTS),
    "rusty-cfc/tests/integration/data/cfc/function_block_call_main.cfc": (
        {"ST-UNKNOWN-TYPE", "FBD-UNKNOWN-CALL"},
        OTHER_FILE,
    ),
    "rusty-cfc/tests/integration/data/cfc/jump_missing_label.cfc": ({"FBD-UNKNOWN-LABEL"}, BROKEN),
    "rusty-cfc/tests/integration/data/cfc/jump_no_label.cfc": ({"FBD-UNKNOWN-LABEL"}, BROKEN),
    "rusty-cfc/tests/integration/data/cfc/my_add.cfc": ({"FBD-UNKNOWN-CALL"}, OTHER_FILE),
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-configuration.xml": ({"UNKNOWN-PROGRAM"}, GRAMMAR),
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-cdata.xml": (
        {"ST-UNKNOWN-VAR", "ST-DECL"},
        GRAMMAR,
    ),
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-pou.xml": ({"ST-DECL"}, GRAMMAR),
    "ironplc/integrations/vscode/tests/grammar/snap/plcopen-sfc.xml": ({"SFC-EMPTY"}, GRAMMAR),
}
#: POUs reported as unsupported (file -> POU names): none, SFC and IL both import (issues 24 and 26).
UNSUPPORTED: dict[str, list[str]] = {}


class _Summary:
    """Prints the fixture counts at the end of the run (pytest_terminal_summary of a runtime plugin)."""

    lines: ClassVar[list[str]] = []

    def pytest_terminal_summary(self, terminalreporter) -> None:
        if self.lines:
            terminalreporter.section("PLCopen fixtures (../shared/external)")
            for line in self.lines:
                terminalreporter.write_line(line)


SUMMARY = _Summary()


@pytest.fixture(scope="module")
def fixtures(request) -> dict[str, object]:
    """Every fixture file imported once: relative path -> ImportResult."""
    if not request.config.pluginmanager.is_registered(SUMMARY):
        request.config.pluginmanager.register(SUMMARY, "plcopen-fixture-summary")
    for folder in FOLDERS:
        external(folder)
    files = sorted(p for folder in FOLDERS for p in (EXTERNAL / folder).rglob("*") if p.suffix in (".xml", ".cfc"))
    return {p.relative_to(EXTERNAL).as_posix(): import_plcopen(p.read_bytes(), file=p.name) for p in files}


def test_every_fixture_imports_ld_fbd_sfc_and_st_without_errors_and_reports_il(fixtures):
    languages: Counter[str] = Counter()
    errors, unsupported = {}, {}
    for path, result in fixtures.items():
        assert result.project is not None, path
        languages.update(pou.language for pou in result.project.pous)
        found = [d.code for d in result.diagnostics if d.severity == "error"]
        if found:
            errors[path] = found
        skipped = [d.pou for d in result.diagnostics if d.code == "PLCOPEN-UNSUPPORTED" and "written in" in d.message]
        if skipped:
            unsupported[path] = skipped
    SUMMARY.lines.append(
        f"{len(fixtures)} files imported: {languages['ld']} LD, {languages['fbd']} FBD, {languages['st']} ST, "
        f"{languages['il']} IL and {languages['sfc']} SFC POUs; {sum(map(len, unsupported.values()))} POUs reported "
        f"unsupported; import errors in {len(errors)} file(s), all in the source"
    )
    assert errors == IMPORT_ERRORS
    assert unsupported == UNSUPPORTED
    assert len(fixtures) >= 51 and languages["ld"] >= 12 and languages["fbd"] >= 36 and languages["st"] >= 12
    assert languages["il"] == 2  # CounterIL of first_steps and of Multi_Language


def test_imported_projects_pass_the_project_check_unless_the_source_is_not_standard(fixtures):
    failing = {}
    for path, result in fixtures.items():
        codes = {d.code for d in check_project(result.project) if d.severity == "error"}
        if codes:
            failing[path] = codes
    SUMMARY.lines.append(
        f"check_project: {len(fixtures) - len(failing)} imported projects pass, {len(failing)} fail "
        f"for reasons in the source ({len({r for _, r in CHECK_FAILS.values()})} kinds, listed in "
        "test_plcopen_fixtures.py)"
    )
    assert failing == {path: codes for path, (codes, _) in CHECK_FAILS.items()}


def test_first_steps_counters_in_ld_fbd_st_and_il_agree_scan_for_scan(fixtures):
    """Beremiz first_steps: CounterST, CounterFBD, CounterLD and CounterIL count up, and Reset loads
    ResetCounterValue (17)."""
    project = fixtures["beremiz-examples/exemples/first_steps/plc.xml"].project
    counters = [p for p in project.pous if p.name in ("CounterST", "CounterFBD", "CounterLD", "CounterIL")]
    assert sorted((p.name, p.language) for p in counters) == [
        ("CounterFBD", "fbd"),
        ("CounterIL", "il"),
        ("CounterLD", "ld"),
        ("CounterST", "st"),
    ]
    check = Pou(
        name="Check",
        kind="program",
        language="st",
        declarations="VAR\n    Reset : BOOL;\n    st : CounterST;\n    fbd : CounterFBD;\n    ld : CounterLD;\n"
        "    il : CounterIL;\nEND_VAR",
        body="st(Reset := Reset);\nfbd(Reset := Reset);\nld(Reset := Reset);\nil(Reset := Reset);",
    )
    program = project.model_copy(
        update={
            "pous": [*counters, check],
            "tasks": [Task(name="t", interval="T#100ms", programs=["Check"])],
            "configuration": None,
        }
    )
    result = lower_project(program)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    counts = []
    for scan in range(30):
        sim.write("Check.Reset", scan in (10, 11, 25))
        sim.cycle(1)
        counts.append(
            (sim.read("Check.st.OUT"), sim.read("Check.fbd.OUT"), sim.read("Check.ld.Out"), sim.read("Check.il.Out"))
        )
    assert all(st == fbd == ld == il for st, fbd, ld, il in counts)
    assert [c[0] for c in counts] == [*range(1, 11), 17, 17, *range(18, 31), 17, 18, 19, 20, 21][:30]


def test_first_steps_runs_as_imported_and_its_five_counters_count(fixtures):
    """The whole first_steps project builds as imported; its ST, FBD, LD and IL counters count every scan, the SFC
    counter one scan behind (its first scan is the initial step's, SFC-04)."""
    result = lower_project(fixtures["beremiz-examples/exemples/first_steps/plc.xml"].project)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    for scan in range(1, 6):
        sim.cycle(1)
        counts = [sim.read(f"plc_task_instance.Cnt{n}") for n in range(1, 6)]  # the instance of plc_prg
        assert counts == [scan, scan, scan - 1, scan, scan]
        assert sim.read("plc_task_instance.AVCnt") == pytest.approx((5 * scan - 1) / 5)  # the mean of the five


def test_first_steps_sfc_counter_counts_up_and_resets_as_its_chart_says(fixtures):
    """CounterSFC (Beremiz: "if reset is False, counter is incremented every cycle; if True it is reset to
    ResetCounterValue", 17). Its chart: Start -(NOT Reset)-> Count [Cnt := Cnt + 1; OUT := Cnt] -(Reset)-> Start
    -(Reset)-> ResetCounter [Cnt := 17; OUT := Cnt] -(NOT Reset)-> Start. Worked out from SFC-04: a step acts from
    the scan after its transition fired, and each left action runs once more (so Count adds one in the scan after
    Reset rises, and ResetCounter loads 17 again as Start is active); every pass through Start costs a scan."""
    project = fixtures["beremiz-examples/exemples/first_steps/plc.xml"].project
    counter = project.pou("CounterSFC")
    assert counter is not None and counter.language == "sfc"
    check = Pou(
        name="Check",
        kind="program",
        language="st",
        declarations="VAR\n    Reset : BOOL;\n    sfc : CounterSFC;\nEND_VAR",
        body="sfc(Reset := Reset);",
    )
    program = project.model_copy(
        update={
            "pous": [counter, check],
            "tasks": [Task(name="t", interval="T#100ms", programs=["Check"])],
            "configuration": None,
        }
    )
    result = lower_project(program)
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    counts = []
    for scan in range(30):
        sim.write("Check.Reset", scan in (10, 11, 25))
        sim.cycle(1)
        counts.append(sim.read("Check.sfc.OUT"))
    expected = [*range(0, 12), 17, 17, *range(18, 30), 30, *range(31, 34)]
    assert counts == expected


def test_openplc_blink_in_ld_behaves_like_its_st_twin(fixtures):
    """Blink/plc.xml (LD, TON -> TOF) and Blink/blink.st over 200 scans of 20 ms: the same square wave."""
    ld = fixtures["openplc-examples/examples/Blink/plc.xml"].project
    st = project_from_st(
        external("openplc-examples", "examples", "Blink", "blink.st").read_text(), name="blink", file="blink.st"
    )
    traces = []
    for project, path in ((ld, "instance0.blink_led"), (st, "instance0.LED_PIN")):  # the instances' names
        assert [t.interval for t in project.all_tasks()] == ["T#20ms"]
        sim = Simulation(lower_project(project).program)
        trace = []
        for _ in range(200):
            sim.cycle(1)
            trace.append(sim.read(path))
        traces.append(trace)
    assert traces[0] == traces[1]
    edges = [i for i in range(1, 200) if traces[0][i] != traces[0][i - 1]]
    assert edges[:4] == [25, 51, 77, 103]  # about 500 ms on, 500 ms off


def _rusty_cases() -> list[dict]:
    path = EXTERNAL / "rusty-cfc" / "expected.json"
    return json.loads(path.read_text())["run_cases"] if path.is_file() else []


#: RuSTy run cases whose ST driver and CFC are standard enough to run here; the others use RuSTy's dialect
#: (drivers closing FUNCTIONs with END_PROGRAM, FBs writing their inputs, reading FB internals).
RUSTY_RUNS = {"function_returns", "connection_sink_source", "jump_to_label_with_true", "jump_to_label_with_false"}


@pytest.mark.parametrize("case", [c for c in _rusty_cases() if c["name"] in RUSTY_RUNS], ids=lambda c: c["name"])
def test_rusty_cfc_fixtures_give_the_results_rusty_states(case):
    """The FBD import keeps CFC execution order and jump semantics: main() returns what RuSTy's tests assert."""
    pous = []
    for name in case["files"]:
        path = external("rusty-cfc", name)
        if path.suffix == ".st":
            project, _ = source_to_project(path.read_text())
            pous += project.pous
        else:
            pous += import_plcopen(path.read_bytes()).project.pous
    wrapper = Pou(
        name="Wrap",
        kind="program",
        language="st",
        declarations="VAR\n    result : DINT;\nEND_VAR",
        body="result := main();",
    )
    result = lower_project(Project(name="rusty", pous=[*pous, wrapper], tasks=[Task(name="t", programs=["Wrap"])]))
    assert [d.format() for d in result.diagnostics if d.severity == "error"] == []
    sim = Simulation(result.program)
    sim.cycle(1)
    assert sim.read("Wrap.result") == case["main_returns"]


@pytest.mark.parametrize(
    "fixture, codes",
    [
        ("duplicate_label.cfc", ["FBD-DUPLICATE-LABEL"]),
        ("jump_missing_label.cfc", ["FBD-UNKNOWN-LABEL"]),
        ("multi_labels.cfc", []),
    ],
)
def test_rusty_label_validation_cases_give_the_stated_diagnostics(fixture, codes):
    data = external("rusty-cfc", "tests", "integration", "data", "cfc", fixture).read_bytes()
    project = import_plcopen(data).project
    assert [d.code for d in check_project(project) if d.severity == "error"] == codes
