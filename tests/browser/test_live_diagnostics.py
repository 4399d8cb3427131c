"""Live diagnostics in LD and Check/Compile of an unsaved project (issue 22, item 4): an LD element is
marked as soon as an edit breaks it, without saving; Check never saves; Compile & simulate with unsaved
changes asks: save and compile / compile the saved version / cancel.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import _request, open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "live",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    Start : BOOL;\n    Motor : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {"type": "contact", "id": "c1", "var": "Start"},
                            {"type": "coil", "id": "q1", "var": "Motor"},
                        ],
                    }
                ]
            },
        }
    ],
}


def saved_declarations(server: str) -> str:
    return _request("GET", f"{server}/api/projects/live")["project"]["pous"][0]["declarations"]


def test_an_ld_edit_is_checked_live_check_never_saves_and_compile_asks(page, server: str, browser_errors) -> None:
    # the last compile is of the broken version, which the server refuses (422) on purpose
    browser_errors.allow(r"422 \(Unprocessable Entity\) \(http://[^)]*/api/projects/live/simulations\)")
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "live", "Main")
    contact = page.locator('g.ld-element.ld-contact[data-id="c1"]')
    contact.wait_for()
    assert "ld-has-diagnostic" not in (contact.get_attribute("class") or "")

    views = page.get_by_role("tablist", name="Main views")
    views.get_by_role("tab", name="Declarations").click()
    page.get_by_role("button", name="Remove Start").click()
    views.get_by_role("tab", name="Diagram").click()
    # marked from the live check of the unsaved working copy
    page.locator('g.ld-element.ld-contact.ld-has-diagnostic[data-id="c1"]').wait_for()
    assert "ld-has-diagnostic" not in (page.locator('g.ld-element[data-id="q1"]').get_attribute("class") or "")
    page.screenshot(path=str(ARTIFACTS / "live-diagnostics-ld.png"))

    page.get_by_role("button", name="Check", exact=True).click()
    listed = page.get_by_role("list", name="Diagnostics").get_by_role("button")
    listed.filter(has_text="Start").first.wait_for()
    assert page.get_by_role("status").filter(has_text="Unsaved changes in Main").count() == 1
    assert "Start : BOOL" in saved_declarations(server)

    state = page.get_by_role("status", name="Online state")
    question = page.get_by_role("alertdialog", name="Unsaved changes")
    page.get_by_role("button", name="Compile & simulate").click()
    question.get_by_role("button", name="Cancel").click()
    assert question.count() == 0
    assert state.inner_text().strip() == "Offline"

    page.get_by_role("button", name="Compile & simulate").click()
    question.get_by_role("button", name="Compile the saved version").click()
    state.filter(has_text="Online · stopped").wait_for()
    assert "Start : BOOL" in saved_declarations(server)
    page.get_by_role("button", name="Go offline", exact=True).click()
    state.filter(has_text=re.compile("^Offline")).wait_for()

    page.get_by_role("button", name="Compile & simulate").click()
    question.get_by_role("button", name="Save and compile").click()
    page.get_by_text("All changes saved").wait_for()
    assert "Start" not in saved_declarations(server)
    page.get_by_role("list", name="Diagnostics").get_by_role("button").filter(has_text="Start").first.wait_for()
