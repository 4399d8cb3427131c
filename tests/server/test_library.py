"""The box picker's library: standard functions and FBs plus the project's own."""

from __future__ import annotations

from fastapi.testclient import TestClient

from ladderlab.iec import stdlib

from .helpers import detail


def entries_by_name(client: TestClient, url: str) -> dict[str, dict]:
    response = client.get(url)
    assert response.status_code == 200
    rows = response.json()
    return {row["name"]: row for row in rows}


def pins(*pairs: tuple[str, str]) -> list[dict]:
    return [{"name": name, "type": type_} for name, type_ in pairs]


def test_standard_library_has_ton_with_its_pins(client: TestClient) -> None:
    """SFB-16..18: TON(IN : BOOL, PT : TIME) => Q : BOOL, ET : TIME."""
    library = entries_by_name(client, "/api/library")
    assert library["TON"] == {
        "name": "TON",
        "kind": "function_block",
        "source": "standard",
        "inputs": pins(("IN", "BOOL"), ("PT", "TIME")),
        "outputs": pins(("Q", "BOOL"), ("ET", "TIME")),
        "in_outs": [],
        "extensible": False,
        "return_type": None,
        "comment": "on-delay timer: Q TRUE once IN has been TRUE for PT",
        "methods": [],
    }


def test_standard_library_is_the_whole_catalogue(client: TestClient) -> None:
    rows = client.get("/api/library").json()
    assert [r["name"] for r in rows] == [*stdlib.FUNCTION_BLOCKS, *stdlib.FUNCTIONS]
    assert {r["source"] for r in rows} == {"standard"}


def test_generic_functions_show_their_family_as_result(client: TestClient) -> None:
    """FUN-02/FUN-03: ADD is extensible over ANY_NUM and returns that type; GT returns BOOL."""
    library = entries_by_name(client, "/api/library")
    assert library["ADD"] == {
        "name": "ADD",
        "kind": "function",
        "source": "standard",
        "inputs": pins(("IN1", "ANY_NUM"), ("IN2", "ANY_NUM")),
        "outputs": [],
        "in_outs": [],
        "extensible": True,
        "return_type": "ANY_NUM",
        "comment": "sum IN1 + IN2 + ... (operator +)",
        "methods": [],
    }
    assert (library["GT"]["return_type"], library["SEL"]["return_type"], library["INT_TO_REAL"]["return_type"]) == (
        "BOOL",
        "ANY",
        "REAL",
    )
    assert library["SEL"]["inputs"] == pins(("G", "BOOL"), ("IN0", "ANY"), ("IN1", "ANY"))


def test_library_with_project_adds_the_user_fb(client: TestClient, motor: str) -> None:
    rows = client.get("/api/library", params={"project": "motor"}).json()
    assert rows[-1] == {
        "name": "Blinker",
        "kind": "function_block",
        "source": "user",
        "inputs": pins(("Enable", "BOOL"), ("Period", "TIME")),
        "outputs": pins(("Out", "BOOL")),
        "in_outs": [],
        "extensible": False,
        "return_type": None,
        "comment": None,
        "methods": [],
    }
    assert [r["name"] for r in rows if r["source"] == "user"] == ["Blinker"]  # programs are not boxes


def test_user_function_with_in_out_and_return_type(client: TestClient, motor: str) -> None:
    function = {
        "name": "Scale",
        "kind": "function",
        "language": "st",
        "return_type": "REAL",
        "declarations": "VAR_INPUT\n    raw : INT;\n    span : ARRAY[0..1] OF REAL;\nEND_VAR\n"
        "VAR_IN_OUT\n    count : DINT;\nEND_VAR",
        "body": "Scale := INT_TO_REAL(raw);",
    }
    assert client.put("/api/projects/motor/pous/Scale", json=function, headers={"If-Match": motor}).status_code == 200
    library = entries_by_name(client, "/api/library?project=motor")
    assert library["Scale"] == {
        "name": "Scale",
        "kind": "function",
        "source": "user",
        "inputs": pins(("raw", "INT"), ("span", "ARRAY [0..1] OF REAL")),
        "outputs": [],
        "in_outs": pins(("count", "DINT")),
        "extensible": False,
        "return_type": "REAL",
        "comment": None,
        "methods": [],
    }


