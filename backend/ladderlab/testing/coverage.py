"""Coverage placeholder (filled below)."""

from __future__ import annotations


class Coverage:
    def collect(self, sim) -> None:
        pass
