"""Issue 25's values online over the real websocket: a bit or part of a variable (``MAIN.D.%X0``, ``MAIN.W.%B1``, an
INT's ``MAIN.K.%X15``) is a path of its own - watched, written (the other bits kept), forced and traced, a trigger
too; LTIME, an enumeration and ``p^`` are traced; a PROPERTY without {attribute 'monitoring'} is refused with the
reason (its GET is code that may change variables: a watch or trace never runs it). Expected values follow from the program text by hand: parts
numbered from the least significant bit (IEC 61131-3 ed. 3, 6.5.6), an LTIME in nanoseconds, an enumeration as
its number."""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

from .test_simulations_support import of_type, recv, recv_until, registry, subscribe
from .test_trace import collect, cycles, done

__all__ = ["registry"]  # fixture used below

SOURCE = """
TYPE Mode : (Idle, Run := 5, Halt); END_TYPE
FUNCTION_BLOCK Tank
VAR amount : INT; reads : INT; END_VAR
PROPERTY Level : INT
GET
reads := reads + 1;
Level := amount;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    d : DINT;
    w : WORD := 16#00F0;
    k : INT := -4;
    lt : LTIME;
    m : Mode;
    p : POINTER TO DINT;
    t : Tank;
END_VAR
d := d + 1;
w.%B1 := DINT_TO_BYTE(d);
lt := lt + LTIME#1ms500us;
m := SEL(d.%X0, Mode#Idle, Mode#Run);
p := ADR(d);
END_PROGRAM
"""


@pytest.fixture
def sim_id(client: TestClient, workspace: Workspace, registry: SimulationRegistry) -> str:
    project, diagnostics = source_to_project(SOURCE, "values25")
    assert project is not None, diagnostics
    workspace.create(project)
    response = client.post("/api/projects/values25/simulations")
    assert response.status_code == 201, response.text
    return str(response.json()["id"])


def values_of(ws: Any, scan: int) -> dict[str, Any]:
    message, _ = recv_until(ws, of_type("values", scan=scan))
    return dict(message["changed"])


def test_parts_are_watched_written_and_forced_keeping_the_other_bits(client: TestClient, sim_id: str) -> None:
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.w", "Main.w.%B1", "Main.w.4", "Main.k.%X15", "Main.k.%B0", "Main.d.%X0"])
        assert first["changed"] == {
            "MAIN.W": 0x00F0,
            "MAIN.W.%B1": 0,
            "MAIN.W.%X4": True,  # w.4 names bit 4 too
            "MAIN.K.%X15": True,  # -4 is 16#FFFC: the sign bit
            "MAIN.K.%B0": 0xFC,
            "MAIN.D.%X0": False,
        }
        assert first["types"]["MAIN.W.%B1"] == {"name": "BYTE", "names": None}
        assert first["types"]["MAIN.D.%X0"] == {"name": "BOOL", "names": None}
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 1) == {"MAIN.W": 0x01F0, "MAIN.W.%B1": 1, "MAIN.D.%X0": True}
        ws.send_json({"type": "write", "path": "Main.k.%X15", "value": False})  # -4 -> 16#7FFC
        ws.send_json({"type": "force", "path": "Main.w.%X4", "value": False})  # the program writes only byte 1
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 2) == {
            "MAIN.W": 0x02E0,
            "MAIN.W.%B1": 2,
            "MAIN.W.%X4": False,
            "MAIN.K.%X15": False,
            "MAIN.D.%X0": False,
        }
        ws.send_json({"type": "write", "path": "Main.k.%B1", "value": 300})
        error, _ = recv_until(ws, of_type("error"))
        assert error["message"] == "MAIN.K.%B1: 300 is out of range for BYTE (0..255)"
        ws.send_json({"type": "subscribe", "paths": ["Main.k", "Main.w.%X16"], "interval_ms": 20})
        error, _ = recv_until(ws, of_type("error"))
        assert "MAIN.W.%X16 is outside MAIN.W, a WORD: it has bits 0..15" in error["message"]
        ws.send_json({"type": "single_cycle"})  # still connected


def test_parts_ltime_enumerations_and_pointer_targets_are_traced(client: TestClient, sim_id: str) -> None:
    paths = ["Main.d.%X0", "Main.w.%B1", "Main.k.%X15", "Main.lt", "Main.m", "Main.p^"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        subscribe(ws, [], interval_ms=20)
        ws.send_json({"type": "trace_start", "paths": paths, "samples": 3})
        cycles(ws, 3)
        merged, _ = collect(ws, done)
    assert merged["scans"] == [1, 2, 3]
    assert merged["values"] == {
        "MAIN.D.%X0": [True, False, True],
        "MAIN.W.%B1": [1, 2, 3],
        "MAIN.K.%X15": [True, True, True],
        "MAIN.LT": [1_500_000, 3_000_000, 4_500_000],
        "MAIN.M": [5, 0, 5],  # Run when d is odd
        "MAIN.P^": [1, 2, 3],
    }


def test_a_part_triggers_a_trace_on_its_rising_edge(client: TestClient, sim_id: str) -> None:
    """d.%X1 rises at scan 2 (d = 2) and again at scan 6 (d = 6)."""
    trigger = {"path": "Main.d.%X1", "condition": "rising"}
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        subscribe(ws, [], interval_ms=20)
        ws.send_json({"type": "trace_start", "paths": ["Main.d"], "samples": 2, "trigger": trigger})
        cycles(ws, 4)
        merged, _ = collect(ws, done)
    assert (merged["scans"], merged["values"]) == ([2, 3], {"MAIN.D": [2, 3]})


def test_a_property_is_refused_with_the_reason(client: TestClient, sim_id: str) -> None:
    reason = (
        "MAIN.T.Level is a PROPERTY of TANK: its value is what its GET returns when the program calls it, and "
        "watching or tracing never runs code that may change variables; watch or trace the variables its GET reads, "
        "or mark the property {attribute 'monitoring' := 'variable'} (its last value) or 'call' (its GET run between "
        "scans)"
    )
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        assert subscribe(ws, ["Main.t.reads", "Main.d"])["changed"] == {"MAIN.T.READS": 0, "MAIN.D": 0}
        ws.send_json({"type": "trace_start", "paths": ["Main.t.Level"]})
        error, _ = recv_until(ws, of_type("error"))
        assert (error["code"], error["message"]) == ("bad_path", reason)
        ws.send_json({"type": "write", "path": "Main.t.Level", "value": 1})
        error, _ = recv_until(ws, of_type("error"))
        assert reason in error["message"]
        ws.send_json({"type": "single_cycle"})
        assert values_of(ws, 1) == {"MAIN.D": 1}  # the GET never ran: t.reads is still 0
