"""Completion after qualified names (issue 25) in real Chromium: after a program's name its inputs and outputs
(`Other.k`, read from another POU as the checker allows), after an enumeration type's name its values (CODESYS's
`Color.Green`, IEC's `Color#Red`), in the ST editor and in the LD/FBD operand editor; what is picked compiles."""

from __future__ import annotations

import pytest

from .steps import _request, open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "qualified",
    "types": "TYPE\n    Color : (Red, Green, Blue);\nEND_TYPE",
    "pous": [
        {
            "name": "Other",
            "kind": "program",
            "language": "st",
            "declarations": "VAR_INPUT\n    k : INT;\nEND_VAR\nVAR_OUTPUT\n    done : BOOL;\nEND_VAR\n"
            "VAR\n    hidden : INT;\nEND_VAR",
            "body": "done := k > hidden;",
        },
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    c : Color;\n    n : INT;\n    d : Der;\nEND_VAR",
            "body": "",
        },
        {
            "name": "Base",
            "kind": "function_block",
            "language": "st",
            "declarations": "VAR_INPUT\n    bi : INT;\nEND_VAR\nVAR_OUTPUT\n    bo : INT;\nEND_VAR\nVAR\n    bv : INT;\nEND_VAR",
            "body": "bo := bi + bv;",
        },
        {
            "name": "Der",
            "kind": "function_block",
            "language": "st",
            "extends": "Base",
            "declarations": "VAR_INPUT\n    di : INT;\nEND_VAR\nVAR\n    dv : INT;\nEND_VAR",
            "body": "",
        },
        {
            "name": "Lad",
            "kind": "program",
            "language": "ld",
            "declarations": "VAR\n    c : Color;\n    Motor : BOOL;\nEND_VAR",
            "body": {
                "networks": [
                    {
                        "id": "n1",
                        "elements": [
                            {"type": "compare", "id": "c1", "op": "EQ", "left": "c", "right": "c"},
                            {"type": "coil", "id": "q1", "var": "Motor"},
                        ],
                    }
                ]
            },
        },
        {
            "name": "Fbd",
            "kind": "program",
            "language": "fbd",
            "declarations": "VAR\n    c : Color;\nEND_VAR",
            "body": {"networks": [{"id": "n1", "nodes": [], "wires": []}]},
        },
    ],
    "tasks": [{"name": "Fast", "interval": "T#10ms", "programs": ["Other", "Main", "Lad", "Fbd"]}],
}

OPTIONS = ".cm-tooltip-autocomplete .cm-completionLabel"


def st_options(page, count: int) -> list[str]:
    page.wait_for_function(f"() => document.querySelectorAll('{OPTIONS}').length === {count}")
    return page.locator(OPTIONS).all_inner_texts()


def pick(page, label: str) -> None:
    """Clicks a completion (Enter right after the list changes is ignored for CodeMirror's interaction delay)."""
    page.locator(OPTIONS, has_text=label).click()
    page.locator(OPTIONS).first.wait_for(state="detached")


def errors(server: str) -> list[dict]:
    check = _request("POST", f"{server}/api/projects/qualified/check")
    return [d for d in check["diagnostics"] if d.get("severity", "error") == "error"]


def test_st_completion_after_a_program_and_an_enumeration(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "qualified", "Main")
    body = page.get_by_label("Main body")
    body.wait_for()
    body.focus()
    page.keyboard.type("c := Color.")
    assert st_options(page, 3) == ["Red", "Green", "Blue"]
    page.keyboard.type("Gr")
    assert st_options(page, 1) == ["Green"]
    pick(page, "Green")
    page.keyboard.type(";\nn := Other.")
    # its input and output, not the internal `hidden` (the checker: ST-NOT-ACCESSIBLE)
    assert st_options(page, 2) == ["k", "done"]
    pick(page, "k")
    page.keyboard.type(";\nc := Color#")
    assert st_options(page, 3) == ["Red", "Green", "Blue"]
    pick(page, "Blue")
    page.keyboard.type(";")
    assert body.inner_text() == "c := Color.Green;\nn := Other.k;\nc := Color#Blue;"
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert errors(server) == []
    body.locator(".cm-lintRange").wait_for(state="detached")


