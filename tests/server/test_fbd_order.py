"""POST /api/fbd/order: the FBD editor's execution-order badges come from the lowering (GR-05, CFC-02)."""

from __future__ import annotations

from fastapi.testclient import TestClient


def block(id_: str, call: str, y: float) -> dict:
    return {"type": "block", "id": id_, "call": call, "pos": {"x": 0, "y": y}}


def wire(src: str, dst: str, pin: str) -> dict:
    return {"from": {"node": src, "pin": "OUT"}, "to": {"node": dst, "pin": pin}}


def network(order: list[str] | None = None) -> dict:
    """in a, in b -> add (drawn below) -> sub (drawn above) -> out r; and an independent MOVE."""
    return {
        "id": "n1",
        "nodes": [
            {"type": "input", "id": "a", "expr": "var1", "pos": {"x": 0, "y": 0}},
            {"type": "input", "id": "b", "expr": "var2", "pos": {"x": 0, "y": 40}},
            {"type": "input", "id": "c", "expr": "var3", "pos": {"x": 0, "y": 80}},
            block("sub", "SUB", 0),
            block("add", "ADD", 100),
            block("mv", "MOVE", 50),
            {"type": "output", "id": "r", "var": "result", "pos": {"x": 400, "y": 0}},
        ],
        "wires": [
            wire("a", "add", "IN1"),
            wire("b", "add", "IN2"),
            wire("add", "sub", "IN1"),
            wire("c", "sub", "IN2"),
            wire("sub", "r", "IN"),
            wire("c", "mv", "IN"),
        ],
        "order": order,
    }


def test_data_flow_decides_then_position(client: TestClient) -> None:
    response = client.post("/api/fbd/order", json=network())
    assert response.status_code == 200, response.text
    # add feeds sub although sub is drawn higher; the independent MOVE goes by position (y=50 before y=100).
    assert response.json() == {"order": ["c", "mv", "a", "b", "add", "sub", "r"]}


def test_explicit_order_moves_independent_nodes_but_not_data_flow(client: TestClient) -> None:
    later = client.post("/api/fbd/order", json=network(["add", "sub", "r", "mv"])).json()["order"]
    assert later == ["a", "b", "add", "c", "sub", "r", "mv"]
    forced = client.post("/api/fbd/order", json=network(["sub", "add"])).json()["order"]
    assert forced.index("add") < forced.index("sub")


def test_bad_network_is_a_located_422(client: TestClient) -> None:
    response = client.post("/api/fbd/order", json={"id": "n1", "nodes": [{"type": "blob", "id": "x"}]})
    assert response.status_code == 422
    assert "nodes" in response.text


def test_a_chart_runs_its_order_list_even_against_the_wiring_CFC_02(client: TestClient) -> None:
    """A CFC chart: SUB numbered before the ADD feeding it runs first; unlisted elements follow in FBD order."""
    chart = client.post("/api/fbd/order?chart=true", json=network(["sub", "r", "add"])).json()["order"]
    assert chart == ["c", "sub", "r", "a", "b", "add", "mv"]
    # "Order by data flow" is the FBD order of the same chart: the ADD goes back before the SUB
    by_data_flow = client.post("/api/fbd/order", json=network(["sub", "r", "add"])).json()["order"]
    assert by_data_flow == ["a", "b", "add", "c", "sub", "r", "mv"]
