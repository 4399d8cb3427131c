"""``ladderlab run`` inputs (issue 21): --events files, --fault, --until, and exports --with-plants."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from ladderlab.cli import main
from tests.support import EXAMPLES

TANK = str(EXAMPLES / "tank_filling")


def run(capsys, *args: str) -> tuple[int, list[dict], str]:
    code = main(["run", *args, "--format", "jsonl"])
    out, err = capsys.readouterr()
    return code, [json.loads(line) for line in out.splitlines()], err


WATCH = ["--watch", "Tank.Overflow", "--watch", "LSH", "--watch", "Pump"]


def test_a_stuck_high_switch_runs_the_tank_over_until_the_condition_holds(capsys):
    until = ["--until", "Tank.Overflow", "--for", "60s", *WATCH]
    code, rows, _ = run(capsys, TANK, "--set", "Auto=TRUE", "--fault", "LSH=stuck_false@0", *until)
    assert code == 0 and rows[-1]["Tank.Overflow"] is True and rows[-1]["LSH"] is False and rows[-1]["Pump"] is True
    assert not any(row["Tank.Overflow"] for row in rows[:-1])
    # without the fault the pump stops at 80 %: the tank never runs over within the minute
    code, rows, err = run(capsys, TANK, "--set", "Auto=TRUE", *until)
    assert code == 4 and len(rows) == 6000
    assert err.strip() == "ladderlab run: Tank.Overflow did not hold within 6000 scans"


def test_a_noisy_fault_replays_the_same_with_the_same_seed(capsys):
    args = [TANK, "--fault", "Tank.Level=noisy@5", "--cycles", "50", "--watch", "Tank.Level"]
    _, first, _ = run(capsys, *args, "--seed", "7")
    _, again, _ = run(capsys, *args, "--seed", "7")
    _, other, _ = run(capsys, *args, "--seed", "8")
    assert first == again and first != other
    assert all(row["Tank.Level"] == 0.0 for row in first[:5])  # the fault acts from scan 5


def test_bad_event_files_and_options_are_located_errors(capsys, tmp_path: Path):
    cases = {
        '{"scan": 1, "kind": "melt", "path": "Auto"}': "events.jsonl:1: kind must be one of",
        '{"kind": "panel", "path": "Auto", "value": true}': "events.jsonl:1: scan must be the number of the scan",
        '{"scan": 2, "phase": "halt", "kind": "write", "path": "Auto", "value": true}': (
            "events.jsonl:1: this event was applied while scan 2 was halted at a breakpoint"
        ),
        "[1, 2]": "events.jsonl:1: an event is a JSON object",
        '{"scan": 0, "kind": "panel", "path": "Auto"}': "events.jsonl:1: a panel event needs a value",
        '{"scan": 0, "kind": "fault", "path": "LSH", "mode": "noisy"}': "events.jsonl:1: a noisy fault needs a seed",
    }
    for line, message in cases.items():
        events = tmp_path / "events.jsonl"
        events.write_text(line + "\n")
        code, _, err = run(capsys, TANK, "--events", str(events))
        assert code == 2 and err.startswith(f"ladderlab run: {events.parent}/{message}"), (line, err)
    code, _, err = run(capsys, TANK, "--fault", "LSH=broken")
    assert code == 2 and "expected PATH=MODE[@SCAN]" in err
    code, _, err = run(capsys, TANK, "--until", "Tank.Level")
    assert code == 2 and err.startswith("ladderlab run: --until 'Tank.Level': TANK.LEVEL is not a BOOL")
    code, _, err = run(capsys, TANK, "--events", str(tmp_path / "none.jsonl"))
    assert code == 2 and "no such file" in err


def test_the_st_export_keeps_plants_only_when_asked(capsys):
    assert main(["export", "st", TANK]) == 0
    control = capsys.readouterr().out
    assert main(["export", "st", TANK, "--with-plants"]) == 0
    both = capsys.readouterr().out
    assert "Tank" not in control.replace("Tank filling", "") and "PROGRAM Filling" in control
    assert "PROGRAM Tank\n" in both and "PROGRAM Tank WITH PLANTS : Tank;" in both


def test_check_and_run_name_a_widget_bound_to_a_variable_the_program_lacks(capsys, tmp_path: Path):
    """The panel's bindings are part of the project: ``check`` reports one the program lacks at its widget, and
    ``run`` refuses to build (as the browser's Compile & simulate does)."""
    folder = tmp_path / "tank"
    shutil.copytree(EXAMPLES / "tank_filling", folder)
    panel = folder / "hmi" / "Tank.json"
    document = json.loads(panel.read_text())
    document["widgets"][10]["paths"] = ["Tank.Level", "Tank.Lvl"]
    panel.write_text(json.dumps(document))
    assert main(["check", str(folder)]) == 1
    out, _ = capsys.readouterr()
    assert out.splitlines()[0] == (
        "hmi/Tank.json, widgets[10].paths[1], element trend: error PANEL-BINDING: panel Tank, widget trend "
        "(paths[1]): TANK has no variable 'Lvl' - did you mean 'LEVEL'?"
    )
    code, rows, err = run(capsys, str(folder), "--cycles", "1")
    assert code == 1 and rows == [] and "panel Tank, widget trend (paths[1])" in err
