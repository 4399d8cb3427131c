"""Unit tests in the browser (issue 20): the Tests panel lists the example's tests, runs them all (results
stream in: 6 passed), a new test file is written in the ST editor (a typo is underlined live, then
fixed), run on its own: its failing assertion shows both values, a click on its location puts the
editor's cursor on that line, and the failure opens online with the values the simulation had when it
failed. A run with coverage tints the LD elements and FBD blocks never energised and the ST lines never
executed.
Fails on any page error or console error. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS

pytestmark = pytest.mark.browser

EXTRA = """TEST 'one scan'
  Start := TRUE;
  RUN_SCANS(1);
  ASSERT_TRUE(Motor);
END_TEST

TEST 'timer after 5 s'
  Start := TRUE;
  RUN_FOR(T#5s);
  ASSERT_EQ(Main.RunTimer.ET, T#4s, 'wrong on purpose');
END_TEST
"""


def test_run_tests_see_a_failure_jump_to_it_open_it_online_and_see_coverage(page, server):
    problems: list[str] = []
    page.on("pageerror", lambda error: problems.append(f"page error: {error}"))
    page.on("console", lambda m: problems.append(f"console {m.type}: {m.text}") if m.type == "error" else None)

    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^motor")).click()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="tests/motor.st", exact=True).wait_for()

    # The Tests panel lists the example's six tests; Run all: every result streams in, all pass.
    panels = page.get_by_role("region", name="Panels")
    panels.get_by_role("tab", name=re.compile("^Tests")).click()
    rows = panels.locator("li.test-row")
    rows.nth(5).wait_for()
    assert rows.count() == 6
    panels.get_by_role("button", name="Run all", exact=True).click()
    status = panels.locator(".tests-status")
    page.wait_for_function(
        "() => document.querySelector('.tests-status')?.textContent === '6 passed, 0 failed'", timeout=60_000
    )
    assert panels.locator("li.test-passed").count() == 6

    # A new test file: it opens in the ST editor; a typo is underlined by the live check, then fixed.
    tree.get_by_role("button", name="New test file").click()
    page.get_by_label("Test file name").press_sequentially("extra")
    page.get_by_role("form", name="New test file").get_by_role("button", name="Create").click()
    editor = page.get_by_role("textbox", name="tests/extra.st")
    editor.wait_for()
    editor.click()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(EXTRA.replace("Main.RunTimer.ET", "Main.RunTimr.ET"))
    underline = editor.locator(".cm-lintRange-error")
    underline.wait_for()
    assert underline.inner_text() == "Main.RunTimr"
    editor.click()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(EXTRA)
    underline.wait_for(state="detached")

    # Run this file: one passes, the other fails with both values as IEC literals.
    page.get_by_role("button", name="Run this file").click()
    page.wait_for_function(
        "() => document.querySelector('.tests-status')?.textContent === '1 passed, 1 failed'", timeout=60_000
    )
    failure = panels.get_by_role("group", name="Failure of timer after 5 s")
    assert failure.locator(".test-failure-message").inner_text() == (
        "ASSERT_EQ failed: Main.RunTimer.ET expected T#4s, got T#4s990ms"
    )
    assert failure.get_by_test_id("expected").inner_text() == "T#4s"
    assert failure.get_by_test_id("actual").inner_text() == "T#4s990ms"
    assert failure.locator(".test-note").inner_text() == "wrong on purpose"
    assert panels.get_by_role("tab", name="Tests (1 failed)").is_visible()
    page.screenshot(path=str(ARTIFACTS / "tests-failure.png"))

    # Its location puts the cursor on line 10 of the test file.
    tree.get_by_role("button", name=re.compile("^Main")).click()
    failure.get_by_role("button", name="tests/extra.st:10").click()
    page.wait_for_function(
        """() => {
            const active = document.querySelector('[aria-label="tests/extra.st"]')
                ?.closest('.cm-editor')?.querySelector('.cm-activeLine');
            return active?.textContent?.trim() === "ASSERT_EQ(Main.RunTimer.ET, T#4s, 'wrong on purpose');";
        }"""
    )

    # The failure opened online: the simulation as it stood at the failed assertion.
    failure.get_by_role("button", name="Open failure online").click()
    tree.get_by_role("button", name=re.compile("^Main")).click()
    page.wait_for_function("() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-on')")
    assert "ld-on" not in (page.locator("g.ld-coil[data-id=running]").get_attribute("class") or "")
    page.get_by_role("button", name="Go offline to edit").first.click()

    # Coverage of the new file alone: its tests never pressed Stop or ResetCount and the timer never reached
    # 5 s, so the counter's box never passed power and Blinker stayed disabled (its body lines 6-9, the
    # half-period toggle, never ran).
    panels.get_by_role("tab", name=re.compile("^Tests")).click()
    panels.get_by_label("with coverage").check()
    panels.get_by_role("button", name="Run tests/extra.st").click()
    page.wait_for_function(
        "() => document.querySelector('.tests-status')?.textContent === '1 passed, 1 failed'", timeout=60_000
    )
    tree.get_by_role("button", name=re.compile("^Main")).click()
    page.wait_for_function(
        "() => document.querySelector('g[data-id=ctu]')?.classList.contains('ld-coverage-never-energised')"
    )
    assert "ld-coverage" not in (page.locator("g[data-id=motor]").get_attribute("class") or "")
    page.screenshot(path=str(ARTIFACTS / "tests-coverage-ld.png"))
    # Scaling (FBD): Speed = 1 * 10 + 5 never exceeded 50, so the comparison's output never energised HighSpeed.
    tree.get_by_role("button", name=re.compile("^Scaling")).click()
    page.wait_for_function(
        "() => document.querySelector('[data-node=high]')?.classList.contains('fbd-coverage-never-energised')"
    )
    tree.get_by_role("button", name=re.compile("^Blinker")).click()
    body = page.get_by_label("Blinker body")
    body.wait_for()
    page.wait_for_function(
        "() => document.querySelectorAll('[aria-label=\"Blinker body\"] .cm-coverage-never').length === 4"
    )
    assert [line.strip() for line in body.locator(".cm-coverage-never").all_inner_texts()] == [
        "Half(IN := TRUE, PT := Period / 2);",
        "IF Half.Q THEN",
        "Out := NOT Out;",
        "Half(IN := FALSE);",
    ]
    panels.get_by_role("button", name="Hide coverage").click()
    body.locator(".cm-coverage-never").first.wait_for(state="detached")
    assert status.is_visible()
    assert problems == []


DRAFT = """TEST 'draft'
  VAR count_me : INT; (* VAR in_comment : INT; END_VAR *) END_VAR
  RUN_SCANS(1);
  FAULT(Start, 'stuck_true');
  ASSERT_TRUE(Motor);
END_TEST
"""


def _colour(page, file: str, word: str) -> list:
    """The colour of ``word``'s token in the editor of ``file`` and of plain text there."""
    return page.evaluate(
        """([file, word]) => {
            const content = document.querySelector(`[aria-label="${file}"]`);
            const span = [...content.querySelectorAll('.cm-line span')].find((s) => s.textContent === word);
            return [span ? getComputedStyle(span).color : null, getComputedStyle(content).color];
        }""",
        [file, word],
    )


def test_a_test_file_highlights_verbs_completes_its_locals_and_is_renamed_and_deleted(page, server):
    """Issue 20 item 5: test verbs are keywords of the test file's editor, its own VAR blocks are completed
    (not those in comments), and the tree's menu renames a test file (saved under the new name only) and
    deletes one."""
    problems: list[str] = []
    page.on("pageerror", lambda error: problems.append(f"page error: {error}"))
    page.on("console", lambda m: problems.append(f"console {m.type}: {m.text}") if m.type == "error" else None)

    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^motor")).click()
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="New test file").click()
    page.get_by_label("Test file name").press_sequentially("draft")
    page.get_by_role("form", name="New test file").get_by_role("button", name="Create").click()
    editor = page.get_by_role("textbox", name="tests/draft.st")
    editor.wait_for()
    editor.click()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(DRAFT)

    # Verbs and TEST are keywords; a variable is not.
    for word in ("RUN_SCANS", "FAULT", "ASSERT_TRUE", "TEST"):
        colour, plain = _colour(page, "tests/draft.st", word)
        assert colour is not None and colour != plain, word
    motor, plain = _colour(page, "tests/draft.st", "Motor")
    assert motor in (None, plain)  # a variable is plain text (no span of its own)

    # Completion offers the test's own variable, not the one in a comment.
    page.keyboard.press("Control+End")
    page.keyboard.type("cou")
    options = page.locator(".cm-tooltip-autocomplete .cm-completionLabel")
    options.first.wait_for()
    assert "count_me" in options.all_inner_texts()
    page.keyboard.type("n")
    page.wait_for_function(
        "() => [...document.querySelectorAll('.cm-tooltip-autocomplete .cm-completionLabel')]"
        ".every((o) => o.textContent !== 'in_comment')"
    )
    page.keyboard.press("Escape")
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(DRAFT)

    # Rename through the tree's menu: the tab follows; saved, only the new file is there.
    tree.get_by_role("button", name="Actions for tests/draft.st").click()
    tree.get_by_role("menuitem", name="Rename…").click()
    dialog = page.get_by_role("dialog", name="Rename tests/draft.st")
    dialog.get_by_label("New test file name").fill("motor")
    dialog.get_by_role("button", name="Rename").click()
    assert dialog.get_by_role("alert").inner_text() == "There is already a test file called motor."
    dialog.get_by_label("New test file name").fill("faults")
    dialog.get_by_role("button", name="Rename").click()
    page.get_by_role("textbox", name="tests/faults.st").wait_for()
    assert tree.get_by_role("button", name="tests/draft.st").count() == 0
    page.keyboard.press("Control+s")
    saved = page.get_by_text("All changes saved")
    saved.wait_for()
    names = [t["name"] for t in page.request.get(f"{server}/api/projects/motor").json()["project"]["tests"]]
    assert sorted(names) == ["faults", "motor"]

    # Delete: gone from the tree and its tab closes; saved, gone from the project.
    tree.get_by_role("button", name="Actions for tests/faults.st").click()
    tree.get_by_role("menuitem", name="Delete…").click()
    page.get_by_role("dialog", name="Delete tests/faults.st").get_by_role("button", name="Delete").click()
    tree.get_by_role("button", name="tests/faults.st").wait_for(state="detached")
    assert page.get_by_role("textbox", name="tests/faults.st").count() == 0
    saved.wait_for(state="detached")  # the deletion is unsaved
    page.keyboard.press("Control+s")
    saved.wait_for()
    names = [t["name"] for t in page.request.get(f"{server}/api/projects/motor").json()["project"]["tests"]]
    assert names == ["motor"]
    assert problems == []
