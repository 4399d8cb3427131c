"""ON-11 over HTTP and the websocket: in the instance tree a pointer has a value of its own (the ADR()/REF() it
holds) and expands to what it points to (``p^``, and on to its members and elements, as CODESYS shows it
online); watch, write and force take ``^`` paths and ``r.f`` through a REFERENCE TO; a NULL pointer's target
reads as no value and writing it is refused with an error message, the connection staying open."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import Project
from ladderlab.simulation.registry import SimulationRegistry
from ladderlab.storage import Workspace

from .helpers import st_program
from .test_simulations_support import of_type, recv, recv_until, registry, subscribe

__all__ = ["registry"]  # fixture used below

TYPES = "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE"
DECLARATIONS = (
    "VAR\n    a : ARRAY [1..3] OF INT := [10, 20, 30];\n    pt : Pt;\n    p : POINTER TO INT;\n"
    "    rp : REF_TO Pt;\n    r : REFERENCE TO Pt;\n    n : REF_TO INT;\n    pp : REF_TO REF_TO INT;\nEND_VAR"
)
BODY = "p := ADR(a[2]);\nrp := REF(pt);\nr REF= pt;\npp := REF(p);\npt.x := pt.x + 1;\n"


def node(name: str, path: str, type_: str, var_class=None, expandable=False, pointer=False) -> dict:
    return {
        "name": name,
        "path": path,
        "type": type_,
        "var_class": var_class,
        "expandable": expandable,
        "pointer": pointer,
    }


def children(client: TestClient, path: str) -> list[dict]:
    response = client.get("/api/projects/ptr/variables", params={"path": path})
    assert response.status_code == 200, response.text
    return response.json()["children"]


def test_a_pointer_expands_to_its_target_in_the_instance_tree(client: TestClient, workspace: Workspace) -> None:
    """ON-11: the declaration/Variables view's tree: a pointer row has a value and one child, ``p^``."""
    workspace.create(Project(name="ptr", types=TYPES, pous=[st_program("Main", DECLARATIONS, BODY)]))
    top = children(client, "Main")
    assert top[2:] == [
        node("p", "Main.p", "POINTER TO INT", "VAR", True, True),
        node("rp", "Main.rp", "REF_TO Pt", "VAR", True, True),
        node("r", "Main.r", "REFERENCE TO Pt", "VAR", True, True),
        node("n", "Main.n", "REF_TO INT", "VAR", True, True),
        node("pp", "Main.pp", "REF_TO REF_TO INT", "VAR", True, True),
    ]
    assert children(client, "Main.p") == [node("p^", "Main.p^", "INT")]
    assert children(client, "Main.rp") == [node("rp^", "Main.rp^", "Pt", expandable=True)]
    assert children(client, "Main.rp^") == [node("x", "Main.rp^.x", "INT"), node("y", "Main.rp^.y", "INT")]
    assert children(client, "Main.pp^") == [node("pp^^", "Main.pp^^", "INT")]
    assert children(client, "Main.pp") == [node("pp^", "Main.pp^", "REF_TO INT", expandable=True, pointer=True)]
    assert children(client, "Main.r.x") == []  # through a REFERENCE TO without '^': an INT has no members
    response = client.get("/api/projects/ptr/variables", params={"path": "Main.a^"})
    assert response.status_code == 422


def test_watching_writing_and_forcing_through_pointers_over_the_websocket(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    workspace.create(Project(name="ptr", types=TYPES, pous=[st_program("Main", DECLARATIONS, BODY)]))
    sim_id = client.post("/api/projects/ptr/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.p", "Main.p^", "Main.rp^.x", "Main.r.y", "Main.pp^^", "Main.n^"])
        assert first["changed"] == {  # before the first scan every pointer is NULL
            "MAIN.P": "NULL",
            "MAIN.P^": None,
            "MAIN.RP^.X": None,
            "MAIN.R.Y": None,
            "MAIN.PP^^": None,
            "MAIN.N^": None,
        }
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=1))
        assert message["changed"] == {
            "MAIN.P": "ADR(a[2])",
            "MAIN.P^": 20,
            "MAIN.RP^.X": 1,
            "MAIN.R.Y": 0,
            "MAIN.PP^^": 20,
        }
        assert first["types"]["MAIN.P^"] == {"name": "INT", "names": None}
        assert first["types"]["MAIN.P"] == {"name": "REF_TO", "names": None}
        ws.send_json({"type": "write", "path": "Main.p^", "value": 5})
        ws.send_json({"type": "force", "path": "Main.r.y", "value": 7})
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=2))
        assert message["changed"] == {"MAIN.P^": 5, "MAIN.PP^^": 5, "MAIN.RP^.X": 2, "MAIN.R.Y": 7}
        ws.send_json({"type": "write", "path": "Main.n^", "value": 1})
        error, _ = recv_until(ws, of_type("error"))
        assert "MAIN.N is NULL: MAIN.N^ is no variable now" in error["message"]
        ws.send_json({"type": "single_cycle"})  # still connected and running
        message, _ = recv_until(ws, of_type("values", scan=3))
        assert message["changed"] == {"MAIN.RP^.X": 3}


def test_a_pointer_to_a_temporary_shows_its_value_and_no_target_once_the_call_returned(
    client: TestClient, workspace: Workspace, registry: SimulationRegistry
) -> None:
    """ON-11 with a pointer to the program's VAR_TEMP (issue 25, tests/engine/test_temp_references.py): watched
    between scans, the pointer shows its value (the ADR() it holds) and its target no value (the VAR_TEMP lived only
    while the scan's call ran: never the slot's next value); writing the target is refused with the reason, the
    connection staying open. Within the call the program read t through it (seen = 5 + 1 each scan)."""
    declarations = "VAR\n    kept : POINTER TO INT;\n    seen : INT;\nEND_VAR\nVAR_TEMP\n    t : INT;\nEND_VAR"
    body = "t := 5;\nkept := ADR(t);\nkept^ := kept^ + 1;\nseen := seen + t;\n"
    workspace.create(Project(name="ptr", pous=[st_program("Main", declarations, body)]))
    assert children(client, "Main.kept") == [node("kept^", "Main.kept^", "INT")]
    sim_id = client.post("/api/projects/ptr/simulations").json()["id"]
    with client.websocket_connect(f"/api/simulations/{sim_id}/ws") as ws:
        recv(ws)
        first = subscribe(ws, ["Main.kept", "Main.kept^", "Main.seen"])
        assert first["changed"] == {"MAIN.KEPT": "NULL", "MAIN.KEPT^": None, "MAIN.SEEN": 0}
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=1))
        assert message["changed"] == {"MAIN.KEPT": "ADR(t)", "MAIN.SEEN": 6}  # KEPT^ still no value
        ws.send_json({"type": "write", "path": "Main.kept^", "value": 1})
        error, _ = recv_until(ws, of_type("error"))
        assert "dangling reference: ADR(t) refers to a variable of a call of PROGRAM MAIN" in error["message"]
        ws.send_json({"type": "single_cycle"})
        message, _ = recv_until(ws, of_type("values", scan=2))
        assert message["changed"] == {"MAIN.SEEN": 12}
