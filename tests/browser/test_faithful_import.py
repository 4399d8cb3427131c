"""Imports that look like their originals, in a real browser against a real server (issue 28).

OpenPLC's traffic light FBD is imported through the UI: its five free comment boxes are drawn where and as large
as the original draws them (text, place and size from the fixture's XML, read by hand), none merged into a network
comment, and every wire is an orthogonal path like the editor's own. A comment box added from the palette is saved
in the model. OpenPLC's Blink LD: its comment box is a comment network above the rung, and the rung reads left to
right as drawn (contact, TON, TOF, coil). The page fails the test on any page error or console error.
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import expect

from tests.interchange.test_plcopen_faithful import BLINK, TRAFFIC, TRAFFIC_COMMENTS
from tests.support import external

from .steps import new_project, open_pou
from .test_print_workflow import orthogonal

pytestmark = pytest.mark.browser


def import_file(page, source, name: str) -> None:
    page.get_by_role("button", name="Import PLCopen XML…").click()
    page.get_by_label("PLCopen XML file").set_input_files(str(source))
    page.get_by_label("New project name").fill(name)
    page.get_by_role("button", name="Import", exact=True).click()
    page.get_by_role("form", name="Import PLCopen XML").get_by_text(re.compile(f"^Imported {name}:")).wait_for()
    page.get_by_role("button", name=f"Open {name}").click()
    page.get_by_role("heading", name=name).wait_for()


def saved_project(server: str, name: str) -> dict:
    with urllib.request.urlopen(f"{server}/api/projects/{name}", timeout=30) as response:
        return json.load(response)["project"]


def test_imported_fbd_comment_boxes_and_wires_look_like_the_original(page, server):
    traffic = external(*TRAFFIC)
    new_project(page, server, "scratch")
    import_file(page, traffic, "traffic")
    open_pou(page, "traffic", "Trafic_light")
    editor = page.get_by_role("application", name="Function block diagram editor")
    notes = editor.locator(".fbd-node.fbd-comment")
    expect(notes).to_have_count(len(TRAFFIC_COMMENTS))
    editor.locator(".react-flow__edge").first.wait_for()

    # Each box where and as large as drawn: its top-left and size relative to the first box, at the canvas's zoom.
    boxes = [notes.nth(i).bounding_box() for i in range(len(TRAFFIC_COMMENTS))]
    texts = [notes.nth(i).inner_text().splitlines()[0].strip() for i in range(len(TRAFFIC_COMMENTS))]
    assert texts == [c[0] for c in TRAFFIC_COMMENTS]
    zoom = boxes[0]["width"] / TRAFFIC_COMMENTS[0][3]
    for box, (_, x, y, width, height) in zip(boxes, TRAFFIC_COMMENTS):
        drawn = (box["x"] - boxes[0]["x"], box["y"] - boxes[0]["y"], box["width"], box["height"])
        wanted = ((x - 50) * zoom, (y - 50) * zoom, width * zoom, height * zoom)
        assert all(abs(a - b) <= 2 for a, b in zip(drawn, wanted)), (drawn, wanted)
    expect(editor.locator(".fbd-network-comment")).to_have_text("")  # nothing merged into the network comment

    wires = editor.locator(".react-flow__edge path.react-flow__edge-path")
    paths = [wires.nth(i).get_attribute("d") for i in range(wires.count())]
    assert len(paths) >= 10 and all(orthogonal(d) for d in paths), [d for d in paths if not orthogonal(d)]

    # A comment box of one's own, from the palette, saved in the model.
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    toolbar = page.get_by_role("toolbar", name="FBD editing")
    toolbar.get_by_role("button", name="Comment box", exact=True).drag_to(canvas, target_position={"x": 40, "y": 20})
    page.get_by_role("combobox", name="Comment").press_sequentially("Checked on site")
    page.keyboard.press("Enter")
    expect(notes).to_have_count(len(TRAFFIC_COMMENTS) + 1)
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    pou = next(p for p in saved_project(server, "traffic")["pous"] if p["name"] == "Trafic_light")
    saved = [n["text"] for net in pou["body"]["networks"] for n in net["nodes"] if n["type"] == "comment"]
    assert len(saved) == len(TRAFFIC_COMMENTS) + 1 and "Checked on site" in saved


def test_imported_ld_comment_box_is_a_comment_network_above_the_rung_in_drawing_order(page, server):
    blink = external(*BLINK)
    new_project(page, server, "scratch")
    import_file(page, blink, "blink")
    open_pou(page, "blink", "Blink")
    networks = page.locator("svg.ld-network")
    expect(networks).to_have_count(2)
    assert "This example cascades two timers" in networks.nth(0).text_content()
    rung = networks.nth(1)

    # left to right as drawn: the contact blink_led, TON0, TOF0, the coil blink_led
    def left(name: str, nth: int = 0) -> float:
        return rung.get_by_text(name, exact=True).nth(nth).bounding_box()["x"]

    assert rung.get_by_text("blink_led", exact=True).count() == 2
    xs = [left("blink_led"), left("TON0"), left("TOF0"), left("blink_led", 1)]
    assert xs == sorted(xs) and len(set(xs)) == 4, xs
