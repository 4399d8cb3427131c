"""Every bar fits the window (issue 22 item 7, "one compact toolbar row per editor", "a layout that works at
1024x768 and 1920x1080"): with the project list and the project tree open and a simulation running, in the light
and the dark theme, for the LD, FBD, SFC and ST editors, no control of a toolbar or tab row lies outside the
viewport or is clipped by its bar, neither the page nor a bar scrolls sideways, each toolbar is one row (its
visible controls share one top offset), and the editor (below its tabs) keeps at least 60 % of the height with
the bottom panels hidden. What does not fit goes into the bar's "More" menu (ui/OverflowBar.tsx), measured from
the bar's real width, and runs from there. Screenshots: tests/browser/artifacts/toolbar-fit-*.png."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, open_pou

pytestmark = pytest.mark.browser

#: The project: the motor example (Main in LD, Scaling in FBD, Blinker in ST) and an SFC program Seq.
SEQ = {
    "name": "Seq",
    "kind": "program",
    "language": "sfc",
    "declarations": "VAR go : BOOL; END_VAR",
    "body": {
        "chart": {
            "elements": [
                {"type": "step", "id": "s1", "name": "Init"},
                {"type": "transition", "id": "t1", "condition": "go"},
                {"type": "step", "id": "s2", "name": "Busy"},
                {"type": "transition", "id": "t2", "condition": "NOT go"},
                {"type": "jump", "id": "j1", "target": "Init"},
            ]
        },
        "actions": [],
        "transitions": [],
    },
}

#: Each editor kind: the POU, a control that shows once its editor is there.
EDITORS = {
    "ld": ("Main", 'g.ld-element[data-id="motor"]'),
    "fbd": ("Scaling", ".react-flow__node"),
    "sfc": ("Seq", "g.sfc-step"),
    "st": ("Blinker", ".cm-content"),
}

#: The bars whose controls must all lie inside the window, each one row.
TOOLBARS = '[role="toolbar"]'
TAB_ROWS = '.panel-tabs, .pou-modes, .tabs[role="tablist"]'
CONTROLS = "button, input, select, a, [role=status], .scan-info"


def _store(server: str) -> None:
    _request("POST", f"{server}/api/projects", {"name": "fit", "example": "motor"})
    document = _request("GET", f"{server}/api/projects/fit")
    project = document["project"]
    project["pous"].append(SEQ)
    _request("PUT", f"{server}/api/projects/fit", project, document["revision"])


def _problems(page, width: int, height: int) -> list[str]:
    """Every way a bar fails to fit: a control outside the window or outside its bar's box, a bar or the page
    that scrolls sideways, a toolbar whose visible controls do not share one top offset."""
    return page.evaluate(
        """([bars, rows, controls, width, height]) => {
            const problems = [];
            const name = (el) => `${el.tagName} "${(el.getAttribute('aria-label') || el.textContent).trim().slice(0, 40)}"`;
            const doc = document.documentElement;
            if (doc.scrollWidth > doc.clientWidth) problems.push(`the page scrolls sideways (${doc.scrollWidth})`);
            for (const bar of document.querySelectorAll(`${bars}, ${rows}`)) {
                const own = bar.getBoundingClientRect();
                if (own.width === 0) continue;
                const label = bar.getAttribute('aria-label') || bar.className;
                if (bar.scrollWidth > bar.clientWidth + 1)
                    problems.push(`${label} scrolls sideways: ${bar.scrollWidth} > ${bar.clientWidth}`);
                const tops = new Set();
                for (const el of bar.querySelectorAll(controls)) {
                    const box = el.getBoundingClientRect();
                    if (box.width === 0 || box.height === 0) continue;
                    if (getComputedStyle(el).visibility === 'hidden') continue;
                    if (el.closest('[role=menu]')) continue;
                    if (box.left < 0 || box.top < 0 || box.right > width + 0.5 || box.bottom > height + 0.5)
                        problems.push(`${label}: ${name(el)} outside the window ${box.left}..${box.right}`);
                    if (box.left < own.left - 0.5 || box.right > own.right + 0.5)
                        problems.push(`${label}: ${name(el)} clipped by its bar ${box.left}..${box.right} of ${own.left}..${own.right}`);
                    if (bar.matches(bars) && el.matches('button') && !el.closest('.history-bar'))
                        tops.add(Math.round(box.top + box.height / 2));
                }
                if (tops.size > 1) problems.push(`${label} is more than one row (button centres at ${[...tops]})`);
            }
            return problems;
        }""",
        [TOOLBARS, TAB_ROWS, CONTROLS, width, height],
    )


def _open_online(page, server: str, width: int, height: int, theme: str) -> None:
    page.set_viewport_size({"width": width, "height": height})
    page.add_init_script(f"localStorage.setItem('ladderlab:theme', '{theme}')")
    _store(server)
    page.goto(server)
    open_pou(page, "fit", "Main")
    page.locator(EDITORS["ld"][1]).first.wait_for()
    go_online(page)
    assert page.get_by_role("navigation", name="Projects").is_visible()
    assert page.get_by_role("navigation", name="Project tree").is_visible()
    expect(page.locator("html")).to_have_attribute("data-theme", theme)


@pytest.mark.parametrize("theme", ["light", "dark"])
@pytest.mark.parametrize("size", [(1024, 768), (1920, 1080)], ids=["1024x768", "1920x1080"])
def test_every_bar_is_one_row_inside_the_window_for_each_editor(page, server: str, size, theme: str) -> None:
    width, height = size
    _open_online(page, server, width, height, theme)
    tree = page.get_by_role("navigation", name="Project tree")
    for kind, (pou, shown) in EDITORS.items():
        tree.get_by_role("button", name=re.compile(f"^{pou}")).click()
        page.get_by_role("tab", name=pou, exact=True).wait_for()
        page.locator(shown).first.wait_for()
        page.get_by_role("status", name="Online state").filter(has_text="Online · running").wait_for()
        problems = _problems(page, width, height)
        assert problems == [], "\n".join([kind, str(width), theme, *problems])
        page.screenshot(path=str(ARTIFACTS / f"toolbar-fit-{kind}-{width}x{height}-{theme}.png"))
        # the editor below its view tabs keeps 60 % of the height with the panels hidden
        page.get_by_role("button", name="Hide panels").click()
        editor = page.locator(".pou-view").bounding_box()
        assert editor["height"] >= 0.6 * height, (kind, editor)
        assert _problems(page, width, height) == [], (kind, width, theme, "panels hidden")
        page.get_by_role("button", name="Show panels").click()


def _more(page, bar, name: str) -> list[str]:
    """Opens the bar's More menu ``name`` from the keyboard; the names of its entries (without their shortcuts)."""
    bar.get_by_role("button", name=name).focus()
    page.keyboard.press("Enter")
    menu = page.get_by_role("menu")
    menu.wait_for()
    return menu.locator("button > span").all_inner_texts()


