"""A first session at 1024x768 with the new face (issue 22 items 6 and 7), in the real Chromium: open the
motor example from "New from example", add a rung to its LD program with the keyboard (declaring the new
coil through the editor's prompt), save, compile and run, force Start from the diagram, watch the new coil
and trace it with Motor. What the scan computes is checked against the rung itself: Start forced TRUE seals
Motor in (Motor := (Start OR Motor) AND NOT Stop), and the new rung copies Motor to Busy, so Busy is TRUE in
the watch list and in the trace's last samples, energised in the diagram. The last screenshot is README's
(docs/screenshot.png, copied from tests/browser/artifacts/walkthrough-1024x768.png). The second walkthrough
builds a whole project from an empty one through the UI and steps it scan by scan (issue 22's "Done when").
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import double_click_online, new_pou, new_project, panel_tab, watch

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
    double_click_online(ld_element(page, "start"))
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


def _replace_text(page, label: str, text: str) -> None:
    page.get_by_label(label).focus()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(text)


def _single_cycles(page, count: int) -> None:
    for _ in range(count):
        before = int(page.get_by_test_id("scan-count").inner_text())
        page.get_by_role("button", name="Single cycle").click()
        page.wait_for_function(
            "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=before + 1
        )


def test_a_project_built_from_empty_at_1024x768(page, server: str) -> None:
    """Issue 22's walkthrough: from an empty project, entirely through the UI at 1024x768, a global variable
    list, a STRUCT type, three ST programs using the global, a task running two of them; the global renamed in
    the three POUs at once, the third POU deleted; compiled and stepped scan by scan. Expected values from the
    programs: Main counts Velocity up and notes Velocity > 3 in its STRUCT, Reset (after Main in the task) sets
    it back to 0 once it exceeds 5."""
    page.set_viewport_size({"width": 1024, "height": 768})
    new_project(page, server, "plant")
    tree = page.get_by_role("navigation", name="Project tree")

    tree.get_by_role("button", name="Global variables").click()
    globals_editor = page.get_by_role("region", name="Global variables editor")
    globals_editor.get_by_role("button", name="Add variable").click()
    globals_editor.get_by_label("Name of NewVar").fill("Speed")
    globals_editor.get_by_label("Type of Speed").fill("INT")

    tree.get_by_role("button", name="Types").click()
    types_editor = page.get_by_role("region", name="Types editor")
    types_editor.get_by_label("Type name").fill("Reading")
    types_editor.get_by_label("Type kind").select_option(label="STRUCT")
    types_editor.get_by_role("button", name="Add type").click()  # one member: Member : BOOL

    programs = {
        "Main": ("VAR\n    r : Reading;\nEND_VAR", "Speed := Speed + 1;\nr.Member := Speed > 3;"),
        "Reset": ("", "IF Speed > 5 THEN\n    Speed := 0;\nEND_IF;"),
        "Spare": ("", "Speed := Speed;"),
    }
    for name, (declarations, body) in programs.items():
        new_pou(page, name, language="st", kind="program")
        page.get_by_label(f"{name} body").wait_for()
        if declarations:
            _replace_text(page, f"{name} declarations", declarations)
        _replace_text(page, f"{name} body", body)

    tree.get_by_role("button", name=re.compile("^Tasks")).click()
    tasks_editor = page.get_by_role("region", name="Tasks editor")
    tasks_editor.get_by_role("button", name="New task").click()
    task = tasks_editor.get_by_role("row", name="Task Task1")
    task.get_by_label("Interval").fill("T#10ms")
    task.get_by_label("Add a program to Task1").select_option("Main")
    task.get_by_label("Add a program to Task1").select_option("Reset")

    tree.get_by_role("button", name="Global variables").click()
    globals_editor.get_by_role("button", name="Rename Speed everywhere").click()
    dialog = page.get_by_role("dialog", name="Rename Speed")
    dialog.get_by_label("New name").fill("Velocity")
    dialog.get_by_role("button", name="Preview").click()
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert {text.split(",")[0].split(" line")[0] for text in places.all_inner_texts()} == {
        "Global variables",
        "Main",
        "Reset",
        "Spare",
    }
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)

    tree.get_by_role("button", name="Actions for Spare", exact=True).click()
    page.get_by_role("menu", name="Spare actions", exact=True).get_by_role("menuitem", name="Delete…").click()
    page.get_by_role("dialog", name="Delete Spare").get_by_role("button", name="Delete Spare").click()
    expect(tree.get_by_role("button", name=re.compile("^Spare"))).to_have_count(0)

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    page.get_by_role("button", name="Compile & simulate").click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    velocity = watch(page, "Velocity")
    member = watch(page, "Main.r.Member")
    for scans, (value, flag) in [(1, ("1", "FALSE")), (3, ("4", "TRUE")), (2, ("0", "TRUE")), (1, ("1", "FALSE"))]:
        _single_cycles(page, scans)
        expect(velocity).to_have_text(value)
        expect(member).to_have_text(flag)
    page.screenshot(path=str(ARTIFACTS / "walkthrough-from-empty.png"))
