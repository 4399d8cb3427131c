"""Issue 9: a 1,000-network FBD POU opens, and only canvases near the viewport are mounted.

The opening time is printed, not asserted: timing assertions fail on a busy machine.
"""

from __future__ import annotations

import re
import time

import pytest

from .steps import store_project

pytestmark = pytest.mark.browser

NETWORKS = 1000


def _big_project() -> dict:
    def network(i: int) -> dict:
        return {
            "id": f"n{i}",
            "nodes": [
                {"type": "input", "id": f"a{i}", "expr": f"a{i % 10}", "pos": {"x": 20, "y": 20}},
                {"type": "input", "id": f"b{i}", "expr": f"b{i % 10}", "pos": {"x": 20, "y": 70}},
                {"type": "block", "id": f"and{i}", "call": "AND", "pos": {"x": 200, "y": 20}},
                {"type": "output", "id": f"q{i}", "var": f"q{i % 10}", "pos": {"x": 400, "y": 20}},
            ],
            "wires": [
                {"from": {"node": f"a{i}", "pin": "OUT"}, "to": {"node": f"and{i}", "pin": "IN1"}},
                {"from": {"node": f"b{i}", "pin": "OUT"}, "to": {"node": f"and{i}", "pin": "IN2"}},
                {"from": {"node": f"and{i}", "pin": "OUT"}, "to": {"node": f"q{i}", "pin": "IN"}},
            ],
        }

    declarations = "VAR\n" + "".join(f"  a{i}, b{i}, q{i} : BOOL;\n" for i in range(10)) + "END_VAR"
    main = {
        "name": "Main",
        "kind": "program",
        "language": "fbd",
        "declarations": declarations,
        "body": {"networks": [network(i) for i in range(NETWORKS)]},
    }
    return {"name": "bigfbd", "pous": [main]}


def test_a_1000_network_fbd_pou_opens_and_mounts_only_what_is_near_view(page, server):
    store_project(server, _big_project())
    orders: list[str] = []
    page.on("request", lambda r: orders.append(r.url) if r.url.endswith("/api/fbd/order") else None)

    page.goto(server)
    page.get_by_role("navigation", name="Projects").get_by_role("button", name=re.compile("^bigfbd")).click()
    tree_item = page.get_by_role("navigation", name="Project tree").get_by_role("button", name=re.compile("^Main"))
    tree_item.wait_for()
    start = time.perf_counter()
    tree_item.click()
    page.locator('.fbd-node[data-node="and0"]').wait_for()
    opened = time.perf_counter() - start
    page.locator('.fbd-node[data-node="and0"] .fbd-order').wait_for()
    badges = time.perf_counter() - start
    mounted = page.locator(".react-flow").count()
    print(
        f"1,000-network FBD POU opened in {opened * 1000:.0f} ms, order badges after {badges * 1000:.0f} ms; {mounted} canvases mounted, "
        f"{len(orders)} order requests"
    )
    assert page.locator(".fbd-network").count() == NETWORKS
    assert 0 < mounted < 30, mounted
    assert 0 < len(orders) < 30, len(orders)

    # Scrolling far down mounts the networks there, with their badges.
    page.locator('.fbd-network[data-network="n900"]').scroll_into_view_if_needed()
    page.locator('.fbd-node[data-node="and900"] .fbd-order').wait_for()
    assert page.locator('.fbd-node[data-node="and0"]').count() == 0
