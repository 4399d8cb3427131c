"""What a fault stopped: the elements of the LD/FBD networks it ran in that come after the point of the fault.

Which elements ran comes from the stamps of probe groups (docs/runtime.md, "Probes"), and a group stores its stamp
before its first probe: a fault in the middle of a group would leave the elements after it counted as run, showing
the values an earlier scan left. Each probe knows the origin id of the statement that stores it
(``ProbeTable.origins``); origin ids are numbered in emission order, which in a network is the order it runs in
(straight code: no loops, jumps go to other networks). So the probes of the faulting statement's network stored by
that statement or a later one did not run in that scan; in each caller up the call stack, those of the network
whose call was running, from the call statement on. Worked out only when a fault happened.
"""

from __future__ import annotations

from collections.abc import Callable
from types import FrameType

from .codegen.faults import generated_lines
from .codegen.module import Generated


def stopped_elements(
    error: BaseException, generated: Generated, filename: str, owner: Callable[[FrameType, str], str | None]
) -> dict[str, frozenset[str]]:
    """Probe-view key (an instance path, a FUNCTION's name: upper case) -> the element ids ``error`` stopped.
    ``owner(frame, pou)`` is the key of the probes a generated frame running ``pou``'s code stores, None when no
    probe view shows them."""
    # (key, POU, body, network) -> the origin id of the statement that did not end
    points: dict[tuple[str, str, str | None, str | None], int] = {}
    line_origins, origins = generated.line_origins, generated.origins
    for frame, line in generated_lines(error, filename):  # outermost first: the fault's line, or a call's
        oid = line_origins[line - 1] if 0 < line <= len(line_origins) else None
        if oid is None or origins[oid].network is None:
            continue
        origin = origins[oid]
        key = owner(frame, origin.pou)
        if key is not None:
            where = (key, origin.pou.upper(), origin.body, origin.network)
            points[where] = max(points.get(where, oid), oid)  # (an outlined part: the inner frame's point)
    stopped: dict[str, set[str]] = {}
    for (key, pou, body, network), point in points.items():
        table = generated.context.probes_of(pou)
        found = stopped.setdefault(key, set())
        for index, at in enumerate(table.origins):
            if at >= point and origins[at].network == network and origins[at].body == body:
                found.add(table.elements[index])
    return {key: frozenset(found) for key, found in stopped.items()}
