"""The app opens without the ST and FBD editors' code (issue 22, item 8): CodeMirror and @xyflow load
the first time an ST or FBD POU opens, and the editors then work."""

from __future__ import annotations

import re

import pytest

from .steps import open_pou, store_project

pytestmark = pytest.mark.browser

PROJECT = {
    "name": "lazy",
    "pous": [
        {"name": "Lad", "kind": "program", "language": "ld", "body": {"networks": []}},
        {
            "name": "Text",
            "kind": "program",
            "language": "st",
            "body": "x := TRUE;",
            "declarations": "VAR x : BOOL; END_VAR",
        },
        {"name": "Blocks", "kind": "program", "language": "fbd", "body": {"networks": []}},
    ],
}


def test_st_and_fbd_editors_load_on_first_use(page, server: str) -> None:
    store_project(server, PROJECT)
    scripts: list[str] = []
    page.on("request", lambda request: scripts.append(request.url) if request.resource_type == "script" else None)
    page.goto(server)
    open_pou(page, "lazy", "Lad")
    page.get_by_role("tab", name=re.compile("^Lad")).wait_for()
    page.wait_for_load_state("networkidle")
    loaded = " ".join(scripts)
    assert "StEditor" not in loaded and "FbdPouView" not in loaded

    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name=re.compile("^Text")).click()
    page.get_by_label("Text body").wait_for()
    assert any("StEditor" in url for url in scripts)
    assert not any("FbdPouView" in url for url in scripts)

    tree.get_by_role("button", name=re.compile("^Blocks")).click()
    page.get_by_role("button", name="Add network").first.wait_for()
    assert any("FbdPouView" in url for url in scripts)
