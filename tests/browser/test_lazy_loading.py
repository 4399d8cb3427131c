"""The app opens without the ST and FBD editors' code (issue 22, item 8): CodeMirror and @xyflow load
the first time an ST or FBD POU opens, and the editors then work. The app's entry chunk, which holds the
LD editor, stays within 450 kB (minified) and is measured as the browser receives it; the diagnostics
catalogue and the rarely used panels come only when first shown."""

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


#: Issue 22 item 8: the entry chunk (app shell, LD editor, panels) at most 450 kB minified; 420.9 kB on 2026-11-28
#: once the tree's dialogs load on first use (445 kB before); 426.4 kB with the toolbars' measured "More" menu
#: (ui/OverflowBar.tsx, ui24); 432.8 kB on 2026-11-29 with the named global variable lists in the tree, their
#: store and the monitor's part paths (the editors themselves load on first use): the bound keeps a small margin
#: above that, under the issue's 450 kB.
ENTRY_CHUNK_LIMIT = 436_000
#: Everything the browser runs before the first POU opens: the entry chunk and the chunks it imports (472 kB on
#: 2026-11-27 with the declare dialog, breakpoints that follow edits and the task menu; 486 kB after the fifth
#: session's tree menus for types and tasks, history stepping and opened recordings, pointer rows online; 475.1 kB
#: on 2026-11-28 with the tree's dialogs (tree/dialogs.tsx: rename, delete, duplicate, kind, FBD <-> CFC with its
#: conversion) loaded when a menu entry is first chosen; the issue's target is the entry chunk's 450 kB, this bound
#: catches what moves out of it into chunks loaded at once anyway; 480.7 kB with the "More" menu; 488.7 kB on
#: 2026-11-29 with the named global variable lists and part paths).
OPENING_SCRIPTS_LIMIT = 492_000


def test_st_and_fbd_editors_load_on_first_use(page, server: str) -> None:
    store_project(server, PROJECT)
    scripts: list[str] = []
    sizes: dict[str, int] = {}
    page.on("request", lambda request: scripts.append(request.url) if request.resource_type == "script" else None)
    page.on(
        "response",
        lambda response: (
            sizes.__setitem__(response.url, len(response.body()))
            if response.request.resource_type == "script"
            else None
        ),
    )
    page.goto(server)
    open_pou(page, "lazy", "Lad")
    page.get_by_role("tab", name=re.compile("^Lad")).wait_for()
    page.wait_for_load_state("networkidle")
    loaded = " ".join(scripts)
    assert "StEditor" not in loaded and "FbdPouView" not in loaded
    for rare in (
        "diagnostics-",
        "TracePanel",
        "TestsPanel",
        "XrefPanel",
        "BreakpointsPanel",
        "ProjectParts",
        "dialogs-",
    ):
        assert rare not in loaded, f"{rare} is loaded before it is used"
    entry = [size for url, size in sizes.items() if "/assets/index-" in url]
    print(f"entry chunk {entry} bytes, opening scripts {sum(sizes.values())} bytes")
    assert len(entry) == 1 and entry[0] <= ENTRY_CHUNK_LIMIT, entry
    assert sum(sizes.values()) <= OPENING_SCRIPTS_LIMIT, sizes

    tree = page.get_by_role("navigation", name="Project tree")
    tree.get_by_role("button", name=re.compile("^Text")).click()
    page.get_by_label("Text body").wait_for()
    assert any("StEditor" in url for url in scripts)
    assert not any("FbdPouView" in url for url in scripts)

    tree.get_by_role("button", name=re.compile("^Blocks")).click()
    page.get_by_role("button", name="Add network").first.wait_for()
    assert any("FbdPouView" in url for url in scripts)

    # the tree's dialogs come when a menu entry is first chosen, and then work
    tree.get_by_role("button", name="Actions for Lad", exact=True).click()
    page.get_by_role("menu", name="Lad actions").get_by_role("menuitem", name="Rename…").click()
    page.get_by_role("dialog", name="Rename Lad").get_by_role("button", name="Cancel").click()
    assert any("/dialogs-" in url for url in scripts)
