"""FBD <-> CFC from the POU's menu in a real browser (issue 26 brief item 5, CFC-01, CFC-02).

An FBD program of two networks (``b := a + 1; c := (a + 1) * 2``; ``d := c``) becomes a CFC chart: both networks on
one chart, numbered in the order FBD ran them (ADD 1, b 2, MUL 3, c 4, d 5), and it computes the same (a = 5: b = 6,
c = 12, d = 12 after one cycle). Moving MUL before the ADD wired into it makes the chart's order differ from the data
flow: converting back to FBD is refused with the reason; after "Order by data flow" the chart becomes one FBD
network.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .steps import _request, go_online, open_pou, store_project
from .test_cfc_workflow import badges, cycles
from .test_project_operations import menu_action

pytestmark = pytest.mark.browser


def wire(a: str, b: str) -> dict:
    (n, p), (m, q) = a.split("."), b.split(".")
    return {"from": {"node": n, "pin": p}, "to": {"node": m, "pin": q}}


NETWORKS = [
    {
        "id": "n1",
        "nodes": [
            {"type": "input", "id": "ia", "expr": "a", "pos": {"x": 20, "y": 20}},
            {"type": "input", "id": "one", "expr": "1", "pos": {"x": 20, "y": 70}},
            {"type": "block", "id": "add", "call": "ADD", "pos": {"x": 200, "y": 20}},
            {"type": "output", "id": "ob", "var": "b", "pos": {"x": 400, "y": 30}},
            {"type": "input", "id": "two", "expr": "2", "pos": {"x": 200, "y": 160}},
            {"type": "block", "id": "mul", "call": "MUL", "pos": {"x": 400, "y": 120}},
            {"type": "output", "id": "oc", "var": "c", "pos": {"x": 600, "y": 130}},
        ],
        "wires": [
            wire("ia.OUT", "add.IN1"),
            wire("one.OUT", "add.IN2"),
            wire("add.OUT", "ob.IN"),
            wire("add.OUT", "mul.IN1"),
            wire("two.OUT", "mul.IN2"),
            wire("mul.OUT", "oc.IN"),
        ],
    },
    {
        "id": "n2",
        "nodes": [
            {"type": "input", "id": "ic", "expr": "c", "pos": {"x": 20, "y": 20}},
            {"type": "output", "id": "od", "var": "d", "pos": {"x": 200, "y": 20}},
        ],
        "wires": [wire("ic.OUT", "od.IN")],
    },
]
PROJECT = {
    "name": "conv",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR a : INT := 5; b, c, d : INT; END_VAR",
            "body": {"networks": NETWORKS},
        }
    ],
}


def test_convert_fbd_to_cfc_and_back(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "conv", "Main")
    menu_action(page, "Main", "Convert to CFC…")
    page.get_by_role("dialog", name="Convert Main to CFC").get_by_role("button", name="Convert to CFC").click()
    editor = page.get_by_role("application", name="Continuous function chart editor")
    badges(editor, {"add": "1", "ob": "2", "mul": "3", "oc": "4", "od": "5"})
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    main = _request("GET", f"{server}/api/projects/conv")["project"]["pous"][0]
    assert (main["language"], [n["id"] for n in main["body"]["networks"]]) == ("cfc", ["chart"])
    assert main["body"]["networks"][0]["order"] == ["add", "ob", "mul", "oc", "od"]

    go_online(page, run=False)
    cycles(page, 1)
    page.get_by_test_id("value-ob").filter(has_text=re.compile("^6$")).wait_for()
    page.get_by_test_id("value-oc").filter(has_text=re.compile("^12$")).wait_for()
    page.get_by_test_id("value-od").filter(has_text=re.compile("^12$")).wait_for()
    state = page.get_by_role("status", name="Online state")
    page.get_by_role("button", name="Go offline", exact=True).click()
    state.filter(has_text=re.compile("^Offline")).wait_for()

    # MUL before the ADD feeding it: FBD could not keep that order, so the conversion says why and changes nothing.
    toolbar = page.get_by_role("toolbar", name="FBD editing")
    editor.locator('.fbd-node[data-node="mul"]').click()
    toolbar.get_by_role("button", name="Run earlier").click()
    badges(editor, {"add": "1", "mul": "2", "ob": "3"})
    toolbar.get_by_role("button", name="Run earlier").click()
    badges(editor, {"mul": "1", "add": "2", "ob": "3", "oc": "4", "od": "5"})
    menu_action(page, "Main", "Convert to FBD…")
    dialog = page.get_by_role("dialog", name="Convert Main to FBD")
    dialog.get_by_role("button", name="Convert to FBD").click()
    expect(dialog.get_by_role("alert")).to_have_text(
        'The chart runs MUL as number 1, where data flow would run ADD: FBD cannot keep that order. Use "Order by '
        'data flow" first (it changes what the chart computes), or keep the chart.'
    )
    dialog.get_by_role("button", name="Cancel").click()
    expect(editor).to_be_visible()

    toolbar.get_by_role("button", name="Order by data flow").click()
    badges(editor, {"add": "1", "mul": "2", "ob": "3", "oc": "4", "od": "5"})
    menu_action(page, "Main", "Convert to FBD…")
    page.get_by_role("dialog", name="Convert Main to FBD").get_by_role("button", name="Convert to FBD").click()
    fbd = page.get_by_role("application", name="Function block diagram editor")
    expect(fbd.locator(".fbd-network")).to_have_count(1)
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    main = _request("GET", f"{server}/api/projects/conv")["project"]["pous"][0]
    assert (main["language"], len(main["body"]["networks"])) == ("fbd", 1)
