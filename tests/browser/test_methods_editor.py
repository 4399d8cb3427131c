"""Issue 25: methods and properties of a function block edited in the browser (CODESYS's objects under an FB). In
the FB's Methods tab a method is added, given a result type, declarations and a body in the ST editor, saved and
run: Main's call of it gives the value the method computes; a property's GET is edited; a method is renamed with
Main's call of it (previewed, one undo step) and another deleted; a breakpoint in the method's body halts there online. Expected values follow from the texts."""

from __future__ import annotations

import json

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, open_pou, panel_tab, store_project, watch
from .test_cfc_workflow import cycles

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "methods",
    "pous": [
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    n : INT;\nEND_VAR",
            "body": "n := n + 1;",
            "methods": [{"name": "Old", "body": ""}, {"name": "Unused", "body": ""}],
            "properties": [{"name": "Level", "type": "INT", "get": {"body": "Level := 0;"}}],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    c : Counter;\n    y : INT;\n    lv : INT;\nEND_VAR",
            "body": "c();\ny := c.Scaled(k := 3);\nlv := c.Level;\nc.Old();",
        },
    ],
}


def editor(page, label: str):
    return page.get_by_role("textbox", name=label)


def preview_rename(page, members, fb: str, old: str, new: str):
    """Renames member ``old`` of ``fb`` to ``new`` in the Methods tab up to the preview: the dialog and its places."""
    members.get_by_role("button", name=old).click()
    page.get_by_label(f"New name of {old}").fill(new)
    page.get_by_role("button", name="Rename", exact=True).click()
    dialog = page.get_by_role("dialog", name=f"Rename {fb}.{old}")
    expect(dialog.get_by_label("New name")).to_have_value(new)
    dialog.get_by_role("button", name="Preview").click()
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    return dialog, places.all_inner_texts()


def test_add_edit_rename_and_delete_methods_then_run_and_halt_in_one(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "methods", "Counter")
    page.get_by_role("tab", name="Methods").click()
    members = page.get_by_role("list", name="Methods and properties of Counter")
    expect(members.get_by_role("button")).to_have_text(["MOld", "MUnused", "PLevel"])

    name = page.get_by_label("New method or property name")
    name.fill("Scaled")
    page.get_by_role("button", name="Add method", exact=True).click()
    page.get_by_label("Result type of Scaled").fill("INT")
    editor(page, "Counter.Scaled declarations").fill("VAR_INPUT\n    k : INT;\nEND_VAR")
    editor(page, "Counter.Scaled body").fill("Scaled := n * k;")
    name.fill("Scaled")
    page.get_by_role("button", name="Add method", exact=True).click()
    expect(page.get_by_text("Counter already has a method called Scaled.")).to_be_visible()

    # Renaming Old previews its declaration and Main's call (issue 25 item 5); one undo step takes both back.
    dialog, places = preview_rename(page, members, "Counter", "Old", "Bump")
    assert places == ["Counter METHOD Old", "Main, body line 4 c.Old();"]
    page.screenshot(path=str(ARTIFACTS / "methods-rename-preview.png"))
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    expect(members.get_by_role("button")).to_have_text(["MBump", "MUnused", "MScaled", "PLevel"])
    page.get_by_role("button", name="Undo rename Old to Bump").click()
    expect(members.get_by_role("button")).to_have_text(["MOld", "MUnused", "MScaled", "PLevel"])
    dialog, _ = preview_rename(page, members, "Counter", "Old", "Bump")
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    editor(page, "Counter.Bump body").fill("n := n + 10;")
    members.get_by_role("button", name="Unused").click()
    page.get_by_role("button", name="Delete Unused", exact=True).click()
    members.get_by_role("button", name="Level").click()
    editor(page, "Counter.Level.GET body").fill("Level := n * 2;")
    expect(members.get_by_role("button")).to_have_text(["MBump", "MScaled", "PLevel"])
    page.screenshot(path=str(ARTIFACTS / "methods-editor.png"))

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    counter = _request("GET", f"{server}/api/projects/methods")["project"]["pous"][0]
    assert [(m["name"], m["return_type"], m["body"]) for m in counter["methods"]] == [
        ("Bump", None, "n := n + 10;"),
        ("Scaled", "INT", "Scaled := n * k;"),
    ]
    main = _request("GET", f"{server}/api/projects/methods")["project"]["pous"][1]
    assert main["body"] == "c();\ny := c.Scaled(k := 3);\nlv := c.Level;\nc.Bump();"

    # Online: one cycle gives what the texts compute. Scan 1: c() makes n 1, Scaled gives 1 * 3, Level 1 * 2,
    # then Bump adds 10 (n = 11).
    go_online(page, run=False)
    cycles(page, 1)
    expect(watch(page, "Main.y")).to_have_text("3")
    expect(watch(page, "Main.lv")).to_have_text("2")
    expect(watch(page, "Main.c.n")).to_have_text("11")

    # A breakpoint on the first line of Scaled's body (F9 there): the next scan halts in the method.
    page.get_by_role("tab", name="Body").click()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Scaled : INT").click()  # opens the member in its FB's Methods tab
    expect(page.get_by_role("tab", name="Methods")).to_have_attribute("aria-selected", "true")
    editor(page, "Counter.Scaled body").focus()
    page.keyboard.press("Control+Home")
    page.keyboard.press("F9")
    expect(page.get_by_role("tab", name="Breakpoints (1)")).to_be_visible()
    page.keyboard.press("F5")
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text("Halted at COUNTER.SCALED, line 1").wait_for()
    # the method's own variables show inline at the halt (k = 3, its result 0 so far), and the instance's n too
    # (issue 25 item 6, ON-09): scan 2's c() made it 11 + 1 = 12 before the call
    expect(editor(page, "Counter.Scaled body").locator(".cm-halted-line")).to_have_text("Scaled0 := n12 * k3;")
    page.screenshot(path=str(ARTIFACTS / "methods-breakpoint.png"))


