"""Auto-arrange of an FBD network with a feedback loop in a real browser (issue 22 item 6): an accumulator whose
MUL output is wired back into the ADD feeding it, set to run ADD first (the network's order) but drawn in a
muddle (the MUL left of the ADD, the output left of both), is laid out by Auto-arrange with its data flow left
to right in that order (Step, ADD, MUL, Total), no two nodes overlapping, the loop's back wire (MUL back into
ADD, read from the previous scan) visible around the blocks, and the execution order kept.
Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import _request, open_pou, store_project
from .test_fbd_loop import corners

pytestmark = pytest.mark.browser


def wire(a: str, b: str, pin: str) -> dict:
    return {"from": {"node": a, "pin": "OUT"}, "to": {"node": b, "pin": pin}}


MUDDLE = {
    "name": "arrange",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR\n    Step : INT := 1;\n    Total : INT;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "order": ["add", "mul", "out"],
                        "nodes": [
                            {"type": "block", "id": "add", "call": "ADD", "pos": {"x": 420, "y": 20}},
                            {"type": "output", "id": "out", "var": "Total", "pos": {"x": 20, "y": 160}},
                            {"type": "block", "id": "mul", "call": "MUL", "pos": {"x": 40, "y": 20}},
                            {"type": "input", "id": "in", "expr": "Step", "pos": {"x": 620, "y": 120}},
                            {"type": "input", "id": "k", "expr": "2", "pos": {"x": 250, "y": 200}},
                        ],
                        "wires": [
                            wire("in", "add", "IN1"),
                            wire("add", "mul", "IN1"),
                            wire("k", "mul", "IN2"),
                            wire("mul", "out", "IN"),
                            wire("mul", "add", "IN2"),
                        ],
                    }
                ]
            },
        }
    ],
}


def overlap(a: dict, b: dict) -> bool:
    return (
        a["x"] < b["x"] + b["width"]
        and b["x"] < a["x"] + a["width"]
        and a["y"] < b["y"] + b["height"]
        and b["y"] < a["y"] + a["height"]
    )


def test_auto_arrange_lays_a_loop_out_left_to_right_with_its_back_wire_around(page, server):
    store_project(server, MUDDLE)
    page.goto(server)
    open_pou(page, "arrange", "Main")
    editor = page.get_by_role("application", name="Function block diagram editor")
    editor.locator('.fbd-node[data-node="add"]').wait_for()
    page.screenshot(path=str(ARTIFACTS / "fbd-arrange-loop-before.png"))
    editor.get_by_role("button", name=re.compile("^Auto-arrange")).click()

    ids = ("in", "k", "add", "mul", "out")
    node = {i: editor.locator(f'.fbd-node[data-node="{i}"]') for i in ids}
    page.wait_for_function(
        "() => { const a = document.querySelector('.fbd-node[data-node=\"add\"]').getBoundingClientRect();"
        " const m = document.querySelector('.fbd-node[data-node=\"mul\"]').getBoundingClientRect();"
        " return a.x < m.x; }"
    )
    box = {i: node[i].bounding_box() for i in ids}
    assert box["in"]["x"] < box["add"]["x"] < box["mul"]["x"] < box["out"]["x"], box
    assert box["k"]["x"] < box["mul"]["x"], box
    for a in ids:
        for b in ids:
            assert a == b or not overlap(box[a], box[b]), (a, b, box)

    # the back wire is the only one ending left of where it starts; it runs around ADD and MUL, inside the canvas
    edges = editor.locator(".react-flow__edge path.react-flow__edge-path")
    viewport = editor.locator(".react-flow__viewport").first
    origin = viewport.bounding_box()
    transform = viewport.get_attribute("style") or ""
    scale = float(m.group(1)) if (m := re.search(r"scale\(([\d.]+)\)", transform)) else 1.0
    paths = [corners(p.get_attribute("d") or "") for p in edges.all()]
    loops = [c for c in paths if c[-1][0] < c[0][0]]
    assert len(loops) == 1, paths
    points = [(origin["x"] + x * scale, origin["y"] + y * scale) for x, y in loops[0]]
    for px, py in points:
        for i in ("add", "mul"):
            b = box[i]
            assert not (b["x"] + 1 < px < b["x"] + b["width"] - 1 and b["y"] + 1 < py < b["y"] + b["height"] - 1)
    pane = editor.locator(".fbd-network").first.bounding_box()
    assert all(pane["y"] <= py <= pane["y"] + pane["height"] for _, py in points), (points, pane)
    page.screenshot(path=str(ARTIFACTS / "fbd-arrange-loop.png"))

    # the order runs the loop as before: ADD, MUL, then the output
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    saved = _request("GET", f"{server}/api/projects/arrange")["project"]
    assert saved["pous"][0]["body"]["networks"][0]["order"] == ["add", "mul", "out"]
