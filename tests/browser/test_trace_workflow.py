"""Issue 9 in a real browser against a real server: the trace chart, and a Beremiz example imported and run.

1. A TON with PT = T#200ms on a 10 ms task: trace its Q and ET from the Trace panel, triggered by the
   rising edge of its input, written from the watch list while the simulation runs. The edge of Q in
   the samples table lies PT after the trigger (within one scan), the chart's legend shows the values
   under the cursor, and the exported CSV holds every sample scan by scan.
2. Beremiz's ``first_steps`` (../shared/external, skipped when absent) imported through the UI with no warning:
   its SFC (issue 24) and IL (issue 26) POUs import as such, so the project compiles and runs as imported and its
   five counters count in the watch list.

Screenshots go to tests/browser/artifacts/ (trace-chart.png, trace-table.png, first-steps-*.png).
"""

from __future__ import annotations

import csv
import io
import re
import time
from pathlib import Path

import pytest

from tests.support import external

from .conftest import ARTIFACTS
from .steps import new_project, store_project

pytestmark = pytest.mark.browser

PT_MS = 200
SCAN_MS = 10
SAMPLES = 40

TIMER_DECLARATIONS = """VAR
    Go : BOOL;
    Timer : TON;
    Q : BOOL;
    ET : TIME;
END_VAR"""
TIMER_BODY = f"""Timer(IN := Go, PT := T#{PT_MS}ms);
Q := Timer.Q;
ET := Timer.ET;"""


def _online(page) -> None:
    page.get_by_role("button", name="Compile & simulate").click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    page.get_by_role("button", name="Run", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · running").wait_for()


def _watch(page, path: str):
    page.get_by_role("tab", name=re.compile("^Watch list")).click()
    page.get_by_label("Variable path to watch").fill(path)
    page.keyboard.press("Enter")
    return page.locator(f'tr[data-path="{path.upper()}"] td.watch-value')


def _open_project(page, server: str, name: str) -> None:
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile(f"^{name}")).click()
    page.get_by_role("heading", name=name, exact=True).wait_for()


def test_a_trace_of_a_ton_shows_q_rising_pt_after_its_input(page, server):
    store_project(
        server,
        {
            "name": "timer",
            "pous": [
                {
                    "name": "Main",
                    "kind": "program",
                    "language": "st",
                    "declarations": TIMER_DECLARATIONS,
                    "body": TIMER_BODY,
                }
            ],
            "tasks": [{"name": "Fast", "interval": f"T#{SCAN_MS}ms", "programs": ["Main"]}],
        },
    )
    _open_project(page, server, "timer")
    _online(page)

    # The trace: Q and ET (typed, offered by the autocomplete), triggered by Go rising, 40 samples.
    page.get_by_role("tab", name="Trace").click()
    offered = page.locator("#trace-candidates option")
    page.wait_for_function("() => document.querySelectorAll('#trace-candidates option').length >= 6")
    assert {"Main.Go", "Main.Q", "Main.ET", "Main.Timer.Q", "Main.Timer.ET"} <= set(
        offered.evaluate_all("options => options.map(o => o.value)")
    )
    for path in ("Main.Q", "Main.ET"):
        page.get_by_label("Variable to trace").fill(path)
        page.keyboard.press("Enter")
    assert page.get_by_role("list", name="Traced variables").inner_text().split() == ["Main.Q", "×", "Main.ET", "×"]
    page.get_by_label("Trigger variable").fill("Main.Go")
    page.get_by_label("Samples to keep").fill(str(SAMPLES))
    page.get_by_role("button", name="Start trace").click()
    status = page.get_by_role("status", name="Trace state")
    status.filter(has_text="Waiting for the trigger: Main.Go rising").wait_for()
    scan = int(page.get_by_test_id("scan-count").inner_text())
    page.wait_for_function(f"() => Number(document.querySelector('[data-testid=scan-count]').textContent) > {scan + 5}")
    assert status.inner_text() == "Waiting for the trigger: Main.Go rising"  # scans go by, Go stays FALSE

    # Go := TRUE from the watch list: the trigger fires, 40 samples later the trace is done.
    go = _watch(page, "Main.Go")
    go.filter(has_text="FALSE").wait_for()
    page.get_by_label("New value for Main.Go").fill("TRUE")
    page.get_by_role("button", name="Write", exact=True).click()
    page.get_by_role("tab", name="Trace").click()
    status.filter(has_text=f"Done · {SAMPLES} samples").wait_for()

    # The chart's legend shows the values under the cursor: Q FALSE early, TRUE late.
    plot = page.locator(".trace-plot .u-over")
    plot.wait_for()
    box = plot.bounding_box()
    q_value = page.locator(".trace-plot .u-legend tr.u-series", has_text="MAIN.Q").locator(".u-value")
    for fraction, expected in ((0.1, "FALSE"), (0.95, "TRUE")):
        page.mouse.move(box["x"] + box["width"] * fraction, box["y"] + box["height"] / 2)
        q_value.filter(has_text=re.compile(f"^{expected}$")).wait_for()
    page.screenshot(path=str(ARTIFACTS / "trace-chart.png"))

    # Drag to zoom, double click to reset: the visible x range narrows, then covers every sample again.
    span = "() => { const d = document.querySelector('.trace-plot').dataset; return d.xMax - d.xMin; }"
    whole = (SAMPLES - 1) * SCAN_MS
    assert page.evaluate(span) == whole
    page.mouse.move(box["x"] + box["width"] * 0.3, box["y"] + 20)
    page.mouse.down()
    page.mouse.move(box["x"] + box["width"] * 0.6, box["y"] + 20, steps=5)
    page.mouse.up()
    page.wait_for_function(f"() => ({span})() < {whole / 2}")
    plot.dblclick(position={"x": box["width"] / 2, "y": 20})
    page.wait_for_function(f"() => ({span})() === {whole}")

    # The samples table: Q's rising edge lies PT after the trigger, within one scan.
    page.get_by_label("Table").check()
    rows = page.get_by_role("table", name="Trace samples").locator("tbody tr")
    assert rows.count() == SAMPLES
    table = [
        row.split("\t")
        for row in rows.evaluate_all("rows => rows.map(r => [...r.children].map(c => c.textContent).join('\\t'))")
    ]
    edge = next(row for row in table if row[2] == "TRUE")
    assert abs(float(edge[0]) - PT_MS) <= SCAN_MS, edge
    assert table[0][:3] == ["0", table[0][1], "FALSE"] and table[0][3] == "0"  # the trigger's scan: ET starts
    page.screenshot(path=str(ARTIFACTS / "trace-table.png"))

    # The CSV: a header of paths, every sample scan by scan, ET counting to PT, Q TRUE from PT on.
    with page.expect_download() as download:
        page.get_by_role("button", name="Export CSV").click()
    assert download.value.suggested_filename == "trace-timer.csv"
    text = Path(download.value.path()).read_text(encoding="utf-8")
    records = list(csv.reader(io.StringIO(text)))
    assert records[0] == ["time_ms", "scan", "MAIN.Q", "MAIN.ET"]
    body = records[1:]
    assert len(body) == SAMPLES
    first_time, first_scan = float(body[0][0]), int(body[0][1])
    for i, (time_ms, scan_no, q, et) in enumerate(body):
        assert (float(time_ms), int(scan_no)) == (first_time + i * SCAN_MS, first_scan + i)
        assert int(et) == min(i * SCAN_MS, PT_MS)
        assert q == ("TRUE" if i * SCAN_MS >= PT_MS else "FALSE")


