"""Validation shared by the LD and FBD lowerings: element ids, network labels and jump targets.

Both languages locate problems the same way (POU, network, element, pin) and
follow the same label rules (GR-03, GR-09): a label is an identifier or an
unsigned integer, unique in its POU, and jumps name labels of the same POU.
Element ids are the probe ids of live power flow, so they must be unique too.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Protocol

from ..iec.spelling import did_you_mean

_LABEL = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*|[0-9]+)\Z")


class Report(Protocol):
    """``report(code, message, network=..., element=..., pin=..., severity=...)``: ``PouContext.report``'s shape."""

    def __call__(
        self,
        code: str,
        message: str,
        *,
        network: str | None = None,
        element: str | None = None,
        pin: str | None = None,
        severity: str = "error",
    ) -> None: ...


def canonical_label(label: str) -> str:
    """Labels are compared and stored upper case (IR convention); integer labels stay as written."""
    return label.strip().upper()


def check_labels(networks: Iterable[object], report: Report, lang: str) -> dict[str, str]:
    """Report malformed and duplicate labels; return {canonical label: network id} of the usable ones."""
    labels: dict[str, str] = {}
    numbers: dict[str, int] = {}
    for number, network in enumerate(networks, 1):
        label = getattr(network, "label", None)
        if label is None:
            continue
        if not _LABEL.match(label.strip()):
            report(
                f"{lang}-BAD-LABEL",
                f"network label '{label}' must be an identifier or an unsigned integer",
                network=network.id,
            )
            continue
        key = canonical_label(label)
        if key in labels:
            report(
                f"{lang}-DUPLICATE-LABEL",
                f"label '{label}' is already used by network {numbers[key]}",
                network=network.id,
            )
            continue
        labels[key], numbers[key] = network.id, number
    return labels


def check_jump_target(
    target: str, labels: dict[str, str], report: Report, lang: str, *, network: str, element: str
) -> str | None:
    """The canonical label a jump goes to, or None (reported) when no network of the POU has it."""
    key = canonical_label(target)
    if key in labels:
        return key
    report(
        f"{lang}-UNKNOWN-LABEL",
        f"jump to '{target}', but no network of this POU has that label" + did_you_mean(target, labels),
        network=network,
        element=element,
    )
    return None


def check_unique_ids(elements: Iterable[tuple[int, str, str]], report: Report, lang: str) -> None:
    """``elements`` are (network number, network id, element id); a repeated element id would merge two probes."""
    seen: dict[str, int] = {}
    for number, network, element in elements:
        if element in seen:
            report(
                f"{lang}-DUPLICATE-ID",
                f"an element of network {seen[element]} has the same id '{element}': element ids must be unique "
                "in the POU (was the file edited by hand?)",
                network=network,
                element=element,
            )
        else:
            seen[element] = number


def check_unique_networks(networks: Iterable[object], report: Report, lang: str) -> None:
    seen: set[str] = set()
    for network in networks:
        if network.id in seen:
            report(
                f"{lang}-DUPLICATE-ID",
                f"an earlier network has the same id '{network.id}': network ids must be unique in the POU",
                network=network.id,
            )
        seen.add(network.id)
