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

import asyncio
import hmac
import html
import json
import re
import secrets
import threading
import time
from collections import deque
from typing import Literal
from urllib.parse import parse_qsl, urlencode

from fastapi import APIRouter, Request, Response
from fastapi.responses import HTMLResponse
from pydantic import BaseModel, ConfigDict, Field
from starlette.datastructures import Headers
from starlette.responses import JSONResponse, RedirectResponse
from starlette.types import Receive, Scope, Send

from ..model.api import ErrorDetail
from .errors import ApiError

router = APIRouter(tags=["auth"])

#: Reachable without a session: the health check (container probes), the login page and its API.
PUBLIC_PATHS = frozenset({"/api/health", "/login", "/api/login"})
SESSION_S = 12 * 3600.0  # a session ends after this long without a request
MAX_SESSIONS = 1_000
FAILURES_PER_MINUTE = 10
FAILURE_DELAY_S = 1.0


class Login(BaseModel):
    """Body of ``POST /api/login``: the token or the password."""

    model_config = ConfigDict(extra="forbid")

    secret: str = Field(max_length=1024)


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


def _auth(request: Request) -> Auth:
    auth: Auth | None = request.app.state.security.auth
    if auth is None:
        raise ApiError(404, "this server does not ask anyone to sign in")
    return auth


@router.post("/api/login", status_code=204, response_class=Response)
async def login(body: Login, request: Request) -> Response:
    """Exchange the token or password for a session cookie."""
    auth = _auth(request)
    client = request.client.host if request.client else "?"
    if auth.too_many_failures(client):
        raise ApiError(429, f"more than {FAILURES_PER_MINUTE} wrong attempts in a minute: wait a minute")
    if not auth.accepts(body.secret):
        auth.failed(client)
        await asyncio.sleep(FAILURE_DELAY_S)
        raise ApiError(401, f"wrong {auth.kind}")
    response = Response(status_code=204)
    auth.set_cookie(response, request.headers, auth.open_session())
    return response


@router.post("/api/logout", status_code=204, response_class=Response)
def logout(request: Request) -> Response:
    auth = _auth(request)
    name = auth.cookie_name(request.headers)
    auth.close_session(request.cookies.get(name))
    response = Response(status_code=204)
    response.delete_cookie(name, path="/")
    return response


@router.get("/login", response_class=HTMLResponse, include_in_schema=False)
def login_page(request: Request, next: str = "/") -> str:
    auth = _auth(request)
    target = next if _LOCAL_PATH.fullmatch(next) else "/"  # never another site, never markup
    what = "the token printed when the server started" if auth.kind == "token" else "the password"
    return _LOGIN_PAGE.format(what=html.escape(what), kind=auth.kind, next=json.dumps(target))


_LOCAL_PATH = re.compile(r"/(?!/)[A-Za-z0-9/_.~-]*")


_LOGIN_PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>LadderLab: sign in</title>
<style>body{{font:15px system-ui,sans-serif;margin:15vh auto;max-width:26rem}}input{{width:100%;font:inherit;
padding:.4rem;margin:.5rem 0}}button{{font:inherit;padding:.4rem 1rem}}#error{{color:#b00020}}</style></head>
<body><h1>LadderLab</h1><form id="login"><label for="secret">Enter {what}:</label>
<input id="secret" name="secret" type="password" autocomplete="current-password" autofocus required>
<button type="submit">Sign in</button><p id="error" role="alert"></p></form>
<script>
document.getElementById("login").addEventListener("submit", async (event) => {{
  event.preventDefault();
  const secret = document.getElementById("secret").value;
  const response = await fetch("/api/login", {{method: "POST", headers: {{"Content-Type": "application/json"}},
    body: JSON.stringify({{secret}})}});
  if (response.ok) {{ window.location.assign({next}); return; }}
  let message = "wrong {kind}";
  try {{ message = (await response.json()).detail.message; }} catch {{}}
  document.getElementById("error").textContent = message;
}});
</script></body></html>
"""
