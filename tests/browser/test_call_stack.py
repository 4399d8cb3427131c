"""Issue 25 item 6: halted inside a function called from a method, the halted-scan bar lists the call stack (Main ->
Motor.Start on MAIN.M -> Clamp), Clamp's editor shows its own variables inline, choosing the method's call opens it
in Motor's Methods tab with its own variables, and Step out leaves Clamp (ON-03: halted, the values stay
inspectable). Expected values follow from the texts: x = 7, so Start gets n = 7 and passes tmp = 14 to Clamp."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "stack",
    "pous": [
        {
            "name": "Clamp",
            "kind": "function",
            "language": "st",
            "return_type": "INT",
            "declarations": "VAR_INPUT\n    v : INT;\n    hi : INT;\nEND_VAR\nVAR\n    tmp : INT := 7;\nEND_VAR",
            "body": "tmp := v;\nIF tmp > hi THEN tmp := hi; END_IF;\nClamp := tmp;",
        },
        {
            "name": "Motor",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    count : INT;\nEND_VAR",
            "body": "",
            "methods": [
                {
                    "name": "Start",
                    "return_type": "INT",
                    "declarations": "VAR_INPUT\n    n : INT;\nEND_VAR\nVAR\n    tmp : INT;\nEND_VAR",
                    "body": "tmp := n * 2;\ncount := count + Clamp(tmp, 10);\nStart := count;",
                }
            ],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    m : Motor;\n    x : INT := 7;\n    r : INT;\nEND_VAR",
            "body": "r := m.Start(n := x);",
        },
    ],
}


def inline_values(page, label: str):
    return page.get_by_role("textbox", name=label).locator(".cm-st-value")


def halted_in_clamp_then_open_the_method(page, calls, screenshot: str, count: str) -> None:
    """Halted before Clamp's first line in the call from Motor.Start: the call stack, Clamp's own values inline; then
    the method's call chosen opens it in Motor's Methods tab with its own values and its instance's `count`."""
    expect(calls).to_have_text(["MAIN, line 1", "MOTOR.START (MAIN.M), line 2", "CLAMP, line 1"])
    # Clamp(14, 10) halted before its first statement: tmp still has its declared initial 7, the result its 0
    # (tmp v | tmp hi tmp hi | Clamp tmp)
    expect(inline_values(page, "Clamp body")).to_have_text(["7", "14", "7", "10", "7", "10", "0", "7"])
    page.screenshot(path=str(ARTIFACTS / screenshot))
    # Start's body with its own n = 7, tmp = 14 and result 0, and MAIN.M's count (ON-03, ON-09: the instance's, live)
    # (tmp n | count count tmp | Start count)
    calls.get_by_role("button", name="MOTOR.START (MAIN.M), line 2").click()
    expect(page.get_by_role("tab", name="Methods")).to_have_attribute("aria-selected", "true")
    expect(inline_values(page, "Motor.Start body")).to_have_text(["14", "7", count, count, "14", "0", count])


def test_halted_in_a_function_called_by_a_method_the_call_stack_and_each_calls_own_values(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "stack", "Clamp")
    body = page.get_by_role("textbox", name="Clamp body")
    body.focus()
    page.keyboard.press("Control+Home")
    page.keyboard.press("F9")  # a breakpoint on line 1: before Clamp assigns anything
    go_online(page, run=False)
    page.keyboard.press("F5")

    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at CLAMP, line 1").wait_for()
    calls = debug.get_by_role("navigation", name="Call stack").locator("li")
    halted_in_clamp_then_open_the_method(page, calls, "call-stack-function.png", count="0")  # scan 1: count 0

    # Step out of Clamp (it clamps tmp to 10 and returns; count becomes 10): halted at the method's next line, Clamp's
    # call gone from the stack
    debug.get_by_role("button", name="Step out").click()
    debug.get_by_text("Halted at MOTOR.START, line 3").wait_for()
    expect(calls).to_have_text(["MAIN, line 1", "MOTOR.START (MAIN.M), line 3"])
    expect(inline_values(page, "Motor.Start body")).to_have_text(["14", "7", "10", "10", "14", "0", "10"])
    page.screenshot(path=str(ARTIFACTS / "call-stack-method.png"))


def test_a_step_through_a_past_scan_shows_the_call_stack_of_the_point_reached(page, server):
    """Issue 23 item 3 with issue 25 item 6: scan 2 of three, stepped through line by line from the history's
    timeline, halts in Clamp with the same call stack and the same values a live halt there shows (the scan before
    left x = 7: Start gets n = 7 and passes tmp = 14); the method's call opens it in the Methods tab with its own."""
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "stack", "Main")
    go_online(page, run=False)
    scan, cycle = page.get_by_test_id("scan-count"), page.get_by_role("button", name="Single cycle")
    for number in (1, 2, 3):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
    page.get_by_role("group", name="Scan history").get_by_role("slider", name="Scan").fill("2")
    page.get_by_role("status", name="History view").filter(has_text="Viewing scan 2 (history)").wait_for()

    stepping = page.get_by_role("group", name="Step through the scan")
    point = stepping.get_by_label("Step point")
    stepping.get_by_role("button", name="Step into this scan").click()
    point.filter(has_text="Scan 2, halted before MAIN, line 1").wait_for()
    calls = stepping.get_by_role("navigation", name="Call stack").locator("li")
    expect(calls).to_have_text(["MAIN, line 1"])
    for text in ("MOTOR.START, line 1", "MOTOR.START, line 2", "CLAMP, line 1"):
        stepping.get_by_role("button", name="Next step").click()
        point.filter(has_text=f"Scan 2, halted before {text}").wait_for()
    # scan 1 left count = 0 + Clamp(14, 10) = 10; scan 2 stands before adding to it
    halted_in_clamp_then_open_the_method(page, calls, "call-stack-history-step.png", count="10")
    assert scan.inner_text() == "2"  # the scan shown; the live simulation stays at 3
