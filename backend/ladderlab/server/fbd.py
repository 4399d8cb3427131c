"""The FBD and CFC editors' execution-order badges: a stateless route over one network (or chart).

The order is the lowering's own (``lower_fbd.evaluation_order``), so the numbers the editor
shows are the order the scan runs the nodes in; problems of the network are left to the check.
"""

from __future__ import annotations

from fastapi import APIRouter

from ..model.api import FbdOrder
from ..model.fbd import FbdNetwork
from .errors import responses

router = APIRouter(prefix="/api/fbd", tags=["fbd"])


@router.post("/order", response_model=FbdOrder, responses=responses(422))
def network_order(network: FbdNetwork, chart: bool = False) -> FbdOrder:
    """``chart``: a CFC chart, whose order list is the order (CFC-02); without it, the FBD order - data flow
    first, the order list among what the wiring leaves open - which is also a chart's "order by data flow"."""
    from ..ir.lower_fbd import evaluation_order

    return FbdOrder(order=evaluation_order(network, explicit=chart))
