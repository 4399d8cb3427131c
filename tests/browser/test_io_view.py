"""The process image in a real browser against a real server (issue 16).

A project whose configuration runs two instances of one program on a resource's task: the project
tree shows the configuration, the resource, the task and its instances. Online, the I/O view lists
every address the program uses (area, address, the variables declared at it, value); writing an
input by its address turns an output on, forcing another input turns it off again, and an
unnamed memory word counts. No console errors along the way.
Screenshots are written to tests/browser/artifacts/.
"""

from __future__ import annotations

import re

import pytest

from .conftest import ARTIFACTS
from .steps import store_project

pytestmark = pytest.mark.browser

CONVEYOR_DECLARATIONS = """VAR
    Start AT %IX0.1 : BOOL;
    Lamp AT %QX3.0 : BOOL;
    Count : INT;
END_VAR"""
CONVEYOR_BODY = """Lamp := Start AND NOT %IX0.2;
Count := Count + 1;
%MW10 := Count;"""


def _row(page, address: str):
    return page.locator(f'table[aria-label="Process image"] tr[data-path="{address}"]')


def _shows(page, address: str, value: str, forced: bool = False) -> None:
    """Wait until the I/O view shows ``value`` at ``address``, on the forced colours with an F or not."""
    tag = _row(page, address).locator(f'td.watch-value .value-tag[data-value="{value}"]')
    tag.and_(page.locator(".value-tag-forced" if forced else ".value-tag:not(.value-tag-forced)")).wait_for()


def test_the_io_view_shows_and_drives_the_process_image_of_a_configuration(page, server):
    problems: list[str] = []
    page.on("console", lambda m: problems.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: problems.append(str(e)))
    instances = [{"name": "Line1", "type": "Conveyor"}, {"name": "Line2", "type": "Conveyor"}]
    store_project(
        server,
        {
            "name": "plant",
            "pous": [
                {
                    "name": "Conveyor",
                    "kind": "program",
                    "language": "st",
                    "declarations": CONVEYOR_DECLARATIONS,
                    "body": CONVEYOR_BODY,
                }
            ],
            "configuration": {
                "name": "Plant",
                "resources": [
                    {
                        "name": "Cpu",
                        "on": "PLC",
                        "tasks": [{"name": "Fast", "interval": "T#10ms", "priority": 1, "programs": instances}],
                    }
                ],
            },
        },
    )
    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^plant")).click()
    page.get_by_role("heading", name="plant", exact=True).wait_for()

    # The project tree: the configuration, its resource, the task and the two instances it runs.
    tasks = page.get_by_role("region", name="Tasks")
    assert tasks.get_by_role("heading").text_content() == "Configuration Plant"
    assert tasks.locator(".tree-resource-name").inner_text() == "Resource Cpu on PLC"
    assert tasks.locator(".tree-task > span").first.inner_text() == (  # its ⋯ menu button beside it
        "Fast every T#10ms · priority 1 · Line1 : Conveyor, Line2 : Conveyor"
    )

    page.get_by_role("button", name="Compile & simulate").click()
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    page.get_by_role("tab", name="I/O (4)").click()
    rows = page.locator('table[aria-label="Process image"] tbody tr')
    rows.first.wait_for()
    cells = [[row.locator("td").all_inner_texts()[i] for i in (0, 1, 2, 4)] for row in rows.all()]
    assert cells == [  # area, address, the variables declared at it, type
        ["Input", "%IX0.1", "LINE1.START, LINE2.START", "BOOL"],
        ["Input", "%IX0.2", "—", "BOOL"],
        ["Output", "%QX3.0", "LINE1.LAMP, LINE2.LAMP", "BOOL"],
        ["Memory", "%MW10", "—", "INT"],
    ]
    page.get_by_role("button", name="Run", exact=True).click()
    state.filter(has_text="Online · running").wait_for()
    _shows(page, "%QX3.0", "FALSE")
    page.wait_for_function(
        """() => Number(document.querySelector('tr[data-path="%MW10"] td.watch-value')?.textContent) > 5"""
    )

    # Write the input by its address: the output follows at the end of the next scan.
    page.get_by_label("New value for %IX0.1").fill("TRUE")
    _row(page, "%IX0.1").get_by_role("button", name="Write").click()
    _shows(page, "%IX0.1", "TRUE")
    _shows(page, "%QX3.0", "TRUE")
    page.screenshot(path=str(ARTIFACTS / "io-view.png"))

    # Force the other input (no variable names it): the output goes off and the address shows F.
    page.get_by_label("New value for %IX0.2").fill("TRUE")
    _row(page, "%IX0.2").get_by_role("button", name="Force").click()
    _shows(page, "%IX0.2", "TRUE", forced=True)
    _shows(page, "%QX3.0", "FALSE")
    _row(page, "%IX0.2").get_by_role("button", name="Release").click()
    _shows(page, "%IX0.2", "TRUE")  # released: the input keeps its value
    page.get_by_label("New value for %IX0.2").fill("FALSE")
    _row(page, "%IX0.2").get_by_role("button", name="Write").click()
    _shows(page, "%IX0.2", "FALSE")
    _shows(page, "%QX3.0", "TRUE")

    # Watch an address from the I/O view: it joins the watch list with its value.
    page.get_by_role("button", name="Watch %MW10").click()
    page.get_by_role("tab", name=re.compile("^Watch list")).click()
    page.wait_for_function(
        """() => Number(document.querySelector('table[aria-label="Watch list"] tr[data-path="%MW10"] td.watch-value')
            ?.textContent) > 5"""
    )
    assert problems == []