def test_a_user_fb_lists_its_public_methods_own_and_inherited(client: TestClient, motor: str) -> None:
    """What an FBD block ``inst.M`` draws (issue 25): the PUBLIC methods, an override once, no PRIVATE ones, no
    PROPERTY accessors; each with its inputs, VAR_OUTPUTs and result."""
    base = {
        "name": "Base",
        "kind": "function_block",
        "language": "st",
        "methods": [
            {"name": "Reset", "declarations": "VAR_INPUT to : INT; END_VAR"},
            {"name": "Hidden", "access": "PRIVATE"},
            {
                "name": "Twice",
                "return_type": "INT",
                "declarations": "VAR_INPUT x : INT; END_VAR\nVAR_OUTPUT ok : BOOL; END_VAR",
            },
        ],
        "properties": [{"name": "Level", "type": "INT", "get": {"body": "Level := 1;"}}],
    }
    derived = {
        "name": "Derived",
        "kind": "function_block",
        "language": "st",
        "extends": "Base",
        "methods": [
            {
                "name": "Twice",
                "return_type": "INT",
                "declarations": "VAR_INPUT x : INT; END_VAR\nVAR_OUTPUT ok : BOOL; END_VAR",
            }
        ],
    }
    for pou in (base, derived):
        revision = client.get("/api/projects/motor").json()["revision"]
        response = client.put(f"/api/projects/motor/pous/{pou['name']}", json=pou, headers={"If-Match": revision})
        assert response.status_code == 200, response.text
    library = entries_by_name(client, "/api/library?project=motor")
    twice = {
        "name": "Twice",
        "kind": "function",
        "source": "user",
        "inputs": pins(("x", "INT")),
        "outputs": pins(("ok", "BOOL")),
        "in_outs": [],
        "extensible": False,
        "return_type": "INT",
        "comment": None,
        "methods": [],
    }
    reset = {**twice, "name": "Reset", "inputs": pins(("to", "INT")), "outputs": [], "return_type": None}
    assert library["Base"]["methods"] == [reset, twice]
    assert library["Derived"]["methods"] == [twice, reset]  # its own first, then the inherited ones


def test_a_programs_public_methods_are_functions_named_prog_dot_method(client: TestClient, motor: str) -> None:
    """Issue 25: another POU calls a PROGRAM's method as ``Prog.M`` (CODESYS), so the box picker offers it as a
    function of that name with the method's inputs, VAR_OUTPUTs and result; a PRIVATE one (callable only inside the
    program) is not offered, nor is the program itself, nor a plant's (control code cannot call them)."""
    tally = {
        "name": "Tally",
        "kind": "program",
        "language": "st",
        "declarations": "VAR total : INT; END_VAR",
        "methods": [
            {
                "name": "Add",
                "return_type": "INT",
                "declarations": "VAR_INPUT k : INT; END_VAR\nVAR_OUTPUT twice : INT; END_VAR",
            },
            {"name": "Inner", "access": "PRIVATE"},
        ],
    }
    response = client.put("/api/projects/motor/pous/Tally", json=tally, headers={"If-Match": motor})
    assert response.status_code == 200, response.text
    plant = {**tally, "name": "Tank", "kind": "plant"}  # a plant's methods run only in the plant (ST-PLANT)
    revision = client.get("/api/projects/motor").json()["revision"]
    response = client.put("/api/projects/motor/pous/Tank", json=plant, headers={"If-Match": revision})
    assert response.status_code == 200, response.text
    rows = client.get("/api/library", params={"project": "motor"}).json()
    assert [r["name"] for r in rows if r["source"] == "user"] == ["Blinker", "Tally.Add"]
    assert rows[-1] == {
        "name": "Tally.Add",
        "kind": "function",
        "source": "user",
        "inputs": pins(("k", "INT")),
        "outputs": pins(("twice", "INT")),
        "in_outs": [],
        "extensible": False,
        "return_type": "INT",
        "comment": None,
        "methods": [],
    }


def test_library_of_unknown_project_is_404(client: TestClient) -> None:
    response = client.get("/api/library?project=ghost")
    assert (response.status_code, detail(response)["message"]) == (404, "project 'ghost' does not exist")
