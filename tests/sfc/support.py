"""Small builders for SFC test projects and scan tables.

A chart is written as nested Python calls (``step``, ``tr``, ``alt``, ``par``, ``jump``); an association as
``"N Act"`` or ``"D Act T#30ms"``. A scan table is text: the columns left of ``||`` are written before the scan
(inputs), those right of it are read after it; ``1``/``0`` are TRUE/FALSE, ``'text'`` a STRING, ``-`` no write.
Every expected value in the tests is worked out by hand from IEC 61131-3 (the action control of figure 15) and
seed 003 (SFC-04..SFC-08), never read from the engine.
"""

from __future__ import annotations

import itertools
from typing import Any

from ladderlab.engine.simulation import Simulation
from ladderlab.ir.lower_project import lower_project
from ladderlab.model import Pou, Project

_ids = itertools.count(1)


def _id(prefix: str) -> str:
    return f"{prefix}{next(_ids)}"


def assoc(text: str) -> dict:
    parts = text.split()
    out = {"id": _id("a"), "qualifier": parts[0], "action": parts[1]}
    if len(parts) > 2:
        out["time"] = parts[2]
    return out


def step(name: str, *assocs: str, **extra: Any) -> dict:
    return {"type": "step", "id": _id("s"), "name": name, "actions": [assoc(a) for a in assocs], **extra}


def tr(condition: str, priority: int | None = None) -> dict:
    out: dict = {"type": "transition", "id": _id("t"), "condition": condition}
    if priority is not None:
        out["priority"] = priority
    return out


def alt(*branches: list) -> dict:
    return {"type": "alternative", "id": _id("alt"), "branches": list(branches)}


def par(*branches: list) -> dict:
    return {"type": "parallel", "id": _id("par"), "branches": list(branches)}


def jump(target: str) -> dict:
    return {"type": "jump", "id": _id("j"), "target": target}


def ld_network(*elements: dict) -> dict:
    """An LD body (an action's or a named transition's) of one network holding ``elements``."""
    return {"networks": [{"id": _id("n"), "elements": list(elements)}]}


def sfc_pou(
    name: str,
    declarations: str,
    chart: list,
    actions: dict[str, str] | None = None,
    kind: str = "program",
    transitions: list | None = None,
    extra_actions: list | None = None,
) -> Pou:
    body = {
        "chart": {"elements": chart},
        "actions": [{"name": n, "language": "st", "body": b} for n, b in (actions or {}).items()]
        + list(extra_actions or []),
        "transitions": list(transitions or []),
    }
    return Pou(name=name, kind=kind, language="sfc", declarations=declarations, body=body)


def project(*pous: Pou, globals_: str = "") -> Project:
    return Project(name="sfc_test", pous=list(pous), globals=globals_)


def build(proj: Project, variant: str = "fast") -> Simulation:
    result = lower_project(proj)
    errors = [d for d in result.diagnostics if d.severity == "error"]
    assert result.program is not None and not errors, "\n".join(f"{d.location()}: {d.message}" for d in errors)
    return Simulation(result.program, variant=variant)


def _value(text: str) -> object:
    if text in ("1", "TRUE"):
        return True
    if text in ("0", "FALSE"):
        return False
    if text.startswith("'"):
        return text.strip("'")
    return int(text)


def run_table(proj: Project, table: str, pou: str = "Main") -> None:
    """Run ``proj`` scan by scan as ``table`` says and compare every expected cell; one message lists all wrong."""
    lines = [line.split("#")[0].strip() for line in table.strip().splitlines()]
    lines = [line for line in lines if line]
    head_in, head_out = (part.split() for part in lines[0].split("||"))
    head_in = head_in[1:]  # the scan column
    sim = build(proj)
    wrong = []
    for line in lines[1:]:
        cells_in, cells_out = (part.split() for part in line.split("||"))
        scan = int(cells_in[0])
        assert scan == sim.scan_count, f"the table skips to scan {scan} (at {sim.scan_count})"
        for path, cell in zip(head_in, cells_in[1:]):
            if cell != "-":
                sim.write(_path(path, pou), _value(cell))
        sim.cycle(1)
        assert sim.fault is None, sim.fault.text()
        for path, cell in zip(head_out, cells_out):
            got = sim.read(_path(path, pou))
            if got != _value(cell):
                wrong.append(f"scan {scan}: {path} = {got!r}, expected {cell}")
    assert not wrong, "\n".join(wrong)


def _path(column: str, pou: str) -> str:
    return column if "." in column and column.split(".")[0].upper() in ("OTHER", pou.upper()) else f"{pou}.{column}"
