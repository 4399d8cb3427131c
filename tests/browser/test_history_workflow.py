"""Scan history in the real Chromium (issue 23 item 3): the example ``motor`` (Main in LD, the seal-in rung
``Motor := (Start OR Motor) AND NOT Stop``) runs three single cycles, Start is written TRUE, three more
cycles; the timeline in the toolbar goes back to scan 2 (the Motor coil is off, as it was), steps forward
to scan 4 (the first scan after the write: the coil is on), the simulation runs on meanwhile without the
view moving, and Live shows the running scans again; Find jumps to the scan where Motor became TRUE. The test fails on any page or console error.
Screenshot: tests/browser/artifacts/history-scan-2.png."""

from __future__ import annotations

import json
import re
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import expect

from tests.live_server import LiveServer

from .bench_steps import expect_on
from .conftest import ARTIFACTS
from .steps import double_click_online, go_online, open_pou, store_project, watch

pytestmark = pytest.mark.browser


def _coil(page, state: str) -> None:
    page.wait_for_function(
        f"() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-{state}')"
    )


def _online_motor(page, server):
    """The example motor's Main online, stopped: its scan counter and the Single cycle button."""
    page.goto(server)
    open_pou(page, "motor", "Main")
    page.locator('g.ld-element[data-id="motor"]').wait_for()
    go_online(page, run=False)
    return page.get_by_test_id("scan-count"), page.get_by_role("button", name="Single cycle")


