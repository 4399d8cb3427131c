"""Symbols of one POU for the variable table and operand autocomplete."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.simulation.build import build_project
from ladderlab.storage import Workspace

from .helpers import detail, st_program


def symbol(
    name: str,
    var_class: str,
    type_: str,
    *,
    initial: str | None = None,
    address: str | None = None,
    comment: str | None = None,
    retain: bool = False,
    constant: bool = False,
) -> dict:
    return {
        "name": name,
        "var_class": var_class,
        "type": type_,
        "initial": initial,
        "address": address,
        "comment": comment,
        "retain": retain,
        "constant": constant,
        "gvl": None,
    }


MOTOR_GLOBALS = [
    symbol("Start", "VAR_GLOBAL", "BOOL", address="%IX0.0", comment="start push button, normally open"),
    symbol("Stop", "VAR_GLOBAL", "BOOL", address="%IX0.1", comment="stop push button, wired normally open here"),
    symbol("ResetCount", "VAR_GLOBAL", "BOOL", address="%IX0.2"),
    symbol("Motor", "VAR_GLOBAL", "BOOL", address="%QX0.0"),
    symbol("StartCount", "VAR_GLOBAL", "INT"),
    symbol("Speed", "VAR_GLOBAL", "INT"),
]


def test_symbols_of_the_example_main(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor/pous/Main/symbols")
    assert response.status_code == 200
    assert response.json() == {
        "pou": "Main",
        "symbols": [
            symbol("RunTimer", "VAR", "TON", comment="motor has been running for 5 s"),
            symbol("StartCounter", "VAR", "CTU", comment="counts motor starts"),
            symbol("Blink", "VAR", "Blinker", comment="ST function block used from LD"),
            symbol("MotorRunning", "VAR", "BOOL"),
            symbol("Lamp", "VAR", "BOOL"),
        ],
        "globals": MOTOR_GLOBALS,
        "diagnostics": [],
    }


def test_symbols_of_the_example_blinker_with_initial_values(client: TestClient, motor: str) -> None:
    body = client.get("/api/projects/motor/pous/blinker/symbols").json()
    assert body["pou"] == "Blinker"
    assert body["symbols"] == [
        symbol("Enable", "VAR_INPUT", "BOOL"),
        symbol("Period", "VAR_INPUT", "TIME", initial="T#1s", comment="full on/off cycle"),
        symbol("Out", "VAR_OUTPUT", "BOOL"),
        symbol("Half", "VAR", "TON"),
    ]


def test_symbols_while_the_body_has_errors(client: TestClient, motor: str) -> None:
    """The variable table must stay usable while the user is mid-edit in the body."""
    declarations = (
        "VAR\n    x : INT := 5;  (* five *)\n    arr : ARRAY[1..3] OF INT := [1, 2, 3];\n"
        "    s : STRING[20];\n    AT %QW2 : INT;\nEND_VAR\nVAR RETAIN\n    r : REAL := 2.5;\nEND_VAR\n"
        "VAR CONSTANT\n    K : INT := 3;\nEND_VAR"
    )
    program = st_program("Prog", declarations, "x := x +;")
    assert client.put("/api/projects/motor/pous/Prog", json=program, headers={"If-Match": motor}).status_code == 200
    body = client.get("/api/projects/motor/pous/Prog/symbols").json()
    assert body["symbols"] == [
        symbol("x", "VAR", "INT", initial="5", comment="five"),
        symbol("arr", "VAR", "ARRAY [1..3] OF INT", initial="[1, 2, 3]"),
        symbol("s", "VAR", "STRING[20]"),
        symbol("%QW2", "VAR", "INT", address="%QW2"),
        symbol("r", "VAR", "REAL", initial="2.5", retain=True),
        symbol("K", "VAR", "INT", initial="3", constant=True),
    ]
    assert body["globals"] == MOTOR_GLOBALS
    assert [(d["code"], d["file"], d["line"], d["column"]) for d in body["diagnostics"]] == [
        ("ST-PARSE", "Prog/body", 1, 9)
    ]


def test_symbol_diagnostics_cover_the_pou_and_the_globals_only(client: TestClient, motor: str) -> None:
    project = client.get("/api/projects/motor").json()["project"]
    project["globals"] += "\nVAR_GLOBAL\n    bad : NoSuchType;\nEND_VAR"
    project["pous"].append(st_program("Other", "VAR\n    y : Unknown;\nEND_VAR"))
    assert client.put("/api/projects/motor", json=project, headers={"If-Match": motor}).status_code == 200
    body = client.get("/api/projects/motor/pous/Main/symbols").json()
    assert [(d["code"], d["file"]) for d in body["diagnostics"]] == [("ST-UNKNOWN-TYPE", "globals")]
    assert body["globals"][-1] == symbol("bad", "VAR_GLOBAL", "NoSuchType")
    other = client.get("/api/projects/motor/pous/Other/symbols").json()
    assert [(d["code"], d["file"]) for d in other["diagnostics"]] == [
        ("ST-UNKNOWN-TYPE", "globals"),
        ("ST-UNKNOWN-TYPE", "Other/declarations"),
    ]


def test_symbols_of_unknown_pou_or_project_is_404(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor/pous/Nope/symbols")
    assert (response.status_code, detail(response)["message"]) == (404, "POU 'Nope' does not exist")
    assert client.get("/api/projects/ghost/pous/Main/symbols").status_code == 404


# --------------------------------------------------------------------------- the instance tree (ON-10)

TREE_TYPES = """TYPE
    Point : STRUCT
        x : INT;
        y : REAL;
    END_STRUCT;
