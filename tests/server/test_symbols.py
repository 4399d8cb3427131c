"""Symbols of one POU for the variable table and operand autocomplete."""

from __future__ import annotations

from fastapi.testclient import TestClient

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
