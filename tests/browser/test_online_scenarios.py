"""Online mode as a CODESYS user tries it, one scenario per test, in the real Chromium (issue 17).

Each test drives the example project the server seeds (``motor``: Main in LD with the seal-in rung
``Motor := (Start OR Motor) AND NOT Stop``, a TON ``RunTimer`` (PT = T#5s) timing Motor, a CTU counting
starts, a Blinker FB ``Blink`` in ST; Scaling in FBD) against a real server, and fails on any page error
or console error (conftest.py); a test that provokes an error on purpose allows exactly that one.
Screenshots go to tests/browser/artifacts/ (README's docs/screenshot.png comes from test_walkthrough.py, its
docs/online-ton.png from online-ton.png here).
"""

from __future__ import annotations

import csv
import io
import json
import re
import time
import urllib.request

import pytest

from .conftest import ARTIFACTS
from .steps import double_click_online, go_online, open_pou, panel_tab, watch

pytestmark = pytest.mark.browser

TIME_LITERAL = re.compile(r"^T#(\d+s)?(\d+ms)?$")


def element(page, element_id: str):
    return page.locator(f'g.ld-element[data-id="{element_id}"]')


def badge(page, element_id: str):
    """The value badge under a contact or coil."""
    return element(page, element_id).locator(".ld-badge").first


def pin_value(page, box: str, pin: str):
    return element(page, box).locator(f'[data-pin-value="{pin}"] .ld-badge')


def scan_count(page) -> int:
    return int(page.get_by_test_id("scan-count").inner_text())


def simulations(server: str) -> list[dict]:
    with urllib.request.urlopen(f"{server}/api/simulations") as response:
        return json.load(response)


def open_main_online(page, server: str) -> None:
    """Main online and running, its values shown (as a user sees them before acting on them)."""
    page.goto(server)
    open_pou(page, "motor", "Main")
    element(page, "motor").wait_for()
    go_online(page)
    badge(page, "start").wait_for()


def test_log_force_release_and_tab_switches_never_blank_the_page(page, server):
    """The blocker of issue 17, and the online log (ON-15): force, open the log, switch tabs, release;
    each entry with its scan and virtual time, filtered by kind, exported as CSV."""
    open_main_online(page, server)
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    panels = panel_tab(page, "Online log")
    log = panels.get_by_role("list", name="Online log")
    log.get_by_text("forced STOP := TRUE").wait_for()
    panel_tab(page, "Watch list")
    panel_tab(page, "Online log")
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Release force").click()
    log.get_by_text("released the force on STOP").wait_for()
    panel_tab(page, "Diagnostics")
    panel_tab(page, "Online log")
    assert page.get_by_role("heading", name="motor").is_visible()
    assert page.get_by_role("application", name="Ladder diagram editor").is_visible()

    forced = log.locator('li[data-kind="force"]')
    assert re.fullmatch(r"#\d+", forced.locator(".log-scan").inner_text())
    assert re.fullmatch(r"0:00:\d\d\.\d{3}", forced.locator(".log-time").inner_text())
    # Filter by kind: without "force" the release stays listed.
    panels.get_by_label(re.compile(r"^force \(1\)")).uncheck()
    assert log.locator('li[data-kind="force"]').count() == 0
    assert log.locator('li[data-kind="release"]').count() == 1
    page.screenshot(path=str(ARTIFACTS / "online-log.png"))
    with page.expect_download() as download:
        panels.get_by_role("button", name="Export CSV").click()
    rows = list(csv.reader(io.StringIO(download.value.path().read_text())))
    assert rows[0] == ["scan", "time_ms", "kind", "level", "message", "where"]
    assert "force" not in [r[2] for r in rows[1:]] and "released the force on STOP" in [r[4] for r in rows[1:]]


def test_force_with_f7_release_all_and_the_forced_count(page, server):
    """Double-click prepares (a BOOL toggles), F7 forces, the simulation bar counts the forces, Alt+F7 and
    "Release all forces" release them; forced values are on orange with a red F everywhere they show."""
    open_main_online(page, server)
    forces = page.get_by_role("status", name="Active forces")
    page.locator("body").click(position={"x": 5, "y": 5})
    double_click_online(element(page, "start"))  # prepares TRUE
    element(page, "start").locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("F7")
    forces.filter(has_text="1 forced").wait_for()
    badge(page, "start").locator(".ld-forced-badge").wait_for()
    page.wait_for_function("() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-on')")
    value = watch(page, "Start")
    value.locator(".value-tag-forced .forced-mark").wait_for()
    page.screenshot(path=str(ARTIFACTS / "online-forced.png"))

    # Stop forced too, from the menu: the motor drops; Alt+F7 releases both.
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    forces.filter(has_text="2 forced").wait_for()
    page.wait_for_function("() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-off')")
    page.keyboard.press("Alt+F7")
    forces.filter(has_text="0 forced").wait_for()
    assert element(page, "stop").locator(".ld-forced-badge").count() == 0

    # Force again, release with the toolbar's button.
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    forces.filter(has_text="1 forced").wait_for()
    page.get_by_role("button", name="Release all forces").click()
    forces.filter(has_text="0 forced").wait_for()


