"""Authentication of a server others can reach (``ladderlab serve --allow-remote``): docs/security.md.

The secret is a token printed at start (as Jupyter does; ``LADDERLAB_TOKEN`` fixes it) or the
first line of a password file (``--password-file``). A browser proves it once, by opening the
printed ``/?token=...`` link or on the ``/login`` page, and then carries a session cookie
(HttpOnly, SameSite=Strict, Secure behind a TLS proxy: ``--secure-cookies``); scripts may send
``Authorization: Bearer <secret>`` instead. Sessions live in this process only: a restart signs
everyone out. Failed attempts wait a second and are counted per client, so a password cannot be
guessed quickly.
"""

from __future__ import annotations

import hmac
import secrets
import threading
import time
from collections import deque
from typing import Literal
from urllib.parse import parse_qsl, urlencode

from fastapi import Response
from starlette.datastructures import Headers
from starlette.responses import JSONResponse, RedirectResponse
from starlette.types import Receive, Scope, Send

from ..model.answers import ErrorDetail

#: Reachable without a session: the health check (container probes), the login page and its API.
PUBLIC_PATHS = frozenset({"/api/health", "/login", "/api/login"})
SESSION_S = 12 * 3600.0  # a session ends after this long without a request
MAX_SESSIONS = 1_000
FAILURES_PER_MINUTE = 10


class Auth:
    """The secret of this server and its signed-in browsers."""

    def __init__(self, secret: str, kind: Literal["token", "password"], secure_cookies: bool = False) -> None:
        if not secret:
            raise ValueError("the secret may not be empty")
        self.secret = secret
        self.kind = kind
        self.secure_cookies = secure_cookies
        self._sessions: dict[str, float] = {}  # session id -> monotonic time it expires
        self._failures: dict[str, deque[float]] = {}
        self._lock = threading.Lock()

    @classmethod
    def new_token(cls, secure_cookies: bool = False) -> Auth:
        return cls(secrets.token_urlsafe(24), "token", secure_cookies)

    def accepts(self, secret: str | None) -> bool:
        return secret is not None and hmac.compare_digest(secret.encode(), self.secret.encode())

    # ------------------------------------------------------------------ sessions

    def open_session(self) -> str:
        session = secrets.token_urlsafe(32)
        now = time.monotonic()
        with self._lock:
            self._sessions = {s: end for s, end in self._sessions.items() if end > now}
            while len(self._sessions) >= MAX_SESSIONS:
                self._sessions.pop(next(iter(self._sessions)))
            self._sessions[session] = now + SESSION_S
        return session

    def session_valid(self, session: str | None) -> bool:
        if not session:
            return False
        now = time.monotonic()
        with self._lock:
            end = self._sessions.get(session)
            if end is None or end <= now:
                self._sessions.pop(session, None)
                return False
            self._sessions[session] = now + SESSION_S
            return True

    def close_session(self, session: str | None) -> None:
        with self._lock:
            self._sessions.pop(session or "", None)

    def too_many_failures(self, client: str) -> bool:
        now = time.monotonic()
        with self._lock:
            recent = self._failures.setdefault(client, deque())
            while recent and recent[0] < now - 60:
                recent.popleft()
            return len(recent) >= FAILURES_PER_MINUTE

    def failed(self, client: str) -> None:
        with self._lock:
            self._failures.setdefault(client, deque()).append(time.monotonic())

    # ------------------------------------------------------------------ cookies

    @staticmethod
    def cookie_name(headers: Headers) -> str:
        """Per port: two servers on one host must not overwrite each other's session."""
        port = headers.get("host", "").rpartition(":")[2]
        return f"ladderlab_session_{port}" if port.isdigit() else "ladderlab_session"

    def set_cookie(self, response: Response, headers: Headers, session: str) -> None:
        response.set_cookie(
            self.cookie_name(headers),
            session,
            httponly=True,
            samesite="strict",
            secure=self.secure_cookies,
            path="/",
        )

    # ------------------------------------------------------------------ the gate (SecurityMiddleware)

    async def gate(self, scope: Scope, receive: Receive, send: Send, headers: Headers) -> bool:
        """Let a signed-in request through (False) or answer it here (True): 401, the login page, or
        the redirect that turns a ``?token=`` link into a session."""
        path = scope["path"]
        if path in PUBLIC_PATHS:
            return False
        bearer = headers.get("authorization", "")
        if bearer.lower().startswith("bearer ") and self.accepts(bearer[7:].strip()):
            return False
        cookies = _cookies(headers)
        if self.session_valid(cookies.get(self.cookie_name(headers))):
            return False
        query = dict(parse_qsl(scope.get("query_string", b"").decode("latin-1")))
        if scope["type"] == "http" and scope["method"] == "GET" and self.accepts(query.get("token")):
            rest = urlencode([(k, v) for k, v in parse_qsl(scope["query_string"].decode("latin-1")) if k != "token"])
            response = RedirectResponse(path + (f"?{rest}" if rest else ""), status_code=303)
            self.set_cookie(response, headers, self.open_session())
            await response(scope, receive, send)
            return True
        if scope["type"] == "websocket":
            await send({"type": "websocket.close", "code": 1008, "reason": "sign in first"})
            return True
        if path.startswith("/api/"):
            detail = ErrorDetail(message="sign in first: this server needs its token or password (see /login)")
            await JSONResponse({"detail": detail.model_dump(mode="json")}, 401)(scope, receive, send)
            return True
        await RedirectResponse(f"/login?{urlencode({'next': path})}", status_code=303)(scope, receive, send)
        return True


def _cookies(headers: Headers) -> dict[str, str]:
    found = {}
    for part in headers.get("cookie", "").split(";"):
        name, _, value = part.strip().partition("=")
        if name:
            found[name] = value
    return found
