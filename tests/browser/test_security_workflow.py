"""Issue 18 in the browser: signing in to a remote server, and a broken project in the list.

A real ``ladderlab serve`` (remote mode with a password file, or with the printed token link) and the
system Chromium. The app must work as before once signed in: create a project, compile it and go
online (the websocket carries the session cookie). Fails on any page error or console error.
"""

from __future__ import annotations

import re
from pathlib import Path
from urllib.parse import urlsplit

import pytest

from tests.live_server import LiveServer

from .conftest import ARTIFACTS
from .steps import save_and_run

pytestmark = pytest.mark.browser


class Errors:
    """Page errors, console errors and failed responses; ``unexpected`` leaves out the failures expected."""

    def __init__(self, page) -> None:
        self.page_errors: Errors = []
        self.console: list[str] = []
        self.failed: list[tuple[int, str]] = []
        page.on("pageerror", lambda error: self.page_errors.append(str(error)))
        page.on("console", lambda message: self.console.append(message.text) if message.type == "error" else None)
        page.on("response", lambda r: self.failed.append((r.status, urlsplit(r.url).path)) if r.status >= 400 else None)

    def unexpected(self, *expected: tuple[int, str]) -> list[str]:
        """Anything but a console line for each expected failed response (the browser logs those itself)."""
        loads = [m for m in self.console if m.startswith("Failed to load resource: the server responded")]
        others = [m for m in self.console if m not in loads]
        failures = [f"{status} {path}" for status, path in self.failed if (status, path) not in expected]
        return self.page_errors + others + failures + ([] if len(loads) == len(self.failed) else loads)


@pytest.fixture
def errors(page) -> Errors:
    return Errors(page)


def remote(tmp_path: Path, *args: str) -> LiveServer:
    return LiveServer(tmp_path / "remote-ws", tmp_path / "remote.log", *args).start()


def test_sign_in_with_a_password_then_work_online(page, errors: Errors, browser_errors, tmp_path: Path) -> None:
    browser_errors.allow(r"401 \(Unauthorized\) \(http://127\.0\.0\.1:\d+/api/login\)")  # the wrong password
    secret = tmp_path / "password"
    secret.write_text("correct horse battery\n")
    server = remote(tmp_path, "--allow-remote", "--password-file", str(secret))
    try:
        page.goto(server.url)
        page.wait_for_url(re.compile(r"/login\?next=%2F$"))
        page.get_by_label("Enter the password").fill("tr0ub4dor")
        page.get_by_role("button", name="Sign in").click()
        page.get_by_role("alert").filter(has_text="wrong password").wait_for()
        page.get_by_label("Enter the password").fill("correct horse battery")
        page.get_by_role("button", name="Sign in").click()
        page.wait_for_url(f"{server.url}/")
        page.get_by_role("button", name=re.compile("^motor")).wait_for()

        # the app as before: a new project, saved, compiled and online over the websocket
        page.get_by_role("button", name="New project").click()
        page.get_by_label("Project name").press_sequentially("lab")
        page.keyboard.press("Enter")
        page.get_by_role("heading", name="lab").wait_for()
        page.get_by_role("button", name="New POU").click()
        page.get_by_label("POU name").press_sequentially("Main")
        page.get_by_label("POU language").select_option("st")
        page.get_by_role("button", name="Create").click()
        for label, text in (("Main declarations", "VAR\n    n : INT;\nEND_VAR"), ("Main body", "n := n + 1;")):
            page.get_by_label(label).click()
            page.keyboard.press("Control+a")
            page.keyboard.insert_text(text)
        save_and_run(page)
        n_value = """() => Number(document.querySelectorAll('[aria-label="Main body"] .cm-st-value')[0]?.textContent)"""
        page.wait_for_function(f"() => ({n_value})() > 5")  # values arrive over the websocket
        page.screenshot(path=str(ARTIFACTS / "remote-online.png"))
    finally:
        page.goto("about:blank")  # the app polls its server: leave it before the server stops
        server.stop()
    # expected: the wrong password, and the symbols of the new POU before its first save (as in local mode)
    assert errors.unexpected((401, "/api/login"), (404, "/api/projects/lab/pous/Main/symbols")) == []


def test_the_printed_token_link_opens_the_app(page, errors: Errors, tmp_path: Path) -> None:
    server = remote(tmp_path, "--allow-remote")
    try:
        link = re.search(r"LadderLab on (\S+\?token=\S+)", server.log()).group(1)
        page.goto(link)
        page.wait_for_url(f"{server.url}/")  # the token leaves the address bar
        page.get_by_role("button", name=re.compile("^motor")).wait_for()
    finally:
        page.goto("about:blank")  # the app polls its server: leave it before the server stops
        server.stop()
    assert errors.unexpected() == []


def test_a_project_that_does_not_load_is_listed_with_its_problem(
    page, errors: Errors, server: str, tmp_path: Path
) -> None:
    page.goto(server)
    page.get_by_role("button", name=re.compile("^motor")).wait_for()
    folder = tmp_path / "workspace" / "motor"  # the server fixture's workspace (conftest.py)
    (folder / "pous" / "Main.ld.json").write_text('{\n  "name": "Main",\n  "kind": \n}\n')
    page.reload()
    row = page.get_by_role("button", name=re.compile("^motor"))
    row.get_by_text("cannot be loaded: pous/Main.ld.json:4:1: invalid JSON: Expecting value").wait_for()
    page.screenshot(path=str(ARTIFACTS / "broken-project-listed.png"))
    assert errors.unexpected() == []
