"""A CFC jump and label drawn and run in a real browser (issue 26 item 5, CFC-02).

The chart, by execution order number: 1 LT(n, 3), 2 jump to Over when it is TRUE, 3 y := n, 4 label Over,
5 ADD(n, 1), 6 n := the sum. Worked out by hand: while n < 3 the jump skips y := n, so after scans 1..3
n = 1, 2, 3 and y stays 0 (the output y is shown not executed, the jump shows TRUE); in scan 4 n = 3 is not
below 3: y := 3 runs, n = 4, the jump shows FALSE.
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, new_pou, new_project
from .test_cfc_workflow import badges, cycles
from .test_fbd_workflow import drag_to, drop_from_palette, handle, insert_block, name_and_declare

pytestmark = pytest.mark.browser


def test_draw_a_jump_and_a_label_and_run_the_chart_CFC_02(page, server):
    new_project(page, server, "jumps")
    new_pou(page, "Main", language="cfc")
    editor = page.get_by_role("application", name="Continuous function chart editor")
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    toolbar = page.get_by_role("toolbar", name="FBD editing")

    drop_from_palette(page, "Input", canvas, 60, 30)
    name_and_declare(page, "Input operand", "n", "INT")
    drop_from_palette(page, "Input", canvas, 60, 85)
    name_and_declare(page, "Input operand", "3", None)
    insert_block(page, canvas, "LT", 260, 30)
    drop_from_palette(page, "Jump", canvas, 460, 40)
    name_and_declare(page, "Jump target", "Over", None)
    drop_from_palette(page, "Input", canvas, 60, 160)
    name_and_declare(page, "Input operand", "n", None)
    drop_from_palette(page, "Output", canvas, 260, 160)
    name_and_declare(page, "Output variable", "y", "INT")
    drop_from_palette(page, "Label", canvas, 60, 230)
    name_and_declare(page, "Label name", "Over", None)
    drop_from_palette(page, "Input", canvas, 60, 300)
    name_and_declare(page, "Input operand", "n", None)
    drop_from_palette(page, "Input", canvas, 60, 355)
    name_and_declare(page, "Input operand", "1", None)
    insert_block(page, canvas, "ADD", 260, 300)
    drop_from_palette(page, "Output", canvas, 460, 310)
    name_and_declare(page, "Output variable", "n", None)
    for src, dst in (
        ("in1", ("blk1", "in:IN1")),
        ("in2", ("blk1", "in:IN2")),
        ("blk1", ("jump1", "in:IN")),
        ("in3", ("out1", "in:IN")),
        ("in4", ("blk2", "in:IN1")),
        ("in5", ("blk2", "in:IN2")),
        ("blk2", ("out2", "in:IN")),
    ):
        drag_to(page, handle(page, src, "out:OUT"), handle(page, *dst))
    assert editor.locator(".react-flow__edge").count() == 7
    expect(editor.locator('.fbd-node[data-node="label1"]')).to_contain_text("Over")

    # Unnumbered, the jump and the label run last; moved to their places by "Run earlier".
    badges(editor, {"blk1": "1", "out1": "2", "blk2": "3", "out2": "4", "jump1": "5", "label1": "6"})
    for node, steps in (("jump1", (4, 3, 2)), ("label1", (5, 4))):
        editor.locator(f'.fbd-node[data-node="{node}"]').click()
        for number in steps:  # each move waits for the numbers the server reports for the last one
            toolbar.get_by_role("button", name="Run earlier").click()
            badges(editor, {node: str(number)})
    badges(editor, {"blk1": "1", "jump1": "2", "out1": "3", "label1": "4", "blk2": "5", "out2": "6"})
    page.screenshot(path=str(ARTIFACTS / "cfc-jump-drawn.png"))

    go_online(page, run=False)
    cycles(page, 3)
    page.get_by_test_id("value-out2").filter(has_text=re.compile("^3$")).wait_for()
    expect(page.get_by_test_id("value-out1")).to_have_text("0")
    expect(page.get_by_test_id("value-jump1")).to_have_text("TRUE")  # n = 2 < 3 in scan 3: taken
    expect(editor.locator('.fbd-node[data-node="out1"]')).to_have_class(re.compile(r"\bfbd-skipped\b"))
    expect(editor.locator('.fbd-node[data-node="blk2"]')).not_to_have_class(re.compile(r"\bfbd-skipped\b"))
    page.screenshot(path=str(ARTIFACTS / "cfc-jump-online.png"))

    cycles(page, 1)
    page.get_by_test_id("value-out2").filter(has_text=re.compile("^4$")).wait_for()
    expect(page.get_by_test_id("value-out1")).to_have_text("3")
    expect(page.get_by_test_id("value-jump1")).to_have_text("FALSE")
    expect(editor.locator('.fbd-node[data-node="out1"]')).not_to_have_class(re.compile(r"\bfbd-skipped\b"))

    with urllib.request.urlopen(f"{server}/api/projects/jumps") as response:
        chart = json.load(response)["project"]["pous"][0]["body"]["networks"][0]
    assert chart["order"] == ["blk1", "jump1", "out1", "label1", "blk2", "out2"]
    assert {n["id"]: n.get("name") or n.get("target") for n in chart["nodes"] if n["type"] in ("jump", "label")} == {
        "jump1": "Over",
        "label1": "Over",
    }
