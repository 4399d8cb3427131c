"""Issue 25 item 6 (ON-03, ON-09): online, a method's body in its FB's Methods tab shows the FB instance's variables it
names inline, live scan by scan as the FB body does, and while halted in the method its own variables from the call
stack as well. Expected values by hand: each scan Main calls c.Bump(inc := 2), so Count goes 2, 4, 6; the method's
own `inc` (the input) is 2 in every call."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .steps import go_online, open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "bumps",
    "pous": [
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    Count : INT;\nEND_VAR",
            "body": "",
            "methods": [
                {
                    "name": "Bump",
                    "return_type": None,
                    "declarations": "VAR_INPUT\n    inc : INT;\nEND_VAR",
                    "body": "Count := Count + inc;",
                }
            ],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    c : Counter;\nEND_VAR",
            "body": "c.Bump(inc := 2);",
        },
    ],
}


def test_a_method_body_shows_its_instance_variables_scan_by_scan_and_its_own_while_halted(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "bumps", "Counter")
    page.get_by_role("tab", name="Methods").click()
    body = page.get_by_role("textbox", name="Counter.Bump body")
    values = body.locator(".cm-st-value")
    go_online(page, run=False)
    scan, cycle = page.get_by_test_id("scan-count"), page.get_by_role("button", name="Single cycle")
    # (Count Count): MAIN.C's Count, the only instance; the call's own inc shows only while halted in it
    expect(values).to_have_text(["0", "0"])
    for number, count in ((1, "2"), (2, "4")):
        cycle.click()
        scan.filter(has_text=re.compile(f"^{number}$")).wait_for()
        expect(values).to_have_text([count, count])

    # a breakpoint on the method's line: scan 3 halts before it adds, Count still 4, inc 2 (Count Count inc)
    body.focus()
    page.keyboard.press("Control+Home")
    page.keyboard.press("F9")
    page.keyboard.press("F5")
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at COUNTER.BUMP, line 1").wait_for()
    expect(values).to_have_text(["4", "4", "2"])
    expect(page.get_by_text("The halted call's own variables: read only.")).to_be_visible()
