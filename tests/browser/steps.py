"""What the browser scenarios do first: create a project and add a POU through the UI, or store a whole
project through the REST API."""

from __future__ import annotations

import json
import re
import time
import urllib.request


def new_project(page, server: str, name: str) -> None:
    """Opens the app and creates an empty project ``name``, which opens."""
    page.goto(server)
    page.get_by_role("button", name="New project").click()
    page.get_by_label("Project name").press_sequentially(name)
    page.keyboard.press("Enter")
    page.get_by_role("heading", name=name, exact=True).wait_for()


def new_pou(page, name: str, *, language: str = "ld", kind: str = "program") -> None:
    """Adds a POU through the "New POU" form (it opens in its editor)."""
    page.get_by_role("button", name="New POU").click()
    page.get_by_label("POU name").press_sequentially(name)
    page.get_by_label("POU kind").select_option(kind)
    page.get_by_label("POU language").select_option(language)
    page.get_by_role("button", name="Create").click()


def save_and_run(page):
    """Ctrl+S, then Compile & simulate and Run (the server compiles the saved project); returns the online state."""
    page.keyboard.press("Control+s")
    page.get_by_text("All changes saved").wait_for()
    page.get_by_role("button", name="Compile & simulate").click()
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    page.get_by_role("button", name="Run", exact=True).click()
    state.filter(has_text="Online · running").wait_for()
    return state


def store_project(server: str, project: dict) -> None:
    """Creates project ``project["name"]`` through the REST API and saves ``project`` (a whole model) into it."""
    name = project["name"]
    _request("POST", f"{server}/api/projects", {"name": name})
    revision = _request("GET", f"{server}/api/projects/{name}")["revision"]
    _request("PUT", f"{server}/api/projects/{name}", project, revision)


def _request(method: str, url: str, body: dict | None = None, revision: str | None = None) -> dict:
    headers = {"Content-Type": "application/json"}
    if revision is not None:
        headers["If-Match"] = f'"{revision}"'
    data = json.dumps(body).encode() if body is not None else None
    with urllib.request.urlopen(
        urllib.request.Request(url, data=data, method=method, headers=headers), timeout=30
    ) as response:
        return json.load(response)


def open_pou(page, project: str, pou: str) -> None:
    """Opens ``project`` from the project list and ``pou`` from its tree."""
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile(f"^{project}")).click()
    page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile(f"^{pou}")).click()


def go_online(page, *, run: bool = True) -> None:
    """Compile & simulate (saving unsaved changes when it asks), then Run (unless ``run`` is False): waits for
    the state the toolbar shows."""
    state = page.get_by_role("status", name="Online state")
    page.get_by_role("button", name="Compile & simulate").click()
    question = page.get_by_role("alertdialog", name="Unsaved changes")
    state.filter(has_text="Online · stopped").or_(question).wait_for()
    if question.is_visible():  # unsaved changes: save them, then compile
        question.get_by_role("button", name="Save and compile").click()
        state.filter(has_text="Online · stopped").wait_for()
    if run:
        page.get_by_role("button", name="Run", exact=True).click()
        state.filter(has_text="Online · running").wait_for()


def export_menu(page):
    """Opens the workspace bar's Export menu; returns its group of entries (exports and print)."""
    page.locator(".workspace-bar details.menu > summary").click()
    return page.get_by_role("group", name="Export")


def panel_tab(page, name: str):
    """Shows the bottom panel whose tab starts with ``name`` ("Watch list", "Online log") and returns the panels."""
    panels = page.get_by_role("region", name="Panels")
    tab = panels.get_by_role("tab", name=re.compile(f"^{re.escape(name)}"))
    more = panels.get_by_role("button", name="More panels")
    tab.or_(more).first.wait_for()  # the row is measured after the page renders: wait for either, not a guess
    if tab.count() == 0:  # a narrow window: the tabs that do not fit are in the row's More menu
        more.click()
        page.get_by_role("menuitem", name=re.compile(f"^{re.escape(name)}")).click()
    else:
        tab.click()
    return panels


def watch(page, path: str):
    """Adds ``path`` to the watch list; returns its value cell."""
    panels = panel_tab(page, "Watch list")
    panels.get_by_label("Variable path to watch").fill(path)
    panels.get_by_label("Variable path to watch").press("Enter")
    return panels.locator(f'tr[data-path="{path.upper()}"] td.watch-value')


def scan_count(page) -> int:
    """The scan counter of the simulation toolbar."""
    return int(page.get_by_test_id("scan-count").inner_text())


def settled_scan_count(page) -> int:
    """The counter once the last values sent before a stop have arrived (it stops changing)."""
    previous = scan_count(page)
    while True:
        time.sleep(0.25)
        current = scan_count(page)
        if current == previous:
            return current
        previous = current


def open_print(page):
    """Opens the project's print view (Export menu) in its own page; returns it and the list of the errors it reports
    (page errors, console errors), for the test to assert empty."""
    with page.context.expect_page() as opened:
        export_menu(page).get_by_role("button", name="Print project…").click()
    printed = opened.value
    errors: list[str] = []
    printed.on("pageerror", lambda error: errors.append(f"page error: {error}"))
    printed.on("console", lambda message: errors.append(message.text) if message.type == "error" else None)
    return printed, errors


def double_click_online(element) -> None:
    """Double-clicks an LD element online (CODESYS: a BOOL's value toggles into the prepared one) once the diagram
    shows the element's value, as a user would: until the POU's symbol table has come (slow while the server
    compiles under load) the diagram is not bound to the simulation and a double-click prepares nothing."""
    element.locator(".ld-badge").first.wait_for()
    element.locator(".ld-hit").dblclick()
