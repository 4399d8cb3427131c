"""Issue 25: an FBD block ``d.DivMod`` (a METHOD of the FB instance d, CODESYS; the block picker offers it) is drawn
with the method's pins - its inputs, its result as OUT and its VAR_OUTPUTs - and online those pins show what the call
gave: 14 / 4 is 3 rest 2, also through a MUL fed by the method's output (2 * 3 = 6)."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, store_project
from .test_cfc_workflow import cycles
from .test_fbd_cfc_convert import wire
from .test_fbd_workflow import drag_to, drop_from_palette, handle, insert_block

pytestmark = pytest.mark.browser

DIVIDER = {
    "name": "Divider",
    "kind": "function_block",
    "language": "st",
    "declarations": "VAR calls : INT; END_VAR",
    "body": "",
    "methods": [
        {
            "name": "DivMod",
            "return_type": "BOOL",
            "declarations": "VAR_INPUT a : INT; b : INT; END_VAR\nVAR_OUTPUT q : INT; r : INT; END_VAR",
            "body": "calls := calls + 1;\nq := a / b;\nr := a MOD b;\nDivMod := r = 0;",
        }
    ],
}
NETWORK = {
    "id": "n1",
    "nodes": [
        {"type": "input", "id": "ia", "expr": "n", "pos": {"x": 20, "y": 20}},
        {"type": "input", "id": "ib", "expr": "4", "pos": {"x": 20, "y": 80}},
        {"type": "block", "id": "dm", "call": "d.DivMod", "pos": {"x": 200, "y": 20}},
        {"type": "output", "id": "oq", "var": "q", "pos": {"x": 420, "y": 20}},
        {"type": "output", "id": "or", "var": "r", "pos": {"x": 420, "y": 90}},
        {"type": "input", "id": "two", "expr": "2", "pos": {"x": 420, "y": 220}},
        {"type": "block", "id": "mul", "call": "MUL", "pos": {"x": 600, "y": 160}},
        {"type": "output", "id": "od", "var": "doubled", "pos": {"x": 800, "y": 170}},
    ],
    "wires": [
        wire("ia.OUT", "dm.a"),
        wire("ib.OUT", "dm.b"),
        wire("dm.q", "oq.IN"),
        wire("dm.r", "or.IN"),
        wire("dm.q", "mul.IN1"),
        wire("two.OUT", "mul.IN2"),
        wire("mul.OUT", "od.IN"),
    ],
}
PROJECT = {
    "name": "fbdmethod",
    "pous": [
        DIVIDER,
        {
            "name": "Main",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR d : Divider; n : INT := 14; q, r, doubled : INT; END_VAR",
            "body": {"networks": [NETWORK]},
        },
    ],
}


def test_a_method_block_shows_the_methods_pins_and_their_values_online(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "fbdmethod", "Main")
    block = page.locator('.fbd-node[data-node="dm"]')
    for pin in ("A", "B", "OUT", "Q", "R"):  # the method's pins, as its declaration gives them
        expect(block.get_by_text(re.compile(f"^{pin}$", re.IGNORECASE))).to_have_count(1)
    # the block picker offers the instance's method by its call (cancelled: the network stays as stored)
    canvas = page.locator(".fbd-network .react-flow__pane").first
    drop_from_palette(page, "Block…", canvas, 600, 300)
    picker = page.get_by_role("dialog", name="Insert block")
    picker.get_by_label("Search functions and function blocks").fill("divmod")
    expect(picker.get_by_role("option")).to_have_count(1)
    expect(picker.get_by_role("option").locator(".ld-entry-name")).to_have_text("d.DivMod")
    expect(picker.get_by_role("option").locator(".ld-entry-kind")).to_have_text("METHOD · user")
    page.keyboard.press("Escape")
    expect(picker).to_have_count(0)
    go_online(page, run=False)
    cycles(page, 1)
    page.get_by_test_id("value-oq").filter(has_text=re.compile("^3$")).wait_for()
    page.get_by_test_id("value-or").filter(has_text=re.compile("^2$")).wait_for()
    page.get_by_test_id("value-od").filter(has_text=re.compile("^6$")).wait_for()
    expect(block.locator('[data-pin-value="out:Q"]')).to_have_text("3")
    expect(block.locator('[data-pin-value="out:R"]')).to_have_text("2")
    expect(block.locator('[data-pin-value="out:OUT"]')).to_have_text("FALSE")  # 14 MOD 4 <> 0
    expect(page.locator(".react-flow__edge")).to_have_count(7)  # every wire drawn, to the method's pins too
    page.screenshot(path=str(ARTIFACTS / "fbd-method-block.png"))


TALLY = {
    "name": "Tally",
    "kind": "program",
    "language": "st",
    "declarations": "VAR total : INT; END_VAR",
    "body": "",
    "methods": [
        {
            "name": "Add",
            "return_type": "INT",
            "declarations": "VAR_INPUT k : INT; END_VAR\nVAR_OUTPUT twice : INT; END_VAR",
            "body": "total := total + k;\ntwice := 2 * total;\nAdd := total;",
        }
    ],
}
SUMS = {
    "name": "progmethodblock",
    "pous": [
        TALLY,
        {
            "name": "Main",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR r : INT; END_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "nodes": [
                            {"type": "input", "id": "ik", "expr": "3", "pos": {"x": 20, "y": 20}},
                            {"type": "output", "id": "o", "var": "r", "pos": {"x": 520, "y": 20}},
                        ],
                        "wires": [],
                    }
                ]
            },
        },
    ],
}


def test_a_programs_method_is_picked_as_a_block_wired_and_run(page, server):
    """Issue 25: the block picker offers Tally's method as ``Tally.Add`` (CODESYS: another POU calls a program's
    method so); the block gets the method's pins (K, its result OUT, its VAR_OUTPUT TWICE), and run, each scan adds
    3 to Tally's total: by hand the block gives 3, 6, 9 on OUT and twice that on TWICE (unwired, it shows its value as
    an FB's unwired outputs do, ON-09)."""
    store_project(server, SUMS)
    page.goto(server)
    open_pou(page, "progmethodblock", "Main")
    editor = page.get_by_role("application", name="Function block diagram editor")
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    insert_block(page, canvas, "Tally.Add", 260, 30)
    block = editor.locator(".fbd-node").filter(has_text="Tally.Add")
    node = block.get_attribute("data-node")
    for pin in ("K", "OUT", "TWICE"):
        expect(block.get_by_text(re.compile(f"^{pin}$", re.IGNORECASE))).to_have_count(1)
    expect(page.get_by_role("dialog", name="Insert block")).to_have_count(0)
    drag_to(page, handle(page, "ik", "out:OUT"), handle(page, node, "in:k"))
    drag_to(page, handle(page, node, "out:OUT"), handle(page, "o", "in:IN"))
    expect(editor.locator(".react-flow__edge")).to_have_count(2)

    go_online(page, run=False)
    for total in (3, 6, 9):
        cycles(page, 1)
        page.get_by_test_id("value-o").filter(has_text=re.compile(f"^{total}$")).wait_for()
        expect(block.locator('[data-pin-value="out:OUT"]')).to_have_text(str(total))
        expect(block.locator('[data-pin-value="out:TWICE"]')).to_have_text(str(2 * total))


