"""The Diagnostics panel in a real browser (issue 19 item 5, issue 22 item 5).

Check an LD program with a misspelt contact and a coil on an INT: the panel names each element in the
user's words (network by number and label, element by its operand, never the editor's ids), and a click
on a code opens its entry of the diagnostics catalogue (docs/diagnostics.md): the example and the fix.
The requests go through the generated API client (check, project load).
"""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import open_pou, panel_tab, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "diag",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR Start : BOOL; n : INT; END_VAR",
            "body": {
                "networks": [
                    {
                        "id": "net7",
                        "label": "Pump",
                        "elements": [
                            {"id": "contact3", "type": "contact", "mode": "no", "var": "Strat"},
                            {"id": "coil9", "type": "coil", "mode": "normal", "var": "n"},
                        ],
                    }
                ]
            },
        }
    ],
}


def test_diagnostics_name_elements_in_the_users_words_and_open_their_catalogue_entry(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "diag", "Main")
    page.keyboard.press("Control+Shift+B")  # Check
    panels = panel_tab(page, "Diagnostics")
    items = panels.get_by_role("list", name="Diagnostics").locator(":scope > li")
    items.first.wait_for()
    places = items.locator(".diagnostic-place").all_inner_texts()
    assert places == ['Main, network 1 "Pump", contact Strat', 'Main, network 1 "Pump", coil n']
    text = " ".join(items.all_inner_texts())
    assert "contact3" not in text and "coil9" not in text and "net7" not in text

    code = panels.get_by_role("button", name="ST-UNKNOWN-VAR")
    # the catalogue is loaded when the panel first lists a problem (issue 22 item 8): the summary comes with it
    expect(code).to_have_attribute("title", "A name is used that is not declared.")
    code.click()
    entry = panels.get_by_role("note", name="About ST-UNKNOWN-VAR")
    entry.wait_for()
    assert entry.locator("pre").inner_text() == "Motor := Strat;"
    assert "Fix: declare the variable, or correct the name" in entry.inner_text()
    page.screenshot(path=str(ARTIFACTS / "diagnostics-entry.png"))
