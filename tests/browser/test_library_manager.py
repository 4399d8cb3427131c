"""The Library manager in a real browser: code brought from TwinCAT calls Tc2_Math's FRAC; the check says
which library has it; ticking the library in the Library manager makes the program build, and online it
computes FRAC's documented value (docs/st.md "Vendor libraries", issue 25)."""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from .conftest import ARTIFACTS
from .steps import _request, go_online, open_pou, panel_tab, store_project, watch

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "twincat",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    r : LREAL;\nEND_VAR",
            "body": "r := FRAC(-2.25);",
        }
    ],
}


def test_a_library_function_builds_once_its_library_is_ticked_and_runs(page, server: str) -> None:
    store_project(server, PROJECT)
    page.goto(server)
    open_pou(page, "twincat", "Main")
    page.keyboard.press("Control+Shift+B")  # Check
    problems = panel_tab(page, "Diagnostics").get_by_role("list", name="Diagnostics")
    problems.get_by_text(
        "unknown function 'FRAC': it is in the Tc2_Math library, which the project does not use: add it in the "
        "project's Library manager (--library Tc2_Math for a .st file)"
    ).wait_for()

    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Library manager").click()
    manager = page.get_by_role("region", name="Library manager")
    math = manager.get_by_role("region", name="Tc2_Math")
    expect(math.get_by_role("listitem").filter(has_text="FRAC(in : LREAL) : LREAL")).to_have_count(1)
    math.get_by_role("checkbox").check()
    expect(tree.get_by_role("button", name="Library manager")).to_contain_text("1")
    page.screenshot(path=str(ARTIFACTS / "library-manager.png"))

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert _request("GET", f"{server}/api/projects/twincat")["project"]["libraries"] == ["Tc2_Math"]
    go_online(page)
    expect(watch(page, "Main.r")).to_have_text("-0.25")  # the fraction keeps the sign of the input
    expect(math.get_by_role("checkbox")).to_be_disabled()  # online: the project is not edited


CODESYS_PROJECT = {
    "name": "codesys",
    "pous": [
        {
            "name": "Main",
            "kind": "program",
            "language": "st",
            "declarations": "VAR\n    a : BYTE := 200;\n    b : BYTE;\nEND_VAR",
            "body": "b := a + 100;",
        }
    ],
}


def test_codesys_typing_chosen_in_the_library_manager_builds_bit_string_arithmetic(page, server: str) -> None:
    """IEC refuses BYTE + 100 (ST-20); choosing the CODESYS V3 type rules in the Library manager makes it build,
    and online b is 200 + 100 cut to a BYTE: 44 (CODESYS "Operators", example 3; docs/st.md "CODESYS typing")."""
    store_project(server, CODESYS_PROJECT)
    page.goto(server)
    open_pou(page, "codesys", "Main")
    page.keyboard.press("Control+Shift+B")  # Check
    problems = panel_tab(page, "Diagnostics").get_by_role("list", name="Diagnostics")
    problems.get_by_text("'+' needs numbers (ANY_NUM), not BYTE").wait_for()

    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Library manager").click()
    rules = page.get_by_role("region", name="Library manager").get_by_role("group", name="Type rules")
    expect(rules.get_by_role("radio", name="IEC 61131-3")).to_be_checked()
    rules.get_by_role("radio", name="CODESYS V3").check()
    expect(tree.get_by_role("button", name="Library manager")).to_contain_text("CODESYS typing")

    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    assert _request("GET", f"{server}/api/projects/codesys")["project"]["typing"] == "codesys"
    go_online(page)
    expect(watch(page, "Main.b")).to_have_text("44")
    expect(rules.get_by_role("radio", name="CODESYS V3")).to_be_disabled()  # online: the project is not edited