SPECIFIERS = {
    "name": "specifiers",
    "pous": [
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    n : INT;\nEND_VAR",
            "body": "",
            "methods": [
                {"name": "Clamp", "return_type": "INT", "body": "Clamp := n;"},
                {"name": "Total", "return_type": "INT", "body": "Total := Clamp();"},
            ],
        },
        {
            "name": "Bigger",
            "kind": "function_block",
            "language": "st",
            "extends": "Counter",
            "declarations": "",
            "body": "",
            "methods": [{"name": "Total", "return_type": "INT", "body": "Total := 2;"}],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    c : Counter;\n    b : Bigger;\n    y : INT;\nEND_VAR",
            "body": "y := c.Clamp() + b.Total();",
        },
    ],
}


def test_access_final_and_abstract_are_set_in_the_methods_tab_saved_and_checked(page, server, tmp_path):
    """Issue 25 item 5: Clamp made PRIVATE and Total FINAL in the browser; the tree shows them, the save writes them
    in the FB's file (tests/interchange/test_codesys_oo_import.py exports them), and the check locates Main's call of the PRIVATE method and Bigger's override of the
    FINAL one. FINAL and ABSTRACT exclude each other."""
    store_project(server, SPECIFIERS)
    page.goto(server)
    open_pou(page, "specifiers", "Counter")
    page.get_by_role("tab", name="Methods").click()
    members = page.get_by_role("list", name="Methods and properties of Counter")
    members.get_by_role("button", name="Clamp").click()
    expect(page.get_by_label("Access of Clamp")).to_have_value("PUBLIC")
    page.get_by_label("Access of Clamp").select_option("PRIVATE")
    tree = page.get_by_role("navigation", name="Project tree")
    expect(tree.get_by_role("button", name="Clamp : INT (PRIVATE)")).to_be_visible()

    members.get_by_role("button", name="Total").click()
    final, abstract = page.get_by_label("FINAL Total"), page.get_by_label("ABSTRACT Total")
    final.check()
    abstract.check()
    expect(final).not_to_be_checked()
    expect(tree.get_by_role("button", name="Total : INT (ABSTRACT)")).to_be_visible()
    abstract.uncheck()
    final.check()
    expect(abstract).not_to_be_checked()
    expect(tree.get_by_role("button", name="Total : INT (FINAL)")).to_be_visible()
    page.screenshot(path=str(ARTIFACTS / "methods-specifiers.png"))

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = _request("GET", f"{server}/api/projects/specifiers")["project"]
    assert [(m["name"], m["access"], m["final"], m["abstract"]) for m in project["pous"][0]["methods"]] == [
        ("Clamp", "PRIVATE", False, False),
        ("Total", "PUBLIC", True, False),
    ]
    saved = json.loads((tmp_path / "workspace" / "specifiers" / "pous" / "Counter.st.json").read_text())
    assert [(m["name"], m["access"], m["final"]) for m in saved["methods"]] == [
        ("Clamp", "PRIVATE", False),
        ("Total", "PUBLIC", True),
    ]

    page.keyboard.press("Control+Shift+B")  # Check
    panels = panel_tab(page, "Diagnostics")
    items = panels.get_by_role("list", name="Diagnostics").locator(":scope > li")
    expect(items).to_have_count(2)
    texts = " | ".join(items.all_inner_texts())
    assert "the method Counter.Clamp is PRIVATE: only its own function block may call it" in texts
    assert "Counter.Total is FINAL: Bigger cannot override it" in texts
    expect(panels.get_by_role("button", name="ST-NOT-ACCESSIBLE")).to_be_visible()

    # The FB itself made ABSTRACT (FINAL, then ABSTRACT: the two exclude each other): Main's instance of it is refused.
    page.get_by_label("FINAL Counter").check()
    page.get_by_label("ABSTRACT Counter").check()
    expect(page.get_by_label("FINAL Counter")).not_to_be_checked()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    saved = json.loads((tmp_path / "workspace" / "specifiers" / "pous" / "Counter.st.json").read_text())
    assert (saved.get("abstract"), saved.get("final")) == (True, None)
    page.keyboard.press("Control+Shift+B")
    expect(items).to_have_count(3)
    assert "Counter is ABSTRACT: declare an instance of a function block derived from it" in " ".join(
        items.all_inner_texts()
    )


