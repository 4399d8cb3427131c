"""The cross-reference list (issue 28) over HTTP, checked against hand-written expectations for examples/motor.

The expectations were written from the example's files (globals.st, pous/Main.ld.json, pous/Blinker.st,
pous/Scaling.fbd.json): each variable, where it is declared (the line of its declarations text), and every
network element (with its number and operand) or ST body line that reads, writes or calls it.
"""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.model import Project
from ladderlab.simulation.xref import cross_reference

# (kind, POU, network number, element, line, path); declarations: the line in globals.st / the POU's declarations.
MOTOR = {
    (None, "Start"): [
        ("declared", None, None, None, 2, "Start"),
        ("read", "Main", 1, "start", None, "Start"),
        ("read", "Main", 3, "start_edge", None, "Start"),
    ],
    (None, "Stop"): [("declared", None, None, None, 3, "Stop"), ("read", "Main", 1, "stop", None, "Stop")],
    (None, "ResetCount"): [
        ("declared", None, None, None, 4, "ResetCount"),
        ("read", "Main", 3, "reset_count", None, "ResetCount"),
    ],
    (None, "Motor"): [
        ("declared", None, None, None, 5, "Motor"),
        ("read", "Main", 1, "seal", None, "Motor"),
        ("write", "Main", 1, "motor", None, "Motor"),
        ("read", "Main", 2, "motor_on", None, "Motor"),
    ],
    (None, "StartCount"): [
        ("declared", None, None, None, 6, "StartCount"),
        ("write", "Main", 3, "ctu", None, "StartCount"),  # CV => StartCount
        ("read", "Scaling", 1, "count", None, "StartCount"),
    ],
    (None, "Speed"): [("declared", None, None, None, 7, "Speed"), ("write", "Scaling", 1, "speed_out", None, "Speed")],
    ("Main", "RunTimer"): [
        ("declared", "Main", None, None, 2, "RunTimer"),
        ("call", "Main", 2, "ton", None, "RunTimer"),
        ("read", "Main", 2, "ton", None, "RunTimer.Q"),  # the box's Q carries the power on
    ],
    ("Main", "StartCounter"): [
        ("declared", "Main", None, None, 3, "StartCounter"),
        ("call", "Main", 3, "ctu", None, "StartCounter"),
        ("read", "Main", 3, "ctu", None, "StartCounter.Q"),
    ],
    ("Main", "Blink"): [
        ("declared", "Main", None, None, 4, "Blink"),
        ("call", "Main", 4, "blink", None, "Blink"),
        ("read", "Main", 4, "blink", None, "Blink.Out"),
    ],
    ("Main", "MotorRunning"): [
        ("declared", "Main", None, None, 5, "MotorRunning"),
        ("write", "Main", 2, "running", None, "MotorRunning"),
        ("read", "Main", 4, "running_on", None, "MotorRunning"),
    ],
    ("Main", "Lamp"): [("declared", "Main", None, None, 6, "Lamp"), ("write", "Main", 4, "lamp_coil", None, "Lamp")],
    ("Blinker", "Enable"): [
        ("declared", "Blinker", None, None, 2, "Enable"),
        ("read", "Blinker", None, None, 1, "Enable"),  # IF NOT Enable THEN
    ],
    ("Blinker", "Period"): [
        ("declared", "Blinker", None, None, 3, "Period"),
        ("read", "Blinker", None, None, 6, "Period"),  # Half(IN := TRUE, PT := Period / 2);
    ],
    ("Blinker", "Out"): [
        ("declared", "Blinker", None, None, 6, "Out"),
        ("write", "Blinker", None, None, 2, "Out"),
        ("read", "Blinker", None, None, 8, "Out"),  # Out := NOT Out;
        ("write", "Blinker", None, None, 8, "Out"),
    ],
    ("Blinker", "Half"): [
        ("declared", "Blinker", None, None, 9, "Half"),
        ("call", "Blinker", None, None, 3, "Half"),
        ("call", "Blinker", None, None, 6, "Half"),
        ("read", "Blinker", None, None, 7, "Half.Q"),  # IF Half.Q THEN
        ("call", "Blinker", None, None, 9, "Half"),
    ],
    ("Scaling", "HighSpeed"): [
        ("declared", "Scaling", None, None, 2, "HighSpeed"),
        ("write", "Scaling", 1, "high", None, "HighSpeed"),
    ],
}


def _table(entries) -> dict:
    return {
        (e["pou"], e["name"]): [
            (a["kind"], a["pou"], a["network_number"], a["element"], a["line"], a["path"]) for a in e["accesses"]
        ]
        for e in entries
    }


