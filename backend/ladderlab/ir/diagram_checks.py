"""Validation shared by the LD, FBD and CFC lowerings: element ids, network and chart labels, jump targets.

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


def check_chart_labels(labels: Iterable[tuple[str, str]], report: Report, *, network: str) -> dict[str, str]:
    """A CFC chart's label elements, (element id, name) in the chart's order: report malformed and duplicate
    names (GR-03's rule for network labels); return {canonical label: element id} of the usable ones."""
    found: dict[str, str] = {}
    for element, name in labels:
        if not _LABEL.match(name.strip()):
            report(
                "FBD-BAD-LABEL",
                f"label '{name}' must be an identifier or an unsigned integer",
                network=network,
                element=element,
            )
        elif canonical_label(name) in found:
            report("FBD-DUPLICATE-LABEL", f"label '{name}' is on the chart twice", network=network, element=element)
        else:
            found[canonical_label(name)] = element
    return found


def check_jump_target(
    target: str,
    labels: dict[str, str],
    report: Report,
    lang: str,
    *,
    network: str,
    element: str,
    holder: str = "no network of this POU has",
) -> str | None:
    """The canonical label a jump goes to, or None (reported) when no network of the POU (``holder``: the
    chart) has it."""
    key = canonical_label(target)
    if key in labels:
        return key
    report(
        f"{lang}-UNKNOWN-LABEL",
        f"jump to '{target}', but {holder} that label" + did_you_mean(target, labels),
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
