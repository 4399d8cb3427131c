"""The scan history's bar fits the window at 1024x768 (issue 23): with the project list and the project tree
open and the simulation online, every control of the bar (step buttons, slider, marks, Live, find field and its
buttons, Download recording) lies inside the viewport, the toolbar does not scroll sideways, and the same holds
while a past scan is shown (the banner, the comparison). Before, the bar overflowed and cut off "Next"
(tests/browser/test_walkthrough.py's screenshot). Screenshot: tests/browser/artifacts/history-1024x768.png."""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import double_click_online, go_online, open_pou

pytestmark = pytest.mark.browser

WIDTH, HEIGHT = 1024, 768


def _outside(page, selector: str) -> list[str]:
    """The visible controls under ``selector`` whose box is not wholly inside the viewport (name and box)."""
    return page.evaluate(
        """([selector, width, height]) => {
            const out = [];
            for (const el of document.querySelectorAll(selector)) {
                const box = el.getBoundingClientRect();
                if (box.width === 0 && box.height === 0) continue; // not shown
                if (box.left < 0 || box.top < 0 || box.right > width || box.bottom > height)
                    out.push(`${el.tagName} ${el.getAttribute('aria-label') || el.textContent.trim()}: ` +
                             `${box.left}..${box.right} x ${box.top}..${box.bottom}`);
            }
            return out;
        }""",
        [selector, WIDTH, HEIGHT],
    )


CONTROLS = ".history-bar button, .history-bar input, .history-bar select, .history-bar a"


def test_every_control_of_the_history_bar_is_inside_the_window_at_1024x768(page, server):
    page.set_viewport_size({"width": WIDTH, "height": HEIGHT})
    page.goto(server)
    open_pou(page, "motor", "Main")
    assert page.get_by_role("navigation", name="Projects").is_visible()
    assert page.get_by_role("navigation", name="Project tree").is_visible()
    page.locator('g.ld-element[data-id="motor"]').wait_for()
    go_online(page, run=False)
    scan = page.get_by_test_id("scan-count")
    cycle = page.get_by_role("button", name="Single cycle")
    start = page.locator('g.ld-element[data-id="start"]')
    for number in (1, 2):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
    double_click_online(start)
    start.locator(".ld-prepared").filter(has_text="<TRUE>").wait_for()  # (Ctrl+F7 before it writes nothing)
    page.keyboard.press("Control+F7")  # a write: the timeline gets a mark
    for number in (3, 4):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()

    timeline = page.get_by_role("group", name="Scan history")
    timeline.get_by_role("button", name="scan 3: write").wait_for()
    names = ["◀", "▶", "Live", "Previous", "Next"]
    for name in names:
        assert timeline.get_by_role("button", name=name, exact=True).is_visible(), name
    assert timeline.get_by_role("link", name="Download recording").is_visible()
    count = page.locator(CONTROLS).count()
    assert count >= 10  # 5 buttons, the slider, the mark, the find field and its select, the download link
    assert _outside(page, CONTROLS) == []
    toolbar = page.get_by_role("toolbar", name="Simulation")
    assert toolbar.evaluate("(el) => el.scrollWidth <= el.clientWidth")

    timeline.get_by_role("slider", name="Scan").fill("2")  # a past scan: the bar turns amber, the banner shows
    page.get_by_role("status", name="History view").filter(has_text="Viewing scan 2 (history)").wait_for()
    page.get_by_role("button", name="Show differences").click()
    page.get_by_role("table", name="Differences").wait_for()
    assert _outside(page, CONTROLS) == []
    assert _outside(page, ".history-banner button, .history-compare button, .history-compare input") == []
    page.screenshot(path=str(ARTIFACTS / "history-1024x768.png"))