def test_xref_of_the_motor_example_matches_the_hand_written_list(client: TestClient, motor: str) -> None:
    response = client.get("/api/projects/motor/xref")
    assert response.status_code == 200, response.text
    entries = response.json()["entries"]
    assert _table(entries) == MOTOR
    start = next(e for e in entries if e["name"] == "Start")
    assert (start["address"], start["type"], start["var_class"]) == ("%IX0.0", "BOOL", "VAR_GLOBAL")
    assert start["comment"] == "start push button, normally open"
    contact = next(a for a in start["accesses"] if a["element"] == "start_edge")
    assert (contact["network"], contact["operand"]) == ("count_starts", "Start")


def test_xref_of_a_missing_project_is_404(client: TestClient) -> None:
    assert client.get("/api/projects/nothing/xref").status_code == 404


def test_externals_array_indices_in_outs_and_a_pou_with_errors() -> None:
    """VAR_EXTERNAL is a declaration of the global in that POU; an index is a read; a FOR variable is written;
    a POU whose body has errors still lists its declarations."""
    project = Project.model_validate(
        {
            "name": "x",
            "globals": "VAR_GLOBAL\n    G : INT;\nEND_VAR",
            "pous": [
                {
                    "name": "P",
                    "kind": "program",
                    "language": "st",
                    "declarations": "VAR_EXTERNAL\n    G : INT;\nEND_VAR\nVAR\n    a : ARRAY [0..3] OF INT;\n"
                    "    i : INT;\nEND_VAR",
                    "body": "FOR i := 0 TO 3 DO\n    a[i] := G;\nEND_FOR;",
                },
                {
                    "name": "Broken",
                    "kind": "program",
                    "language": "st",
                    "declarations": "VAR\n    x : INT;\nEND_VAR",
                    "body": "x := nothing;",
                },
            ],
        }
    )
    table = _table([e.model_dump() for e in cross_reference(project).entries])
    assert table[(None, "G")] == [
        ("declared", None, None, None, 2, "G"),
        ("declared", "P", None, None, 2, "G"),
        ("read", "P", None, None, 2, "G"),
    ]
    assert table[("P", "i")] == [
        ("declared", "P", None, None, 6, "i"),
        ("write", "P", None, None, 1, "i"),
        ("read", "P", None, None, 2, "i"),
    ]
    assert table[("P", "a")] == [("declared", "P", None, None, 5, "a"), ("write", "P", None, None, 2, "a[]")]
    assert table[("Broken", "x")][0] == ("declared", "Broken", None, None, 2, "x")


def test_what_methods_use_is_listed_under_the_method_and_its_function_block() -> None:
    """Issue 25: a method's own variables are entries of ``F.M``; the instance variables it reads and writes are
    accesses of the FB's entries, located at the method's body lines; a call of the method is a call of the
    instance it is called on."""
    from ladderlab.st.project_text import source_to_project

    text = (
        "FUNCTION_BLOCK Counter\nVAR count : INT; END_VAR\n"
        "METHOD Add : INT\nVAR_INPUT n : INT; END_VAR\nVAR tmp : INT; END_VAR\n"
        "tmp := n * 2;\ncount := count + tmp;\nAdd := count;\nEND_METHOD\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c : Counter; r : INT; END_VAR\nr := c.Add(n := 1);\nEND_PROGRAM\n"
    )
    project, _ = source_to_project(text, "oo")
    table = _table([e.model_dump() for e in cross_reference(project).entries])
    line = {s: n for n, s in enumerate(text.splitlines(), 1)}
    assert table[("Counter.Add", "tmp")] == [
        ("declared", "Counter.Add", None, None, line["VAR tmp : INT; END_VAR"], "tmp"),
        ("write", "Counter.Add", None, None, line["tmp := n * 2;"], "tmp"),
        ("read", "Counter.Add", None, None, line["count := count + tmp;"], "tmp"),
    ]
    assert table[("Counter.Add", "n")] == [
        ("declared", "Counter.Add", None, None, line["VAR_INPUT n : INT; END_VAR"], "n"),
        ("read", "Counter.Add", None, None, line["tmp := n * 2;"], "n"),
    ]
    assert table[("Counter", "count")] == [
        ("declared", "Counter", None, None, line["FUNCTION_BLOCK Counter"] + 1, "count"),
        ("read", "Counter.Add", None, None, line["count := count + tmp;"], "count"),
        ("write", "Counter.Add", None, None, line["count := count + tmp;"], "count"),
        ("read", "Counter.Add", None, None, line["Add := count;"], "count"),
    ]
    assert table[("Main", "c")] == [
        ("declared", "Main", None, None, line["VAR c : Counter; r : INT; END_VAR"], "c"),
        ("call", "Main", None, None, line["r := c.Add(n := 1);"], "c"),
    ]
