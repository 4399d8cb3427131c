"""Input events as lines of JSON, each with the scan it applies before: what ``GET .../inputs`` gives, what
``ladderlab run --events`` reads and what a recording holds (recording.py). Parsed here, below the CLI and the
server, so both read them with the same rules and the same located errors."""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the engine: imported where events are parsed or run (the server starts without it: issue 27)
    from ..engine.inputs import InputEvent
    from ..engine.simulation import Simulation


@dataclass(frozen=True)
class Scheduled:
    """An input event to submit just before scan number ``scan``."""

    scan: int
    event: InputEvent


def parse_events(text: str, name: str) -> list[Scheduled]:
    """The events of a JSON-lines file (blank lines skipped); ValueError naming the file and line."""
    from ..engine.inputs import InputEvent, InputRefused

    found = []
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        where = f"{name}:{number}"
        try:
            data = json.loads(line)
        except ValueError as error:
            raise ValueError(f"{where}: not JSON: {error}") from None
        if not isinstance(data, dict):
            raise ValueError(f"{where}: an event is a JSON object such as {EVENT_EXAMPLE}")
        scan = data.get("scan")
        if not isinstance(scan, int) or isinstance(scan, bool) or scan < 0:
            raise ValueError(f"{where}: scan must be the number of the scan it applies before (0 for the first)")
        if data.get("phase", "start") != "start":
            raise ValueError(
                f"{where}: this event was applied while scan {scan} was halted at a breakpoint; "
                "ladderlab run replays events at the start of scans only"
            )
        try:
            found.append(Scheduled(scan, InputEvent.from_json(data)))
        except (InputRefused, TypeError) as error:
            raise ValueError(f"{where}: {error}") from None
    return sorted(found, key=lambda scheduled: scheduled.scan)


EVENT_EXAMPLE = '{"scan": 3, "kind": "panel", "path": "Start", "value": true}'


def events_text(lines: Sequence[dict[str, object]]) -> str:
    """Input events (``AppliedInput.to_json()`` lines) as the text of an ``--events`` file."""
    return "".join(json.dumps(line) + "\n" for line in lines)


def scan_inputs(
    sim: Simulation, inputs: Sequence[Scheduled], cycles: int | None = None, for_ms: float | None = None
) -> Iterator[int]:
    """Scan ``sim`` from its scan 0, submitting each input just before the scan it names (in the order given
    within a scan), and yield each scan's number once it ran: ``cycles`` scans, or every scan due within
    ``for_ms`` of virtual time. ``ladderlab run``/``replay`` and an opened recording (runner.py) scan this way,
    so a recording replays alike on the command line and in the browser."""
    pending = sorted(inputs, key=lambda scheduled: scheduled.scan)  # stable: a scan's inputs keep their order
    scan = 0
    while (scan < cycles) if cycles is not None else (sim.next_scan_time() <= (for_ms or 0.0)):
        while pending and pending[0].scan <= scan:
            sim.submit(pending.pop(0).event)
        sim.cycle(1)
        yield scan
        scan += 1
