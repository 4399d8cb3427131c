"""Global variables, types and tasks edited in the browser (issue 22, item 2): the globals in the
declarations table and text of the POUs, a STRUCT added from the Types editor, a task with its
interval and programs; each part's live-check errors shown where they are; saved and run.
Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import pytest

from .conftest import ARTIFACTS
from .steps import _request, go_online, new_pou, new_project

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
    assert rows.all_inner_texts() == ["Cell\tSTRUCT"]
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
