"""PLCopen TC6 ``<SFC>`` bodies (with the POU's ``<actions>`` and ``<transitions>``) -> an SfcBody.

A PLCopen chart is a graph: every element's ``connectionPointIn`` names the element before it. Each transition's
steps are found by walking back through divergences and simultaneous convergences to steps, and forward through
simultaneous divergences, convergences and jumps (``targetName``) to steps; transitions that leave one step are
ordered left to right by their position (SFC-08), an explicit ``priority`` first. ``model.sfc_graph.graph_chart``
then draws the graph as a structured chart. Conditions: inline ST (``negated`` adds NOT), a ``<reference>`` to a
named transition, inline LD/FBD (made a named transition); an action block's action: a ``<reference>`` to an
action or a BOOL variable, or an inline body (made a named action). What cannot be imported is reported, located.
When LadderLab's addData carries the body and the standard XML still says the same, that body is used.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass, field

from pydantic import ValidationError

from ...model.fbd import FbdBody
from ...model.ld import LdBody
from ...model.sfc import (
    QUALIFIERS,
    SfcAction,
    SfcAssociation,
    SfcBody,
    SfcChart,
    SfcNamedTransition,
    SfcStep,
    SfcTransition,
    prefix_ids,
)
from ...model.sfc_graph import ImportedStep, ImportedTransition, UnstructuredChart, graph_chart
from ...st import ast
from ...st.parser import parse_expression, parse_statements
from .sfc_export import write_sfc_pou
from .xml_io import Reader, body_language, canonical, info, info_text, local, text_content

#: Reads a ``<body>`` written in LD or FBD: (language, networks) or None (reported).
DiagramReader = Callable[[ET.Element, str], "tuple[str, LdBody | FbdBody] | None"]

_FLOW = (
    "step",
    "transition",
    "selectionDivergence",
    "selectionConvergence",
    "simultaneousDivergence",
    "simultaneousConvergence",
    "jumpStep",
    "actionBlock",
    "macroStep",
)


class _NotDrawable(ValueError):
    """A condition drawn in the chart that is more than contacts, variables and logic blocks."""


@dataclass
class _Element:
    node: ET.Element
    tag: str
    local_id: int
    x: float
    y: float
    before: list[int] = field(default_factory=list)
    after: list[int] = field(default_factory=list)


class SfcImporter:
    def __init__(self, reader: Reader, pou: str, diagram: DiagramReader, write_diagram: Callable):
        self.r = reader
        self.pou = pou
        self.diagram = diagram
        self.write_diagram = write_diagram
        self.actions: list[SfcAction] = []
        self.transitions: list[SfcNamedTransition] = []
        self.names: set[str] = set()
        self.drawing: dict[int, ET.Element] = {}

    def report(self, message: str, node: ET.Element | None, severity: str = "error", code: str = "PLCOPEN-SFC") -> None:
        self.r.report(code, message, node, severity=severity, pou=self.pou)

    # ------------------------------------------------------------ the POU
    def body(self, pou_node: ET.Element, body_node: ET.Element, sfc: ET.Element) -> SfcBody:
        carried = self.carried(pou_node, body_node, sfc)
        if carried is not None:
            return carried
        for holder in self.r.children(self.r.child(pou_node, "actions"), "action"):
            self.named_action(holder)
        for holder in self.r.children(self.r.child(pou_node, "transitions"), "transition"):
            self.named_transition(holder)
        self.names = {a.name.upper() for a in self.actions} | {t.name.upper() for t in self.transitions}
        chart = self.chart(sfc)
        return SfcBody(chart=chart or SfcChart(), actions=self.actions, transitions=self.transitions)

    def carried(self, pou_node: ET.Element, body_node: ET.Element, sfc: ET.Element) -> SfcBody | None:
        """LadderLab's own body from addData, when writing it again gives the same standard XML."""
        text = info_text(info(body_node, self.r), "sfc")
        if text is None:
            return None
        try:
            body = SfcBody.model_validate(json.loads(text))
        except (ValueError, ValidationError):
            return None
        again = ET.Element("pou")
        write_sfc_pou(again, body, self.write_diagram)
        expected = [e for e in again if local(e) in ("actions", "transitions")]
        actual = [e for e in self.r.elements(pou_node) if local(e) in ("actions", "transitions")]
        written_sfc = next(iter(again.find("body") or []), None)
        same = (
            [canonical(e) for e in expected] == [canonical(e) for e in actual]
            and written_sfc is not None
            and (canonical(written_sfc) == canonical(sfc))
        )
        return body if same else None

    def named_action(self, holder: ET.Element) -> None:
        name = holder.get("name", "")
        made = self.body_of(self.r.child(holder, "body"), f"action {name}", action=name)
        if made is not None:
            self.actions.append(SfcAction(name=name, language=made[0], body=made[1]))

    def named_transition(self, holder: ET.Element) -> None:
        name = holder.get("name", "")
        made = self.body_of(self.r.child(holder, "body"), f"transition {name}")
        if made is None:
            return
        language, body = made
        if language == "st" and isinstance(body, str):
            body = self.transition_text(body, name, holder)
        self.transitions.append(SfcNamedTransition(name=name, language=language, body=body))  # type: ignore[arg-type]  # ST, LD or FBD

    def transition_text(self, text: str, name: str, node: ET.Element) -> str:
        """A named transition in ST: an expression, or ``name := expression;`` as some tools write it."""
        stripped = text.strip().rstrip(";").strip()
        if parse_expression(stripped).ok:
            return stripped
        statements = parse_statements(text).ast or []
        first = statements[0] if len(statements) == 1 else None
        if (
            isinstance(first, ast.Assign)
            and isinstance(first.target, ast.Name)
            and first.target.name.upper() == (name.upper())
        ):
            span = first.value.span
            lines = text.splitlines()
            if span.line == span.end_line:
                return lines[span.line - 1][span.column - 1 : span.end_column - 1]
        self.report(f"transition {name}: its ST is neither a condition nor '{name} := condition;'", node)
        return stripped

    def body_of(
        self, body: ET.Element | None, what: str, action: str | None = None
    ) -> tuple[str, str | LdBody | FbdBody | SfcChart] | None:
        """An action's or named transition's body; an action's (``action``: its name) may be written in SFC."""
        tag, language = body_language(body, self.r)  # CODESYS's CFC chart (an empty ST) is reported below
        if tag == "ST":
            return "st", text_content(language)
        if tag == "IL":  # SFC-02: an action or named transition written in IL (docs/il.md)
            return "il", text_content(language).strip("\n")
        if tag in ("LD", "FBD") and body is not None:
            return self.diagram(body, what)
        if tag == "SFC" and action is not None and language is not None:
            drawn = self.chart(language)
            if drawn is None:
                return None
            return "sfc", prefix_ids(drawn, f"{action}_")  # local ids restart in every body
        self.report(f"{what} is written in {tag}, which LadderLab cannot import here", language)
        return None

    # ------------------------------------------------------------ the chart
    def chart(self, sfc: ET.Element) -> SfcChart | None:
        self.drawing = {int(n.get("localId", "")): n for n in self.r.elements(sfc) if n.get("localId", "").isdigit()}
        elements = self.flow(sfc)
        steps: list[ImportedStep] = []
        for e in sorted(elements.values(), key=lambda e: (e.y, e.x)):
            if e.tag == "step":
                steps.append(ImportedStep(self.step(e, elements), e.node.get("initialStep") == "true"))
            elif e.tag == "macroStep":
                self.report("a macro step cannot be imported: its steps were left out", e.node)
        transitions = []
        for e in sorted((e for e in elements.values() if e.tag == "transition"), key=lambda e: (e.x, e.y)):
            sources = self.steps_before(e, elements)
            targets = self.steps_after(e, elements)
            if sources is None or targets is None:
                continue
            transitions.append(ImportedTransition(self.transition(e), sources, targets))
        try:
            chart, unreachable = graph_chart(steps, transitions)
        except UnstructuredChart as error:
            self.report(f"the chart cannot be drawn as a LadderLab chart: {error}", sfc)
            return None
        for name in unreachable:
            self.report(f"step {name} is reached from no initial step: it was left out", sfc, "warning")
        return chart

    def flow(self, sfc: ET.Element) -> dict[int, _Element]:
        out: dict[int, _Element] = {}
        for node in self.r.elements(sfc):
            tag = local(node)
            if tag not in _FLOW:
                continue
            try:
                local_id = int(node.get("localId", ""))
            except ValueError:
                self.report(f"<{tag}> has no localId", node)
                continue
            where = self.r.child(node, "position")
            x, y = (float(where.get(axis, "0") or 0) if where is not None else 0.0 for axis in "xy")
            element = _Element(node, tag, local_id, x, y)
            for point in self.r.children(node, "connectionPointIn"):
                for connection in self.r.children(point, "connection"):
                    try:
                        element.before.append(int(connection.get("refLocalId", "")))
                    except ValueError:
                        self.report(f"<{tag}> {local_id} has a connection without refLocalId", node)
            out[local_id] = element
        for element in out.values():
            for before in element.before:
                if before in out:
                    out[before].after.append(element.local_id)
        return out

    def steps_before(self, start: _Element, elements: dict[int, _Element]) -> list[str] | None:
        found: list[str] = []
        todo = list(start.before)
        while todo:
            e = elements.get(todo.pop(0))
            if e is None:
                continue
            if e.tag == "step":
                found.append(e.node.get("name", ""))
            elif e.tag in ("selectionDivergence", "simultaneousConvergence"):
                todo += e.before
            else:
                self.report(f"transition {start.local_id} follows a <{e.tag}>, not a step", start.node)
                return None
        if not found:
            self.report(f"transition {start.local_id} follows no step", start.node)
            return None
        return found

    def steps_after(self, start: _Element, elements: dict[int, _Element]) -> list[str] | None:
        found: list[str] = []
        todo = list(start.after)
        while todo:
            e = elements[todo.pop(0)]
            if e.tag == "step":
                found.append(e.node.get("name", ""))
            elif e.tag == "jumpStep":
                found.append(e.node.get("targetName", ""))
            elif e.tag in ("selectionConvergence", "simultaneousDivergence"):
                todo += e.after
            elif e.tag != "actionBlock":
                self.report(f"transition {start.local_id} leads to a <{e.tag}>, not a step", start.node)
                return None
        if not found:
            self.report(f"transition {start.local_id} leads to no step", start.node)
            return None
        return found

    def step(self, e: _Element, elements: dict[int, _Element]) -> SfcStep:
        name = e.node.get("name", "")
        associations = []
        for block_id in e.after:
            block = elements[block_id]
            if block.tag != "actionBlock":
                continue
            for number, action in enumerate(self.r.children(block.node, "action"), 1):
                association = self.association(action, name, number)
                if association is not None:
                    associations.append(association)
        return SfcStep(id=f"s{e.local_id}", name=name, actions=associations)

    def association(self, action: ET.Element, step: str, number: int) -> SfcAssociation | None:
        qualifier = action.get("qualifier", "N")
        if qualifier not in QUALIFIERS:
            self.report(
                f"step {step}: the qualifier {qualifier} is not one LadderLab runs; N is used", action, "warning"
            )
            qualifier = "N"
        if action.get("indicator"):
            self.report(f"step {step}: the indicator variable {action.get('indicator')} is not kept", action, "warning")
        reference = self.r.child(action, "reference")
        if reference is not None:
            target = reference.get("name", "")
        else:
            made = self.body_of(self.r.child(action, "inline"), f"the inline action {number} of step {step}")
            if made is None:
                return None
            target = self.fresh(f"{step}_action{number}")
            self.actions.append(SfcAction(name=target, language=made[0], body=made[1]))
        return SfcAssociation(
            id=f"a{action.get('localId', number)}_{step}_{number}",
            qualifier=qualifier,  # type: ignore[arg-type]  # checked against QUALIFIERS above
            action=target,
            time=action.get("duration") or None,
        )

    def transition(self, e: _Element) -> SfcTransition:
        condition = self.r.child(e.node, "condition")
        text = "FALSE"
        priority = e.node.get("priority")
        if condition is None:
            self.report(f"transition {e.local_id} has no condition: FALSE is used", e.node, "warning")
        else:
            reference = self.r.child(condition, "reference")
            inline = self.r.child(condition, "inline")
            if reference is not None:
                text = reference.get("name", "FALSE")
            elif inline is not None:
                made = self.body_of(inline, f"the condition of transition {e.local_id}")
                if made is not None and made[0] == "st" and isinstance(made[1], str):
                    text = made[1].strip().rstrip(";").strip() or "FALSE"
                elif made is not None:
                    text = self.fresh(f"Transition{e.local_id}")
                    self.transitions.append(SfcNamedTransition(name=text, language=made[0], body=made[1]))  # type: ignore[arg-type]  # IL, LD or FBD
            else:
                drawn = self.drawn_condition(self.r.child(condition, "connectionPointIn"), e.local_id, condition)
                text = drawn if drawn is not None else "FALSE"
            if condition.get("negated") == "true":
                text = f"NOT ({text})"
        return SfcTransition(id=f"t{e.local_id}", condition=text, priority=int(priority) if priority else None)

    def drawn_condition(self, point: ET.Element | None, transition: int, where: ET.Element) -> str | None:
        """A condition drawn in the chart (connectionPointIn): LD contacts from the left rail (in series: AND, joined:
        OR; negated: NOT), a variable, or AND/OR/XOR/NOT blocks of those, as one ST expression; else reported."""
        try:
            return self._wired(self._sources(point), set())
        except _NotDrawable as error:
            self.report(f"transition {transition}: its condition drawn in the chart {error}; FALSE is used", where)
            return None

    def _sources(self, point: ET.Element | None) -> list[int]:
        out = []
        for connection in self.r.children(point, "connection"):
            ref = connection.get("refLocalId", "")
            if not ref.isdigit():
                raise _NotDrawable("has a connection without refLocalId")
            out.append(int(ref))
        if not out:
            raise _NotDrawable("is connected to nothing")
        return out

    def _wired(self, sources: list[int], seen: set[int]) -> str:
        terms = [self._drawn(source, seen) for source in sources]
        return terms[0] if len(terms) == 1 else "(" + " OR ".join(terms) + ")"

    def _drawn(self, local_id: int, seen: set[int]) -> str:
        if local_id in seen:
            raise _NotDrawable("is a loop")
        node = self.drawing.get(local_id)
        if node is None:
            raise _NotDrawable(f"names element {local_id}, which is not in the chart")
        tag = local(node)
        if tag == "leftPowerRail":
            return "TRUE"
        if tag == "inVariable":
            text = (
                (self.r.child(node, "expression").text or "").strip()
                if self.r.child(node, "expression") is not None
                else ""
            )
            return f"NOT {text}" if node.get("negated") == "true" else text
        if tag == "contact":
            if node.get("edge") not in (None, "none"):
                raise _NotDrawable("uses an edge contact, which a condition drawn in the chart cannot import")
            variable = (
                (self.r.child(node, "variable").text or "").strip()
                if self.r.child(node, "variable") is not None
                else ""
            )
            term = f"NOT {variable}" if node.get("negated") == "true" else variable
            before = self._wired(self._sources(self.r.child(node, "connectionPointIn")), seen | {local_id})
            return term if before == "TRUE" else f"{before} AND {term}"
        if tag == "block" and node.get("typeName", "").upper() in ("AND", "OR", "XOR", "NOT"):
            operator = node.get("typeName", "").upper()
            inputs = self.r.children(self.r.child(node, "inputVariables"), "variable")
            parts = [
                self._wired(self._sources(self.r.child(v, "connectionPointIn")), seen | {local_id}) for v in inputs
            ]
            if operator == "NOT" and len(parts) == 1:
                return f"NOT ({parts[0]})"
            if operator != "NOT" and parts:
                return "(" + f" {operator} ".join(parts) + ")"
        if tag == "block" and node.get("instanceName"):
            raise _NotDrawable(
                f"calls the function block {node.get('instanceName')} ({node.get('typeName')}): a transition "
                "condition calls no FB instance (SFC-03); call it in an action and read its output"
            )
        raise _NotDrawable(f"uses a <{tag}>, which a condition drawn in the chart cannot import")

    def fresh(self, stem: str) -> str:
        name, number = stem, 1
        while name.upper() in self.names:
            number += 1
            name = f"{stem}_{number}"
        self.names.add(name.upper())
        return name
