"""``ladderlab run``: scan a project on the virtual clock, apply inputs, report watched values per scan.

Inputs come as ``--set`` writes, ``--fault`` injections and ``--events`` files (one input event per
line, as the server's ``GET /api/simulations/{id}/inputs`` gives them: a panel session replays
here scan for scan). Every one goes through ``Simulation.submit`` before the scan it names.
Kept apart from the CLI's argument parsing so the rules (what ``PATH=VALUE@SCAN`` means, when a
scan counts as inside ``--for``, how values print) are testable alone.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from ..engine.inputs import InputEvent
from ..engine.simulation import Simulation
from ..iec.literals import decode_duration, decode_string
from ..ir.types import Elementary
from ..model.faults import FAULT_MODES
from ..simulation.conditions import Condition
from ..simulation.events import Scheduled, scan_inputs

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


def parse_fault(text: str, seed: int) -> Scheduled:
    """``PATH=MODE[@SCAN]`` (stuck_true, stuck_false, open, noisy; ``stuck:VALUE``); a noisy one gets ``seed``."""
    path, sep, rest = text.partition("=")
    head, at, tail = rest.rpartition("@")
    mode, scan = (head, int(tail)) if at and tail.strip().isdigit() else (rest, 0)
    mode, _, value = mode.strip().partition(":")
    if not sep or not path.strip() or mode not in FAULT_MODES or (mode == "stuck") != bool(value):
        raise ValueError(
            f"--fault {text!r}: expected PATH=MODE[@SCAN] with MODE one of stuck_true, stuck_false, open, noisy, "
            "or stuck:VALUE"
        )
    event = InputEvent(
        "fault",
        path.strip(),
        value.strip() or None,
        mode=mode,
        seed=seed if mode == "noisy" else None,
    )
    return Scheduled(scan, event)


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
    sim: Simulation,
    *,
    watch: list[str],
    sets: Sequence[SetAction] = (),
    events: Sequence[Scheduled] = (),
    cycles: int | None = None,
    for_ms: float | None = None,
    until: Condition | None = None,
) -> Iterator[Row]:
    """Yield a Row after every scan; stops early after a scan that faulted (``sim.fault`` says why) or after
    which ``until`` holds.

    ``cycles`` scans, or every scan due within ``for_ms`` of virtual time. The inputs of a scan (``sets``
    first, then ``events`` in file order) are submitted just before it. Paths are resolved before the
    first scan, so a typo fails before anything runs.
    """
    for path in watch:
        sim.location(path)
    writes = [Scheduled(s.scan, InputEvent("write", s.path, _typed_text(sim, s), source="cli")) for s in sets]
    for scan in scan_inputs(sim, [*writes, *events], cycles=cycles, for_ms=for_ms):
        yield Row(scan, sim.time_ms, {path: sim.read(path, enum_literals=True) for path in watch})
        if sim.fault is not None or (until is not None and until.holds(sim)):
            return


def _typed_text(sim: Simulation, action: SetAction) -> str:
    """A quoted STRING literal (``'on'``) is decoded; other text goes to the engine's IEC literal parser."""
    ty = sim.location(action.path).type
    quoted = len(action.value) >= 2 and action.value[0] == action.value[-1] and action.value[0] in "'\""
    if quoted and isinstance(ty, Elementary) and ty.info.category == "string":
        return decode_string(action.value)
    return action.value


def json_value(value: object) -> object:
    """Values as JSON: BOOL true/false, numbers, TIME/DATE as ms, strings, enumerations as their literals
    (``"TCOLOR#Red"``: ``run_scans`` reads them so); NaN/inf as their IEC-ish names."""
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
