"""Breakpoints follow what they are on (issue 22): an ST line's breakpoint moves down when a line is inserted
above it and is dropped with a message when its line's text is deleted; a POU's breakpoints take its new name
when it is renamed from the tree; an LD element's breakpoint is dropped with a message naming it by its operand when
the element is deleted.
Never a breakpoint silently on another line.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .steps import open_pou, panel_tab, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "follow",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    a : INT;\n    b : INT;\n    c : INT;\nEND_VAR",
            "body": "a := 1;\nb := 2;\nc := 3;",
        }
    ],
}


def rows(page, count: int) -> list[tuple[str | None, str]]:
    """The Breakpoints panel's ``count`` rows: each one's key (POU|line:N) and where it says it is."""
    panel_tab(page, "Breakpoints")
    found = page.locator("tr.breakpoint-row")
    expect(found).to_have_count(count)
    return [(r.get_attribute("data-breakpoint"), r.locator("button.link").inner_text()) for r in found.all()]


def test_st_breakpoints_follow_their_lines_and_their_pou(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "follow", "Main")
    body = page.get_by_label("Main body")
    body.focus()
    page.keyboard.press("Control+End")  # line 3, c := 3;
    page.keyboard.press("F9")
    expect(page.get_by_role("tab", name="Breakpoints (1)")).to_be_visible()
    assert rows(page, 1) == [("MAIN|line:3", "Main line 3: c := 3;")]

    # A line inserted above: the breakpoint stays on c := 3;, now line 4.
    body.focus()
    page.keyboard.press("Control+Home")
    page.keyboard.type("// the constants\n")
    expect(page.locator("tr.breakpoint-row")).to_have_attribute("data-breakpoint", "MAIN|line:4")
    assert rows(page, 1) == [("MAIN|line:4", "Main line 4: c := 3;")]

    # Its line's text deleted: dropped, and the panel says so.
    body.focus()
    page.keyboard.press("Control+End")
    page.keyboard.press("Shift+Home")
    page.keyboard.press("Delete")
    notice = page.get_by_role("region", name="Panels").get_by_role("status").filter(has_text="breakpoint")
    expect(notice).to_have_text(
        re.compile(r"^The breakpoint at Main, line 4 was removed: the text of its line was deleted\.")
    )
    assert rows(page, 0) == []

    # A breakpoint on b := 2; (line 3), then Main renamed Plant from the tree: the breakpoint is Plant's.
    body.focus()
    page.keyboard.press("Control+Home")
    page.keyboard.press("ArrowDown")
    page.keyboard.press("ArrowDown")
    page.keyboard.press("F9")
    assert rows(page, 1) == [("MAIN|line:3", "Main line 3: b := 2;")]
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Actions for Main").click()
    tree.get_by_role("menuitem", name="Rename…").click()
    dialog = page.get_by_role("dialog", name="Rename Main")
    dialog.get_by_label("New name").fill("Plant")
    dialog.get_by_role("button", name="Preview").click()
    dialog.get_by_role("button", name="Rename").click()
    expect(dialog).to_have_count(0)
    expect(page.locator("tr.breakpoint-row")).to_have_attribute("data-breakpoint", "PLANT|line:3")
    assert rows(page, 1) == [("PLANT|line:3", "Plant line 3: b := 2;")]


def test_an_ld_element_breakpoint_is_dropped_with_a_message_when_the_element_is_deleted(page, server):
    store_project(
        server,
        {
            "name": "followld",
            "pous": [
                {
                    "name": "Lad",
                    "kind": "program",
                    "language": "ld",
                    "declarations": "VAR\n    Go : BOOL;\n    Lamp : BOOL;\nEND_VAR",
                    "body": {
                        "networks": [
                            {
                                "id": "n1",
                                "elements": [
                                    {"type": "contact", "id": "c1", "var": "Go"},
                                    {"type": "coil", "id": "q1", "var": "Lamp"},
                                ],
                            }
                        ]
                    },
                }
            ],
        },
    )
    page.goto(server)
    open_pou(page, "followld", "Lad")
    page.locator('g.ld-element[data-id="q1"] .ld-hit').click()
    page.keyboard.press("F9")
    assert rows(page, 1) == [("LAD|element:q1", "Lad element q1 (coil Lamp)")]
    page.locator('g.ld-element[data-id="q1"] .ld-hit').click()
    page.keyboard.press("Delete")
    expect(page.locator('g.ld-element[data-id="q1"]')).to_have_count(0)
    notice = page.get_by_role("region", name="Panels").get_by_role("status").filter(has_text="breakpoint")
    expect(notice).to_have_text(
        re.compile(r"^The breakpoint at Lad, element q1 \(coil Lamp\) was removed: its element was deleted\.")
    )
    assert rows(page, 0) == []
