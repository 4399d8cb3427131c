"""POST /api/ld/il: an LD network as IL for the editor's read-only "View as IL" (issue 26 item 4)."""

from __future__ import annotations

from tests.ir.diagram_support import coil, contact, rung


def test_the_view_as_il_route(client):
    network = rung("n1", contact("a", "i0"), coil("q", "o0")).model_dump(mode="json")
    response = client.post("/api/ld/il", json=network)
    assert response.status_code == 200, response.text
    assert response.json() == {"text": "LD i0\nST o0", "reason": None}
    edge = rung("n2", contact("a", "i0", "n"), coil("q", "o0")).model_dump(mode="json")
    assert client.post("/api/ld/il", json=edge).json() == {
        "text": None,
        "reason": "the N contact i0 detects an edge: IL needs an R_TRIG",
    }
