"""The new user's ST workflow in a real browser against a real server (issue 9, "Tests").

Write a function block with a typo in a variable name, see the live diagnostic underline with its
message before saving, fix it and see the underline go; save. Use the FB from a program (member
completion offers the FB's output), run the simulation and watch the value inline in the body,
hover for value and type, halt at a line breakpoint and see the values of the halt, force a
variable from the right-click menu and see the count stop.
Screenshots are written to tests/browser/artifacts/.
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest

from .conftest import ARTIFACTS
from .steps import new_pou, new_project, save_and_run

pytestmark = pytest.mark.browser

COUNTER_DECLARATIONS = "VAR_INPUT\n    Enable : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Count : INT;\nEND_VAR"
COUNTER_BODY = "IF Enable THEN\n    Count := Cuont + 1;\nEND_IF;"
MAIN_DECLARATIONS = "VAR\n    c1 : Counter;\n    Run : BOOL := TRUE;\n    n : INT;\nEND_VAR"


def new_st_pou(page, name: str, kind: str) -> None:
    new_pou(page, name, language="st", kind=kind)
    page.get_by_label(f"{name} body").wait_for()


def replace_text(page, label: str, text: str) -> None:
    """Select all of an ST editor's text and put ``text`` there (as a paste would). Focused, not clicked: an open
    completion list of the previous text may lie over the editor's middle."""
    page.get_by_label(label).focus()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(text)


def inline_values(page, label: str) -> list[str]:
    return page.get_by_label(label).locator(".cm-st-value").all_inner_texts()


def char_at(page, label: str, line: int, column: int) -> tuple[float, float]:
    """The centre of the character at 0-based ``line``/``column`` of an editor's text (inline values skipped)."""
    box = page.evaluate(
        """([label, line, column]) => {
            const el = document.querySelectorAll(`[aria-label="${label}"] .cm-line`)[line];
            const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT,
                { acceptNode: (n) => n.parentElement.closest('.cm-st-value') ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT });
            for (let node = walker.nextNode(), left = column; node; node = walker.nextNode()) {
                if (left < node.length) {
                    const range = document.createRange();
                    range.setStart(node, left);
                    range.setEnd(node, left + 1);
                    const r = range.getBoundingClientRect();
                    return [r.x + r.width / 2, r.y + r.height / 2];
                }
                left -= node.length;
            }
            return null;
        }""",
        [label, line, column],
    )
    assert box is not None, (label, line, column)
    return box[0], box[1]


