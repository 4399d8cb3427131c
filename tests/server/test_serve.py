"""``ladderlab serve`` as started from the shell: sign-in in remote mode, its options, connection floods.

Real processes on free ports (tests/live_server.py): what is printed at start is what a user sees.
"""

from __future__ import annotations

import contextlib
import re
import resource
import subprocess
import sys
import time
from pathlib import Path

import httpx
import pytest
from websockets.exceptions import InvalidStatus
from websockets.sync.client import connect

from tests.live_server import LiveServer

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX process limits")


def serve(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "ladderlab.cli", "serve", *args],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
    )


def test_remote_mode_prints_a_token_link_and_needs_it(tmp_path: Path) -> None:
    server = LiveServer(tmp_path / "ws", tmp_path / "server.log", "--allow-remote").start()
    try:
        printed = re.search(r"LadderLab on (http://127\.0\.0\.1:\d+/)\?token=([\w-]{20,}) ", server.log())
        assert printed is not None, server.log()
        url, token = printed.groups()
        assert "Open that link to sign in" in server.log()
        with httpx.Client(base_url=server.url) as http:
            assert http.get("/api/projects").status_code == 401
            signed = http.get(f"/?token={token}", follow_redirects=False)
            assert signed.status_code == 303
            assert http.get("/api/projects").status_code == 200, "the session cookie came with the redirect"
    finally:
        server.stop()


def test_a_fixed_token_comes_from_the_environment(tmp_path: Path) -> None:
    env = {"LADDERLAB_TOKEN": "team-token-of-our-lab"}
    server = LiveServer(tmp_path / "ws", tmp_path / "server.log", "--allow-remote", env=env).start()
    try:
        assert "?token=team-token-of-our-lab" in server.log()
        headers = {"Authorization": "Bearer team-token-of-our-lab"}
        assert httpx.get(f"{server.url}/api/projects", headers=headers).status_code == 200
    finally:
        server.stop()


def test_a_password_file_replaces_the_token(tmp_path: Path) -> None:
    secret = tmp_path / "password"
    secret.write_text("correct horse battery\n")
    server = LiveServer(tmp_path / "ws", tmp_path / "server.log", "--password-file", str(secret)).start()
    try:
        assert "token=" not in server.log()
        with httpx.Client(base_url=server.url, headers={"Origin": server.url}) as http:
            assert http.get("/api/projects").status_code == 401
            assert http.post("/api/login", json={"secret": "correct horse battery"}).status_code == 204
            assert http.get("/api/projects").status_code == 200
    finally:
        server.stop()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--password-file", "/nonexistent/password"], "cannot read a password from /nonexistent/password"),
        (["--allowed-host", "*"], "--allowed-host '*' needs --allow-remote or --password-file"),
        (["--host", "0.0.0.0"], "pass --allow-remote to serve other machines"),
        (["--history-mb", "-1"], "argument --history-mb: '-1' is not a whole number >= 0"),
    ],
)
def test_serve_refuses_unsafe_or_broken_options(tmp_path: Path, args: list[str], message: str) -> None:
    result = serve("--port", "1", "--workspace", str(tmp_path / "ws"), *args)
    assert result.returncode == 2
    assert message in result.stderr
    assert "Traceback" not in result.stderr


def test_history_mb_is_each_simulations_history_budget(tmp_path: Path) -> None:
    """Issue 23 item 1 ("default 256 MB, configurable"): ``--history-mb 3`` gives a simulation 3 MiB of history."""
    server = LiveServer(tmp_path / "ws", tmp_path / "server.log", "--history-mb", "3").start()
    try:
        with httpx.Client(base_url=server.url, timeout=30) as http:
            created = http.post("/api/projects/motor/simulations", json={})  # the example the server seeds
            assert created.status_code == 201, created.text
            simulation = created.json()["id"]
            info = http.post(f"/api/simulations/{simulation}/cycle", json={}).json()
            assert info["history"]["budget_bytes"] == 3 * 1024 * 1024
            http.delete(f"/api/simulations/{simulation}")
    finally:
        server.stop()


def test_a_short_password_is_refused(tmp_path: Path) -> None:
    secret = tmp_path / "password"
    secret.write_text("1234\n")
    result = serve("--port", "1", "--workspace", str(tmp_path / "ws"), "--password-file", str(secret))
    assert result.returncode == 2
    assert f"the password in {secret} is shorter than 8 characters" in result.stderr


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_NOFILE as on Linux")
def test_a_websocket_flood_is_refused_before_descriptors_run_out_and_logged_once(tmp_path: Path) -> None:
    """Issue 18: ~1,200 connections exhausted the file descriptors and logged 514,000 tracebacks in 41 s.
    With 200 descriptors the server allows 100 websockets; 300 attempts leave it answering."""

    def few_descriptors() -> None:
        resource.setrlimit(resource.RLIMIT_NOFILE, (200, 200))

    server = LiveServer(tmp_path / "ws", tmp_path / "server.log", preexec=few_descriptors).start()
    try:
        with httpx.Client(base_url=server.url, headers={"Content-Type": "application/json"}) as http:
            assert http.post("/api/projects", json={"name": "p", "example": "motor"}).status_code == 201
            sim = http.post("/api/projects/p/simulations").json()["id"]
        url = f"ws://127.0.0.1:{server.port}/api/simulations/{sim}/ws"
        with contextlib.ExitStack() as sockets:
            opened = refused = 0
            for _ in range(300):
                try:
                    sockets.enter_context(connect(url, open_timeout=5))
                    opened += 1
                except (InvalidStatus, OSError):
                    refused += 1
            assert (opened, refused) == (100, 200)
            assert httpx.get(f"{server.url}/api/health", timeout=5).status_code == 200
        time.sleep(0.5)
        with connect(url, open_timeout=5) as again:
            assert '"status"' in again.recv(timeout=5)
    finally:
        server.stop()
    log = server.log()
    assert "Traceback" not in log
    assert log.count("websocket connections are open, the most allowed: refusing more") == 1
    assert log.count("websocket connections below the limit again; 200 were refused") == 1
    assert len([line for line in log.splitlines() if "WARNING" in line or "ERROR" in line]) <= 3
