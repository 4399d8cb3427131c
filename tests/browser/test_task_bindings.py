"""A program instance's parameter bindings edited in the Tasks editor (issue 22 item 2, CFG-06): ``PROGRAM P1
WITH Fast : Pump(Start := Go, Level := 5, Running => Out)`` built field by field, a binding of the wrong type
refused at its field by the live check, and the bound instance run: Out follows Go through Pump's body.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, store_project, watch

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "binds",
    "globals": "VAR_GLOBAL\n    Go : BOOL := TRUE;\n    Out : BOOL;\nEND_VAR",
    "pous": [
        {
            "name": "Pump",
            "kind": "program",
            "language": "st",
            "declarations": "VAR_INPUT\n    Start : BOOL;\n    Level : INT;\nEND_VAR\nVAR_OUTPUT\n    Running : BOOL;\nEND_VAR",
            "body": "Running := Start AND Level > 3;",
        }
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "programs": ["Pump"]}],
}


def test_program_instance_bindings_edited_validated_and_run(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^binds")).click()
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name="Tasks").click()
    editor = page.get_by_role("region", name="Tasks editor")
    editor.get_by_role("button", name="Parameters of Pump").click()
    params = editor.get_by_role("group", name=re.compile("^Parameters of "))
    params.get_by_label("Instance name").fill("P1")
    params.get_by_label("Start :=").fill("Go")
    # BOOL into the INT input Level: refused at that field, in words that name the input and the instance.
    params.get_by_label("Level :=").fill("Go")
    level = params.get_by_role("listitem").filter(has=page.get_by_label("Level :="))
    expect(level.get_by_role("alert")).to_contain_text(re.compile(r"Level of P1"))
    expect(params.get_by_label("Level :=")).to_have_attribute("aria-invalid", "true")
    page.screenshot(path=str(ARTIFACTS / "task-bindings-error.png"))
    params.get_by_label("Level :=").fill("5")
    expect(level.get_by_role("alert")).to_have_count(0)
    params.get_by_label("Running =>").fill("Out")
    expect(params.get_by_label("As ST")).to_have_text(
        "PROGRAM P1 WITH Fast : Pump(Start := Go, Level := 5, Running => Out);"
    )
    expect(editor.get_by_role("button", name="Parameters of P1 : Pump")).to_have_attribute("aria-expanded", "true")

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    [run] = _request("GET", f"{server}/api/projects/binds")["project"]["tasks"][0]["programs"]
    assert (run["name"], run["type"], run["inputs"], run["outputs"]) == (
        "P1",
        "Pump",
        {"Start": "Go", "Level": "5"},
        {"Running": "Out"},
    )

    # Online: Go is TRUE and Level 5 > 3, so Pump's Running, bound to Out, makes Out TRUE.
    go_online(page)
    expect(watch(page, "P1.Level")).to_have_text("5")
    expect(watch(page, "Out")).to_have_text("TRUE")


def test_a_task_renamed_from_the_project_tree(page, server: str) -> None:
    """Issue 22 item 1 for tasks: the tree's task has a ⋯ menu whose Rename refuses another task's name."""
    store_project(
        server,
        {**PROJECT, "name": "retask", "tasks": [*PROJECT["tasks"], {"name": "Slow", "interval": "T#100ms"}]},
    )
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^retask")).click()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Actions for task Fast").click()
    tree.get_by_role("menuitem", name="Rename…").click()
    dialog = page.get_by_role("dialog", name="Rename task Fast")
    dialog.get_by_label("New name").fill("slow")
    dialog.get_by_label("New name").press("Enter")
    expect(dialog.get_by_role("alert")).to_have_text("There is already a task called slow.")
    dialog.get_by_label("New name").fill("Quick")
    dialog.get_by_label("New name").press("Enter")
    expect(dialog).to_have_count(0)
    expect(tree.get_by_role("region", name="Tasks").get_by_role("listitem")).to_have_text(
        [re.compile(r"^Quick every T#10ms · priority 0 · Pump"), re.compile(r"^Slow every T#100ms")]
    )
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    tasks = _request("GET", f"{server}/api/projects/retask")["project"]["tasks"]
    assert [(t["name"], t["programs"]) for t in tasks] == [("Quick", ["Pump"]), ("Slow", [])]
