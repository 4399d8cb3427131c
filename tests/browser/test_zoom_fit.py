"""Zoom to fit (issue 22 item 7) in the LD, FBD and SFC editors: a diagram larger than the view, after the
toolbar's "Zoom to fit" or Ctrl+Shift+H, lies wholly inside the view (its bounding box within the scroll
area, or within each network's canvas in FBD), at a zoom the toolbar shows where it has one.
"""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from .steps import open_pou, store_project

pytestmark = pytest.mark.browser

BOOLS = "VAR\n" + "".join(f"  x{i} : BOOL;\n" for i in range(30)) + "END_VAR"


def _ld_body() -> dict:
    """12 networks of five contacts and a coil: taller than the view at 100 %."""

    def network(i: int) -> dict:
        contacts = [{"type": "contact", "id": f"c{i}_{k}", "var": f"x{(i + k) % 30}"} for k in range(5)]
        return {"id": f"n{i}", "elements": [*contacts, {"type": "coil", "id": f"q{i}", "var": f"x{i}"}]}

    return {"networks": [network(i) for i in range(12)]}


def _fbd_body() -> dict:
    """One network whose output stands 1,600 px to the right: wider than its canvas at zoom 1."""
    return {
        "networks": [
            {
                "id": "n1",
                "nodes": [
                    {"type": "input", "id": "a", "expr": "x1", "pos": {"x": 20, "y": 20}},
                    {"type": "input", "id": "b", "expr": "x2", "pos": {"x": 20, "y": 90}},
                    {"type": "block", "id": "and1", "call": "AND", "pos": {"x": 700, "y": 20}},
                    {"type": "output", "id": "q", "var": "x3", "pos": {"x": 1600, "y": 40}},
                ],
                "wires": [
                    {"from": {"node": "a", "pin": "OUT"}, "to": {"node": "and1", "pin": "IN1"}},
                    {"from": {"node": "b", "pin": "OUT"}, "to": {"node": "and1", "pin": "IN2"}},
                    {"from": {"node": "and1", "pin": "OUT"}, "to": {"node": "q", "pin": "IN"}},
                ],
            }
        ]
    }


def _sfc_body() -> dict:
    """Five steps in sequence, a jump back: taller than the view at 100 %."""
    elements: list[dict] = []
    for i in range(5):
        elements.append({"type": "step", "id": f"s{i}", "name": f"Step{i}", "actions": []})
        elements.append({"type": "transition", "id": f"t{i}", "condition": f"x{i}"})
    elements.append({"type": "jump", "id": "j", "target": "Step0"})
    return {"chart": {"elements": elements}}


def _project() -> dict:
    pou = {"kind": "program", "declarations": BOOLS}
    return {
        "name": "zoomfit",
        "pous": [
            {**pou, "name": "Ladder", "language": "ld", "body": _ld_body()},
            {**pou, "name": "Blocks", "language": "fbd", "body": _fbd_body()},
            {**pou, "name": "Chart", "language": "sfc", "body": _sfc_body()},
        ],
    }


def _inside(inner: dict, outer: dict) -> bool:
    return (
        inner["x"] >= outer["x"] - 0.5
        and inner["y"] >= outer["y"] - 0.5
        and inner["x"] + inner["width"] <= outer["x"] + outer["width"] + 0.5
        and inner["y"] + inner["height"] <= outer["y"] + outer["height"] + 0.5
    )


def _fits(editor, toolbar: str, diagram, view, zoom, reset_key: str, actual_size: str) -> None:
    """``diagram`` overflows ``view`` at 100 %; the toolbar's "Zoom to fit" puts it wholly inside, ``reset_key``
    goes back to 100 % (``zoom`` shows ``actual_size``), and Ctrl+Shift+H fits it again."""
    assert not _inside(diagram.bounding_box(), view.bounding_box())
    editor.get_by_role("toolbar", name=toolbar).get_by_role("button", name="Zoom to fit").click()
    expect(zoom).not_to_have_text(actual_size)
    assert _inside(diagram.bounding_box(), view.bounding_box())
    editor.press(reset_key)
    expect(zoom).to_have_text(actual_size)
    assert not _inside(diagram.bounding_box(), view.bounding_box())
    editor.press("Control+Shift+H")
    expect(zoom).not_to_have_text(actual_size)
    assert _inside(diagram.bounding_box(), view.bounding_box())