INTERFACED = {
    "name": "interfaced",
    "types": "INTERFACE IBump\nMETHOD Bump : INT\nEND_METHOD\nEND_INTERFACE",
    "pous": [
        {
            "name": "Counter",
            "kind": "function_block",
            "language": "st",
            "implements": ["IBump"],
            "declarations": "VAR\n    n : INT;\nEND_VAR",
            "body": "",
            "methods": [{"name": "Bump", "return_type": "INT", "body": "n := n + 1;\nBump := n;"}],
        },
        {
            "name": "Other",
            "kind": "function_block",
            "language": "st",
            "implements": ["IBump"],
            "declarations": "",
            "body": "",
            "methods": [{"name": "Bump", "return_type": "INT", "body": "Bump := 7;"}],
        },
        {
            "name": "Holder",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_OUTPUT\n    inner : Counter;\nEND_VAR",
            "body": "",
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    h : Holder;\n    o : Other;\n    i : IBump;\n    a : INT;\n    b : INT;\nEND_VAR",
            "body": "a := h.inner.Bump();\ni := o;\nb := i.Bump();",
        },
    ],
}


def test_renaming_an_interface_method_from_the_methods_tab_renames_it_everywhere_in_one_undo_step(page, server):
    """Issue 25 item 5 (rename): Counter's Bump implements IBump's, so renaming it in the Methods tab previews and
    renames IBump's METHOD line, Other's implementation, the call through the member path h.inner and the one
    through the interface variable i; one Undo takes all of it back."""
    store_project(server, INTERFACED)
    page.goto(server)
    open_pou(page, "interfaced", "Counter")
    page.get_by_role("tab", name="Methods").click()
    members = page.get_by_role("list", name="Methods and properties of Counter")
    dialog, places = preview_rename(page, members, "Counter", "Bump", "Add")
    assert places == [
        "Types line 2 METHOD Bump : INT",
        "Counter METHOD Bump",
        "Counter.Bump, body line 2 Bump := n;",
        "Other METHOD Bump",
        "Other.Bump, body line 1 Bump := 7;",
        "Main, body line 1 a := h.inner.Bump();",
        "Main, body line 3 b := i.Bump();",
    ]
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    expect(members.get_by_role("button")).to_have_text(["MAdd"])
    page.get_by_role("button", name="Undo rename Bump to Add").click()
    expect(members.get_by_role("button")).to_have_text(["MBump"])
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert _request("GET", f"{server}/api/projects/interfaced")["project"]["types"] == INTERFACED["types"]

    dialog, _ = preview_rename(page, members, "Counter", "Bump", "Add")
    dialog.get_by_role("button", name="Rename", exact=True).click()
    expect(dialog).to_have_count(0)
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = _request("GET", f"{server}/api/projects/interfaced")["project"]
    assert project["types"] == "INTERFACE IBump\nMETHOD Add : INT\nEND_METHOD\nEND_INTERFACE"
    assert [(p["name"], [m["name"] for m in p.get("methods") or []]) for p in project["pous"]] == [
        ("Counter", ["Add"]),
        ("Other", ["Add"]),
        ("Holder", []),
        ("Main", []),
    ]
    assert project["pous"][3]["body"] == "a := h.inner.Add();\ni := o;\nb := i.Add();"
