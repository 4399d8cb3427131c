"""A CODESYS CFC export imported and run in a real browser against a real server (issue 25).

tests/interchange/data/codesys_cfc.xml (the structure of a real CODESYS export, see
tests/interchange/test_codesys_cfc.py) is imported through the UI; its PLC_PRG opens in the CFC editor with
CODESYS's execution order numbers on its elements and its comment box. Online, scan by scan as worked out by hand
there: level rises by 3 while it is not over 9, so in scans 1..3 the jump to Done is taken (level := 0 skipped);
in scan 4 the ADD gives 12, full, the jump is not taken, level := 0 runs and pulses counts 1; in scan 5 level is 3
and the jump is taken again. An output node shows its variable, so level's outputs show its value at the scan's
end.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, new_project
from .test_cfc_workflow import badges, cycles
from .test_faithful_import import import_file

pytestmark = pytest.mark.browser

FIXTURE = Path(__file__).parents[1] / "interchange" / "data" / "codesys_cfc.xml"


def test_a_codesys_cfc_export_opens_as_a_chart_and_runs(page, server):
    new_project(page, server, "scratch")
    import_file(page, FIXTURE, "charts")
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^PLC_PRG")).click()
    editor = page.get_by_role("application", name="Continuous function chart editor")
    editor.locator(".react-flow__edge").first.wait_for()
    badges(
        editor,
        {
            "block1": "1",  # ADD
            "output1": "2",  # level
            "block2": "3",  # GT
            "output2": "4",  # full
            "output3": "5",  # notFull (negated)
            "jump1": "6",
            "output4": "7",  # level := 0
            "label1": "8",
            "block3": "9",  # pulses : CTU
            "output5": "10",  # count
            "block4": "11",  # F_DOUBLE
            "output6": "12",  # twice
        },
    )
    expect(editor.locator(".fbd-node.fbd-comment")).to_contain_text("Fill by inflow; empty once over the limit")
    expect(editor.locator(".react-flow__edge")).to_have_count(15)
    page.screenshot(path=str(ARTIFACTS / "codesys-cfc-imported.png"))

    go_online(page, run=False)
    cycles(page, 3)
    page.get_by_test_id("value-output1").filter(has_text=re.compile("^9$")).wait_for()
    expect(page.get_by_test_id("value-jump1")).to_have_text("TRUE")  # not over 9: level := 0 skipped
    expect(page.get_by_test_id("value-output6")).to_have_text("18")
    cycles(page, 1)
    add = editor.locator('.fbd-node[data-node="block1"]')
    add.locator('[data-pin-value="out:OUT"]').filter(has_text=re.compile("^12$")).wait_for()
    expect(page.get_by_test_id("value-output1")).to_have_text("0")  # the variable: level := 0 ran after the ADD
    expect(page.get_by_test_id("value-jump1")).to_have_text("FALSE")
    expect(page.get_by_test_id("value-output2")).to_have_text("TRUE")
    expect(page.get_by_test_id("value-output5")).to_have_text("1")
    expect(page.get_by_test_id("value-output6")).to_have_text("0")
    page.screenshot(path=str(ARTIFACTS / "codesys-cfc-online.png"))
    cycles(page, 1)
    page.get_by_test_id("value-output1").filter(has_text=re.compile("^3$")).wait_for()
    expect(page.get_by_test_id("value-jump1")).to_have_text("TRUE")
    expect(page.get_by_test_id("value-output5")).to_have_text("1")
