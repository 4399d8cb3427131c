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
        return "".join(json.dumps(line) + "\n" for line in self.inputs)


def read_recording(path: Path) -> Recording:
    """The recording in ``path``; ValueError in the user's words when it is not one this version reads."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ValueError(f"{path}: no such file") from None
    except (UnicodeDecodeError, ValueError) as error:
        raise ValueError(f"{path}: not a recording (not JSON text: {error})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise ValueError(f"{path}: not a recording of ladderlab run --record")
    if data.get("version") != VERSION:
        raise ValueError(
            f"{path}: a recording of format version {data.get('version')!r}; this ladderlab reads {VERSION}"
        )
    fields = {"project": str, "revision": str, "scans": int, "inputs": list}
    for name, kind in fields.items():
        if not isinstance(data.get(name), kind):
            raise ValueError(f"{path}: the recording's {name} is missing or not a {kind.__name__}")
    watch = data.get("watch")
    if watch is not None and not (isinstance(watch, list) and all(isinstance(p, str) for p in watch)):
        raise ValueError(f"{path}: the recording's watch is not a list of paths")
    return Recording(data["project"], data["revision"], data["scans"], watch, data["inputs"])
