"""The faults a lab bench user or a test injects into a signal (docs/hmi.md, "Faults"; docs/testing.md), and
which signals each acts on: one rule for the browser's requests, the engine and the test-file checker."""

from __future__ import annotations

from typing import Literal, get_args

FaultMode = Literal["stuck_true", "stuck_false", "stuck", "open", "noisy"]
FAULT_MODES: tuple[str, ...] = get_args(FaultMode)
#: What a fault acts on: a BOOL, an integer (ANY_INT, ANY_BIT but BOOL, subranges) or a real signal.
SignalKind = Literal["bool", "int", "real"]


def signal_kind(category: str) -> SignalKind | None:
    """The kind of signal an elementary type of ``category`` (iec/elementary.py) is, None for no signal."""
    if category == "bool":
        return "bool"
    if category in ("int", "bits"):
        return "int"
    return "real" if category == "real" else None


def fault_refusal(mode: str, kind: SignalKind | None, signal: str) -> str | None:
    """Why fault ``mode`` cannot act on a signal of ``kind`` (``signal`` names its type), or None when it can."""
    if kind is None:
        return f"faults act on BOOL and numeric signals, not on {signal}"
    if kind != "bool" and mode in ("stuck_true", "stuck_false"):
        return f"{mode} is for BOOL signals; hold a number with stuck and a value"
    if kind == "bool" and mode == "stuck":
        return "hold a BOOL with stuck_true or stuck_false"
    return None
