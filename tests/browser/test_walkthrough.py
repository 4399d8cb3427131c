"""A first session at 1024x768 with the new face (issue 22 items 6 and 7), in the real Chromium: open the
motor example from "New from example", add a rung to its LD program with the keyboard (declaring the new
coil through the editor's prompt), save, compile and run, force Start from the diagram, watch the new coil
and trace it with Motor. What the scan computes is checked against the rung itself: Start forced TRUE seals
Motor in (Motor := (Start OR Motor) AND NOT Stop), and the new rung copies Motor to Busy, so Busy is TRUE in
the watch list and in the trace's last samples, energised in the diagram. The last screenshot is README's
(docs/screenshot.png, copied from tests/browser/artifacts/walkthrough-1024x768.png).
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import panel_tab, watch

pytestmark = pytest.mark.browser


def ld_element(page, element_id: str):
    return page.locator(f'g.ld-element[data-id="{element_id}"]')


def operand(page, kind: str, name: str):
    return page.locator(f"g.ld-element.ld-{kind}").filter(
        has=page.locator("g.ld-operand > text", has_text=re.compile(f"^{name}$"))
    )


def test_a_first_session_at_1024x768(page, server: str) -> None:
    page.set_viewport_size({"width": 1024, "height": 768})
    page.goto(server)
    page.get_by_role("button", name="New from example").click()
    form = page.get_by_role("form", name="New from example")
    form.get_by_label("Example", exact=True).select_option("motor")
    form.get_by_label("New project name").fill("tour")
    form.get_by_role("button", name="Create").click()
    page.get_by_role("heading", name="tour", exact=True).wait_for()
    page.get_by_role("button", name="Hide projects").click()
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^Main")).click()
    ld_element(page, "lamp_coil").wait_for()

    # Edit: a new rung under the lamp's, Busy := Motor, typed; Busy is declared from the editor's prompt.
    ld_element(page, "lamp_coil").locator(".ld-hit").click()
    page.keyboard.press("Control+Enter")
    for key, name in (("c", "Motor"), ("o", "Busy")):
        page.keyboard.press(key)
        page.get_by_role("combobox", name="Variable").press_sequentially(name)
        page.keyboard.press("Enter")
    page.get_by_role("button", name="Declare Busy", exact=True).click()
    operand(page, "coil", "Busy").wait_for()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()

    # Run, then force Start TRUE from the diagram (double-click prepares the value, F7 forces it).
    bar = page.get_by_role("toolbar", name="Simulation")
    bar.get_by_role("button", name="Compile & simulate").click()
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    bar.get_by_role("button", name="Run", exact=True).click()
    state.filter(has_text="Online · running").wait_for()
    ld_element(page, "start").locator(".ld-hit").dblclick()
    page.locator(".ld-prepared").filter(has_text="<TRUE>").first.wait_for()
    page.keyboard.press("F7")
    expect(page.get_by_role("status", name="Active forces")).to_have_text("1 forced")

    # Watch Busy: TRUE once Motor is sealed in; the new coil is drawn energised.
    watch(page, "Main.Busy").filter(has_text="TRUE").wait_for()
    busy = operand(page, "coil", "Busy")
    expect(busy).to_have_class(re.compile(r"\bld-on\b"))
    expect(busy.locator(".ld-badge").first).to_have_attribute("data-value", "TRUE")

    # Trace Motor and Busy from now on (no trigger): both TRUE in every sample taken after the force.
    panels = panel_tab(page, "Trace")
    for path in ("Motor", "Main.Busy"):  # Motor is a global of the example
        panels.get_by_label("Variable to trace").fill(path)
        page.keyboard.press("Enter")
    panels.get_by_label("Samples to keep").fill("50")
    panels.get_by_role("button", name="Start trace").click()
    page.wait_for_timeout(1000)  # samples arrive with the scans
    panels.get_by_role("radio", name="Table").check()
    rows = panels.locator("table tbody tr")
    rows.first.wait_for()
    last = rows.last.inner_text().split()
    assert last[-2:] == ["TRUE", "TRUE"], last
    panels.get_by_role("radio", name="Chart").check()
    page.locator(".trace-plot .u-over").wait_for()
    # More room for the chart: the panels' edge moved up by keyboard (four steps of 24 px).
    page.get_by_role("separator", name="Resize the panels").focus()
    for _ in range(4):
        page.keyboard.press("ArrowUp")
    page.screenshot(path=str(ARTIFACTS / "walkthrough-1024x768.png"))
