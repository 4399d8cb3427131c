"""Sequential function charts in a real browser against a real server (issue 24).

1. The editor: a new SFC program starts with its initial step, a transition and the jump back; the user
   inserts a step and a transition below with the toolbar and the keyboard, names them, divides a
   transition into an alternative branch and a step into a simultaneous one, retargets a jump, adds an
   ST action and associates it with a step through the qualifier picker (L with a time), opens the
   action in the ST editor and writes it, moves across the chart with the arrow keys, copies and pastes
   a step, zooms, undoes and redoes, and sees the live check mark a transition that assigns (SFC-03);
   the saved chart is the one drawn.
2. Online: the example car wash runs; its active steps and actions are blue, each step shows its time,
   every transition its condition's value (also the inactive ones); a written input fires a transition;
   a forced step flag activates a step; a breakpoint on a step halts the scan there, "Step to next
   transition" halts where a transition fires, a single cycle advances the scan counter by one.

Screenshots go to tests/browser/artifacts/ (sfc-*.png).
"""

from __future__ import annotations

import json
import re
import urllib.request
from pathlib import Path

import pytest
from playwright.sync_api import expect

from ladderlab.storage.project_folder import read_project_folder

from .conftest import ARTIFACTS
from .steps import (
    go_online,
    new_pou,
    new_project,
    open_pou,
    open_print,
    panel_tab,
    scan_count,
    settled_scan_count,
    store_project,
    watch,
)

pytestmark = pytest.mark.browser

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DECLARATIONS = "VAR\n    go : BOOL;\n    full : BOOL;\n    abort : BOOL;\n    fills : INT;\nEND_VAR"


def item(editor, element_id: str):
    return editor.locator(f'g.sfc-item[data-sfc-id="{element_id}"]')


def step_named(editor, name: str):
    return editor.locator("g.sfc-step", has=editor.page.locator(f'text.sfc-name:text-is("{name}")'))


def pick(target) -> None:
    """Clicks a drawn step or transition (its shape with its texts)."""
    target.locator(":scope > g").first.click()


def selected(editor) -> str | None:
    found = editor.locator("g.sfc-item.sfc-selected")
    return found.get_attribute("data-sfc-id") if found.count() else None


def chart_kinds(editor) -> list[str]:
    """The drawn steps, transitions and jumps, top to bottom then left to right: step names, conditions, ->targets."""
    return editor.evaluate(
        """root => [...root.querySelectorAll('g.sfc-item')].map(g => {
            const text = (sel) => g.querySelector(sel)?.textContent ?? '';
            if (g.classList.contains('sfc-step')) return text('text.sfc-name');
            if (g.classList.contains('sfc-transition')) return ':' + text('text.sfc-condition');
            return '->' + text('text.sfc-condition');
        })"""
    )


def commit_field(editor, label: str, text: str) -> None:
    field = editor.get_by_label(label, exact=True)
    field.fill(text)
    field.press("Enter")


def saved_pou(server: str, project: str, pou: str) -> dict:
    with urllib.request.urlopen(f"{server}/api/projects/{project}") as response:
        pous = json.load(response)["project"]["pous"]
    return next(p for p in pous if p["name"] == pou)


