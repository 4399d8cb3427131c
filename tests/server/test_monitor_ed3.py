"""The online websocket with the IEC ed. 3 / CODESYS types of issue 25: LTIME and LDATE_AND_TIME travel as ns with
their type names (the browser writes them as LTIME#/LDT# literals, iec.json's value_texts), a user writes an LTIME
as a literal, a based enumeration shows by name (as declared: Low, High), a REFERENCE TO by the REF(...) text it was made by."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import Project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixture used below

MS = 1_000_000  # ns


def test_long_times_based_enums_and_references_online(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    types = "TYPE\n    Level : INT (Low := -10, High := 10);\nEND_TYPE"
    program = st_program(
        "Main",
        "VAR\n    lt : LTIME := LTIME#1m2s3us;\n    at_ : LDT := LDT#2024-01-01-12:00:00;\n"
        "    lv : Level := Level#High;\n    x : INT := 4;\n    r : REFERENCE TO INT;\nEND_VAR",
        "r REF= x;\nlt := lt + LT#1ns;\n",
    )
    workspace.create(Project(name="ed3", types=types, pous=[program]))
    sim_id = client.post("/api/projects/ed3/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.lt", "Main.at_", "Main.lv", "Main.r"])
        assert first["changed"] == {
            "MAIN.LT": 62_000 * MS + 3000,
            "MAIN.AT_": 1_704_110_400_000 * MS,
            "MAIN.LV": 10,
            "MAIN.R": "NULL",
        }
        assert first["types"] == {
            "MAIN.LT": {"name": "LTIME", "names": None},
            "MAIN.AT_": {"name": "LDATE_AND_TIME", "names": None},
            "MAIN.LV": {"name": "LEVEL", "names": {"-10": "Low", "10": "High"}},
            "MAIN.R": {"name": "REF_TO", "names": None},
        }
        ws.send_json({"type": "write", "path": "Main.lt", "value": "LT#5s250ns"})
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=1))
        assert message["changed"]["MAIN.LT"] == 5000 * MS + 250 + 1
        assert message["changed"]["MAIN.R"] == "REF(x)"
