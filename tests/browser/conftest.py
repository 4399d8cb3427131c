"""A real ``ladderlab serve`` on a free port with a temporary workspace, and the system Chromium.

Browser tests drive Debian's ``chromium`` through Playwright's ``executable_path`` (never a
downloaded browser). They are skipped, with the reason, when chromium or Playwright is missing
or the browser app has not been built (``make test`` builds it first).
"""

from __future__ import annotations

import re
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

from ladderlab.server import STATIC_DIR
from tests.live_server import LiveServer

ARTIFACTS = Path(__file__).parent / "artifacts"


@pytest.fixture(scope="session")
def chromium_path() -> str:
    path = shutil.which("chromium") or shutil.which("chromium-browser")
    if path is None:
        pytest.skip("Debian's chromium is not installed (make test installs it)")
    pytest.importorskip("playwright.sync_api", reason="playwright is not installed")
    if not (STATIC_DIR / "index.html").is_file():
        pytest.skip("the browser app is not built (make frontend)")
    return path


@pytest.fixture
def server(tmp_path: Path, chromium_path: str) -> Iterator[str]:
    """Base URL of a fresh server whose workspace is empty."""
    live = LiveServer(tmp_path / "workspace", tmp_path / "server.log")
    try:
        yield live.start().url
    finally:
        live.stop()


class BrowserErrors:
    """Page errors (uncaught exceptions) and console errors of one test's page; the test fails on any,
    except those it expects by calling ``allow`` (e.g. the error a test provokes on purpose)."""

    def __init__(self) -> None:
        self.seen: list[str] = []
        self.allowed: list[re.Pattern[str]] = []

    def allow(self, pattern: str) -> None:
        self.allowed.append(re.compile(pattern, re.S))

    def record(self, text: str) -> None:
        self.seen.append(text)

    def unexpected(self) -> list[str]:
        return [text for text in self.seen if not any(p.search(text) for p in self.allowed)]


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item, call):
    """Keeps each phase's report on the test item, so the page fixture knows whether the test failed."""
    report = yield
    setattr(item, f"report_{report.when}", report)
    return report


@pytest.fixture
def browser_errors() -> BrowserErrors:
    return BrowserErrors()


@pytest.fixture
def page(server: str, chromium_path: str, browser_errors: BrowserErrors, request: pytest.FixtureRequest):
    from playwright.sync_api import sync_playwright

    ARTIFACTS.mkdir(exist_ok=True)
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=chromium_path, args=["--no-sandbox"])
        context = browser.new_context(viewport={"width": 1400, "height": 900})
        page = context.new_page()
        # Generous: the simulation runs in its own process and the shared 2-core machine is often busy.
        page.set_default_timeout(20_000)
        page.on("pageerror", lambda error: browser_errors.record(f"page error: {error}"))
        page.on(
            "console",
            lambda message: (
                browser_errors.record(f"console error: {message.text} ({message.location.get('url')})")
                if message.type == "error"
                else None
            ),
        )
        try:
            yield page
        finally:
            failed = getattr(request.node, "report_call", None)
            if failed is not None and failed.failed:  # what the page showed when the test failed
                page.screenshot(path=str(ARTIFACTS / f"{request.node.name}-failed.png"))
            context.close()
            browser.close()
        unexpected = browser_errors.unexpected()
        assert not unexpected, "the page reported errors:\n" + "\n".join(unexpected)