def _shown(bar) -> list[str]:
    return [button.get_attribute("aria-label") or button.inner_text() for button in bar.get_by_role("button").all()]


def test_what_does_not_fit_is_in_more_and_runs_from_there_at_1024x768(page, server: str) -> None:
    page.set_viewport_size({"width": 1024, "height": 768})
    _store(server)
    page.goto(server)
    open_pou(page, "fit", "Main")
    page.locator('g.ld-element[data-id="start"] .ld-hit').click()  # network 1 selected
    toolbar = page.get_by_role("toolbar", name="LD editing")
    shown = _shown(toolbar)
    assert shown[-1] == "More tools"
    moved = _more(page, toolbar, "More tools")
    # every tool is in the row or in More, once; what is in More keeps its shortcut
    assert sorted(shown[:-1] + moved) == sorted(LD_TOOLS)
    assert "Contact" in shown and "Network comment…" in moved
    menu = page.get_by_role("menu")
    expect(menu.get_by_role("menuitem", name=re.compile("^Copy"))).to_contain_text("Ctrl+C")
    box = menu.bounding_box()
    assert box["x"] >= 0 and box["x"] + box["width"] <= 1024 and box["y"] + box["height"] <= 768, box
    page.screenshot(path=str(ARTIFACTS / "toolbar-fit-more-1024x768.png"))
    menu.get_by_role("menuitem", name=re.compile("^Network comment")).click()
    comment = page.get_by_label("Network comment", exact=True)
    expect(comment).to_be_focused()
    comment.fill("Seal-in")
    comment.press("Enter")
    expect(page.locator(".ld-editor")).to_contain_text("Seal-in")

    # the simulation bar's commands: online, what does not fit runs from its More menu too
    go_online(page)
    bar = page.get_by_role("toolbar", name="Simulation")
    moved = _more(page, bar, "More simulation commands")
    assert moved == ["Open recording…"]  # the run controls, the state and the figures stay in the row
    assert {"Check", "Compile & simulate", "Run", "Stop", "Single cycle", "Go offline"} <= set(_shown(bar))
    with page.expect_file_chooser() as chooser:
        page.get_by_role("menu").get_by_role("menuitem", name="Open recording…").click()
    assert not chooser.value.is_multiple()

    # the panel tabs: a panel whose tab is in More shows from there, and its tab joins the row
    tabs = page.get_by_role("tablist", name="Panel tabs")
    assert "Cross references" not in _shown(tabs)
    assert "Cross references" in _more(page, tabs, "More panels")
    page.get_by_role("menu").get_by_role("menuitem", name="Cross references").click()
    expect(tabs.get_by_role("tab", name="Cross references")).to_have_attribute("aria-selected", "true")
    assert _problems(page, 1024, 768) == []


#: The LD toolbar's tools, by name (README "LD editor"; the zoom percentage is the button "Zoom").
LD_TOOLS = [
    "Contact",
    "NC contact",
    "Coil",
    "Compare",
    "Box…",
    "Parallel branch",
    "Jump",
    "Return",
    "Next mode",
    "EN/ENO",
    "Delete",
    "New network below",
    "Duplicate network",
    "Move network up",
    "Move network down",
    "Network label…",
    "Network comment…",
    "Copy",
    "Cut",
    "Paste",
    "Undo",
    "Redo",
    "Zoom out",
    "Zoom",
    "Zoom in",
    "Zoom to fit",
    "Shortcuts",
]
