"""Malformed websocket messages (issue 6): each gets one ``error``; the connection stays open and the
simulation is unchanged (hypothesis)."""

from __future__ import annotations

import json
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from hypothesis import assume, given
from hypothesis import strategies as st
from pydantic import ValidationError
from starlette.testclient import WebSocketTestSession

from ladderlab.server.app import create_app
from ladderlab.server.monitor import CLIENT_MESSAGE
from ladderlab.simulation.remote import SimulationHandle
from ladderlab.storage import Workspace
from tests.support import api_client, fuzz_settings

from .test_simulations_support import counter_project, install, recv

TYPES = [
    "subscribe",
    "write",
    "force",
    "unforce",
    "unforce_all",
    "breakpoint_set",
    "breakpoint_clear",
    "continue",
    "step",
    "run",
    "stop",
    "single_cycle",
    "trace_start",
    "values",
    "status",
    "",
    "Subscribe",
    "RUN",
]
FIELDS = [
    "paths",
    "elements",
    "interval_ms",
    "path",
    "value",
    "pou",
    "network",
    "element",
    "line",
    "granularity",
    "samples",
    "trigger",
    "pou_instance",
    "ids",
    "extra",
]

scalars = st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=12)
json_values = st.recursive(
    scalars,
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=8), inner, max_size=3),
    max_leaves=12,
)
message_like = st.builds(
    lambda kind, fields: {**({"type": kind} if kind is not None else {}), **fields},
    st.none() | st.sampled_from(TYPES) | json_values,
    st.dictionaries(
        st.sampled_from(FIELDS), json_values | st.sampled_from(["Main.Count", "Main", "MAIN.FLAG"]), max_size=4
    ),
)


def is_valid(data: Any) -> bool:
    try:
        CLIENT_MESSAGE.validate_python(data)
    except ValidationError:
        return False
    return True


@pytest.fixture(scope="module")
def session() -> Iterator[tuple[TestClient, WebSocketTestSession, SimulationHandle]]:
    with tempfile.TemporaryDirectory() as root:
        workspace = Workspace(Path(root))
        workspace.create(counter_project())
        client = api_client(create_app(workspace))
        registry = install(client)
        sim_id = client.post("/api/projects/counter/simulations").json()["id"]
        client.post(f"/api/simulations/{sim_id}/cycle")
        handle = registry.get(sim_id).handle
        with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
            assert recv(ws)["type"] == "status"
            assert recv(ws)["message"] == "single cycle"  # the log so far
            yield client, ws, handle
        registry.close()


def state_of(handle: SimulationHandle) -> tuple:
    state = handle.inspect()
    keys = ("state", "scan_count", "time_ms", "snapshot", "forced", "breakpoints", "halted", "variant")
    return tuple(state[key] for key in keys)


def assert_refused_without_effect(session: tuple, send: Any) -> dict[str, Any]:
    _, ws, handle = session
    before = state_of(handle)
    send(ws)
    reply = recv(ws)
    assert reply["type"] == "error" and reply["message"], reply
    assert state_of(handle) == before
    return reply


@fuzz_settings()
@given(data=message_like | json_values)
def test_malformed_messages_get_an_error_and_change_nothing(session: tuple, data: Any) -> None:
    assume(not is_valid(data))
    reply = assert_refused_without_effect(session, lambda ws: ws.send_text(json.dumps(data)))
    assert reply["code"] == "bad_message"


@fuzz_settings()
@given(text=st.text(max_size=40))
def test_text_that_is_not_json_gets_an_error(session: tuple, text: str) -> None:
    try:
        json.loads(text)
    except ValueError:
        reply = assert_refused_without_effect(session, lambda ws: ws.send_text(text))
        assert reply["code"] == "bad_json"
    else:
        assume(False)


@fuzz_settings()
@given(blob=st.binary(max_size=40))
def test_binary_frames_get_an_error(session: tuple, blob: bytes) -> None:
    reply = assert_refused_without_effect(session, lambda ws: ws.send_bytes(blob))
    assert reply == {
        "type": "error",
        "code": "bad_message",
        "message": "binary frames are not understood: send JSON text",
    }


@fuzz_settings()
@given(
    text=st.one_of(
        st.integers(1, 5000).map(lambda n: "[" * n + "]" * n),
        st.sampled_from(["\\udcff", "\\ud800", "\\ud83d\\ude00"]).map(
            lambda escape: '{"type": "write", "path": "Main.' + escape + '", "value": 1}'
        ),
        st.sampled_from(["subscribe", "trace_start", "force"]).map(
            lambda kind: '{"type": "' + kind + '", "paths": ["\\udcff"], "path": "\\ud800", "value": "\\udfff"}'
        ),
    )
)
def test_deep_or_surrogate_messages_get_an_error(session: tuple, text: str) -> None:
    """Issue 18: nesting past the interpreter's limits and lone surrogates in JSON strings."""
    reply = assert_refused_without_effect(session, lambda ws: ws.send_text(text))
    assert reply["code"] in ("bad_json", "bad_message", "bad_path", "bad_value")


def test_the_connection_and_the_server_still_work_afterwards(session: tuple) -> None:
    client, ws, handle = session
    ws.send_json({"type": "subscribe", "paths": ["Main.Count"], "interval_ms": 20})
    assert recv(ws)["changed"] == {"MAIN.COUNT": handle.read("Main.Count")}
    assert client.get("/api/health").status_code == 200
