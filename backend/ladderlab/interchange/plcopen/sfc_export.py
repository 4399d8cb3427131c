"""An SFC POU -> PLCopen TC6: the ``<SFC>`` body, the POU's ``<actions>`` and ``<transitions>``.

The structured chart is drawn top to bottom, branches side by side: a step (and its ``<actionBlock>`` to the
right), a transition (its condition inline ST, or a ``<reference>`` to a named transition), alternative branches
between a ``<selectionDivergence>`` and a ``<selectionConvergence>``, simultaneous ones between a
``<simultaneousDivergence>`` and a ``<simultaneousConvergence>``, a ``<jumpStep>``. Each element's
``connectionPointIn`` names the element before it (its ``localId``). What PLCopen cannot say (entry and exit
actions, time limits, comments, element ids) travels with the whole body in LadderLab's addData, so LadderLab
reads its own files back to the same chart (sfc_import.py uses it while the standard XML still says the same).
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections.abc import Callable

from ...model.fbd import FbdBody
from ...model.ld import LdBody
from ...model.sfc import SfcAlternative, SfcBody, SfcChart, SfcElement, SfcJump, SfcParallel, SfcStep, SfcTransition
from .body import Counter
from .xml_io import formatted_text, ladderlab_data, position, sub

STEP_W, STEP_H = 100, 30
TRANSITION_W, TRANSITION_H = 20, 2
GAP = 30
BRANCH_GAP = 60
ACTION_W, ACTION_ROW = 160, 20

#: Writes a diagram body (``<LD>`` / ``<FBD>``) into a ``<body>`` element.
DiagramWriter = Callable[[ET.Element, LdBody | FbdBody], None]


def write_sfc_pou(node: ET.Element, body: SfcBody, diagram: DiagramWriter) -> ET.Element:
    """``<actions>``, ``<transitions>`` and ``<body><SFC>`` of an SFC POU into ``node`` (after its interface)."""
    if body.actions:
        actions = sub(node, "actions")
        for action in body.actions:
            holder = sub(actions, "action", {"name": action.name})
            _write_text_or_diagram(sub(holder, "body"), action.language, action.body, diagram)
    if body.transitions:
        transitions = sub(node, "transitions")
        for transition in body.transitions:
            holder = sub(transitions, "transition", {"name": transition.name})
            _write_text_or_diagram(sub(holder, "body"), transition.language, transition.body, diagram)
    holder = sub(node, "body")
    sfc = sub(holder, "SFC")
    named = {t.name.upper() for t in body.transitions}
    _ChartWriter(sfc, named).sequence(body.chart.elements, 0.0, 0.0, None, initial=True)
    ladderlab_data(holder, {"language": "sfc"}, {"sfc": carried_text(body)})
    return sfc


def carried_text(body: SfcBody) -> str:
    """The body as LadderLab carries it in addData: its JSON, keys sorted."""
    return json.dumps(body.model_dump(mode="json", exclude_none=True), sort_keys=True, ensure_ascii=False)


def _write_text_or_diagram(holder: ET.Element, language: str, body: object, diagram: DiagramWriter) -> None:
    if isinstance(body, str):
        formatted_text(holder, "IL" if language == "il" else "ST", body)
    elif isinstance(body, (LdBody, FbdBody)):
        diagram(holder, body)
    elif isinstance(body, SfcChart):  # an action written in SFC
        _ChartWriter(sub(holder, "SFC"), set()).sequence(body.elements, 0.0, 0.0, None, initial=True)


class _ChartWriter:
    def __init__(self, sfc: ET.Element, named: set[str]):
        self.sfc = sfc
        self.named = named
        self.counter = Counter()
        self.first = True

    # a sequence: returns (the localId the next element connects to or None, its bottom y, its width)
    def sequence(
        self, elements: list[SfcElement], x: float, y: float, incoming: int | None, initial: bool = False
    ) -> tuple[int | None, float, float]:
        width = STEP_W
        for element in elements:
            incoming, y, used = self.element(element, x, y, incoming, initial)
            initial = False
            width = max(width, used)
        return incoming, y, width

    def element(
        self, element: SfcElement, x: float, y: float, incoming: int | None, initial: bool
    ) -> tuple[int | None, float, float]:
        if isinstance(element, SfcStep):
            return self.step(element, x, y, incoming, initial)
        if isinstance(element, SfcTransition):
            return self.transition(element, x, y, incoming)
        if isinstance(element, SfcJump):
            node = self.node("jumpStep", x + STEP_W / 2 - 6, y, 12, 13, {"targetName": element.target})
            self.connect(node, incoming, 6)
            return None, y + 13 + GAP, STEP_W
        if isinstance(element, SfcAlternative):
            return self.branches(element, x, y, incoming, "selection")
        return self.branches(element, x, y, incoming, "simultaneous")

    def node(self, tag: str, x: float, y: float, width: float, height: float, attrib: dict | None = None) -> ET.Element:
        made = sub(
            self.sfc, tag, {"localId": self.counter.next_local(), "height": height, "width": width, **(attrib or {})}
        )
        position(made, "position", x, y)
        return made

    @staticmethod
    def connect(node: ET.Element, incoming: int | None, rel_x: float) -> None:
        if incoming is None:
            return
        point = sub(node, "connectionPointIn")
        position(point, "relPosition", rel_x, 0)
        sub(point, "connection", {"refLocalId": incoming})

    def step(self, step: SfcStep, x: float, y: float, incoming: int | None, initial: bool) -> tuple[int, float, float]:
        node = self.node("step", x, y, STEP_W, STEP_H, {"name": step.name, "initialStep": initial})
        self.connect(node, incoming, STEP_W / 2)
        out = sub(node, "connectionPointOut", {"formalParameter": ""})
        position(out, "relPosition", STEP_W / 2, STEP_H)
        width = STEP_W
        if step.actions:
            action_out = sub(node, "connectionPointOutAction", {"formalParameter": ""})
            position(action_out, "relPosition", STEP_W, STEP_H / 2)
            block = self.node("actionBlock", x + STEP_W + 40, y, ACTION_W, ACTION_ROW * len(step.actions))
            point = sub(block, "connectionPointIn")
            position(point, "relPosition", 0, STEP_H / 2)
            sub(point, "connection", {"refLocalId": node.get("localId")})
            for row, association in enumerate(step.actions):
                action = sub(
                    block,
                    "action",
                    {
                        "localId": self.counter.next_local(),
                        "qualifier": association.qualifier,
                        "duration": association.time,
                    },
                )
                position(action, "relPosition", 0, row * ACTION_ROW)
                sub(action, "reference", {"name": association.action})
            width += 40 + ACTION_W
        return int(node.get("localId", "0")), y + STEP_H + GAP, width

    def transition(
        self, transition: SfcTransition, x: float, y: float, incoming: int | None
    ) -> tuple[int, float, float]:
        node = self.node(
            "transition",
            x + (STEP_W - TRANSITION_W) / 2,
            y,
            TRANSITION_W,
            TRANSITION_H,
            {"priority": transition.priority},
        )
        self.connect(node, incoming, TRANSITION_W / 2)
        out = sub(node, "connectionPointOut")
        position(out, "relPosition", TRANSITION_W / 2, TRANSITION_H)
        condition = sub(node, "condition")
        text = transition.condition.strip()
        if text.upper() in self.named:
            sub(condition, "reference", {"name": text})
        else:
            formatted_text(sub(condition, "inline", {"name": ""}), "ST", text)
        return int(node.get("localId", "0")), y + TRANSITION_H + GAP, STEP_W

    def branches(
        self, element: SfcAlternative | SfcParallel, x: float, y: float, incoming: int | None, kind: str
    ) -> tuple[int | None, float, float]:
        divergence = self.node(f"{kind}Divergence", x, y, 0, 1)
        self.connect(divergence, incoming, 0)
        top = y + 1 + GAP
        ends: list[tuple[int, float]] = []
        left, bottom = x, top
        for branch in element.branches:
            out = sub(divergence, "connectionPointOut", {"formalParameter": ""})
            position(out, "relPosition", left - x + STEP_W / 2, 1)
            end, branch_bottom, width = self.sequence(branch, left, top, int(divergence.get("localId", "0")))
            if end is not None:
                ends.append((end, left + STEP_W / 2))
            bottom = max(bottom, branch_bottom)
            left += width + BRANCH_GAP
        total = left - BRANCH_GAP - x
        divergence.set("width", str(int(total)))
        if not ends:
            return None, bottom, total
        convergence = self.node(f"{kind}Convergence", x, bottom, total, 1)
        for end, at in ends:
            point = sub(convergence, "connectionPointIn")
            position(point, "relPosition", at - x, 0)
            sub(point, "connection", {"refLocalId": end})
        out = sub(convergence, "connectionPointOut")
        position(out, "relPosition", STEP_W / 2, 1)
        return int(convergence.get("localId", "0")), bottom + 1 + GAP, total
