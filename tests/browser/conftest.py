"""A real ``ladderlab serve`` on a free port with a temporary workspace, and the system Chromium.

Browser tests drive Debian's ``chromium`` through Playwright's ``executable_path`` (never a
downloaded browser). They are skipped, with the reason, when chromium or Playwright is missing
or the browser app has not been built (``make test`` builds it first).
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

from ladderlab.server.app import STATIC_DIR
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


@pytest.fixture
def page(server: str, chromium_path: str):
    from playwright.sync_api import sync_playwright

    ARTIFACTS.mkdir(exist_ok=True)
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=chromium_path, args=["--no-sandbox"])
        context = browser.new_context(viewport={"width": 1400, "height": 900})
        page = context.new_page()
        page.set_default_timeout(10_000)
        try:
            yield page
        finally:
            context.close()
            browser.close()
