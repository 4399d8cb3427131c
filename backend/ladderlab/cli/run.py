"""``ladderlab run``: scan a project on the virtual clock, apply ``--set``s, report watched values per scan.

Kept apart from the CLI's argument parsing so the rules (what ``PATH=VALUE@SCAN``
means, when a scan counts as inside ``--for``, how values print) are testable alone.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from dataclasses import dataclass

from ..engine.simulation import Simulation
from ..iec.literals import decode_duration, decode_string
from ..ir.types import Elementary

_DURATION = re.compile(r"(?:T|TIME)?#?((?:\d+(?:\.\d+)?(?:d|h|ms|m|s|us|ns)_?)+)", re.IGNORECASE)


@dataclass(frozen=True)
class SetAction:
    """Write ``value`` (IEC literal text) to ``path`` just before scan number ``scan`` (0 = the first)."""

    path: str
    value: str
    scan: int = 0


def parse_set(text: str) -> SetAction:
    """``PATH=VALUE[@SCAN]``; the ``@SCAN`` suffix is taken only when it is a number, so ``'a@b'`` strings work."""
    path, sep, value = text.partition("=")
    if not sep or not path.strip() or not value.strip():
        raise ValueError(f"--set {text!r}: expected PATH=VALUE or PATH=VALUE@SCAN")
    scan = 0
    head, at, tail = value.rpartition("@")
    if at and tail.strip().isdigit():
        value, scan = head, int(tail)
    return SetAction(path.strip(), value.strip(), scan)


def parse_duration(text: str) -> float:
    """``2s``, ``1m30s``, ``500ms``, ``T#2s`` -> milliseconds."""
    match = _DURATION.fullmatch(text.strip())
    if match is None:
        raise ValueError(f"--for {text!r}: expected a duration such as 2s, 500ms, 1m30s or T#2s")
    return float(decode_duration("T#" + match.group(1)))


@dataclass
class Row:
    """One scan's report: ``scan`` (0 for the first), ``time_ms`` at its end, the watched values by path as given."""

    scan: int
    time_ms: float
    values: dict[str, object]


def run_scans(
    sim: Simulation, *, watch: list[str], sets: list[SetAction], cycles: int | None = None, for_ms: float | None = None
) -> Iterator[Row]:
    """Yield a Row after every scan; stops early after a scan that faulted (``sim.fault`` says why).

    ``cycles`` scans, or every scan due within ``for_ms`` of virtual time. Paths are
    resolved before the first scan, so a typo fails before anything runs.
    """
    for path in watch:
        sim.location(path)
    pending = sorted(sets, key=lambda s: s.scan)
    scan = 0
    while (scan < cycles) if cycles is not None else (sim.next_scan_time() <= (for_ms or 0.0)):
        while pending and pending[0].scan <= scan:
            action = pending.pop(0)
            sim.write(action.path, _typed_text(sim, action))
        sim.cycle(1)
        yield Row(scan, sim.time_ms, {path: sim.read(path) for path in watch})
        if sim.fault is not None:
            return
        scan += 1


def _typed_text(sim: Simulation, action: SetAction) -> str:
    """A quoted STRING literal (``'on'``) is decoded; other text goes to the engine's IEC literal parser."""
    ty = sim.location(action.path).type
    quoted = len(action.value) >= 2 and action.value[0] == action.value[-1] and action.value[0] in "'\""
    if quoted and isinstance(ty, Elementary) and ty.info.category == "string":
        return decode_string(action.value)
    return action.value


def json_value(value: object) -> object:
    """Values as JSON: BOOL true/false, numbers, TIME/DATE as ms, strings; NaN/inf as their IEC-ish names."""
    if isinstance(value, float) and not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, list):
        return [json_value(v) for v in value]
    if isinstance(value, dict):
        return {k: json_value(v) for k, v in value.items()}
    return value


def jsonl_line(row: Row) -> str:
    return json.dumps(
        {"scan": row.scan, "time_ms": _number(row.time_ms), **{path: json_value(v) for path, v in row.values.items()}}
    )


def table_lines(rows: Iterator[Row], watch: list[str]) -> Iterator[str]:
    """A header, then one aligned line per scan (column width from the header and the first row)."""
    header = ["scan", "time_ms", *watch]
    widths: list[int] | None = None
    for row in rows:
        cells = [str(row.scan), str(_number(row.time_ms)), *(json.dumps(json_value(row.values[p])) for p in watch)]
        if widths is None:
            widths = [max(len(h), len(c)) for h, c in zip(header, cells)]
            yield "  ".join(h.ljust(w) for h, w in zip(header, widths)).rstrip()
        yield "  ".join(c.ljust(w) for c, w in zip(cells, widths)).rstrip()


def _number(ms: float) -> int | float:
    return int(ms) if float(ms).is_integer() else ms
