"""What keeps other web sites (and, in remote mode, other people) out: docs/security.md.

``SecurityMiddleware`` runs before every route and the websocket:

* **Host**: only the names the server is served under (127.0.0.1, localhost, [::1] and the
  configured ones) are answered. A page on any site can point its own name at 127.0.0.1 (DNS
  rebinding); its requests then carry its name in ``Host`` and are refused with 403.
* **State-changing requests** (POST, PUT, PATCH, DELETE) must say ``Content-Type:
  application/json`` (the PLCopen import: ``application/xml``) and, when the browser sends an
  ``Origin``, an allowed one. A cross-site page can send JSON only after a CORS preflight, which
  this server never grants; the content types a plain HTML form or a "simple" fetch may send
  (text/plain, form encodings, multipart) are refused, and so is ``Sec-Fetch-Site: cross-site``.
* **Origins** are checked against the allow-list: an origin is allowed when it is configured, or when
  its host is one of the served names and its port is the one the request came to (the app's own
  pages); never because it matches ``Host``, which the page chooses.
* **Authentication** (auth.py) when the server is reachable by others.
* **Response headers**: no framing (``X-Frame-Options: DENY``, CSP ``frame-ancestors 'none'``), no
  content sniffing, no referrer to other sites.
"""

from __future__ import annotations

import ipaddress
import logging
from dataclasses import dataclass
from urllib.parse import urlsplit

from starlette.datastructures import Headers
from starlette.responses import JSONResponse
from starlette.types import ASGIApp, Message, Receive, Scope, Send
from starlette.websockets import WebSocket

from ..model.answers import ErrorDetail
from .auth import Auth
from .limits import media_type

log = logging.getLogger(__name__)

LOOPBACK_HOSTS = frozenset({"127.0.0.1", "localhost", "::1"})
STATE_CHANGING = frozenset({"POST", "PUT", "PATCH", "DELETE"})
#: Routes whose body is not JSON, and the media types they take.
OTHER_BODIES = {"/api/import/plcopen": frozenset({"application/xml", "text/xml"})}
SECURITY_HEADERS = [
    (b"x-frame-options", b"DENY"),
    (b"content-security-policy", b"frame-ancestors 'none'"),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"same-origin"),
]


@dataclass(frozen=True)
class Security:
    """How this server is reached: its names, extra allowed origins, and authentication (None: local only).

    ``hosts`` holds lower-case host names without port; ``"*"`` accepts any (only with authentication)."""

    hosts: frozenset[str] = LOOPBACK_HOSTS
    origins: frozenset[str] = frozenset()
    auth: Auth | None = None

    def host_allowed(self, host_header: str | None) -> bool:
        if "*" in self.hosts:
            return True
        host = split_host(host_header or "")
        return host is not None and host[0] in self.hosts

    def origin_allowed(self, origin: str | None, host_header: str | None) -> bool:
        """Whether a browser page of ``origin`` may act on this server (None: no browser sent it)."""
        if origin is None:
            return True
        origin = origin.strip()
        if origin in self.origins:
            return True
        try:
            parts = urlsplit(origin)
            origin_port = parts.port
        except ValueError:
            return False
        if parts.scheme not in ("http", "https") or not parts.hostname or parts.path or parts.query:
            return False
        if parts.hostname.lower() not in self.hosts:
            return False
        served = split_host(host_header or "")
        default = 443 if parts.scheme == "https" else 80
        return served is not None and (origin_port or default) == (served[1] or default)


def websocket_origin_allowed(websocket: WebSocket) -> bool:
    """The upgrade's ``Origin`` against the app's allow-list (the monitor asks before accepting)."""
    security: Security = websocket.app.state.security
    return security.origin_allowed(websocket.headers.get("origin"), websocket.headers.get("host"))


def split_host(value: str) -> tuple[str, int | None] | None:
    """``Host`` header -> (lower-case name without brackets, port or None); None when malformed."""
    value = value.strip().lower()
    if not value:
        return None
    if value.startswith("["):
        name, _, rest = value[1:].partition("]")
        try:
            ipaddress.IPv6Address(name)
        except ValueError:
            return None
        port_text = rest[1:] if rest.startswith(":") else ("" if not rest else None)
    else:
        name, _, port_text = value.partition(":")
    if port_text is None or (port_text and not port_text.isdigit()) or not name:
        return None
    return name, int(port_text) if port_text else None


class SecurityMiddleware:
    """ASGI middleware applying ``Security`` to every HTTP request and websocket upgrade."""

    def __init__(self, app: ASGIApp, security: Security) -> None:
        self.app = app
        self.security = security

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] not in ("http", "websocket"):
            await self.app(scope, receive, send)
            return
        headers = Headers(scope=scope)
        refusal = self.refusal(scope, headers)
        if refusal is not None:
            status, message = refusal
            if scope["type"] == "websocket":
                await send({"type": "websocket.close", "code": 1008, "reason": message[:120]})  # before accept: 403
            else:
                await self._send_json(scope, receive, send, status, message)
            return
        auth = self.security.auth
        if auth is not None and await auth.gate(scope, receive, self._with_headers(send), headers):
            return
        await self.app(scope, receive, self._with_headers(send))

    def refusal(self, scope: Scope, headers: Headers) -> tuple[int, str] | None:
        """(status, message) when the request must not reach the app, else None."""
        security = self.security
        host = headers.get("host")
        if not security.host_allowed(host):
            return 403, (
                f"this server is not served under the name {host!r}; add it with --allowed-host "
                "if that is intended (a page of another site may have pointed its name here)"
            )
        origin = headers.get("origin")
        if scope["type"] == "websocket":
            if not security.origin_allowed(origin, host):
                return 403, "origin not allowed"
            return None
        if scope["method"] not in STATE_CHANGING:
            return None
        if not security.origin_allowed(origin, host) or headers.get("sec-fetch-site") == "cross-site":
            return 403, f"requests from {origin or 'another site'} may not change anything here"
        allowed = OTHER_BODIES.get(scope["path"], frozenset()) | {"application/json"}
        if media_type(headers) not in allowed:
            kinds = " or ".join(sorted(allowed))
            return 403, f"a {scope['method']} request must be sent as {kinds} (Content-Type)"
        return None

    def _with_headers(self, send: Send) -> Send:
        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message = {**message, "headers": [*message.get("headers", []), *SECURITY_HEADERS]}
            await send(message)

        return send_with_headers

    async def _send_json(self, scope: Scope, receive: Receive, send: Send, status: int, message: str) -> None:
        response = JSONResponse({"detail": ErrorDetail(message=message).model_dump(mode="json")}, status)
        await response(scope, receive, self._with_headers(send))