def test_st_completion_after_a_global_variable_lists_name(page, server: str) -> None:
    """After a named GVL's name its variables, after an instance in it the FB's pins; what is picked compiles (a
    qualified_only list's variables are used qualified)."""
    store_project(
        server,
        {
            **PROJECT,
            "gvls": [
                {
                    "name": "GVL_IO",
                    "qualified_only": True,
                    "text": "VAR_GLOBAL\n    bStart : BOOL;\n    tOn : TON;\nEND_VAR",
                }
            ],
        },
    )
    page.goto(server)
    open_pou(page, "qualified", "Main")
    body = page.get_by_label("Main body")
    body.wait_for()
    body.focus()
    page.keyboard.type("GVL_IO.")
    assert st_options(page, 2) == ["bStart", "tOn"]
    pick(page, "tOn")
    page.keyboard.type("(IN := GVL_IO.bS")
    assert st_options(page, 1) == ["bStart"]
    pick(page, "bStart")
    page.keyboard.type(", PT := T#1s);\nGVL_IO.bStart := GVL_IO.tOn.")
    assert st_options(page, 4) == ["IN", "PT", "Q", "ET"]
    pick(page, "Q")
    page.keyboard.type(";")
    assert body.inner_text() == "GVL_IO.tOn(IN := GVL_IO.bStart, PT := T#1s);\nGVL_IO.bStart := GVL_IO.tOn.Q;"
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert errors(server) == []


def test_st_completion_through_extends_this_and_super(page, server: str) -> None:
    """An instance of an FB with EXTENDS offers its base's pins too; THIS^. all the instance's variables, SUPER^. the
    base's (the checker accepts `THIS^.bv`, internal, in the FB's own code)."""
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "qualified", "Main")
    body = page.get_by_label("Main body")
    body.wait_for()
    body.focus()
    page.keyboard.type("n := d.")
    assert st_options(page, 3) == ["bi", "di", "bo"]
    pick(page, "bo")
    page.keyboard.type(";")

    open_pou(page, "qualified", "Der")
    body = page.get_by_label("Der body")
    body.wait_for()
    body.focus()
    page.keyboard.type("dv := THIS^.")
    assert st_options(page, 5) == ["bi", "bo", "bv", "di", "dv"]
    pick(page, "bv")
    page.keyboard.type(" + SUPER^.")
    assert st_options(page, 3) == ["bi", "bo", "bv"]
    pick(page, "bi")
    page.keyboard.type(";")
    assert body.inner_text() == "dv := THIS^.bv + SUPER^.bi;"
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert errors(server) == []


def test_ld_and_fbd_operand_editors_after_a_program_and_an_enumeration(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "qualified", "Lad")
    page.locator('g.ld-element[data-id="c1"]').wait_for()

    # the compare's right operand: an enumeration value, picked from the list
    page.locator('g.ld-element[data-id="c1"] [data-field="right"] text').click()
    field = page.get_by_role("combobox", name="Right operand")
    field.press("Control+a")
    field.press_sequentially("Color.")
    options = page.get_by_role("option")
    options.first.wait_for()
    assert [o.split(" ")[0] for o in options.all_inner_texts()] == ["Color.Red", "Color.Green", "Color.Blue"]
    field.press("ArrowDown")
    field.press("Enter")
    field.wait_for(state="detached")

    # a new contact reading another program's output
    page.locator('g.ld-element[data-id="c1"] rect.ld-hit').click(position={"x": 4, "y": 4})  # beside its operands
    page.keyboard.press("c")
    field = page.get_by_role("combobox", name="Variable")
    field.press_sequentially("Other.")
    options.first.wait_for()
    assert options.all_inner_texts() == ["Other.k INT", "Other.done BOOL"]
    field.press_sequentially("d")
    page.wait_for_function("document.querySelectorAll('[role=option]').length === 1")
    field.press("Enter")
    field.wait_for(state="detached")
    texts = page.locator("g.ld-element g.ld-operand > text").evaluate_all("els => els.map((e) => e.textContent)")
    assert "Color.Green" in texts and "Other.done" in texts

    # an FBD input node: `Color#` offers the values too
    open_pou(page, "qualified", "Fbd")
    page.locator(".fbd-network .react-flow__pane").first.wait_for()
    page.get_by_role("toolbar", name="FBD editing").get_by_role("button", name="Input", exact=True).click()
    field = page.get_by_role("combobox", name="Input operand")
    field.wait_for()
    page.wait_for_function("document.activeElement && document.activeElement.getAttribute('role') === 'combobox'")
    page.keyboard.type("color#")
    options.first.wait_for()
    assert options.all_inner_texts() == ["color#Red Color", "color#Green Color", "color#Blue Color"]
    page.keyboard.press("Enter")  # the first, highlighted as the typed text starts it
    page.locator(".react-flow__node .fbd-text", has_text="color#Red").wait_for()

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    saved = _request("GET", f"{server}/api/projects/qualified")["project"]
    lad = next(p for p in saved["pous"] if p["name"] == "Lad")
    elements = [e for n in lad["body"]["networks"] for e in n["elements"]]
    assert [(e["type"], e.get("right") or e.get("var")) for e in elements] == [
        ("compare", "Color.Green"),
        ("contact", "Other.done"),
        ("coil", "Motor"),
    ]
    fbd = next(p for p in saved["pous"] if p["name"] == "Fbd")
    assert [n.get("expr") for n in fbd["body"]["networks"][0]["nodes"]] == ["color#Red"]
    assert errors(server) == []  # the picked operands compile
