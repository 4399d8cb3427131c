"""The sign-in routes of a server others can reach: ``POST /api/login``, ``POST /api/logout`` and the ``/login``
page (docs/security.md). What a session is and how requests are checked: auth.py."""

from __future__ import annotations

import asyncio
import html
import json
import re

from fastapi import APIRouter, Request, Response
from fastapi.responses import HTMLResponse
from pydantic import BaseModel, ConfigDict, Field

from .auth import FAILURES_PER_MINUTE, Auth
from .errors import ApiError

router = APIRouter(tags=["auth"])

FAILURE_DELAY_S = 1.0  # a wrong secret is answered this much later


class Login(BaseModel):
    """Body of ``POST /api/login``: the token or the password."""

    model_config = ConfigDict(extra="forbid")

    secret: str = Field(max_length=1024)


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