FIRST_STEPS = ("beremiz-examples", "exemples", "first_steps", "plc.xml")


def test_the_beremiz_first_steps_example_imports_and_runs(page, server):
    source = external(*FIRST_STEPS)
    new_project(page, server, "scratch")

    # Import through the UI: the report names what was not converted, then the project opens.
    page.get_by_role("button", name="Import PLCopen XML…").click()
    page.get_by_label("PLCopen XML file").set_input_files(str(source))
    page.get_by_label("New project name").fill("first_steps")  # the document's own name is "First Steps"
    page.get_by_role("button", name="Import", exact=True).click()
    form = page.get_by_role("form", name="Import PLCopen XML")
    form.get_by_text(re.compile(r"^Imported first_steps: 7 POUs, no warnings\.")).wait_for()
    assert "CounterSFC" not in form.inner_text() and "CounterIL" not in form.inner_text()
    page.screenshot(path=str(ARTIFACTS / "first-steps-import.png"))
    page.get_by_role("button", name="Open first_steps").click()
    page.get_by_role("heading", name="first_steps").wait_for()
    tree = page.get_by_role("navigation", name="Project tree")
    for pou in ("plc_prg", "CounterST", "CounterFBD", "CounterLD", "CounterSFC", "CounterIL", "AverageVal"):
        tree.get_by_role("button", name=re.compile(f"^{pou}")).wait_for()

    # As imported, it compiles and runs: the ST, FBD, LD, SFC and IL counters count every 100 ms scan.
    _online(page)
    paths = ("plc_prg.Cnt1", "plc_prg.Cnt2", "plc_prg.Cnt3", "plc_prg.Cnt4", "plc_prg.Cnt5")  # Cnt3 SFC, Cnt4 IL
    values = {path: _watch(page, path) for path in paths}
    first = {}
    for path, cell in values.items():
        cell.filter(has_text=re.compile(r"^[1-9]\d*$")).wait_for()
        first[path] = int(cell.inner_text())
    deadline = time.monotonic() + 10
    while min(int(cell.inner_text()) - first[path] for path, cell in values.items()) < 3:
        assert time.monotonic() < deadline, "the counters did not advance"
        page.wait_for_timeout(100)
    page.screenshot(path=str(ARTIFACTS / "first-steps-running.png"))
