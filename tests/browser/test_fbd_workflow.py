"""The new user's FBD workflow in a real browser against a real server (issue 9, "Tests").

Create an FBD program and build ``result := (var1 + var2) - var3``: drag input, block and
output nodes from the palette onto the network, pick ADD and SUB in the block picker, declare
the variables through the editor's offer, move a node by dragging it, wire the pins with the mouse (a second wire into an
occupied input is refused with the reason), save, compile and run, write var1..var3 from the
input nodes' context menus, read the result at the block pins and the output node, and halt at a
breakpoint on the network and on the SUB block. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import json
import urllib.request

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import new_pou, new_project

pytestmark = pytest.mark.browser


def handle(page, node: str, handle_id: str):
    return page.locator(f'.react-flow__handle[data-nodeid="{node}"][data-handleid="{handle_id}"]')


def drag_to(page, source, target) -> None:
    """Press on ``source``, move in steps (xyflow tracks the pointer) and release on ``target``."""
    source.hover()
    page.mouse.down()
    box = target.bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2, steps=8)
    page.mouse.up()


def drop_from_palette(page, label: str, canvas, x: int, y: int) -> None:
    page.get_by_role("toolbar", name="FBD editing").get_by_role("button", name=label, exact=True).drag_to(
        canvas, target_position={"x": x, "y": y}
    )


def insert_block(page, canvas, call: str, x: int, y: int) -> None:
    """Drops a block from the palette at (x, y) and picks ``call`` in the block picker."""
    drop_from_palette(page, "Block…", canvas, x, y)
    picker = page.get_by_role("dialog", name="Insert block")
    picker.get_by_label("Search functions and function blocks").press_sequentially(call)
    picker.get_by_role("option", name=f"{call} ").first.wait_for()
    page.keyboard.press("Enter")


def new_fbd_network(page, server: str, project: str):
    """A new project with an FBD program Main and one network: (editor, the network's canvas)."""
    new_project(page, server, project)
    new_pou(page, "Main", language="fbd")
    editor = page.get_by_role("application", name="Function block diagram editor")
    editor.get_by_role("button", name="Add network").click()
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    return editor, canvas


def name_and_declare(page, label: str, name: str, declare_as: str | None) -> None:
    page.get_by_role("combobox", name=label).press_sequentially(name)
    page.keyboard.press("Enter")
    if declare_as:
        page.get_by_label("Type of the new variable").fill(declare_as)
        page.get_by_role("button", name=f"Declare {name}", exact=True).click()


def test_new_user_builds_and_runs_an_fbd_calculation(page, server):
    editor, canvas = new_fbd_network(page, server, "calc")

    # Three inputs, ADD, SUB and the output, each dragged from the palette onto the network.
    for i, name in enumerate(("var1", "var2", "var3")):
        drop_from_palette(page, "Input", canvas, 60, 30 + 55 * i)
        name_and_declare(page, "Input operand", name, "INT")
    for call, x in (("ADD", 260), ("SUB", 460)):
        insert_block(page, canvas, call, x, 30)
    drop_from_palette(page, "Output", canvas, 660, 40)
    name_and_declare(page, "Output variable", "result", "INT")
    nodes = {n.get_attribute("data-node"): n.inner_text() for n in editor.locator(".fbd-node").all()}
    assert [(k, v.split("\n")[-1].strip()) for k, v in nodes.items() if k.startswith(("in", "out"))] == [
        ("in1", "var1"),
        ("in2", "var2"),
        ("in3", "var3"),
        ("out1", "result"),
    ]

    # Move the output node right by dragging it (its position is a layout hint in the model).
    result_box = editor.locator('.fbd-node[data-node="out1"] .fbd-text').bounding_box()
    page.mouse.move(result_box["x"] + 5, result_box["y"] + 5)
    page.mouse.down()
    page.mouse.move(result_box["x"] + 65, result_box["y"] + 5, steps=6)
    page.mouse.up()
    shift = editor.locator('.fbd-node[data-node="out1"] .fbd-text').bounding_box()["x"] - result_box["x"]
    assert shift > 30

    # Wire with the mouse: output handles onto input handles.
    for src, dst in (
        ("in1", ("blk1", "in:IN1")),
        ("in2", ("blk1", "in:IN2")),
        ("blk1", ("blk2", "in:IN1")),
        ("in3", ("blk2", "in:IN2")),
        ("blk2", ("out1", "in:IN")),
    ):
        drag_to(page, handle(page, src, "out:OUT"), handle(page, *dst))
    assert editor.locator(".react-flow__edge").count() == 5
    # A second wire into SUB.IN1 is refused, with the reason: as a tooltip while dragging, then as a message.
    handle(page, "in3", "out:OUT").hover()
    page.mouse.down()
    box = handle(page, "blk2", "in:IN1").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2, steps=8)
    expect(editor.get_by_role("tooltip")).to_contain_text("Input IN1 of blk2 is already wired from blk1.OUT")
    page.mouse.up()
    assert editor.get_by_role("alert").inner_text().startswith("Input IN1 of blk2 is already wired from blk1.OUT")
    assert editor.locator(".react-flow__edge").count() == 5

    # Execution order from the backend: inputs just before their consumer, ADD, SUB, then the output.
    # (The badges follow edits after a short debounce: wait for the answer to the last wire.)
    order = {"in1": "1", "in2": "2", "blk1": "3", "in3": "4", "blk2": "5", "out1": "6"}
    for node, badge in order.items():
        expect(editor.locator(f'.fbd-node[data-node="{node}"] .fbd-order')).to_have_text(badge)
    assert sorted(n.get_attribute("data-node") for n in editor.locator(".fbd-node").all()) == sorted(order)

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    page.screenshot(path=str(ARTIFACTS / "fbd-offline.png"))
    with urllib.request.urlopen(f"{server}/api/projects/calc") as response:
        main = json.load(response)["project"]["pous"][0]
    network = main["body"]["networks"][0]
    wires = {(w["from"]["node"], w["to"]["node"], w["to"]["pin"]) for w in network["wires"]}
    assert wires == {
        ("in1", "blk1", "IN1"),
        ("in2", "blk1", "IN2"),
        ("blk1", "blk2", "IN1"),
        ("in3", "blk2", "IN2"),
        ("blk2", "out1", "IN"),
    }
    assert [n.get("call") for n in network["nodes"] if n["type"] == "block"] == ["ADD", "SUB"]
    # dropped 660 px into the canvas, whose origin is 12 px in (NetworkCanvas ORIGIN), at zoom 1
    assert [n["pos"]["x"] for n in network["nodes"] if n["id"] == "out1"] == [660 - 12 + shift]

    # Online: run, write var1..var3 from the input nodes, read the result at the pins.
    page.get_by_role("button", name="Compile & simulate").click()
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    page.get_by_role("button", name="Run", exact=True).click()
    state.filter(has_text="Online · running").wait_for()
    for node, value in (("in1", "7"), ("in2", "5"), ("in3", "2")):
        editor.locator(f'.fbd-node[data-node="{node}"]').click(button="right")
        page.get_by_role("menuitem", name=f"Write value of var{node[-1]}…").click()
        page.get_by_label("Value").fill(value)
        page.keyboard.press("Enter")
        page.get_by_test_id(f"value-{node}").filter(has_text=value).wait_for()
    # Values on every pin (issue 17): SUB's output, and ADD's input as its wire feeds it.
    pin = editor.locator('.fbd-node[data-node="blk2"] [data-pin-value="out:OUT"]')
    pin.filter(has_text="10").wait_for()
    page.get_by_test_id("value-out1").filter(has_text="10").wait_for()
    assert editor.locator('.fbd-node[data-node="blk1"] [data-pin-value="in:IN1"]').text_content() == "7"
    page.screenshot(path=str(ARTIFACTS / "fbd-online.png"))

    # Breakpoints: on the network (its number), then on the SUB block (Alt+click); each halts the scan there.
    editor.get_by_role("button", name="1", exact=True).click()
    state.filter(has_text="halted").wait_for()
    editor.locator('.fbd-network.fbd-network-halted[data-network="n1"]').wait_for()
    editor.get_by_role("button", name="1", exact=True).click()
    page.get_by_role("button", name="Continue").click()
    state.filter(has_text="running").wait_for()
    editor.locator('.fbd-node[data-node="blk2"]').click(modifiers=["Alt"])
    editor.locator('.fbd-node[data-node="blk2"] .fbd-breakpoint').wait_for()
    editor.locator('.fbd-node.fbd-halted[data-node="blk2"]').wait_for()
    page.screenshot(path=str(ARTIFACTS / "fbd-halted.png"))
    editor.locator('.fbd-node[data-node="blk2"]').click(modifiers=["Alt"])
    page.get_by_role("button", name="Continue").click()
    state.filter(has_text="running").wait_for()
