"""The SFC example project (examples/car_wash_sfc): a premium wash runs through every step, scan-exact.

100 ms scans. Worked out from the chart (docs/sfc.md): a transition fires at the end of a scan, the next step acts
from the following scan with T#0s, ``Step.T >= T#3s`` is TRUE 30 scans later; the simultaneous join fires in the
first scan in which both Drain and BrushHome are active.
"""

from __future__ import annotations

from pathlib import Path

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.storage.project_folder import read_project_folder

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "car_wash_sfc"

#: scan -> the steps active after it
EXPECTED = {
    0: {"Idle"},
    1: {"Welcome"},
    2: {"Soak"},
    32: {"Soak"},
    33: {"Brush", "Spray"},
    63: {"Brush", "Spray"},
    64: {"Brush", "Drain"},
    73: {"Brush", "Drain"},
    74: {"BrushHome", "Drain"},
    75: {"Rinse"},
    96: {"Dry"},
    127: {"Leave"},
    139: {"Leave"},
    140: {"Idle"},
}
STEPS = ("Idle", "Welcome", "Soak", "Brush", "BrushHome", "Spray", "Drain", "Rinse", "Dry", "Leave")


def test_a_premium_wash_runs_through_every_step():
    result = lower_project(read_project_folder(EXAMPLE))
    assert result.program is not None, [d.message for d in result.diagnostics]
    sim = Simulation(result.program)
    sim.write("Wash.CarInside", True)
    sim.write("Wash.Premium", True)
    seen = {}
    for scan in range(141):
        if scan == 1:
            sim.write("Wash.Start", True)
        if scan == 3:
            sim.write("Wash.Start", False)
        if scan == 140:
            sim.write("Wash.CarInside", False)
        sim.cycle(1)
        seen[scan] = {name for name in STEPS if sim.read(f"Wash.{name}.X")}
        if scan == 25:  # Soak acts from scan 3: L_TMR reaches T#2s in scan 23
            assert (sim.read("Wash.Soap"), sim.read("Wash.Water")) == (True, False)  # L Water T#2s has ended
        if scan == 80:
            assert sim.read("Status.Busy") is True and sim.read("Wash.Cars") == 1
    assert {scan: seen[scan] for scan in EXPECTED} == EXPECTED
    assert sim.read("Wash.SFCCurrentStep") == "Idle" and sim.read("Wash.Done") is False
