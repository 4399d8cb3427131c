"""The actions of an SFC POU in a real browser against a real server (issue 24 items 3 and 4, SFC-02, ON-17).

1. An action written in FBD: the user adds it to a chart (language FBD), associates it with the initial step
   (N), opens it, draws ``n := n + 1`` in the FBD editor (two inputs, ADD, an output, three wires), and runs the
   chart: the action's output node shows the count going up while its step is active, and it stops counting once
   a transition leaves the step (the final run of the N action, then nothing).
2. Breakpoints inside actions: a line of an ST action (gutter click) halts the scan on that line with the values
   of the halt, "Step over" goes to the next line of the action; a network of an LD action (its number) halts
   there and "Step network" goes to the action's next network.

Screenshots go to tests/browser/artifacts/ (sfc-action-*.png).
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from ladderlab.model import Pou, Project

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, open_print, panel_tab, scan_count, store_project, watch
from .test_fbd_workflow import drag_to, drop_from_palette, handle, name_and_declare
from .test_sfc_workflow import chart_kinds, commit_field, context_menu, item, saved_pou, step_named, write

pytestmark = pytest.mark.browser


def sfc_project(name: str, declarations: str, elements: list, actions: list) -> dict:
    pou = Pou(
        name="Main",
        kind="program",
        language="sfc",
        declarations=declarations,
        body={"chart": {"elements": elements}, "actions": actions, "transitions": []},
    )
    return Project(name=name, pous=[pou]).model_dump(mode="json", exclude_none=True)


def open_chart(page, server, project: str, declarations: str, elements: list, actions: list):
    """Stores the project ``project`` with the SFC program Main, opens Main and returns its chart editor."""
    store_project(server, sfc_project(project, declarations, elements, actions))
    page.goto(server)
    open_pou(page, project, "Main")
    return chart_editor(page)


def chart_editor(page):
    editor = page.get_by_role("application", name="Sequential function chart editor")
    editor.wait_for()
    return editor


def open_action(page, editor, name: str, language: str) -> None:
    parts = editor.locator('section.sfc-parts[aria-label="Actions"]')
    parts.locator("li", has=page.get_by_label(f"Name of action {name}")).get_by_role("button", name="Open").click()
    page.get_by_role("navigation", name="SFC parts").get_by_text(f"Action {name} ({language})").wait_for()


def add_action(page, editor, name: str, language: str, step: str) -> None:
    """Adds the action ``name`` in ``language`` (the parts list) and associates it (N) with ``step`` (the picker)."""
    editor.get_by_label("New action name").fill(name)
    editor.get_by_label("New action language").select_option(language)
    editor.get_by_role("button", name="Add action").click()
    associate(editor, step, name)


def associate(editor, step: str, name: str) -> None:
    """Associates the action ``name`` (N) with ``step`` through the qualifier picker."""
    step_named(editor, step).locator("rect.sfc-box").click(force=True)
    editor.press("q")
    picker = editor.get_by_role("form", name="New action association")
    picker.get_by_label("Qualifier").select_option("N")
    picker.get_by_label("Action or BOOL variable").fill(name)
    picker.get_by_role("button", name="Add").click()
    expect(step_named(editor, step).locator("g.sfc-association", has_text=name)).to_have_count(1)


def back_to_chart(page):
    page.get_by_role("navigation", name="SFC parts").get_by_role("button", name="Chart").click()
    return chart_editor(page)


def test_an_fbd_action_is_drawn_and_counts_online_while_its_step_is_active(page, server):
    chart = [
        {"type": "step", "id": "s1", "name": "Init"},
        {"type": "transition", "id": "t1", "condition": "go"},
        {"type": "step", "id": "s2", "name": "Done"},
        {"type": "transition", "id": "t2", "condition": "FALSE"},
        {"type": "jump", "id": "j1", "target": "Init"},
    ]
    editor = open_chart(page, server, "fbdact", "VAR\n    go : BOOL;\n    n : INT;\nEND_VAR", chart, [])

    # A new action in FBD, associated with Init (N) through the qualifier picker.
    add_action(page, editor, "Count", "fbd", "Init")

    # Opened, it is an FBD editor: n := n + 1 drawn from the palette and wired with the mouse.
    open_action(page, editor, "Count", "FBD")
    fbd = page.get_by_role("application", name="Function block diagram editor")
    fbd.get_by_role("button", name="Add network").click()
    canvas = fbd.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    drop_from_palette(page, "Input", canvas, 60, 30)
    name_and_declare(page, "Input operand", "n", None)
    drop_from_palette(page, "Input", canvas, 60, 90)
    name_and_declare(page, "Input operand", "1", None)
    drop_from_palette(page, "Block…", canvas, 260, 30)
    block_picker = page.get_by_role("dialog", name="Insert block")
    block_picker.get_by_label("Search functions and function blocks").press_sequentially("ADD")
    block_picker.get_by_role("option", name="ADD ").first.wait_for()
    page.keyboard.press("Enter")
    drop_from_palette(page, "Output", canvas, 460, 40)
    name_and_declare(page, "Output variable", "n", None)
    for src, dst in (("in1", ("blk1", "in:IN1")), ("in2", ("blk1", "in:IN2")), ("blk1", ("out1", "in:IN"))):
        drag_to(page, handle(page, src, "out:OUT"), handle(page, *dst))
    expect(fbd.locator(".react-flow__edge")).to_have_count(3)

    # Online (saved and compiled): the action runs every scan while Init is active; its output shows n growing.
    count = watch(page, "Main.n")
    go_online(page)  # saves first
    main = saved_pou(server, "fbdact", "Main")
    association = main["body"]["chart"]["elements"][0]["actions"][0]
    assert (association["qualifier"], association["action"], association.get("time")) == ("N", "Count", None)
    (action,) = main["body"]["actions"]
    assert (action["name"], action["language"]) == ("Count", "fbd")
    network = action["body"]["networks"][0]
    assert {(w["from"]["node"], w["to"]["node"], w["to"]["pin"]) for w in network["wires"]} == {
        ("in1", "blk1", "IN1"),
        ("in2", "blk1", "IN2"),
        ("blk1", "out1", "IN"),
    }
    assert [(n["type"], n.get("expr") or n.get("var") or n.get("call")) for n in network["nodes"]] == [
        ("input", "n"),
        ("input", "1"),
        ("block", "ADD"),
        ("output", "n"),
    ]
    out = page.get_by_test_id("value-out1")
    expect(out).to_have_text(re.compile(r"^[1-9]\d*$"))
    first = int(out.inner_text())
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=value-out1]')?.textContent) > n + 2", arg=first
    )
    page.screenshot(path=str(ARTIFACTS / "sfc-action-fbd-online.png"))

    # go: Done becomes active, Count runs once more (its final run) and then no more: n stays.
    editor = back_to_chart(page)
    write(page, "Main.go", "TRUE")
    expect(item(editor, "s2")).to_have_class(re.compile(r"\bsfc-active\b"))
    settled = count.inner_text()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) > n + 5", arg=scan_count(page)
    )
    assert count.inner_text() == settled


def test_breakpoints_on_an_st_action_line_and_an_ld_action_network_halt_and_step(page, server):
    chart = [
        {
            "type": "step",
            "id": "s1",
            "name": "Init",
            "actions": [
                {"id": "a1", "qualifier": "N", "action": "Fill"},
                {"id": "a2", "qualifier": "N", "action": "Lamp"},
            ],
        },
        {"type": "transition", "id": "t1", "condition": "FALSE"},
        {"type": "jump", "id": "j1", "target": "Init"},
    ]
    lamp = {
        "networks": [
            {
                "id": "blink",
                "elements": [
                    {"type": "contact", "id": "c1", "var": "on", "mode": "nc"},
                    {"type": "coil", "id": "k1", "var": "on", "mode": "normal"},
                ],
            },
            {
                "id": "copy",
                "elements": [
                    {"type": "contact", "id": "c2", "var": "on", "mode": "no"},
                    {"type": "coil", "id": "k2", "var": "shown", "mode": "normal"},
                ],
            },
        ]
    }
    actions = [
        {"name": "Fill", "language": "st", "body": "n := n + 1;\nm := m + n;\nn := n + 10;"},
        {"name": "Lamp", "language": "ld", "body": lamp},
    ]
    declarations = "VAR\n    n, m : INT;\n    on, shown : BOOL;\nEND_VAR"
    editor = open_chart(page, server, "bpact", declarations, chart, actions)
    n, m = watch(page, "Main.n"), watch(page, "Main.m")

    # A breakpoint on line 2 of the ST action Fill (gutter click); listed with the action it is in.
    open_action(page, editor, "Fill", "ST")
    line2 = page.get_by_label("Main action Fill").locator(".cm-line").nth(1)
    gutter = page.locator(".cm-breakpoint-gutter").last
    gutter_box, line_box = gutter.bounding_box(), line2.bounding_box()
    page.mouse.click(gutter_box["x"] + gutter_box["width"] / 2, line_box["y"] + line_box["height"] / 2)
    panels = panel_tab(page, "Breakpoints")
    expect(panels.locator("tr.breakpoint-row")).to_have_text("Main action Fill, line 2: m := m + n;×")

    # Run: the first scan halts before line 2: line 1 has run (n = 1), m is still 0.
    go_online(page, run=False)
    page.get_by_role("button", name="Run", exact=True).click()
    debug = page.get_by_role("region", name="Debugging")
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Fill, line 2$", re.I))
    expect(line2).to_have_class(re.compile(r"\bcm-halted-line\b"))
    halted_scan = scan_count(page)
    panel_tab(page, "Watch list")
    expect(n).to_have_text("1")
    expect(m).to_have_text("0")
    page.screenshot(path=str(ARTIFACTS / "sfc-action-st-halted.png"))

    # Step over: line 2 runs (m = 0 + 1), the halt moves to line 3 of the same scan.
    debug.get_by_role("button", name="Step over").click()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Fill, line 3$", re.I))
    expect(m).to_have_text("1")
    expect(n).to_have_text("1")
    assert scan_count(page) == halted_scan

    # The line breakpoint removed (the Breakpoints panel), a breakpoint on network 1 of the LD action Lamp.
    panels = panel_tab(page, "Breakpoints")
    panels.get_by_role("button", name="Remove breakpoint Main, action Fill, line 2: m := m + n;").click()
    panels.get_by_text("No breakpoints.").wait_for()
    editor = back_to_chart(page)
    open_action(page, editor, "Lamp", "LD")
    page.get_by_role("button", name="Toggle breakpoint on network 1").click()
    expect(panels.locator("tr.breakpoint-row")).to_have_text("Main action Lamp, network 1×")

    # Continue: the scan goes on into Lamp (Fill ran first: alphabetical) and halts before its network 1.
    debug.get_by_role("button", name="Continue").click()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Lamp, network 1$", re.I))
    expect(page.locator('svg.ld-network[data-network="blink"]')).to_have_class(re.compile(r"halted"))
    page.screenshot(path=str(ARTIFACTS / "sfc-action-ld-halted.png"))
    # Step network: network 1 runs, the halt is on Lamp's network 2 in the same scan.
    debug.get_by_role("button", name="Step network").click()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, action Lamp, network 2$", re.I))
    panel_tab(page, "Watch list")
    expect(watch(page, "Main.on")).to_have_text("TRUE")  # the NC contact on FALSE set it in network 1
    expect(watch(page, "Main.shown")).to_have_text("FALSE")  # network 2 has not run yet


def test_an_sfc_action_is_drawn_and_its_chart_runs_online_while_the_action_is_active(page, server):
    """Issue 24 item 1: an action written in SFC, made and edited in the browser, highlighted online."""
    chart = [
        {"type": "step", "id": "s1", "name": "M0"},
        {"type": "transition", "id": "t1", "condition": "go"},
        {"type": "step", "id": "s2", "name": "M1"},
        {"type": "transition", "id": "t2", "condition": "FALSE"},
        {"type": "jump", "id": "j1", "target": "M0"},
    ]
    declarations = "VAR\n    go, next : BOOL;\n    a : INT;\nEND_VAR"
    actions = [{"name": "IncA", "language": "st", "body": "a := a + 1;"}]
    editor = open_chart(page, server, "sfcact", declarations, chart, actions)

    # A new action Seq in SFC, associated with M0 (N); opened, it is a chart of its own with its initial step.
    add_action(page, editor, "Seq", "sfc", "M0")
    open_action(page, editor, "Seq", "SFC")
    inner = chart_editor(page)
    assert chart_kinds(inner) == ["Seq_Init1", ":FALSE", "->Seq_Init1"]

    # Its transition waits for next; a step Second below it; IncA associated with the initial step.
    inner.locator("g.sfc-transition > g").first.click()
    inner.press("Enter")
    condition = inner.get_by_label("Condition", exact=True)
    condition.fill("next")
    condition.press("Enter")
    inner.get_by_role("button", name="Step + transition").click()
    commit_field(inner, "Step name", "Second")
    associate(inner, "Seq_Init1", "IncA")
    assert chart_kinds(inner) == ["Seq_Init1", ":next", "Second", ":FALSE", "->Seq_Init1"]

    # Online: M0 runs Seq, whose initial step is active (blue) and runs IncA; next moves the inner chart.
    count = watch(page, "Main.a")
    go_online(page)
    main = saved_pou(server, "sfcact", "Main")
    seq = next(a for a in main["body"]["actions"] if a["name"] == "Seq")
    assert seq["language"] == "sfc"
    assert [e.get("name") or e.get("condition") or e["target"] for e in seq["body"]["elements"]] == [
        "Seq_Init1",
        "next",
        "Second",
        "FALSE",
        "Seq_Init1",
    ]
    active = re.compile(r"\bsfc-active\b")
    expect(step_named(inner, "Seq_Init1")).to_have_class(active)
    expect(step_named(inner, "Second")).not_to_have_class(active)
    expect(count).to_have_text(re.compile(r"^[1-9]\d*$"))
    page.screenshot(path=str(ARTIFACTS / "sfc-action-sfc-online.png"))
    write(page, "Main.next", "TRUE")
    expect(step_named(inner, "Second")).to_have_class(active)
    expect(step_named(inner, "Seq_Init1")).not_to_have_class(active)
    # the POU's chart: M0 active, its association with Seq active
    editor = back_to_chart(page)
    expect(step_named(editor, "M0")).to_have_class(active)

    # A breakpoint on Second (the step's menu, in the action's chart) halts the running scan there at once; back
    # on the POU's chart, Continue halts at it in the next scan, which opens the action's chart and marks the step.
    second = seq["body"]["elements"][2]["id"]
    open_action(page, editor, "Seq", "SFC")
    context_menu(chart_editor(page), second, "Set breakpoint")
    debug = page.get_by_role("region", name="Debugging")
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, step Second$", re.I))
    back_to_chart(page)
    debug.get_by_role("button", name="Continue").click()
    page.get_by_role("navigation", name="SFC parts").get_by_text("Action Seq (SFC)").wait_for()
    expect(debug.get_by_role("status")).to_have_text(re.compile(r"^Halted at Main, step Second$", re.I))
    expect(item(chart_editor(page), second)).to_have_class(re.compile(r"\bsfc-halted\b"))
    page.screenshot(path=str(ARTIFACTS / "sfc-action-sfc-halted.png"))

    # Printed: the action's chart is drawn in its section, after the POU's chart.
    printed, problems = open_print(page)
    section = printed.get_by_role("region", name="Action Seq")
    section.locator("svg.sfc-canvas").wait_for()
    assert section.locator("text.sfc-name").all_text_contents() == ["Seq_Init1", "Second"]
    assert problems == []
