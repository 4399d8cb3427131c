"""REST fuzzers (issue 18 item 7): whatever names, bodies, headers and bytes a client sends, the server answers
without a 500 or a traceback, with a JSON detail, and keeps answering. A few dozen cases per test in
``make test``, 10,000 in ``make test-slow``."""

from __future__ import annotations

import tempfile
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import quote

import pytest
from fastapi.testclient import TestClient
from hypothesis import given
from hypothesis import strategies as st

from ladderlab.model import Project
from ladderlab.model.names import project_name_problem
from ladderlab.server.app import create_app
from ladderlab.storage import Workspace
from tests.foundation.strategies import pous, projects
from tests.support import api_client, fuzz_settings

json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False) | st.text(max_size=20),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=10), children, max_size=4),
    max_leaves=20,
)
# Objects shaped like the models, so fuzzing reaches past the first "expected an object".
model_like = st.fixed_dictionaries(
    {},
    optional={
        "name": json_values | st.just("fuzz"),
        "kind": json_values | st.sampled_from(["program", "function"]),
        "language": json_values | st.sampled_from(["st", "ld", "fbd"]),
        "pous": json_values,
        "body": json_values,
        "tasks": json_values,
        "declarations": json_values,
        "format": json_values,
    },
)
names = st.text(max_size=70) | st.sampled_from(["..", ".", "motor", "a/b", "../x", "CON", "fuzz", " lead"])


@pytest.fixture(scope="module")
def client() -> Iterator[TestClient]:
    with tempfile.TemporaryDirectory() as root:
        app_client = api_client(create_app(Workspace(Path(root))))
        assert app_client.post("/api/projects", json={"name": "fuzz", "example": "motor"}).status_code == 201
        yield app_client


def assert_answered(response) -> None:
    assert response.status_code < 500, response.text
    if response.status_code >= 400:
        assert response.json()["detail"]["message"]


@fuzz_settings()
@given(name=names)
def test_random_project_names_never_fail_the_server(client: TestClient, name: str) -> None:
    url = f"/api/projects/{quote(name, safe='')}"
    created = client.post("/api/projects", json={"name": name})
    assert_answered(created)
    if created.status_code == 201:
        assert project_name_problem(name) is None
        assert client.get(url).json()["name"] == name
        assert client.delete(url).status_code == 204
    for response in (
        client.get(url),
        client.post(f"{url}/check"),
        client.get(f"{url}/pous/Main/symbols"),
        client.get("/api/library", params={"project": name}),
        client.post("/api/projects/fuzz/rename", json={"new_name": name}, headers={"If-Match": "0"}),
    ):
        assert_answered(response)
    assert client.get("/api/projects/fuzz").status_code == 200


@fuzz_settings()
@given(payload=json_values | model_like, pou=names)
def test_random_payloads_never_fail_the_server(client: TestClient, payload: object, pou: str) -> None:
    revision = client.get("/api/projects/fuzz").json()["revision"]
    for url in ("/api/projects/fuzz", f"/api/projects/fuzz/pous/{quote(pou, safe='')}"):
        response = client.put(url, json=payload, headers={"If-Match": revision})
        assert_answered(response)
        stored = client.get("/api/projects/fuzz").json()["revision"]
        assert stored == (response.json()["revision"] if response.status_code == 200 else revision)
        revision = stored
    for url, body in (("/api/projects", payload), ("/api/projects/fuzz/rename", payload)):
        response = client.post(url, json=body, headers={"If-Match": "0" * 16})
        assert_answered(response)
        if response.status_code == 201:
            client.delete(f"/api/projects/{quote(response.json()['name'], safe='')}")


@fuzz_settings(fast=30)
@given(project=projects(), extra=pous())
def test_any_valid_project_saves_reads_back_and_checks(client: TestClient, project: Project, extra) -> None:
    """A saved project comes back equal and every analysis route answers for every POU."""
    project = project.model_copy(update={"name": "fuzz"})
    revision = client.get("/api/projects/fuzz").json()["revision"]
    saved = client.put("/api/projects/fuzz", json=project.model_dump(mode="json"), headers={"If-Match": revision})
    assert_answered(saved)
    if saved.status_code != 200:  # only names that cannot be stored are refused
        assert {d["code"] for d in saved.json()["detail"]["diagnostics"]} <= {"BAD-NAME", "DUPLICATE-POU"}
        return
    assert client.get("/api/projects/fuzz").json()["project"] == project.model_dump(mode="json")
    pou_saved = client.put(
        f"/api/projects/fuzz/pous/{extra.name}",
        json=extra.model_dump(mode="json"),
        headers={"If-Match": saved.json()["revision"]},
    )
    assert_answered(pou_saved)
    assert client.post("/api/projects/fuzz/check").status_code == 200
    assert client.get("/api/library", params={"project": "fuzz"}).status_code == 200
    for pou in client.get("/api/projects/fuzz").json()["project"]["pous"]:
        assert client.get(f"/api/projects/fuzz/pous/{pou['name']}/symbols").status_code == 200


PATHS = [
    "/api/projects",
    "/api/projects/fuzz",
    "/api/projects/fuzz/check",
    "/api/projects/fuzz/pous/Main",
    "/api/projects/fuzz/rename",
    "/api/projects/fuzz/simulations",
    "/api/projects/fuzz/export/st",
    "/api/projects/fuzz/export/plcopen",
    "/api/import/plcopen",
    "/api/check",
    "/api/fbd/order",
    "/api/library",
    "/api/simulations",
    "/api/login",
    "/login",
    "/",
]
hostile_bodies = st.one_of(
    st.binary(max_size=200),
    st.integers(1, 3000).map(lambda n: b"[" * n + b"]" * n),
    st.sampled_from([b'{"name": "\\udcff"}', b'{"name": "fuzz", "globals": "\\ud800x"}', b"\xff\xfe{}", b"{"]),
    json_values.map(lambda v: __import__("json").dumps(v).encode()),
)
headers = st.fixed_dictionaries(
    {},
    optional={
        "Content-Type": st.sampled_from(
            ["application/json", "text/plain", "application/xml", "multipart/form-data; boundary=x", "", "a/b"]
        ),
        "Origin": st.sampled_from(["http://localhost", "http://evil.example", "null", "http://localhost:1", ""]),
        "Host": st.sampled_from(["localhost", "127.0.0.1:8000", "evil.example", "[::1]", "", "a:b:c"]),
        "If-Match": st.sampled_from(['"0"', "W/x", "", "*"]),
        "Sec-Fetch-Site": st.sampled_from(["cross-site", "same-origin", "none"]),
    },
)


@fuzz_settings()
@given(
    method=st.sampled_from(["GET", "POST", "PUT", "PATCH", "DELETE", "OPTIONS", "HEAD"]),
    path=st.sampled_from(PATHS) | names.map(lambda n: f"/api/projects/{quote(n, safe='')}"),
    body=hostile_bodies,
    sent=headers,
)
def test_any_request_is_answered_without_a_500(client: TestClient, method: str, path: str, body: bytes, sent) -> None:
    """Raw requests: any method, path, headers (hosts, origins, content types) and bytes (invalid UTF-8, lone
    surrogates, nesting past the limit)."""
    response = client.request(method, path, content=body, headers=sent)
    assert response.status_code < 500, response.text
    json_answer = response.headers.get("content-type", "").startswith("application/json") and method != "HEAD"
    if response.status_code >= 400 and json_answer:
        assert response.json()["detail"]["message"]
    assert response.headers["x-frame-options"] == "DENY"
    assert client.get("/api/health").status_code == 200
    assert client.get("/api/projects/fuzz").status_code in (200, 404)
