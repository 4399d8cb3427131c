"""Global variable lists in the project tree (issue 25): listed with their qualified_only option, opened in the
global variables' editor, added, renamed everywhere (its qualifier in GVL_IO.bStart too) and deleted; the live
check reports a bare use of a qualified_only list's variable at its place; online, GVL_IO.bStart is watched and
written, and an LD contact on it shows its value. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, store_project, watch
from .test_project_operations import menu_action as menu
from .test_project_operations import tree

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "lists",
    "gvls": [
        {"name": "GVL_IO", "qualified_only": True, "text": "VAR_GLOBAL\n    bStart : BOOL;\nEND_VAR"},
        {"name": "GVL", "qualified_only": False, "text": "VAR_GLOBAL\n    counter : INT;\nEND_VAR"},
    ],
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "",
            "body": "IF GVL_IO.bStart THEN\n    GVL.counter := GVL.counter + 1;\nEND_IF;",
        }
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "priority": 0, "programs": ["Main"]}],
}
LAMP = {
    "name": "Lamp",
    "kind": "program",
    "language": "ld",
    "declarations": "VAR\n    q : BOOL;\nEND_VAR",
    "body": {
        "networks": [
            {
                "id": "n1",
                "elements": [
                    {"type": "contact", "id": "c1", "var": "GVL_IO.bStart"},
                    {"type": "coil", "id": "q1", "var": "q"},
                ],
            }
        ]
    },
}


def stored(server: str) -> dict:
    return _request("GET", f"{server}/api/projects/lists")["project"]


def test_lists_are_edited_added_renamed_and_deleted_from_the_tree(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^lists")).click()
    section = tree(page).get_by_role("region", name="Global variable lists")
    expect(section.locator(".tree-name")).to_have_text(["GVL_IO", "GVL"])
    expect(section.get_by_role("button", name=re.compile("^GVL_IO"))).to_contain_text("qualified only")

    # Open GVL_IO: its option and its variables in the global variables' table; a bare use is a located error
    section.get_by_role("button", name=re.compile("^GVL_IO")).click()
    editor = page.get_by_role("region", name="Global variable list GVL_IO")
    expect(editor.get_by_role("checkbox", name=re.compile("qualified_only"))).to_be_checked()
    expect(editor.get_by_label("Name of bStart")).to_have_value("bStart")
    editor.get_by_role("button", name="Add variable").click()
    editor.get_by_label("Name of NewVar").fill("bStop")
    editor.get_by_label("Type of bStop").fill("BOOL")
    expect(page.get_by_role("tab", name=re.compile("^GVL_IO \\(GVL\\)"))).to_contain_text("●")
    page.screenshot(path=str(ARTIFACTS / "gvl-editor.png"))

    # New list: a taken name is refused in the list's words, a free one opens
    section.get_by_role("button", name="New list").click()
    section.get_by_label("List name").fill("gvl_io")
    section.get_by_role("button", name="Create").click()
    expect(section.get_by_role("alert")).to_have_text("There is already a global variable list called GVL_IO.")
    section.get_by_label("List name").fill("GVL_Motors")
    section.get_by_role("button", name="Create").click()
    expect(page.get_by_role("region", name="Global variable list GVL_Motors")).to_be_visible()
    expect(section.locator(".tree-name")).to_have_text(["GVL_IO", "GVL", "GVL_Motors"])

    # Rename GVL_IO everywhere: the preview lists the qualified use in Main; its tab follows
    menu(page, "list GVL_IO", "Rename…")
    dialog = page.get_by_role("dialog", name="Rename GVL_IO")
    dialog.get_by_label("New name").fill("GVL_Inputs")
    dialog.get_by_role("button", name="Preview").click()
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert places.all_inner_texts() == ["Main, body line 1 IF GVL_IO.bStart THEN"]
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)
    expect(section.locator(".tree-name")).to_have_text(["GVL_Inputs", "GVL", "GVL_Motors"])
    expect(page.get_by_role("tab", name=re.compile("^GVL_Inputs \\(GVL\\)"))).to_be_visible()

    # Delete GVL_Motors (nothing uses it), then save: the stored project has the lists as edited
    menu(page, "list GVL_Motors", "Delete…")
    dialog = page.get_by_role("dialog", name="Delete global variable list GVL_Motors")
    expect(dialog).to_contain_text("Nothing refers to global variable list GVL_Motors.")
    dialog.get_by_role("button", name="Delete global variable list GVL_Motors").click()
    expect(section.locator(".tree-name")).to_have_text(["GVL_Inputs", "GVL"])
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    after = stored(server)
    assert after["gvls"] == [
        {
            "name": "GVL_Inputs",
            "qualified_only": True,
            "text": "VAR_GLOBAL\n    bStart : BOOL;\n    bStop  : BOOL;\nEND_VAR",
        },
        PROJECT["gvls"][1],
    ]
    assert after["pous"][0]["body"] == "IF GVL_Inputs.bStart THEN\n    GVL.counter := GVL.counter + 1;\nEND_IF;"


def test_a_bare_use_of_a_qualified_only_list_is_shown_at_its_line_and_a_list_variable_watched_online(
    page, server: str
) -> None:
    tasks = [{**PROJECT["tasks"][0], "programs": ["Main", "Lamp"]}]
    store_project(server, {**PROJECT, "pous": [*PROJECT["pous"], LAMP], "tasks": tasks})
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^lists")).click()
    tree(page).get_by_role("button", name=re.compile("^Main")).click()
    body = page.get_by_label("Main body")
    body.wait_for()

    # Untick qualified_only: a bare bStart is fine then, and reported at its line once it is ticked again
    tree(page).get_by_role("button", name=re.compile("^GVL_IO")).click()
    option = page.get_by_role("region", name="Global variable list GVL_IO").get_by_role(
        "checkbox", name=re.compile("qualified_only")
    )
    option.uncheck()
    tree(page).get_by_role("button", name=re.compile("^Main")).click()
    body.focus()
    page.keyboard.press("Control+End")
    page.keyboard.insert_text("\nbStart := FALSE;")
    expect(body.locator(".cm-lintRange-error")).to_have_count(0)
    tree(page).get_by_role("button", name=re.compile("^GVL_IO")).click()
    option.check()
    tree(page).get_by_role("button", name=re.compile("^Main")).click()
    expect(body.locator(".cm-lintRange-error")).to_have_count(1)
    expect(body.locator(".cm-lintRange-error")).to_have_text("bStart")
    page.screenshot(path=str(ARTIFACTS / "gvl-qualified-only.png"))
    body.focus()
    page.keyboard.press("Control+End")
    page.keyboard.press("Shift+Home")
    page.keyboard.insert_text("GVL_IO.bStart := GVL_IO.bStart;")
    expect(body.locator(".cm-lintRange-error")).to_have_count(0)

    # Online: GVL_IO.bStart written from the watch list (its row keyed as the server names it); the counter counts
    go_online(page)
    watch(page, "GVL_IO.bStart")
    watch(page, "GVL.counter")
    panels = page.get_by_role("region", name="Panels")
    start = panels.locator('tr[data-path="BSTART"] td.watch-value')
    counter = panels.locator('tr[data-path="COUNTER"] td.watch-value')
    expect(start).to_have_text("FALSE")
    expect(counter).to_have_text("0")
    page.get_by_label("New value for GVL_IO.bStart").fill("TRUE")
    panels.locator('tr[data-path="BSTART"]').get_by_role("button", name="Write").click()
    expect(start).to_have_text("TRUE")
    expect(counter).to_have_text(re.compile(r"^[1-9][0-9]*$"))

    # The LD contact on GVL_IO.bStart shows the list's variable online
    tree(page).get_by_role("button", name=re.compile("^Lamp")).click()
    contact = page.locator('g.ld-element[data-id="c1"] .ld-badge').first
    expect(contact).to_have_attribute("data-value", "TRUE")
    expect(page.locator('g.ld-element[data-id="q1"] .ld-badge').first).to_have_attribute("data-value", "TRUE")
    expect(page.locator('g.ld-element[data-id="q1"]')).to_have_class(re.compile(r"\bld-on\b"))  # the power flow too
    page.screenshot(path=str(ARTIFACTS / "gvl-online.png"))


SHARED = {
    "name": "shared",
    "gvls": [
        {"name": "GVL_A", "qualified_only": False, "text": "VAR_GLOBAL\n    n : INT := 5;\nEND_VAR"},
        {"name": "GVL_B", "qualified_only": False, "text": "VAR_GLOBAL\n    n : INT;\nEND_VAR"},
    ],
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "",
            "body": "GVL_B.n := GVL_A.n + 1;",
        }
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "priority": 0, "programs": ["Main"]}],
}


def test_a_name_two_lists_declare_is_watched_and_shown_inline_per_list(page, server: str) -> None:
    """CODESYS's namespace of global variable lists: GVL_A.n and GVL_B.n are two variables, each shown with its own
    value in the watch list (the rows keyed by the qualified path, as the server names them) and inline in ST."""
    store_project(server, SHARED)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^shared")).click()
    tree(page).get_by_role("button", name=re.compile("^Main")).click()
    go_online(page, run=False)
    a, b = watch(page, "GVL_A.n"), watch(page, "GVL_B.n")
    expect(a).to_have_text("5")
    expect(b).to_have_text("0")
    page.get_by_role("button", name="Single cycle").click()
    expect(b).to_have_text("6")  # GVL_A.n + 1
    expect(a).to_have_text("5")
    values = page.get_by_role("textbox", name="Main body").locator(".cm-st-value")
    expect(values).to_have_text(["6", "5"])  # GVL_B.n, GVL_A.n
    page.screenshot(path=str(ARTIFACTS / "gvl-shared-online.png"))