def test_new_user_draws_an_sfc_program(page, server):
    new_project(page, server, "seq")
    new_pou(page, "Main", language="sfc")
    editor = page.get_by_role("application", name="Sequential function chart editor")
    editor.wait_for()
    assert chart_kinds(editor) == ["Init", ":FALSE", "->Init"]
    # the initial step is drawn with a double border
    assert item(editor, "s1").locator("rect.sfc-box-inner").count() == 1

    # Declarations first (the Declarations view of the POU).
    page.get_by_role("tablist", name="Main views").get_by_role("tab", name="Declarations").click()
    page.get_by_role("tablist", name="Declarations view").get_by_role("tab", name="Text").click()
    page.get_by_label("Declarations text").fill(DECLARATIONS)
    page.get_by_role("tablist", name="Main views").get_by_role("tab", name="Chart").click()
    editor.wait_for()

    # The transition's condition, edited in place (Enter on the selected transition focuses it).
    pick(item(editor, "t1"))
    assert selected(editor) == "t1"
    editor.press("Enter")
    condition = editor.get_by_label("Condition", exact=True)
    expect(condition).to_be_focused()
    condition.fill("go")
    condition.press("Enter")
    expect(item(editor, "t1").locator("text.sfc-condition")).to_have_text("go")

    # A step and a transition below the transition: the toolbar button; the new step is selected.
    editor.get_by_role("button", name="Step + transition").click()
    assert chart_kinds(editor) == ["Init", ":go", "Step1", ":FALSE", "->Init"]
    commit_field(editor, "Step name", "Fill")
    # ArrowDown moves to the new transition; Enter edits its condition.
    editor.focus()
    editor.press("ArrowDown")
    new_transition = selected(editor)
    assert new_transition is not None and new_transition.startswith("t")
    editor.press("Enter")
    condition.fill("full")
    condition.press("Enter")
    assert chart_kinds(editor) == ["Init", ":go", "Fill", ":full", "->Init"]

    # An alternative branch at that transition ("A"): a second transition beside it, abort.
    editor.focus()
    editor.press("a")
    assert chart_kinds(editor) == ["Init", ":go", "Fill", ":full", ":FALSE", "->Init"]
    commit_field(editor, "Condition", "abort")
    # Below the abort transition (S): a step Drain, then its own transition and a jump back to Init.
    editor.focus()
    editor.press("s")
    commit_field(editor, "Step name", "Drain")
    editor.focus()
    editor.press("ArrowDown")
    editor.press("Enter")
    condition.fill("NOT abort")
    condition.press("Enter")
    assert chart_kinds(editor) == ["Init", ":go", "Fill", ":full", ":abort", "Drain", ":NOT abort", "->Init"]
    # The alternative convergence is drawn as a single line; the convergence ends in the jump.
    page.screenshot(path=str(ARTIFACTS / "sfc-editor-alternative.png"))

    # An ST action Pump, associated with Fill through the qualifier picker: L for T#2s.
    editor.get_by_label("New action name").fill("Pump")
    editor.get_by_role("button", name="Add action").click()
    step_named(editor, "Fill").locator("rect.sfc-box").click(force=True)
    editor.press("q")
    picker = editor.get_by_role("form", name="New action association")
    picker.get_by_label("Qualifier").select_option("L")
    picker.get_by_label("Action or BOOL variable").fill("Pump")
    picker.get_by_label("Time").fill("T#2s")
    picker.get_by_role("button", name="Add").click()
    block = step_named(editor, "Fill").locator("g.sfc-association")
    expect(block).to_have_count(1)
    assert block.locator("text").all_text_contents() == ["L", "Pump", "T#2s"]
    # The qualifier can be changed in the step's properties (the picker lists all eleven).
    qualifier = editor.get_by_label("Qualifier of Pump")
    assert qualifier.locator("option").all_inner_texts() == [
        "N", "R", "S", "L", "D", "P", "P1", "P0", "SD", "DS", "SL",
    ]  # fmt: skip

    # Open the action: the ST editor; its text joins the POU; back to the chart.
    editor.get_by_role("button", name="Open").first.click()
    page.get_by_role("navigation", name="SFC parts").get_by_text("Action Pump (ST)").wait_for()
    page.get_by_label("Main action Pump").click()
    page.keyboard.insert_text("fills := fills + 1;")
    page.get_by_role("navigation", name="SFC parts").get_by_role("button", name="Chart").click()
    editor.wait_for()

    # A simultaneous branch at Fill ("P"), then undone and redone with the keys.
    step_named(editor, "Fill").locator("rect.sfc-box").click(force=True)
    editor.press("p")
    expect(editor.locator("g.sfc-double")).to_have_count(2)  # divergence and convergence
    assert chart_kinds(editor) == [
        "Init", ":go", "Fill", "Step1", ":full", ":abort", "Drain", ":NOT abort", "->Init",
    ]  # fmt: skip
    editor.press("Control+z")
    expect(editor.locator("g.sfc-double")).to_have_count(0)
    editor.press("Control+y")
    expect(editor.locator("g.sfc-double")).to_have_count(2)
    editor.press("Control+z")
    expect(editor.locator("g.sfc-double")).to_have_count(0)

    # Copy Drain and its transition (Ctrl+C), paste them below Init's transition (Ctrl+V); a step is
    # refused there with the reason.
    step_named(editor, "Drain").locator("rect.sfc-box").click(force=True)
    editor.press("Control+c")
    step_named(editor, "Init").locator("rect.sfc-box").click(force=True)
    editor.press("Control+v")
    expect(editor.get_by_text("Paste steps below a transition.")).to_be_visible()
    pick(item(editor, "t1"))
    editor.press("Control+v")
    expect(editor.locator("g.sfc-step")).to_have_count(4)
    pasted = [name for name in chart_kinds(editor) if name.startswith("Drain") and name != "Drain"]
    assert len(pasted) == 1, chart_kinds(editor)
    editor.press("Control+z")
    expect(editor.locator("g.sfc-step")).to_have_count(3)

    # Zoom with the keys; the toolbar shows the factor.
    editor.press("=")
    expect(editor.get_by_label("Zoom", exact=True)).to_have_text("125 %")
    editor.press("0")
    expect(editor.get_by_label("Zoom", exact=True)).to_have_text("100 %")

    # The jump's target, picked from the steps.
    jump = editor.locator("g.sfc-jump")
    jump.click()
    editor.get_by_label("Jump target").select_option("Fill")
    expect(jump.locator("text")).to_have_text("Fill")
    editor.get_by_label("Jump target").select_option("Init")

    # Live check: an assignment in a transition condition is refused (SFC-03), located on the transition.
    step_named(editor, "Drain").locator("rect.sfc-box").click(force=True)
    editor.focus()
    editor.press("ArrowDown")
    last = selected(editor)
    editor.press("Enter")
    condition.fill("fills := 1")
    condition.press("Enter")
    expect(item(editor, last)).to_have_class(re.compile(r"\bsfc-error\b"))
    assert "SFC-CONDITION" in (item(editor, last).locator("title").first.text_content() or "")
    page.screenshot(path=str(ARTIFACTS / "sfc-editor-diagnostic.png"))
    editor.press("Control+z")
    expect(item(editor, last)).not_to_have_class(re.compile(r"\bsfc-error\b"))

    # Saved: the chart the server holds is the one drawn.
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    page.screenshot(path=str(ARTIFACTS / "sfc-editor.png"))
    main = saved_pou(server, "seq", "Main")
    assert main["language"] == "sfc"
    elements = main["body"]["chart"]["elements"]
    assert [e["type"] for e in elements] == ["step", "transition", "step", "alternative", "jump"]
    assert elements[2]["actions"][0] | {"id": None} == {"id": None, "qualifier": "L", "action": "Pump", "time": "T#2s"}
    assert [(a["name"], a["language"], a["body"]) for a in main["body"]["actions"]] == [
        ("Pump", "st", "fills := fills + 1;")
    ]


