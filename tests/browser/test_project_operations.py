"""Project operations in the browser (issue 22, item 1): rename a POU everywhere with a preview and one
undo step, duplicate, change an empty POU's kind, delete with the list of what refers to it; the New POU
form starts from "program" and says what each kind is. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import _request, new_pou, open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "ops",
    "pous": [
        {
            "name": "Blink",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_INPUT\n    IN : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Q : BOOL;\nEND_VAR",
            "body": "Q := NOT IN;",
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    b : Blink;\n    lamp : BOOL;\nEND_VAR",
            "body": "b(IN := lamp);\nlamp := b.Q;",
        },
        {
            "name": "Lad",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    c : Blink;\n    x : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "label": "Blinker",
                        "elements": [
                            {"type": "box", "id": "box1", "call": "Blink", "instance": "c", "inputs": {"IN": "x"}},
                        ],
                    }
                ]
            },
        },
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "programs": ["Main", "Lad"]}],
}


def tree(page):
    return page.get_by_role("navigation", name="Project tree")


def menu_action(page, pou: str, action: str) -> None:
    tree(page).get_by_role("button", name=f"Actions for {pou}", exact=True).click()
    page.get_by_role("menu", name=f"{pou} actions", exact=True).get_by_role("menuitem", name=action).click()


def saved(server: str) -> dict:
    return _request("GET", f"{server}/api/projects/ops")["project"]


def test_rename_previews_every_use_applies_in_one_step_and_undoes(page, server: str, browser_errors) -> None:
    browser_errors.allow(r"422 \(Unprocessable Entity\) \(http://[^)]*/api/refactor/rename\)")  # the bad name below
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "ops", "Main")
    page.keyboard.press("Escape")

    menu_action(page, "Blink", "Rename…")
    dialog = page.get_by_role("dialog", name="Rename Blink")
    dialog.get_by_label("New name").fill("2x")
    dialog.get_by_role("button", name="Preview").click()
    dialog.get_by_role("alert").filter(has_text="2x is no IEC name").wait_for()
    dialog.get_by_label("New name").fill("Flash")
    dialog.get_by_role("button", name="Preview").click()
    references = dialog.get_by_role("list", name="References")
    references.wait_for()
    assert references.get_by_role("listitem").all_inner_texts() == [
        "Main, declarations line 2 b : Blink;",
        "Lad, declarations line 2 c : Blink;",
        'Lad, network 1 "Blinker" Blink',
    ]
    page.screenshot(path=str(ARTIFACTS / "project-ops-rename-preview.png"))
    dialog.get_by_role("button", name="Rename").click()
    assert dialog.count() == 0
    tree(page).get_by_role("button", name=re.compile("^Flash")).wait_for()
    assert tree(page).get_by_role("button", name=re.compile("^Blink")).count() == 0

    page.get_by_role("button", name="Undo rename Blink to Flash").click()
    tree(page).get_by_role("button", name=re.compile("^Blink")).wait_for()
    assert tree(page).get_by_role("button", name=re.compile("^Flash")).count() == 0

    menu_action(page, "Main", "Rename…")
    dialog = page.get_by_role("dialog", name="Rename Main")
    dialog.get_by_label("New name").fill("Plant")
    dialog.get_by_role("button", name="Preview").click()
    dialog.get_by_role("list", name="References").get_by_text("task Fast").wait_for()
    dialog.get_by_role("button", name="Rename").click()
    # the open tab follows the rename
    page.get_by_role("tab", name=re.compile("^Plant")).wait_for()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = saved(server)
    assert [p["name"] for p in project["pous"]] == ["Blink", "Plant", "Lad"]
    assert project["tasks"][0]["programs"] == ["Plant", "Lad"]


def test_duplicate_change_kind_and_delete_with_its_references(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "ops", "Lad")

    menu_action(page, "Blink", "Duplicate…")
    dialog = page.get_by_role("dialog", name="Duplicate Blink")
    assert dialog.get_by_label("Name of the copy").input_value() == "Blink_copy"
    dialog.get_by_role("button", name="Duplicate").click()
    page.get_by_role("tab", name=re.compile("^Blink_copy")).wait_for()

    # A non-empty POU keeps its kind; a new, empty one may change it.
    tree(page).get_by_role("button", name="Actions for Blink_copy").click()
    assert page.get_by_role("menuitem", name="Change kind…").is_disabled()
    page.get_by_role("button", name="Actions for Blink_copy").click()

    new_pou(page, "Helper", language="st", kind="function_block")
    page.get_by_label("Helper body").wait_for()
    page.get_by_role("button", name="New POU").click()
    assert page.get_by_label("POU kind").input_value() == "program"
    page.get_by_text("Runs in a task every cycle").wait_for()
    page.get_by_label("POU kind").select_option("function")
    page.get_by_text("Computes a result from its inputs").wait_for()
    page.get_by_role("form", name="New POU").get_by_role("button", name="Cancel").click()

    menu_action(page, "Helper", "Change kind…")
    dialog = page.get_by_role("dialog", name="Kind of Helper")
    dialog.get_by_label("POU kind").select_option("function")
    dialog.get_by_role("button", name="Change kind").click()
    functions = tree(page).locator("section").filter(has=page.get_by_role("heading", name="Functions"))
    functions.get_by_role("button", name=re.compile("^Helper")).wait_for()

    menu_action(page, "Blink", "Delete…")
    dialog = page.get_by_role("dialog", name="Delete Blink")
    items = dialog.get_by_role("list", name="References").get_by_role("listitem")
    items.first.wait_for()
    assert items.all_inner_texts() == [
        "Main, declarations line 2 b : Blink;",
        "Lad, declarations line 2 c : Blink;",
        'Lad, network 1 "Blinker" Blink',
    ]
    page.screenshot(path=str(ARTIFACTS / "project-ops-delete.png"))
    dialog.get_by_role("button", name="Cancel").click()

    menu_action(page, "Lad", "Delete…")
    dialog = page.get_by_role("dialog", name="Delete Lad")
    dialog.get_by_role("list", name="References").get_by_text("task Fast").wait_for()
    dialog.get_by_role("button", name="Delete Lad").click()
    assert page.get_by_role("tab", name=re.compile("^Lad")).count() == 0
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = saved(server)
    assert [(p["name"], p["kind"]) for p in project["pous"]] == [
        ("Blink", "function_block"),
        ("Blink_copy", "function_block"),
        ("Main", "program"),
        ("Helper", "function"),
    ]
