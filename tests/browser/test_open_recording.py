"""Open a recording in the real Chromium (issue 23 item 5: "the browser can download and open recordings"). A run
of the example ``motor`` recorded by ``ladderlab run --record`` (six scans, Start written TRUE before the fourth: the
seal-in rung ``Motor := (Start OR Motor) AND NOT Stop`` holds from scan 4 on) opens from the toolbar as a
history-only simulation: the timeline shows its last scan, scan 2 shows the coil off as it was, the differences
between scans 2 and 6 are Start and Motor, Run and Single cycle are off until "Continue from here" (from scan 4,
the coil on) makes it live again. A recording of another revision of the project and a file that is not a
recording are refused with the server's words in the toolbar. When the simulation's process crashes after such a
fork, Reset opens the recording again, history only (hist4 item 1). The test fails on any page or console error."""

from __future__ import annotations

import json
import os
import re
import signal
from pathlib import Path

import pytest

from ladderlab.cli import main

from .conftest import ARTIFACTS
from .steps import open_pou

pytestmark = pytest.mark.browser


def _coil(page, state: str) -> None:
    page.wait_for_function(
        f"() => document.querySelector('g.ld-coil[data-id=motor]')?.classList.contains('ld-{state}')"
    )


def test_open_a_recording_view_its_scans_and_continue_from_one(page, server, tmp_path: Path, browser_errors):
    page.goto(server)  # the server put the examples into its workspace
    folder = tmp_path / "workspace" / "motor"
    recording = tmp_path / "motor-run.json"
    assert main(["run", str(folder), "--cycles", "6", "--set", "Start=TRUE@3", "--record", str(recording)]) == 0
    open_pou(page, "motor", "Main")
    page.locator('g.ld-element[data-id="motor"]').wait_for()

    bar = page.get_by_role("toolbar", name="Simulation")
    bar.get_by_label("Recording file").set_input_files(str(recording))
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · stopped").wait_for()
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 6 (history)").wait_for()
    timeline = page.get_by_role("group", name="Scan history")
    timeline.get_by_label("History kept").filter(has_text="recording · history only · from scan 1").wait_for()
    _coil(page, "on")
    assert bar.get_by_role("button", name="Run", exact=True).is_disabled()
    assert bar.get_by_role("button", name="Single cycle").is_disabled()

    slider = timeline.get_by_role("slider", name="Scan")
    assert (slider.get_attribute("min"), slider.get_attribute("max")) == ("1", "6")
    slider.fill("2")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    page.get_by_test_id("scan-count").filter(has_text=re.compile("^2$")).wait_for()
    _coil(page, "off")
    mark = timeline.get_by_role("button", name="scan 4: write")  # the recorded write, before the fourth scan
    mark.wait_for()
    page.screenshot(path=str(ARTIFACTS / "open-recording-scan-2.png"))

    page.get_by_label("Compare with scan").fill("6")
    page.get_by_role("button", name="Show differences").click()
    differences = page.get_by_role("table", name="Differences")
    differences.locator('tr[data-path="START"]').wait_for()
    assert differences.locator('tr[data-path="START"] td').all_inner_texts() == ["START", "FALSE", "→", "TRUE"]
    assert differences.locator('tr[data-path="MOTOR"] td').all_inner_texts() == ["MOTOR", "FALSE", "→", "TRUE"]

    mark.click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    _coil(page, "on")
    page.get_by_role("button", name="Continue from here").click()
    banner.wait_for(state="detached")
    timeline.get_by_label("History kept").filter(has_text="branch 2 live").wait_for()
    assert "history only" not in timeline.get_by_label("History kept").inner_text()
    cycle = bar.get_by_role("button", name="Single cycle")
    cycle.click()
    page.get_by_test_id("scan-count").filter(has_text=re.compile("^5$")).wait_for()
    _coil(page, "on")  # sealed in

    # refused: the project at another revision, a file that is not a recording (each in the server's words)
    data = json.loads(recording.read_text())
    other = tmp_path / "other.json"
    other.write_text(json.dumps({**data, "revision": "0000000000000000"}))
    browser_errors.allow(r"409 \(Conflict\)")
    browser_errors.allow(r"422 \(Unprocessable")
    bar.get_by_label("Recording file").set_input_files(str(other))
    alert = bar.get_by_role("alert")
    alert.filter(
        has_text=re.compile(
            r"^other\.json was recorded with revision 0000000000000000 of .*motor; project 'motor' is now at "
            r"revision [0-9a-f]{16}: open it in the project as it was when it was recorded$"
        )
    ).wait_for()
    state.filter(has_text="Offline").wait_for()
    text = tmp_path / "notes.json"
    text.write_text('{"format": "plcopen"}')
    bar.get_by_label("Recording file").set_input_files(str(text))
    alert.filter(
        has_text="notes.json: not a recording of ladderlab run --record or of a simulation's download"
    ).wait_for()


