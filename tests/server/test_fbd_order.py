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
