"""Object orientation in the browser (issue 25, item 5): the project tree shows a function block's methods and
properties under it (with EXTENDS / IMPLEMENTS), choosing one opens it in the FB's Methods tab, and a program that calls methods,
properties and an interface runs online with the values worked out by hand. Screenshot in tests/browser/artifacts/.
"""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from ladderlab.st.project_text import source_to_project

from .conftest import ARTIFACTS
from .steps import go_online, open_pou, settled_scan_count, store_project, watch

pytestmark = pytest.mark.browser

SOURCE = """
INTERFACE ICount
METHOD Add : INT
VAR_INPUT n : INT; END_VAR
END_METHOD
END_INTERFACE
FUNCTION_BLOCK Base
VAR sum : INT; END_VAR
METHOD PRIVATE Bump
VAR_INPUT n : INT; END_VAR
sum := sum + n;
END_METHOD
METHOD Add : INT
VAR_INPUT n : INT; END_VAR
Bump(n);
Add := sum;
END_METHOD
PROPERTY Total : INT
GET
Total := sum;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
FUNCTION_BLOCK Counter EXTENDS Base IMPLEMENTS ICount
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : Counter; i : ICount; seen : INT; END_VAR
i := c;
i.Add(2);
seen := c.Total;
END_PROGRAM
"""


def test_methods_and_properties_in_the_tree_and_online(page, server) -> None:
    project, diagnostics = source_to_project(SOURCE, "oop")
    assert project is not None and diagnostics == []
    store_project(server, project.model_dump(mode="json", exclude_none=True))
    page.goto(server)
    open_pou(page, "oop", "Main")
    tree = page.get_by_role("navigation", name="Project tree")
    base = tree.get_by_role("list", name="Base members")
    expect(base.get_by_role("button")).to_have_text(["MBump (PRIVATE)", "MAdd : INT", "PTotal : INT"])
    expect(tree.get_by_role("list", name="Counter members")).to_have_text("EXTENDS Base IMPLEMENTS ICount")
    page.screenshot(path=str(ARTIFACTS / "oop-tree.png"))

    base.get_by_role("button", name="Add : INT").click()  # the FB holding the method opens on it, as CODESYS does
    expect(page.get_by_role("tab", name="Methods")).to_have_attribute("aria-selected", "true")
    expect(page.get_by_role("textbox", name="Base.Add body")).to_contain_text("Bump(n);Add := sum;")

    open_pou(page, "oop", "Main")
    seen = watch(page, "Main.seen")
    go_online(page, run=False)
    start = settled_scan_count(page)
    for done in range(1, 4):
        page.get_by_role("button", name="Single cycle").click()
        page.wait_for_function(
            "n => Number(document.querySelector('[data-testid=scan-count]').textContent) === n", arg=start + done
        )
        # each scan adds 2 through the interface; the inherited property reads the base's variable
        expect(seen).to_have_text(str(2 * (start + done)))


def test_renaming_a_base_lists_and_rewrites_extends_and_what_methods_use(page, server) -> None:
    """Issue 25 item 5 of the brief: the rename preview lists the EXTENDS and IMPLEMENTS that name the renamed function
    block or interface, and a method's own texts, in the tree's words; applying it rewrites them."""
    project, diagnostics = source_to_project(SOURCE, "oop")
    assert project is not None and diagnostics == []
    store_project(server, project.model_dump(mode="json", exclude_none=True))
    page.goto(server)
    open_pou(page, "oop", "Main")
    page.keyboard.press("Escape")
    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name="Actions for Base", exact=True).click()
    page.get_by_role("menu", name="Base actions", exact=True).get_by_role("menuitem", name="Rename…").click()
    dialog = page.get_by_role("dialog", name="Rename Base")
    dialog.get_by_label("New name").fill("Root")
    dialog.get_by_role("button", name="Preview").click()
    references = dialog.get_by_role("list", name="References")
    references.wait_for()
    assert references.get_by_role("listitem").all_inner_texts() == ["Counter EXTENDS Base"]
    dialog.get_by_role("button", name="Rename").click()
    expect(tree.get_by_role("list", name="Counter members")).to_have_text("EXTENDS Root IMPLEMENTS ICount")
