"""Issue 25 item 5: a METHOD of a PROGRAM edited in the browser (CODESYS has them). The program's Methods tab adds
a method (without the FINAL / ABSTRACT a function block's has: nothing extends a program), the tree lists it under
the program and opens it, the program's body calls it bare and through ``THIS^`` and another program as
``Main.Add``; a rename there and back takes those calls along; saved and run, the values are the ones worked out from the texts; a breakpoint in the method's body
halts in the engine's POU ``MAIN.ADD`` with the call stack Main -> Main.Add (ON-03)."""

from __future__ import annotations

import json

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, open_pou, store_project, watch
from .test_cfc_workflow import cycles
from .test_methods_editor import editor, preview_rename

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "progmeth",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    total : INT;\n    r : INT;\nEND_VAR",
            "body": "",
        },
        {
            "name": "Other",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    x : INT;\nEND_VAR",
            "body": "x := Main.Add(k := 10);",
        },
    ],
}


def test_a_program_method_is_added_called_run_and_halted_in(page, server, tmp_path):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "progmeth", "Main")
    page.get_by_role("tab", name="Methods").click()
    members = page.get_by_role("list", name="Methods and properties of Main")
    expect(members.get_by_role("button")).to_have_count(0)
    expect(page.get_by_label("ABSTRACT Main")).to_have_count(0)  # a program is no class to extend

    page.get_by_label("New method or property name").fill("Add")
    page.get_by_role("button", name="Add method", exact=True).click()
    page.get_by_label("Result type of Add").fill("INT")
    editor(page, "Main.Add declarations").fill("VAR_INPUT\n    k : INT;\nEND_VAR")
    expect(members.get_by_role("button")).to_have_text(["MAdd"])
    expect(page.get_by_label("FINAL Add")).to_have_count(0)
    tree = page.get_by_role("navigation", name="Project tree")
    expect(tree.get_by_role("button", name="Add : INT")).to_be_visible()

    page.get_by_role("tab", name="Body").click()
    editor(page, "Main body").fill("r := Put(k := 1);\nr := r + THIS^.Put(k := 2);")
    page.get_by_role("tab", name="Methods").click()
    editor(page, "Main.Add body").fill("total := total + k;\nAdd := total;")

    # Renamed Put: the preview lists the method, its result variable and Other's Main.Add call (Main's body calls
    # Put, no method yet: untouched); back to Add, also Main's bare and THIS^ calls of it
    dialog, places = preview_rename(page, members, "Main", "Add", "Put")
    assert places == [
        "Main METHOD Add",
        "Main.Add, body line 2 Add := total;",
        "Other, body line 1 x := Main.Add(k := 10);",
    ]
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    expect(members.get_by_role("button")).to_have_text(["MPut"])
    dialog, places = preview_rename(page, members, "Main", "Put", "Add")
    assert places == [
        "Main, body line 1 r := Put(k := 1);",
        "Main, body line 2 r := r + THIS^.Put(k := 2);",
        "Main METHOD Put",
        "Main.Put, body line 2 Put := total;",
        "Other, body line 1 x := Main.Put(k := 10);",
    ]
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = _request("GET", f"{server}/api/projects/progmeth")["project"]
    main, other = project["pous"]
    assert [(m["name"], m["return_type"], m["body"]) for m in main["methods"]] == [
        ("Add", "INT", "total := total + k;\nAdd := total;")
    ]
    assert (main["body"], other["body"]) == (
        "r := Add(k := 1);\nr := r + THIS^.Add(k := 2);",
        "x := Main.Add(k := 10);",
    )
    saved = json.loads((tmp_path / "workspace" / "progmeth" / "pous" / "Main.st.json").read_text())
    assert [m["name"] for m in saved["methods"]] == ["Add"]

    # Online, two scans (Main runs before Other): scan 1: Add(1) -> 1, THIS^.Add(2) -> 3, r = 1 + 3 = 4, Other's
    # Main.Add(10) -> 13; scan 2: 14, 16, r = 30, Other's -> 26.
    go_online(page, run=False)
    cycles(page, 2)
    expect(watch(page, "Main.total")).to_have_text("26")
    expect(watch(page, "Main.r")).to_have_text("30")
    expect(watch(page, "Other.x")).to_have_text("26")

    # The tree's method opens in the program's Methods tab; F9 on its body's first line, then a scan halts in it.
    tree.get_by_role("button", name="Add : INT").click()
    expect(page.get_by_role("tab", name="Methods")).to_have_attribute("aria-selected", "true")
    editor(page, "Main.Add body").focus()
    page.keyboard.press("Control+Home")
    page.keyboard.press("F9")
    expect(page.get_by_role("tab", name="Breakpoints (1)")).to_be_visible()
    page.keyboard.press("F5")
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at MAIN.ADD, line 1").wait_for()
    calls = debug.get_by_role("navigation", name="Call stack").locator("li")
    expect(calls).to_have_text(["MAIN, line 1", "MAIN.ADD (MAIN), line 1"])
    # the method's own k = 1 inline, and the program's total as the halted scan 3 found it (26 after scan 2),
    # as an FB's method body shows its instance's variables (issue 25 item 6, ON-09)
    expect(editor(page, "Main.Add body").locator(".cm-halted-line")).to_have_text("total26 := total26 + k1;")
    page.screenshot(path=str(ARTIFACTS / "program-method-breakpoint.png"))
