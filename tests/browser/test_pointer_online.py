"""ON-11 in Chromium: online, a pointer shows its own value (the ADR()/REF() it holds) in the Variables view (the
declaration part online) and expands to what it points to, ``p^``, and on to its members; a value written to
``p^`` there lands in the array element p points to; the watch list takes ``rp^.y`` and ``r.x`` paths and forces
through them. Expected values follow from the program text."""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, panel_tab, store_project, watch

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "pointers",
    "types": "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    a : ARRAY [1..3] OF INT := [10, 20, 30];\n    pt : Pt;\n"
            "    p : POINTER TO INT;\n    rp : REF_TO Pt;\n    r : REFERENCE TO Pt;\nEND_VAR",
            "body": "p := ADR(a[2]);\nrp := REF(pt);\nr REF= pt;\npt.x := 4;\n",
        }
    ],
}


def test_a_pointer_expands_to_its_target_and_paths_take_carets(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "pointers", "Main")
    go_online(page)
    page.get_by_role("tab", name="Variables").click()
    table = page.get_by_role("table", name="Variables of MAIN")
    value = lambda path: table.locator(f'tr[data-path="{path}"] td.watch-value')  # noqa: E731
    expect(value("MAIN.P")).to_have_text("ADR(a[2])")
    expect(value("MAIN.RP")).to_have_text("REF(pt)")
    table.get_by_role("button", name="Expand MAIN.p", exact=True).click()
    expect(value("MAIN.P^")).to_have_text("20")
    expect(table.locator('tr[data-path="MAIN.P^"] td.watch-type')).to_have_text("INT")
    table.get_by_role("button", name="Expand MAIN.rp", exact=True).click()
    table.get_by_role("button", name="Expand MAIN.rp^", exact=True).click()
    expect(value("MAIN.RP^.X")).to_have_text("4")
    expect(table.get_by_label("New value for MAIN.p", exact=True)).to_have_count(0)  # a pointer is set by the program

    page.get_by_label("New value for MAIN.p^").fill("77")
    table.locator('tr[data-path="MAIN.P^"]').get_by_role("button", name="Write").click()
    expect(value("MAIN.P^")).to_have_text("77")
    table.get_by_role("button", name="Expand MAIN.a", exact=True).click()
    expect(value("MAIN.A[2]")).to_have_text("77")  # the element p points to
    page.screenshot(path=str(ARTIFACTS / "online-pointer.png"))

    expect(watch(page, "Main.r.x")).to_have_text("4")
    cell = watch(page, "Main.rp^.y")
    expect(cell).to_have_text("0")
    panels = panel_tab(page, "Watch list")
    panels.get_by_label("New value for Main.rp^.y").fill("9")
    panels.locator('tr[data-path="MAIN.RP^.Y"]').get_by_role("button", name="Force").click()
    expect(cell).to_contain_text("9")
    panels.locator('tr[data-path="MAIN.RP^.Y"] .forced-mark').wait_for()
    expect(value("MAIN.RP^.Y")).to_contain_text("9")  # pt.y itself, seen through rp in the Variables view
