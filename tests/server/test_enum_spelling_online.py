"""Enumeration values online in their declared spelling (brief polish25 item 1), over the real websocket: CODESYS
shows ``Green`` for ``TYPE Color : (Red, Green)``, not the canonical ``GREEN``, so the types of a subscription (which
the watch list, inline values, panels and history show values by), a trace's first chunk (the trace's table and
legend), a force's log entry and a halted call's own variables name each value as declared; a write takes any
case (``'GREEN'``, ``'color#blueish'``) as before. Expected names come from the declaration text."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.st.project_text import source_to_project
from ladderlab.storage import Workspace

from .test_simulations_support import log_of, of_type, recv, recv_until, registry, subscribe
from .test_trace import collect, cycles, done

__all__ = ["registry"]  # fixture used below

SOURCE = """TYPE Color : (Red, Green, blueIsh := 7); END_TYPE
FUNCTION Next : Color
VAR_INPUT c : Color; END_VAR
VAR seen : Color; END_VAR
seen := c;
IF c = Color#Red THEN Next := Green; ELSE Next := Red; END_IF;
END_FUNCTION
PROGRAM Main
VAR c : Color := Green; d : Color; END_VAR
d := Next(c);
END_PROGRAM
"""
AS_DECLARED = {"name": "COLOR", "names": {"0": "Red", "1": "Green", "7": "blueIsh"}}


def test_values_of_an_enumeration_are_named_as_declared_and_written_in_any_case(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    project, diagnostics = source_to_project(SOURCE, "colors")
    assert project is not None and diagnostics == []
    workspace.create(project)
    sim_id = client.post("/api/projects/colors/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.c", "Main.d"])
        assert first["changed"] == {"MAIN.C": 1, "MAIN.D": 0}
        assert first["types"] == {"MAIN.C": AS_DECLARED, "MAIN.D": AS_DECLARED}
        for scan, (written, value, result) in enumerate(
            (("RED", 0, 1), ("color#BLUEISH", 7, 0), ("green", 1, 0), (7, 7, 0)), start=1
        ):
            ws.send_json({"type": "write", "path": "Main.c", "value": written})
            ws.send_json({"type": "single_cycle"})
            message, _ = recv_until(ws, of_type("values", scan=scan))
            shown = {"MAIN.C": value, "MAIN.D": result}
            assert {**shown, **message["changed"]} == shown, written
        ws.send_json({"type": "force", "path": "Main.c", "value": "blueish"})
        entry, _ = recv_until(ws, log_of("force"))
        assert entry["message"] == "forced MAIN.C := blueIsh"  # the online log names the value as declared too
        ws.send_json({"type": "trace_start", "id": 3, "paths": ["Main.d", "Main.c"], "samples": 2})
        first, _ = recv_until(ws, of_type("trace_data", id=3))  # its first chunk says how to show the values
        assert first["types"] == {"MAIN.D": AS_DECLARED, "MAIN.C": AS_DECLARED}
        cycles(ws, 2)
        merged, chunks = collect(ws, done)
        assert merged["values"] == {"MAIN.D": [0, 0], "MAIN.C": [7, 7]}  # c = blueIsh: Next gives Red
        assert [chunk["types"] for chunk in chunks] == [{}] * len(chunks)  # only the first chunk carries them
        ws.send_json({"type": "breakpoint_set", "pou": "Next", "line": 6})
        ws.send_json({"type": "single_cycle"})
        status, _ = recv_until(ws, of_type("status", state="halted"))
        function = status["stack"][-1]
        assert [(v["name"], v["type"], v["value"]) for v in function["variables"]] == [
            ("C", AS_DECLARED, 7),
            ("SEEN", AS_DECLARED, 7),
            ("NEXT", AS_DECLARED, 0),
        ]
