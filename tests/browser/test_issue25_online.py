"""Issue 25's values online in Chromium: the ST editor shows an LTIME, an enumeration value (as declared, the
watch list too), a part (``w.%X3``) and a pointer's own value (the ADR() it holds: ON-11) inline; an LD box writes a part (a MOVE's OUT into ``w.%B0``) and
a contact on ``w.%X3`` lights up, its badge showing the bit; a part is traced and triggers the trace. Expected values
follow from the program text (IEC 61131-3 ed. 3 6.5.6 numbers parts from the least significant bit; 16#08 is
bit 3)."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, store_project, watch

pytestmark = pytest.mark.browser

MAIN_BODY = "w.%X3 := TRUE;\nlt := LTIME#1ms500us;\nm := Mode#Run;\np := ADR(a[2]);\n"

PROJECT = {
    "name": "values25",
    "types": "TYPE Mode : (Idle, Run := 5, Halt); END_TYPE",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    w : WORD;\n    lt : LTIME;\n    m : Mode;\n"
            "    a : ARRAY [1..3] OF INT := [10, 20, 30];\n    p : POINTER TO INT;\nEND_VAR",
            "body": MAIN_BODY,
        },
        {
            "name": "Lights",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    w : WORD;\n    lamp : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {
                                "type": "box",
                                "id": "move",
                                "call": "MOVE",
                                "en": True,
                                "inputs": {"IN": "16#08"},
                                "outputs": {"OUT": "w.%B0"},
                            },
                        ],
                    },
                    {
                        "id": "n2",
                        "elements": [
                            {"type": "contact", "id": "bit3", "var": "w.%X3"},
                            {"type": "coil", "id": "lamp", "var": "lamp"},
                        ],
                    },
                ],
            },
        },
    ],
    "tasks": [{"name": "Cyclic", "interval": "T#10ms", "programs": ["Main", "Lights"]}],
}


def test_ltime_an_enumeration_a_part_and_a_pointer_show_inline_in_st(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "values25", "Main")
    go_online(page)
    values = page.get_by_role("textbox", name="Main body").locator(".cm-st-value")
    # w.%X3, lt, m (the enumeration's value by name, spelled as declared: Run, as CODESYS shows it; brief polish25
    # item 1), p, a[2] (the element p points to)
    expect(values).to_have_text(["TRUE", "LTIME#1ms500us", "Run", "ADR(a[2])", "20"])
    expect(watch(page, "Main.m")).to_have_text("Run")  # the watch list names it alike
    page.screenshot(path=str(ARTIFACTS / "online-issue25-st.png"))


def test_an_ld_box_writes_a_part_and_a_contact_on_it_lights_up(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "values25", "Lights")
    go_online(page)
    contact = page.locator('g.ld-element[data-id="bit3"]')
    expect(contact).to_have_class(re.compile(r"\bld-on\b"))
    expect(contact.locator(".ld-badge").first).to_have_attribute("data-value", "TRUE")  # w.%X3's own value
    move = page.locator('g.ld-element[data-id="move"]')
    expect(move.locator('[data-pin-value="out:OUT"] .ld-badge')).to_have_attribute("data-value", "8")  # 16#08
    expect(page.locator('g.ld-element[data-id="lamp"]')).to_have_class(re.compile(r"\bld-on\b"))
    page.screenshot(path=str(ARTIFACTS / "online-issue25-ld.png"))


def test_a_part_is_traced_and_triggers_the_trace(page, server: str) -> None:
    """Trace d and its bit 0, triggered by bit 1 rising: the trace starts where d reaches 2 (mod 4), and bit 0
    alternates FALSE, TRUE with d even, odd."""
    main = {
        "name": "Main",
        "kind": "program",
        "language": "st",
        "declarations": "VAR\n    d : DINT;\nEND_VAR",
        "body": "d := d + 1;\n",
    }
    store_project(server, {"name": "trace25", "pous": [main]})
    page.goto(server)
    open_pou(page, "trace25", "Main")
    go_online(page)
    page.get_by_role("tab", name="Trace").click()
    for path in ("Main.d.%X0", "Main.d"):
        page.get_by_label("Variable to trace").fill(path)
        page.keyboard.press("Enter")
    page.get_by_label("Trigger variable").fill("Main.d.%X1")
    page.get_by_label("Samples to keep").fill("4")
    page.get_by_role("button", name="Start trace").click()
    page.get_by_role("status", name="Trace state").filter(has_text="Done · 4 samples").wait_for()
    page.get_by_label("Table").check()
    rows = page.get_by_role("table", name="Trace samples").locator("tbody tr")
    table = rows.evaluate_all("rows => rows.map(r => [...r.children].map(c => c.textContent))")
    assert [row[2] for row in table] == ["FALSE", "TRUE", "FALSE", "TRUE"]
    first = int(table[0][3])
    assert first % 4 == 2 and [int(row[3]) for row in table] == [first, first + 1, first + 2, first + 3]


def test_an_enumeration_is_traced_by_its_values_names_as_declared(page, server: str) -> None:
    """Main sets m := Mode#Run every scan: the trace's table names the value Run (declared), not RUN or 5."""
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "values25", "Main")
    go_online(page)
    page.get_by_role("tab", name="Trace").click()
    page.get_by_label("Variable to trace").fill("Main.m")
    page.keyboard.press("Enter")
    page.get_by_label("Samples to keep").fill("2")
    page.get_by_role("button", name="Start trace").click()
    page.get_by_role("status", name="Trace state").filter(has_text="Done · 2 samples").wait_for()
    page.get_by_label("Table").check()
    rows = page.get_by_role("table", name="Trace samples").locator("tbody tr")
    assert rows.evaluate_all("rows => rows.map(r => r.children[2].textContent)") == ["Run", "Run"]