def test_ld_zoom_to_fit_shows_every_network(page, server):
    store_project(server, _project())
    page.goto(server)
    open_pou(page, "zoomfit", "Ladder")
    editor = page.get_by_role("application", name="Ladder diagram editor")
    editor.locator("g.ld-element.ld-coil").first.wait_for()
    zoom = editor.get_by_role("button", name="Zoom", exact=True)
    _fits(editor, "LD editing", editor.locator(".ld-canvas"), editor.locator(".ld-scroller"), zoom, "Control+0", "100%")
    expect(editor.locator("g.ld-element.ld-coil")).to_have_count(12)  # every network drawn


def test_fbd_zoom_to_fit_shows_every_node_of_each_network(page, server):
    store_project(server, _project())
    page.goto(server)
    open_pou(page, "zoomfit", "Blocks")
    editor = page.get_by_role("application", name="Function block diagram editor")
    pane = editor.locator(".fbd-network .fbd-canvas").first
    output = editor.locator('.fbd-node[data-node="q"]')
    editor.locator('.fbd-node[data-node="and1"]').wait_for()
    assert not _inside(output.bounding_box(), pane.bounding_box())  # right of the canvas at zoom 1

    editor.get_by_role("toolbar", name="FBD editing").get_by_role("button", name="Zoom to fit").click()
    for node in ("a", "b", "and1", "q"):
        locator = editor.locator(f'.fbd-node[data-node="{node}"]')
        expect(locator).to_be_visible()
        page.wait_for_function(
            """([node]) => {
                const box = document.querySelector(`.fbd-node[data-node="${node}"]`).getBoundingClientRect();
                const pane = document.querySelector(".fbd-network .fbd-canvas").getBoundingClientRect();
                return box.left >= pane.left && box.right <= pane.right && box.top >= pane.top && box.bottom <= pane.bottom;
            }""",
            arg=[node],
        )
        assert _inside(locator.bounding_box(), pane.bounding_box()), node

    # The key does the same after the canvas was zoomed in by hand (Ctrl+wheel over the canvas).
    pane.hover()
    page.keyboard.down("Control")
    page.mouse.wheel(0, -600)
    page.keyboard.up("Control")
    page.wait_for_function(
        """() => {
            const box = document.querySelector('.fbd-node[data-node="q"]').getBoundingClientRect();
            const pane = document.querySelector(".fbd-network .fbd-canvas").getBoundingClientRect();
            return box.right > pane.right || box.left < pane.left;
        }"""
    )
    editor.locator(".fbd-network-header").first.click()  # the keys go to the editor, not the canvas
    editor.press("Control+Shift+H")
    page.wait_for_function(
        """() => {
            const box = document.querySelector('.fbd-node[data-node="q"]').getBoundingClientRect();
            const pane = document.querySelector(".fbd-network .fbd-canvas").getBoundingClientRect();
            return box.left >= pane.left && box.right <= pane.right;
        }"""
    )


def test_sfc_zoom_to_fit_shows_the_whole_chart(page, server):
    store_project(server, _project())
    page.goto(server)
    open_pou(page, "zoomfit", "Chart")
    editor = page.get_by_role("application", name="Sequential function chart editor")
    chart = editor.locator("svg.sfc-canvas")
    chart.wait_for()
    _fits(
        editor,
        "SFC editing",
        chart,
        editor.locator(".sfc-scroll"),
        editor.get_by_label("Zoom", exact=True),
        "0",
        "100 %",
    )
