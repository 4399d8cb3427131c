"""Room for the diagram at 1024x768 (issue 22, item 7): the project list, the project tree and the bottom
panels can be hidden and resized, the editor takes their room, and the layout is kept across a reload;
one compact row of icon tools per bar; the LD diagram zooms with Ctrl +/-/0, Ctrl+wheel and the toolbar,
an FBD network with Ctrl+wheel."""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

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
    projects_width = page.get_by_role("navigation", name="Projects").bounding_box()["width"]
    tree_width = page.get_by_role("navigation", name="Project tree").bounding_box()["width"]

    page.get_by_role("button", name="Hide projects").click()
    page.get_by_role("button", name="Hide project tree").click()
    page.get_by_role("button", name="Hide panels").click()
    assert page.get_by_role("navigation", name="Projects").count() == 0
    assert page.get_by_role("navigation", name="Project tree").count() == 0
    assert page.get_by_role("region", name="Panels").count() == 0
    after = editor_box(page)
    assert after["width"] >= before["width"] + projects_width + tree_width - 2  # the list's and the tree's columns
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


def _open_zoomed(page, server: str):
    """The ZOOMED project's Main open: its contact's hit area, that area's width at 100 %, the zoom button."""
    store_project(server, ZOOMED)
    page.goto(server)
    open_pou(page, "zoom", "Main")
    contact = page.locator('g.ld-element[data-id="c1"] rect.ld-hit')
    contact.wait_for()
    zoom = page.get_by_role("toolbar", name="LD editing").get_by_role("button", name="Zoom", exact=True)
    return contact, contact.bounding_box()["width"], zoom


def test_ld_zooms_with_ctrl_plus_minus_and_the_toolbar(page, server: str) -> None:
    contact, width, zoom = _open_zoomed(page, server)
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


def test_ld_zooms_with_ctrl_wheel_and_the_page_does_not(page, server: str) -> None:
    contact, width, zoom = _open_zoomed(page, server)
    contact.hover()
    page.keyboard.down("Control")
    page.mouse.wheel(0, -100)
    page.mouse.wheel(0, -100)
    page.mouse.wheel(0, -100)
    expect(zoom).to_have_text("130%")
    page.mouse.wheel(0, 100)
    page.keyboard.up("Control")
    expect(zoom).to_have_text("120%")
    assert abs(contact.bounding_box()["width"] - 1.2 * width) < 1.5
    assert page.evaluate("window.visualViewport.scale") == 1  # the browser's page zoom did not act
    page.mouse.wheel(0, 100)  # without Ctrl the wheel scrolls, the zoom stays
    expect(zoom).to_have_text("120%")


#: An FBD program of one input wired to one output (also the dark theme's FBD view, test_theme.py).
BLOCKS = {
    "name": "Blocks",
    "kind": "program",
    "language": "fbd",
    "declarations": "VAR a : BOOL; q : BOOL; END_VAR",
    "body": {
        "networks": [
            {
                "id": "n1",
                "nodes": [
                    {"type": "input", "id": "in1", "expr": "a", "pos": {"x": 20, "y": 20}},
                    {"type": "output", "id": "out1", "var": "q", "pos": {"x": 220, "y": 20}},
                ],
                "wires": [{"from": {"node": "in1", "pin": "OUT"}, "to": {"node": "out1", "pin": "IN"}}],
            }
        ]
    },
}

FBD = {"name": "fbdzoom", "pous": [BLOCKS]}


def test_an_fbd_network_zooms_with_ctrl_wheel(page, server: str) -> None:
    store_project(server, FBD)
    page.goto(server)
    open_pou(page, "fbdzoom", "Blocks")
    node = page.locator(".react-flow__node").first
    node.wait_for()
    width = node.bounding_box()["width"]
    node.hover()
    page.keyboard.down("Control")
    page.mouse.wheel(0, -200)
    page.keyboard.up("Control")
    page.wait_for_function(f"document.querySelector('.react-flow__node').getBoundingClientRect().width > {width} * 1.1")
    assert page.evaluate("window.visualViewport.scale") == 1


def test_side_panels_and_bottom_panels_keep_the_sizes_they_are_dragged_to(page, server: str) -> None:
    page.set_viewport_size({"width": 1440, "height": 900})
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "room", "Main")
    projects = page.get_by_role("navigation", name="Projects")
    tree = page.get_by_role("navigation", name="Project tree")
    panels = page.get_by_role("region", name="Panels")
    tree.wait_for()
    widths = projects.bounding_box()["width"], tree.bounding_box()["width"]
    height = panels.bounding_box()["height"]

    # the project list's edge dragged 60 px to the right
    edge = page.get_by_role("separator", name="Resize the project list").bounding_box()
    page.mouse.move(edge["x"] + edge["width"] / 2, edge["y"] + 200)
    page.mouse.down()
    page.mouse.move(edge["x"] + edge["width"] / 2 + 60, edge["y"] + 200, steps=4)
    page.mouse.up()
    # the tree's edge moved with the keyboard: two steps of 24 px narrower; the panels one step (24 px) higher
    page.get_by_role("separator", name="Resize the project tree").focus()
    page.keyboard.press("ArrowLeft")
    page.keyboard.press("ArrowLeft")
    page.get_by_role("separator", name="Resize the panels").focus()
    page.keyboard.press("ArrowUp")

    def sizes() -> tuple[float, float, float]:
        return projects.bounding_box()["width"], tree.bounding_box()["width"], panels.bounding_box()["height"]

    expected = (widths[0] + 60, widths[1] - 48, height + 24)
    assert all(abs(got - want) <= 2 for got, want in zip(sizes(), expected)), (sizes(), expected)
    page.reload()
    tree.wait_for()
    assert all(abs(got - want) <= 2 for got, want in zip(sizes(), expected)), (sizes(), expected)


def test_the_bars_are_one_compact_row_of_named_icons_at_1024x768(page, server: str) -> None:
    page.set_viewport_size({"width": 1024, "height": 768})
    store_project(server, ZOOMED)
    page.goto(server)
    open_pou(page, "zoom", "Main")
    toolbar = page.get_by_role("toolbar", name="LD editing")
    toolbar.wait_for()
    for bar in (page.locator(".header"), page.locator(".workspace-bar"), toolbar):
        assert bar.bounding_box()["height"] <= 36, bar
    # icons carry their name for screen readers and tests, and the shortcut in the tooltip
    contact = toolbar.get_by_role("button", name="Contact", exact=True)
    assert contact.locator("svg").count() == 1 and contact.inner_text() == ""
    assert contact.get_attribute("title") == "Contact (C)"
    # the diagram (below the tabs and the toolbar) keeps at least 60 % of the height with the panels hidden
    page.get_by_role("button", name="Hide projects").click()
    page.get_by_role("button", name="Hide panels").click()
    assert page.locator(".ld-editor").bounding_box()["height"] >= 0.6 * 768
    page.screenshot(path=str(ARTIFACTS / "layout-1024x768-compact.png"))