END_TYPE"""
TREE_GLOBALS = "VAR_GLOBAL\n    Alarm : BOOL;\n    Grid : ARRAY [1..2, 0..1] OF INT;\nEND_VAR"
TREE_MAIN = """VAR
    p : Point;
    pts : ARRAY [0..2] OF Point;
    big : ARRAY [1..1500] OF BOOL;
    t1 : TON;
    tmp_in : INT;
END_VAR
VAR_TEMP
    scratch : INT;
END_VAR"""


def node(name: str, path: str, type_: str, var_class: str | None = None, expandable: bool = False) -> dict:
    return {
        "name": name,
        "path": path,
        "type": type_,
        "var_class": var_class,
        "expandable": expandable,
        "pointer": False,
    }


def children(client: TestClient, project: str, path: str) -> list[dict]:
    response = client.get(f"/api/projects/{project}/variables", params={"path": path})
    assert response.status_code == 200, response.text
    return response.json()["children"]


def test_the_instance_tree_of_the_example_programs_and_fb_instances(client: TestClient, motor: str) -> None:
    """ON-10: program, FB instances (standard and user), their pins and variables, with types and classes."""
    top = children(client, "motor", "")
    assert [(n["name"], n["var_class"], n["expandable"]) for n in top[:2]] == [
        ("Main", "PROGRAM", True),
        ("Scaling", "PROGRAM", True),
    ]
    assert [n["path"] for n in top[2:]] == [s["name"] for s in MOTOR_GLOBALS]
    assert children(client, "motor", "Main")[:3] == [
        node("RunTimer", "Main.RunTimer", "TON", "VAR", True),
        node("StartCounter", "Main.StartCounter", "CTU", "VAR", True),
        node("Blink", "Main.Blink", "Blinker", "VAR", True),
    ]
    # A standard FB: its inputs and outputs as IEC 61131-3 declares them (TON: IN, PT; Q, ET).
    assert children(client, "motor", "Main.RunTimer") == [
        node("IN", "Main.RunTimer.IN", "BOOL", "VAR_INPUT"),
        node("PT", "Main.RunTimer.PT", "TIME", "VAR_INPUT"),
        node("Q", "Main.RunTimer.Q", "BOOL", "VAR_OUTPUT"),
        node("ET", "Main.RunTimer.ET", "TIME", "VAR_OUTPUT"),
    ]
    # A user FB (examples/motor/pous/Blinker.st): its own declarations, a nested instance too.
    assert children(client, "motor", "main.blink") == [
        node("Enable", "main.blink.Enable", "BOOL", "VAR_INPUT"),
        node("Period", "main.blink.Period", "TIME", "VAR_INPUT"),
        node("Out", "main.blink.Out", "BOOL", "VAR_OUTPUT"),
        node("Half", "main.blink.Half", "TON", "VAR", True),
    ]
    assert [n["path"] for n in children(client, "motor", "main.blink.Half")] == [
        "main.blink.Half.IN",
        "main.blink.Half.PT",
        "main.blink.Half.Q",
        "main.blink.Half.ET",
    ]


def tree_project(client: TestClient) -> None:
    response = client.post("/api/projects", json={"name": "tree"})
    assert response.status_code == 201, response.text
    project = {
        "name": "tree",
        "types": TREE_TYPES,
        "globals": TREE_GLOBALS,
        "pous": [st_program("Main", TREE_MAIN, "p.x := p.x + 1;")],
    }
    saved = client.put("/api/projects/tree", json=project, headers={"If-Match": f'"{response.json()["revision"]}"'})
    assert saved.status_code == 200, saved.text


def test_structures_arrays_and_globals_expand(client: TestClient) -> None:
    tree_project(client)
    main = children(client, "tree", "Main")
    assert [n["name"] for n in main] == ["p", "pts", "big", "t1", "tmp_in"]  # VAR_TEMP lives only in a call
    assert children(client, "tree", "Main.p") == [
        node("x", "Main.p.x", "INT"),
        node("y", "Main.p.y", "REAL"),
    ]
    assert children(client, "tree", "Main.pts") == [
        node(f"[{i}]", f"Main.pts[{i}]", "Point", expandable=True) for i in range(3)
    ]
    assert children(client, "tree", "Main.pts[2]") == [
        node("x", "Main.pts[2].x", "INT"),
        node("y", "Main.pts[2].y", "REAL"),
    ]
    # A two-dimensional global, through GVL. or by name: rows, then the elements of a row.
    assert children(client, "tree", "GVL.Grid") == [
        node("[1]", "GVL.Grid[1]", "ARRAY [0..1] OF INT", expandable=True),
        node("[2]", "GVL.Grid[2]", "ARRAY [0..1] OF INT", expandable=True),
    ]
    assert children(client, "tree", "Grid[2]") == [node("[0]", "Grid[2, 0]", "INT"), node("[1]", "Grid[2, 1]", "INT")]
    # A long array lists its first 1,000 elements and counts the rest.
    big = client.get("/api/projects/tree/variables", params={"path": "Main.big"}).json()
    assert (len(big["children"]), big["children"][-1]["path"], big["more"]) == (1000, "Main.big[1000]", 500)


def test_every_path_of_the_tree_reads_in_a_running_simulation(client: TestClient, workspace: Workspace) -> None:
    """The tree's paths are the engine's: each one the server lists can be read while the program runs."""
    tree_project(client)
    sim = build_project(workspace.load("tree").project).simulation()
    sim.cycle()
    pending, read = [""], 0
    while pending:
        for child in children(client, "tree", pending.pop()):
            if child["expandable"] and not child["path"].endswith("big"):
                pending.append(child["path"])
            else:
                sim.read(child["path"])  # raises for a path the engine does not know
                read += 1
    assert read == 2 + 1 + 2 * 3 + 4 + 1 + 1 + 4  # p.x/y, big, pts[i].x/y, t1 pins, tmp_in, Alarm, Grid elements


def test_an_unknown_variable_is_refused_with_a_suggestion(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor/variables", params={"path": "Mian"})
    assert response.status_code == 404
    assert detail(response)["message"] == "no program or global variable 'Mian' - did you mean 'Main'?"
    response = client.get("/api/projects/motor/variables", params={"path": "Main.RunTimer.Nope"})
    assert response.status_code == 404
    assert detail(response)["message"] == "Main.RunTimer.Nope: TON has no member 'Nope'"


def test_the_instance_tree_of_a_configuration_lists_its_named_instances(
    client: TestClient, workspace: Workspace
) -> None:
    """Issue 16 (CFG-04): two instances of one PROGRAM are two roots of the tree, by instance name and typed by
    their PROGRAM; each path the tree lists reads in the running simulation."""
    response = client.post("/api/projects", json={"name": "plant"})
    assert response.status_code == 201, response.text
    project = {
        "name": "plant",
        "pous": [st_program("Conveyor", "VAR\n    Count : INT;\nEND_VAR", "Count := Count + 1;")],
        "configuration": {
            "name": "Plant",
            "resources": [
                {
                    "name": "Cpu",
                    "tasks": [
                        {
                            "name": "Fast",
                            "interval": "T#10ms",
                            "programs": [{"name": "Line1", "type": "Conveyor"}, {"name": "Line2", "type": "Conveyor"}],
                        }
                    ],
                }
            ],
        },
    }
    saved = client.put("/api/projects/plant", json=project, headers={"If-Match": f'"{response.json()["revision"]}"'})
    assert saved.status_code == 200, saved.text
    top = children(client, "plant", "")
    assert [(n["name"], n["path"], n["type"], n["var_class"]) for n in top] == [
        ("Line1", "Line1", "Conveyor", "PROGRAM"),
        ("Line2", "Line2", "Conveyor", "PROGRAM"),
    ]
    assert children(client, "plant", "Line2") == [node("Count", "Line2.Count", "INT", "VAR")]
    response = client.get("/api/projects/plant/variables", params={"path": "Conveyor"})  # two instances: name one
    assert response.status_code == 404
    sim = build_project(workspace.load("plant").project).simulation()
    sim.cycle(3)
    assert [sim.read("Line1.Count"), sim.read("Line2.Count")] == [3, 3]
