"""Projects with plants for the engine tests: ST POUs given as text, built as the CLI and the server build them."""

from __future__ import annotations

from ladderlab.engine.simulation import Simulation
from ladderlab.model import Pou, Project, Task
from ladderlab.simulation.build import build_project


def st_pou(name: str, kind: str, declarations: str, body: str) -> Pou:
    return Pou(name=name, kind=kind, language="st", declarations=declarations, body=body)  # type: ignore[arg-type]


def project(*pous: Pou, globals: str = "", tasks: list[Task] | None = None) -> Project:
    return Project(name="bench", globals=globals, pous=list(pous), tasks=tasks or [])


def simulate(*pous: Pou, globals: str = "", tasks: list[Task] | None = None, variant: str = "fast") -> Simulation:
    build = build_project(project(*pous, globals=globals, tasks=tasks), variant)
    assert build.compiled is not None, [d.format() for d in build.diagnostics]
    return build.simulation()


#: A tank and its pump: the plant fills 3 units per scan while the pump runs and drains 1 per scan always;
#: the switch HIGH reads TRUE from level 10. The control program runs the pump until HIGH.
TANK_GLOBALS = "VAR_GLOBAL\n    Pump : BOOL;\n    High : BOOL;\n    Level : INT;\nEND_VAR"
TANK_PLANT = st_pou(
    "Tank",
    "plant",
    "VAR_EXTERNAL\n    Pump : BOOL;\n    High : BOOL;\n    Level : INT;\nEND_VAR",
    "IF Pump THEN\n    Level := Level + 3;\nEND_IF;\nIF Level > 0 THEN\n    Level := Level - 1;\nEND_IF;\n"
    "High := Level >= 10;",
)
TANK_CONTROL = st_pou(
    "Main",
    "program",
    "VAR_EXTERNAL\n    Pump : BOOL;\n    High : BOOL;\nEND_VAR\nVAR\n    Starts : INT;\nEND_VAR",
    "IF NOT Pump AND NOT High THEN\n    Starts := Starts + 1;\nEND_IF;\nPump := NOT High;",
)


def tank_reference(scans: int, forced_high: bool | None = None) -> list[tuple[bool, bool, int]]:
    """(Pump, High, Level) after each scan, computed here: the plant first (it sees the pump of the previous
    scan), then the control program (it sees the switch the plant just set, or the forced value)."""
    pump, high, level, rows = False, False, 0, []
    for _ in range(scans):
        if pump:
            level += 3
        if level > 0:
            level -= 1
        high = level >= 10 if forced_high is None else forced_high
        pump = not high
        rows.append((pump, high, level))
    return rows
