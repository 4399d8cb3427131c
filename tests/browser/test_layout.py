"""Room for the diagram at 1024x768 (issue 22, item 7): the project list, the project tree and the bottom
panels can be hidden, the editor takes their room, and the layout is kept across a reload."""

from __future__ import annotations

import pytest

from .conftest import ARTIFACTS
from .steps import open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {"name": "room", "pous": [{"name": "Main", "kind": "program", "language": "ld", "body": {"networks": []}}]}


def editor_box(page) -> dict:
    return page.locator(".editor-area").bounding_box()


def test_hidden_panels_give_the_editor_their_room_and_stay_hidden(page, server: str) -> None:
    page.set_viewport_size({"width": 1024, "height": 768})
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "room", "Main")
    page.get_by_role("tab", name="Main").wait_for()
    before = editor_box(page)

    page.get_by_role("button", name="Hide projects").click()
    page.get_by_role("button", name="Hide project tree").click()
    page.get_by_role("button", name="Hide panels").click()
    assert page.get_by_role("navigation", name="Projects").count() == 0
    assert page.get_by_role("navigation", name="Project tree").count() == 0
    assert page.get_by_role("region", name="Panels").count() == 0
    after = editor_box(page)
    assert after["width"] >= before["width"] + 280 + 240 - 2  # the list's and the tree's columns
    assert after["height"] > before["height"] + 100
    assert after["height"] >= 0.6 * 768
    page.screenshot(path=str(ARTIFACTS / "layout-1024x768-hidden-panels.png"))

    page.reload()
    page.get_by_role("button", name="Show projects").wait_for()
    page.get_by_role("button", name="Show project tree").wait_for()
    page.get_by_role("button", name="Show panels").click()
    page.get_by_role("region", name="Panels").wait_for()


ZOOMED = {
    "name": "zoom",
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


def test_ld_zooms_with_ctrl_plus_minus_and_the_toolbar(page, server: str) -> None:
    store_project(server, ZOOMED)
    page.goto(server)
    open_pou(page, "zoom", "Main")
    contact = page.locator('g.ld-element[data-id="c1"] rect.ld-hit')
    contact.wait_for()
    width = contact.bounding_box()["width"]
    zoom = page.get_by_role("group", name="Zoom").get_by_role("button", name="Zoom")
    assert zoom.inner_text() == "100%"

    contact.click()  # the editor has the keyboard
    page.keyboard.press("Control+=")
    page.keyboard.press("Control+=")
    assert zoom.inner_text() == "120%"
    assert abs(contact.bounding_box()["width"] - 1.2 * width) < 1.5
    page.keyboard.press("Control+-")
    assert zoom.inner_text() == "110%"
    zoom.click()
    assert zoom.inner_text() == "100%"
    assert abs(contact.bounding_box()["width"] - width) < 1.5
