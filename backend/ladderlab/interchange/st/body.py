"""The body of an exported LD/FBD POU: networks in order, each under its comment, and the jumps between them.

Networks run top to bottom; a jump or return acts after its whole network
(GR-05 c). Where every jump goes forward and the skipped ranges nest (no two
overlap partly), and no network has more than one jump or return, the jumps
become IF structure: ``IF NOT cond THEN <skipped networks> END_IF;``. Otherwise
the body is a network-index state machine - ``CASE`` inside ``WHILE`` - where
each network sets the index of the next one (backward jumps loop, as in the
diagram; the watchdog catches endless ones). Returns are ``RETURN;``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ...st import ast
from ...st.printer import INDENT, print_statements
from .network import Declarations, Planned


@dataclass
class Network:
    """One planned network: its id, its heading (comment lines, ``network_title``), statements, and controls
    as (label | None, element)."""

    id: str
    title: list[str]
    planned: Planned
    controls: list[tuple[str | None, str]]


@dataclass
class Line:
    text: str
    network: str | None = None
    element: str | None = None


def comment(text: str) -> str:
    """``text`` as one ``(* *)`` comment that nothing inside can end early (or open a nested one)."""
    return "(* " + _inert(text) + " *)"


def _inert(text: str) -> str:
    return text.replace("(*", "( *").replace("*)", "* )")


def network_title(number: int, label: str | None, text: str | None) -> list[str]:
    """The comment over a network, as the editor shows it: ``(* Network 2 "Motor_timer": what it does *)``;
    the lines of a longer comment follow inside the same comment, indented under the first."""
    head = f"Network {number}" + (f' "{label.strip()}"' if label and label.strip() else "")
    lines = [line.strip() for line in (text or "").splitlines() if line.strip()]
    if not lines:
        return [comment(head)]
    first = f"(* {_inert(head)}: {_inert(lines[0])}"
    rest = ["   " + _inert(line) for line in lines[1:]]
    out = [first, *rest]
    out[-1] += " *)"
    return out


def body_lines(networks: list[Network], labels: dict[str, int], declarations: Declarations) -> list[Line]:
    """The body's lines; ``labels`` maps canonical labels to network indexes."""
    if _structured(networks, labels):
        return _structured_lines(networks, labels, 0, len(networks), 0)
    return _state_machine(networks, labels, declarations)


def _jumps(networks: list[Network], labels: dict[str, int]) -> list[tuple[int, int]]:
    return [
        (index, labels[label])
        for index, network in enumerate(networks)
        for label, _ in network.controls
        if label is not None
    ]


def _structured(networks: list[Network], labels: dict[str, int]) -> bool:
    if any(len(network.controls) > 1 for network in networks):
        return False
    spans = [(source, target) for source, target in _jumps(networks, labels)]
    if any(target <= source for source, target in spans):
        return False
    return not any(a < c < b < d for a, b in spans for c, d in spans)


def _statements(network: Network, level: int) -> list[Line]:
    lines = [Line(INDENT * level + text, network.id) for text in network.title]
    for element, statement in network.planned.statements:
        lines += _printed([statement], level, network.id, element)
    return lines


def _printed(statements: list[Any], level: int, network: str, element: str | None) -> list[Line]:
    return [Line(text, network, element) for text in print_statements(statements, level).splitlines()]


def _structured_lines(networks: list[Network], labels: dict[str, int], start: int, stop: int, level: int) -> list[Line]:
    """Networks ``start`` .. ``stop - 1``; a forward jump wraps the networks it skips in ``IF NOT cond``."""
    lines: list[Line] = []
    index = start
    while index < stop:
        network = networks[index]
        lines += _statements(network, level)
        index += 1
        if not network.controls:
            continue
        (label, element), condition = network.controls[0], network.planned.conditions[0]
        if label is None:
            statement = ast.Return() if condition is None else ast.If([(condition, [ast.Return()])])
            lines += _printed([statement], level, network.id, element)
            continue
        target = labels[label]
        if target == index:
            continue  # to the next network: nothing is skipped
        if condition is None:  # always taken: the networks in between never run
            skipped = [str(n + 1) for n in range(index, target)]
            what = (
                f"Network {skipped[0]} never runs" if len(skipped) == 1 else f"Networks {', '.join(skipped)} never run"
            )
            lines += [
                Line(
                    INDENT * level
                    + comment(
                        f"{what}: the jump in network {index} always skips {'it' if len(skipped) == 1 else 'them'}"
                    ),
                    network.id,
                    element,
                )
            ]
        else:
            lines += _printed_header(ast.Unary("NOT", condition), level, network.id, element)
            lines += _structured_lines(networks, labels, index, target, level + 1)
            lines.append(Line(INDENT * level + "END_IF;", network.id, element))
        index = target
    return lines


def _printed_header(condition: Any, level: int, network: str, element: str) -> list[Line]:
    """The ``IF cond THEN`` line of a statement printed by the printer (so parentheses follow ST-02)."""
    text = print_statements([ast.If([(condition, [ast.Empty()])])], level).splitlines()
    return [Line(text[0], network, element)]


def _state_machine(networks: list[Network], labels: dict[str, int], declarations: Declarations) -> list[Line]:
    """``WHILE next < n DO CASE next OF i: <network i> next := ...; END_CASE; END_WHILE;``"""
    state = declarations.declare("next_network", "INT" if len(networks) < 32000 else "DINT")
    name = ast.Name(state)
    lines = [Line(f"{state} := 0;"), Line(f"WHILE {state} < {len(networks)} DO"), Line(f"{INDENT}CASE {state} OF")]
    for index, network in enumerate(networks):
        lines.append(Line(f"{INDENT * 2}{index}:", network.id))
        lines += _statements(network, 3)
        following = ast.Assign(name, ast.IntLit(index + 1))
        branches: list[tuple[Any, list[Any]]] = []
        final: list[Any] | None = [following]
        for (label, _), condition in zip(network.controls, network.planned.conditions):
            act = [ast.Return()] if label is None else [ast.Assign(name, ast.IntLit(labels[label]))]
            if condition is None:
                final = act
                break
            branches.append((condition, act))
        element = network.controls[0][1] if network.controls else None
        statement = ast.If(branches, final) if branches else None
        lines += _printed([statement] if statement is not None else final, 3, network.id, element)
    lines += [Line(f"{INDENT}END_CASE;"), Line("END_WHILE;")]
    return lines
