"""An FBD feedback loop in a real browser against a real server (issue 22 item 6, IEC 61131-3 ed. 3 "feedback
paths").

Draw a counter whose ADD's output is wired back into its own IN1 (IN2 is ``1``) and whose result feeds a MUL by
``2`` into ``r``: no variable holds the count, the loop does (a feedback variable starting at 0). The loop wire
is routed around the ADD, not through it. Online, three single cycles give (scan k: ADD reads k - 1, returns k,
r = 2k) ADD.IN1 = 2, ADD.OUT = 3, r = 6: the input pin shows the value the block read, the previous scan's.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import go_online
from .test_cfc_workflow import cycles
from .test_fbd_workflow import drag_to, drop_from_palette, handle, insert_block, name_and_declare, new_fbd_network

pytestmark = pytest.mark.browser


def corners(path: str) -> list[tuple[float, float]]:
    """The points of an SVG ``M x y L x y ...`` path."""
    numbers = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", path)]
    return list(zip(numbers[::2], numbers[1::2]))


def test_draw_a_counter_loop_and_see_the_value_the_block_read(page, server):
    editor, canvas = new_fbd_network(page, server, "loop")

    drop_from_palette(page, "Input", canvas, 60, 110)
    name_and_declare(page, "Input operand", "1", None)
    drop_from_palette(page, "Input", canvas, 300, 150)
    name_and_declare(page, "Input operand", "2", None)
    for call, x, y in (("ADD", 200, 60), ("MUL", 440, 60)):
        insert_block(page, canvas, call, x, y)
    drop_from_palette(page, "Output", canvas, 660, 70)
    name_and_declare(page, "Output variable", "r", "INT")
    for src, dst in (
        ("blk1", ("blk1", "in:IN1")),  # the loop: ADD's output back into its own input
        ("in1", ("blk1", "in:IN2")),
        ("blk1", ("blk2", "in:IN1")),
        ("in2", ("blk2", "in:IN2")),
        ("blk2", ("out1", "in:IN")),
    ):
        drag_to(page, handle(page, src, "out:OUT"), handle(page, *dst))
    edges = editor.locator(".react-flow__edge")
    assert edges.count() == 5
    assert editor.get_by_role("alert").count() == 0

    # The loop wire leaves right of the ADD and comes back around it: no corner and no segment inside the block.
    add = editor.locator('.fbd-node[data-node="blk1"]').bounding_box()
    paths = [p.get_attribute("d") for p in edges.locator("path.react-flow__edge-path").all()]
    viewport = editor.locator(".react-flow__viewport").first.bounding_box()
    transform = editor.locator(".react-flow__viewport").first.get_attribute("style") or ""
    scale = float(m.group(1)) if (m := re.search(r"scale\(([\d.]+)\)", transform)) else 1.0
    # the loop is the one wire that ends left of where it starts
    loops = [c for c in map(corners, paths) if c[-1][0] < c[0][0]]
    assert len(loops) == 1, paths
    for x, y in loops[0]:
        px, py = viewport["x"] + x * scale, viewport["y"] + y * scale
        inside = add["x"] + 1 < px < add["x"] + add["width"] - 1 and add["y"] + 1 < py < add["y"] + add["height"] - 1
        assert not inside, (loops[0], add)
    xs = [viewport["x"] + x * scale for x, _ in loops[0]]
    assert max(xs) > add["x"] + add["width"] and min(xs) < add["x"]  # around the block, right and left of it
    page.screenshot(path=str(ARTIFACTS / "fbd-loop.png"))

    go_online(page, run=False)
    cycles(page, 3)
    page.get_by_test_id("value-out1").filter(has_text=re.compile("^6$")).wait_for()
    block = editor.locator('.fbd-node[data-node="blk1"]')
    block.locator('[data-pin-value="out:OUT"]').filter(has_text=re.compile("^3$")).wait_for()
    assert block.locator('[data-pin-value="in:IN1"]').text_content() == "2"  # what ADD read: the previous scan's
    assert block.locator('[data-pin-value="in:IN2"]').text_content() == "1"
    page.screenshot(path=str(ARTIFACTS / "fbd-loop-online.png"))
