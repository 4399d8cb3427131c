"""A CFC chart in a real browser against a real server (issue 26 item 5, CFC-01, CFC-02).

Create a CFC program and draw ``count := count + 1; r := (count + 1) * 2`` on its one chart (no networks: the
network tools are gone; jumps go to label elements, test_cfc_jumps.py). Every executed element shows its execution order number;
"Run earlier" moves the MUL before the ADD that feeds it - which a CFC chart allows: the MUL then reads the
ADD's result of the previous scan, through ``count``. Three single cycles give count 3 and r 4 (scan k:
r = 2 * (k - 1)); the MUL's IN1 shows online what it read then, the previous scan's count (2), not the ADD's
value of this scan. Offline again, "Order by data flow" puts the MUL after the ADD (the old numbers breaking the
tie with the output ``count``); three cycles then give count 3 and r 6 (r = 2 * k).
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, new_pou, new_project, settled_scan_count
from .test_fbd_workflow import drag_to, drop_from_palette, handle, insert_block, name_and_declare

pytestmark = pytest.mark.browser


def badges(editor, expected: dict[str, str]) -> None:
    for node, number in expected.items():
        expect(editor.locator(f'.fbd-node[data-node="{node}"] .fbd-order')).to_have_text(number)


def cycles(page, count: int) -> None:
    for _ in range(count):
        before = settled_scan_count(page)
        page.get_by_role("button", name="Single cycle").click()
        page.wait_for_function(
            "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=before + 1
        )


def test_draw_reorder_and_run_a_cfc_chart(page, server):
    new_project(page, server, "chart")
    new_pou(page, "Main", language="cfc")
    editor = page.get_by_role("application", name="Continuous function chart editor")
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    toolbar = page.get_by_role("toolbar", name="FBD editing")
    expect(toolbar.get_by_role("button", name="Add network")).to_be_hidden()
    expect(toolbar.get_by_role("button", name="Jump", exact=True)).to_be_visible()  # jumps go to label elements
    expect(toolbar.get_by_role("button", name="Label", exact=True)).to_be_visible()

    drop_from_palette(page, "Input", canvas, 60, 30)
    name_and_declare(page, "Input operand", "count", "DINT")
    drop_from_palette(page, "Input", canvas, 60, 85)
    name_and_declare(page, "Input operand", "1", None)
    drop_from_palette(page, "Input", canvas, 260, 160)
    name_and_declare(page, "Input operand", "2", None)
    for call, x, y in (("ADD", 260, 30), ("MUL", 460, 160)):
        insert_block(page, canvas, call, x, y)
    drop_from_palette(page, "Output", canvas, 480, 30)
    name_and_declare(page, "Output variable", "count", None)
    drop_from_palette(page, "Output", canvas, 680, 170)
    name_and_declare(page, "Output variable", "r", "DINT")
    for src, dst in (
        ("in1", ("blk1", "in:IN1")),
        ("in2", ("blk1", "in:IN2")),
        ("blk1", ("out1", "in:IN")),
        ("blk1", ("blk2", "in:IN1")),
        ("in3", ("blk2", "in:IN2")),
        ("blk2", ("out2", "in:IN")),
    ):
        drag_to(page, handle(page, src, "out:OUT"), handle(page, *dst))
    assert editor.locator(".react-flow__edge").count() == 6

    # Numbers on the executed elements only (inputs are read where they are used), by position at first.
    badges(editor, {"blk1": "1", "out1": "2", "blk2": "3", "out2": "4"})
    expect(editor.locator('.fbd-node[data-node="in1"] .fbd-order')).to_have_count(0)

    # The MUL earlier, past the output and past the ADD feeding it (FBD would refuse the second move).
    editor.locator('.fbd-node[data-node="blk2"]').click()
    toolbar.get_by_role("button", name="Run earlier").click()
    badges(editor, {"blk1": "1", "blk2": "2", "out1": "3", "out2": "4"})
    toolbar.get_by_role("button", name="Run earlier").click()
    badges(editor, {"blk2": "1", "blk1": "2", "out1": "3", "out2": "4"})
    page.screenshot(path=str(ARTIFACTS / "cfc-reordered.png"))

    go_online(page, run=False)
    cycles(page, 3)
    page.get_by_test_id("value-out1").filter(has_text=re.compile("^3$")).wait_for()
    page.get_by_test_id("value-out2").filter(has_text=re.compile("^4$")).wait_for()
    # MUL.IN1 read the ADD's result of the previous scan (2), not its 3 of this scan: it shows the 2 it read
    mul = editor.locator('.fbd-node[data-node="blk2"]')
    mul.locator('[data-pin-value="out:OUT"]').filter(has_text=re.compile("^4$")).wait_for()
    assert mul.locator('[data-pin-value="in:IN2"]').text_content() == "2"
    assert mul.locator('[data-pin-value="in:IN1"]').text_content() == "2"
    page.screenshot(path=str(ARTIFACTS / "cfc-online.png"))

    state = page.get_by_role("status", name="Online state")
    page.get_by_role("button", name="Go offline", exact=True).click()
    state.filter(has_text=re.compile("^Offline")).wait_for()
    toolbar.get_by_role("button", name="Order by data flow").click()
    badges(editor, {"blk1": "1", "blk2": "2", "out1": "3", "out2": "4"})
    go_online(page, run=False)
    cycles(page, 3)
    page.get_by_test_id("value-out1").filter(has_text=re.compile("^3$")).wait_for()
    page.get_by_test_id("value-out2").filter(has_text=re.compile("^6$")).wait_for()
    mul.locator('[data-pin-value="in:IN1"]').filter(has_text=re.compile("^3$")).wait_for()  # this scan's now

    with urllib.request.urlopen(f"{server}/api/projects/chart") as response:
        main = json.load(response)["project"]["pous"][0]
    assert main["language"] == "cfc"
    assert [n["id"] for n in main["body"]["networks"]] == ["chart"]
    assert main["body"]["networks"][0]["order"] == ["blk1", "blk2", "out1", "out2"]
