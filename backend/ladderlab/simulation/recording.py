"""Recordings of a run (issue 23): ``ladderlab run --record FILE``, or an online session's "Download
recording", keep what makes the run what it was, so ``ladderlab replay FILE`` prints the same rows on any
machine and a recording attached to a bug report reproduces the bug.

A run is the project and the inputs applied to it, scan by scan: the clock is virtual and every input
(``--set``, ``--fault``, ``--events``) enters through the engine's one input path, which reports each
applied input with its scan (docs/architecture.md, "Inputs" and "Scan history"). So the file holds the
project's path and revision (a content hash: the replay refuses another revision), the number of scans,
the watched paths, and the applied inputs as ``--events`` lines; JSON, with its format name and version.
No checkpoint is needed: a replay from scan 0 is exact, and a CLI run is short.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from .events import Scheduled, events_text, parse_events

FORMAT = "ladderlab-recording"
VERSION = 1


@dataclass(frozen=True)
class Recording:
    project: str  # the project's path as given to run, made absolute
    revision: str
    scans: int
    watch: list[str] | None  # None: every variable
    inputs: list[dict[str, object]]  # AppliedInput.to_json() lines, in the order they applied

    def to_bytes(self) -> bytes:
        data = {
            "format": FORMAT,
            "version": VERSION,
            "project": self.project,
            "revision": self.revision,
            "scans": self.scans,
            "watch": self.watch,
            "inputs": self.inputs,
        }
        return (json.dumps(data, separators=(",", ":")) + "\n").encode()

    def events_text(self) -> str:
        """The inputs as the lines of an ``--events`` file."""
        return events_text(self.inputs)

    def scheduled(self, name: str) -> list[Scheduled]:
        """The inputs, each with the scan it applies before (ValueError naming ``name``'s inputs and the line)."""
        return parse_events(self.events_text(), f"{name} inputs")


def read_recording(path: Path) -> Recording:
    """The recording in ``path``; ValueError in the user's words when it is not one this version reads."""
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise ValueError(f"{path}: no such file") from None
    return parse_recording(data, str(path))


def parse_recording(data: bytes, name: str) -> Recording:
    """The recording in ``data`` (a file called ``name`` in the messages): ValueError in the user's words when it
    is not one this version reads. The CLI reads files, the server uploads (the browser's "Open recording")."""
    try:
        document = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as error:
        raise ValueError(f"{name}: not a recording (not JSON text: {error})") from None
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise ValueError(f"{name}: not a recording of ladderlab run --record or of a simulation's download")
    if document.get("version") != VERSION:
        raise ValueError(
            f"{name}: a recording of format version {document.get('version')!r}; this ladderlab reads {VERSION}"
        )
    fields = {"project": str, "revision": str, "scans": int, "inputs": list}
    for field, kind in fields.items():
        if not isinstance(document.get(field), kind):
            raise ValueError(f"{name}: the recording's {field} is missing or not a {kind.__name__}")
    watch = document.get("watch")
    if watch is not None and not (isinstance(watch, list) and all(isinstance(p, str) for p in watch)):
        raise ValueError(f"{name}: the recording's watch is not a list of paths")
    if document["scans"] < 0:
        raise ValueError(f"{name}: the recording's scans is negative")
    recording = Recording(document["project"], document["revision"], document["scans"], watch, document["inputs"])
    recording.scheduled(name)  # the inputs are checked here, so a bad line is reported before anything runs
    return recording