def test_write_prepared_values_with_ctrl_f7_and_in_place(page, server):
    """Ctrl+F7 writes the prepared values (the program may overwrite them: a write is once); a value typed
    in the watch list is written in place."""
    open_main_online(page, server)
    double_click_online(element(page, "start"))
    element(page, "start").locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("Control+F7")
    page.wait_for_function("() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-on')")
    badge(page, "motor").filter(has_text="TRUE").wait_for()
    assert element(page, "start").locator(".ld-prepared").count() == 0  # written: nothing prepared any more

    watch(page, "StartCount").filter(has_text=re.compile(r"^1$")).wait_for()  # the rising edge of Start, once
    # A TIME nothing writes while the Blinker is disabled: written in place as an IEC literal.
    value = watch(page, "Main.Blink.Half.PT")
    value.filter(has_text=re.compile(r"^T#0s$")).wait_for()  # as the engine's TO_STRING writes it
    page.get_by_label("New value for Main.Blink.Half.PT").fill("T#7s250ms")
    page.get_by_role("region", name="Panels").locator('tr[data-path="MAIN.BLINK.HALF.PT"]').get_by_role(
        "button", name="Write"
    ).click()
    value.filter(has_text=re.compile(r"^T#7s250ms$")).wait_for()
    page.screenshot(path=str(ARTIFACTS / "online-written.png"))


def test_values_on_every_pin_and_the_instance_tree(page, server):
    """A TON box shows IN, PT, Q and ET, ET although nothing is wired to it, TIMEs as IEC literals; "Add to
    watch list" on the box gives a tree of readable members; the Variables view lists Main's instance."""
    open_main_online(page, server)
    double_click_online(element(page, "start"))
    element(page, "start").locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()
    page.keyboard.press("Control+F7")
    pin_value(page, "ton", "in:IN").filter(has_text="TRUE").wait_for()
    assert pin_value(page, "ton", "in:PT").get_attribute("data-value") == "T#5s"
    page.wait_for_function(
        """() => /^T#[1-4]s/.test(document.querySelector('[data-id="ton"] [data-pin-value="out:ET"] .ld-badge')
            ?.getAttribute('data-value') ?? '')"""
    )
    assert pin_value(page, "ton", "out:Q").get_attribute("data-value") == "FALSE"
    assert pin_value(page, "ctu", "out:CV").get_attribute("data-value") == "1"
    assert badge(page, "start").get_attribute("class") == "ld-badge ld-badge-true"
    page.locator('svg.ld-network[data-network="run_timer"]').screenshot(path=str(ARTIFACTS / "online-ton.png"))

    # The box's instance in the watch list: a tree whose members read as IEC text.
    element(page, "ton").locator(".ld-box-body").click(button="right")
    page.get_by_role("menuitem", name="Add to watch list").click()
    panels = panel_tab(page, "Watch list")
    panels.get_by_role("button", name="Expand MAIN.RUNTIMER").click()
    et = panels.locator('tr[data-path="MAIN.RUNTIMER.ET"] td.watch-value')
    et.locator(".value-tag").wait_for()
    assert TIME_LITERAL.match(et.inner_text()), et.inner_text()
    assert panels.locator('tr[data-path="MAIN.RUNTIMER.PT"] td.watch-value').inner_text() == "T#5s"
    assert panels.locator('tr[data-path="MAIN.RUNTIMER.PT"] td.watch-type').inner_text() == "TIME"
    assert "{" not in panels.locator("table").inner_text()  # no raw JSON anywhere
    page.screenshot(path=str(ARTIFACTS / "online-values.png"))

    # The Variables view: Main's variables, the Blinker instance expands into its own and its TON.
    page.get_by_role("tab", name="Variables").click()
    table = page.get_by_role("table", name="Variables of MAIN")
    table.get_by_role("button", name="Expand Main.Blink").click()
    table.get_by_role("button", name="Expand Main.Blink.Half").click()
    table.locator('tr[data-path="MAIN.BLINK.PERIOD"] td.watch-value').filter(has_text="T#500ms").wait_for()
    assert table.locator('tr[data-path="MAIN.BLINK.HALF.PT"] td.watch-type').inner_text() == "TIME"
    # In-place write from the Variables view.
    page.get_by_label("New value for Main.Lamp").fill("TRUE")
    table.locator('tr[data-path="MAIN.LAMP"]').get_by_role("button", name="Force").click()
    table.locator('tr[data-path="MAIN.LAMP"] .forced-mark').wait_for()
    page.screenshot(path=str(ARTIFACTS / "online-variables.png"))