def test_go_back_to_a_scan_and_see_the_diagram_as_it_was(page, server):
    scan, cycle = _online_motor(page, server)
    for number in (1, 2, 3):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
    _coil(page, "off")
    start = page.locator('g.ld-element[data-id="start"]')
    double_click_online(start)  # prepares TRUE; Ctrl+F7 writes it before the next scan
    start.locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("Control+F7")
    for number in (4, 5, 6):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
    _coil(page, "on")
    watched = watch(page, "Motor")  # the watch list shows the scan shown too
    watched.filter(has_text=re.compile("^TRUE$")).wait_for()

    timeline = page.get_by_role("group", name="Scan history")
    slider = timeline.get_by_role("slider", name="Scan")
    assert slider.get_attribute("max") == "6"
    slider.fill("2")
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    scan.filter(has_text=re.compile("^2$")).wait_for()
    _coil(page, "off")
    watched.filter(has_text=re.compile("^FALSE$")).wait_for()
    page.screenshot(path=str(ARTIFACTS / "history-scan-2.png"))

    page.get_by_role("button", name="Show differences").click()  # with the live scan (6) by default
    differences = page.get_by_role("table", name="Differences")
    differences.locator('tr[data-path="START"]').wait_for()  # Start and Motor are globals
    assert differences.locator('tr[data-path="START"] td').all_inner_texts() == [
        "START",
        "FALSE",
        "→",
        "TRUE",
    ]
    assert differences.locator('tr[data-path="MOTOR"] td').all_inner_texts() == [
        "MOTOR",
        "FALSE",
        "→",
        "TRUE",
    ]
    page.get_by_label("Comparison").filter(
        has_text=re.compile(r"^\d+ variables differ between scan 2 and scan 6$")
    ).wait_for()

    forward = timeline.get_by_role("button", name="▶")
    forward.click()
    banner.filter(has_text="Viewing scan 3 (history)").wait_for()
    _coil(page, "off")
    forward.click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")  # Start was written before scan 4: the seal-in holds from there

    slider.focus()
    page.keyboard.press("ArrowLeft")  # the arrow keys step one scan
    banner.filter(has_text="Viewing scan 3 (history)").wait_for()
    _coil(page, "off")

    mark = timeline.get_by_role("button", name="scan 4: write")  # the timeline marks the write's scan
    assert mark.get_attribute("data-mark-scan") == "4"
    mark.click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")

    page.get_by_role("button", name="Run", exact=True).click()  # the live simulation goes on; the view stays
    page.get_by_role("status", name="Online state").filter(has_text="Online · running").wait_for()
    page.wait_for_function("() => Number(document.querySelector('[aria-label=\"Scan history\"] input')?.max) > 10")
    assert scan.inner_text() == "4"
    assert banner.inner_text().startswith("Viewing scan 4 (history)")

    timeline.get_by_role("button", name="Live").click()
    banner.wait_for(state="detached")
    _coil(page, "on")
    page.wait_for_function("() => Number(document.querySelector('[data-testid=scan-count]').textContent) > 10")

    # Find: the previous scan where Motor became TRUE is scan 4; Start changed in no scan after it.
    page.get_by_role("button", name="Stop", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    timeline.get_by_label("Find in history").fill("Motor")
    timeline.get_by_label("Find what").select_option("became TRUE")
    timeline.get_by_role("button", name="Previous").click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")
    timeline.get_by_label("Find in history").fill("Start")
    timeline.get_by_label("Find what").select_option("changed")
    timeline.get_by_role("button", name="Next").click()
    page.get_by_role("status", name="History search").filter(has_text="no scan after 4 in the history").wait_for()

    # the session as a file ladderlab replay takes: one write, at scan 3 (the fourth scan), six scans so far
    with page.expect_download() as download:
        timeline.get_by_role("link", name="Download recording").click()
    recording = json.loads(Path(download.value.path()).read_text())
    assert recording["format"] == "ladderlab-recording" and recording["scans"] > 10  # it ran meanwhile
    assert [(line["scan"], line["kind"], line["path"]) for line in recording["inputs"]] == [(3, "write", "START")]

    # Continue from scan 2 (Motor off): the simulation takes that state, a new branch is live
    slider.fill("2")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    page.get_by_role("button", name="Continue from here").click()
    banner.wait_for(state="detached")
    timeline.get_by_label("History kept").filter(has_text="branch 2 live").wait_for()
    scan.filter(has_text=re.compile("^2$")).wait_for()
    _coil(page, "off")
    cycle.click()
    scan.filter(has_text=re.compile("^3$")).wait_for()
    _coil(page, "off")  # this branch never had the write of Start


def test_the_timeline_marks_the_scan_a_breakpoint_halted_in(page, server):
    """Issue 23 item 3: a breakpoint on network 2 halts the third scan; once that scan completes, the timeline
    marks it as a breakpoint hit (its own colour), and a click on the mark shows that scan; a force before scan 5
    marks that scan as an input."""
    scan, cycle = _online_motor(page, server)
    for number in (1, 2):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
    page.get_by_role("button", name="Toggle breakpoint on network 2").click()
    cycle.click()
    page.get_by_role("region", name="Debugging").get_by_text("Halted at MAIN, network 2").wait_for()
    page.get_by_role("button", name="Toggle breakpoint on network 2").click()
    cycle.click()  # the rest of the halted scan
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    scan.filter(has_text=re.compile("^3$")).wait_for()
    cycle.click()
    scan.filter(has_text=re.compile("^4$")).wait_for()

    timeline = page.get_by_role("group", name="Scan history")
    mark = timeline.get_by_role("button", name="scan 3: breakpoint")
    mark.wait_for()
    assert mark.get_attribute("class") == "history-mark breakpoint"
    mark.click()
    page.get_by_role("status", name="History view").filter(has_text="Viewing scan 3 (history)").wait_for()

    start = page.locator('g.ld-element[data-id="start"]')  # a force (F7) before scan 5: marked as an input
    double_click_online(start)
    start.locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("F7")
    cycle.click()
    forced = timeline.get_by_role("button", name="scan 5: force")
    forced.wait_for()
    assert forced.get_attribute("class") == "history-mark"


def test_the_trace_chart_and_the_timeline_move_together(page, server):
    """Issue 23 item 3: Motor traced over six single cycles (off in scans 1-3, on from scan 4, Start written
    before it); a click on the chart's second sample shows scan 2 from the history (the coil off, the legend
    FALSE), and the timeline moved to scan 5 puts the chart's cursor on scan 5's sample (legend TRUE)."""
    scan, cycle = _online_motor(page, server)
    page.get_by_role("tab", name="Trace").click()
    page.get_by_label("Variable to trace").fill("Motor")
    page.keyboard.press("Enter")
    page.get_by_role("button", name="Start trace").click()
    status = page.get_by_role("status", name="Trace state")
    status.filter(has_text="Recording").wait_for()
    _start_written_before_scan_4(page, scan, cycle)
    status.filter(has_text="Recording · 6 samples").wait_for()
    _coil(page, "on")

    plot = page.locator(".trace-plot .u-over")
    box = plot.bounding_box()
    plot.click(position={"x": box["width"] * 1 / 5, "y": box["height"] / 2})  # the 2nd of 6 samples: scan 2
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    _coil(page, "off")
    chart = page.locator(".trace-plot")
    motor = chart.locator(".u-legend tr.u-series", has_text=re.compile("MOTOR", re.I)).locator(".u-value")
    page.wait_for_function("() => document.querySelector('.trace-plot')?.dataset.viewingScan === '2'")
    motor.filter(has_text=re.compile("^FALSE$")).wait_for()

    slider = page.get_by_role("group", name="Scan history").get_by_role("slider", name="Scan")
    slider.fill("5")
    banner.filter(has_text="Viewing scan 5 (history)").wait_for()
    page.wait_for_function("() => document.querySelector('.trace-plot')?.dataset.viewingScan === '5'")
    motor.filter(has_text=re.compile("^TRUE$")).wait_for()


def test_the_timeline_marks_the_scan_a_trace_trigger_fired_at(page, server):
    """Issue 23 item 3: a trace of Motor triggered on its rising edge; Start is written before scan 4, so Motor
    rises at the end of scan 4 and the trace says so; the timeline marks scan 4 in the trigger's colour (a trigger
    outranks the write of the same scan), and a click on the mark shows scan 4 with the coil on."""
    scan, cycle = _online_motor(page, server)
    page.get_by_role("tab", name="Trace").click()
    page.get_by_label("Variable to trace").fill("Motor")
    page.keyboard.press("Enter")
    page.get_by_label("Trigger variable").fill("Motor")
    page.get_by_label("Trigger condition").select_option("rising")
    page.get_by_role("button", name="Start trace").click()
    status = page.get_by_role("status", name="Trace state")
    status.filter(has_text="Waiting for the trigger").wait_for()
    _start_written_before_scan_4(page, scan, cycle)
    status.filter(has_text="triggered at scan 4").wait_for()

    timeline, mark = _the_only_mark(page, 4, "history-mark trigger", "scan 4: trigger, write")  # none in 1-3, 5, 6
    mark.click()
    page.get_by_role("status", name="History view").filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")


def _the_only_mark(page, scan: int, colour: str, label: str):
    """The timeline and its one mark, which is at ``scan``, of the class ``colour``, named ``label``."""
    timeline = page.get_by_role("group", name="Scan history")
    mark = timeline.locator(f'.history-mark[data-mark-scan="{scan}"]')
    mark.wait_for()
    assert mark.get_attribute("class") == colour
    assert mark.get_attribute("aria-label") == label
    assert timeline.locator(".history-mark").count() == 1
    return timeline, mark


def _halted_networks(page) -> list[str]:
    return page.eval_on_selector_all("svg.ld-network.ld-halted", "els => els.map(e => e.dataset.network)")


def test_step_through_a_past_scan_network_by_network(page, server):
    """Issue 23 item 3 ("one network within a scan"): scan 4 (the first after Start was written) shown, then
    stepped through (and one network back and forth: Step back, the arrow keys in the stepping group): before network 1 runs, the Motor coil has not run in this scan (drawn as not executed) and network 1 is
    marked; one step later network 2 is marked and the seal-in has switched the coil on; the steps go on through
    networks 3 and 4, the lines of the ST block Blinker that network 4 calls and the FBD program Scaling's network
    (each shown in its editor, the point marked), and the last step ends the scan; "Whole scan" shows scan 4 complete again. The live simulation and its history are not changed: scan 5
    still shows the coil on, and the counter of the live scans stays at 6."""
    scan, cycle = _online_motor(page, server)
    _start_written_before_scan_4(page, scan, cycle)
    timeline = page.get_by_role("group", name="Scan history")
    timeline.get_by_role("slider", name="Scan").fill("4")
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")

    stepping = page.get_by_role("group", name="Step through the scan")
    point = stepping.get_by_label("Step point")
    stepping.get_by_role("button", name="Step into this scan").click()
    point.filter(has_text="Scan 4, halted before MAIN, network 1").wait_for()
    page.wait_for_function("() => document.querySelector('svg.ld-network.ld-halted')?.dataset.network === 'seal_in'")
    page.wait_for_function(  # not run yet in this scan: drawn neither energised nor off
        "() => { const c = document.querySelector('g.ld-coil[data-id=motor]')?.classList;"
        " return c && !c.contains('ld-on') && !c.contains('ld-off'); }"
    )
    assert scan.inner_text() == "4"
    page.screenshot(path=str(ARTIFACTS / "history-step-network-1.png"))

    stepping.get_by_role("button", name="Next step").click()
    point.filter(has_text="Scan 4, halted before MAIN, network 2").wait_for()
    page.wait_for_function("() => document.querySelector('svg.ld-network.ld-halted')?.dataset.network === 'run_timer'")
    _coil(page, "on")  # network 1 ran: Start OR Motor, AND NOT Stop
    stepping.get_by_role("button", name="Step back").click()  # back one network: the coil not run yet again
    point.filter(has_text="Scan 4, halted before MAIN, network 1").wait_for()
    page.wait_for_function("() => document.querySelector('svg.ld-network.ld-halted')?.dataset.network === 'seal_in'")
    stepping.get_by_role("button", name="Next step").press("ArrowRight")  # the keys of the stepping group: forth
    point.filter(has_text="Scan 4, halted before MAIN, network 2").wait_for()
    _coil(page, "on")
    stepping.get_by_role("button", name="Next step").press("ArrowLeft")  # and back
    point.filter(has_text="Scan 4, halted before MAIN, network 1").wait_for()
    stepping.get_by_role("button", name="Next step").click()
    point.filter(has_text="Scan 4, halted before MAIN, network 2").wait_for()
    points = []
    for _ in range(40):  # the rest of the scan
        text = point.inner_text()
        if text == "Scan 4 ran to its end":
            break
        points.append(text.removeprefix("Scan 4, halted before "))
        if text.endswith("SCALING, network 1"):  # the FBD program, shown in its editor with the network marked
            page.locator('.fbd-network.fbd-network-halted[data-network="speed"]').wait_for()
        stepping.get_by_role("button", name="Next step").click()
        page.wait_for_function(
            "(text) => document.querySelector('[aria-label=\"Step point\"]')?.textContent !== text", arg=text
        )
    assert points == [
        "MAIN, network 2",
        "MAIN, network 3",
        "MAIN, network 4",
        *[f"BLINKER (MAIN.BLINK), line {line}" for line in (1, 2, 3, 4)],  # the ST block network 4 calls
        "SCALING, network 1",  # the task's second program, in FBD
    ]
    assert point.inner_text() == "Scan 4 ran to its end"
    assert stepping.get_by_role("button", name="Next step").is_disabled()
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^Main")).click()
    _coil(page, "on")  # the steps showed Blinker and Scaling in their editors; Main at the scan's end
    assert _halted_networks(page) == []

    stepping.get_by_role("button", name="Whole scan").click()
    point.filter(has_text="Step through scan 4").wait_for()
    timeline.get_by_role("button", name="▶").click()
    banner.filter(has_text="Viewing scan 5 (history)").wait_for()
    _coil(page, "on")
    timeline.get_by_role("button", name="Live").click()
    banner.wait_for(state="detached")
    scan.filter(has_text=re.compile("^6$")).wait_for()


def _start_written_before_scan_4(page, scan, cycle) -> None:
    """Three single cycles, Start prepared TRUE and written (Ctrl+F7: before the next scan), three more cycles."""
    _cycles(page, scan, cycle, (1, 2, 3))
    start = page.locator('g.ld-element[data-id="start"]')
    double_click_online(start)
    start.locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("Control+F7")
    _cycles(page, scan, cycle, (4, 5, 6))


def _st_project(name: str, declarations: str, body: str, panels: list | None = None) -> dict:
    main = {"name": "Main", "kind": "program", "language": "st", "declarations": declarations, "body": body}
    return {"name": name, "pous": [main], "panels": panels or []}


def _cycles(page, scan, cycle, numbers) -> None:
    """Single cycles, each awaited until the scan counter shows its number."""
    for number in numbers:
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()


def test_the_timeline_marks_the_scan_that_ended_with_a_runtime_error(page, server):
    """Issue 23 item 3 (marks for runtime errors): Main counts its scans and divides 100 by Divisor; Divisor is
    written 0 from the watch list after scan 3, so scan 4 divides by zero and the simulation faults. The timeline
    marks scan 4 in the error colour (an error outranks the write of the same scan), and a click on the mark shows
    scan 4's values: Count 4, Divisor 0; scan 2 shows Count 2, Divisor 1, Result 100."""
    declarations = "VAR\n    Count : INT;\n    Divisor : INT := 1;\n    Result : INT;\nEND_VAR"
    store_project(server, _st_project("divide", declarations, "Count := Count + 1;\nResult := 100 / Divisor;"))
    page.goto(server)
    open_pou(page, "divide", "Main")
    go_online(page, run=False)
    scan, cycle = page.get_by_test_id("scan-count"), page.get_by_role("button", name="Single cycle")
    count, divisor, result = (watch(page, path) for path in ("Main.Count", "Main.Divisor", "Main.Result"))
    _cycles(page, scan, cycle, (1, 2, 3))
    result.filter(has_text=re.compile("^100$")).wait_for()
    page.get_by_label("New value for Main.Divisor").fill("0")
    page.get_by_role("region", name="Panels").locator('tr[data-path="MAIN.DIVISOR"]').get_by_role(
        "button", name="Write"
    ).click()
    cycle.click()  # scan 4 divides by zero
    page.get_by_role("status", name="Online state").filter(has_text="faulted").wait_for()
    count.filter(has_text=re.compile("^4$")).wait_for()

    timeline, mark = _the_only_mark(page, 4, "history-mark error", "scan 4: error, write")  # none in scans 1 to 3

    slider = timeline.get_by_role("slider", name="Scan")
    slider.fill("2")
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    count.filter(has_text=re.compile("^2$")).wait_for()
    divisor.filter(has_text=re.compile("^1$")).wait_for()
    result.filter(has_text=re.compile("^100$")).wait_for()
    mark.click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    count.filter(has_text=re.compile("^4$")).wait_for()
    divisor.filter(has_text=re.compile("^0$")).wait_for()
    page.screenshot(path=str(ARTIFACTS / "history-error-mark.png"))


@pytest.fixture
def small_history_server(tmp_path: Path, chromium_path: str) -> Iterator[str]:
    """A server whose simulations keep 1 MB of scan history each (``--history-mb 1``)."""
    live = LiveServer(tmp_path / "small", tmp_path / "small-server.log", "--history-mb", "1")
    try:
        yield live.start().url
    finally:
        live.stop()


def _info(server: str, simulation: str) -> dict:
    with urllib.request.urlopen(f"{server}/api/simulations/{simulation}", timeout=30) as response:
        return json.load(response)


def test_the_timeline_says_from_which_scan_history_is_available_once_the_oldest_is_dropped(small_history_server, page):
    """Issue 23 item 1 ("the oldest history is dropped first and the UI says from which scan history is available"):
    a server with 1 MB of history per simulation runs a program whose 20,000 LREALs change every scan (pseudo-random: a
    checkpoint hardly compresses and takes a good part of the budget); within a few hundred scans the oldest
    checkpoints are dropped (seen: history from scan 32 after 203 scans). Stopped, the
    timeline says "from scan N" with N the first scan the server reports (GET /api/simulations/ID), N > 1, the
    slider starts at N, and the back button is disabled there."""
    server = small_history_server
    declarations = "VAR\n    Noise : ARRAY[1..20000] OF LREAL;\n    I : DINT;\n    Seed : LREAL := 0.5;\nEND_VAR"
    body = "FOR I := 1 TO 20000 DO\n    Seed := Seed * 3.9 * (1.0 - Seed);\n    Noise[I] := Seed;\nEND_FOR;"
    store_project(server, _st_project("big", declarations, body))
    page.goto(server)
    open_pou(page, "big", "Main")
    go_online(page, run=True)
    timeline = page.get_by_role("group", name="Scan history")
    recording = timeline.get_by_role("link", name="Download recording").get_attribute("href")
    simulation = re.fullmatch(r"/api/simulations/([^/]+)/recording", recording or "").group(1)
    page.wait_for_function(
        "() => Number(document.querySelector('[aria-label=\"Scan history\"] input')?.min) > 1", timeout=120_000
    )
    page.get_by_role("button", name="Stop", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()

    history = _info(server, simulation)["history"]
    first = history["first"]
    assert first > 1 and history["budget_bytes"] == 1024 * 1024
    expect(timeline.get_by_label("History kept")).to_have_text(f"from scan {first}")
    slider = timeline.get_by_role("slider", name="Scan")
    assert slider.get_attribute("min") == str(first)
    slider.fill(str(first))
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text=f"Viewing scan {first} (history)").wait_for()
    expect(timeline.get_by_role("button", name="◀")).to_be_disabled()  # no scan before the first one kept
    slider.focus()
    page.keyboard.press("ArrowLeft")
    page.keyboard.press("Home")
    expect(slider).to_have_value(str(first))
    assert banner.inner_text().startswith(f"Viewing scan {first} (history)")


def test_an_operator_panel_shows_the_past_scan_while_it_is_viewed(page, server):
    """Issue 23 item 2 ("the watch list and panels show exactly what that scan computed"): the panel Desk's lamp
    shows Main.Lamp (Count >= 3) and its numeric display Main.Count; after five single cycles they show 5 and on;
    scan 2 viewed, they show 2 and off; back to live, 5 and on again."""
    desk = {
        "name": "Desk",
        "widgets": [
            {"type": "lamp", "id": "lamp1", "x": 20, "y": 20, "w": 30, "h": 30, "bind": "Main.Lamp"},
            {"type": "numeric_display", "id": "count1", "x": 80, "y": 20, "w": 120, "h": 30, "bind": "Main.Count"},
        ],
    }
    declarations = "VAR\n    Count : INT;\n    Lamp : BOOL;\nEND_VAR"
    store_project(server, _st_project("desk", declarations, "Count := Count + 1;\nLamp := Count >= 3;", [desk]))
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^desk")).click()
    page.get_by_role("heading", name="desk").wait_for()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name=re.compile("^Desk")).filter(has_text="HMI").click()
    page.locator('svg.hmi-canvas[data-panel="Desk"]').wait_for()
    go_online(page, run=False)
    scan, cycle = page.get_by_test_id("scan-count"), page.get_by_role("button", name="Single cycle")
    _cycles(page, scan, cycle, (1, 2, 3, 4, 5))
    display = page.locator('[data-widget="count1"] [data-text]').first
    expect(display).to_have_attribute("data-text", "5")
    expect_on(page, "lamp1")

    timeline = page.get_by_role("group", name="Scan history")
    timeline.get_by_role("slider", name="Scan").fill("2")
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    expect(display).to_have_attribute("data-text", "2")
    expect_on(page, "lamp1", False)
    page.screenshot(path=str(ARTIFACTS / "history-panel-scan-2.png"))

    timeline.get_by_role("button", name="Live").click()
    banner.wait_for(state="detached")
    expect(display).to_have_attribute("data-text", "5")
    expect_on(page, "lamp1")