ACTIVE = re.compile(r"\bsfc-active\b")
HALTED = re.compile(r"\bsfc-halted\b")
BLUE_FILL = "rgb(214, 228, 255)"  # sfc.css --sfc-active-fill


def write(page, path: str, text: str) -> None:
    """Writes ``text`` into ``path`` from its watch list row (added first)."""
    watch(page, path)
    row = page.get_by_role("region", name="Panels").locator(f'tr[data-path="{path.upper()}"]')
    row.get_by_label(f"New value for {path}").fill(text)
    row.get_by_role("button", name="Write").click()


def context_menu(editor, element_id: str, entry: str) -> None:
    """Right-clicks a drawn step or transition and picks ``entry`` from its menu."""
    item(editor, element_id).locator(":scope > g").first.click(button="right")
    editor.page.get_by_role("menuitem", name=entry).click()


def test_the_car_wash_online_breakpoints_and_stepping_by_transition(page, server):
    """SFC-09, ON-17; issue 24 item 4: the running chart as the scans compute it, a step breakpoint, stepping to
    the next transition that fires, a single cycle and a forced step flag."""
    project = read_project_folder(EXAMPLES / "car_wash_sfc").model_dump(mode="json", exclude_none=True)
    store_project(server, project)
    page.goto(server)
    open_pou(page, "car_wash_sfc", "Wash")
    editor = page.get_by_role("application", name="Sequential function chart editor")
    editor.wait_for()
    cars = watch(page, "Wash.Cars")
    go_online(page)

    # Waiting for a car: Idle is active, blue, and its N action Ready runs (blue too).
    idle = item(editor, "s1")
    expect(idle).to_have_class(ACTIVE)
    assert idle.locator("rect.sfc-box").evaluate("e => getComputedStyle(e).fill") == BLUE_FILL
    expect(editor.locator('g.sfc-association[data-sfc-association="a2"]')).to_have_class(ACTIVE)
    expect(item(editor, "s23")).not_to_have_class(ACTIVE)
    # Idle's time grows with the scans (100 ms each); inactive steps show none.
    idle_time = idle.locator("text.sfc-time")
    expect(idle_time).to_have_text(re.compile(r"^T#[1-9]"))
    first = idle_time.text_content()
    expect(idle_time).not_to_have_text(first or "")
    assert re.fullmatch(r"(T#0m?s)?", item(editor, "s23").locator("text.sfc-time").text_content() or "")
    # Every transition shows its condition's value, the inactive ones too: NOT Premium and TRUE are TRUE.
    condition = lambda t: editor.locator(f'text[data-condition="{t}"]')  # noqa: E731
    expect(condition("t3")).to_have_text("FALSE")  # Start AND CarInside
    expect(condition("t7")).to_have_text("FALSE")  # Premium
    expect(condition("t12")).to_have_text("TRUE")  # NOT Premium, Welcome inactive
    expect(condition("t22")).to_have_text("TRUE")  # TRUE, the join's steps inactive
    page.screenshot(path=str(ARTIFACTS / "sfc-online-idle.png"))

    # The LD action Ready, opened online: its network shows the power its scans computed (no car: the NC contact
    # on CarInside conducts and the coil GreenLamp is on); back to the chart.
    parts = editor.locator('section.sfc-parts[aria-label="Actions"]')
    parts.locator("li", has=page.get_by_label("Name of action Ready")).get_by_role("button", name="Open").click()
    page.get_by_role("navigation", name="SFC parts").get_by_text("Action Ready (LD)").wait_for()
    expect(page.locator('g.ld-coil[data-id="k1"]')).to_have_class(re.compile(r"\bld-on\b"))
    page.screenshot(path=str(ARTIFACTS / "sfc-online-ld-action.png"))
    page.get_by_role("navigation", name="SFC parts").get_by_role("button", name="Chart").click()
    editor.wait_for()

    # A car drives in and Start is pressed (written inputs): t3 fires, Welcome counts the car (P), NOT Premium
    # leads to the simultaneous Brush and Spray.
    write(page, "Wash.CarInside", "TRUE")
    expect(condition("t3")).to_have_text("FALSE")
    write(page, "Wash.Start", "TRUE")
    expect(item(editor, "s13")).to_have_class(ACTIVE)
    expect(item(editor, "s18")).to_have_class(ACTIVE)
    expect(idle).not_to_have_class(ACTIVE)
    expect(cars).to_have_text("1")
    expect(editor.locator('g.sfc-association[data-sfc-association="a14"]')).to_have_class(ACTIVE)  # N Brushes
    page.screenshot(path=str(ARTIFACTS / "sfc-online-running.png"))

    # Stopped, a breakpoint on Rinse from its context menu; Run halts in the scan where Rinse is active, before
    # its actions run.
    page.get_by_role("button", name="Stop", exact=True).click()
    context_menu(editor, "s23", "Set breakpoint")
    expect(item(editor, "s23").locator("circle.sfc-breakpoint")).to_have_count(1)
    panels = panel_tab(page, "Breakpoints")
    expect(panels.locator("tr.breakpoint-row")).to_contain_text("step Rinse")
    page.get_by_role("button", name="Run", exact=True).click()
    debug = page.get_by_role("region", name="Debugging")
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Wash, step Rinse$", re.I))
    expect(item(editor, "s23")).to_have_class(HALTED)
    expect(item(editor, "s23")).to_have_class(ACTIVE)
    page.screenshot(path=str(ARTIFACTS / "sfc-online-breakpoint.png"))

    # The breakpoint removed, "Step to next transition": scans run until Rinse.T >= T#2s fires (20 scans of
    # 100 ms after Rinse became active), and halt there; Rinse is still the active step.
    context_menu(editor, "s23", "Remove breakpoint")
    expect(item(editor, "s23").locator("circle.sfc-breakpoint")).to_have_count(0)
    halted_scan = scan_count(page)
    editor.get_by_role("button", name="Step to next transition").click()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Wash, transition Rinse\.T >= T#2s$", re.I))
    expect(item(editor, "t26")).to_have_class(HALTED)
    expect(item(editor, "s23")).to_have_class(ACTIVE)
    expect(item(editor, "s27")).not_to_have_class(ACTIVE)
    assert 15 <= scan_count(page) - halted_scan <= 25, (halted_scan, scan_count(page))
    page.screenshot(path=str(ARTIFACTS / "sfc-online-transition.png"))

    # Continue: the transition fires, Dry follows; stopped, a single cycle is exactly one scan.
    debug.get_by_role("button", name="Continue").click()
    expect(item(editor, "s27")).to_have_class(ACTIVE)
    page.get_by_role("button", name="Stop", exact=True).click()
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    before = settled_scan_count(page)
    page.get_by_role("button", name="Single cycle").click()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=before + 1
    )

    # A forced step flag: Leave.X forced TRUE from the step's menu; the next cycle runs Leave's actions (N Gate),
    # the step shows the force; released, the force is gone.
    context_menu(editor, "s32", "Force TRUE")
    page.get_by_role("button", name="Single cycle").click()
    expect(item(editor, "s32")).to_have_class(ACTIVE)
    expect(item(editor, "s32").locator("text.sfc-time")).to_have_text(re.compile(r"^F "))
    expect(editor.locator('g.sfc-association[data-sfc-association="a33"]')).to_have_class(ACTIVE)
    page.screenshot(path=str(ARTIFACTS / "sfc-online-forced.png"))
    context_menu(editor, "s32", "Release force")
    expect(item(editor, "s32").locator("text.sfc-time")).not_to_have_text(re.compile(r"^F "))


def test_the_car_wash_prints_its_chart_and_its_actions(page, server):
    """Issue 24 with the print view: an SFC POU prints as its chart, then each action (ST text, LD networks)."""
    project = read_project_folder(EXAMPLES / "car_wash_sfc").model_dump(mode="json", exclude_none=True)
    store_project(server, project)
    page.goto(server)
    open_pou(page, "car_wash_sfc", "Wash")
    page.get_by_role("application", name="Sequential function chart editor").wait_for()
    printed, errors = open_print(page)
    wash = printed.get_by_role("region", name="PROGRAM Wash")
    wash.locator("svg.sfc-canvas").wait_for()
    names = wash.locator("svg.sfc-canvas text.sfc-name").all_text_contents()
    assert names == ["Idle", "Welcome", "Soak", "Brush", "BrushHome", "Spray", "Drain", "Rinse", "Dry", "Leave"]
    assert "Cars := Cars + 1;" in wash.get_by_role("region", name="Action CountCar").inner_text()
    wash.get_by_role("region", name="Action Ready").locator(".print-network svg").wait_for()
    printed.screenshot(path=str(ARTIFACTS / "sfc-print.png"), full_page=True)
    assert errors == []
