"""A PROPERTY with CODESYS's {attribute 'monitoring'} online in the browser (issue 25): its value in the watch list,
inline in the ST editor where the program names it and in the Variables view's instance, changing scan by scan - 'variable' the value of its last GET
or SET, 'call' what its GET returns between scans (CODESYS's online help, "Attribute: monitoring"). The values are
worked out by hand from the program text. Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, store_project, watch
from .test_project_operations import tree

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "tanks",
    "pous": [
        {
            "name": "Tank",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR\n    amount : INT;\nEND_VAR",
            "body": "",
            "properties": [
                {
                    "name": "Level",
                    "type": "INT",
                    "get": {"declarations": "{attribute 'monitoring' := 'variable'}", "body": "Level := amount * 10;"},
                    "set": {"declarations": "", "body": "amount := Level;"},
                },
                {
                    "name": "Share",
                    "type": "INT",
                    "get": {"declarations": "{attribute 'monitoring' := 'call'}", "body": "Share := amount + 100;"},
                },
            ],
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    t : Tank;\n    n : INT;\n    x : INT;\nEND_VAR",
            "body": "n := n + 1;\nt.Level := n;\nx := t.Share;",
        },
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "priority": 0, "programs": ["Main"]}],
}


def test_a_monitored_propertys_value_changes_online_in_the_watch_list_and_inline(page, server: str) -> None:
    """Scan k: the SET stores k (Level's last access: k), Share's GET returns k + 100."""
    store_project(server, PROJECT)
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^tanks")).click()
    tree(page).get_by_role("button", name=re.compile("^Main")).click()
    go_online(page, run=False)
    level, share = watch(page, "Main.t.Level"), watch(page, "Main.t.Share")
    expect(level).to_have_text("0")
    expect(share).to_have_text("100")
    values = page.get_by_role("textbox", name="Main body").locator(".cm-st-value")
    page.get_by_role("button", name="Single cycle").click()
    expect(level).to_have_text("1")
    expect(share).to_have_text("101")
    expect(values).to_have_text(["1", "1", "1", "1", "101", "101"])  # n, n, t.Level, n, x, t.Share
    page.get_by_role("button", name="Single cycle").click()
    expect(level).to_have_text("2")
    expect(share).to_have_text("102")
    expect(values).to_have_text(["2", "2", "2", "2", "102", "102"])
    page.screenshot(path=str(ARTIFACTS / "property-monitoring-online.png"))
    # The Variables view: the instance lists its monitored properties after its variables, with their values
    page.get_by_role("tab", name="Variables").click()
    table = page.get_by_role("table", name="Variables of MAIN")
    table.get_by_role("button", name="Expand Main.t").click()
    expect(table.locator('tr[data-path="MAIN.T.AMOUNT"] td.watch-value')).to_have_text("2")
    expect(table.locator('tr[data-path="MAIN.T.LEVEL"] td.watch-value')).to_have_text("2")
    expect(table.locator('tr[data-path="MAIN.T.SHARE"] td.watch-value')).to_have_text("102")
    page.get_by_role("button", name="Single cycle").click()
    expect(table.locator('tr[data-path="MAIN.T.LEVEL"] td.watch-value')).to_have_text("3")
    expect(table.locator('tr[data-path="MAIN.T.SHARE"] td.watch-value')).to_have_text("103")
    page.screenshot(path=str(ARTIFACTS / "property-monitoring-variables.png"))
