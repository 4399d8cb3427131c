"""What a new user does first in every browser scenario: create a project, add a POU (through the UI)."""

from __future__ import annotations


def new_project(page, server: str, name: str) -> None:
    """Opens the app and creates an empty project ``name``, which opens."""
    page.goto(server)
    page.get_by_role("button", name="New project").click()
    page.get_by_label("Project name").press_sequentially(name)
    page.keyboard.press("Enter")
    page.get_by_role("heading", name=name).wait_for()


def new_pou(page, name: str, *, language: str = "ld", kind: str = "program") -> None:
    """Adds a POU through the "New POU" form (it opens in its editor)."""
    page.get_by_role("button", name="New POU").click()
    page.get_by_label("POU name").press_sequentially(name)
    page.get_by_label("POU kind").select_option(kind)
    page.get_by_label("POU language").select_option(language)
    page.get_by_role("button", name="Create").click()
