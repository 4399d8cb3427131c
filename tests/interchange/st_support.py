"""Helpers of the ST export tests: export, replace the diagram POUs by their ST, and compare traces.

``same_traces`` is the equivalence contract of issue 8: the project as drawn and the
project with every LD/FBD POU replaced by its exported ST (parsed back from the
text) run side by side; before each scan both get the same random writes to a
random subset of the programs' and the globals' BOOL and integer variables, after
each scan every elementary variable the two have in common must be equal. Every export is also checked to map
each line of its networks to its network and element (``check_source_map``, issue 28).
"""

from __future__ import annotations

import random

from ladderlab.interchange.st.export import StExport, export_pou_st
from ladderlab.ir import types as irt
from ladderlab.model import ld
from ladderlab.model.project import Project
from ladderlab.simulation.build import build_project
from ladderlab.st.checker import check_project
from ladderlab.storage.st_text import parse_pou_text

INTEGERS = {"SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT"}


def exported(project: Project, name: str) -> StExport:
    """Export ``name``; the export must succeed without any diagnostic."""
    result = export_pou_st(project, name)
    assert [d.format() for d in result.diagnostics] == [], result.text
    assert result.text
    check_source_map(project, name, result)
    return result


#: Lines of the network-index state machine that belong to no one network (docs/st_export.md, jumps).
SCAFFOLDING = {"END_CASE;", "END_WHILE;"}


def check_source_map(project: Project, name: str, result: StExport) -> None:
    """Issue 28: every line from the first network's comment to the POU's end (the state machine's closing lines
    apart) maps to a network of the POU and, if to an element, to one of that network's elements. (An SFC POU's
    source map is not written: its networks are those of its actions.)"""
    if project.pou(name).language not in ("ld", "fbd", "cfc"):
        return
    lines = result.text.splitlines()
    headings = ("(* Network", "(* CFC chart")
    first = next((i for i, line in enumerate(lines, 1) if line.lstrip().startswith(headings)), None)
    if first is None:
        return
    mapped = {line: (network, element) for line, network, element in result.source_map}
    networks = project.pou(name).body.networks
    elements = {n.id: {e.id for e in (n.nodes if hasattr(n, "nodes") else ld.walk(n.elements))} for n in networks}
    for number in range(first, len(lines)):  # the last line is END_PROGRAM (or END_FUNCTION...)
        text = lines[number - 1]
        if text.strip() in SCAFFOLDING:
            continue
        assert number in mapped, f"line {number} {text!r} maps to no network"
        network, element = mapped[number]
        assert network in elements, f"line {number} {text!r}: no network {network!r}"
        assert element is None or element in elements[network], f"line {number} {text!r}: no element {element!r}"


def as_st(project: Project) -> Project:
    """``project`` with every LD/FBD POU replaced by its exported text, which checks without any diagnostic."""
    pous = [parse_pou_text(exported(project, p.name).text) if p.language != "st" else p for p in project.pous]
    replaced = project.model_copy(update={"pous": pous})
    names = {p.name.upper() for p in project.pous if p.language != "st"}
    found = [d.format() for d in check_project(replaced).diagnostics if (d.pou or "").upper() in names]
    assert found == []
    return replaced


def same_traces(
    project: Project, scans: int = 200, seed: int = 0, other: Project | None = None
) -> list[dict[str, object]]:
    """Run ``project`` and ``other`` (default: its ST export) ``scans`` scans with the same random writes; the
    traces must agree. Returns the trace (snapshots of the common variables), so callers can check it too."""
    builds = [build_project(project), build_project(other if other is not None else as_st(project))]
    for build in builds:
        assert [d.format() for d in build.diagnostics if d.severity == "error"] == []
    sims = [build.simulation() for build in builds]
    common = sorted(set(sims[0].snapshot()) & set(sims[1].snapshot()))
    writable = [path for path in common if path.count(".") <= 1 and _scalar(sims[0], path) is not None]
    rng = random.Random(seed)
    trace = []
    for scan in range(scans):
        for path in writable:
            if rng.random() < 0.4:
                kind = _scalar(sims[0], path)
                value = rng.random() < 0.5 if kind == "BOOL" else rng.randint(0 if kind.startswith("U") else -2, 12)
                for sim in sims:
                    sim.write(path, value)
        rows = []
        for sim in sims:
            sim.cycle(1)
            snapshot = sim.snapshot()
            rows.append({path: snapshot[path] for path in common})
        faults = [sim.fault for sim in sims]
        if faults != [None, None]:  # an endless jump loop: the watchdog stops both, in the same scan
            assert None not in faults and faults[0].code == faults[1].code and faults[0].scan == faults[1].scan, faults
            break
        assert rows[1] == rows[0], f"scan {scan}: " + str(
            {p: (rows[0][p], rows[1][p]) for p in common if rows[0][p] != rows[1][p]}
        )
        trace.append(rows[0])
    return trace


def _scalar(sim, path: str) -> str | None:
    ty = sim.location(path).type
    if isinstance(ty, irt.Elementary) and (ty.name == "BOOL" or ty.name in INTEGERS):
        return ty.name
    return None


def body(text: str) -> str:
    """The statements of an exported POU text: after its last END_VAR, without the END_ line."""
    return text.split("END_VAR\n")[-1].rsplit("END_", 1)[0]
