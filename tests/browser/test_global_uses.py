"""A global variable deleted from the Global variables table lists every use first (issue 22 item 1: "delete
(with a list of what refers to it)"): the ST line, the LD contact by network number and label, the task's SINGLE
trigger, the operator panel's widget, the watch list row, the traced variable and the trace's trigger, not its own
declaration. The delete is one undoable step, and what is saved is the globals without it. A rename from the same
table previews the watch list row with the project's places and renames it too. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, panel_tab, store_project, watch

pytestmark = pytest.mark.browser

GLOBALS = "VAR_GLOBAL\n    Go    : BOOL;\n    Level : INT;\nEND_VAR"
PROJECT = {
    "name": "globaluse",
    "globals": GLOBALS,
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    n : INT;\nEND_VAR",
            "body": "IF Go THEN\n    Level := Level + 1;\nEND_IF;",
        },
        {
            "name": "Lad",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    Out : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "label": "Start",
                        "elements": [
                            {"type": "contact", "id": "c1", "var": "Go"},
                            {"type": "coil", "id": "q1", "var": "Out"},
                        ],
                    }
                ]
            },
        },
    ],
    "tasks": [{"name": "OnGo", "interval": None, "single": "Go", "programs": ["Main", "Lad"]}],
    "panels": [
        {
            "name": "Operator",
            "widgets": [
                {"type": "lamp", "id": "run", "x": 20, "y": 20, "w": 30, "h": 30, "label": "run", "bind": "Go"}
            ],
        }
    ],
}


def stored(server: str) -> dict:
    return _request("GET", f"{server}/api/projects/globaluse")["project"]


def test_a_global_deleted_from_the_table_lists_every_use_undoes_and_saves(page, server: str) -> None:
    store_project(server, PROJECT)
    before = stored(server)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^globaluse")).click()
    watch(page, "Go")
    watch(page, "Level")
    panels = panel_tab(page, "Trace")
    panels.get_by_label("Variable to trace").fill("Go")
    panels.get_by_label("Variable to trace").press("Enter")
    expect(panels.get_by_role("list", name="Traced variables")).to_contain_text("Go")
    panels.get_by_label("Trigger variable").fill("go")

    page.get_by_role("navigation", name="Project tree").get_by_role(
        "button", name=re.compile("^Global variables")
    ).click()
    editor = page.get_by_role("region", name="Global variables editor")
    editor.get_by_role("button", name="Remove Go").click()
    dialog = page.get_by_role("dialog", name="Delete global Go")
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert places.all_inner_texts() == [
        "Main, body line 1 IF Go THEN",
        'Lad, network 1 "Start" Go',
        "task OnGo Go",
        "panel Operator, widget run Go",
        "Watch list Go",
        "Trace Go",
        "Trace trigger go",
    ]
    expect(dialog).to_contain_text("These places use global Go and will no longer compile:")
    page.screenshot(path=str(ARTIFACTS / "global-delete-references.png"))
    dialog.get_by_role("button", name="Delete global Go").click()
    expect(dialog).to_have_count(0)
    expect(editor.get_by_label("Name of Go")).to_have_count(0)
    expect(editor.get_by_label("Name of Level")).to_have_value("Level")

    # one undo step gives the row back; Cancel leaves it
    page.get_by_role("button", name="Undo delete global Go").click()
    expect(editor.get_by_label("Name of Go")).to_have_value("Go")
    editor.get_by_role("button", name="Remove Go").click()
    page.get_by_role("dialog", name="Delete global Go").get_by_role("button", name="Cancel").click()
    expect(editor.get_by_label("Name of Go")).to_have_value("Go")

    # A rename from the table previews the watch list row with the project's places and renames it too.
    editor.get_by_role("button", name="Rename Level everywhere").click()
    dialog = page.get_by_role("dialog", name="Rename Level")
    dialog.get_by_label("New name").fill("Count")
    dialog.get_by_role("button", name="Preview").click()
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert places.all_inner_texts() == [
        "Global variables line 3 Level : INT;",
        "Main, body line 2 Level := Level + 1;",
        "Watch list Level",
    ]
    expect(dialog).to_contain_text("3 places will change:")
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)
    watched = panel_tab(page, "Watch list").locator("tr[data-path]")
    expect(watched).to_have_count(2)
    assert [watched.nth(i).get_attribute("data-path") for i in range(2)] == ["GO", "COUNT"]

    # deleted for good and saved: the stored project is the one from the start with Go gone and Level renamed
    editor.get_by_role("button", name="Remove Go").click()
    page.get_by_role("dialog", name="Delete global Go").get_by_role("button", name="Delete global Go").click()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    after = stored(server)
    assert after["globals"] == "VAR_GLOBAL\n    Count : INT;\nEND_VAR"
    main, lad = after["pous"]
    assert main["body"] == "IF Go THEN\n    Count := Count + 1;\nEND_IF;"
    assert lad == before["pous"][1]
    assert {**after, "globals": GLOBALS, "pous": before["pous"]} == before
