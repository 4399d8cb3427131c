"""Online mode as a CODESYS user tries it, one scenario per test, in the real Chromium (issue 17).

Each test drives the example project the server seeds (``motor``: Main in LD with a seal-in rung, a TON
``RunTimer`` with PT = T#5s, a start counter; Scaling in FBD; Blinker in ST) against a real server, and
fails on any page error or console error (conftest.py). Screenshots go to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, panel_tab

pytestmark = pytest.mark.browser


def contact(page, element_id: str):
    return page.locator(f'g.ld-element[data-id="{element_id}"]')


def test_log_force_release_and_tab_switches_never_blank_the_page(page, server):
    """The blocker of issue 17: force, open the Online log, switch tabs, release: the page stays."""
    page.goto(server)
    open_pou(page, "motor", "Main")
    go_online(page)

    contact(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Force TRUE").click()
    panels = panel_tab(page, "Online log")
    log = panels.get_by_role("list", name="Online log")
    log.get_by_text(re.compile("forced", re.I)).first.wait_for()
    panel_tab(page, "Watch list")
    panel_tab(page, "Online log")
    contact(page, "stop").locator(".ld-hit").click(button="right")
    page.get_by_role("menuitem", name="Release force").click()
    log.get_by_text(re.compile("released", re.I)).first.wait_for()
    panel_tab(page, "Diagnostics")
    panel_tab(page, "Online log")
    assert page.get_by_role("heading", name="motor").is_visible()
    assert page.get_by_role("application", name="Ladder diagram editor").is_visible()
    page.screenshot(path=str(ARTIFACTS / "online-log.png"))
