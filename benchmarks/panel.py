"""Operator panel benchmark (issue 21): a panel of 50 widgets bound to 200 variables, online in Chromium.

A real uvicorn server runs in this process, the simulation in its worker process and the panel in
Debian's Chromium (Playwright), opened as a panel window (its own websocket, 20 ms values interval:
the server's publish rate). The program runs on a 10 ms task: a plant writes 100 of the variables and
the control program the other 100, each changing every scan. The 50 widgets: lamps, numeric displays,
bars, seven-segment displays, multistate indicators, symbols (each bound to its variable and moved or
shown by three more) and trends (four variables each); every widget reads four variables.

Reported: the panel's updates per second in the browser (how often a numeric display bound to a
variable that changes every scan changed in the DOM, counted by a MutationObserver) against the
publish rate (50 per second), the p50/p99 time between two updates, the scan rate (target: the task's
100 scans/s, within 2 %) with the pacer's overruns (target 0) and mean scan time, the CPU of the
server and of the simulation's process, and the load average. ``--seconds`` sets the length.
"""

from __future__ import annotations

import argparse
import itertools
import json
import os
import pathlib
import shutil
import statistics
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "backend"), str(ROOT), str(ROOT / "benchmarks")]

from common import load_average  # noqa: E402
from monitor import cpu_seconds, request, serve  # noqa: E402

VARIABLES = 200
WIDGETS = 50
KINDS = ["lamp", "numeric_display", "bar", "seven_segment", "multistate", "symbol", "trend"]


def project():
    """The program (100 variables), the plant (100 more) and the panel reading all 200."""
    from ladderlab.model import Panel, Pou, Project, Task

    half = VARIABLES // 2

    def pou(name: str, kind: str, first: int) -> Pou:
        names = [f"v{i}" for i in range(first, first + half)]
        declarations = "VAR\n" + "".join(f"    {n} : DINT;\n" for n in names) + "END_VAR"
        body = "".join(f"{n} := {n} + 1;\n" for n in names)
        return Pou(name=name, kind=kind, language="st", declarations=declarations, body=body)  # type: ignore[arg-type]

    paths = [f"Main.v{i}" for i in range(half)] + [f"Plant.v{i}" for i in range(half, VARIABLES)]
    widgets = []
    for n in range(WIDGETS):
        kind = KINDS[n % len(KINDS)]
        four = paths[4 * n : 4 * n + 4]
        base = {"id": f"w{n}", "x": 10 + (n % 10) * 75, "y": 10 + (n // 10) * 90, "w": 60, "h": 50}
        if kind == "trend":
            widgets.append({**base, "type": "trend", "paths": four})
            continue
        widget = {**base, "type": kind, "bind": four[0]}
        widget["visible"] = four[1]  # a DINT that is never 0 once running: shown
        widget["move_x"] = {"path": four[2], "min": 0, "max": 1_000_000, "distance": 5}
        widget["move_y"] = {"path": four[3], "min": 0, "max": 1_000_000, "distance": 5}
        if kind == "multistate":
            widget["states"] = [{"value": v, "text": str(v)} for v in range(8)]
        if kind == "symbol":
            widget["shape"] = "motor"
        widgets.append(widget)
    panel = Panel.model_validate({"name": "Desk", "width": 800, "height": 480, "widgets": widgets})
    assert len({p for w in widgets for p in ([w["bind"]] if "bind" in w else w["paths"])}) <= VARIABLES
    return Project(
        name="bench",
        pous=[pou("Main", "program", 0), pou("Plant", "plant", half)],
        tasks=[Task(name="T", interval="T#10ms", programs=["Main"])],
        panels=[panel],
    )


COUNT_UPDATES = """() => {
    const target = document.querySelector('[data-widget="w1"] [data-text]');
    window.__updates = [];
    new MutationObserver(() => window.__updates.push(performance.now()))
        .observe(target, {attributes: true, attributeFilter: ['data-text']});
}"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    address, registry, _ = serve([project()])
    sim = request(address, "POST", "/api/projects/bench/simulations")["id"]
    request(address, "POST", f"/api/simulations/{sim}/start")
    handle = registry.get(sim).handle
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
        page = browser.new_page(viewport={"width": 1000, "height": 700})
        page.goto(f"http://{address}/?panel=bench/Desk&simulation={sim}")
        page.locator('[data-widget="w49"]').wait_for()
        page.wait_for_function("document.querySelector('[data-widget=\"w1\"] [data-text]').dataset.text !== '…'")
        time.sleep(1.0)
        page.evaluate(COUNT_UPDATES)
        before = request(address, "GET", f"/api/simulations/{sim}")
        worker = handle.process.pid
        cpu, worker_cpu, wall = time.process_time(), cpu_seconds(worker), time.monotonic()
        time.sleep(args.seconds)
        cpu, wall = time.process_time() - cpu, time.monotonic() - wall
        worker_cpu = cpu_seconds(worker) - worker_cpu
        after = request(address, "GET", f"/api/simulations/{sim}")
        updates = page.evaluate("window.__updates")
        load = load_average()
        browser.close()
    registry.close()
    gaps = sorted(b - a for a, b in itertools.pairwise(updates))
    scans = after["scan_count"] - before["scan_count"]
    busy = after["scan_ms"]["avg"] * after["scan_count"] - before["scan_ms"]["avg"] * before["scan_count"]
    mean_scan = busy / scans
    figures = {
        "widgets": WIDGETS,
        "variables": VARIABLES,
        "updates_per_s": len(updates) / wall,
        "publish_per_s": 50.0,
        "gap_p50_ms": statistics.median(gaps) if gaps else None,
        "gap_p99_ms": gaps[min(len(gaps) - 1, int(0.99 * len(gaps)))] if gaps else None,
        "scans_per_s": scans / wall,
        "overruns": after["overruns"] - before["overruns"],
        "mean_scan_ms": mean_scan,
        "server_cpu": 100.0 * cpu / wall,
        "worker_cpu": 100.0 * worker_cpu / wall,
    }
    print(json.dumps({k: round(v, 2) if isinstance(v, float) else v for k, v in figures.items()}))
    print(
        f"panel {WIDGETS} widgets / {VARIABLES} variables: {figures['updates_per_s']:.1f} updates/s in Chromium "
        f"(publish rate 50/s; gap p50 {figures['gap_p50_ms']:.0f} ms, p99 {figures['gap_p99_ms']:.0f} ms), "
        f"{figures['scans_per_s']:.1f} scans/s, {figures['overruns']} overruns, mean scan {mean_scan:.3f} ms, "
        f"server CPU {figures['server_cpu']:.0f} %, simulation CPU {figures['worker_cpu']:.0f} %, {load}"
    )


if __name__ == "__main__":
    os.environ.setdefault("LADDERLAB_WORKSPACE", "/tmp")
    main()
