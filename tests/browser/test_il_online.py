"""IL online in a real browser (issue 26 item 3, ON-04): the accumulator after every line shown at the line's
end (a line a jump skipped shows none), and a single step that stops at the next LD, JMP or CAL instead of at
every line. Values worked out by hand: ``a`` counts, the CR after ``GT 2`` is ``a > 2``, the JMPC skips lines
6 and 7 once it is TRUE."""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, settled_scan_count, store_project

pytestmark = pytest.mark.browser

BODY = "LD a\nADD 1\nST a\nGT 2\nJMPC done\nLD 100\nST b\ndone:\nLD a\nMUL 10\nST b"
PROJECT = {
    "name": "ilonline",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "il",
            "declarations": "VAR\n    a : INT;\n    b : INT;\nEND_VAR",
            "body": BODY,
        }
    ],
}


def single_cycle(page) -> None:
    before = settled_scan_count(page)
    page.get_by_role("button", name="Single cycle").click()
    page.wait_for_function(
        "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=before + 1
    )


def accumulators(page) -> list[tuple[int, str]]:
    """(line, accumulator shown at its end) for every line that shows one."""
    return page.evaluate(
        """() => [...document.querySelectorAll('[aria-label="Main body"] .cm-line')].flatMap((line, i) =>
            [...line.querySelectorAll('.cm-il-accumulator')].map((w) => [i + 1, w.textContent]))"""
    )


def wait_accumulators(page, expected: list[tuple[int, str]]) -> None:
    page.wait_for_function(
        """expected => JSON.stringify([...document.querySelectorAll('[aria-label="Main body"] .cm-line')]
            .flatMap((line, i) => [...line.querySelectorAll('.cm-il-accumulator')].map((w) => [i + 1, w.textContent])))
            === JSON.stringify(expected)""",
        arg=[list(pair) for pair in expected],
    )


def test_accumulator_per_line_and_single_step_at_loads_jumps_and_calls(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "ilonline", "Main")
    body = page.get_by_label("Main body")
    body.wait_for()

    go_online(page, run=False)
    single_cycle(page)  # a: 0 -> 1, 1 > 2 FALSE: no jump, b := 100, then b := 10
    wait_accumulators(
        page,
        [(1, "0"), (2, "1"), (3, "1"), (4, "FALSE"), (5, "FALSE"), (6, "100"), (7, "100"), (9, "1"), (10, "10"),
         (11, "10")],
    )  # fmt: skip
    page.screenshot(path=str(ARTIFACTS / "il-online-accumulator.png"))
    for _ in range(2):
        single_cycle(page)  # a = 3: 3 > 2, the jump skips lines 6 and 7
    wait_accumulators(page, [(1, "2"), (2, "3"), (3, "3"), (4, "TRUE"), (5, "TRUE"), (9, "3"), (10, "30"), (11, "30")])

    # A breakpoint on line 2 (ADD 1); single steps then stop at the JMPC (5) and, as it jumps, the LD on 9.
    line2 = body.locator(".cm-line").nth(1)
    gutter = page.locator(".cm-breakpoint-gutter").last
    gutter_box, line_box = gutter.bounding_box(), line2.bounding_box()
    page.mouse.click(gutter_box["x"] + gutter_box["width"] / 2, line_box["y"] + line_box["height"] / 2)
    page.get_by_role("button", name="Single cycle").click()
    debug = page.get_by_role("region", name="Debugging")
    debug.get_by_text(re.compile(r"Halted at \w+, line 2$", re.I)).wait_for()
    for line in (5, 9):
        debug.get_by_role("button", name="Step into").click()
        debug.get_by_text(re.compile(rf"Halted at \w+, line {line}$", re.I)).wait_for()
        assert "cm-halted-line" in body.locator(".cm-line").nth(line - 1).get_attribute("class").split()
    page.screenshot(path=str(ARTIFACTS / "il-online-step.png"))
    debug.get_by_role("button", name="Step into").click()  # no load, jump or call left: the scan ends
    debug.wait_for(state="detached")
    page.get_by_role("status", name="Online state").filter(has_text="Online · stopped").wait_for()
    wait_accumulators(page, [(1, "3"), (2, "4"), (3, "4"), (4, "TRUE"), (5, "TRUE"), (9, "4"), (10, "40"), (11, "40")])
    assert accumulators(page)[0] == [1, "3"]
