"""Where something is in an LD or FBD body, in the words of the user who drew it.

Diagnostics keep the machine location (network, element and pin ids) for click-to-reveal; people read
``network 2 "Motor timer", TON RunTimer.PT``: the network by its number and label, an element by what
is written on it (operand, instance, call; a CFC chart is "chart") and a box's pin after a dot - never an internal id
(issue 22, "Messages in the user's words").
"""

from __future__ import annotations

from . import fbd, ld
from .cfc import CfcBody

_COIL_WORDS = {"normal": "", "negated": "negated ", "set": "set ", "reset": "reset ", "p": "P ", "n": "N "}
_CONTACT_WORDS = {"no": "", "nc": "NC ", "p": "P ", "n": "N "}
_COMPARE_SIGNS = {"GT": ">", "GE": ">=", "EQ": "=", "LE": "<=", "LT": "<", "NE": "<>"}


def _operand(text: str) -> str:
    return text.strip() or "(no operand)"


def _ordinal(number: int) -> str:
    suffix = "th" if 10 <= number % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(number % 10, "th")
    return f"{number}{suffix}"


def network_name(number: int, label: str | None) -> str:
    """``network 2 "Motor timer"`` (1-based number; the label when it has one)."""
    return f'network {number} "{label}"' if label else f"network {number}"


def _calls(calls: list[tuple[str, str | None, str]]) -> dict[str, str]:
    """Element id -> the name of a box or block: ``TON RunTimer`` by its instance, else ``ADD`` (``the 2nd ADD`` when
    the network has several without an instance, counted in the order given)."""
    counts: dict[str, int] = {}
    for _, instance, call in calls:
        if not (instance or "").strip():
            counts[call.upper()] = counts.get(call.upper(), 0) + 1
    names, seen = {}, dict.fromkeys(counts, 0)
    for element_id, instance, call in calls:
        if instance and instance.strip():
            names[element_id] = f"{call.strip()} {instance.strip()}"
        elif counts[call.upper()] > 1:
            seen[call.upper()] += 1
            names[element_id] = f"the {_ordinal(seen[call.upper()])} {call.strip()}"
        else:
            names[element_id] = call.strip() or "(box without a call)"
    return names


def _ld_names(network: ld.LdNetwork) -> dict[str, tuple[str, bool]]:
    """Element id -> (name, whether its pins are named after it)."""
    names: dict[str, tuple[str, bool]] = {}
    boxes: list[tuple[str, str | None, str]] = []
    for element in ld.walk(network.elements):
        if isinstance(element, ld.Contact):
            names[element.id] = (f"{_CONTACT_WORDS[element.mode]}contact {_operand(element.var)}", False)
        elif isinstance(element, ld.Coil):
            names[element.id] = (f"{_COIL_WORDS[element.mode]}coil {_operand(element.var)}", False)
        elif isinstance(element, ld.Compare):
            sign = _COMPARE_SIGNS[element.op]
            names[element.id] = (f"comparison {_operand(element.left)} {sign} {_operand(element.right)}", False)
        elif isinstance(element, ld.Box):
            boxes.append((element.id, element.instance, element.call))
        elif isinstance(element, ld.Jump):
            names[element.id] = (f"jump to {element.target}", False)
        elif isinstance(element, ld.Return):
            names[element.id] = ("RETURN", False)
        else:
            names[element.id] = ("parallel branch", False)
    names.update({element_id: (name, True) for element_id, name in _calls(boxes).items()})
    return names


def _fbd_names(network: fbd.FbdNetwork) -> dict[str, tuple[str, bool]]:
    names: dict[str, tuple[str, bool]] = {}
    blocks = [node for node in network.nodes if isinstance(node, fbd.Block)]
    blocks.sort(key=lambda b: (b.pos.y, b.pos.x) if b.pos else (float("inf"), float("inf")))
    for node in network.nodes:
        if isinstance(node, fbd.InputNode):
            names[node.id] = (f"input {_operand(node.expr)}", False)
        elif isinstance(node, fbd.OutputNode):
            names[node.id] = (f"{_COIL_WORDS[node.mode]}output {_operand(node.var)}", False)
        elif isinstance(node, fbd.FbdJump):
            names[node.id] = (f"jump to {node.target}", False)
        elif isinstance(node, fbd.FbdReturn):
            names[node.id] = ("RETURN", False)
        elif isinstance(node, fbd.FbdLabel):
            names[node.id] = (f"label {node.name}", False)
        elif isinstance(node, fbd.Connector):
            names[node.id] = (f"connector {node.name}", False)
        elif isinstance(node, fbd.Continuation):
            names[node.id] = (f"continuation {node.name}", False)
    calls = _calls([(b.id, b.instance, b.call) for b in blocks])
    names.update({element_id: (name, True) for element_id, name in calls.items()})
    return names


class NetworkNames:
    """The names of one network's elements (built on first use: only problems ask for them)."""

    def __init__(self, network: ld.LdNetwork | fbd.FbdNetwork) -> None:
        self.network = network
        self._names: dict[str, tuple[str, bool]] | None = None

    def get(self, element_id: str, pin: str | None = None) -> str | None:
        """``TON RunTimer.PT``, ``contact Start``, ``input T#5s``; None for an id the network does not hold."""
        if self._names is None:
            network = self.network
            self._names = _ld_names(network) if isinstance(network, ld.LdNetwork) else _fbd_names(network)
        entry = self._names.get(element_id)
        if entry is None:
            return None
        name, has_pins = entry
        return f"{name}.{pin}" if pin and has_pins else name

    def __call__(self, element_id: str, pin: str | None = None) -> str:
        """As ``get``; an id the network does not hold is quoted (a file edited by hand may name one)."""
        return self.get(element_id, pin) or f"'{element_id}'"


class Places:
    """Names the networks, elements and pins of one LD or FBD body."""

    def __init__(self, body: ld.LdBody | fbd.FbdBody) -> None:
        self.body = body
        self._networks: dict[str, tuple[str, NetworkNames]] | None = None

    def where(self, network_id: str, element_id: str | None = None, pin: str | None = None) -> str | None:
        """``network 2 "Motor timer", TON RunTimer.PT`` (as much as is known), or None for an unknown network."""
        if self._networks is None:
            self._networks = {}
            networks: list[ld.LdNetwork | fbd.FbdNetwork] = list(self.body.networks)
            for number, network in enumerate(networks, 1):
                name = "chart" if isinstance(self.body, CfcBody) else network_name(number, network.label)
                if network.id in self._networks:  # a file edited by hand: say which networks share the id
                    name = f"{self._networks[network.id][0]} or {name} (the same id '{network.id}')"
                self._networks[network.id] = (name, NetworkNames(network))
        found = self._networks.get(network_id)
        if found is None:
            return None
        name, names = found
        element = names.get(element_id, pin) if element_id is not None else None
        return f"{name}, {element}" if element else name


class ProjectPlaces:
    """``Places`` of every LD and FBD POU of a project, by upper-case POU name (runtime faults name elements too)."""

    def __init__(self, pous: list[tuple[str, ld.LdBody | fbd.FbdBody]]) -> None:
        self._bodies = {name.upper(): body for name, body in pous}
        self._places: dict[str, Places] = {}

    def where(self, pou: str, network_id: str, element_id: str | None = None, pin: str | None = None) -> str | None:
        key = pou.upper()
        places = self._places.get(key)
        if places is None:
            body = self._bodies.get(key)
            if body is None:
                return None
            places = self._places[key] = Places(body)
        return places.where(network_id, element_id, pin)
