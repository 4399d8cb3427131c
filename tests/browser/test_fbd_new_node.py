"""A new FBD input or output node takes typing at once (issue 22, item 6): its text field is focused and
drawn on the node, so a name typed right after placing it lands in the node."""

from __future__ import annotations

import pytest

from .steps import new_pou, new_project, open_pou, store_project

pytestmark = pytest.mark.browser


@pytest.mark.parametrize("how", ["click", "drop"])
def test_a_placed_node_takes_the_typed_name(page, server: str, how: str) -> None:
    new_project(page, server, "nodes")
    new_pou(page, "Main", language="fbd")
    editor = page.get_by_role("application", name="Function block diagram editor")
    editor.get_by_role("button", name="Add network").click()
    canvas = editor.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    tool = page.get_by_role("toolbar", name="FBD editing").get_by_role("button", name="Input", exact=True)
    if how == "click":
        tool.click()
    else:
        tool.drag_to(canvas, target_position={"x": 80, "y": 40})
    field = page.get_by_role("combobox", name="Input operand")
    field.wait_for()
    page.wait_for_function("document.activeElement && document.activeElement.getAttribute('role') === 'combobox'")
    page.keyboard.type("Speed")
    assert field.input_value() == "Speed"
    # drawn on its node: the field's box overlaps the node's
    node = page.locator(".react-flow__node").filter(has=field)
    field_box, node_box = field.bounding_box(), node.bounding_box()
    assert node_box["y"] <= field_box["y"] + field_box["height"] / 2 <= node_box["y"] + node_box["height"]
    page.keyboard.press("Enter")
    page.locator(".react-flow__node .fbd-text", has_text="Speed").wait_for()


def test_the_field_stays_on_the_node_while_it_suggests_names(page, server: str) -> None:
    """With variables to suggest, the list opens below the field; the field stays on the node (the list in the
    node's flow drew it ~60 px above the node)."""
    store_project(
        server,
        {
            "name": "named",
            "pous": [
                {
                    "name": "Main",
                    "kind": "program",
                    "language": "fbd",
                    "declarations": "VAR\n    Speed : INT;\n    Start : BOOL;\n    Total : INT;\nEND_VAR",
                    "body": {"networks": [{"id": "n1", "nodes": [], "wires": []}]},
                }
            ],
        },
    )
    page.goto(server)
    open_pou(page, "named", "Main")
    canvas = page.locator(".fbd-network .react-flow__pane").first
    canvas.wait_for()
    page.get_by_role("toolbar", name="FBD editing").get_by_role("button", name="Input", exact=True).click()
    field = page.get_by_role("combobox", name="Input operand")
    field.wait_for()
    page.keyboard.type("S")
    suggestions = page.get_by_role("listbox")
    suggestions.get_by_role("option").first.wait_for()
    node = page.locator(".react-flow__node").filter(has=field)
    field_box, node_box, list_box = field.bounding_box(), node.bounding_box(), suggestions.bounding_box()
    assert node_box["y"] <= field_box["y"] + field_box["height"] / 2 <= node_box["y"] + node_box["height"]
    assert list_box["y"] >= field_box["y"] + field_box["height"] - 1  # below the field
