"""Global variables, types and tasks edited in the browser (issue 22, item 2): the globals in the
declarations table and text of the POUs, a STRUCT added from the Types editor, a task with its
interval and programs; each part's live-check errors shown where they are; saved and run.
Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, new_pou, new_project, store_project

pytestmark = pytest.mark.browser


def open_part(page, part: str) -> None:
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=part).click()


def test_globals_types_and_a_task_built_in_the_browser_compile_and_run(page, server: str) -> None:
    new_project(page, server, "parts")
    new_pou(page, "Main", language="st", kind="program")
    page.get_by_label("Main body").wait_for()

    open_part(page, "Global variables")
    globals_editor = page.get_by_role("region", name="Global variables editor")
    globals_editor.get_by_role("button", name="Add variable").click()
    globals_editor.get_by_label("Name of NewVar").fill("Speed")
    globals_editor.get_by_label("Type of Speed").fill("INTT")
    globals_editor.get_by_role("tab", name="Text").click()
    assert globals_editor.get_by_label("Declarations text").input_value() == "VAR_GLOBAL\n    Speed : INTT;\nEND_VAR"
    problems = globals_editor.get_by_role("list", name="Declaration problems")
    problems.get_by_text("line 2: unknown type 'INTT' - did you mean 'INT'?").wait_for()
    globals_editor.get_by_label("Declarations text").fill("VAR_GLOBAL\n    Speed : INT;\nEND_VAR")
    problems.wait_for(state="detached")

    open_part(page, "Types")
    types_editor = page.get_by_role("region", name="Types editor")
    types_editor.get_by_label("Type name").fill("Cell")
    types_editor.get_by_label("Type kind").select_option(label="STRUCT")
    types_editor.get_by_role("button", name="Add type").click()
    rows = types_editor.get_by_role("table", name="Types").locator("tbody tr")
    assert [r.split("\t")[:2] for r in rows.all_inner_texts()] == [["Cell", "STRUCT"]]
    types_editor.get_by_label("Type name").fill("cell")
    types_editor.get_by_role("button", name="Add type").click()
    types_editor.get_by_role("alert").filter(has_text="There is already a type called cell.").wait_for()
    page.screenshot(path=str(ARTIFACTS / "project-parts-types.png"))

    open_part(page, "Tasks")
    tasks_editor = page.get_by_role("region", name="Tasks editor")
    tasks_editor.get_by_role("button", name="New task").click()
    task = tasks_editor.get_by_role("row", name="Task Task1")
    task.get_by_label("Interval").fill("T#xx")
    task.get_by_role("alert").filter(
        has_text="task Task1: interval 'T#xx' is not a TIME literal such as T#10ms"
    ).wait_for()
    task.get_by_label("Interval").fill("T#20ms")
    task.get_by_label("Add a program to Task1").select_option("Main")
    task.get_by_role("alert").wait_for(state="detached")
    assert task.get_by_role("list", name="Programs of Task1").get_by_role("listitem").all_inner_texts() == ["Main↑↓×"]
    page.screenshot(path=str(ARTIFACTS / "project-parts-tasks.png"))

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    project = _request("GET", f"{server}/api/projects/parts")["project"]
    assert project["globals"] == "VAR_GLOBAL\n    Speed : INT;\nEND_VAR"
    assert project["types"] == "TYPE\n    Cell : STRUCT\n        Member : BOOL;\n    END_STRUCT;\nEND_TYPE"
    [task] = project["tasks"]
    assert (task["name"], task["interval"], task["priority"], task["programs"]) == ("Task1", "T#20ms", 0, ["Main"])
    assert task["single"] is None
    go_online(page)


RENAMES = {
    "name": "renames",
    "globals": "VAR_GLOBAL\n    Speed : INT;\nEND_VAR",
    "types": "TYPE\n    Point : STRUCT\n        x : INT;\n    END_STRUCT;\nEND_TYPE",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    p : Point;\nEND_VAR",
            "body": "p.x := Speed;",
        },
        {
            "name": "Lad",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    q : Point;\n    High : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {"type": "compare", "id": "c1", "op": "GT", "left": "Speed", "right": "3"},
                            {"type": "coil", "id": "q1", "var": "High"},
                        ],
                    }
                ]
            },
        },
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "programs": ["Main", "Lad"]}],
}


def test_a_global_and_a_type_renamed_everywhere_and_a_struct_edited_as_a_table(page, server: str) -> None:
    """Issue 22 items 1-2: "Rename everywhere" on a global's row and on a type previews every use (the ST body,
    the LD compare's operand, the declarations) and applies them in one step; the STRUCT's members are a
    table whose edits rewrite the TYPE text; the renamed project compiles and saves."""
    store_project(server, RENAMES)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^renames")).click()
    open_part(page, "Global variables")
    page.get_by_role("region", name="Global variables editor").get_by_role(
        "button", name="Rename Speed everywhere"
    ).click()
    dialog = page.get_by_role("dialog", name="Rename Speed")
    dialog.get_by_label("New name").fill("Velocity")
    dialog.get_by_role("button", name="Preview").click()
    places = dialog.get_by_role("list", name="References").locator("li")
    places.first.wait_for()
    assert sorted(places.all_inner_texts()) == [
        "Global variables line 2 Speed : INT;",
        "Lad, network 1 Speed",
        "Main, body line 1 p.x := Speed;",
    ]
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)

    open_part(page, "Types")
    types_editor = page.get_by_role("region", name="Types editor")
    types_editor.get_by_role("button", name="Rename Point everywhere").click()
    dialog = page.get_by_role("dialog", name="Rename Point")
    dialog.get_by_label("New name").fill("Coord")
    dialog.get_by_role("button", name="Preview").click()
    dialog.get_by_role("list", name="References").locator("li").first.wait_for()
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)

    # Coord's members as a table: x becomes a DINT with an initial value, a member y is added.
    types_editor.get_by_role("button", name="Coord", exact=True).click()
    members = types_editor.get_by_role("table", name="Members of Coord")
    members.get_by_label("Type of member 1").fill("DINT")
    members.get_by_label("Initial value of member 1").fill("7")
    types_editor.get_by_role("button", name="Add member").click()
    members.get_by_label("Name of member 2").fill("y")
    page.screenshot(path=str(ARTIFACTS / "types-struct-members.png"))

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    saved = _request("GET", f"{server}/api/projects/renames")["project"]
    assert saved["globals"] == "VAR_GLOBAL\n    Velocity : INT;\nEND_VAR"
    assert saved["types"] == (
        "TYPE\n    Coord : STRUCT\n        x : DINT := 7;\n        y : BOOL;\n    END_STRUCT;\nEND_TYPE"
    )
    main, lad = saved["pous"]
    assert (main["declarations"], main["body"]) == ("VAR\n    p : Coord;\nEND_VAR", "p.x := Velocity;")
    assert lad["declarations"] == "VAR\n    q : Coord;\n    High : BOOL;\nEND_VAR"
    assert lad["body"]["networks"][0]["elements"][0]["left"] == "Velocity"
    check = _request("POST", f"{server}/api/projects/renames/check")
    assert [d for d in check["diagnostics"] if d.get("severity", "error") == "error"] == []
