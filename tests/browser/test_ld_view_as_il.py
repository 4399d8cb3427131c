"""'View as IL' in the LD editor (issue 26 item 4): the context menu of a network's element shows the network
as IL, read-only; a network with an edge contact says why it has none. (That the IL runs like the network is
tests/interchange/test_ld_il.py's.)"""

from __future__ import annotations

import pytest

from .conftest import ARTIFACTS
from .steps import open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "ldil",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    Start, Stop, Motor, Lamp : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {
                                "type": "parallel",
                                "id": "p1",
                                "branches": [
                                    [{"type": "contact", "id": "start", "var": "Start"}],
                                    [{"type": "contact", "id": "self", "var": "Motor"}],
                                ],
                            },
                            {"type": "contact", "id": "stop", "var": "Stop", "mode": "nc"},
                            {"type": "coil", "id": "motor", "var": "Motor"},
                        ],
                    },
                    {
                        "id": "n2",
                        "elements": [
                            {"type": "contact", "id": "edge", "var": "Start", "mode": "p"},
                            {"type": "coil", "id": "lamp", "var": "Lamp"},
                        ],
                    },
                ]
            },
        }
    ],
}


def test_view_a_network_as_il(page, server):
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "ldil", "Main")
    page.locator('g.ld-element[data-id="stop"] .ld-hit').click(button="right")
    page.get_by_role("menuitem", name="View as IL").click()
    dialog = page.get_by_role("dialog", name="Network 1 as IL")
    text = dialog.get_by_label("IL text")
    text.wait_for()
    assert text.inner_text() == "LD Start\nOR Motor\nANDN Stop\nST Motor"
    page.screenshot(path=str(ARTIFACTS / "ld-view-as-il.png"))
    dialog.get_by_role("button", name="Close").click()
    dialog.wait_for(state="detached")

    page.locator('g.ld-element[data-id="edge"] .ld-hit').click(button="right")
    page.get_by_role("menuitem", name="View as IL").click()
    note = page.get_by_role("dialog", name="Network 2 as IL").get_by_role("note")
    note.wait_for()
    assert note.inner_text() == (
        "This network has no plain IL equivalent: the P contact Start detects an edge: IL needs an R_TRIG."
    )
