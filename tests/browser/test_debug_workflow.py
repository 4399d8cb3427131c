"""A new user debugs the example ladder program in a real browser against a real server (issue 9,
"Debugging" and "Tests": set a breakpoint on an LD network, run, see it halt at that network, step
to the next network, continue).

The server seeds its empty workspace with the motor example (Main: seal-in, run timer, start
counter, lamp). The user clicks network number 2 to set a breakpoint (still there after a page
reload), watches Motor and StartCount, runs and sees the scan halt at network 2 (highlighted), presses
Start while halted,
steps network by network (the highlight moves; StartCount is counted mid-scan, at the halt),
continues into the next scan's halt where Motor is already on, disables the breakpoint in the
Breakpoints panel so the scan runs free, removes it, and finally a Single cycle from stopped
advances the scan counter by exactly one. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re
import time

import pytest

from .conftest import ARTIFACTS
from .steps import double_click_online, scan_count, settled_scan_count

pytestmark = pytest.mark.browser


def halted_networks(page) -> list[str]:
    return page.eval_on_selector_all("svg.ld-network.ld-halted", "els => els.map(e => e.dataset.network)")


def open_main(page) -> None:
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^motor")).click()
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^Main")).click()
    page.locator("svg.ld-network").nth(3).wait_for()


def test_breakpoint_halt_step_continue_disable_and_single_cycle(page, server):
    page.goto(server)
    open_main(page)

    # A breakpoint on network 2: click its number; a red dot appears there and the panel lists it.
    page.get_by_role("button", name="Toggle breakpoint on network 2").click()
    network2 = page.locator('svg.ld-network[data-network="run_timer"]')
    network2.get_by_role("img", name="Breakpoint on network 2").wait_for()
    panels = page.get_by_role("region", name="Panels")
    panels.get_by_role("tab", name="Breakpoints (1)").click()
    row = panels.locator("tr.breakpoint-row")
    assert row.inner_text().strip().startswith("Main network 2 MotorRunning after 5 s of Motor")

    # The breakpoint survives a page reload: the project opened again shows it on network 2 and in the panel.
    page.reload()
    open_main(page)
    network2.get_by_role("img", name="Breakpoint on network 2").wait_for()
    panels.get_by_role("tab", name="Breakpoints (1)").click()
    assert row.inner_text().strip().startswith("Main network 2 MotorRunning after 5 s of Motor")

    # Watch Motor and StartCount.
    panels.get_by_role("tab", name=re.compile("^Watch list")).click()
    for name in ("Motor", "StartCount"):
        panels.get_by_label("Variable path to watch").fill(name)
        panels.get_by_label("Variable path to watch").press("Enter")
    motor = panels.locator('tr[data-path="MOTOR"] td.watch-value')
    count = panels.locator('tr[data-path="STARTCOUNT"] td.watch-value')

    # Compile and run: the first scan halts before network 2, highlighted and named in the debug bar.
    page.get_by_role("button", name="Compile & simulate").click()
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    page.get_by_role("button", name="Run", exact=True).click()
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at MAIN, network 2").wait_for()
    state.filter(has_text="Online · halted").wait_for()
    assert halted_networks(page) == ["run_timer"]
    motor.filter(has_text="FALSE").wait_for()
    count.filter(has_text="0").wait_for()
    halted_scan = scan_count(page)
    page.screenshot(path=str(ARTIFACTS / "debug-halted.png"))

    # Start pressed while halted (writes act at once), then step: network 3 counts the rising edge
    # of Start within this scan, and StartCount shows it at the next halt.
    double_click_online(page.locator('g.ld-element[data-id="start"]'))  # prepares TRUE (CODESYS)
    page.keyboard.press("Control+F7")  # writes the prepared value
    debug.get_by_role("button", name="Step network").click()
    debug.get_by_text("Halted at MAIN, network 3").wait_for()
    assert halted_networks(page) == ["count_starts"]
    debug.get_by_role("button", name="Step network").click()
    debug.get_by_text("Halted at MAIN, network 4").wait_for()
    assert halted_networks(page) == ["lamp"]
    count.filter(has_text=re.compile(r"^1$")).wait_for()
    assert scan_count(page) == halted_scan  # still the same scan
    page.screenshot(path=str(ARTIFACTS / "debug-stepped.png"))

    # Continue (F5): the next scan halts at the breakpoint again; network 1 has run, Motor is on.
    page.keyboard.press("F5")
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=halted_scan + 1
    )
    debug.get_by_text("Halted at MAIN, network 2").wait_for()
    motor.filter(has_text="TRUE").wait_for()
    page.wait_for_function("() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-on')")

    # Disable the breakpoint in the panel: it stays listed (hollow dot), the scan runs free.
    panels.get_by_role("tab", name="Breakpoints (1)").click()
    panels.get_by_role("checkbox", name=re.compile("^Enable breakpoint Main, network 2")).uncheck()
    network2.get_by_role("img", name="Breakpoint on network 2 (disabled)").wait_for()
    debug.get_by_role("button", name="Continue").click()
    state.filter(has_text="Online · running").wait_for()
    running_from = scan_count(page)
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) > n + 5", arg=running_from
    )
    assert debug.count() == 0
    page.screenshot(path=str(ARTIFACTS / "debug-disabled.png"))
    panels.get_by_role("button", name=re.compile("^Remove breakpoint Main, network 2")).click()
    panels.get_by_text("No breakpoints.").wait_for()
    assert network2.locator(".ld-breakpoint").count() == 0

    # Stop, then Single cycle: exactly one more scan.
    page.get_by_role("button", name="Stop", exact=True).click()
    state.filter(has_text="Online · stopped").wait_for()
    before = settled_scan_count(page)
    page.get_by_role("button", name="Single cycle").click()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=before + 1
    )
    time.sleep(0.3)  # nothing else runs: the counter stays
    assert scan_count(page) == before + 1
    assert state.inner_text().endswith("stopped")
