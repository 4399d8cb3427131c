"""The dark theme (issue 22 item 7): the header's switch turns it on, it is kept after a reload, and every
view stays readable. Readability is measured, not eyeballed: the WCAG 2 contrast ratio between a text's
colour (or a diagram line's stroke) and the background it is drawn on, at least 4.5:1 for text and 3:1
for the diagram's lines (WCAG 2.1, 1.4.3 and 1.4.11). Screenshots of each view are kept as artifacts."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import store_project
from .test_layout import BLOCKS

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "dark",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR Start : BOOL; Motor : BOOL; END_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "label": "Seal",
                        "elements": [
                            {"type": "contact", "id": "c1", "var": "Start"},
                            {"type": "coil", "id": "q1", "var": "Motor"},
                        ],
                    }
                ]
            },
        },
        {
            "name": "Text",
            "kind": "program",
            "language": "st",
            "declarations": "VAR n : INT; END_VAR",
            "body": "n := n + 1; (* count *)",
        },
        BLOCKS,
    ],
}

# The lowest contrast among the elements a selector matches: the colour each is drawn in against the first
# opaque background behind it, as WCAG 2 defines the ratio (relative luminance of linearised sRGB).
CONTRAST = """([selector, property]) => {
  const elements = [...document.querySelectorAll(selector)];
  if (!elements.length) return null;
  const rgb = (text) => (text.match(/[\\d.]+/g) || []).map(Number);
  const ratio = (element) => {
  const fg = rgb(getComputedStyle(element)[property]);
  let node = element, bg = null;
  while (node && node.nodeType === 1) {
    const c = rgb(getComputedStyle(node).backgroundColor);
    if (c.length === 3 || (c.length === 4 && c[3] === 1)) { bg = c; break; }
    node = node.parentElement;
  }
  bg = bg || rgb(getComputedStyle(document.documentElement).backgroundColor);
  const lum = ([r, g, b]) => [r, g, b].map((v) => { v /= 255; return v <= 0.03928 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4; })
    .reduce((sum, v, i) => sum + v * [0.2126, 0.7152, 0.0722][i], 0);
  const [l1, l2] = [lum(fg), lum(bg)].sort((a, b) => b - a);
  return (l1 + 0.05) / (l2 + 0.05);
  };
  return Math.min(...elements.map(ratio));
}"""


def contrast(page, selector: str, prop: str = "color") -> float:
    ratio = page.evaluate(CONTRAST, [selector, prop])
    assert ratio is not None, f"{selector} is not on the page"
    return ratio


def test_the_dark_theme_is_kept_and_every_view_stays_readable(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^dark")).click()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name=re.compile("^Main")).click()
    page.locator("g.ld-element").first.wait_for()
    light_background = page.evaluate("getComputedStyle(document.documentElement).backgroundColor")

    switch = page.get_by_role("button", name="Dark theme")
    expect(switch).to_have_attribute("aria-pressed", "false")
    switch.click()
    expect(page.locator("html")).to_have_attribute("data-theme", "dark")
    page.reload()
    expect(page.locator("html")).to_have_attribute("data-theme", "dark")
    expect(page.get_by_role("button", name="Dark theme")).to_have_attribute("aria-pressed", "true")
    assert page.evaluate("getComputedStyle(document.documentElement).backgroundColor") != light_background

    tree.get_by_role("button", name=re.compile("^Main")).click()
    page.locator("g.ld-element").first.wait_for()
    page.screenshot(path=str(ARTIFACTS / "theme-dark-ld.png"))
    assert contrast(page, ".tree-item") >= 4.5
    assert contrast(page, ".workspace-bar h2") >= 4.5
    assert contrast(page, ".ld-editor .ld-network text") >= 4.5  # the operand names
    assert contrast(page, ".ld-editor .ld-rail", "stroke") >= 3
    assert contrast(page, ".panel-tabs button") >= 4.5
    assert contrast(page, ".simulation-bar .scan-info") >= 4.5

    tree.get_by_role("button", name=re.compile("^Text")).click()
    page.locator(".cm-content").first.wait_for()
    page.screenshot(path=str(ARTIFACTS / "theme-dark-st.png"))
    assert contrast(page, ".cm-content .cm-line") >= 4.5
    assert page.locator(".cm-content .cm-line span").count() >= 3  # the number, the comment, ...
    assert contrast(page, ".cm-content .cm-line span") >= 4.5  # every highlighted token

    tree.get_by_role("button", name=re.compile("^Blocks")).click()
    page.locator(".react-flow__node").first.wait_for()
    page.screenshot(path=str(ARTIFACTS / "theme-dark-fbd.png"))
    assert contrast(page, ".fbd-editor .react-flow__node") >= 4.5
    assert contrast(page, ".fbd-editor .react-flow__controls-button", "color") >= 4.5

    tree.get_by_role("button", name=re.compile("^Global variables")).click()
    page.get_by_role("region", name="Global variables editor").wait_for()
    page.screenshot(path=str(ARTIFACTS / "theme-dark-globals.png"))
    assert contrast(page, ".part-view") >= 4.5

    page.get_by_role("button", name="Dark theme").click()  # back to light, kept too
    page.reload()
    expect(page.locator("html")).to_have_attribute("data-theme", "light")
