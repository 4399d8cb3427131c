"""``ladderlab run --record`` and ``ladderlab replay`` (issue 23 item 5): a recorded run replays row for row,
``--seek N`` ends at scan N, another revision of the project is refused, bad files are clear errors."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from ladderlab.cli import main
from tests.support import EXAMPLES

TANK = EXAMPLES / "tank_filling"


def _out(capsys, *args: str) -> tuple[int, str, str]:
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_a_recorded_run_replays_row_for_row_and_seeks(capsys, tmp_path: Path):
    """A pump filling a tank (a plant), Auto pressed at scan 3, a noisy level sensor from scan 40, 120 scans: the
    replay prints exactly the run's rows, in both formats; --seek 57 prints scans 0..57."""
    project = tmp_path / "tank"
    shutil.copytree(TANK, project)
    recording = tmp_path / "run.rec"
    run = ["run", str(project), "--cycles", "120", "--set", "Auto=TRUE@3", "--fault", "Tank.Level=noisy@40"]
    watch = ["--watch", "Tank.Level", "--watch", "Pump", "--watch", "LSH"]
    code, live, _ = _out(capsys, *run, "--seed", "11", *watch, "--record", str(recording))
    assert code == 0 and len(live.splitlines()) == 121  # header and 120 rows
    data = json.loads(recording.read_text())
    assert (data["format"], data["version"], data["scans"], data["project"]) == (
        "ladderlab-recording",
        1,
        120,
        str(project.resolve()),
    )
    assert [(line["scan"], line["kind"]) for line in data["inputs"]] == [(3, "write"), (40, "fault")]
    assert data["inputs"][1]["seed"] == 11

    code, again, _ = _out(capsys, "replay", str(recording))
    assert code == 0 and again == live
    code, rows, _ = _out(capsys, "replay", str(recording), "--format", "jsonl")
    _, live_rows, _ = _out(capsys, *run, "--seed", "11", *watch, "--format", "jsonl")
    assert rows == live_rows
    code, seeked, _ = _out(capsys, "replay", str(recording), "--seek", "57", "--format", "jsonl")
    assert seeked.splitlines() == live_rows.splitlines()[:58]
    assert json.loads(seeked.splitlines()[-1])["scan"] == 57

    # another revision of the project is refused; the project as it was, elsewhere, is taken with --project
    moved = tmp_path / "moved"
    shutil.copytree(project, moved)
    (project / "project.json").write_text((project / "project.json").read_text().replace('"tank_filling"', '"tank2"'))
    code, _, err = _out(capsys, "replay", str(recording))
    assert code == 2 and err.startswith(f"ladderlab replay: {project} is at revision ")
    assert err.rstrip().endswith(
        f"the recording was made at revision {data['revision']}: replay it with the project as it was (--project)"
    )
    code, from_copy, _ = _out(capsys, "replay", str(recording), "--project", str(moved))
    assert code == 0 and from_copy == live


def test_bad_recordings_and_seeks_are_clear_errors(capsys, tmp_path: Path):
    recording = tmp_path / "r.rec"
    cases = {
        "not json": "not a recording (not JSON text:",
        '{"format": "other"}': "not a recording of ladderlab run --record",
        '{"format": "ladderlab-recording", "version": 9}': "a recording of format version 9; this ladderlab reads 1",
        '{"format": "ladderlab-recording", "version": 1, "project": "x", "revision": "r", "scans": 2}': (
            "the recording's inputs is missing or not a list"
        ),
    }
    for text, message in cases.items():
        recording.write_text(text)
        code, _, err = _out(capsys, "replay", str(recording))
        assert code == 2 and err.startswith(f"ladderlab replay: {recording}: {message}"), (text, err)
    code, _, err = _out(capsys, "replay", str(tmp_path / "none.rec"))
    assert code == 2 and err.strip() == f"ladderlab replay: {tmp_path / 'none.rec'}: no such file"
    code, _, _ = _out(capsys, "run", str(TANK), "--cycles", "5", "--record", str(recording))
    code, _, err = _out(capsys, "replay", str(recording), "--seek", "5")
    assert code == 2 and err.strip() == "ladderlab replay: --seek 5: the recording has scans 0 to 4"
