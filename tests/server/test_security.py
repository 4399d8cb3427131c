"""Web security (issue 18 item 1): Host names, cross-site requests, origins, framing, sign-in.

Each attack of the issue is replayed as a browser (or ``curl``) would send it: a DNS-rebound page
(its own name in ``Host``), a cross-site form or simple fetch (text/plain, no body), a foreign
``Origin``. Expected statuses come from the rules in docs/security.md.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

from ladderlab.server.app import create_app
from ladderlab.server.auth import Auth
from ladderlab.server.security import Security
from ladderlab.storage import Workspace
from tests.support import api_client

from .helpers import detail


@pytest.fixture
def raw(workspace: Workspace) -> TestClient:
    """A client that adds no header of its own: every request says exactly what the test gives."""
    return TestClient(create_app(workspace), base_url="http://localhost:8000")


def projects(workspace: Workspace) -> list[str]:
    return [info.name for info in workspace.list()]


# ----------------------------------------------------------------- Host (DNS rebinding)


@pytest.mark.parametrize("host", ["evil.example:8000", "evil.example", "127.0.0.1.evil.example", "localhost.:8000", ""])
def test_a_rebound_name_gets_nothing(raw: TestClient, workspace: Workspace, motor: str, host: str) -> None:
    """curl -H 'Host: evil.example:8000' 127.0.0.1:8000/api/projects, then DELETE (the issue's attack)."""
    listed = raw.get("/api/projects", headers={"Host": host})
    assert listed.status_code == 403
    assert "is not served under the name" in detail(listed)["message"]
    deleted = raw.delete("/api/projects/motor", headers={"Host": host, "Content-Type": "application/json"})
    assert deleted.status_code == 403
    assert projects(workspace) == ["motor"]
    assert raw.get("/", headers={"Host": host}).status_code == 403


@pytest.mark.parametrize("host", ["localhost:8000", "127.0.0.1:8000", "[::1]:8000", "LOCALHOST", "127.0.0.1"])
def test_the_served_names_are_answered(raw: TestClient, motor: str, host: str) -> None:
    assert raw.get("/api/projects", headers={"Host": host}).status_code == 200


def test_configured_names_are_answered(workspace: Workspace) -> None:
    client = TestClient(create_app(workspace, security=Security(hosts=frozenset({"plc.example.com"}))))
    assert client.get("/api/health", headers={"Host": "plc.example.com"}).status_code == 200
    assert client.get("/api/health", headers={"Host": "localhost:8000"}).status_code == 403


def test_a_rebound_websocket_is_refused(client: TestClient, motor: str) -> None:
    with pytest.raises(WebSocketDisconnect) as refused:
        with client.websocket_connect("/api/simulations/x/ws", headers={"Host": "evil.example:8000"}):
            pass
    assert refused.value.code == 1008


# ----------------------------------------------------------------- cross-site requests


def test_a_cross_site_text_plain_import_creates_nothing(raw: TestClient, workspace: Workspace, motor: str) -> None:
    """A form or simple fetch from another site can send text/plain without a preflight (the issue: 201)."""
    xml = raw.get("/api/projects/motor/export/plcopen").content
    for headers in (
        {"Content-Type": "text/plain", "Origin": "http://evil.example"},
        {"Content-Type": "text/plain"},
        {"Content-Type": "application/x-www-form-urlencoded", "Origin": "http://evil.example"},
        {"Content-Type": "multipart/form-data; boundary=x"},
        {"Content-Type": "application/xml", "Origin": "http://evil.example"},
        {"Content-Type": "application/xml", "Origin": "null"},
        {"Content-Type": "application/xml", "Sec-Fetch-Site": "cross-site"},
    ):
        response = raw.post("/api/import/plcopen", params={"name": "stolen"}, content=xml, headers=headers)
        assert response.status_code == 403, headers
    assert projects(workspace) == ["motor"]
    imported = raw.post(
        "/api/import/plcopen",
        params={"name": "copy"},
        content=xml,
        headers={"Content-Type": "application/xml", "Origin": "http://localhost:8000", "Sec-Fetch-Site": "same-origin"},
    )
    assert imported.status_code == 201
    assert projects(workspace) == ["copy", "motor"]


def test_body_less_posts_from_another_site_fill_no_simulation_slot(raw: TestClient, motor: str) -> None:
    for _ in range(20):
        refused = raw.post("/api/projects/motor/simulations")
        assert refused.status_code == 403
        assert detail(refused)["message"] == "a POST request must be sent as application/json (Content-Type)"
    assert raw.get("/api/simulations").json() == []
    created = raw.post("/api/projects/motor/simulations", headers={"Content-Type": "application/json"})
    assert created.status_code == 201
    assert (
        raw.delete(f"/api/simulations/{created.json()['id']}", headers={"Content-Type": "application/json"}).status_code
        == 204
    )


@pytest.mark.parametrize(
    ("origin", "allowed"),
    [
        ("http://localhost:8000", True),
        ("http://127.0.0.1:8000", True),
        ("http://[::1]:8000", True),
        ("https://localhost:8000", True),
        ("http://localhost:3000", False),  # another local site
        ("http://evil.example:8000", False),
        ("http://localhost:8000/path", False),
        ("file://", False),
        ("null", False),
    ],
)
def test_state_changing_json_needs_an_allowed_origin(raw: TestClient, motor: str, origin: str, allowed: bool) -> None:
    response = raw.post("/api/projects", json={"name": "fresh"}, headers={"Origin": origin, "Host": "localhost:8000"})
    assert response.status_code == (201 if allowed else 403), response.text
    if not allowed:
        assert detail(response)["message"] == f"requests from {origin} may not change anything here"


def test_clients_that_are_no_browser_send_no_origin_and_are_served(raw: TestClient, motor: str) -> None:
    """curl and scripts send no Origin; a cross-site page cannot omit it (docs/security.md)."""
    assert raw.post("/api/projects", json={"name": "fresh"}).status_code == 201


def test_a_configured_origin_may_act(workspace: Workspace) -> None:
    security = Security(origins=frozenset({"https://plc.example.com"}))
    client = TestClient(create_app(workspace, security=security), base_url="http://localhost:8000")
    created = client.post("/api/projects", json={"name": "p"}, headers={"Origin": "https://plc.example.com"})
    assert created.status_code == 201


def test_reads_need_no_origin_and_no_content_type(raw: TestClient, motor: str) -> None:
    assert raw.get("/api/projects", headers={"Origin": "http://evil.example"}).status_code == 200  # CORS hides it


# ----------------------------------------------------------------- response headers


def test_every_response_forbids_framing_and_sniffing(raw: TestClient, motor: str) -> None:
    for response in (
        raw.get("/"),
        raw.get("/api/projects"),
        raw.get("/api/projects/ghost"),
        raw.get("/api/projects", headers={"Host": "evil.example"}),
        raw.post("/api/projects/motor/simulations"),
    ):
        assert response.headers["x-frame-options"] == "DENY"
        assert response.headers["content-security-policy"] == "frame-ancestors 'none'"
        assert response.headers["x-content-type-options"] == "nosniff"
        assert response.headers["referrer-policy"] == "same-origin"


# ----------------------------------------------------------------- JSON bodies


def test_a_deeply_nested_json_body_is_a_located_422(client: TestClient) -> None:
    body = b'{"name": "p", "pous": ' + b"[" * 100_000 + b"]" * 100_000 + b"}"
    response = client.post("/api/check", content=body)
    assert response.status_code == 422
    [diagnostic] = detail(response)["diagnostics"]
    # the object's brace is level 1, so the 400th "[" is level 401: column 22 (the prefix) + 400
    assert (diagnostic["line"], diagnostic["column"]) == (1, 22 + 400)
    assert diagnostic["message"] == (
        "the JSON nests deeper than the limit of 400 levels for the nesting of one JSON document "
        "(the setting LADDERLAB_MAX_JSON_DEPTH raises it)"
    )


def test_a_lone_surrogate_in_a_json_string_is_a_located_422_not_a_500(
    client: TestClient, workspace: Workspace, motor: str
) -> None:
    """Issue 18: a lone surrogate in any JSON string gave 500 (it cannot be encoded as UTF-8)."""
    before = workspace.load("motor")
    for url, method, body in (
        ("/api/check", "POST", b'{"name": "p", "globals": "\\udcff"}'),
        ("/api/projects", "POST", b'{"name": "a\\ud800b"}'),
        ("/api/projects/motor", "PUT", b'{"name": "motor", "types": "x\\udc00"}'),
    ):
        response = client.request(method, url, content=body, headers={"If-Match": motor})
        assert response.status_code == 422, (url, response.text)
        [diagnostic] = detail(response)["diagnostics"]
        assert diagnostic["code"] == "BAD-JSON"
        assert "half of a UTF-16 surrogate pair" in diagnostic["message"]
    assert workspace.load("motor") == before
    paired = client.post("/api/check", content=b'{"name": "p", "globals": "(* \\ud83d\\ude00 *)"}')
    assert paired.status_code == 200


# ----------------------------------------------------------------- sign-in (remote mode)


@pytest.fixture
def remote(workspace: Workspace) -> tuple[TestClient, Auth]:
    auth = Auth("s3cret-token-value", "token", secure_cookies=True)
    app = create_app(workspace, security=Security(auth=auth))
    return TestClient(app, base_url="http://localhost:8000", follow_redirects=False), auth


def test_remote_mode_refuses_everything_without_sign_in(remote, motor: str) -> None:
    client, _ = remote
    api = client.get("/api/projects")
    assert api.status_code == 401
    assert detail(api)["message"] == "sign in first: this server needs its token or password (see /login)"
    page = client.get("/")
    assert (page.status_code, page.headers["location"]) == (303, "/login?next=%2F")
    assert client.get("/login").status_code == 200
    assert client.get("/api/health").status_code == 200  # container probes
    with pytest.raises(WebSocketDisconnect) as refused:
        with client.websocket_connect("ws://localhost:8000/api/simulations/x/ws"):
            pass
    assert refused.value.code == 1008


def test_the_printed_token_link_signs_the_browser_in(remote, motor: str) -> None:
    client, _ = remote
    wrong = client.get("/?token=guess")
    assert wrong.status_code == 303 and wrong.headers["location"].startswith("/login")
    signed = client.get("/?token=s3cret-token-value")
    assert (signed.status_code, signed.headers["location"]) == (303, "/")
    cookie = signed.headers["set-cookie"]
    assert cookie.startswith("ladderlab_session_8000=")
    for attribute in ("HttpOnly", "SameSite=strict", "Secure", "Path=/"):
        assert attribute.lower() in cookie.lower()
    session = cookie.split(";")[0].split("=", 1)[1]
    headers = {"Cookie": f"ladderlab_session_8000={session}"}
    assert client.get("/api/projects", headers=headers).status_code == 200
    with client.websocket_connect("ws://localhost:8000/api/simulations/x/ws", headers=headers) as ws:
        assert ws.receive_json()["code"] == "bad_path"  # in: this app has no such simulation
    assert client.get("/api/projects", headers={"Cookie": "ladderlab_session_8000=forged"}).status_code == 401


def test_scripts_may_send_the_secret_as_a_bearer_token(remote, motor: str) -> None:
    client, _ = remote
    assert client.get("/api/projects", headers={"Authorization": "Bearer s3cret-token-value"}).status_code == 200
    assert client.get("/api/projects", headers={"Authorization": "Bearer nope"}).status_code == 401


def test_login_and_logout_with_a_password(workspace: Workspace) -> None:
    auth = Auth("correct horse battery", "password")
    client = TestClient(create_app(workspace, security=Security(auth=auth)), base_url="http://localhost:8000")
    started = time.monotonic()
    wrong = client.post("/api/login", json={"secret": "tr0ub4dor"})
    assert wrong.status_code == 401 and detail(wrong)["message"] == "wrong password"
    assert time.monotonic() - started >= 0.9, "a wrong guess costs a second"
    assert "ladderlab_session" not in client.cookies.keys().__repr__()
    right = client.post("/api/login", json={"secret": "correct horse battery"})
    assert right.status_code == 204
    assert "Secure" not in right.headers["set-cookie"]
    assert client.get("/api/projects").status_code == 200
    assert client.post("/api/logout", headers={"Content-Type": "application/json"}).status_code == 204
    assert client.get("/api/projects").status_code == 401
    forged = client.post(
        "/api/login", json={"secret": "correct horse battery"}, headers={"Origin": "http://evil.example"}
    )
    assert forged.status_code == 403, "no login CSRF"


def test_password_guessing_is_throttled(workspace: Workspace, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("ladderlab.server.login.FAILURE_DELAY_S", 0)
    auth = Auth("correct horse battery", "password")
    client = TestClient(create_app(workspace, security=Security(auth=auth)), base_url="http://localhost:8000")
    statuses = [client.post("/api/login", json={"secret": f"guess{i}"}).status_code for i in range(12)]
    assert statuses == [401] * 10 + [429] * 2
    assert client.post("/api/login", json={"secret": "correct horse battery"}).status_code == 429


def test_the_login_page_never_sends_the_browser_elsewhere(remote) -> None:
    client, _ = remote
    for target in ("//evil.example", "https://evil.example", "/x</script><script>alert(1)</script>"):
        page = client.get("/login", params={"next": target}).text
        assert 'window.location.assign("/")' in page
        assert "evil.example" not in page and "alert(1)" not in page
    assert 'window.location.assign("/projects/a")' in client.get("/login", params={"next": "/projects/a"}).text


def test_with_authentication_any_host_name_may_be_allowed(workspace: Workspace) -> None:
    security = Security(hosts=frozenset({"*"}), auth=Auth("s3cret-token-value", "token"))
    client = TestClient(create_app(workspace, security=security), base_url="http://203.0.113.7:8000")
    assert client.get("/api/projects").status_code == 401
    assert client.get("/api/projects", headers={"Authorization": "Bearer s3cret-token-value"}).status_code == 200


def test_api_client_helper_matches_what_the_app_sends(workspace: Workspace) -> None:
    """The helper the other server tests use is what the browser sends: JSON to http://localhost."""
    client = api_client(create_app(workspace))
    assert client.post("/api/projects", json={"name": "p"}).status_code == 201
    assert Path(workspace.root / "p" / "project.json").is_file()