def test_breakpoints_and_stepping_with_codesys_keys(page, server):
    """F9 sets a breakpoint on the selected network, F5 runs into it; F11 steps into the Blinker FB (its
    ST opens at line 1), F10 steps over its statements, Shift+F11 steps out: the scan ends and the
    next one halts at the breakpoint again; F10 over Main's last network halts in the task's next program,
    Scaling, and F10 over its last network ends the scan. Shift+F5 stops."""
    page.goto(server)
    open_pou(page, "motor", "Main")
    element(page, "running_on").locator(".ld-hit").click()
    page.keyboard.press("F9")  # on the selected element
    element(page, "running_on").get_by_role("img", name=re.compile("^Breakpoint on element")).wait_for()
    page.keyboard.press("F9")  # off again
    page.locator('svg.ld-network[data-network="lamp"] .ld-comment').click()  # the network selected
    page.keyboard.press("F9")
    page.get_by_role("img", name="Breakpoint on network 4").wait_for()
    assert element(page, "running_on").locator(".ld-breakpoint").count() == 0

    go_online(page, run=False)
    state = page.get_by_role("status", name="Online state")
    debug = page.get_by_role("region", name="Debugging")
    page.keyboard.press("F5")
    debug.get_by_text("Halted at MAIN, network 4").wait_for()
    halted_scan = scan_count(page)
    page.keyboard.press("F11")
    debug.get_by_text(re.compile(r"^Halted at Blinker \(MAIN\.BLINK\), line 1$", re.I)).wait_for()
    body = page.get_by_label("Blinker body")
    body.locator(".cm-halted-line").filter(has_text=re.compile(r"^IF NOT Enable.* THEN$")).wait_for()
    page.keyboard.press("F10")
    debug.get_by_text(re.compile(r"^Halted at Blinker \(MAIN\.BLINK\), line 2$", re.I)).wait_for()
    page.keyboard.press("F10")
    debug.get_by_text(re.compile(r"^Halted at Blinker \(MAIN\.BLINK\), line 3$", re.I)).wait_for()
    page.screenshot(path=str(ARTIFACTS / "online-step-into.png"))
    page.keyboard.press("Shift+F11")
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=halted_scan + 1
    )
    debug.get_by_text("Halted at MAIN, network 4").wait_for()
    page.keyboard.press("F10")  # over the last network of Main: the next program of the task, Scaling (CODESYS)
    debug.get_by_text(re.compile(r"^Halted at SCALING, network 1$", re.I)).wait_for()
    page.keyboard.press("F10")  # over the last network of the task's last program: this scan ends, the next halts
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=halted_scan + 2
    )
    debug.get_by_text("Halted at MAIN, network 4").wait_for()
    page.get_by_role("tab", name=re.compile("^Main")).click()
    page.get_by_role("img", name="Breakpoint on network 4").click()  # clear it (a click on the number)
    page.keyboard.press("F5")  # continue
    state.filter(has_text="Online · running").wait_for()
    page.keyboard.press("Shift+F5")
    state.filter(has_text="Online · stopped").wait_for()


def test_trace_setup_and_the_watch_list_come_back_after_a_reload_with_the_simulation(page, server):
    """The reconnect: a reload reopens the last project and its tabs, the watch list and the trace setup,
    and reattaches to the simulation, which kept running (no new compile, forces still active)."""
    open_main_online(page, server)
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    page.get_by_role("status", name="Active forces").filter(has_text="1 forced").wait_for()
    watch(page, "Motor").filter(has_text="FALSE").wait_for()
    panels = panel_tab(page, "Trace")
    panels.get_by_label("Variable to trace").fill("Main.RunTimer.ET")
    panels.get_by_label("Variable to trace").press("Enter")
    panels.get_by_text("Main.RunTimer.ET").first.wait_for()
    [before] = simulations(server)
    scanned = scan_count(page)

    page.reload()
    page.get_by_role("heading", name="motor").wait_for()
    page.get_by_role("status", name="Online state").filter(has_text="Online · running").wait_for()
    element(page, "stop").locator(".ld-forced-badge").wait_for()
    page.get_by_role("status", name="Active forces").filter(has_text="1 forced").wait_for()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) > n", arg=scanned
    )
    assert [s["id"] for s in simulations(server)] == [before["id"]]  # the same simulation, reattached
    panels = panel_tab(page, "Watch list (1)")
    panels.locator('tr[data-path="MOTOR"] td.watch-value').filter(has_text="FALSE").wait_for()
    panels = panel_tab(page, "Trace")
    panels.get_by_text("Main.RunTimer.ET").first.wait_for()
    page.screenshot(path=str(ARTIFACTS / "online-reattached.png"))


