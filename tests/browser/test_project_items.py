"""Types and tasks deleted and duplicated from the project tree, and POUs named like the project's parts (issue 22,
item 1 and the Types/Tasks tab collision). Each operation is one undoable step of the working copy; the delete
dialog lists what refers to the type by POU and line. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, new_pou, new_project, store_project
from .test_project_operations import menu_action as menu
from .test_project_operations import tree

pytestmark = pytest.mark.browser

ITEMS = {
    "name": "items",
    "types": (
        "TYPE\n"
        "    Valve : (Shut, Open);\n"
        "    Line : STRUCT\n"
        "        Inlet : Valve;\n"
        "        Flow : REAL;\n"
        "    END_STRUCT;\n"
        "END_TYPE\n"
    ),
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    v : Valve;\n    d : Dosing;\nEND_VAR",
            "body": "d(Want := v);",
        },
        {
            "name": "Dosing",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_INPUT\n    Want : Valve;\nEND_VAR",
            "body": "",
        },
    ],
    "tasks": [
        {
            "name": "Fast",
            "interval": "T#10ms",
            "priority": 1,
            "programs": ["Main"],
        }
    ],
}


def stored(server: str) -> dict:
    return _request("GET", f"{server}/api/projects/items")["project"]


def test_a_type_deleted_and_duplicated_and_a_task_duplicated_from_the_tree_each_undone(page, server: str) -> None:
    store_project(server, ITEMS)
    before = stored(server)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^items")).click()
    user_types = tree(page).get_by_role("list", name="User types")
    names = user_types.locator(".tree-name")
    expect(names).to_have_text(["Valve", "Line"])

    # Delete Valve: the dialog lists every use (a STRUCT member, a variable, an FB's input pin), not its own line.
    menu(page, "type Valve", "Delete…")
    dialog = page.get_by_role("dialog", name="Delete type Valve")
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert places.all_inner_texts() == [
        "Types line 4 Inlet : Valve;",
        "Main, declarations line 2 v : Valve;",
        "Dosing, declarations line 2 Want : Valve;",
    ]
    expect(dialog).to_contain_text("These places use type Valve and will no longer compile:")
    page.screenshot(path=str(ARTIFACTS / "type-delete-references.png"))
    dialog.get_by_role("button", name="Delete type Valve").click()
    expect(names).to_have_text(["Line"])
    page.get_by_role("button", name="Undo delete type Valve").click()
    expect(names).to_have_text(["Valve", "Line"])

    # Duplicate Line: a free name is offered; the copy is declared right after the original.
    menu(page, "type Line", "Duplicate…")
    dialog = page.get_by_role("dialog", name="Duplicate type Line")
    expect(dialog.get_by_label("Name of the copy")).to_have_value("Line_copy")
    dialog.get_by_label("Name of the copy").fill("main")
    dialog.get_by_role("button", name="Duplicate").click()
    dialog.get_by_role("alert").filter(has_text="There is already a type or POU called Main.").wait_for()
    dialog.get_by_label("Name of the copy").fill("Line2")
    dialog.get_by_role("button", name="Duplicate").click()
    expect(names).to_have_text(["Valve", "Line", "Line2"])
    user_types.get_by_role("button", name="T Line2", exact=True).click()
    types_editor = page.get_by_role("region", name="Types editor")
    rows = types_editor.get_by_role("table", name="Types").locator("tbody tr")
    expect(rows).to_have_count(3)
    assert [r.split("\t")[:2] for r in rows.all_inner_texts()] == [
        ["Valve", "enumeration"],
        ["Line", "STRUCT"],
        ["Line2", "STRUCT"],
    ]
    page.get_by_role("button", name="Undo duplicate type Line").click()
    expect(names).to_have_text(["Valve", "Line"])

    # Duplicate the task Fast: the copy runs its own instance of Main under a new name.
    tasks = tree(page).get_by_role("region", name="Tasks")
    menu(page, "task Fast", "Duplicate…")
    dialog = page.get_by_role("dialog", name="Duplicate task Fast")
    expect(dialog.get_by_label("Name of the copy")).to_have_value("Fast_copy")
    dialog.get_by_role("button", name="Duplicate").click()
    expect(tasks.get_by_role("listitem")).to_have_text(
        [
            re.compile(r"^Fast every T#10ms · priority 1 · Main"),
            re.compile(r"^Fast_copy every T#10ms · priority 1 · Main_copy : Main"),
        ]
    )
    page.screenshot(path=str(ARTIFACTS / "task-duplicated.png"))
    page.get_by_role("button", name="Undo duplicate task Fast").click()
    expect(tasks.get_by_role("listitem")).to_have_text([re.compile(r"^Fast every T#10ms")])
    # Delete the task: nothing names a task, but its runs stop with it
    menu(page, "task Fast", "Delete…")
    dialog = page.get_by_role("dialog", name="Delete task Fast")
    expect(dialog).to_contain_text("Fast runs Main: those runs stop with it.")
    expect(dialog).to_contain_text("Nothing refers to task Fast.")
    dialog.get_by_role("button", name="Delete task Fast").click()
    expect(tasks.get_by_role("listitem")).to_have_count(0)
    page.get_by_role("button", name="Undo delete task Fast").click()
    expect(tasks.get_by_role("listitem")).to_have_text([re.compile(r"^Fast every T#10ms")])
    # the Tasks editor's Delete is one undoable step too
    tree(page).get_by_role("button", name=re.compile(r"^Tasks \d")).click()
    editor = page.get_by_role("region", name="Tasks editor")
    editor.get_by_role("button", name="Delete task Fast").click()
    expect(editor.get_by_role("row", name="Task Fast")).to_have_count(0)
    page.get_by_role("button", name="Undo delete task Fast").click()
    expect(editor.get_by_role("row", name="Task Fast")).to_have_count(1)

    # each undo gave the working copy back as it was: with the task duplicated once more and saved, the
    # project is the one stored at the start plus that copy
    menu(page, "task Fast", "Duplicate…")
    page.get_by_role("dialog", name="Duplicate task Fast").get_by_role("button", name="Duplicate").click()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    copy = {**before["tasks"][0], "name": "Fast_copy"}
    copy["programs"] = [{"name": "Main_copy", "type": "Main", "retain": None, "inputs": {}, "outputs": {}}]
    assert stored(server) == {**before, "tasks": [before["tasks"][0], copy]}


def test_pous_named_types_and_tasks_open_their_own_editors(page, server: str) -> None:
    """A POU may be called Types or Tasks (IEC identifiers); its tab is its own, beside the Types and Tasks
    editors, and survives a reload with them."""
    new_project(page, server, "clash")
    new_pou(page, "Types", language="st")
    page.get_by_label("Types body").wait_for()
    new_pou(page, "Tasks", language="st")
    page.get_by_label("Tasks body").wait_for()
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()

    tree(page).get_by_role("button", name=re.compile(r"^Types ST")).click()
    expect(page.get_by_label("Types body")).to_be_visible()
    tree(page).get_by_role("button", name=re.compile(r"^Types \d")).click()
    expect(page.get_by_role("region", name="Types editor")).to_be_visible()
    tree(page).get_by_role("button", name=re.compile(r"^Tasks ST")).click()
    expect(page.get_by_label("Tasks body")).to_be_visible()
    tree(page).get_by_role("button", name=re.compile(r"^Tasks default")).click()
    expect(page.get_by_role("region", name="Tasks editor")).to_be_visible()
    tabs = page.get_by_role("tablist", name="Open POUs").get_by_role("tab")
    expect(tabs).to_have_text(["Types", "Tasks", "Types", "Tasks"])
    page.screenshot(path=str(ARTIFACTS / "pous-named-types-and-tasks.png"))

    # each tab opens what it is
    tabs.nth(0).click()
    expect(page.get_by_label("Types body")).to_be_visible()
    tabs.nth(2).click()
    expect(page.get_by_role("region", name="Types editor")).to_be_visible()
    page.reload()
    expect(tabs).to_have_text(["Types", "Tasks", "Types", "Tasks"])
    tabs.nth(1).click()
    expect(page.get_by_label("Tasks body")).to_be_visible()
    tabs.nth(3).click()
    expect(page.get_by_role("region", name="Tasks editor")).to_be_visible()