def _children(pid: int) -> set[int]:
    """The processes whose parent is ``pid`` (Linux /proc)."""
    found = set()
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                found.add(int(entry))
    return found


def _simulation_workers(workspace: Path) -> set[int]:
    """The simulation processes of the ``ladderlab serve`` over ``workspace``: forked by its fork server, with the
    thread that links them to the server beside the engine's (a build worker has one thread)."""
    servers = [
        int(entry)
        for entry in os.listdir("/proc")
        if entry.isdigit() and str(workspace).encode() in _cmdline(int(entry))
    ]
    assert len(servers) == 1, servers
    workers = {worker for child in _children(servers[0]) for worker in _children(child)}
    return {worker for worker in workers if len(_listing(f"/proc/{worker}/task")) >= 2}


def _listing(folder: str) -> list[str]:
    try:
        return os.listdir(folder)
    except OSError:
        return []


def _cmdline(pid: int) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


def test_reset_after_a_crash_opens_the_recording_again(page, server, tmp_path: Path, browser_errors):
    """A recording opened, continued from scan 4 and run one cycle; then the simulation's process is killed (a
    crash). The toolbar says the simulation is faulted, offers no history (it was in the process) and enables Reset;
    Reset opens the recording again in a new process: history only, its six scans, the coil as recorded."""
    page.goto(server)
    workspace = tmp_path / "workspace"
    recording = tmp_path / "motor-run.json"
    assert (
        main(["run", str(workspace / "motor"), "--cycles", "6", "--set", "Start=TRUE@3", "--record", str(recording)])
        == 0
    )
    open_pou(page, "motor", "Main")
    page.locator('g.ld-element[data-id="motor"]').wait_for()
    before = _simulation_workers(workspace)

    bar = page.get_by_role("toolbar", name="Simulation")
    bar.get_by_label("Recording file").set_input_files(str(recording))
    banner = page.get_by_role("status", name="History view")
    banner.filter(has_text="Viewing scan 6 (history)").wait_for()
    timeline = page.get_by_role("group", name="Scan history")
    kept = timeline.get_by_label("History kept")
    reset = bar.get_by_role("button", name="Reset")
    assert reset.is_disabled()  # history only: a recording is not reset, as it is not run
    timeline.get_by_role("button", name="scan 4: write").click()
    banner.filter(has_text="Viewing scan 4 (history)").wait_for()
    page.get_by_role("button", name="Continue from here").click()
    kept.filter(has_text="branch 2 live").wait_for()
    bar.get_by_role("button", name="Single cycle").click()
    page.get_by_test_id("scan-count").filter(has_text=re.compile("^5$")).wait_for()
    assert reset.is_enabled()

    workers = _simulation_workers(workspace) - before
    assert len(workers) == 1, workers  # the simulation's process
    browser_errors.allow(r"ended unexpectedly")
    os.kill(workers.pop(), signal.SIGKILL)
    state = page.get_by_role("status", name="Online state")
    state.filter(has_text="Online · faulted").wait_for()
    timeline.wait_for(state="detached")  # the history was in the process that ended
    page.screenshot(path=str(ARTIFACTS / "open-recording-crashed.png"))
    assert reset.is_enabled()

    reset.click()
    banner.filter(has_text="Viewing scan 6 (history)").wait_for()
    kept.filter(has_text="recording · history only · from scan 1").wait_for()
    assert "branch 2" not in kept.inner_text()
    state.filter(has_text="Online · stopped").wait_for()
    _coil(page, "on")
    slider = timeline.get_by_role("slider", name="Scan")
    assert (slider.get_attribute("min"), slider.get_attribute("max")) == ("1", "6")
    slider.fill("2")
    banner.filter(has_text="Viewing scan 2 (history)").wait_for()
    _coil(page, "off")
    assert reset.is_disabled() and bar.get_by_role("button", name="Run", exact=True).is_disabled()