def test_new_user_writes_an_st_fb_fixes_a_typo_and_watches_it_run(page, server):
    new_project(page, server, "lab")

    # The FB with a typo: the live check underlines it while the text is unsaved.
    new_st_pou(page, "Counter", "function_block")
    replace_text(page, "Counter declarations", COUNTER_DECLARATIONS)
    replace_text(page, "Counter body", COUNTER_BODY)
    body = page.get_by_label("Counter body")
    underline = body.locator(".cm-lintRange-error")
    underline.wait_for()
    assert underline.inner_text() == "Cuont"
    assert page.get_by_role("status").filter(has_text="Unsaved changes in Counter").is_visible()
    underline.hover()
    tooltip = page.locator(".cm-tooltip-lint")
    tooltip.wait_for()
    assert (
        tooltip.locator(".cm-diagnosticText").inner_text()
        == "ST-UNKNOWN-VAR: unknown variable 'Cuont' - did you mean 'Count'?"
    )
    # The quick fix (issue 22): the declare dialog for the unknown name, offered on the mark.
    assert tooltip.get_by_role("button", name="Declare Cuont").is_visible()
    page.screenshot(path=str(ARTIFACTS / "st-typo.png"))

    # Fix it by typing: the underline goes away without a save.
    underline.dblclick()
    page.keyboard.type("Count")
    page.keyboard.press("Escape")  # close the completion list the typing opened
    underline.wait_for(state="detached")
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    with urllib.request.urlopen(f"{server}/api/projects/lab") as response:
        saved = json.load(response)["project"]["pous"]
    assert [(p["name"], p["body"]) for p in saved] == [("Counter", COUNTER_BODY.replace("Cuont", "Count"))]

    # A program using the FB: after `c1.` the completion offers the FB's parameters.
    new_st_pou(page, "Main", "program")
    replace_text(page, "Main declarations", MAIN_DECLARATIONS)
    replace_text(page, "Main body", "c1(Enable := Run);\nn := c1")
    page.keyboard.type(".")
    options = page.locator(".cm-tooltip-autocomplete .cm-completionLabel")
    options.first.wait_for()
    assert options.all_inner_texts() == ["Enable", "Count"]
    page.keyboard.type("Co")
    page.wait_for_function(
        "() => document.querySelectorAll('.cm-tooltip-autocomplete .cm-completionLabel').length === 1"
    )
    assert options.all_inner_texts() == ["Count"]
    page.keyboard.press("Enter")
    page.keyboard.type(";")
    assert page.get_by_label("Main body").inner_text() == "c1(Enable := Run);\nn := c1.Count;"
    page.get_by_label("Main body").locator(".cm-lintRange").wait_for(state="detached")

    # Online: values appear inline after the variables and n keeps counting.
    state = save_and_run(page)
    assert page.get_by_label("Show values inline").is_checked()
    # Both texts are read-only online, and the POU says why once (not once per editor).
    assert page.locator(".st-editor-readonly").all_inner_texts() == ["Online: go offline to edit."]
    for part in ("Main declarations", "Main body"):
        assert page.get_by_label(part).get_attribute("aria-readonly") == "true"
    # Run, n and c1.Count have values; c1 (an FB) and Enable (a formal parameter) do not.
    n_value = """() => Number(document.querySelectorAll('[aria-label="Main body"] .cm-st-value')[1]?.textContent)"""
    page.wait_for_function(f"() => ({n_value})() > 5")
    run_shown, n_shown, count_shown = inline_values(page, "Main body")
    assert run_shown == "TRUE"
    assert abs(int(count_shown) - int(n_shown)) <= 1  # one scan apart at most: n takes c1.Count each scan
    page.wait_for_function(f"() => ({n_value})() > {int(n_shown)}")
    page.screenshot(path=str(ARTIFACTS / "st-online.png"))

    # Hover on n: its value and type.
    page.mouse.move(*char_at(page, "Main body", 1, 0))
    hover = page.locator(".cm-st-value-tooltip")
    hover.wait_for()
    assert re.fullmatch(r"n : INT = \d+", hover.inner_text())

    # A breakpoint on line 2 (gutter click): the scan halts there, the line is highlighted, and the
    # values are those of the halt: line 1 has counted c1 up, n still holds the previous scan's count.
    page.mouse.move(0, 0)
    line2 = page.get_by_label("Main body").locator(".cm-line").nth(1)
    gutter = page.locator(".cm-breakpoint-gutter").last

    def click_gutter_of_line2() -> None:  # measured each time: the debug bar's buttons move the editor
        gutter_box, line_box = gutter.bounding_box(), line2.bounding_box()
        page.mouse.click(gutter_box["x"] + gutter_box["width"] / 2, line_box["y"] + line_box["height"] / 2)

    click_gutter_of_line2()
    state.filter(has_text="Online · halted").wait_for()
    assert page.locator(".cm-halted-line").count() == 1
    assert "cm-halted-line" in line2.get_attribute("class").split()
    count_value = n_value.replace("[1]", "[2]")
    page.wait_for_function(f"() => ({count_value})() === ({n_value})() + 1")
    halt_values = inline_values(page, "Main body")
    page.wait_for_timeout(300)
    assert inline_values(page, "Main body") == halt_values  # halted: nothing moves
    page.screenshot(path=str(ARTIFACTS / "st-halted.png"))
    dots = page.locator(".cm-breakpoint:visible")
    assert dots.count() == 1
    click_gutter_of_line2()
    dots.first.wait_for(state="detached")
    page.get_by_role("button", name="Continue").click()
    state.filter(has_text="Online · running").wait_for()
    assert page.locator(".cm-halted-line").count() == 0

    # Right click Run, force FALSE: the FB stops counting, Run shows as forced.
    page.mouse.move(0, 0)
    page.mouse.click(*char_at(page, "Main body", 0, len("c1(Enable := R")), button="right")
    page.get_by_role("menuitem", name="Force FALSE").click()
    page.wait_for_function(
        """() => {
            const run = document.querySelectorAll('[aria-label="Main body"] .cm-st-value')[0];
            return run.firstChild.textContent === 'FALSE' && run.querySelector('.forced-mark')?.textContent === 'F';
        }"""
    )
    stopped = inline_values(page, "Main body")[1]
    page.wait_for_timeout(300)
    assert inline_values(page, "Main body")[1] == stopped
    page.screenshot(path=str(ARTIFACTS / "st-forced.png"))
