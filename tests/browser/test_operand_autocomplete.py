"""Operand autocomplete in LD (issue 22, item 7): Enter and Tab take the highlighted suggestion, not the
typed prefix; a name typed in full stays as typed."""

from __future__ import annotations

import pytest

from .steps import open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "complete",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    Start : BOOL;\n    StartCount : BOOL;\n    Motor : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {"type": "contact", "id": "c1", "var": "Start"},
                            {"type": "coil", "id": "q1", "var": "Motor"},
                        ],
                    }
                ]
            },
        }
    ],
}


def operands(page) -> list[str]:
    return page.locator("g.ld-element g.ld-operand > text").evaluate_all("els => els.map((e) => e.textContent)")


def insert_contact(page, typed: str, key: str) -> None:
    page.locator('g.ld-element[data-id="c1"] rect.ld-hit').click()
    page.keyboard.press("c")
    field = page.get_by_role("combobox", name="Variable")
    field.press_sequentially(typed)
    page.get_by_role("option").first.wait_for()
    field.press(key)
    field.wait_for(state="detached")


def test_enter_and_tab_take_the_highlighted_suggestion(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "complete", "Main")
    page.locator('g.ld-element[data-id="c1"]').wait_for()
    page.wait_for_function("document.querySelectorAll('g.ld-element').length === 2")

    insert_contact(page, "Mo", "Enter")
    assert operands(page) == ["Start", "Motor", "Motor"]
    insert_contact(page, "StartC", "Tab")
    assert operands(page) == ["Start", "StartCount", "Motor", "Motor"]
    insert_contact(page, "Start", "Enter")  # a full name stays, though StartCount is suggested
    assert operands(page) == ["Start", "Start", "StartCount", "Motor", "Motor"]
