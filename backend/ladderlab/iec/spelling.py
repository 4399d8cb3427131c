"""Suggestions for misspelt names in diagnostics (checker, lowering, engine paths share one rule)."""

from __future__ import annotations

import difflib
from typing import Any


def did_you_mean(name: str, candidates: Any) -> str:
    """`` - did you mean 'Start'?`` for the closest candidate (case-insensitive), or ''."""
    by_upper = {c.upper(): c for c in candidates}
    match = difflib.get_close_matches(name.upper(), list(by_upper), n=1, cutoff=0.6)
    return f" - did you mean '{by_upper[match[0]]}'?" if match else ""