def test_a_failed_view_keeps_the_connection_the_watch_list_and_unsaved_edits(page, server, browser_errors):
    """Error boundaries: a panel that fails shows its error with "Reload this view"; the simulation, the
    diagram and the watch list carry on. Offline, a failing view keeps the unsaved edits and their draft."""
    # The online log fails to scroll its newest entry into view (a browser API misbehaving, as in issue 17).
    page.add_init_script(
        """window.__failLog = true;
        const scroll = Element.prototype.scrollIntoView;
        Element.prototype.scrollIntoView = function (...args) {
            if (window.__failLog && this.closest?.('.online-log')) throw new Error('scrollIntoView refused');
            return scroll.apply(this, args);
        };"""
    )
    browser_errors.allow("scrollIntoView refused|The above error occurred|online log|LogPanel")
    open_main_online(page, server)
    watch(page, "Motor").filter(has_text="FALSE").wait_for()
    panel_tab(page, "Online log")
    element(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    failed = page.get_by_role("alert", name="The online log failed")
    failed.wait_for()
    assert "scrollIntoView refused" in failed.inner_text()
    scanned = scan_count(page)
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) > n", arg=scanned
    )
    element(page, "stop").locator(".ld-forced-badge").wait_for()
    panel_tab(page, "Watch list (1)").locator('tr[data-path="MOTOR"]').wait_for()
    panel_tab(page, "Online log")
    page.get_by_role("alert", name="The online log failed").wait_for()  # still failed: the API still refuses
    page.screenshot(path=str(ARTIFACTS / "view-failed.png"))
    page.evaluate("window.__failLog = false")
    page.get_by_role("button", name="Reload this view").click()
    page.get_by_role("list", name="Online log").get_by_text("forced STOP := TRUE").wait_for()

    # Offline with unsaved edits: a view fails (the server answers its request with an unexpected shape).
    page.get_by_role("button", name="Go offline", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Offline").wait_for()
    element(page, "stop").locator(".ld-hit").click()
    page.keyboard.press("Delete")
    page.get_by_text("Unsaved changes in Main").wait_for()
    browser_errors.allow("Cannot read properties|StView|The ST view")
    page.route("**/export/st?pou=Main", lambda route: route.fulfill(json={"text": None, "source_map": []}))
    page.get_by_role("tab", name="View as ST").click()
    page.get_by_role("alert", name="The ST view of Main failed").wait_for()
    assert page.get_by_text("Unsaved changes in Main").is_visible()
    page.unroute("**/export/st?pou=Main")
    page.get_by_role("button", name="Reload this view").click()
    page.get_by_label("Exported ST").wait_for()
    page.get_by_role("tab", name="Diagram").click()
    assert element(page, "stop").count() == 0  # the edit is still there
    assert page.evaluate("() => JSON.parse(localStorage.getItem('ladderlab:draft:motor')).changed") == ["Main"]
    page.reload()
    page.get_by_text(re.compile("^Restored unsaved changes from")).wait_for()
    element(page, "motor").wait_for()
    assert element(page, "stop").count() == 0


def test_f5_never_reloads_and_check_has_its_own_key(page, server):
    """F5 (with any modifiers) never reloads the page, online or offline; build/check is Ctrl+Shift+B, and
    F7 (force) does not check."""
    page.goto(server)
    open_pou(page, "motor", "Main")
    element(page, "motor").wait_for()
    page.evaluate("window.__sameDocument = true")
    for key in ("F5", "Control+F5", "Shift+F5", "Alt+F5", "F7", "F11"):
        page.keyboard.press(key)
    time.sleep(0.5)
    assert page.evaluate("window.__sameDocument === true")
    assert page.get_by_role("tab", name="Diagnostics (0)").count() == 1
    page.keyboard.press("Control+Shift+B")
    page.get_by_text("No problems found").wait_for()
    go_online(page)
    page.keyboard.press("F5")
    page.keyboard.press("Control+F5")  # single cycle: stopped after one scan
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    assert page.evaluate("window.__sameDocument === true")
