"""A function block's ACTION added and edited in the browser, then called (IL-08's action call, CODESYS).

The project (stored through the REST API): FB Counter counts ``out`` up by one per call; program P calls
``Inst(); Inst.Wrap(); ERG := Inst.out;`` - which does not check until Counter has the action Wrap. In the browser:
Counter's Actions tab, "Add action" Wrap, its ST body ``IF out >= 3 THEN out := 0; END_IF;`` typed in the editor,
saved; the tree lists it under Counter. Online, by hand: out goes 1, 2, 3 -> wrapped to 0, 1 - so ERG after 3
single cycles is 0, after 4 is 1.
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import expect

from .steps import go_online, open_pou, store_project, watch
from .test_cfc_workflow import cycles

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "actions",
    "pous": [
        {
            "name": "P",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    Inst : Counter;\n    ERG : INT;\nEND_VAR",
            "body": "Inst();\nInst.Wrap();\nERG := Inst.out;",
        },
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_OUTPUT\n    out : INT;\nEND_VAR",
            "body": "out := out + 1;",
        },
    ],
}


def test_add_an_action_in_the_browser_and_call_it_IL_08(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "actions", "Counter")
    page.get_by_role("tablist", name="Counter views").get_by_role("tab", name="Actions (0)").click()
    page.get_by_label("New action").fill("Wrap")
    page.get_by_role("button", name="Add action").click()
    section = page.get_by_role("region", name="Action Wrap")
    editor = section.locator(".cm-content")
    editor.click()
    page.keyboard.type("IF out >= 3 THEN out := 0; END_IF;")
    expect(page.get_by_role("tab", name="Actions (1)")).to_be_visible()
    tree = page.get_by_role("navigation", name="Project tree")
    expect(tree.get_by_role("list", name="Counter members")).to_contain_text("Wrap")
    # a second action of that name is refused with the reason
    page.get_by_label("New action").fill("wrap")
    page.get_by_role("button", name="Add action").click()
    expect(page.get_by_role("alert").filter(has_text="already has")).to_have_text(
        "Counter already has a method, property or action called wrap."
    )

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    with urllib.request.urlopen(f"{server}/api/projects/actions") as response:
        saved = {p["name"]: p for p in json.load(response)["project"]["pous"]}
    assert saved["Counter"]["actions"] == [{"name": "Wrap", "body": "IF out >= 3 THEN out := 0; END_IF;"}]

    erg = watch(page, "P.ERG")
    go_online(page, run=False)
    cycles(page, 3)
    expect(erg).to_have_text(re.compile(r"^0\b"))
    cycles(page, 1)
    expect(erg).to_have_text(re.compile(r"^1\b"))
