"""A real ``ladderlab serve`` process on a free port, for tests that need one (browser, crash, limits)."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LiveServer:
    """``ladderlab serve`` over ``workspace``; ``url`` is its base URL once ``start`` returned."""

    def __init__(self, workspace: Path, log: Path, *extra: str, env: dict[str, str] | None = None, preexec=None):
        self.workspace, self.log_path, self.extra, self.env, self.preexec = workspace, log, extra, env, preexec
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.process: subprocess.Popen | None = None

    def start(self, timeout_s: float = 20) -> LiveServer:
        log = self.log_path.open("a")
        command = ["serve", "--port", str(self.port), "--workspace", str(self.workspace), *self.extra]
        self.process = subprocess.Popen(
            [sys.executable, "-c", "import sys; from ladderlab.cli import main; sys.exit(main())", *command],
            stdout=log,
            stderr=subprocess.STDOUT,
            env={**os.environ, **(self.env or {})},
            preexec_fn=self.preexec,
        )
        log.close()
        self._wait_healthy(timeout_s)
        return self

    def _wait_healthy(self, timeout_s: float) -> None:
        deadline = time.monotonic() + timeout_s
        assert self.process is not None
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"ladderlab serve exited with {self.process.returncode}: {self.log()}")
            try:
                with urllib.request.urlopen(f"{self.url}/api/health", timeout=1) as response:
                    if response.status == 200:
                        return
            except OSError:
                time.sleep(0.05)
        raise RuntimeError(f"ladderlab serve did not answer at {self.url} within {timeout_s} s")

    def log(self) -> str:
        return self.log_path.read_text(errors="replace") if self.log_path.exists() else ""

    def kill(self) -> None:
        """SIGKILL: no handler, no cleanup runs (a crash or a power cut, as far as the files can tell)."""
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL)
            self.process.wait(10)

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)
