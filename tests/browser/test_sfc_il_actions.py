"""An SFC action written in IL in a real browser against a real server (issue 24 item 2, SFC-02, ON-17).

The user adds the action Count in IL to a chart, associates it (N) with the initial step, opens it, types
``LD n / ADD 1 / ST n`` in the text editor, sets a breakpoint on line 3 (from the chart, the Breakpoints panel's
"Show in the editor" opens the action again) and runs: the first scan halts before line
3 of the action (n still 0) with the accumulator of lines 1 and 2 shown at their ends (0, then 1); Continue runs
the store and the next scan halts there again with n = 1. The page must log no error (conftest).
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, panel_tab, watch
from .test_sfc_actions import add_action, back_to_chart, open_action, open_chart
from .test_sfc_workflow import saved_pou

pytestmark = pytest.mark.browser


def accumulators(page) -> list[list]:
    """[line, accumulator shown at its end] for every line of the action's editor that shows one."""
    return page.evaluate(
        """() => [...document.querySelectorAll('[aria-label="Main action Count"] .cm-line')].flatMap((line, i) =>
            [...line.querySelectorAll('.cm-il-accumulator')].map((w) => [i + 1, w.textContent]))"""
    )


def test_an_il_action_is_written_run_online_and_halts_on_a_breakpoint_on_its_line(page, server):
    chart = [
        {"type": "step", "id": "s1", "name": "Init"},
        {"type": "transition", "id": "t1", "condition": "FALSE"},
        {"type": "jump", "id": "j1", "target": "Init"},
    ]
    editor = open_chart(page, server, "ilact", "VAR\n    n : INT;\nEND_VAR", chart, [])

    # A new action in IL, associated with Init (N); opened, it is the text editor: three IL lines typed.
    add_action(page, editor, "Count", "il", "Init")
    open_action(page, editor, "Count", "IL")
    text = page.get_by_label("Main action Count")
    text.click()
    for number, line in enumerate(("LD n", "ADD 1", "ST n")):
        if number:
            page.keyboard.press("Enter")
        page.keyboard.type(line)
    expect(text.locator(".cm-line")).to_have_count(3)

    # A breakpoint on line 3 (ST n), listed with the action it is in.
    line3 = text.locator(".cm-line").nth(2)
    gutter = page.locator(".cm-breakpoint-gutter").last
    gutter_box, line_box = gutter.bounding_box(), line3.bounding_box()
    page.mouse.click(gutter_box["x"] + gutter_box["width"] / 2, line_box["y"] + line_box["height"] / 2)
    panels = panel_tab(page, "Breakpoints")
    expect(panels.locator("tr.breakpoint-row")).to_have_text("Main action Count, line 3: ST n×")

    # Back on the chart, "Show in the editor" of the breakpoint opens the action it is in (issue 24 item 3).
    back_to_chart(page)
    panels.get_by_role("button", name=re.compile(r"^Main action Count, line 3")).click()
    page.get_by_role("navigation", name="SFC parts").get_by_text("Action Count (IL)").wait_for()
    expect(text.locator(".cm-line")).to_have_count(3)

    # Saved and compiled: the action is IL text; Run halts the first scan before line 3: n is still 0, the
    # accumulator after LD n is 0 and after ADD 1 is 1.
    n = watch(page, "Main.n")
    go_online(page, run=False)
    (action,) = saved_pou(server, "ilact", "Main")["body"]["actions"]
    assert (action["name"], action["language"], [line.strip() for line in action["body"].splitlines()]) == (
        "Count",
        "il",
        ["LD n", "ADD 1", "ST n"],
    )
    page.get_by_role("button", name="Run", exact=True).click()
    debug = page.get_by_role("region", name="Debugging")
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Count, line 3$", re.I))
    expect(line3).to_have_class(re.compile(r"\bcm-halted-line\b"))
    panel_tab(page, "Watch list")
    expect(n).to_have_text("0")
    page.wait_for_function(
        """() => [...document.querySelectorAll('[aria-label="Main action Count"] .cm-line')].slice(0, 2)
            .map((line) => line.querySelector('.cm-il-accumulator')?.textContent).join() === '0,1'"""
    )
    assert accumulators(page)[:2] == [[1, "0"], [2, "1"]]
    page.screenshot(path=str(ARTIFACTS / "sfc-action-il-halted.png"))

    # Continue: ST n stores 1; the next scan halts on line 3 again, n = 1.
    debug.get_by_role("button", name="Continue").click()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Count, line 3$", re.I))
    expect(n).to_have_text("1")
