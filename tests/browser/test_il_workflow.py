"""An IL POU in a real browser against a real server (issue 26): written in the text editor with IL
highlighting and operator completion, the typed accumulator's error shown live with its message,
fixed, saved, run online (watch list), halted at a line breakpoint.
Screenshots are written to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import new_pou, new_project, save_and_run, watch
from .test_st_workflow import replace_text

pytestmark = pytest.mark.browser

DECLARATIONS = "VAR\n    n : INT;\n    big : BOOL;\nEND_VAR"
BODY = "LD n\nADD 1\nST n\nGE 3\n"


def test_il_pou_is_written_with_help_checked_live_and_run(page, server):
    new_project(page, server, "il")
    new_pou(page, "Main", language="il", kind="program")
    body = page.get_by_label("Main body")
    body.wait_for()
    replace_text(page, "Main declarations", DECLARATIONS)

    # IL-25: storing the BOOL accumulator into an INT is underlined with the accumulator's type.
    replace_text(page, "Main body", BODY + "ST n")
    underline = body.locator(".cm-lintRange-error")
    underline.wait_for()
    assert underline.inner_text() == "ST n"
    underline.hover()
    tooltip = page.locator(".cm-tooltip-lint")
    tooltip.wait_for()
    assert tooltip.inner_text() == "IL-TYPE: ST n: the accumulator holds BOOL, n is INT"

    # The operator of each line is highlighted as a keyword, its operand is not.
    colours = page.evaluate(
        """() => {
            const line = document.querySelector('[aria-label="Main body"] .cm-line');
            const op = [...line.querySelectorAll('span')].find((s) => s.textContent === 'LD');
            return [op ? getComputedStyle(op).color : null, getComputedStyle(line).color];
        }"""
    )
    assert colours[0] is not None and colours[0] != colours[1]

    # Completion at the operator position offers the IL operators first.
    replace_text(page, "Main body", BODY)
    page.keyboard.type("ST")
    options = page.locator(".cm-tooltip-autocomplete .cm-completionLabel")
    options.first.wait_for()
    assert options.all_inner_texts()[:2] == ["ST", "STN"]
    page.keyboard.press("Escape")
    page.keyboard.type(" big")
    page.keyboard.press("Escape")
    body.locator(".cm-lintRange").wait_for(state="detached")
    page.screenshot(path=str(ARTIFACTS / "il-editor.png"))

    # Online: n counts every scan, big follows n >= 3.
    state = save_and_run(page)
    n, big = watch(page, "Main.n"), watch(page, "Main.big")
    page.wait_for_function(
        """() => Number(document.querySelector('tr[data-path="MAIN.N"] td.watch-value')?.textContent) > 3"""
    )
    big.filter(has_text="TRUE").wait_for()

    # A breakpoint on line 3 (ST n) halts the scan there.
    line3 = body.locator(".cm-line").nth(2)
    gutter = page.locator(".cm-breakpoint-gutter").last
    gutter_box, line_box = gutter.bounding_box(), line3.bounding_box()
    page.mouse.click(gutter_box["x"] + gutter_box["width"] / 2, line_box["y"] + line_box["height"] / 2)
    state.filter(has_text="Online · halted").wait_for()
    assert "cm-halted-line" in line3.get_attribute("class").split()
    page.wait_for_timeout(500)  # the values of the halt come in the frame after the state
    halted = n.inner_text()
    page.wait_for_timeout(300)
    assert n.inner_text() == halted  # halted: nothing moves
    page.screenshot(path=str(ARTIFACTS / "il-halted.png"))
    page.get_by_role("button", name="Continue").click()
    # the breakpoint stays: the next scan halts on line 3 again, with n one higher
    n.filter(has_text=re.compile(f"^{int(halted) + 1}$")).wait_for()
    state.filter(has_text="Online · halted").wait_for()
    page.wait_for_timeout(300)
    assert int(n.inner_text()) == int(halted) + 1