def test_an_ld_box_of_a_programs_method_shows_every_pin_online(page, server):
    """Issue 25 (ON-09): an LD box ``Tally.Add`` draws the method's pins from the library (K, OUT, TWICE) and online
    shows a value on each, the unwired TWICE too. By hand: each scan adds k = 3 to Tally's total, so after scan k
    OUT (and r) is 3k and TWICE 6k."""
    box = {"type": "box", "id": "b1", "call": "Tally.Add", "en": True, "inputs": {"k": "3"}, "outputs": {"OUT": "r"}}
    main = {
        "name": "Main",
        "kind": "program",
        "language": "ld",
        "declarations": "VAR r : INT; END_VAR",
        "body": {"networks": [{"id": "n1", "elements": [{"type": "contact", "id": "c", "var": "TRUE"}, box]}]},
    }
    store_project(server, {"name": "ldprogmethod", "pous": [TALLY, main]})
    page.goto(server)
    open_pou(page, "ldprogmethod", "Main")
    drawn = page.locator('g.ld-element[data-id="b1"]')
    for pin in ("k", "OUT", "twice"):  # the method's pins, as the library gives them
        expect(drawn.get_by_text(pin, exact=True)).to_have_count(1)
    go_online(page, run=False)
    for total in (3, 6, 9):
        cycles(page, 1)
        expect(drawn.locator('[data-pin-value="out:OUT"] .ld-badge')).to_have_attribute("data-value", str(total))
        expect(drawn.locator('[data-pin-value="out:TWICE"] .ld-badge')).to_have_attribute("data-value", str(2 * total))


def test_an_ld_box_of_an_instances_method_draws_its_pins_and_runs(page, server):
    """Issue 25: an LD box ``d.DivMod`` (a METHOD of the FB instance d) draws the method's pins (a, b, q, r and its
    result OUT), as the FBD block does, and shows their values online. By hand: n = 10, b = 4 gives q = 10 / 4 = 2,
    r = 10 MOD 4 = 2 and the result r = 0, FALSE; the method counts its calls in d.calls: 1, 2, 3."""
    box = {
        "type": "box",
        "id": "b1",
        "call": "d.DivMod",
        "en": True,
        "inputs": {"a": "n", "b": "4"},
        "outputs": {"q": "quot", "r": "rest"},
    }
    main = {
        "name": "Main",
        "kind": "program",
        "language": "ld",
        "declarations": "VAR d : Divider; n : INT := 10; quot : INT; rest : INT; END_VAR",
        "body": {"networks": [{"id": "n1", "elements": [{"type": "contact", "id": "c", "var": "TRUE"}, box]}]},
    }
    store_project(server, {"name": "ldmethod", "pous": [DIVIDER, main]})
    page.goto(server)
    open_pou(page, "ldmethod", "Main")
    drawn = page.locator('g.ld-element[data-id="b1"]')
    for pin in ("a", "b", "q", "r", "OUT"):  # the method's pins, from its FB's library entry
        expect(drawn.get_by_text(pin, exact=True)).to_have_count(1)
    go_online(page, run=False)
    cycles(page, 1)
    expect(drawn.locator('[data-pin-value="out:Q"] .ld-badge')).to_have_attribute("data-value", "2")
    expect(drawn.locator('[data-pin-value="out:R"] .ld-badge')).to_have_attribute("data-value", "2")
    expect(drawn.locator('[data-pin-value="out:OUT"] .ld-badge')).to_have_attribute("data-value", "FALSE")
