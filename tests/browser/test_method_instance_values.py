"""Issue 25 item 6 (ON-03, ON-09): online, a method's body in its FB's Methods tab shows the FB instance's variables it
names inline, live scan by scan as the FB body does, and while halted in the method its own variables from the call
stack as well. Expected values by hand: each scan Main calls c.Bump(inc := 2), so Count goes 2, 4, 6; the method's
own `inc` (the input) is 2 in every call."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .steps import go_online, open_pou, store_project, watch
from .test_cfc_workflow import cycles

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


STEPPER = {
    "name": "stepper",
    "pous": [
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_OUTPUT\n    Count : INT;\nEND_VAR\nVAR\n    Inc : INT := 1;\nEND_VAR",
            "body": "",
            "methods": [{"name": "Bump", "return_type": None, "body": "Count := Count + Inc;"}],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    c : Counter;\n    n : INT;\nEND_VAR",
            "body": "c.Bump();\nn := c.Count;",
        },
    ],
}


def test_write_and_force_from_a_method_body_act_on_the_instance_scan_by_scan(page, server):
    """Issue 25 item 6 (ON-05, ON-07): in the Methods tab online, a double-click on a variable of the method's body
    prepares a value for the FB instance's variable it names; Ctrl+F7 writes it before the next scan, F7 forces it
    and the release gives it back to the program. Expected values by hand: every scan Main calls c.Bump(), which
    adds Inc (1) to Count, then n takes Count. Inc written 10 adds 10 a scan; Count forced 100 reads 100 after
    every scan (the force is applied again after the scan), and once released the next scan adds 10 to it."""
    store_project(server, STEPPER)
    page.goto(server)
    open_pou(page, "stepper", "Counter")
    page.get_by_role("tab", name="Methods").click()
    body = page.get_by_role("textbox", name="Counter.Bump body")
    values = body.locator(".cm-st-value")  # Count Count Inc
    go_online(page, run=False)
    n = watch(page, "Main.n")
    expect(values).to_have_text(["0", "0", "1"])
    cycles(page, 1)
    expect(values).to_have_text(["1", "1", "1"])
    expect(n).to_have_text("1")

    values.nth(2).dblclick()  # prepare a value for Inc
    prompt = page.get_by_role("dialog", name="Prepare a value for Inc")
    prompt.get_by_label("Value").fill("10")
    prompt.get_by_role("button", name="OK").click()
    expect(body.locator(".prepared-tag")).to_have_text(["<10>"])
    page.keyboard.press("Control+F7")
    expect(body.locator(".prepared-tag")).to_have_count(0)  # written before the next scan: nothing prepared now
    cycles(page, 1)
    expect(values).to_have_text(["11", "11", "10"])
    expect(n).to_have_text("11")

    values.nth(0).dblclick()  # prepare a value for Count, then force it
    prompt = page.get_by_role("dialog", name="Prepare a value for Count")
    prompt.get_by_label("Value").fill("100")
    prompt.get_by_role("button", name="OK").click()
    expect(body.locator(".prepared-tag")).to_have_text(["<100>", "<100>"])
    page.keyboard.press("F7")
    forces = page.get_by_role("status", name="Active forces")
    forces.filter(has_text="1 forced").wait_for()
    expect(values.nth(0).locator(".forced-mark")).to_have_text("F")
    for _ in range(2):  # the scan adds 10 to 100 and Main's n takes 110, then the force puts Count back to 100
        cycles(page, 1)
        expect(values).to_have_text(["100F", "100F", "10"])
        expect(n).to_have_text("110")

    page.keyboard.press("Alt+F7")  # release all forces
    forces.filter(has_text="0 forced").wait_for()
    cycles(page, 1)
    expect(values).to_have_text(["110", "110", "10"])
    expect(n).to_have_text("110")


TANK = {
    "name": "tank",
    "pous": [
        {
            "name": "Tank",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    level : INT;\nEND_VAR",
            "body": "level := level + 1;",
            "properties": [
                {
                    "name": "Doubled",
                    "type": "INT",
                    "get": {
                        "declarations": "VAR\n    twice : INT;\nEND_VAR",
                        "body": "twice := level * 2;\nDoubled := twice;",
                    },
                    "set": {
                        "declarations": "VAR\n    half : INT;\nEND_VAR",
                        "body": "half := Doubled / 2;\nlevel := half;",
                    },
                }
            ],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    t : Tank;\n    d : INT;\nEND_VAR",
            "body": "t();\nd := t.Doubled;\nt.Doubled := d + 2;",
        },
    ],
}


def test_halted_in_a_property_accessor_its_own_variables_show_inline(page, server):
    """Issue 25 item 6 (ON-03, ON-09): a breakpoint in a property's GET and one in its SET halt there, and each
    accessor's body shows its own variables (its VAR and the property's value) from the call stack beside the
    instance's, as a method's body does. By hand, scan 1: t() makes level 1; the GET computes twice = 2 and halts
    before `Doubled := twice` (Doubled still 0); Main writes 2 + 2 through the SET, which computes half = 2 and halts
    before `level := half` (level still 1)."""
    store_project(server, TANK)
    page.goto(server)
    open_pou(page, "tank", "Tank")
    page.get_by_role("tab", name="Methods").click()
    page.get_by_role("list", name="Methods and properties of Tank").get_by_role("button", name="Doubled").click()
    go_online(page, run=False)
    for which in ("GET", "SET"):  # a breakpoint on line 2 of each accessor's body
        page.get_by_role("textbox", name=f"Tank.Doubled.{which} body").focus()
        page.keyboard.press("Control+End")
        page.keyboard.press("F9")
    expect(page.get_by_role("tab", name="Breakpoints (2)")).to_be_visible()
    page.keyboard.press("F5")
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at TANK.DOUBLED.GET, line 2").wait_for()
    get = page.get_by_role("textbox", name="Tank.Doubled.GET body")
    expect(get.locator(".cm-st-value")).to_have_text(["2", "1", "0", "2"])  # twice level Doubled twice
    expect(get.locator(".cm-halted-line")).to_have_text("Doubled0 := twice2;")

    page.keyboard.press("F5")
    debug.get_by_text("Halted at TANK.DOUBLED.SET, line 2").wait_for()
    setter = page.get_by_role("textbox", name="Tank.Doubled.SET body")
    expect(setter.locator(".cm-st-value")).to_have_text(["2", "4", "1", "2"])  # half Doubled level half
    expect(get.locator(".cm-st-value")).to_have_text(["1"])  # no longer halted in the GET: only the instance's level
